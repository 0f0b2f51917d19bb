"""Child process of the ``up:NAME`` planners: read PDDL with unified-planning, solve, write the plan.

Run as ``python -m relevance_plan.planning.planners.up.child ENGINE DOMAIN PROBLEM PLAN VERDICT TIMEOUT``
by ``up.adapter.UnifiedPlanningPlanner``, inside its own session so that the
parent's watchdog can kill it (and whatever the engine started) at once.
The plan is written to PLAN in the IPC format with the names of the PDDL
files (a time-triggered plan as timed lines ``t: (action args) [d]``, the
duration left out for an instantaneous action); the engine's verdict, the name of its ``PlanGenerationResultStatus``,
to VERDICT (the parent maps it through ``up.adapter.UP_STATUS``).  When
unified-planning cannot read the files there is no verdict and the exit code
is ``up.adapter.CHILD_CANNOT_READ``.  A problem whose kind the engine does
not take is first rewritten into an equivalent one it takes when
``up.fitting`` can (integer fluents for whole values, flat types, guarded
undefined values, no quality metric), saying so on stderr.
"""

from __future__ import annotations

import contextlib
import sys
import time
from typing import TYPE_CHECKING, Any

from relevance_plan.planning.planners.up.adapter import CHILD_CANNOT_READ, ENGINE_FEATURES
from relevance_plan.planning.planners.up.deferred import defer_configspace

if TYPE_CHECKING:
    from relevance_plan.planning.planners.up.fitting import Fitted

# An engine that raises instead of answering cannot take the problem's features.
_REFUSED = "UNSUPPORTED_PROBLEM"
_CRASHED = "INTERNAL_ERROR"
# Engines that come with a ``register()`` of their own rather than in unified-planning's table.
REGISTERED_BY_PACKAGE = {"kairos": "up_kairos"}
# Engines that, given a quality metric and a timeout, search for better plans until the timeout.
FIRST_PLAN_ENGINES = frozenset({"kairos"})
# The least an engine is given to search when reading and fitting took nearly all of the time.
MIN_SEARCH_SECONDS = 0.1


def main(arguments: list[str]) -> int:
    engine, domain_path, problem_path, plan_path, verdict_path, timeout_text = arguments
    defer_configspace()  # a second of a core that no one-shot solve needs
    timeout = None if timeout_text == "none" else float(timeout_text)
    return solve_files(engine, domain_path, problem_path, plan_path, verdict_path, timeout)


def solve_files(
    engine: str, domain_path: str, problem_path: str, plan_path: str, verdict_path: str, timeout: float | None
) -> int:
    """Read, fit, solve and write the plan and the verdict; the child's exit code (the worker's answer).

    ``timeout`` covers the reading and fitting too: the engine's own timeout counts its search only."""
    started = time.monotonic()
    import unified_planning.shortcuts as shortcuts
    from unified_planning.engines.results import POSITIVE_OUTCOMES
    from unified_planning.io import PDDLReader

    shortcuts.get_environment().credits_stream = None
    register_engine(engine)
    try:
        problem = PDDLReader().parse_problem(domain_path, problem_path)
    except Exception as error:  # the engine's reader rejects it: an input error, said in the log
        print(f"unified-planning cannot read the problem: {error}", file=sys.stderr)
        return CHILD_CANNOT_READ
    fitted = _fit(shortcuts.get_environment(), engine, problem)
    if fitted is not None:
        problem = fitted.problem
    if engine in FIRST_PLAN_ENGINES and problem.quality_metrics:
        # with a metric and a timeout such an engine improves its plan until the timeout: the first one is wanted
        problem.clear_quality_metrics()
        print(f"{engine}: the quality metric left out (the first plan is wanted)", file=sys.stderr)
    lacking = () if fitted is None else fitted.lacking
    if timeout is not None:
        timeout = max(timeout - (time.monotonic() - started), MIN_SEARCH_SECONDS)
    try:
        with shortcuts.OneshotPlanner(name=engine, problem_kind=problem.kind) as planner:
            result = planner.solve(problem, timeout=timeout)
    except Exception as error:
        print(f"{engine}: {type(error).__name__}: {error}{_undeclared(lacking)}", file=sys.stderr)
        verdict = _REFUSED
    else:
        verdict = result.status.name
        print(f"{engine}: {verdict}")
        if verdict == _CRASHED and lacking and engine in ENGINE_FEATURES:
            # An engine whose limits were found by trying, failing on a kind it does not declare,
            # is refusing it: no wider or full problem would do better.
            print(f"{engine}: {verdict}{_undeclared(lacking)}: taken as {_REFUSED}", file=sys.stderr)
            verdict = _REFUSED
        if result.status in POSITIVE_OUTCOMES and result.plan is not None:
            with open(plan_path, "w", encoding="utf-8") as stream:
                stream.write("".join(line + "\n" for line in _plan_lines(result.plan)))
    with open(verdict_path, "w", encoding="utf-8") as stream:
        stream.write(verdict + "\n")
    return 0


def register_engine(engine: str) -> None:
    """Register an engine that unified-planning's own table of engines does not list (Kairos)."""
    if engine in REGISTERED_BY_PACKAGE:
        import importlib

        with contextlib.suppress(ImportError):  # not installed: the engine's lookup says so
            importlib.import_module(REGISTERED_BY_PACKAGE[engine]).register()


def _fit(environment: Any, engine: str, problem: Any) -> Fitted | None:
    """The problem rewritten for an engine that does not take its kind as read (``up.fitting``)."""
    try:
        from relevance_plan.planning.planners.up.fitting import fit_problem

        fitted = fit_problem(environment, engine, problem)
    except Exception as error:  # a rewrite that fails leaves the engine the problem as read
        print(f"{engine}: could not fit the problem to it ({type(error).__name__}: {error})", file=sys.stderr)
        return None
    for note in fitted.notes:
        print(f"{engine}: {note}", file=sys.stderr)
    return fitted


def _undeclared(lacking: tuple[str, ...]) -> str:
    return f" (on a problem of a kind it does not declare: {', '.join(lacking)})" if lacking else ""


def _plan_lines(plan: Any) -> list[str]:
    """The plan in the IPC format: timed lines for a time-triggered plan, else one action per line."""

    def step(instance: Any) -> str:
        return "(" + " ".join([instance.action.name, *(str(p) for p in instance.actual_parameters)]) + ")"

    timed = getattr(plan, "timed_actions", None)
    if timed is None:
        return [step(instance) for instance in plan.actions]
    lines: list[str] = []
    for start, instance, duration in timed:
        lines.append(f"{float(start)!r}: {step(instance)}" + ("" if duration is None else f" [{float(duration)!r}]"))
    return lines


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
