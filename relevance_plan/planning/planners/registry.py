"""The planner registry: every planner the attempt loop can call, behind one contract.

A planner says which PDDL features it takes, refuses a problem that needs
more (``check``), and runs one domain/problem pair under a time and memory
limit, returning a :class:`~relevance_plan.planning.planners.base.RunOutcome` whose
status it classified itself (solved with plan and cost, unsolvable, out of
time, out of memory, input error, configuration error, crash — with its
exit code explained in its own terms and the log tail).  ``PLANNERS`` maps a
kind to its adapter; a planner is named ``KIND`` or ``KIND:ARGUMENT``:

- ``auto`` (the default) — the installed planner that takes what the problem
  uses, chosen by its features: ``auto.py``;
- ``fast-downward`` — Fast Downward from up-fast-downward (``--planner-config``
  chooses its alias or search): ``fast_downward/``;
- ``lpg`` — the LPG-td binary of up-lpg (temporal and numeric PDDL 2.1): ``lpg.py``;
- ``up:NAME`` — a one-shot planner installed for unified-planning
  (``up:aries``, ``up:tamer``, ``up:enhsp``, ``up:pyperplan``, ``up:symk``, ...), run in a child process so
  that its time limit holds and a hung engine can be killed: ``up/``;
- ``cmd:TEMPLATE`` — any external planner: a command template with
  ``{domain}``, ``{problem}`` and optionally ``{plan}``, split into an
  argument list (never a shell): ``command.py``.

All of them run in their own session and temporary directory under the
watchdog of ``process.run_process_group``.
"""

from __future__ import annotations

from collections.abc import Callable
from contextlib import AbstractContextManager

from relevance_plan import errors
from relevance_plan.pddl.model import Domain, Problem
from relevance_plan.planning.planners import auto, lpg
from relevance_plan.planning.planners.auto import AutoPlanner, FallbackPlanner
from relevance_plan.planning.planners.base import Planner
from relevance_plan.planning.planners.command import CommandPlanner
from relevance_plan.planning.planners.fast_downward import adapter as fast_downward
from relevance_plan.planning.planners.fast_downward import command_line, head_start
from relevance_plan.planning.planners.fast_downward.adapter import FastDownwardPlanner
from relevance_plan.planning.planners.lpg import LpgPlanner
from relevance_plan.planning.planners.up.adapter import UnifiedPlanningPlanner
from relevance_plan.planning.planners.up.pool import WorkerPool, current_pool, worker_pool

DEFAULT_PLANNER = auto.NAME
DEFAULT_PLANNER_CONFIG = command_line.DEFAULT_CONFIG

# A run of the full problem the launcher started before the tool was imported (Fast Downward's, today):
# the loop takes it, offers it to its first call on the full problem, and stops it if not taken over.
take_early_run = head_start.take
offer_early_run = head_start.offered


PLANNERS: dict[str, Callable[[str, str], Planner]] = {
    auto.NAME: lambda argument, config: AutoPlanner(config),
    fast_downward.NAME: lambda argument, config: FastDownwardPlanner(config),
    lpg.NAME: lambda argument, config: LpgPlanner(),
    "up": lambda argument, config: UnifiedPlanningPlanner(argument),
    "cmd": lambda argument, config: CommandPlanner(argument),
}

# Kinds named without an argument.
_PLAIN = frozenset({auto.NAME, fast_downward.NAME, lpg.NAME})


def make_planner(name: str, config: str = DEFAULT_PLANNER_CONFIG, check: bool = False) -> Planner:
    """The planner called ``name`` (``auto``, ``fast-downward``, ``lpg``, ``up:NAME`` or ``cmd:TEMPLATE``).

    With ``check``, also verify that it can run (engine installed, executable
    found, template complete) — a front end does this once, before any work.
    """
    kind, _, argument = name.partition(":")
    if kind not in PLANNERS or (kind in _PLAIN) == bool(argument):
        raise errors.UsageError(
            f"unknown planner '{name}' (choose from: auto, fast-downward, lpg, up:NAME, cmd:TEMPLATE)"
        )
    planner = PLANNERS[kind](argument, config)
    if check:
        planner.check_installed()
    return planner


def warm_planners(memory_limit_mb: int | None, beside: bool = False) -> AbstractContextManager[WorkerPool]:
    """The run's warm planners (a unified-planning engine's worker), killed when the block ends;
    ``beside``: for work beside the run's own (the race's pruned side), copies of its warm planners."""
    return worker_pool(memory_limit_mb, beside)


def warm_up(planner: Planner) -> None:
    """Start what ``planner`` can start before its first run, inside :func:`warm_planners`: a
    unified-planning engine's worker imports the engine while the tool reads and scores.  For
    ``auto``'s choice with planners standing by, only the first."""
    first = planner.first if isinstance(planner, FallbackPlanner) else planner
    if isinstance(first, UnifiedPlanningPlanner):
        first.warm_up()


def release_warm() -> None:
    """Stop now what :func:`warm_up` started in this thread's run: nothing more will plan here."""
    pool = current_pool()
    if pool is not None:
        pool.close()


def await_warm(planner: Planner, until: float | None) -> None:
    """Wait (until ``until``, ``time.monotonic()``) for what :func:`warm_up` started to be ready, so
    that an attempt's time limit is the planner's search, not its start."""
    first = planner.first if isinstance(planner, FallbackPlanner) else planner
    if isinstance(first, UnifiedPlanningPlanner):
        first.await_warm(until)


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


def split_planner_names(text: str) -> tuple[str, ...]:
    """``fast-downward,up:pyperplan`` -> names; a ``cmd:`` template may contain commas, so it must come last."""
    names: list[str] = []
    rest = text.strip()
    while rest:
        if rest.startswith("cmd:"):
            names.append(rest)
            break
        head, _, rest = rest.partition(",")
        if head.strip():
            names.append(head.strip())
        rest = rest.strip()
    if not names:
        raise errors.UsageError("no planner given")
    return tuple(dict.fromkeys(names))
