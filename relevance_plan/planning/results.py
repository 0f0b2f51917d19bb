"""The records of a planning run, and the one chain of statuses from a planner's run to the exit code.

A planner run ends in a :class:`~relevance_plan.planning.planners.base.PlannerStatus`;
an :class:`Attempt` (one run on one object set) in an :class:`AttemptStatus`,
which is the planner's status unless a plan was found, and then what its
validation on the original problem said; a problem's :class:`PlanResult` in a
:class:`PlanStatus`, taken from the last attempt (``PLANNER_TO_PLAN_STATUS``
and ``summary.summarise``); the CLI's exit code from the :class:`PlanStatus`
(``exitcodes.PLAN_STATUS_EXIT``).  docs/how-it-works.md has the whole table.
"""

from __future__ import annotations

import enum
import threading
import time
from collections.abc import Sequence
from dataclasses import dataclass, field, replace
from typing import Any

from relevance_plan.pddl.model import UNSPELLED, Problem, Spelling
from relevance_plan.pddl.plans import Plan, format_plan, format_plan_step
from relevance_plan.planning.methods import Method
from relevance_plan.planning.planners.base import PlannerStatus, RunOutcome
from relevance_plan.planning.planners.registry import DEFAULT_PLANNER
from relevance_plan.planning.validation import ValidationResult, ValidationStatus
from relevance_plan.progress import ProgressCallback, ProgressEvent
from relevance_plan.relevance.scoring.word_matching import WordMatch
from relevance_plan.relevance.selection.prune import Selection, Thresholds


class PlanStatus(enum.Enum):
    """A problem's verdict.  These values are stored in results stores: never respell them."""

    SOLVED = "solved"
    UNSOLVABLE = "unsolvable"
    NO_VALID_PLAN = "no-valid-plan"
    OUT_OF_TIME = "out-of-time"
    OUT_OF_MEMORY = "out-of-memory"
    INSUFFICIENT_CUES = "insufficient-cues"
    INPUT_ERROR = "input-error"
    UNSUPPORTED = "unsupported"  # the planner cannot take the problem's features
    PLANNER_CONFIG_ERROR = "planner-config-error"
    PLANNER_ERROR = "planner-error"
    VALIDATOR_UNAVAILABLE = "validator-unavailable"


class AttemptStatus(enum.Enum):
    """How one attempt ended: the planner's status, or for a found plan what validation said.

    The planner's statuses are spelled as :class:`PlannerStatus` spells them (a test checks it).
    """

    SOLVED = "solved"  # a plan, valid on the original problem (or not validated: --validator none)
    PLAN_INVALID = "plan-invalid"
    PLAN_UNAVAILABLE = "plan-unavailable"  # a plan, but no validator could run
    PLAN_OUT_OF_TIME = "plan-out-of-time"  # a plan, but validating it ran out of time
    UNSOLVABLE = "unsolvable"
    SEARCH_INCOMPLETE = "search-incomplete"
    OUT_OF_TIME = "out-of-time"
    OUT_OF_MEMORY = "out-of-memory"
    INPUT_ERROR = "input-error"
    PLANNER_CONFIG_ERROR = "planner-config-error"
    UNSUPPORTED = "unsupported"
    PLANNER_CRASH = "planner-crash"
    STOPPED = "stopped"  # the tool stopped its planner: the race's other side decided first


_VALIDATION_FAILURE = {
    ValidationStatus.INVALID: AttemptStatus.PLAN_INVALID,
    ValidationStatus.UNAVAILABLE: AttemptStatus.PLAN_UNAVAILABLE,
    ValidationStatus.OUT_OF_TIME: AttemptStatus.PLAN_OUT_OF_TIME,
}


@dataclass(frozen=True, kw_only=True)
class Attempt:
    """One planner run on one object set; a found plan was validated on the original problem."""

    number: int
    objects_kept: int
    thresholds: Thresholds | None  # None for the full problem
    added_back: int  # removed objects put back by rank at this widening
    outcome: RunOutcome
    validation: ValidationResult | None
    time_limit: float | None
    validation_time: float = 0.0
    selection: Selection | None = None  # the objects it planned on (None: the user's full problem)
    raced: bool = False  # the full problem, planned from the start beside the pruned attempts (planning.race)
    stopped: bool = False  # stopped unfinished because the race's other side decided first

    @property
    def full(self) -> bool:
        return self.thresholds is None

    @property
    def side(self) -> str:
        """Which side of a race it ran on: "full" (planned from the start) or "pruned"."""
        return "full" if self.raced else "pruned"

    @property
    def wins(self) -> bool:
        """Whether it decides a race: a valid plan, or (the full problem only) a proof that there is none."""
        return self.status is AttemptStatus.SOLVED or (self.full and self.status is AttemptStatus.UNSOLVABLE)

    def as_stopped(self) -> Attempt:
        """This attempt, its planner stopped by the tool (the race's other side decided first)."""
        return replace(self, stopped=True, outcome=replace(self.outcome, status=PlannerStatus.STOPPED))

    @property
    def status(self) -> AttemptStatus:
        if self.stopped:
            return AttemptStatus.STOPPED
        if self.outcome.status is PlannerStatus.SOLVED and self.validation is not None:
            return AttemptStatus.SOLVED if self.validation.accepted else _VALIDATION_FAILURE[self.validation.status]
        return AttemptStatus(self.outcome.status.value)


