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
set (``plan_task`` writes the pruned file and calls its planner; the
unified-planning engine restricts a UP problem and calls its inner engine).
Both then turn the attempts into a :class:`PlanResult` with :func:`summarise`.

:func:`plan_task` reads the files and runs the steps in order: obtain the
planner, score and choose the first selection (:func:`_first_selection`),
run the attempts, beside a race of the full problem where the options ask
for one (:func:`_race_and_plan`), and summarise.  What its steps share is one
frozen value, :class:`_Run`.

The loop knows no planner by name.  It obtains its planner once, from
``planners.supply``: chosen (``auto`` by the problem's features), checked
against the problem before any work, prepared (compilations), warmed, with
the launcher's head start.  What is a planner's own (the PDDL it takes, its
exit codes, its plan files) is its adapter's (``planners/``); every run
arrives as a :class:`RunOutcome` whose status the adapter already
classified and whose ``reason`` says what the planner reported, in its terms.

Nothing a planner can solve is refused: when our reader refuses the input
(PDDL+, object fluents) or the relevance analysis cannot take it, the
planner gets the full problem and the result says why it was not pruned.
"""

from __future__ import annotations

import contextvars
import os
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, fields, replace
from pathlib import Path
from typing import Any

from relevance_plan.errors import OutOfTimeError, UnsupportedFeatureError, UsageError, counted
from relevance_plan.io import load_domain, load_problem, scratch_directory, write_text_atomic
from relevance_plan.limits import DEFAULT_TIMEOUT, MAX_TIMEOUT
from relevance_plan.pddl.formatter import format_atom
from relevance_plan.pddl.model import Problem
from relevance_plan.pddl.plans import Plan
from relevance_plan.pddl.sexpr import collection_paused
from relevance_plan.planning.planners.base import PlannerStatus, RunOutcome
from relevance_plan.planning.planners.supply import (
    DEFAULT_PLANNER,
    DEFAULT_PLANNER_CONFIG,
    PlannerRequest,
    PlannerSupply,
    SuppliedPlanner,
    open_planners,
)
from relevance_plan.planning.race import Race
from relevance_plan.planning.results import (
    PLANNER_TO_PLAN_STATUS,
    Attempt,
    AttemptStatus,
    PlanResult,
    PlanStatus,
    RunRecord,
    kept_count,
)
from relevance_plan.planning.validate import (
    ValidationResult,
    ValidationStatus,
    check_validators,
    validate_plan,
    validate_unread,
)
from relevance_plan.progress import ProgressCallback
from relevance_plan.relevance.decisions import kept_summary
from relevance_plan.relevance.knowledge import KnowledgeModel
from relevance_plan.relevance.prune import Selection, Thresholds, Widening, next_witnesses, widen
from relevance_plan.relevance.setup import Scoring, ScoringOptions, score_problem
from relevance_plan.relevance.task import PlanningTask
from relevance_plan.supervision.process import CancelScope, cancel_scope

METHODS = ("relevance", "pure", "random", "oracle")
# The least a planner is given when the --timeout is nearly out: a chance to finish, yet with the
# watchdog's grace a run still ends close to the --timeout.
LAST_SECONDS = 0.2
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
    planner: str = DEFAULT_PLANNER  # a planner name as planners.registry.make_planner takes it
    planner_config: str = DEFAULT_PLANNER_CONFIG
    timeout: float | None = DEFAULT_TIMEOUT  # None: no limit (the UP engine without a timeout)
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
    place_kinds: bool = False
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

    def planner_request(self, keep_work: str | os.PathLike[str] | None = None) -> PlannerRequest:
        """What these options ask of the run's planner (``planners.supply``), with ``--keep-work``."""
        return PlannerRequest(self.planner, self.planner_config, self.planner_args, self.memory_limit_mb, keep_work)

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


# --------------------------------------------------------------------------- the attempts


@dataclass(frozen=True)
class _Attempting:
    """What every attempt of one :func:`run_attempts` reads."""

    task: PlanningTask
    call_planner: PlannerCall
    options: PlanOptions
    deadline: float | None  # time.perf_counter(); None: no limit
    model: KnowledgeModel | None
    race: Race[Attempt] | None
    record: RunRecord

    @property
    def total(self) -> int:
        return len(self.task.problem.objects)

    def say(self, message: str) -> None:
        self.record.say(message)

    def time_left(self) -> bool:
        return self.deadline is None or time.perf_counter() < self.deadline

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
    task: PlanningTask,
    selection: Selection | None,
    call_planner: PlannerCall,
    options: PlanOptions,
    *,
    started: float,
    model: KnowledgeModel | None = None,
    record: RunRecord | None = None,
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
    each pruned attempt is held to its budget, with or without a race.  ``record`` hears each step
    and keeps each attempt as it ends (:class:`~relevance_plan.planning.results.RunRecord`).
    """
    deadline = None if options.timeout is None else started + options.timeout
    record = RunRecord(options.method) if record is None else record
    loop = _Attempting(task, call_planner, options, deadline, model, race, record)
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
                pruned, Widening(options.widen_factor, _goal_filter(options)), state.added_back, model
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


def _time_limit(loop: _Attempting, pruned: Selection | None, state: _AttemptState) -> float | None:
    """The attempt's time limit: a share of what is left for a pruned attempt that may widen (all of
    it beside a race), all of it for the last; a pruned attempt's budget when it has one."""
    final = pruned is None or not loop.options.widen
    if loop.deadline is None:
        limit = None
    else:
        remaining = max(loop.deadline - time.perf_counter(), LAST_SECONDS)
        limit = remaining if final or loop.race is not None else max(1.0, remaining * loop.options.first_share)
    if state.budgets is not None and pruned is not None and not final:
        budget = state.budgets.limit(state.pruned_before)
        limit = budget if limit is None else min(limit, budget)
    return limit


