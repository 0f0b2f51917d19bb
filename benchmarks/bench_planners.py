"""Pure vs relevance across planner families, measured in one run.

For each planner (Fast Downward lama-first, SymK through unified-planning,
LPG through unified-planning, by default) and each problem (the coffee world
at 10, 50 and 100 distractors; blocksworld and gripper padded with objects
the goal does not need), runs ``pure`` and ``relevance`` through the same
attempt loop and prints their times and the ratio.  Every reported plan was
validated on the original problem; a run without a valid plan is shown with
its status.  ``up:`` planners need their packages (``pip install -e
'.[planners]'``); a planner that is not installed is refused before any run.
Every run is stored in a results store (``--store``; one suite per problem,
one block per planner in the report), which ``relevance-plan report`` shows.

Takes about 11 minutes on 2 cores with the defaults: pure SymK runs out of
the 120 s timeout on four of the five problems.  Fast Downward alone
(``--planners fast-downward``) takes under a minute.

    python benchmarks/bench_planners.py
    python benchmarks/bench_planners.py --planners fast-downward,up:pyperplan --timeout 60
"""

from __future__ import annotations

import argparse
import tempfile
from pathlib import Path

from base import Measured, Store, add_store_option, run_method, speedup, table_header, table_row

from relevance_plan.generators import WORLDS, Settings
from relevance_plan.generators.padded import BLOCKSWORLD_DOMAIN, GRIPPER_DOMAIN, blocksworld_problem, gripper_problem
from relevance_plan.planning.options import PlanOptions
from relevance_plan.planning.planners.registry import make_planner, split_planner_names


def problems(scratch: Path) -> list[tuple[str, Path, Path]]:
    found = []
    for distractors in (10, 50, 100):
        suite = scratch / f"coffee-{distractors}"
        (problem,) = WORLDS["coffee"].suite(1, 1, suite, Settings("simple", distractors=distractors))
        found.append((f"coffee +{distractors}", suite / "domain.pddl", problem))
    for name, domain_text, problem_text in (
        ("blocksworld +60", BLOCKSWORLD_DOMAIN, blocksworld_problem(60, seed=1, in_the_way=3)),
        ("gripper +100", GRIPPER_DOMAIN, gripper_problem(100, rooms=4)),
    ):
        domain = scratch / f"{name.split()[0]}-domain.pddl"
        domain.write_text(domain_text)
        problem = scratch / f"{name.split()[0]}-problem.pddl"
        problem.write_text(problem_text)
        found.append((name, domain, problem))
    return found


def seconds(run: Measured) -> str:
    if run.solved and run.valid:
        return f"{run.time:.2f}"
    return f"{run.status} ({run.time:.0f} s)"


def parse_args(argv: list[str] | None = None) -> argparse.Namespace:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument(
        "--planners",
        default="fast-downward,up:symk,up:lpg",
        help="comma-separated planner names, as for --planner (default: fast-downward,up:symk,up:lpg)",
    )
    parser.add_argument("--timeout", type=float, default=120.0, help="seconds per planning run (default: 120)")
    add_store_option(parser)
    return parser.parse_args(argv)


def main(argv: list[str] | None = None) -> int:
    args = parse_args(argv)
    planners = split_planner_names(args.planners)
    for name in planners:
        make_planner(name, check=True)
    print(f"timeout {args.timeout:g} s per run; relevance = knowledge model (coffee) or goal scorer (classic)")
    table_header("planner | problem | objects | pure (s) | relevance (s) | pure/relevance | kept | attempts")
    with tempfile.TemporaryDirectory(prefix="bench-planners-") as scratch, Store(args.store, "bench_planners") as store:
        cases = problems(Path(scratch))
        for planner in planners:
            for label, domain, problem in cases:
                pure, relevance = (
                    run_method(
                        domain, problem, PlanOptions(method=method, planner=planner, timeout=args.timeout), store, label
                    )[1]
                    for method in ("pure", "relevance")
                )
                shown = (seconds(pure), seconds(relevance), speedup(pure, relevance, validated=True))
                table_row(
                    planner, label, relevance.total, *shown, f"{relevance.kept}/{relevance.total}", relevance.attempts
                )
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
