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
watchdog of ``process.run_process_group``.  The attempt loop gets its
planner through ``supply``, which makes it here.
"""

from __future__ import annotations

from collections.abc import Callable

from relevance_plan import errors
from relevance_plan.planning.planners import auto, lpg
from relevance_plan.planning.planners.auto import AutoPlanner
from relevance_plan.planning.planners.base import Planner
from relevance_plan.planning.planners.command import CommandPlanner
from relevance_plan.planning.planners.fast_downward import adapter as fast_downward
from relevance_plan.planning.planners.fast_downward import command_line
from relevance_plan.planning.planners.fast_downward.adapter import FastDownwardPlanner
from relevance_plan.planning.planners.lpg import LpgPlanner
from relevance_plan.planning.planners.up.adapter import UnifiedPlanningPlanner

DEFAULT_PLANNER = auto.NAME
DEFAULT_PLANNER_CONFIG = command_line.DEFAULT_CONFIG

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
