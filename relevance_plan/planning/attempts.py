"""The attempt loop: plan on a selection, validate on the original problem, widen, try again.

:func:`run_attempts` is the loop itself.  Every front end calls it: ``run``'s
:func:`~relevance_plan.planning.run.plan_task`, the live session and the
unified-planning engine.  It does not know how a planner is called: the
front end's :class:`AttemptLoop` carries a function that runs the planner on
one object set (``plan_task`` writes the pruned file and calls its planner;
the unified-planning engine restricts a UP problem and calls its inner
engine).  When a pruned problem turns out unsolvable, gives an invalid plan
or uses up its share of the time, the selection is widened
(``relevance.selection.prune.widen``) and the planner retries; the last attempt is the
full problem, so every solvable problem is solved given time.

Every run arrives as a :class:`RunOutcome` whose status the planner's adapter
already classified; the loop names no planner.  A planner that cannot prove
a pruned problem unsolvable gets :class:`Budgets` for its pruned attempts.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace

from relevance_plan.errors import OutOfTimeError
from relevance_plan.pddl.formatter import format_atom
from relevance_plan.planning.options import PlanOptions
from relevance_plan.planning.planners.base import PlannerStatus, RunOutcome
from relevance_plan.planning.race import Race
from relevance_plan.planning.results import Attempt, AttemptStatus, RunRecord
from relevance_plan.planning.validation import ValidationResult, ValidationStatus, validate_plan
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.scoring.knowledge import KnowledgeModel
from relevance_plan.relevance.selection.prune import Selection, Widening, next_witnesses, widen

# The least a planner is given when the --timeout is nearly out: a chance to finish, yet with the
# watchdog's grace a run still ends close to the --timeout.
LAST_SECONDS = 0.2
# A planner that cannot prove a pruned problem unsolvable searches it until its time runs out, so
# its pruned attempts get budgets: the first this many times what scoring and pruning took (the
# relaxed check among them), at least MIN_BUDGET seconds, and each widening's twice the last.
BUDGET_PER_PRUNING = 4.0
MIN_BUDGET = 1.0
BUDGET_GROWTH = 2.0


@dataclass(frozen=True)
class Budgets:
    """The time limits of pruned attempts for a planner that cannot prove one unsolvable.

    The ``n``-th pruned attempt (from 0) gets ``first * growth ** n`` seconds (never more than
    the loop would give it anyway); the full problem gets what is left.  A pruned attempt whose
    budget runs out is taken as a wrong guess: the selection widens at once.
    """

    first: float
    growth: float = BUDGET_GROWTH

    def limit(self, pruned_before: int) -> float:
        return self.first * self.growth**pruned_before

    @classmethod
    def after(cls, pruning_seconds: float) -> Budgets:
        return cls(max(MIN_BUDGET, BUDGET_PER_PRUNING * pruning_seconds))


# Planner results that say nothing about the object set: retrying a wider set
# is pointless, so the loop goes straight to the full problem.
_PLANNER_FAULTS = (PlannerStatus.INPUT_ERROR, PlannerStatus.PLANNER_CRASH)
# A planner that cannot take the domain's features, or rejects its own
# configuration, would fail the full problem the same way: stop.
_PLANNER_STOPS = (PlannerStatus.UNSUPPORTED, PlannerStatus.PLANNER_CONFIG_ERROR)


# Runs the planner on one object set (None: the user's full problem) within a
# time limit (None: no limit) and returns its outcome.
PlannerCall = Callable[["Selection | None", "float | None"], RunOutcome]


@dataclass(frozen=True)
class AttemptLoop:
    """What every attempt of one :func:`run_attempts` reads.

    The deadline is ``started + options.timeout`` (``started`` on ``time.perf_counter()``).
    ``record`` hears each step and keeps each attempt as it ends (a new one when None).  With
    ``race`` (the full problem planned since the start, in a thread), the pruned attempts may use
    all the time left; the full problem is never planned twice, and whichever side decides first
    ends the other.
    """

    task: PlanningTask
    call_planner: PlannerCall
    options: PlanOptions
    started: float
    model: KnowledgeModel | None = None
    record: RunRecord | None = None
    race: Race[Attempt] | None = None

    def __post_init__(self) -> None:
        if self.record is None:
            object.__setattr__(self, "record", RunRecord(self.options.method))

    @property
    def recorder(self) -> RunRecord:
        assert self.record is not None  # set when made
        return self.record

    @property
    def deadline(self) -> float | None:
        """The loop's deadline on ``time.perf_counter()``; None: no limit."""
        return None if self.options.timeout is None else self.started + self.options.timeout

    @property
    def total(self) -> int:
        return len(self.task.problem.objects)

    def say(self, message: str) -> None:
        self.recorder.say(message)

    def time_left(self) -> bool:
        deadline = self.deadline
        return deadline is None or time.perf_counter() < deadline

    def pruned(self, selection: Selection | None) -> Selection | None:
        """``selection`` when it leaves objects out; None for the full problem."""
        return selection if selection is not None and len(selection.kept) < self.total else None