@dataclass(frozen=True)
class PlanResult:
    method: Method
    status: PlanStatus
    plan: Plan = Plan()
    plan_cost: float | None = None
    validation: ValidationResult | None = None
    attempts: tuple[Attempt, ...] = ()
    wall_time: float = 0.0
    relevance_time: float = 0.0
    planner_time: float = 0.0
    validation_time: float = 0.0
    # None: not known (the run stopped before reading the problem, or before choosing its objects)
    objects_total: int | None = None
    objects_kept: int | None = None  # the last attempt's objects; before any attempt, the first selection's
    selection: Selection | None = None  # the first attempt's objects (None: pure planning)
    message: str = ""
    peak_memory_mb: float = 0.0
    planner: str = DEFAULT_PLANNER
    scorer: str | None = None
    log_tail: str = ""  # the last planner's log tail when it failed
    problem: Problem | None = field(default=None, repr=False)  # the original problem (for the user's spelling)
    refusal: str = ""  # why the input could not be pruned at all: our reader or the relevance analysis refused it
    planner_choice: str = ""  # why the default planner chose ``planner``
    compilations: tuple[str, ...] = ()  # what was compiled away for the planner (pddl.compile)
    plans: tuple[Plan, ...] = ()  # an anytime planner's valid plans, in the order found (``plan`` is the last)
    deciding_side: str = ""  # with a race: the side that won it (Attempt.wins), "full" or "pruned"; "" if none did
    race: bool = False  # the full problem was planned beside the pruned attempts (planning.race)
    understood: tuple[WordMatch, ...] = ()  # free text (--objective, --activity) and what it was taken for, or asked

    @property
    def first_kept(self) -> int | None:
        """How many objects pruning chose for the first pruned attempt (all of them without pruning)."""
        return len(self.selection.kept) if self.selection is not None else self.objects_total

    @property
    def spelling(self) -> Spelling:
        """How the user wrote the original problem's names (and its domain's)."""
        return self.problem.spelling if self.problem is not None else UNSPELLED

    def plan_text(self) -> str:
        """The plan in the IPC format, every name in the user's spelling."""
        return format_plan(self.plan, self.spelling)

    @property
    def valid(self) -> bool:
        return self.validation is not None and self.validation.valid

    @property
    def pruned(self) -> bool:
        """Whether the first attempt planned on fewer objects than the problem has."""
        return self.selection is not None and bool(self.selection.removed)

    @property
    def unpruned_reason(self) -> str | None:
        """Why every object was kept (None when the problem was pruned)."""
        if self.pruned:
            return None
        if self.refusal:
            return self.refusal
        if self.selection is not None:
            return self.selection.unpruned_reason or None
        return f"method '{Method.PURE}' plans the full problem" if self.method == Method.PURE else None

    @property
    def first_attempt_status(self) -> str:
        """The first attempt's status value; without attempts, the result's own."""
        if self.attempts:
            return self.attempts[0].status.value
        return self.status.value

    def to_json(self) -> dict[str, Any]:
        return {
            "method": self.method,
            "planner": self.planner,
            "planner_choice": self.planner_choice or None,
            "status": self.status.value,
            "valid": self.valid,
            "validation": self.validation.status.value if self.validation else None,
            "validator": self.validation.validator if self.validation else None,
            "pruned": self.pruned,
            "unpruned_reason": self.unpruned_reason,
            "plan_length": len(self.plan) if self.status is PlanStatus.SOLVED else None,
            "plan_cost": self.plan_cost,
            "wall_time": round(self.wall_time, 4),
            "relevance_time": round(self.relevance_time, 4),
            "planner_time": round(self.planner_time, 4),
            "validation_time": round(self.validation_time, 4),
            "objects_total": self.objects_total,
            "objects_kept": self.objects_kept,
            "attempts": len(self.attempts),
            "first_attempt_status": self.first_attempt_status,
            "attempt_log": [
                {
                    "attempt": a.number,
                    "objects_kept": a.objects_kept,
                    "tau_class": a.thresholds.tau_class if a.thresholds else None,
                    "tau_element": a.thresholds.tau_element if a.thresholds else None,
                    "added_back": a.added_back,
                    "time_limit": None if a.time_limit is None else round(a.time_limit, 3),
                    "planner_status": a.outcome.status.value,
                    "planner_exit_code": a.outcome.exit_code,
                    "status": a.status.value,
                    "side": a.side if self.race else None,
                    "wall_time": round(a.outcome.wall_time, 4),
                    **_objects_of(a),
                }
                for a in self.attempts
            ],
            "peak_memory_mb": round(self.peak_memory_mb, 1),
            "message": self.message,
            "compilations": list(self.compilations),
            "deciding_side": self.deciding_side or None,
            "race": race_sides(self) or None,  # each side's last status, whether or not one won
            "raced": self.deciding_side or None,  # deciding_side's old name, still written for one release
            "anytime_plans": [{"plan_length": len(plan), "plan_cost": plan.cost} for plan in self.plans],
            "understood": [match.as_json() for match in self.understood],
            # one IPC line per step: a timed step keeps its start time and duration
            "plan": [format_plan_step(step, self.spelling) for step in self.plan.steps]
            if self.status is PlanStatus.SOLVED
            else [],
        }


