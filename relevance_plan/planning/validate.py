"""Plan validation against the ORIGINAL problem.

Three validators, in a registry:
- ``builtin``: the simulator of ``pddl/simulator.py`` (ADL, numeric fluents,
  derived predicates, PDDL 2.1 timed plans).  It costs milliseconds, so it
  runs on every plan, however large the problem, and it watches the deadline.
- ``up``: unified-planning's validators (sequential, or time-triggered for
  timed plans), reading the original files with UP's reader (seconds on
  large problems).
- ``val``: VAL's ``Validate`` when it is on PATH.
A validator that cannot run says so (``UNAVAILABLE``); that is never read as
valid or invalid.
"""

from __future__ import annotations

import enum
import shutil
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass

from relevance_plan.errors import SimulationTimeout
from relevance_plan.pddl.model import Domain, Problem
from relevance_plan.pddl.plans import Plan, format_plan
from relevance_plan.pddl.simulator import simulate


class ValidationStatus(enum.Enum):
    VALID = "valid"
    INVALID = "invalid"
    UNAVAILABLE = "unavailable"
    OUT_OF_TIME = "out-of-time"


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


# --------------------------------------------------------------------------- builtin


def validate_builtin(domain: Domain, problem: Problem, plan: Plan, deadline: float | None = None) -> ValidationResult:
    try:
        result = simulate(domain, problem, plan, deadline)
    except SimulationTimeout as error:
        return ValidationResult(ValidationStatus.OUT_OF_TIME, "builtin", error.message)
    status = ValidationStatus.VALID if result.valid else ValidationStatus.INVALID
    return ValidationResult(status, "builtin", result.message, result.failed_step, result.cost)


# --------------------------------------------------------------------------- unified-planning


def validate_with_up(domain: Domain, problem: Problem, plan: Plan, deadline: float | None = None) -> ValidationResult:
    """Validate with unified-planning's validators, from the original files."""
    if domain.path is None or problem.path is None:
        return ValidationResult(ValidationStatus.UNAVAILABLE, "up", "needs the domain and problem files on disk")
    try:
        from unified_planning.engines.results import ValidationResultStatus
        from unified_planning.io import PDDLReader
        from unified_planning.shortcuts import get_environment
    except ImportError as error:  # pragma: no cover - depends on the installation
        return ValidationResult(ValidationStatus.UNAVAILABLE, "up", f"unified-planning not importable: {error}")
    get_environment().credits_stream = None
    try:
        up_problem = PDDLReader().parse_problem(domain.path, problem.path)
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
        duration = None if step.duration is None else Fraction(str(step.duration))
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
    from relevance_plan.planning.process import run_val  # subprocess access lives in the process module

    if not val_available():
        return ValidationResult(ValidationStatus.UNAVAILABLE, "val", "VAL's Validate is not on PATH")
    if domain.path is None or problem.path is None:
        return ValidationResult(ValidationStatus.UNAVAILABLE, "val", "needs the domain and problem files on disk")
    timeout = 60.0 if deadline is None else max(0.1, deadline - time.monotonic())
    ok, message = run_val(domain.path, problem.path, format_plan(plan), timeout=timeout)
    if ok is None:
        return ValidationResult(ValidationStatus.UNAVAILABLE, "val", message)
    return ValidationResult(ValidationStatus.VALID if ok else ValidationStatus.INVALID, "val", message)


Validator = Callable[[Domain, Problem, Plan, "float | None"], ValidationResult]

VALIDATORS: dict[str, Validator] = {
    "builtin": validate_builtin,
    "up": validate_with_up,
    "val": validate_with_val,
}


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
    ran: list[ValidationResult] = []
    unavailable: list[ValidationResult] = []
    for name in names:
        result = VALIDATORS[name](domain, problem, plan, deadline)
        if result.status in (ValidationStatus.INVALID, ValidationStatus.OUT_OF_TIME):
            return result
        (ran if result.status is ValidationStatus.VALID else unavailable).append(result)
    if not ran:
        reasons = "; ".join(f"{r.validator}: {r.message}" for r in unavailable)
        return ValidationResult(ValidationStatus.UNAVAILABLE, "+".join(names), reasons)
    return ValidationResult(
        ValidationStatus.VALID, "+".join(r.validator for r in ran), ran[0].message, cost=ran[0].cost
    )