def _attempt(loop: _Attempting, number: int, pruned: Selection | None, state: _AttemptState) -> Attempt:
    """One attempt on ``pruned`` (None: the full problem), its plan validated on the original."""
    kept = loop.total if pruned is None else len(pruned.kept)
    limit = _time_limit(loop, pruned, state)
    loop.record.attempting(number, pruned, limit)
    loop.say(
        f"attempt {number}: the full problem" if pruned is None else f"attempt {number}: {kept} of {loop.total} objects"
    )
    outcome = loop.call_planner(pruned, limit)
    stopped = loop.race is not None and loop.race.won and not outcome.solved
    if stopped:
        loop.say("the full problem, planned since the start, decided first: the pruned attempt was stopped")
        validation, validation_time = None, 0.0
    else:
        outcome, validation, validation_time = _validate(loop.task, outcome, loop.options, loop.deadline)
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


def _race_decides(attempt: Attempt) -> bool:
    """A full-problem attempt ends the run: a valid plan, or proof that the problem has none."""
    return attempt.wins


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


# --------------------------------------------------------------------------- one problem, from its files


def plan_task(
    domain_path: str | Path,
    problem_path: str | Path,
    options: PlanOptions = PlanOptions(),
    progress: ProgressCallback | None = None,
    keep_work: str | os.PathLike[str] | None = None,
    record: RunRecord | None = None,
) -> PlanResult:
    """Run one method on one problem; the plan returned is always validated on the original.

    With ``keep_work``, each attempt's planner files stay in ``keep_work/attempt-N``.  ``record``
    (made for ``progress`` when None; give one or the other) keeps what the run establishes as it
    goes, for a caller that may stop it from outside (``RunRecord.stopped``).
    """
    started = time.perf_counter()
    if record is None:
        record = RunRecord(options.method, progress)
    elif progress is not None:
        raise UsageError("plan_task takes progress or a record that tells it, not both")
    # the run's facts die with it: no pass over them needed; its warm planners too
    with collection_paused(), open_planners(options.planner_request(keep_work)) as supply:
        return _plan_task(str(domain_path), str(problem_path), options, supply, started, record)


@dataclass(frozen=True)
class _Run:
    """What the steps of one :func:`plan_task` share once the problem is read and its planner prepared."""

    task: PlanningTask
    domain_path: str
    problem_path: str
    options: PlanOptions
    planner: SuppliedPlanner
    started: float  # time.perf_counter()
    scratch: Path  # where the pruned problems are written
    record: RunRecord

    @property
    def total(self) -> int:
        return len(self.task.problem.objects)

    def say(self, message: str) -> None:
        self.record.say(message)

    @property
    def races(self) -> bool:
        """Whether the full problem is planned beside the pruned attempts (nothing to race for 'pure')."""
        return self.options.race and self.options.method != "pure"

    def call_planner(self, objects: Selection | None, limit: float | None) -> RunOutcome:
        """The planner on ``objects`` (written to a pruned file), or on the user's files (None)."""
        if objects is None:
            return self.planner.run_full(self.domain_path, self.problem_path, limit)
        target = write_text_atomic(self.scratch / f"pruned-{len(objects.kept)}.pddl", objects.text)
        return self.planner.run(self.domain_path, str(target), limit)

    def plan_full_problem(self) -> Attempt:
        """The race's side: the full problem with all the time there is, its plan validated."""
        deadline = None if self.options.timeout is None else self.started + self.options.timeout
        return _full_attempt(
            0,
            self.total,
            deadline,
            lambda limit: self.call_planner(None, limit),
            lambda outcome: _validate(self.task, outcome, self.options, deadline),
            raced=True,
        )


