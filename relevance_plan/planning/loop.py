"""Prune, plan, validate on the original problem, and widen until solved: the one attempt loop.

Methods: ``pure`` (the planner on the original problem), ``relevance``
(knowledge-model scorer when a model applies, else the goal scorer),
``random`` (the paper's baseline) and ``oracle`` (the generator's necessary
set).  Every plan is checked against the ORIGINAL problem before it is
reported.  When a pruned problem turns out unsolvable, gives an invalid plan
or uses up its share of the time, the selection is widened
(``relevance.prune.widen``) and the planner retries; the last attempt is the
full problem, so every solvable problem is solved given time.

:func:`run_attempts` is the loop itself.  It does not know how a planner is
called: the front end passes a function that runs the planner on one object
set (``plan_task`` writes the pruned file and calls a registered planner; the
unified-planning engine restricts a UP problem and calls its inner engine).
Both then turn the attempts into a :class:`PlanResult` with :func:`summarise`.

The loop knows no planner by name.  What is a planner's own (the PDDL it
takes, its exit codes, its plan files) is its adapter's (``planners/``):
``plan_task`` lets the planner ``check`` the problem before any work, and
every run arrives as a :class:`RunOutcome` whose status the adapter already
classified and whose ``reason`` says what the planner reported, in its terms.
The default planner (``auto``) is chosen there too, by the problem's features.

Nothing a planner can solve is refused: when our reader refuses the input
(PDDL+, object fluents) or the relevance analysis cannot take it, the
planner gets the full problem and the result says why it was not pruned.
"""

from __future__ import annotations

import contextlib
import contextvars
import os
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, fields, replace
from pathlib import Path
from typing import Any

from relevance_plan.errors import OutOfTimeError, UnsupportedFeatureError, UsageError
from relevance_plan.io import load_domain, load_problem, scratch_directory, write_text_atomic
from relevance_plan.pddl.model import Problem
from relevance_plan.pddl.plans import Plan
from relevance_plan.pddl.sexpr import collection_paused
from relevance_plan.planning.planners.auto import FallbackPlanner
from relevance_plan.planning.planners.base import Planner, PlannerStatus, RunOutcome
from relevance_plan.planning.planners.preparation import PreparedPlanner, prepare_planner, with_planner_args
from relevance_plan.planning.planners.registry import (
    DEFAULT_PLANNER,
    DEFAULT_PLANNER_CONFIG,
    await_warm,
    make_planner,
    offer_early_run,
    planner_for,
    planner_for_unread,
    release_warm,
    take_early_run,
    warm_planners,
    warm_up,
)
from relevance_plan.planning.race import Race
from relevance_plan.planning.results import (
    PLANNER_TO_PLAN_STATUS,
    Attempt,
    AttemptStatus,
    PlanResult,
    PlanStatus,
)
from relevance_plan.planning.validate import (
    ValidationResult,
    ValidationStatus,
    check_validators,
    validate_plan,
    validate_unread,
)
from relevance_plan.progress import ProgressCallback, ProgressEvent
from relevance_plan.relevance.knowledge import KnowledgeModel
from relevance_plan.relevance.prune import Selection, Thresholds, Widening, widen
from relevance_plan.relevance.setup import Scoring, ScoringOptions, score_problem
from relevance_plan.relevance.task import PlanningTask
from relevance_plan.supervision.process import CancelScope, cancel_scope

METHODS = ("relevance", "pure", "random", "oracle")
# The least a planner is given when the --timeout is nearly out: a chance to finish, yet with the
# watchdog's grace a run still ends close to the --timeout.
LAST_SECONDS = 0.2
# Limits beyond these are typos: the watchdog's timer cannot even hold much more.
MAX_TIMEOUT = 1e6
# Below 16 MB Python cannot start the planner at all; above 1 PB is absurd.
MIN_MEMORY_MB = 16
MAX_MEMORY_MB = 1 << 30
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


