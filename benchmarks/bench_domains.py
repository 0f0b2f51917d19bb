"""Without a knowledge model: pure vs relevance (goal scorer) on classic domains.

Blocksworld with extra towers and blocks stacked on the goal's blocks (100,
200 and 300 extra blocks), and gripper with extra balls (200, 500 and 1,000),
in one run.  The relevance method here uses the domain-independent goal
scorer (no model applies to these domains).  Prints one row per problem:
pure and relevance wall times, their ratio, objects kept, and whether the
plan is valid on the original problem.  Every run is stored in a results
store (``--store``; one suite per domain and size), which ``relevance-plan
report`` shows.

Takes about a minute on 2 cores (pure planning on the 300-block problem is
most of it).

    python benchmarks/bench_domains.py          # timeout 120 s per planning run
    python benchmarks/bench_domains.py 60       # the table in docs/results.md
"""

from __future__ import annotations

import argparse
import tempfile
from pathlib import Path

from base import Store, add_store_option, run_method, show_time, speedup, table_header, table_row

from relevance_plan.generators.padded import BLOCKSWORLD_DOMAIN, GRIPPER_DOMAIN, blocksworld_problem, gripper_problem
from relevance_plan.planning.options import PlanOptions

CASES = [
    ("blocksworld", BLOCKSWORLD_DOMAIN, lambda n: blocksworld_problem(n, seed=1, in_the_way=3), (100, 200, 300)),
    ("gripper", GRIPPER_DOMAIN, lambda n: gripper_problem(n), (200, 500, 1000)),
]


def parse_args(argv: list[str] | None = None) -> argparse.Namespace:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("timeout", nargs="?", type=float, default=120.0, help="seconds per planning run (default: 120)")
    add_store_option(parser)
    return parser.parse_args(argv)


def main(argv: list[str] | None = None) -> int:
    args = parse_args(argv)
    print(f"timeout {args.timeout:g} s, lama-first; relevance = goal scorer (no knowledge model)")
    table_header("domain | extra objects | pure (s) | relevance (s) | pure/relevance | kept | plan valid")
    with tempfile.TemporaryDirectory(prefix="bench-domains-") as scratch, Store(args.store, "bench_domains") as store:
        for name, domain_text, make, sizes in CASES:
            domain_path = Path(scratch) / f"{name}-domain.pddl"
            domain_path.write_text(domain_text)
            for size in sizes:
                problem_path = Path(scratch) / f"{name}-{size}.pddl"
                problem_path.write_text(make(size))
                suite = f"{name} +{size}"
                pure, relevance = (
                    run_method(
                        domain_path, problem_path, PlanOptions(method=method, timeout=args.timeout), store, suite
                    )[1]
                    for method in ("pure", "relevance")
                )
                shown = (show_time(pure), f"{relevance.time:.2f}", speedup(pure, relevance))
                table_row(name, size, *shown, f"{relevance.kept}/{relevance.total}", relevance.valid)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