@dataclass(frozen=True)
class _FirstSelection:
    """The objects' scores (None: nothing scored) and the first selection, and the seconds they took."""

    scoring: Scoring | None
    selection: Selection | None
    unpruned_reason: str  # why the relevance analysis could not take the input ('' when it could)
    seconds: float

    @property
    def model(self) -> KnowledgeModel | None:
        return self.scoring.knowledge_model if self.scoring is not None else None

    @property
    def scorer(self) -> str | None:
        return self.scoring.scorer if self.scoring is not None else None


def _plan_task(
    domain_path: str,
    problem_path: str,
    options: PlanOptions,
    supply: PlannerSupply,
    started: float,
    record: RunRecord,
) -> PlanResult:
    """Read the problem, obtain its planner, and plan (unpruned when our reader refuses the input)."""
    reading = None if options.timeout is None else time.monotonic() + options.timeout
    try:
        domain = load_domain(domain_path, deadline=reading)
        task = PlanningTask(domain, load_problem(problem_path, domain, deadline=reading), deadline=reading)
    except OutOfTimeError:
        return _ran_out("reading the domain and problem", started, options, record)
    except UnsupportedFeatureError as refused:
        return _plan_unread(domain_path, problem_path, supply.for_unread(refused), refused, options, started, record)
    record.read(task.problem)
    # the planner's check; what it lacks and can be compiled away is compiled away at each attempt
    planner = supply.for_task(task.domain, task.problem, problem_path, record.say)
    record.planning_with(planner.name, planner.choice)
    overran = _overran("reading the domain and problem", started, options, record)
    if overran is not None:
        return overran
    if not options.validators or "builtin" in options.validators:
        # the plan is checked once the planner has ended: import the checker now, while it runs
        import relevance_plan.pddl.simulator  # noqa: F401
    with scratch_directory() as scratch:
        run = _Run(task, domain_path, problem_path, options, planner, planner.began(started), scratch, record)
        return _race_and_plan(run)


def _race_and_plan(run: _Run) -> PlanResult:
    """:func:`_prune_and_plan`, with the full problem planned beside it when the run races."""
    own_runs = CancelScope()
    if not run.races:
        with cancel_scope(own_runs):
            return _prune_and_plan(run, None)
    run.record.racing()
    run.say("racing: the full problem is planned beside the pruned attempts")
    # the race's thread takes the run's warm planners, as planning without pruning would have
    # them; the pruned attempts get their own: copies of those, asked for before the full
    # problem keeps them busy, and let go if nothing is pruned
    full_side = contextvars.copy_context()
    race = Race(run.plan_full_problem, _race_decides, own_runs)
    try:
        with cancel_scope(own_runs), run.planner.beside():
            race.start(full_side)
            return _prune_and_plan(run, race)
    finally:
        race.stop()
        run.record.ended_beside(race.result(), race.cancelled)


def _prune_and_plan(run: _Run, race: Race[Attempt] | None) -> PlanResult:
    """Score, choose the first selection, and run the attempts on it."""
    first = _first_selection(run)
    if isinstance(first, PlanResult):  # the run ended before any attempt
        # out of time, the race's side is part of the verdict; the tool's own verdicts (insufficient
        # cues, a proof of unsolvability) stop it unheard
        return _raced(first, race) if race is not None and first.status is PlanStatus.OUT_OF_TIME else first
    if race is not None and (first.selection is None or not first.selection.removed):
        run.planner.release()  # the full problem is all there is to plan, and the race plans it
    attempts, widening_time = run_attempts(
        run.task,
        first.selection,
        run.call_planner,
        run.options,
        started=run.started,
        model=first.model,
        record=run.record,
        race=race,
        budgets=_budgets(run, first),
    )
    deciding = [a for a in attempts if not a.stopped]
    result = summarise(
        run.task,
        run.options,
        attempts,
        run.started,
        first.seconds + widening_time,
        first.selection,
        planner=run.planner.answering(deciding[-1].outcome.planner if deciding else ""),
        scorer=first.scorer,
        refusal=first.unpruned_reason,
        planner_choice=run.planner.choice,
        compilations=run.planner.compilations,
    )
    return result if race is None else _raced(result, race)


