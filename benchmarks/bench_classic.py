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
import math
import statistics
import sys
import tempfile
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(REPO))

from relevance_plan.generators.classic import BUILDERS, generate_classic_problem  # noqa: E402
from relevance_plan.planning.loop import PlanOptions, plan_task  # noqa: E402
from relevance_plan.planning.results import PlanStatus  # noqa: E402

UNPADDED_SIZES = {"blocksworld": 40, "logistics": 60, "gripper": 60, "ferry": 60, "grid": 60, "miconic": 80}


def run(domain_path: Path, problem_path: Path, method: str, timeout: float) -> dict:
    result = plan_task(domain_path, problem_path, PlanOptions(method=method, timeout=timeout))
    return {
        "status": result.status.value,
        "solved": result.status is PlanStatus.SOLVED,
        "valid": result.valid,
        "time": result.wall_time,
        "kept": result.objects_kept,
        "total": result.objects_total,
        "attempts": len(result.attempts),
        "relevance_time": result.relevance_time,
    }


def median(values):
    values = [v for v in values if v is not None]
    return statistics.median(values) if values else None


def parse_args(argv: list[str] | None = None) -> argparse.Namespace:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument(
        "--worlds",
        nargs="*",
        default=list(BUILDERS),
        choices=list(BUILDERS),
        metavar="WORLD",
        help=f"classic worlds to run (default: all of {', '.join(BUILDERS)})",
    )
    parser.add_argument("--typed", action="store_true", help="use the typed variants")
    parser.add_argument("--unpadded", action="store_true", help="every movable object in the goal, small sizes")
    parser.add_argument("--count", type=int, default=1, help="problems per world (default: 1)")
    parser.add_argument("--seed", type=int, default=1, help="generator seed (default: 1)")
    parser.add_argument("--size", type=int, default=None, help="objects per problem (default: each world's)")
    parser.add_argument("--timeout", type=float, default=120.0, help="seconds per planning run (default: 120)")
    parser.add_argument("--json", type=Path, default=None, help="also write the raw rows here")
    return parser.parse_args(argv)


def main() -> int:
    args = parse_args()

    rows = []
    print(
        f"lama-first, timeout {args.timeout:g} s, seed {args.seed}, {args.count} problem(s) per world"
        f"{', typed' if args.typed else ', untyped'}{', unpadded' if args.unpadded else ''}; relevance = goal scorer"
    )
    print("| problem | objects | pure (s) | relevance (s) | kept | attempts | oracle (s) | valid |")
    print("|---|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory(prefix="bench-classic-") as scratch:
        for base in args.worlds:
            world = f"{base}-typed" if args.typed else base
            domain_path = REPO / "relevance_plan" / "data" / "domains" / world / "domain.pddl"
            size = UNPADDED_SIZES[base] if args.unpadded and args.size is None else args.size
            for index in range(1, args.count + 1):
                problem = generate_classic_problem(world, args.seed, index, size, dense=args.unpadded)
                problem_path = Path(scratch) / f"{problem.name}.pddl"
                problem_path.write_text(problem.pddl_text)
                problem_path.with_suffix(".json").write_text(json.dumps(problem.sidecar))
                row = {"world": world, "problem": problem.name, "objects": problem.sidecar["objects_total"]}
                row["pure"] = run(domain_path, problem_path, "pure", args.timeout)
                row["relevance"] = run(domain_path, problem_path, "relevance", args.timeout)
                row["oracle"] = (
                    run(domain_path, problem_path, "oracle", args.timeout) if "necessary" in problem.sidecar else None
                )
                rows.append(row)
                pure, rel, oracle = row["pure"], row["relevance"], row["oracle"]
                valid = all(r["valid"] for r in (pure, rel, oracle) if r is not None and r["solved"])
                print(
                    f"| {problem.name} | {row['objects']} | {_time(pure)} | {_time(rel)} |"
                    f" {rel['kept']} | {rel['attempts']} | {_time(oracle) if oracle else '–'} | {valid} |",
                    flush=True,
                )

    print()
    print(
        "| domain | problems | objects | pure median (s) | relevance median (s) | pure/relevance |"
        " kept median | attempts median | oracle median (s) | failures |"
    )
    print("|---|---|---|---|---|---|---|---|---|---|")
    ratios = []
    worst = []
    for world in dict.fromkeys(r["world"] for r in rows):
        mine = [r for r in rows if r["world"] == world]
        pure_t = median([r["pure"]["time"] for r in mine])
        rel_t = median([r["relevance"]["time"] for r in mine])
        oracle_t = median([r["oracle"]["time"] for r in mine if r["oracle"]])
        ratio = pure_t / rel_t if rel_t else None
        unsolved_pure = any(not r["pure"]["solved"] for r in mine)
        failures = sum(not r["relevance"]["solved"] or not r["relevance"]["valid"] for r in mine)
        if ratio:
            ratios.append(ratio)
        for r in mine:
            worst.append((r["relevance"]["time"] - (1.25 * r["pure"]["time"] + 1.0), r["problem"]))
        print(
            f"| {world} | {len(mine)} | {median([r['objects'] for r in mine]):.0f} |"
            f" {pure_t:.2f}{' (timeouts)' if unsolved_pure else ''} | {rel_t:.2f} |"
            f" {'>' if unsolved_pure else ''}{ratio:.1f}x | {median([r['relevance']['kept'] for r in mine]):.0f} |"
            f" {median([r['relevance']['attempts'] for r in mine]):.0f} |"
            f" {f'{oracle_t:.2f}' if oracle_t is not None else '–'} | {failures} |"
        )
    geomean = math.exp(sum(math.log(r) for r in ratios) / len(ratios)) if ratios else float("nan")
    all_attempts = [r["relevance"]["attempts"] for r in rows]
    slower = [name for excess, name in worst if excess > 0]
    within = [r["problem"] for r in rows if r["relevance"]["time"] > 1.1 * r["pure"]["time"] + 0.5]
    invalid = [
        r["problem"]
        for r in rows
        for m in ("pure", "relevance", "oracle")
        if r[m] is not None and r[m]["solved"] and not r[m]["valid"]
    ]
    failed = [r["problem"] for r in rows if not r["relevance"]["solved"]]
    print()
    print(f"geometric mean pure/relevance over {len(ratios)} domains: {geomean:.2f}x (target >= 5x)")
    print(f"median attempts: {statistics.median(all_attempts):.0f} (target <= 2)")
    print(f"slower than pure by more than 25 % + 1 s: {', '.join(slower) or 'none'}")
    print(f"slower than pure by more than 10 % + 0.5 s: {', '.join(within) or 'none'}")
    print(f"invalid plans: {', '.join(invalid) or 'none'}; relevance failures: {', '.join(failed) or 'none'}")
    if args.json:
        args.json.write_text(json.dumps(rows, indent=2))
    return 0


def _time(result: dict | None) -> str:
    if result is None:
        return "–"
    return f"{result['time']:.2f}" if result["solved"] else f"{result['status']} ({result['time']:.0f})"


if __name__ == "__main__":
    raise SystemExit(main())