@dataclass(frozen=True)
class _Running:
    """The attempt a run is in: its number, its objects (None: the full problem), its start."""

    number: int
    selection: Selection | None
    started: float  # time.perf_counter()
    time_limit: float | None


@dataclass(frozen=True)
class _Established:
    """What a run has established so far (:class:`RunRecord`)."""

    problem: Problem | None = None
    planner: str = DEFAULT_PLANNER
    planner_choice: str = ""
    selection: Selection | None = None
    scorer: str | None = None
    relevance_time: float = 0.0
    attempts: tuple[Attempt, ...] = ()
    running: _Running | None = None
    race: bool = False
    beside: Attempt | None = None  # the race's full problem, once it ended
    step: str = ""  # the last step the run reported
    refusal: str = ""  # why the input is planned unpruned: our reader refused it (nothing counted)


class RunRecord:
    """What one ``plan_task`` run has established, kept as it goes: the problem's objects, its planner,
    the first selection, the attempts finished and the one under way, the last step it reported.

    A run stopped from outside at any instruction (the CLI's last alarm past ``--timeout``) is then
    reported from it (:meth:`stopped`) with the counts that were known, never as 0 of 0.  The run
    tells its progress through :meth:`say`, which forwards to ``progress``.  The race's thread
    reports its attempt too: the facts are one frozen value, replaced under a lock.
    """

    def __init__(self, method: Method | str, progress: ProgressCallback | None = None):
        self.method = Method(method)
        self._progress = progress
        self._started = time.perf_counter()
        self._lock = threading.Lock()
        self._facts = _Established()

    @property
    def facts(self) -> _Established:
        return self._facts

    def _note(self, **facts: Any) -> None:
        with self._lock:
            self._facts = replace(self._facts, **facts)

    def say(self, message: str) -> None:
        """One step of the run: kept as the last step, and told to ``progress``."""
        self._note(step=message)
        if self._progress is not None:
            self._progress(ProgressEvent(message=message))

    def read(self, problem: Problem) -> None:
        self._note(problem=problem)

    def planning_with(self, planner: str, choice: str = "") -> None:
        self._note(planner=planner, planner_choice=choice)

    def unread(self, refusal: str) -> None:
        """Our reader refused the input: it is planned unpruned, its objects never counted."""
        self._note(refusal=refusal)

    def racing(self) -> None:
        self._note(race=True)

    def selected(self, selection: Selection | None, scorer: str | None, seconds: float) -> None:
        self._note(selection=selection, scorer=scorer, relevance_time=seconds)

    def attempting(self, number: int, selection: Selection | None, time_limit: float | None) -> None:
        self._note(running=_Running(number, selection, time.perf_counter(), time_limit))

    def attempted(self, attempt: Attempt) -> None:
        with self._lock:
            self._facts = replace(self._facts, attempts=(*self._facts.attempts, attempt), running=None)

    def ended_beside(self, attempt: Attempt | None, cancelled: bool) -> None:
        """The race's full problem ended (None: it raised); ``cancelled``: the run stopped it."""
        if attempt is not None:
            self._note(beside=attempt.as_stopped() if cancelled and not attempt.wins else attempt)

    @property
    def total(self) -> int | None:
        """The problem's object count once it is read."""
        problem = self._facts.problem
        return None if problem is None else len(problem.objects)

    def where(self) -> str:
        """Where the run stands, for a message: after its last step, or the step it never left."""
        if self._facts.step:
            return f"after '{self._facts.step}'"
        return "while reading the domain and problem" if self.total is None else "while scoring"

    def stopped(self, message: str) -> PlanResult:
        """The out-of-time result of a run stopped where it stood: every count it had, the attempt
        under way listed as out of time, the race's sides as they ended."""
        facts = self._facts
        now = time.perf_counter()
        attempts = list(facts.attempts)
        if facts.running is not None:
            attempts.append(self._cut_short(facts.running, now))
        if facts.beside is not None and not any(a.raced for a in attempts):
            attempts.append(replace(facts.beside, number=len(attempts) + 1))
        return PlanResult(
            method=self.method,
            status=PlanStatus.OUT_OF_TIME,
            attempts=tuple(attempts),
            wall_time=now - self._started,
            relevance_time=facts.relevance_time,
            planner_time=sum(a.outcome.wall_time for a in attempts if not a.stopped),
            validation_time=sum(a.validation_time for a in attempts),
            objects_total=self.total,
            objects_kept=None if self.total is None else kept_count(attempts, facts.selection, self.total, self.method),
            selection=facts.selection,
            message=message,
            planner=facts.planner,
            scorer=facts.scorer,
            problem=facts.problem,
            planner_choice=facts.planner_choice,
            refusal=facts.refusal,
            race=facts.race,
            understood=facts.selection.scores.understood if facts.selection is not None else (),
        )

    def _cut_short(self, running: _Running, now: float) -> Attempt:
        """The attempt under way when the run stopped, as an out-of-time attempt."""
        total = self.total or 0
        outcome = RunOutcome(
            status=PlannerStatus.OUT_OF_TIME,
            exit_code=None,
            plan=Plan(),
            plan_cost=None,
            wall_time=now - running.started,
            planner=self._facts.planner,
            reason="stopped by the tool at the --timeout",
        )
        return Attempt(
            number=running.number,
            objects_kept=total if running.selection is None else len(running.selection.kept),
            thresholds=None if running.selection is None else running.selection.thresholds,
            added_back=0,
            outcome=outcome,
            validation=None,
            time_limit=running.time_limit,
            selection=running.selection,
        )