def _first_selection(run: _Run) -> _FirstSelection | PlanResult:
    """The scores and the first selection; instead, the result when the run ends here (out of time,
    insufficient cues)."""
    scoring_started = time.perf_counter()
    try:
        scoring, unpruned_reason = _score(run)
    except OutOfTimeError:
        return _ran_out("scoring", run.started, run.options, run.record)
    selection = None
    if scoring is not None:
        overran = _overran("scoring", run.started, run.options, run.record)
        if overran is not None:
            return overran
        if not scoring.scores.sufficient:
            return _before_planning(
                PlanStatus.INSUFFICIENT_CUES,
                scoring.scores.insufficiency,
                time.perf_counter() - run.started,
                run.options,
                run.total,
                planner=run.planner.name,
                scorer=scoring.scorer,
                understood=scoring.scores.understood,
            )
        proved = _proved_unsolvable(run)
        if proved is not None:
            return proved
        try:
            selection = scoring.first_selection(run.options.narrows_first)
        except OutOfTimeError:
            return _ran_out("pruning and closure", run.started, run.options, run.record)
    # scoring and pruning only: reading came before, and a race's planner only waits beside it
    first = _FirstSelection(scoring, selection, unpruned_reason, time.perf_counter() - scoring_started)
    run.record.selected(selection, first.scorer, first.seconds)
    if selection is not None:
        overran = _overran("pruning and closure", run.started, run.options, run.record)
        if overran is not None:
            return overran
        _say_selection(run.say, selection, run.total)
    return first


def _proved_unsolvable(run: _Run) -> PlanResult | None:
    """The unsolvable result, without a planner, of a problem whose goal needs more witnesses than
    it has (``relevance.witness_proof``: a proof, not a guess); None for others, and for the
    baseline methods (they plan as the paper's did)."""
    if run.options.method != "relevance":
        return None
    try:
        proof = run.task.proved_unsolvable
    except OutOfTimeError:
        return _ran_out("proving the goal's witnesses short", run.started, run.options, run.record)
    if not proof:
        return None
    run.say(f"no plan can exist: {proof}")
    elapsed = time.perf_counter() - run.started
    message = f"{proof}, so the problem has no plan (proved before planning: no planner ran)"
    result = _before_planning(PlanStatus.UNSOLVABLE, message, elapsed, run.options, run.total, planner=run.planner.name)
    return replace(result, objects_kept=run.total)


def _budgets(run: _Run, first: _FirstSelection) -> Budgets | None:
    """The pruned attempts' budgets, for a planner that cannot prove a pruned problem unsolvable."""
    selection = first.selection
    if selection is None or not selection.removed or not run.options.widen or run.planner.proves_unsolvable:
        return None
    budgets = Budgets.after(first.seconds)
    run.say(
        f"{run.planner.name} cannot prove a pruned problem unsolvable: pruned attempts get"
        f" {budgets.first:.1f} s, doubling at each widening"
    )
    # a budget is the planner's search: a warm engine still starting is waited for first
    run.planner.await_warm(None if run.options.timeout is None else time.monotonic() + _left(run.started, run.options))
    return budgets


def _raced(result: PlanResult, race: Race[Attempt]) -> PlanResult:
    """The result of a race: which side won it, if one did (a valid plan, or the full problem's proof
    that there is none; a side that ran out of time or failed wins nothing), and the full problem's
    run listed when it was not the last (the pruned side decided, or the time ran out)."""
    attempts = result.attempts
    won = bool(attempts) and attempts[-1].wins
    result = replace(result, race=True, deciding_side=attempts[-1].side if won else "")
    if attempts and attempts[-1].raced:
        return result
    race.stop()
    beside = race.result()
    if beside is None:
        return result
    beside = replace(beside, number=len(attempts) + 1)
    return replace(result, attempts=(*attempts, beside.as_stopped() if race.cancelled else beside))


def _score(run: _Run) -> tuple[Scoring | None, str]:
    """The objects' scores (None for 'pure'); None and the reason when the analysis does not take the input."""
    if run.options.method == "pure":
        return None, ""
    try:
        scoring = score_problem(
            run.task,
            run.options.scoring,
            method=run.options.method,
            domain_path=run.domain_path,
            problem_path=run.problem_path,
        )
    except UnsupportedFeatureError as refused:
        unpruned_reason = f"the relevance analysis does not take this input: {refused.message}"
        run.say(f"pruned: no ({unpruned_reason}); planning the full problem")
        return None, unpruned_reason
    run.say(f"scoring {run.total} objects with the {scoring.scorer} scorer")
    return scoring, ""