@dataclass(frozen=True)
class PlanOptions:
    """Everything that decides how one problem is planned; every front end builds one."""

    method: str = "relevance"
    planner: str = DEFAULT_PLANNER  # a planner name as planning.planners.make_planner takes it
    planner_config: str = DEFAULT_PLANNER_CONFIG
    timeout: float | None = 120.0  # None: no limit (the UP engine without a timeout)
    memory_limit_mb: int | None = None
    thresholds: Thresholds = field(default_factory=Thresholds)
    widen: bool = True  # after a failed attempt, widen the selection and try again
    widen_factor: float = 0.5  # thresholds shrink by this factor at each widening
    first_share: float = 0.5  # share of the remaining time a pruned attempt may use
    scorer: str | None = None  # overrides the method's scorer
    goal_filter: bool = True  # for 'relevance': drop relevant objects no goal-directed action can use
    prefer_free: bool = True  # for 'relevance' with a model: first try without blocked alternatives
    economical: bool = True  # for 'relevance': first try, of many candidates for a role, those a relaxed plan needs
    model_path: str | None = None
    objective: str | None = None
    model_task: str | None = None
    human: str | None = None
    seed: int = 0
    validators: tuple[str, ...] | None = None
    planner_args: tuple[str, ...] = ()  # appended to the planner's command line (--planner-args)
    race: bool = False  # plan the full problem beside the pruned attempts (planning.race); takes a second core

    def __post_init__(self) -> None:
        if self.method not in METHODS:
            raise UsageError(f"unknown method '{self.method}' (choose from: {', '.join(METHODS)})")
        if self.timeout is not None and not 0 < self.timeout < float("inf"):
            raise UsageError(f"--timeout must be a positive number of seconds, got {self.timeout}")
        if self.timeout is not None and self.timeout > MAX_TIMEOUT:
            raise UsageError(f"--timeout must be at most {MAX_TIMEOUT:g} s (about 11 days), got {self.timeout}")
        if self.memory_limit_mb is not None and self.memory_limit_mb < MIN_MEMORY_MB:
            raise UsageError(f"--memory-limit must be at least {MIN_MEMORY_MB} MB, got {self.memory_limit_mb}")
        if self.memory_limit_mb is not None and self.memory_limit_mb > MAX_MEMORY_MB:
            raise UsageError(f"--memory-limit must be at most {MAX_MEMORY_MB} MB (1 PB), got {self.memory_limit_mb}")
        if not 0.0 < self.widen_factor < 1.0:
            raise UsageError(f"widen factor must be in (0, 1), got {self.widen_factor}")
        if not 0.0 < self.first_share <= 1.0:
            raise UsageError(f"first share must be in (0, 1], got {self.first_share}")
        if self.validators:
            check_validators(self.validators)

    @property
    def scoring(self) -> ScoringOptions:
        """The scoring part of these options (the fields share their names)."""
        return ScoringOptions(**{name: getattr(self, name) for name in SCORING_FIELDS})

    @classmethod
    def from_scoring(cls, scoring: ScoringOptions, **planning: Any) -> PlanOptions:
        return cls(**{name: getattr(scoring, name) for name in SCORING_FIELDS}, **planning)

    @property
    def narrows_first(self) -> bool:
        """Whether the first selection is narrowed (goal filter, blocked alternatives set aside)."""
        return self.method == "relevance"


PLAN_OPTION_FIELDS = tuple(f.name for f in fields(PlanOptions))
SCORING_FIELDS = tuple(f.name for f in fields(ScoringOptions))
assert set(SCORING_FIELDS) <= set(PLAN_OPTION_FIELDS), "PlanOptions must carry every scoring option"


# Planner results that say nothing about the object set: retrying a wider set
# is pointless, so the loop goes straight to the full problem.
_PLANNER_FAULTS = (PlannerStatus.INPUT_ERROR, PlannerStatus.PLANNER_CRASH)
# A planner that cannot take the domain's features, or rejects its own
# configuration, would fail the full problem the same way: stop.
_PLANNER_STOPS = (PlannerStatus.UNSUPPORTED, PlannerStatus.PLANNER_CONFIG_ERROR)


# Runs the planner on one object set (None: the user's full problem) within a
# time limit (None: no limit) and returns its outcome.
PlannerCall = Callable[["Selection | None", "float | None"], RunOutcome]