def kept_count(
    attempts: Sequence[Attempt], selection: Selection | None, total: int | None, method: Method
) -> int | None:
    """A result's ``objects_kept``: the last attempt's that was not stopped; before any such attempt,
    the first selection's; for method 'pure', all; None when no selection was made."""
    ran = [a for a in attempts if not a.stopped]
    if ran:
        return ran[-1].objects_kept
    if selection is not None:
        return len(selection.kept)
    return total if not method.prunes else None


def race_sides(result: PlanResult) -> dict[str, str]:
    """Each side of a race ("pruned", "full") and the status its last attempt ended in."""
    return {attempt.side: attempt.status.value for attempt in result.attempts} if result.race else {}


def _objects_of(attempt: Attempt) -> dict[str, Any]:
    """The attempt's kept, removed and restored objects (with reasons); the full problem keeps all."""
    if attempt.selection is None:
        return {"pruned": False, "kept": "all", "removed": [], "restored": []}
    described = attempt.selection.describe()
    return {
        key: described[key]
        for key in ("pruned", "unpruned_reason", "kept", "removed", "restored", "set_aside", "witnesses")
    }


PLANNER_TO_PLAN_STATUS = {
    PlannerStatus.UNSOLVABLE: PlanStatus.UNSOLVABLE,
    PlannerStatus.SEARCH_INCOMPLETE: PlanStatus.NO_VALID_PLAN,
    PlannerStatus.OUT_OF_TIME: PlanStatus.OUT_OF_TIME,
    PlannerStatus.OUT_OF_MEMORY: PlanStatus.OUT_OF_MEMORY,
    PlannerStatus.INPUT_ERROR: PlanStatus.INPUT_ERROR,
    PlannerStatus.PLANNER_CONFIG_ERROR: PlanStatus.PLANNER_CONFIG_ERROR,
    PlannerStatus.UNSUPPORTED: PlanStatus.UNSUPPORTED,
    PlannerStatus.PLANNER_CRASH: PlanStatus.PLANNER_ERROR,
}
