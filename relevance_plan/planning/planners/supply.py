"""A run's planner, obtained in one place: chosen, prepared, warmed, with its head start.

As unified-planning's factory hands its caller an engine ready to solve,
this module hands the attempt loop the planner of one run.  Two steps,
because one part must start before the problem is read:

1. :func:`open_planners` (a context around the whole run) makes the planner
   the options name, opens the run's warm pool and starts what that planner
   can start early (a unified-planning engine's worker imports the engine
   while the tool reads and scores), and takes the launcher's head start
   (Fast Downward on the full problem, started before the tool was
   imported).  When the run ends, the pool is closed and a head start
   nobody took over is stopped.
2. :meth:`PlannerSupply.for_task` (the problem read) or
   :meth:`PlannerSupply.for_unread` (our reader refused it) gives the one
   value the loop uses from then on, a :class:`SuppliedPlanner`: the chosen
   planner (``auto`` chooses by the problem's features), prepared for the
   problem (compilations, ``--planner-args``, ``--keep-work``), why it was
   chosen, and the handles on the warm pool a race needs.

The loop imports nothing else of this package but the run's records
(``base``).
"""

from __future__ import annotations

import contextlib
import os
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass, replace

from relevance_plan import errors
from relevance_plan.pddl.model import Domain, Problem
from relevance_plan.planning.planners.auto import AutoPlanner, FallbackPlanner
from relevance_plan.planning.planners.base import READER_REFUSED, Planner, PlannerStatus, RunOutcome
from relevance_plan.planning.planners.fast_downward import head_start
from relevance_plan.planning.planners.fast_downward.head_start import HeadStart
from relevance_plan.planning.planners.preparation import PreparedPlanner, prepare_planner, with_planner_args
from relevance_plan.planning.planners.registry import DEFAULT_PLANNER, DEFAULT_PLANNER_CONFIG, make_planner
from relevance_plan.planning.planners.up.adapter import UnifiedPlanningPlanner
from relevance_plan.planning.planners.up.pool import WorkerPool, current_pool, worker_pool

__all__ = [
    "DEFAULT_PLANNER",
    "DEFAULT_PLANNER_CONFIG",
    "PlannerRequest",
    "PlannerSupply",
    "SuppliedPlanner",
    "open_planners",
    "planner_for",
    "planner_for_unread",
    "warm_planners",
    "warm_up",
]


@dataclass(frozen=True)
class PlannerRequest:
    """What a run asks of its planner: the planner part of its options, and ``--keep-work``."""

    planner: str = DEFAULT_PLANNER  # a name as registry.make_planner takes it
    config: str = DEFAULT_PLANNER_CONFIG
    arguments: tuple[str, ...] = ()  # --planner-args
    memory_limit_mb: int | None = None
    keep_work: str | os.PathLike[str] | None = None

    @property
    def warms(self) -> bool:
        """Whether warm planners serve the run: not with --keep-work (each attempt's files stay apart)."""
        return self.keep_work is None


@dataclass(frozen=True)
class SuppliedPlanner:
    """The planner of one run, prepared for its problem; each :meth:`run` is one attempt."""

    prepared: PreparedPlanner
    choice: str  # why ``auto`` chose it ('' for a planner named by the user)
    memory_limit_mb: int | None
    warm: Planner | None = None  # what a race's pruned side warms up (None: no warm planners)
    head: HeadStart | None = None  # the launcher's run of the full problem, offered to the first full-problem run

    @property
    def name(self) -> str:
        return self.prepared.planner.name

    @property
    def proves_unsolvable(self) -> bool:
        return self.prepared.planner.proves_unsolvable

    @property
    def compilations(self) -> tuple[str, ...]:
        """What is compiled away for the planner, in order (``pddl.compile``)."""
        return self.prepared.compilations

    def run(self, domain_path: str, problem_path: str, time_limit: float | None) -> RunOutcome:
        """One attempt on this pair (a pruned problem, compiled first when needed)."""
        memory = self.memory_limit_mb
        outcome = self.prepared.run(domain_path, problem_path, time_limit=time_limit, memory_limit_mb=memory)
        return died_of_memory(outcome, memory)

    def run_full(self, domain_path: str, problem_path: str, time_limit: float | None) -> RunOutcome:
        """One attempt on the user's full problem, which the tool's reader has read: it may take the
        head start over, which is stopped after it in any case."""
        with head_start.offered(self.head):
            return refused_by_its_reader(self.run(domain_path, problem_path, time_limit))

    def began(self, started: float) -> float:
        """When the run began (``time.perf_counter()``): with a head start, when the launcher started
        the driver, so that times and limits count from there."""
        if self.head is None:
            return started
        return min(started, self.head.spawned.started + time.perf_counter() - time.monotonic())

    def answering(self, last: str) -> str:
        """The planner that gave the last answer (``last``, the deciding run's planner): ``auto``'s
        next one when its first gave up, else this planner."""
        return last if isinstance(self.prepared.planner, FallbackPlanner) and last else self.name

    @contextlib.contextmanager
    def beside(self) -> Iterator[WorkerPool]:
        """Warm planners for work beside the run's own (a race's pruned side): copies of the run's,
        started now, killed when the block ends.  The run's own serve the full problem."""
        with warm_planners(self.memory_limit_mb, beside=True) as pool:
            if self.warm is not None:
                warm_up(self.warm)
            yield pool

    def release(self) -> None:
        """Stop the warm planners of this thread's side now: nothing more will plan here."""
        pool = current_pool()
        if pool is not None:
            pool.close()

    def await_warm(self, until: float | None) -> None:
        """Wait (until ``until``, ``time.monotonic()``) for a warm planner still starting, so that an
        attempt's time limit is the planner's search, not its start."""
        first = _first(self.prepared.planner)
        if isinstance(first, UnifiedPlanningPlanner):
            first.await_warm(until)


