"""unified-planning's validators (sequential, or time-triggered for timed plans) as a validator.

They read the original files with UP's own reader (seconds on large
problems), so they judge a plan independently of our reader; a problem
without files on disk cannot be judged by them.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from relevance_plan.pddl.model import Domain, Problem
from relevance_plan.pddl.plans import Plan
from relevance_plan.planning.validation.verdicts import ValidationResult, ValidationStatus


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
