"""The contract every planner adapter keeps, and what one planner run ends in.

:class:`Planner` is the protocol the attempt loop calls; :class:`RunOutcome`
is one run's status, plan, costs and the planner's own words.  Every
adapter (``fast_downward``, ``lpg``, ``up``, ``command``)
classifies its own exit codes into :class:`PlannerStatus` and says in
``reason`` what the planner reported in the planner's own terms, naming
whose terms they are ("Fast Downward exit code 23: search out of time"), so
no message ever shows a bare number that the tool's own exit table could
be taken to explain.
"""

from __future__ import annotations

import enum
import signal
from dataclasses import dataclass
from typing import Any, Protocol

from relevance_plan.errors import PlanFormatError
from relevance_plan.pddl.model import Domain, Problem
from relevance_plan.pddl.plans import Plan, read_plan


class PlannerStatus(enum.Enum):
    """How one planner run ended (values: hyphenated lower case, like every status of the tool)."""

    SOLVED = "solved"
    UNSOLVABLE = "unsolvable"
    SEARCH_INCOMPLETE = "search-incomplete"
    OUT_OF_TIME = "out-of-time"
    OUT_OF_MEMORY = "out-of-memory"
    INPUT_ERROR = "input-error"
    PLANNER_CONFIG_ERROR = "planner-config-error"  # the planner rejected its configuration, not the task
    UNSUPPORTED = "unsupported"
    PLANNER_CRASH = "planner-crash"
    STOPPED = "stopped"  # the tool stopped it: the race's other side decided first


# The ``raw_status`` of a run whose planner's own reader refused the files, where that reader takes less
# than PDDL (unified-planning's has no number written 1e308): when the tool's reader took them, the
# planner does not take that input, which is not malformed PDDL.
READER_REFUSED = "reader-refused"


class FinishedRun(Protocol):
    """A planner process that has ended, as the tool measured it: ``process.ProcessRun``, or a warm
    worker's answer to one request (``up.pool.WorkerAnswer``)."""

    @property
    def exit_code(self) -> int: ...

    @property
    def wall_time(self) -> float: ...

    @property
    def cpu_time(self) -> float: ...

    @property
    def peak_memory_mb(self) -> float: ...

    @property
    def watchdog_fired(self) -> bool: ...

    @property
    def process_group(self) -> int: ...


@dataclass(frozen=True, kw_only=True)
class RunOutcome:
    """One planner run.

    ``plan`` holds the steps lower-cased and without the planner's
    formatting.  ``exit_code`` is the planner process's (-N for death by
    signal N; None when no process ran, as for an engine called in-process).
    ``reason`` explains the end of the run in the planner's own terms and
    says whose they are; ``raw_status`` is the planner's own word for it
    (a driver code's name, an engine's status name), for logs.
    ``cpu_time`` and ``peak_memory_mb`` cover the processes the run reaped;
    ``translate_time`` and ``search_time`` are a planner's own reports, None
    if it gives none.  ``process_group`` is the run's (now dead) group id.
    An anytime planner (Fast Downward's ``lama``) lists every plan it wrote
    in ``plans``, each better than the one before.
    """

    status: PlannerStatus
    exit_code: int | None
    plan: Plan
    plan_cost: float | None
    wall_time: float
    planner: str
    cpu_time: float = 0.0
    peak_memory_mb: float = 0.0
    translate_time: float | None = None
    search_time: float | None = None
    config: str = ""
    log_tail: str = ""
    killed_by_watchdog: bool = False
    process_group: int | None = None
    raw_status: str = ""
    reason: str = ""
    optimal: bool = False  # the planner proved the plan optimal
    plans: tuple[Plan, ...] = ()  # an anytime run's plans in the order found (``plan`` is the last); else empty

    @classmethod
    def of_process(cls, run: FinishedRun, status: PlannerStatus, plan: Plan | None, **details: Any) -> RunOutcome:
        """The outcome of a finished planner process: exit code, times, memory, watchdog and group
        from ``run``; ``plan`` kept only when solved, its cost as the plan's; ``details`` add or override."""
        fields: dict[str, Any] = dict(
            status=status,
            exit_code=run.exit_code,
            plan=plan if plan is not None and status is PlannerStatus.SOLVED else Plan(),
            plan_cost=plan.cost if plan is not None else None,
            wall_time=run.wall_time,
            cpu_time=run.cpu_time,
            peak_memory_mb=run.peak_memory_mb,
            killed_by_watchdog=run.watchdog_fired,
            process_group=run.process_group,
        )
        fields.update(details)
        return cls(**fields)

    @property
    def solved(self) -> bool:
        return self.status is PlannerStatus.SOLVED


def parse_ipc_plan(text: str) -> Plan | None:
    """The plan in the IPC format, or None when a line is neither a step nor a comment."""
    try:
        return read_plan(text)
    except PlanFormatError:
        return None


def signal_reason(exit_code: int) -> str:
    """ "killed by SIGKILL" for exit code -9 (a death by signal)."""
    try:
        return f"killed by {signal.Signals(-exit_code).name}"
    except ValueError:
        return f"killed by signal {-exit_code}"


class Planner(Protocol):
    @property
    def name(self) -> str: ...

    @property
    def features(self) -> frozenset[str] | None:
        """The PDDL features it takes (names from ``requirements.py``); None: unknown, it decides."""
        ...

    @property
    def proves_unsolvable(self) -> bool:
        """Whether its search ends on a problem that has no plan (and says so), rather than searching
        until its time runs out.  The attempt loop gives a planner that cannot short, growing budgets
        on pruned problems, which pruning may have made unsolvable; unknown counts as no."""
        ...

    def check_installed(self) -> None:
        """Raise when it cannot run at all (engine not installed, executable not found, template incomplete)."""
        ...

    def check(self, domain: Domain, problem: Problem) -> None:
        """Raise UnsupportedFeatureError naming what the problem needs and it does not take."""
        ...

    def version(self) -> str: ...

    def run(
        self, domain_path: str, problem_path: str, *, time_limit: float | None, memory_limit_mb: int | None
    ) -> RunOutcome: ...
