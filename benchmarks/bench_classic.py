"""Classic many-object domains without a knowledge model: pure vs relevance vs oracle, in one run.

Generates seeded suites of the classic worlds (``relevance-plan generate
<world>``), runs Fast Downward ``lama-first`` on the full problem (pure), the
relevance method (goal scorer: no model applies) and, where the sidecar has a
``necessary`` set, the oracle; every plan is validated on the original
problem.  Prints one row per problem as it goes, then per domain the median
times, the pure/relevance ratio of the medians, objects kept, attempts, and
the geometric mean of the ratios over domains, each next to its target:
geometric-mean speed-up >= 5x, median attempts <= 2, no problem slower than
pure by more than 25 % + 1 s, every plan valid, no relevance failure.
Every run is stored in a results store (``--store``; one suite per world),
which ``relevance-plan report`` shows.

Takes about 3 minutes on 2 cores with the defaults (one problem per world;
pure planning takes 10-45 s per problem), about 7 minutes with --count 3,
and under a minute with --unpadded.

    python benchmarks/bench_classic.py                       # untyped worlds, default sizes
    python benchmarks/bench_classic.py --count 3 --seed 1    # the table in docs/results.md
    python benchmarks/bench_classic.py --typed --count 2 --seed 7
    python benchmarks/bench_classic.py --unpadded            # every movable object in the goal
    python benchmarks/bench_classic.py --worlds logistics grid --size 600
"""

from __future__ import annotations

import argparse
import json
import statistics
import tempfile
from dataclasses import asdict
from pathlib import Path

from base import (
    DOMAINS,
    Store,
    add_store_option,
    add_worlds_option,
    geometric_mean,
    median,
    run_method,
    show_time,
    table_header,
    table_row,
)

from relevance_plan.generators import CLASSIC, worlds_of
from relevance_plan.generators.classic import generate_classic_problem
from relevance_plan.planning.options import PlanOptions

UNPADDED_SIZES = {"blocksworld": 40, "logistics": 60, "gripper": 60, "ferry": 60, "grid": 60, "miconic": 80}
METHODS = ("pure", "relevance", "oracle")
# The six classic domains, by their untyped worlds' names (--typed runs their typed forms).
FAMILIES = tuple(world.name for world in worlds_of(CLASSIC) if world.base == world.name)


def parse_args(argv: list[str] | None = None) -> argparse.Namespace:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    add_worlds_option(parser, FAMILIES, FAMILIES, f"classic worlds to run (default: all of {', '.join(FAMILIES)})")
    parser.add_argument("--typed", action="store_true", help="use the typed variants")
    parser.add_argument("--unpadded", action="store_true", help="every movable object in the goal, small sizes")
    parser.add_argument("--count", type=int, default=1, help="problems per world (default: 1)")
    parser.add_argument("--seed", type=int, default=1, help="generator seed (default: 1)")
    parser.add_argument("--size", type=int, default=None, help="objects per problem (default: each world's)")
    parser.add_argument("--timeout", type=float, default=120.0, help="seconds per planning run (default: 120)")
    parser.add_argument("--json", type=Path, default=None, help="also write the raw rows here")
    add_store_option(parser)
    return parser.parse_args(argv)


