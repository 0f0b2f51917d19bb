"""One problem from its files to its result: read, obtain the planner, score, prune, attempt, summarise.

:func:`plan_task` reads the files and runs the steps in order: obtain the
planner, score and choose the first selection (:func:`_first_selection`),
run the attempts (``attempts.run_attempts``), beside a race of the full
problem where the options ask for one (:func:`_race_and_plan`), and
summarise (``summary.summarise``).  What its steps share is one frozen value,
:class:`_TaskRun`.

The run knows no planner by name.  It obtains its planner once, from
``planners.supply``: chosen (``auto`` by the problem's features), checked
against the problem before any work, prepared (compilations), warmed, with
the launcher's head start.  What is a planner's own (the PDDL it takes, its
exit codes, its plan files) is its adapter's (``planners/``).

Nothing a planner can solve is refused: when our reader refuses the input
(PDDL+, object fluents) or the relevance analysis cannot take it, the
planner gets the full problem and the result says why it was not pruned.
"""

from __future__ import annotations

import contextvars
import os
import time
from collections.abc import Callable
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

from relevance_plan.errors import OutOfTimeError, UnsupportedFeatureError, UsageError
from relevance_plan.io import load_domain, load_problem, scratch_directory, write_text_atomic
from relevance_plan.pddl.sexpr import collection_paused
from relevance_plan.planning.attempts import (
    AttemptLoop,
    Budgets,
    full_attempt,
    race_decides,
    run_attempts,
    validate_outcome,
    witness_list,
)
from relevance_plan.planning.options import PlanOptions
from relevance_plan.planning.planners.base import RunOutcome
from relevance_plan.planning.planners.supply import PlannerSupply, SuppliedPlanner, open_planners
from relevance_plan.planning.race import Race
from relevance_plan.planning.results import Attempt, PlanResult, PlanStatus, RunRecord
from relevance_plan.planning.summary import RunFacts, summarise
from relevance_plan.planning.validation import ValidationResult, validate_unread
from relevance_plan.progress import ProgressCallback
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.scoring.knowledge import KnowledgeModel
from relevance_plan.relevance.selection.decisions import kept_summary
from relevance_plan.relevance.selection.prune import Selection
from relevance_plan.relevance.setup import Scoring, score_problem
from relevance_plan.supervision.process import CancelScope, cancel_scope


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
class _TaskRun:
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
        return self.options.race and self.options.method.prunes

    def call_planner(self, objects: Selection | None, limit: float | None) -> RunOutcome:
        """The planner on ``objects`` (written to a pruned file), or on the user's files (None)."""
        if objects is None:
            return self.planner.run_full(self.domain_path, self.problem_path, limit)
        target = write_text_atomic(self.scratch / f"pruned-{len(objects.kept)}.pddl", objects.text)
        return self.planner.run(self.domain_path, str(target), limit)

    def plan_full_problem(self) -> Attempt:
        """The race's side: the full problem with all the time there is, its plan validated."""
        deadline = None if self.options.timeout is None else self.started + self.options.timeout
        return full_attempt(
            0,
            self.total,
            deadline,
            lambda limit: self.call_planner(None, limit),
            lambda outcome: validate_outcome(self.task, outcome, self.options, deadline),
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
        run = _TaskRun(task, domain_path, problem_path, options, planner, planner.began(started), scratch, record)
        return _race_and_plan(run)


def _race_and_plan(run: _TaskRun) -> PlanResult:
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
    race = Race(run.plan_full_problem, race_decides, own_runs)
    try:
        with cancel_scope(own_runs), run.planner.beside():
            race.start(full_side)
            return _prune_and_plan(run, race)
    finally:
        race.stop()
        run.record.ended_beside(race.result(), race.cancelled)


def _prune_and_plan(run: _TaskRun, race: Race[Attempt] | None) -> PlanResult:
    """Score, choose the first selection, and run the attempts on it."""
    first = _first_selection(run)
    if isinstance(first, PlanResult):  # the run ended before any attempt
        # out of time, the race's side is part of the verdict; the tool's own verdicts (insufficient
        # cues, a proof of unsolvability) stop it unheard
        return _raced(first, race) if race is not None and first.status is PlanStatus.OUT_OF_TIME else first
    if race is not None and (first.selection is None or not first.selection.removed):
        run.planner.release()  # the full problem is all there is to plan, and the race plans it
    loop = AttemptLoop(run.task, run.call_planner, run.options, run.started, first.model, run.record, race)
    attempts, widening_time = run_attempts(loop, first.selection, _budgets(run, first))
    deciding = [a for a in attempts if not a.stopped]
    facts = RunFacts(
        run.task,
        run.started,
        first.seconds + widening_time,
        first.selection,
        planner=run.planner.answering(deciding[-1].outcome.planner if deciding else ""),
        scorer=first.scorer,
        refusal=first.unpruned_reason,
        planner_choice=run.planner.choice,
        compilations=run.planner.compilations,
    )
    result = summarise(facts, run.options, attempts)
    return result if race is None else _raced(result, race)


def _first_selection(run: _TaskRun) -> _FirstSelection | PlanResult:
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


def _proved_unsolvable(run: _TaskRun) -> PlanResult | None:
    """The unsolvable result, without a planner, of a problem whose goal needs more witnesses than
    it has (``relevance.witness_proof``: a proof, not a guess); None for others, and for the
    baseline methods (they plan as the paper's did)."""
    if not run.options.method.narrows_first:
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


# A ring's first budget: this share of the --timeout (at least MIN_RING_BUDGET), growing by RING_BUDGET_GROWTH.
RING_BUDGET_SHARE = 0.1
MIN_RING_BUDGET = 0.5
RING_BUDGET_GROWTH = 1.5


def _budgets(run: _TaskRun, first: _FirstSelection) -> Budgets | None:
    """The pruned attempts' budgets, for a planner that cannot prove a pruned problem unsolvable."""
    selection = first.selection
    if selection is None or not selection.removed or not run.options.widen:
        return None
    if run.planner.proves_unsolvable:
        if not run.task.network or run.options.timeout is None:
            return None
        # in a network a pruned problem that is too tight may take long to prove so: each ring
        # gets a small share of the --timeout, so that the next ring, not the budget's end, decides
        return Budgets(max(MIN_RING_BUDGET, RING_BUDGET_SHARE * run.options.timeout), RING_BUDGET_GROWTH)
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


def _score(run: _TaskRun) -> tuple[Scoring | None, str]:
    """The objects' scores (None for 'pure'); None and the reason when the analysis does not take the input."""
    if not run.options.method.prunes:
        return None, ""
    try:
        scoring = score_problem(
            run.task,
            run.options.scoring,
            method=run.options.method.value,
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
        say("witnesses: " + witness_list(selection))


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
    attempt = full_attempt(1, 0, deadline, lambda limit: planner.run(domain_path, problem_path, limit), validate)
    record.attempted(attempt)
    facts = RunFacts(None, started, planner=planner.name, refusal=unpruned_reason, planner_choice=planner.choice)
    return summarise(facts, options, [attempt])


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