@dataclass(frozen=True)
class PlannerSupply:
    """The run's planner as the options name it, before the problem is read (see :func:`open_planners`)."""

    request: PlannerRequest
    named: Planner
    head: HeadStart | None

    def for_task(
        self, domain: Domain, problem: Problem, problem_path: str, say: Callable[[str], None]
    ) -> SuppliedPlanner:
        """The planner for this problem (``auto`` chooses by its features), prepared for it; ``say``
        hears the choice and the compilations.  ``UnsupportedFeatureError`` or ``UsageError`` when
        the planner cannot take the problem or the options."""
        planner, choice = planner_for(self.named, domain, problem)
        if choice:
            say(f"planner: {planner.name} (auto: {choice})")
            if self.request.warms:
                warm_up(planner)
        request = self.request
        prepared = prepare_planner(planner, domain, problem, problem_path, request.arguments, request.keep_work, say)
        warm = planner if request.warms else None
        return SuppliedPlanner(prepared, choice, request.memory_limit_mb, warm, self.head)

    def for_unread(self, refused: errors.UnsupportedFeatureError) -> SuppliedPlanner:
        """The planner for input our reader refuses (planned unpruned, on the files as they are)."""
        planner, choice = planner_for_unread(self.named, refused)
        planner = with_planner_args(planner, self.request.arguments)
        return SuppliedPlanner(PreparedPlanner(planner), choice, self.request.memory_limit_mb)


@contextlib.contextmanager
def open_planners(request: PlannerRequest) -> Iterator[PlannerSupply]:
    """The run's planner made and, where it can be, warmed, inside its warm pool; the launcher's head
    start taken.  At the end of the block the pool is closed and an unclaimed head start stopped."""
    with warm_planners(request.memory_limit_mb):
        named = make_planner(request.planner, request.config)
        if request.warms:
            warm_up(named)  # a named engine starts now, beside the reading and scoring
        head = head_start.take()
        try:
            yield PlannerSupply(request, named, head)
        finally:
            if head is not None:
                head.discard()


# --------------------------------------------------------------------------- what an outcome means here


def died_of_memory(outcome: RunOutcome, memory_limit_mb: int | None) -> RunOutcome:
    """A planner that crashed under the memory limit the tool set ran out of memory, whatever its last
    words: with its address space capped, an allocation that fails can surface as any error (Fast
    Downward's translator has died of it with "SystemError: error return without exception set")."""
    if memory_limit_mb is None or outcome.status is not PlannerStatus.PLANNER_CRASH:
        return outcome
    died = f"it died under the {memory_limit_mb} MB --memory-limit"
    return replace(outcome, status=PlannerStatus.OUT_OF_MEMORY, reason=f"{outcome.reason}; {died}".lstrip("; "))


def refused_by_its_reader(outcome: RunOutcome) -> RunOutcome:
    """A planner whose own reader, which takes less than PDDL, cannot read the user's problem that the
    tool's reader has read: the planner does not take that input (a number written 1e308, say), which is
    not malformed PDDL.  (Fast Downward's adapter tells its translator's refusals of legal PDDL from
    malformed PDDL itself, by the translator's words.)"""
    if outcome.status is not PlannerStatus.INPUT_ERROR or outcome.raw_status != READER_REFUSED:
        return outcome
    refused = "its reader refuses the problem, which the tool's reader takes"
    return replace(outcome, status=PlannerStatus.UNSUPPORTED, reason=f"{outcome.reason}; {refused}".lstrip("; "))


# --------------------------------------------------------------------------- the pieces


def warm_planners(memory_limit_mb: int | None, beside: bool = False) -> contextlib.AbstractContextManager[WorkerPool]:
    """The run's warm planners (a unified-planning engine's worker), killed when the block ends;
    ``beside``: for work beside the run's own (the race's pruned side), copies of its warm planners."""
    return worker_pool(memory_limit_mb, beside)


def _first(planner: Planner) -> Planner:
    """The planner that runs first: for ``auto``'s choice with planners standing by, the chosen one."""
    return planner.first if isinstance(planner, FallbackPlanner) else planner


def warm_up(planner: Planner) -> None:
    """Start what ``planner`` can start before its first run, inside :func:`warm_planners`: a
    unified-planning engine's worker imports the engine while the tool reads and scores.  For
    ``auto``'s choice with planners standing by, only the first."""
    first = _first(planner)
    if isinstance(first, UnifiedPlanningPlanner):
        first.warm_up()


def planner_for(planner: Planner, domain: Domain, problem: Problem) -> tuple[Planner, str]:
    """The planner that runs on this problem, and why: ``auto`` chooses by its features; any other is itself."""
    if isinstance(planner, AutoPlanner):
        choice = planner.choose(domain, problem)
        return choice.planner, choice.reason
    return planner, ""


def planner_for_unread(planner: Planner, refused: errors.UnsupportedFeatureError) -> tuple[Planner, str]:
    """The planner for input our reader refuses (it is planned unpruned); ``auto`` chooses by the refusal."""
    if isinstance(planner, AutoPlanner):
        choice = planner.choose_unread(refused)
        return choice.planner, choice.reason
    return planner, ""
