"""Child process of the ``up:NAME`` planners: read PDDL with unified-planning, solve, write the plan.

Run as ``python -m relevance_plan.planning.up_child ENGINE DOMAIN PROBLEM PLAN TIMEOUT``
by ``planners.UnifiedPlanningPlanner``, inside its own session so that the
parent's watchdog can kill it (and whatever the engine started) at once.
The plan is written in the IPC format with the names of the PDDL files; the
exit code says how the engine ended (``planners.UP_CHILD_STATUS``).
"""

from __future__ import annotations

import sys


def main(arguments: list[str]) -> int:
    engine, domain_path, problem_path, plan_path, timeout_text = arguments
    import unified_planning.shortcuts as shortcuts
    from unified_planning.engines.results import PlanGenerationResultStatus as Status
    from unified_planning.io import PDDLReader

    shortcuts.get_environment().credits_stream = None
    try:
        problem = PDDLReader().parse_problem(domain_path, problem_path)
    except Exception as error:  # the engine's reader rejects it: an input error, said in the log
        print(f"unified-planning cannot read the problem: {error}", file=sys.stderr)
        return 31
    timeout = None if timeout_text == "none" else float(timeout_text)
    try:
        with shortcuts.OneshotPlanner(name=engine, problem_kind=problem.kind) as planner:
            result = planner.solve(problem, timeout=timeout)
    except Exception as error:  # the engine cannot take the problem's features
        print(f"{engine}: {type(error).__name__}: {error}", file=sys.stderr)
        return 34
    print(f"{engine}: {result.status.name}")
    if result.status in (Status.SOLVED_SATISFICING, Status.SOLVED_OPTIMALLY) and result.plan is not None:
        lines = []
        for step in result.plan.actions:
            names = [step.action.name] + [str(parameter) for parameter in step.actual_parameters]
            lines.append("(" + " ".join(names) + ")")
        with open(plan_path, "w", encoding="utf-8") as stream:
            stream.write("\n".join(lines) + "\n")
        return 0
    return {
        Status.UNSOLVABLE_PROVEN: 10,
        Status.UNSOLVABLE_INCOMPLETELY: 12,
        Status.MEMOUT: 22,
        Status.TIMEOUT: 23,
        Status.UNSUPPORTED_PROBLEM: 34,
    }.get(result.status, 30)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
