"""A run's attempts summed up as one :class:`~relevance_plan.planning.results.PlanResult`.

Every front end ends a run of attempts here: :func:`summarise` takes what the
run established besides its attempts (:class:`RunFacts`: the problem, the
first selection, the planner and the scorer, the time relevance took), the
options and the attempts, and gives the verdict: the last attempt's plan if
it validated on the original problem, else why not.  The planner's exit code
is quoted only through the ``reason`` its adapter wrote, which says whose
code it is.
"""

from __future__ import annotations

import time
from collections.abc import Sequence
from dataclasses import dataclass, replace
from typing import Any

from relevance_plan.errors import counted
from relevance_plan.pddl.model import Problem
from relevance_plan.pddl.plans import Plan
from relevance_plan.planning.options import PlanOptions
from relevance_plan.planning.planners.base import PlannerStatus
from relevance_plan.planning.planners.supply import DEFAULT_PLANNER
from relevance_plan.planning.results import PLANNER_TO_PLAN_STATUS, Attempt, PlanResult, PlanStatus, kept_count
from relevance_plan.planning.validation import ValidationResult, ValidationStatus
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.selection.prune import Selection


@dataclass(frozen=True)
class RunFacts:
    """What a run established besides its attempts.

    ``task`` is None for input our reader refuses (no objects to count); ``started`` is on
    ``time.perf_counter()``; ``relevance_time`` is what scoring, pruning and widening took;
    ``refusal`` says why the input could not be pruned at all.
    """

    task: PlanningTask | None
    started: float
    relevance_time: float = 0.0
    selection: Selection | None = None
    planner: str = DEFAULT_PLANNER
    scorer: str | None = None
    refusal: str = ""
    planner_choice: str = ""
    compilations: tuple[str, ...] = ()


def summarise(facts: RunFacts, options: PlanOptions, attempts: Sequence[Attempt]) -> PlanResult:
    """The result of a run of attempts: the plan of the last attempt if it validated, else why not."""
    task, selection = facts.task, facts.selection
    total = len(task.problem.objects) if task is not None else None
    common: dict[str, Any] = dict(
        method=options.method,
        attempts=tuple(attempts),
        wall_time=time.perf_counter() - facts.started,
        relevance_time=facts.relevance_time,
        planner_time=sum(a.outcome.wall_time for a in attempts if not a.stopped),
        validation_time=sum(a.validation_time for a in attempts),
        objects_total=total,
        selection=selection,
        peak_memory_mb=max((a.outcome.peak_memory_mb for a in attempts), default=0.0),
        planner=facts.planner,
        scorer=facts.scorer,
        problem=task.problem if task is not None else None,
        refusal=facts.refusal,
        planner_choice=facts.planner_choice,
        compilations=facts.compilations,
        understood=selection.scores.understood if selection is not None else (),
    )
    common["objects_kept"] = kept_count(attempts, selection, total, options.method) if task is not None else None
    if not attempts:
        return PlanResult(status=PlanStatus.OUT_OF_TIME, message="no time left for planning", **common)
    last = next((a for a in reversed(attempts) if not a.stopped), attempts[-1])
    if last.outcome.status is PlannerStatus.SOLVED:
        return _validated(last, common)
    status, message = _failure(last, options)
    return PlanResult(status=status, message=message, log_tail=last.outcome.log_tail, **common)


def plan_cost_of(
    problem: Problem | None, plan: Plan, validation: ValidationResult, reported: float | None
) -> float | None:
    """A plan's cost as VAL's "Final value" gives it: the total-cost the validator found on the
    original problem; without action costs, a sequential plan's length (unit cost, the IPC
    convention); None for a timed plan without action costs (VAL would give its makespan) and for a
    plan nobody validated whose planner named no cost."""
    if validation.cost is not None:
        return validation.cost
    costs = problem is not None and (problem.metric is not None or ("total-cost",) in problem.numeric_init)
    if costs or problem is None:
        return reported  # not validated (--validator none), or a metric other than total-cost: the planner's word
    return None if plan.timed else float(len(plan))


def _validated(last: Attempt, common: dict[str, Any]) -> PlanResult:
    """The result when the last attempt found a plan: what its validation on the original said."""
    validation = last.validation
    if validation is not None and validation.accepted:
        cost = plan_cost_of(common["problem"], last.outcome.plan, validation, last.outcome.plan_cost)
        plan = replace(last.outcome.plan, cost=cost) if cost is not None else last.outcome.plan
        checked = f"validated on the original problem ({validation.validator})"
        return PlanResult(
            status=PlanStatus.SOLVED,
            plan=plan,
            plan_cost=cost,
            plans=last.outcome.plans,
            validation=validation,
            message=f"plan of {counted(len(plan), 'step')} "
            + (checked if validation.valid else "NOT validated (--validator none)"),
            **common,
        )
    if validation is not None and validation.status is ValidationStatus.OUT_OF_TIME:
        status = PlanStatus.OUT_OF_TIME
        message = f"a plan was found but validating it ran out of time: {validation.message}"
    elif validation is not None and validation.status is ValidationStatus.UNAVAILABLE:
        status = PlanStatus.VALIDATOR_UNAVAILABLE
        message = f"a plan was found but NO VALIDATOR COULD RUN: {validation.message}"
    else:
        status = PlanStatus.NO_VALID_PLAN
        message = f"the plan failed validation on the original problem: {validation.message if validation else ''}"
    return PlanResult(status=status, validation=validation, message=message, **common)


# Verdicts whose message ends with the planner's last line of output.
_QUOTES_OUTPUT = (PlanStatus.PLANNER_ERROR, PlanStatus.INPUT_ERROR, PlanStatus.UNSUPPORTED)


def _failure(last: Attempt, options: PlanOptions) -> tuple[PlanStatus, str]:
    """The verdict and its message when the last attempt found no plan.

    The planner's exit code is quoted only through its ``reason``, which
    says whose code it is and what it means.
    """
    outcome = last.outcome
    status = PLANNER_TO_PLAN_STATUS.get(outcome.status, PlanStatus.PLANNER_ERROR)
    because = f" ({outcome.reason})" if outcome.reason else ""
    if status is PlanStatus.UNSOLVABLE and not last.full:
        # Only the full problem's unsolvability says anything about the user's problem.
        why = "widening is off" if not options.widen else "no time was left to widen it"
        return PlanStatus.NO_VALID_PLAN, f"the pruned problem is unsolvable (pruning removed something needed; {why})"
    if status is PlanStatus.UNSOLVABLE:
        return status, "the problem is unsolvable"
    if status is PlanStatus.PLANNER_CONFIG_ERROR:
        return status, f"{outcome.planner} rejected --planner-config '{options.planner_config}'{because}"
    message = f"planner: {outcome.status.value}{because}"
    output = outcome.log_tail.strip().splitlines()
    if output and status in _QUOTES_OUTPUT:
        message += f"; last planner output: {output[-1].strip()[:200]}"
    return status, message