def plan_all(args: argparse.Namespace, scratch: Path, store: Store) -> list[dict]:
    """Every problem of every world with each method, one row per problem as it goes."""
    rows = []
    print(
        f"lama-first, timeout {args.timeout:g} s, seed {args.seed}, {args.count} problem(s) per world"
        f"{', typed' if args.typed else ', untyped'}{', unpadded' if args.unpadded else ''}; relevance = goal scorer"
    )
    table_header("problem | objects | pure (s) | relevance (s) | kept | attempts | oracle (s) | valid")
    for base in args.worlds:
        world = f"{base}-typed" if args.typed else base
        domain_path = DOMAINS / world / "domain.pddl"
        size = UNPADDED_SIZES[base] if args.unpadded and args.size is None else args.size
        for index in range(1, args.count + 1):
            problem = generate_classic_problem(world, args.seed, index, size, dense=args.unpadded)
            problem_path = scratch / f"{problem.name}.pddl"
            problem_path.write_text(problem.pddl_text)
            problem_path.with_suffix(".json").write_text(json.dumps(problem.sidecar))
            row = {"world": world, "problem": problem.name, "objects": problem.sidecar["objects_total"]}
            for method in METHODS:
                if method == "oracle" and "necessary" not in problem.sidecar:
                    row[method] = None
                    continue
                options = PlanOptions(method=method, timeout=args.timeout)
                row[method] = run_method(domain_path, problem_path, options, store, world)[1]
            rows.append(row)
            pure, rel, oracle = row["pure"], row["relevance"], row["oracle"]
            valid = all(r.valid for r in (pure, rel, oracle) if r is not None and r.solved)
            table_row(
                problem.name,
                row["objects"],
                show_time(pure),
                show_time(rel),
                rel.kept,
                rel.attempts,
                show_time(oracle),
                valid,
            )
    return rows


def summarise(rows: list[dict]) -> None:
    print()
    table_header(
        "domain | problems | objects | pure median (s) | relevance median (s) | "
        "pure/relevance | kept median | attempts median | oracle median (s) | failures"
    )
    ratios = []
    for world in dict.fromkeys(r["world"] for r in rows):
        mine = [r for r in rows if r["world"] == world]
        pure_t = median(r["pure"].time for r in mine)
        rel_t = median(r["relevance"].time for r in mine)
        oracle_t = median(r["oracle"].time for r in mine if r["oracle"])
        ratio = pure_t / rel_t if rel_t else None
        unsolved_pure = any(not r["pure"].solved for r in mine)
        failures = sum(not r["relevance"].solved or not r["relevance"].valid for r in mine)
        if ratio:
            ratios.append(ratio)
        table_row(
            world,
            len(mine),
            f"{median(r['objects'] for r in mine):.0f}",
            f"{pure_t:.2f}{' (timeouts)' if unsolved_pure else ''}",
            f"{rel_t:.2f}",
            f"{'>' if unsolved_pure else ''}{ratio:.1f}x",
            f"{median(r['relevance'].kept for r in mine):.0f}",
            f"{median(r['relevance'].attempts for r in mine):.0f}",
            f"{oracle_t:.2f}" if oracle_t is not None else "–",
            failures,
        )
    slower = [r["problem"] for r in rows if r["relevance"].time > 1.25 * r["pure"].time + 1.0]
    within = [r["problem"] for r in rows if r["relevance"].time > 1.1 * r["pure"].time + 0.5]
    invalid = [r["problem"] for r in rows for m in METHODS if r[m] is not None and r[m].solved and not r[m].valid]
    failed = [r["problem"] for r in rows if not r["relevance"].solved]
    print()
    print(f"geometric mean pure/relevance over {len(ratios)} domains: {geometric_mean(ratios):.2f}x (target >= 5x)")
    print(f"median attempts: {statistics.median(r['relevance'].attempts for r in rows):.0f} (target <= 2)")
    print(f"slower than pure by more than 25 % + 1 s: {', '.join(slower) or 'none'}")
    print(f"slower than pure by more than 10 % + 0.5 s: {', '.join(within) or 'none'}")
    print(f"invalid plans: {', '.join(invalid) or 'none'}; relevance failures: {', '.join(failed) or 'none'}")


def main(argv: list[str] | None = None) -> int:
    args = parse_args(argv)
    with tempfile.TemporaryDirectory(prefix="bench-classic-") as scratch, Store(args.store, "bench_classic") as store:
        rows = plan_all(args, Path(scratch), store)
    summarise(rows)
    if args.json:
        raw = [{key: asdict(value) if key in METHODS and value else value for key, value in r.items()} for r in rows]
        args.json.write_text(json.dumps(raw, indent=2))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
