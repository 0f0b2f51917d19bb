"""Plan validation against the ORIGINAL problem.

Three validators, in a registry:
- ``builtin``: the simulator of ``pddl/simulator.py`` (ADL, numeric fluents,
  derived predicates, PDDL 2.1 timed plans).  It costs milliseconds, so it
  runs on every plan, however large the problem, and it watches the deadline.
  It does not check hard trajectory constraints (PDDL3), so on a problem
  with them it cannot run.
- ``up``: unified-planning's validators (sequential, or time-triggered for
  timed plans), reading the original files with UP's reader (seconds on
  large problems).
- ``val``: VAL's ``Validate`` when it is on PATH.
A validator that cannot run says so (``UNAVAILABLE``); that is never read as
valid or invalid.  ``none``, alone, is the user's explicit choice not to
validate: the plan is reported as NOT validated.  Input our reader refuses
(PDDL+, object fluents) is planned unpruned; only the validators that read
the files themselves can check its plans (:func:`validate_unread`).
"""

from __future__ import annotations

import enum
import shutil
import time
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass

from relevance_plan.errors import SimulationTimeout, UsageError
from relevance_plan.pddl.formulas import Modal, Node, Preference, children
from relevance_plan.pddl.model import Domain, Problem
from relevance_plan.pddl.plans import Plan, format_plan


class ValidationStatus(enum.Enum):
    VALID = "valid"
    INVALID = "invalid"
    UNAVAILABLE = "unavailable"
    OUT_OF_TIME = "out-of-time"
    NOT_VALIDATED = "not-validated"  # --validator none: the user chose not to validate


NONE = "none"


@dataclass(frozen=True)
class ValidationResult:
    status: ValidationStatus
    validator: str
    message: str = ""
    failed_step: int | None = None  # 1-based; None for a goal failure or success
    cost: float | None = None  # the plan's total-cost on the original problem, when it has one

    @property
    def valid(self) -> bool:
        return self.status is ValidationStatus.VALID

    @property
    def accepted(self) -> bool:
        """The plan may be reported: valid, or not validated at the user's request."""
        return self.status in (ValidationStatus.VALID, ValidationStatus.NOT_VALIDATED)


# --------------------------------------------------------------------------- builtin


def validate_builtin(domain: Domain, problem: Problem, plan: Plan, deadline: float | None = None) -> ValidationResult:
    if any(_hard(constraint) for constraint in (domain.constraints, problem.constraints) if constraint is not None):
        return ValidationResult(ValidationStatus.UNAVAILABLE, "builtin", "it does not check trajectory constraints")
    try:
        from relevance_plan.pddl.simulator import simulate  # only when a plan is checked

        result = simulate(domain, problem, plan, deadline)
    except SimulationTimeout as error:
        return ValidationResult(ValidationStatus.OUT_OF_TIME, "builtin", error.message)
    status = ValidationStatus.VALID if result.valid else ValidationStatus.INVALID
    return ValidationResult(status, "builtin", result.message, result.failed_step, result.cost)


def _hard(constraint: Node) -> bool:
    """Whether a constraint has a part outside preferences (preferences are soft: never a plan's validity)."""
    if isinstance(constraint, Preference):
        return False
    return isinstance(constraint, Modal) or any(_hard(part) for part in children(constraint))


# --------------------------------------------------------------------------- unified-planning


def validate_with_up(domain: Domain, problem: Problem, plan: Plan, deadline: float | None = None) -> ValidationResult:
    """Validate with unified-planning's validators, from the original files."""
    if domain.path is None or problem.path is None:
        return ValidationResult(ValidationStatus.UNAVAILABLE, "up", "needs the domain and problem files on disk")
    return validate_files_with_up(domain.path, problem.path, plan)


def validate_files_with_up(domain_path: str, problem_path: str, plan: Plan) -> ValidationResult:
    try:
        from unified_planning.engines.results import ValidationResultStatus
        from unified_planning.io import PDDLReader
        from unified_planning.shortcuts import get_environment
    except ImportError as error:  # pragma: no cover - depends on the installation
        return ValidationResult(ValidationStatus.UNAVAILABLE, "up", f"unified-planning not importable: {error}")
    get_environment().credits_stream = None
    try:
        up_problem = PDDLReader().parse_problem(domain_path, problem_path)
        up_plan = _up_plan(up_problem, plan)
        if isinstance(up_plan, ValidationResult):
            return up_plan
        result = _up_validator(up_problem, plan).validate(up_problem, up_plan)
    except Exception as error:  # UP raises many unrelated types; report, never guess
        return ValidationResult(ValidationStatus.UNAVAILABLE, "up", f"unified-planning failed: {error}".splitlines()[0])
    if result.status == ValidationResultStatus.VALID:
        return ValidationResult(ValidationStatus.VALID, "up", "valid")
    reason = str(getattr(result, "reason", "") or getattr(result, "log_messages", "") or "invalid")
    return ValidationResult(ValidationStatus.INVALID, "up", reason.splitlines()[0] if reason else "invalid")


def _up_plan(up_problem, plan: Plan):
    from fractions import Fraction

    from unified_planning.model import DurativeAction
    from unified_planning.plans import ActionInstance, SequentialPlan, TimeTriggeredPlan

    objects = {o.name.lower(): o for o in up_problem.all_objects}
    actions = {a.name.lower(): a for a in up_problem.actions}
    instances = []
    for number, step in enumerate(plan.steps, start=1):
        if step.action not in actions or any(arg not in objects for arg in step.args):
            return ValidationResult(ValidationStatus.INVALID, "up", f"step {number}: unknown action or object", number)
        instances.append(ActionInstance(actions[step.action], tuple(objects[arg] for arg in step.args)))
    if not plan.timed:
        return SequentialPlan(instances)
    timed = []
    for step, instance in zip(plan.steps, instances):
        # an instantaneous action has no duration, whatever a planner printed for it
        durative = isinstance(instance.action, DurativeAction)
        duration = None if step.duration is None or not durative else Fraction(str(step.duration))
        timed.append((Fraction(str(step.time or 0.0)), instance, duration))
    return TimeTriggeredPlan(timed)