def run_attempts(
    task: PlanningTask,
    selection: Selection | None,
    call_planner: PlannerCall,
    options: PlanOptions,
    *,
    started: float,
    model: KnowledgeModel | None = None,
    progress: ProgressCallback | None = None,
    race: Race[Attempt] | None = None,
    budgets: Budgets | None = None,
) -> tuple[list[Attempt], float]:
    """Plan on ``selection`` (None: the full problem), widening after each failure.

    Returns the attempts and the seconds spent widening.  The deadline is
    ``started + options.timeout``.  With ``race`` (the full problem planned
    since the start, in a thread), the pruned attempts may use all the time
    left; the full problem is never planned twice, and whichever side
    decides first ends the other (the race's attempt is then the last; a
    pruned attempt the race stopped is listed as ``stopped``).  With
    ``budgets`` (a planner that cannot prove a pruned problem unsolvable),
    each pruned attempt is held to its budget, with or without a race.
    """
    say = _teller(progress)
    total = len(task.problem.objects)
    deadline = None if options.timeout is None else started + options.timeout
    goal_filter = options.goal_filter and options.narrows_first
    attempts: list[Attempt] = []
    widening_time = 0.0
    extra: frozenset[str] = frozenset()
    current = selection
    pruned_before = 0
    while deadline is None or time.perf_counter() < deadline:
        if race is not None and race.won:
            break
        number = len(attempts) + 1
        pruned = current if current is not None and len(current.kept) < total else None
        full = pruned is None
        last = attempts[-1] if attempts else None
        if full and race is not None and budgets is not None and last is not None and last.selection is not None:
            if last.status is AttemptStatus.OUT_OF_TIME:
                # the full problem is planned beside: rather than wait for it, the widest pruned
                # selection, stopped at its budget, gets the time left
                say(f"attempt {number}: {len(last.selection.kept)} of {total} objects again, with the time left")
                current, budgets = last.selection, None
                continue
        if full and race is not None:
            say(f"attempt {number}: the full problem, planned since the start")
            attempts.append(replace(race.wait(), number=number))
            return attempts, widening_time
        kept = total if pruned is None else len(pruned.kept)
        say(f"attempt {number}: the full problem" if full else f"attempt {number}: {kept} of {total} objects")
        final = full or not options.widen
        if deadline is None:
            limit = None
        else:
            remaining = max(deadline - time.perf_counter(), LAST_SECONDS)
            limit = remaining if final or race is not None else max(1.0, remaining * options.first_share)
        if budgets is not None and pruned is not None and not final:
            budget = budgets.limit(pruned_before)
            limit = budget if limit is None else min(limit, budget)
        if pruned is not None:
            pruned_before += 1
        outcome = call_planner(pruned, limit)
        stopped = race is not None and race.won and not outcome.solved
        if stopped:
            say("the full problem, planned since the start, decided first: the pruned attempt was stopped")
            validation, validation_time = None, 0.0
        else:
            outcome, validation, validation_time = _validate(task, outcome, options, deadline)
        attempts.append(
            Attempt(
                number=number,
                objects_kept=kept,
                thresholds=None if pruned is None else pruned.thresholds,
                added_back=len(extra),
                outcome=outcome,
                validation=validation,
                time_limit=limit,
                validation_time=validation_time,
                selection=pruned,
                stopped=stopped,
            )
        )
        if stopped:
            break
        if validation is not None and validation.status is not ValidationStatus.INVALID:
            break  # valid, out of time, or no validator could run: report it, never retry blindly
        if not options.widen or pruned is None:
            break
        if outcome.status in _PLANNER_STOPS:
            break
        if outcome.status in _PLANNER_FAULTS:
            say(f"the planner reported {outcome.status.value} on a pruned problem: trying the full problem")
            current = None
            continue
        widen_started = time.perf_counter()
        try:
            current, extra = widen(pruned, Widening(options.widen_factor, goal_filter), extra, model)
        except OutOfTimeError:
            break  # the --timeout ran out while widening: as when it runs out between attempts
        finally:
            widening_time += time.perf_counter() - widen_started
    if race is not None and race.won and not (attempts and attempts[-1].status is AttemptStatus.SOLVED):
        attempts.append(replace(race.wait(), number=len(attempts) + 1))
    return attempts, widening_time


def _answering(prepared: PreparedPlanner, attempts: Sequence[Attempt]) -> str:
    """The planner that gave the last answer: auto's next one when its first gave up."""
    deciding = [a for a in attempts if not a.stopped]
    last = deciding[-1].outcome.planner if deciding else ""
    return last if isinstance(prepared.planner, FallbackPlanner) and last else prepared.name


def _race_decides(attempt: Attempt) -> bool:
    """A full-problem attempt ends the run: a valid plan, or proof that the problem has none."""
    return attempt.status in (AttemptStatus.SOLVED, AttemptStatus.UNSOLVABLE)


def _teller(progress: ProgressCallback | None) -> Callable[[str], None]:
    """A function that reports one step as a message (nothing when nobody listens)."""
    if progress is None:
        return lambda message: None
    return lambda message: progress(ProgressEvent(message=message))


def _validate(
    task: PlanningTask, outcome: RunOutcome, options: PlanOptions, deadline: float | None
) -> tuple[RunOutcome, ValidationResult | None, float]:
    """The outcome (an anytime run's: its valid plans only, the last valid one as its plan), and
    the validation of its plan on the original problem."""
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