@dataclass(frozen=True)
class _AttemptState:
    """Where the loop stands between attempts: the next selection (None: the full problem), the
    objects widening added back, how many pruned attempts ran, and their budgets."""

    selection: Selection | None
    added_back: frozenset[str] = frozenset()
    pruned_before: int = 0
    budgets: Budgets | None = None


def run_attempts(
    loop: AttemptLoop, selection: Selection | None, budgets: Budgets | None = None
) -> tuple[list[Attempt], float]:
    """Plan on ``selection`` (None: the full problem), widening after each failure.

    Returns the attempts and the seconds spent widening.  Beside a race (``loop.race``), when
    the race's side decides first it is the last attempt, and a pruned attempt the race stopped
    is listed as ``stopped``.  With ``budgets`` (a planner that cannot prove a pruned problem
    unsolvable), each pruned attempt is held to its budget, with or without a race.
    """
    race, record, options = loop.race, loop.recorder, loop.options
    state = _AttemptState(selection, budgets=budgets)
    attempts: list[Attempt] = []
    widening_time = 0.0
    while loop.time_left() and not (race is not None and race.won):
        number = len(attempts) + 1
        pruned = loop.pruned(state.selection)
        if pruned is None and race is not None:
            if state.budgets is not None and _ran_out_of_budget(attempts):
                # the full problem is planned beside: rather than wait for it, the widest pruned
                # selection, stopped at its budget, gets the time left
                again = attempts[-1].selection
                assert again is not None
                loop.say(f"attempt {number}: {len(again.kept)} of {loop.total} objects again, with the time left")
                state = replace(state, selection=again, budgets=None)
                continue
            loop.say(f"attempt {number}: the full problem, planned since the start")
            attempts.append(replace(race.wait(), number=number))
            record.attempted(attempts[-1])
            return attempts, widening_time
        attempt = _attempt(loop, number, pruned, state)
        attempts.append(attempt)
        record.attempted(attempt)
        if pruned is not None:
            state = replace(state, pruned_before=state.pruned_before + 1)
        if _decided(attempt, options):
            break
        if attempt.outcome.status in _PLANNER_FAULTS:
            loop.say(
                f"the planner reported {attempt.outcome.status.value} on a pruned problem: trying the full problem"
            )
            state = replace(state, selection=None)
            continue
        assert pruned is not None  # _decided ends the loop after the full problem
        widen_started = time.perf_counter()
        try:
            widened, added_back = widen(
                pruned,
                Widening(options.widen_factor, _goal_filter(options), step=state.pruned_before - 1),
                state.added_back,
                loop.model,
            )
        except OutOfTimeError:
            break  # the --timeout ran out while widening: as when it runs out between attempts
        finally:
            widening_time += time.perf_counter() - widen_started
        _say_next_witnesses(loop.say, pruned, widened)
        state = replace(state, selection=widened, added_back=added_back)
    if race is not None and race.won and not (attempts and attempts[-1].status is AttemptStatus.SOLVED):
        attempts.append(replace(race.wait(), number=len(attempts) + 1))
        record.attempted(attempts[-1])
    return attempts, widening_time


def _goal_filter(options: PlanOptions) -> bool:
    return options.goal_filter and options.narrows_first


def _ran_out_of_budget(attempts: Sequence[Attempt]) -> bool:
    """Whether the last attempt was a pruned one that ran out of its time."""
    return bool(attempts) and attempts[-1].selection is not None and attempts[-1].status is AttemptStatus.OUT_OF_TIME


def _time_limit(loop: AttemptLoop, pruned: Selection | None, state: _AttemptState) -> float | None:
    """The attempt's time limit: a share of what is left for a pruned attempt that may widen (all of
    it beside a race), all of it for the last; a pruned attempt's budget when it has one."""
    final = pruned is None or not loop.options.widen
    deadline = loop.deadline
    if deadline is None:
        limit = None
    else:
        remaining = max(deadline - time.perf_counter(), LAST_SECONDS)
        limit = remaining if final or loop.race is not None else max(1.0, remaining * loop.options.first_share)
    if state.budgets is not None and pruned is not None and not final:
        budget = state.budgets.limit(state.pruned_before)
        limit = budget if limit is None else min(limit, budget)
    return limit