def _up_validator(up_problem, plan: Plan):
    if plan.timed:
        from unified_planning.engines.plan_validator import TimeTriggeredPlanValidator

        return TimeTriggeredPlanValidator(environment=up_problem.environment)
    from unified_planning.engines.plan_validator import SequentialPlanValidator

    return SequentialPlanValidator(environment=up_problem.environment)


# --------------------------------------------------------------------------- VAL


def val_available() -> bool:
    return shutil.which("Validate") is not None


def validate_with_val(domain: Domain, problem: Problem, plan: Plan, deadline: float | None = None) -> ValidationResult:
    if domain.path is None or problem.path is None:
        return ValidationResult(ValidationStatus.UNAVAILABLE, "val", "needs the domain and problem files on disk")
    return validate_files_with_val(domain.path, problem.path, plan, deadline)


def validate_files_with_val(
    domain_path: str, problem_path: str, plan: Plan, deadline: float | None
) -> ValidationResult:
    from relevance_plan.supervision.process import run_val  # subprocess access lives in the process module

    if not val_available():
        return ValidationResult(ValidationStatus.UNAVAILABLE, "val", "VAL's Validate is not on PATH")
    timeout = 60.0 if deadline is None else max(0.1, deadline - time.monotonic())
    ok, message = run_val(domain_path, problem_path, format_plan(plan), timeout=timeout)
    if ok is None:
        return ValidationResult(ValidationStatus.UNAVAILABLE, "val", message)
    return ValidationResult(ValidationStatus.VALID if ok else ValidationStatus.INVALID, "val", message)


Validator = Callable[[Domain, Problem, Plan, "float | None"], ValidationResult]

VALIDATORS: dict[str, Validator] = {
    "builtin": validate_builtin,
    "up": validate_with_up,
    "val": validate_with_val,
}
# Every --validator choice: the validators, and ``none`` (no validation, explicitly).
VALIDATOR_CHOICES = (*VALIDATORS, NONE)

_NOT_VALIDATED = ValidationResult(ValidationStatus.NOT_VALIDATED, NONE, "not validated (--validator none)")


def check_validators(names: Sequence[str]) -> None:
    """Refuse an unknown name, and ``none`` together with a validator."""
    unknown = [name for name in names if name not in VALIDATOR_CHOICES]
    if unknown:
        raise UsageError(f"unknown validator '{unknown[0]}' (choose from: {', '.join(VALIDATOR_CHOICES)})")
    if NONE in names and len(set(names)) > 1:
        raise UsageError("--validator none means no validation; it cannot be combined with a validator")


def default_validators() -> tuple[str, ...]:
    """Always the builtin simulator; VAL as a second opinion when it is installed."""
    return ("builtin", "val") if val_available() else ("builtin",)


def validate_plan(
    domain: Domain,
    problem: Problem,
    plan: Plan,
    validators: Sequence[str] | None = None,
    deadline: float | None = None,
) -> ValidationResult:
    """Run each validator; the plan is valid only if every one that ran says so.

    If none could run, the result is UNAVAILABLE (the caller must say so loudly);
    past ``deadline`` (``time.monotonic()`` seconds) it is OUT_OF_TIME.
    """
    names = tuple(validators) if validators else default_validators()
    if NONE in names:
        return _NOT_VALIDATED
    return _combine(names, (VALIDATORS[name](domain, problem, plan, deadline) for name in names))


def validate_unread(
    domain_path: str,
    problem_path: str,
    plan: Plan,
    refused: str,
    validators: Sequence[str] | None = None,
    deadline: float | None = None,
) -> ValidationResult:
    """Validate a plan of input our reader refuses (``refused`` says why): only the validators that
    read the files themselves can run; the builtin simulator cannot."""
    names = tuple(validators) if validators else default_validators()
    if NONE in names:
        return _NOT_VALIDATED

    def run(name: str) -> ValidationResult:
        if name == "up":
            return validate_files_with_up(domain_path, problem_path, plan)
        if name == "val":
            return validate_files_with_val(domain_path, problem_path, plan, deadline)
        return ValidationResult(ValidationStatus.UNAVAILABLE, name, f"our reader refuses the input ({refused})")

    return _combine(names, (run(name) for name in names))


def _combine(names: Sequence[str], results: Iterable[ValidationResult]) -> ValidationResult:
    """Valid only if every validator that ran says so; the first invalid or out-of-time verdict stops."""
    ran: list[ValidationResult] = []
    unavailable: list[ValidationResult] = []
    for result in results:
        if result.status in (ValidationStatus.INVALID, ValidationStatus.OUT_OF_TIME):
            return result
        (ran if result.status is ValidationStatus.VALID else unavailable).append(result)
    if not ran:
        reasons = "; ".join(f"{r.validator}: {r.message}" for r in unavailable)
        return ValidationResult(ValidationStatus.UNAVAILABLE, "+".join(names), reasons)
    return ValidationResult(
        ValidationStatus.VALID, "+".join(r.validator for r in ran), ran[0].message, cost=ran[0].cost
    )