def plan_task(
    domain_path: str | Path,
    problem_path: str | Path,
    options: PlanOptions = PlanOptions(),
    progress: ProgressCallback | None = None,
    keep_work: str | os.PathLike[str] | None = None,
) -> PlanResult:
    """Run one method on one problem; the plan returned is always validated on the original.

    With ``keep_work``, each attempt's planner files stay in ``keep_work/attempt-N``.
    """
    # the run's facts die with it: no pass over them needed; its warm planners too
    with collection_paused(), warm_planners(options.memory_limit_mb):
        return _plan_task(domain_path, problem_path, options, progress, keep_work)


def _plan_task(
    domain_path: str | Path,
    problem_path: str | Path,
    options: PlanOptions,
    progress: ProgressCallback | None,
    keep_work: str | os.PathLike[str] | None,
) -> PlanResult:
    say = _teller(progress)
    started = time.perf_counter()
    domain_path, problem_path = str(domain_path), str(problem_path)
    planner = make_planner(options.planner, options.planner_config)
    if keep_work is None:
        warm_up(planner)  # a named engine starts now, beside the reading and scoring
    reading = None if options.timeout is None else time.monotonic() + options.timeout
    try:
        domain = load_domain(domain_path, deadline=reading)
        task = PlanningTask(domain, load_problem(problem_path, domain, deadline=reading), deadline=reading)
    except OutOfTimeError:
        return _ran_out("reading the domain and problem", started, options, 0)
    except UnsupportedFeatureError as refused:
        return _plan_unread(domain_path, problem_path, planner, refused, options, started, say)
    total = len(task.problem.objects)
    planner, choice = planner_for(planner, task.domain, task.problem)
    if choice:
        say(f"planner: {planner.name} (auto: {choice})")
        if keep_work is None:
            warm_up(planner)
    # the planner's check; what it lacks and can be compiled away is compiled away at each attempt
    prepared = prepare_planner(planner, task.domain, task.problem, problem_path, options.planner_args, keep_work, say)
    overran = _overran("reading the domain and problem", started, options, total)
    if overran is not None:
        return overran

    if not options.validators or "builtin" in options.validators:
        # the plan is checked once the planner has ended: import the checker now, while it runs
        import relevance_plan.pddl.simulator  # noqa: F401

    # the launcher's early run of the full problem: the first call on the full problem may take it
    # over; offered() stops it after that call, and the end of the run in every case
    early = take_early_run()
    if early is not None:  # the run began when the launcher started the driver: times and limits count from there
        started = min(started, early.spawned.started + time.perf_counter() - time.monotonic())
    with scratch_directory() as scratch, offer_early_run(early):

        def call_planner(objects: Selection | None, limit: float | None) -> RunOutcome:
            if objects is None:
                with offer_early_run(early):
                    return prepared.run(
                        domain_path, problem_path, time_limit=limit, memory_limit_mb=options.memory_limit_mb
                    )
            target = str(write_text_atomic(Path(scratch) / f"pruned-{len(objects.kept)}.pddl", objects.text))
            return prepared.run(domain_path, target, time_limit=limit, memory_limit_mb=options.memory_limit_mb)

        def plan_full_problem() -> Attempt:
            deadline = None if options.timeout is None else started + options.timeout
            limit = None if deadline is None else max(deadline - time.perf_counter(), LAST_SECONDS)
            outcome = call_planner(None, limit)
            outcome, validation, validation_time = _validate(task, outcome, options, deadline)
            return Attempt(
                number=0,
                objects_kept=total,
                thresholds=None,
                added_back=0,
                outcome=outcome,
                validation=validation,
                time_limit=limit,
                validation_time=validation_time,
                raced=True,
            )

        own_runs = CancelScope()
        racing = options.race and options.method != "pure"
        race: Race[Attempt] | None = None
        pruned_side: contextlib.AbstractContextManager[object] = contextlib.nullcontext()
        if racing:
            say("racing: the full problem is planned beside the pruned attempts")
            # the race's thread takes the run's warm planners, as planning without pruning would have
            # them; the pruned attempts get their own: copies of those, asked for before the full
            # problem keeps them busy, and let go if nothing is pruned
            full_side = contextvars.copy_context()
            pruned_side = warm_planners(options.memory_limit_mb, beside=True)
        try:
            with cancel_scope(own_runs), pruned_side:
                if racing:
                    if keep_work is None:
                        warm_up(planner)
                    race = Race(plan_full_problem, _race_decides, own_runs).start(full_side)
                return _prune_and_plan(
                    task, (domain_path, problem_path), options, prepared, call_planner, race, started, progress, choice
                )
        finally:
            if race is not None:
                race.stop()