def _attempt(loop: AttemptLoop, number: int, pruned: Selection | None, state: _AttemptState) -> Attempt:
    """One attempt on ``pruned`` (None: the full problem), its plan validated on the original."""
    kept = loop.total if pruned is None else len(pruned.kept)
    limit = _time_limit(loop, pruned, state)
    loop.recorder.attempting(number, pruned, limit)
    loop.say(
        f"attempt {number}: the full problem" if pruned is None else f"attempt {number}: {kept} of {loop.total} objects"
    )
    outcome = loop.call_planner(pruned, limit)
    stopped = loop.race is not None and loop.race.won and not outcome.solved
    if stopped:
        loop.say("the full problem, planned since the start, decided first: the pruned attempt was stopped")
        validation, validation_time = None, 0.0
    else:
        outcome, validation, validation_time = validate_outcome(loop.task, outcome, loop.options, loop.deadline)
    attempt = Attempt(
        number=number,
        objects_kept=kept,
        thresholds=None if pruned is None else pruned.thresholds,
        added_back=len(state.added_back),
        outcome=outcome,
        validation=validation,
        time_limit=limit,
        validation_time=validation_time,
        selection=pruned,
    )
    return attempt.as_stopped() if stopped else attempt


def _decided(attempt: Attempt, options: PlanOptions) -> bool:
    """Whether the loop ends after ``attempt``: it was stopped, its plan was valid (or could not be
    judged), it was the last one widening allows, or the planner cannot take the problem at all."""
    if attempt.stopped:
        return True
    if attempt.validation is not None and attempt.validation.status is not ValidationStatus.INVALID:
        return True  # valid, out of time, or no validator could run: report it, never retry blindly
    return not options.widen or attempt.selection is None or attempt.outcome.status in _PLANNER_STOPS


def race_decides(attempt: Attempt) -> bool:
    """A full-problem attempt ends the run: a valid plan, or proof that the problem has none."""
    return attempt.wins


def validate_outcome(
    task: PlanningTask, outcome: RunOutcome, options: PlanOptions, deadline: float | None
) -> tuple[RunOutcome, ValidationResult | None, float]:
    """The outcome (an anytime run's: its valid plans only, the last valid one as its plan), the
    validation of its plan on the original problem, and the seconds validating took."""
    if outcome.status is not PlannerStatus.SOLVED:
        return outcome, None, 0.0
    started = time.perf_counter()
    # the validator's clock is time.monotonic(); the loop's deadline is on perf_counter()
    until = None if deadline is None else time.monotonic() + max(deadline - started, 0.5)
    if not outcome.plans:
        validation = validate_plan(task.domain, task.problem, outcome.plan, options.validators, until)
        return outcome, validation, time.perf_counter() - started
    checked = [
        (plan, validate_plan(task.domain, task.problem, plan, options.validators, until)) for plan in outcome.plans
    ]
    valid = tuple(plan for plan, validation in checked if validation.accepted)
    if valid:
        validation = next(validation for plan, validation in reversed(checked) if validation.accepted)
        outcome = replace(outcome, plan=valid[-1], plan_cost=valid[-1].cost, plans=valid)
    else:
        validation = checked[-1][1]
    return outcome, validation, time.perf_counter() - started


def full_attempt(
    number: int,
    objects_kept: int,
    deadline: float | None,
    run: Callable[[float | None], RunOutcome],
    validate: Callable[[RunOutcome], tuple[RunOutcome, ValidationResult | None, float]],
    raced: bool = False,
) -> Attempt:
    """An attempt on the full problem with all the time left before ``deadline`` (``perf_counter``):
    ``run`` plans within a limit, ``validate`` judges the outcome (and says the seconds it took)."""
    limit = None if deadline is None else max(deadline - time.perf_counter(), LAST_SECONDS)
    outcome, validation, validation_time = validate(run(limit))
    return Attempt(
        number=number,
        objects_kept=objects_kept,
        thresholds=None,
        added_back=0,
        outcome=outcome,
        validation=validation,
        time_limit=limit,
        validation_time=validation_time,
        raced=raced,
    )


def witness_list(selection: Selection) -> str:
    """``item3_vase for (classrelation vase microwave), ...`` (``Selection.witnesses``)."""
    spelling = selection.task.problem.spelling
    return ", ".join(f"{spelling.object(name)} for {format_atom(goal, spelling)}" for goal, name in selection.witnesses)


def _say_next_witnesses(say: Callable[[str], None], failed: Selection, widened: Selection) -> None:
    """Which witnesses a failed attempt had, and the next candidates the widened selection adds."""
    added = [name for name in next_witnesses(failed.task, failed.kept) if name in widened.kept]
    if failed.witnesses and added:
        show = failed.task.problem.display
        say(f"no plan with the witnesses {witness_list(failed)}: widening adds {', '.join(map(show, added))}")
