"""Pure vs relevance vs oracle planning time, measured in one run.

For each world and distractor count, generates problems (seeded), runs every
method on each with the same timeout, and prints median times and the
ratios pure/relevance and relevance/oracle.  Every reported plan was
validated on the original problem (a method whose plan is not valid counts as
failed).  Targets: relevance at least 20x faster than pure at 100
distractors, within 1.5x of the oracle at every size, under 3 s at 1,000
distractors, no failures.

Takes about 3.5 minutes on 2 cores with the defaults (pure planning at 100
distractors, 16-25 s per problem, is most of it).

    python benchmarks/bench_planning.py                       # coffee+cereal, 10/50/100/1000
    python benchmarks/bench_planning.py --worlds coffee --sizes 10,50,100 --methods pure,oracle
"""

from __future__ import annotations

import argparse
import statistics
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(REPO))

from relevance_plan.generators.generate import generate_suite  # noqa: E402
from relevance_plan.planning.loop import PlanOptions, plan_task  # noqa: E402
from relevance_plan.planning.results import PlanStatus  # noqa: E402


def run(args: argparse.Namespace) -> int:
    sizes = [int(s) for s in args.sizes.split(",")]
    methods = args.methods.split(",")
    worlds = args.worlds.split(",")
    rows = []
    with tempfile.TemporaryDirectory(prefix="bench-planning-") as scratch:
        for world in worlds:
            for size in sizes:
                suite = Path(scratch) / f"{world}-{size}"
                generate_suite(world, "simple", args.problems, args.seed, suite, distractors=size)
                problems = sorted(p for p in suite.glob("*.pddl") if p.name != "domain.pddl")
                times: dict[str, list[float]] = {m: [] for m in methods}
                kept: dict[str, list[int]] = {m: [] for m in methods}
                failures: dict[str, int] = {m: 0 for m in methods}
                total_objects = 0
                for problem in problems:
                    for method in methods:
                        if method == "pure" and size > args.max_pure:
                            continue
                        # Sub-second runs vary by ~30 %: repeat the cheap methods, take the median.
                        repeats = 1 if method == "pure" else args.repeats
                        runs = [
                            plan_task(suite / "domain.pddl", problem, PlanOptions(method=method, timeout=args.timeout))
                            for _ in range(repeats)
                        ]
                        result = runs[-1]
                        ok = all(r.status is PlanStatus.SOLVED and r.valid for r in runs)
                        failures[method] += 0 if ok else 1
                        times[method].append(statistics.median(r.wall_time for r in runs) if ok else args.timeout)
                        kept[method].append(result.objects_kept)
                        total_objects = result.objects_total
                        print(
                            f"  {world:<6} {size:>5} {problem.stem:<22} {method:<9} {result.status.value:<14}"
                            f" {result.wall_time:7.2f} s  kept {result.objects_kept}/{result.objects_total}"
                            f"  attempts {len(result.attempts)}",
                            file=sys.stderr,
                            flush=True,
                        )
                rows.append((world, size, total_objects, times, kept, failures))
    print()
    print(
        f"median wall time per problem (s), {args.problems} problem(s) per cell (relevance and oracle: median of"
        f" {args.repeats} runs each), timeout {args.timeout:g} s, lama-first; failures in brackets"
    )
    header = "| world | distractors | objects | " + " | ".join(methods)
    header += " | pure/relevance | relevance/oracle | kept (relevance) | kept (oracle) |"
    print(header)
    print("|" + "---|" * (header.count("|") - 1))
    for world, size, total, times, kept, failures in rows:
        medians = {m: statistics.median(t) if t else None for m, t in times.items()}
        cells = []
        for m in methods:
            if medians[m] is None:
                cells.append("not run")
            else:
                timed_out = " (timeout)" if medians[m] >= args.timeout else ""
                cells.append(f"{medians[m]:.2f}{timed_out}" + (f" [{failures[m]}]" if failures[m] else ""))
        pure, relevance, oracle = medians.get("pure"), medians.get("relevance"), medians.get("oracle")
        ratio_pure = f"{pure / relevance:.1f}x" if pure and relevance else "–"
        if pure and pure >= args.timeout and relevance:
            ratio_pure = f">{pure / relevance:.0f}x"
        ratio_oracle = f"{relevance / oracle:.2f}" if relevance and oracle else "–"
        kept_rel = f"{statistics.mean(kept['relevance']):.0f}/{total}" if kept.get("relevance") else "–"
        kept_or = f"{statistics.mean(kept['oracle']):.0f}/{total}" if kept.get("oracle") else "–"
        print(
            f"| {world} | {size} | {total} | "
            + " | ".join(cells)
            + f" | {ratio_pure} | {ratio_oracle} | {kept_rel} | {kept_or} |"
        )
    return 0


def parse_args(argv: list[str] | None = None) -> argparse.Namespace:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--worlds", default="coffee,cereal", help="comma-separated kitchen worlds (default: both)")
    parser.add_argument(
        "--sizes", default="10,50,100,1000", help="comma-separated distractor counts (default: 10,50,100,1000)"
    )
    parser.add_argument(
        "--methods", default="pure,relevance,oracle", help="comma-separated methods (default: pure,relevance,oracle)"
    )
    parser.add_argument("--problems", type=int, default=3, help="problems per cell (default: 3)")
    parser.add_argument("--seed", type=int, default=1, help="generator seed (default: 1)")
    parser.add_argument("--timeout", type=float, default=120.0, help="seconds per planning run (default: 120)")
    parser.add_argument("--repeats", type=int, default=3, help="runs per problem for relevance and oracle (default: 3)")
    parser.add_argument(
        "--max-pure", type=int, default=100, help="skip pure planning above this many distractors (default: 100)"
    )
    return parser.parse_args(argv)


def main() -> int:
    args = parse_args()
    started = time.perf_counter()
    code = run(args)
    print(f"\nbenchmark wall time: {time.perf_counter() - started:.0f} s")
    return code


if __name__ == "__main__":
    raise SystemExit(main())