def _prune_and_plan(
    task: PlanningTask,
    paths: tuple[str, str],
    options: PlanOptions,
    prepared: PreparedPlanner,
    call_planner: PlannerCall,
    race: Race[Attempt] | None,
    started: float,
    progress: ProgressCallback | None,
    choice: str,
) -> PlanResult:
    """Score, choose the first selection, and run the attempts (``plan_task``'s second half)."""
    say = _teller(progress)
    total = len(task.problem.objects)
    domain_path, problem_path = paths
    selection = None
    scoring_started = time.perf_counter()
    try:
        scoring, unpruned = _score(task, options, domain_path, problem_path, say)
    except OutOfTimeError:
        return _ran_out("scoring", started, options, total)
    if scoring is not None:
        overran = _overran("scoring", started, options, total)
        if overran is not None:
            return overran
        if not scoring.scores.sufficient:
            elapsed = time.perf_counter() - started
            return PlanResult(
                method=options.method,
                status=PlanStatus.INSUFFICIENT_CUES,
                wall_time=elapsed,
                relevance_time=elapsed,
                objects_total=total,
                message=scoring.scores.insufficiency,
                planner=prepared.name,
                scorer=scoring.scorer,
            )
        try:
            selection = scoring.first_selection(options.narrows_first)
        except OutOfTimeError:
            return _ran_out("pruning and closure", started, options, total)
        overran = _overran("pruning and closure", started, options, total)
        if overran is not None:
            return overran
        _say_selection(say, selection, total)
    # scoring and pruning only: reading came before, and a race's planner only waits beside it
    relevance_time = time.perf_counter() - scoring_started
    if race is not None and (selection is None or not selection.removed):
        release_warm()  # the full problem is all there is to plan, and the race plans it
    budgets = None
    if selection is not None and selection.removed and options.widen and not prepared.proves_unsolvable:
        budgets = Budgets.after(relevance_time)
        say(
            f"{prepared.name} cannot prove a pruned problem unsolvable: pruned attempts get"
            f" {budgets.first:.1f} s, doubling at each widening"
        )
        # a budget is the planner's search: a warm engine still starting is waited for first
        await_warm(prepared.planner, None if options.timeout is None else time.monotonic() + _left(started, options))
    attempts, widening_time = run_attempts(
        task,
        selection,
        call_planner,
        options,
        started=started,
        model=scoring.knowledge_model if scoring else None,
        progress=progress,
        race=race,
        budgets=budgets,
    )
    result = summarise(
        task,
        options,
        attempts,
        started,
        relevance_time + widening_time,
        selection,
        planner=_answering(prepared, attempts),
        scorer=scoring.scorer if scoring else None,
        unpruned_reason=unpruned,
        planner_choice=choice,
        compilations=prepared.compilations,
    )
    if race is None or not attempts:
        return result
    result = replace(result, raced=attempts[-1].side)
    if not attempts[-1].raced:
        # the pruned side decided (or the time ran out): the full problem's run is listed too
        race.stop()
        beside = race.result()
        if beside is not None:
            beside = replace(beside, number=len(attempts) + 1, stopped=race.cancelled)
            result = replace(result, attempts=(*attempts, beside))
    return result


def _score(
    task: PlanningTask, options: PlanOptions, domain_path: str, problem_path: str, say: Callable[[str], None]
) -> tuple[Scoring | None, str]:
    """The objects' scores (None for 'pure'); None and the reason when the analysis does not take the input."""
    if options.method == "pure":
        return None, ""
    try:
        scoring = score_problem(
            task, options.scoring, method=options.method, domain_path=domain_path, problem_path=problem_path
        )
    except UnsupportedFeatureError as refused:
        unpruned = f"the relevance analysis does not take this input: {refused.message}"
        say(f"pruned: no ({unpruned}); planning the full problem")
        return None, unpruned
    say(f"scoring {len(task.problem.objects)} objects with the {scoring.scorer} scorer")
    return scoring, ""


def _say_selection(say: Callable[[str], None], selection: Selection, total: int) -> None:
    say(
        f"kept {len(selection.kept)} of {total} objects ({len(selection.restored)} restored by closure"
        + (f", {len(selection.set_aside)} blocked alternatives set aside)" if selection.set_aside else ")")
    )
    if not selection.removed:
        say(f"pruned: no ({selection.unpruned_reason})")


