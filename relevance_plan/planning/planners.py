"""The planner registry: every planner the attempt loop can call, behind one contract.

A planner says which PDDL features it takes, refuses a problem that needs
more (``check``), and runs one domain/problem pair under a time and memory
limit, returning a :class:`~relevance_plan.planning.outcome.RunOutcome` whose
status it classified itself (solved with plan and cost, unsolvable, out of
time, out of memory, input error, configuration error, crash — with its
exit code explained in its own terms and the log tail).  ``PLANNERS`` maps a
kind to its adapter; a planner is named ``KIND`` or ``KIND:ARGUMENT``:

- ``fast-downward`` — Fast Downward from up-fast-downward (``--planner-config``
  chooses its alias or search): ``fast_downward.py``;
- ``up:NAME`` — a one-shot planner installed for unified-planning
  (``up:pyperplan``, ``up:symk``, ``up:lpg``, ...), run in a child process so
  that its time limit holds and a hung engine can be killed: ``up_engines.py``;
- ``cmd:TEMPLATE`` — any external planner: a command template with
  ``{domain}``, ``{problem}`` and optionally ``{plan}``, split into an
  argument list (never a shell): ``command.py``.

All of them run in their own session and temporary directory under the
watchdog of ``process.run_process_group``.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Protocol

from relevance_plan import errors
from relevance_plan.pddl.model import Domain, Problem
from relevance_plan.planning import fast_downward
from relevance_plan.planning.command import CommandPlanner
from relevance_plan.planning.fast_downward import FastDownwardPlanner
from relevance_plan.planning.outcome import RunOutcome
from relevance_plan.planning.up_engines import UnifiedPlanningPlanner

DEFAULT_PLANNER = fast_downward.NAME
DEFAULT_PLANNER_CONFIG = fast_downward.DEFAULT_CONFIG


class Planner(Protocol):
    @property
    def name(self) -> str: ...

    @property
    def features(self) -> frozenset[str] | None:
        """The PDDL features it takes (names from ``features.py``); None: unknown, it decides."""
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


PLANNERS: dict[str, Callable[[str, str], Planner]] = {
    fast_downward.NAME: lambda argument, config: FastDownwardPlanner(config),
    "up": lambda argument, config: UnifiedPlanningPlanner(argument),
    "cmd": lambda argument, config: CommandPlanner(argument),
}

# Kinds named without an argument.
_PLAIN = frozenset({fast_downward.NAME})


def make_planner(name: str, config: str = DEFAULT_PLANNER_CONFIG, check: bool = False) -> Planner:
    """The planner called ``name`` (``fast-downward``, ``up:NAME`` or ``cmd:TEMPLATE``).

    With ``check``, also verify that it can run (engine installed, executable
    found, template complete) — a front end does this once, before any work.
    """
    kind, _, argument = name.partition(":")
    if kind not in PLANNERS or (kind in _PLAIN) == bool(argument):
        raise errors.UsageError(f"unknown planner '{name}' (choose from: fast-downward, up:NAME, cmd:TEMPLATE)")
    planner = PLANNERS[kind](argument, config)
    if check:
        planner.check_installed()
    return planner


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