def _say_selection(say: Callable[[str], None], selection: Selection, total: int) -> None:
    aside = len(selection.set_aside)
    say(
        kept_summary(selection)
        + (f", {aside} {'alternative' if aside == 1 else 'alternatives'} set aside" if aside else "")
    )
    if not selection.removed:
        say(f"pruned: no ({selection.unpruned_reason})")
    if selection.witnesses:
        say("witnesses: " + _witness_list(selection))


def _witness_list(selection: Selection) -> str:
    """``item3_vase for (classrelation vase microwave), ...`` (``Selection.witnesses``)."""
    spelling = selection.task.problem.spelling
    return ", ".join(f"{spelling.object(name)} for {format_atom(goal, spelling)}" for goal, name in selection.witnesses)


def _say_next_witnesses(say: Callable[[str], None], failed: Selection, widened: Selection) -> None:
    """Which witnesses a failed attempt had, and the next candidates the widened selection adds."""
    added = [name for name in next_witnesses(failed.task, failed.kept) if name in widened.kept]
    if failed.witnesses and added:
        show = failed.task.problem.display
        say(f"no plan with the witnesses {_witness_list(failed)}: widening adds {', '.join(map(show, added))}")


def _plan_unread(
    domain_path: str,
    problem_path: str,
    planner: SuppliedPlanner,
    refused: UnsupportedFeatureError,
    options: PlanOptions,
    started: float,
    record: RunRecord,
) -> PlanResult:
    """Input our reader refuses (PDDL+, object fluents): the planner gets the full problem, unpruned;
    only validators that read the files themselves can check its plan."""
    unpruned_reason = f"our reader refuses the input: {refused}"
    record.planning_with(planner.name, planner.choice)
    record.unread(unpruned_reason)
    record.say(
        f"pruned: no ({unpruned_reason}); planning the full problem with {planner.name}"
        + (f" (auto: {planner.choice})" if planner.choice else "")
    )
    deadline = None if options.timeout is None else started + options.timeout

    def validate(outcome: RunOutcome) -> tuple[RunOutcome, ValidationResult | None, float]:
        if not outcome.solved:
            return outcome, None, 0.0
        begun = time.perf_counter()
        until = None if deadline is None else time.monotonic() + max(deadline - begun, 0.5)
        validation = validate_unread(
            domain_path, problem_path, outcome.plan, refused.message, options.validators, until
        )
        return outcome, validation, time.perf_counter() - begun

    record.attempting(1, None, None)
    attempt = _full_attempt(1, 0, deadline, lambda limit: planner.run(domain_path, problem_path, limit), validate)
    record.attempted(attempt)
    return summarise(
        None,
        options,
        [attempt],
        started,
        0.0,
        None,
        planner.name,
        refusal=unpruned_reason,
        planner_choice=planner.choice,
    )


def _full_attempt(
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


def _left(started: float, options: PlanOptions) -> float:
    """Seconds left of the --timeout (``started`` on ``time.perf_counter()``)."""
    assert options.timeout is not None
    return max(started + options.timeout - time.perf_counter(), 0.0)


def _overran(step: str, started: float, options: PlanOptions, record: RunRecord) -> PlanResult | None:
    """An out-of-time result naming ``step`` when ``--timeout`` ran out during it."""
    if options.timeout is None or time.perf_counter() - started < options.timeout:
        return None
    return _ran_out(step, started, options, record)


def _ran_out(step: str, started: float, options: PlanOptions, record: RunRecord) -> PlanResult:
    """The out-of-time result of a step that stopped because ``--timeout`` ran out, with what the run
    had established by then (the problem's objects, the selection)."""
    elapsed = time.perf_counter() - started
    message = f"out of time while {step}: {elapsed:.1f} s of the {options.timeout:g} s --timeout"
    return replace(record.stopped(message), wall_time=elapsed, relevance_time=elapsed)


def _before_planning(
    status: PlanStatus, message: str, elapsed: float, options: PlanOptions, total: int, **more: Any
) -> PlanResult:
    """The result of a run that ended before any planner ran: all its time went to reading and relevance."""
    return PlanResult(
        method=options.method,
        status=status,
        wall_time=elapsed,
        relevance_time=elapsed,
        objects_total=total,
        message=message,
        **more,
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
    refusal: str = "",
    planner_choice: str = "",
    compilations: tuple[str, ...] = (),
) -> PlanResult:
    """The result of a run of attempts: the plan of the last attempt if it validated, else why not.

    ``task`` is None for input our reader refuses (no objects to count)."""
    total = len(task.problem.objects) if task is not None else None
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
        refusal=refusal,
        planner_choice=planner_choice,
        compilations=compilations,
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