def _plan_unread(
    domain_path: str,
    problem_path: str,
    planner: Planner,
    refused: UnsupportedFeatureError,
    options: PlanOptions,
    started: float,
    say: Callable[[str], None],
) -> PlanResult:
    """Input our reader refuses (PDDL+, object fluents): the planner gets the full problem, unpruned;
    only validators that read the files themselves can check its plan."""
    planner, choice = planner_for_unread(planner, refused)
    planner = with_planner_args(planner, options.planner_args)
    unpruned = f"our reader refuses the input: {refused}"
    say(
        f"pruned: no ({unpruned}); planning the full problem with {planner.name}"
        + (f" (auto: {choice})" if choice else "")
    )
    deadline = None if options.timeout is None else started + options.timeout
    limit = None if deadline is None else max(deadline - time.perf_counter(), LAST_SECONDS)
    outcome = planner.run(domain_path, problem_path, time_limit=limit, memory_limit_mb=options.memory_limit_mb)
    validation, validation_time = None, 0.0
    if outcome.solved:
        begun = time.perf_counter()
        until = None if deadline is None else time.monotonic() + max(deadline - begun, 0.5)
        validation = validate_unread(
            domain_path, problem_path, outcome.plan, refused.message, options.validators, until
        )
        validation_time = time.perf_counter() - begun
    attempt = Attempt(
        number=1,
        objects_kept=0,
        thresholds=None,
        added_back=0,
        outcome=outcome,
        validation=validation,
        time_limit=limit,
        validation_time=validation_time,
    )
    return summarise(
        None, options, [attempt], started, 0.0, None, planner.name, unpruned_reason=unpruned, planner_choice=choice
    )


def _left(started: float, options: PlanOptions) -> float:
    """Seconds left of the --timeout (``started`` on ``time.perf_counter()``)."""
    assert options.timeout is not None
    return max(started + options.timeout - time.perf_counter(), 0.0)


def _overran(step: str, started: float, options: PlanOptions, total: int) -> PlanResult | None:
    """An out-of-time result naming ``step`` when ``--timeout`` ran out during it."""
    if options.timeout is None or time.perf_counter() - started < options.timeout:
        return None
    return _ran_out(step, started, options, total)


def _ran_out(step: str, started: float, options: PlanOptions, total: int) -> PlanResult:
    """The out-of-time result of a step that stopped because ``--timeout`` ran out."""
    elapsed = time.perf_counter() - started
    return PlanResult(
        method=options.method,
        status=PlanStatus.OUT_OF_TIME,
        wall_time=elapsed,
        relevance_time=elapsed,
        objects_total=total,
        message=f"out of time while {step}: {elapsed:.1f} s of the {options.timeout:g} s --timeout",
    )


def summarise(
    task: PlanningTask | None,
    options: PlanOptions,
    attempts: Sequence[Attempt],
    started: float,
    relevance_time: float,
    selection: Selection | None,
    planner: str = DEFAULT_PLANNER,
    scorer: str | None = None,
    unpruned_reason: str = "",
    planner_choice: str = "",
    compilations: tuple[str, ...] = (),
) -> PlanResult:
    """The result of a run of attempts: the plan of the last attempt if it validated, else why not.

    ``task`` is None for input our reader refuses (no objects to count)."""
    total = len(task.problem.objects) if task is not None else 0
    common: dict[str, Any] = dict(
        method=options.method,
        attempts=tuple(attempts),
        wall_time=time.perf_counter() - started,
        relevance_time=relevance_time,
        planner_time=sum(a.outcome.wall_time for a in attempts if not a.stopped),
        validation_time=sum(a.validation_time for a in attempts),
        objects_total=total,
        selection=selection,
        peak_memory_mb=max((a.outcome.peak_memory_mb for a in attempts), default=0.0),
        planner=planner,
        scorer=scorer,
        problem=task.problem if task is not None else None,
        unpruned_reason=unpruned_reason,
        planner_choice=planner_choice,
        compilations=compilations,
    )
    if not attempts:
        return PlanResult(status=PlanStatus.OUT_OF_TIME, message="no time left for planning", **common)
    last = next((a for a in reversed(attempts) if not a.stopped), attempts[-1])
    common["objects_kept"] = last.objects_kept
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
            message=f"plan of {len(plan)} steps {checked if validation.valid else 'NOT validated (--validator none)'}",
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
