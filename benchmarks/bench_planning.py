"""Pure vs relevance vs oracle planning time, measured in one run.

For each world and distractor count, generates problems (seeded), runs every
method on each with the same timeout, and prints median times and the
ratios pure/relevance and relevance/oracle.  Every reported plan was
validated on the original problem (a method whose plan is not valid counts as
failed).  Targets: relevance at least 20x faster than pure at 100
distractors, within 1.5x of the oracle at every size, under 3 s at 1,000
distractors, no failures.  Every run is stored in a results store
(``--store``; one suite per world and size; of the repeated runs of a
problem, the one of median time), which ``relevance-plan report`` shows.

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
from dataclasses import dataclass, field
from pathlib import Path

from base import Store, add_store_option, median, median_run, ratio

from relevance_plan.generators import WORLDS, Settings
from relevance_plan.planning.options import PlanOptions
from relevance_plan.planning.results import PlanResult, PlanStatus
from relevance_plan.planning.run import plan_task


@dataclass
class Cell:
    """One world and size: each method's times, objects kept and failures over the cell's problems."""

    world: str
    size: int
    objects: int = 0
    times: dict[str, list[float]] = field(default_factory=dict)
    kept: dict[str, list[int]] = field(default_factory=dict)
    failures: dict[str, int] = field(default_factory=dict)

    def add(self, method: str, runs: list[PlanResult], timeout: float) -> None:
        ok = all(r.status is PlanStatus.SOLVED and r.valid for r in runs)
        self.failures[method] = self.failures.get(method, 0) + (0 if ok else 1)
        self.times.setdefault(method, []).append(statistics.median(r.wall_time for r in runs) if ok else timeout)
        self.kept.setdefault(method, []).append(runs[-1].objects_kept)
        self.objects = runs[-1].objects_total


def run_cell(world: str, size: int, args: argparse.Namespace, scratch: Path, store: Store) -> Cell:
    suite = scratch / f"{world}-{size}"
    WORLDS[world].suite(args.problems, args.seed, suite, Settings("simple", distractors=size))
    cell = Cell(world, size)
    for problem in sorted(p for p in suite.glob("*.pddl") if p.name != "domain.pddl"):
        for method in args.methods:
            if method == "pure" and size > args.max_pure:
                continue
            # Sub-second runs vary by ~30 %: repeat the cheap methods, take the median.
            options = PlanOptions(method=method, timeout=args.timeout)
            runs = [
                plan_task(suite / "domain.pddl", problem, options)
                for _ in range(1 if method == "pure" else args.repeats)
            ]
            cell.add(method, runs, args.timeout)
            store.add(f"{world}-{size}", suite / "domain.pddl", problem, options, median_run(runs))
            result = runs[-1]
            print(
                f"  {world:<6} {size:>5} {problem.stem:<22} {method:<9} {result.status.value:<14}"
                f" {result.wall_time:7.2f} s  kept {result.objects_kept}/{result.objects_total}"
                f"  attempts {len(result.attempts)}",
                file=sys.stderr,
                flush=True,
            )
    return cell


def print_cells(cells: list[Cell], args: argparse.Namespace) -> None:
    methods = args.methods
    print()
    print(
        f"median wall time per problem (s), {args.problems} problem(s) per cell (relevance and oracle: median of"
        f" {args.repeats} runs each), timeout {args.timeout:g} s, lama-first; failures in brackets"
    )
    header = "| world | distractors | objects | " + " | ".join(methods)
    header += " | pure/relevance | relevance/oracle | kept (relevance) | kept (oracle) |"
    print(header)
    print("|" + "---|" * (header.count("|") - 1))
    for cell in cells:
        medians = {m: median(cell.times.get(m, ())) for m in methods}
        cells_text = []
        for m in methods:
            if medians[m] is None:
                cells_text.append("not run")
            else:
                timed_out = " (timeout)" if medians[m] >= args.timeout else ""
                failed = cell.failures.get(m, 0)
                cells_text.append(f"{medians[m]:.2f}{timed_out}" + (f" [{failed}]" if failed else ""))
        pure, relevance, oracle = medians.get("pure"), medians.get("relevance"), medians.get("oracle")
        speedup = ratio(pure, relevance)
        ratio_pure = "–" if speedup is None else f"{speedup:.1f}x"
        if speedup is not None and pure >= args.timeout:
            ratio_pure = f">{speedup:.0f}x"
        to_oracle = ratio(relevance, oracle)
        ratio_oracle = "–" if to_oracle is None else f"{to_oracle:.2f}"
        kept_rel = (
            f"{statistics.mean(cell.kept['relevance']):.0f}/{cell.objects}" if cell.kept.get("relevance") else "–"
        )
        kept_or = f"{statistics.mean(cell.kept['oracle']):.0f}/{cell.objects}" if cell.kept.get("oracle") else "–"
        print(
            f"| {cell.world} | {cell.size} | {cell.objects} | "
            + " | ".join(cells_text)
            + f" | {ratio_pure} | {ratio_oracle} | {kept_rel} | {kept_or} |"
        )


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
    add_store_option(parser)
    args = parser.parse_args(argv)
    args.methods = args.methods.split(",")
    return args


def main(argv: list[str] | None = None) -> int:
    args = parse_args(argv)
    started = time.perf_counter()
    sizes = [int(s) for s in args.sizes.split(",")]
    with tempfile.TemporaryDirectory(prefix="bench-planning-") as scratch, Store(args.store, "bench_planning") as store:
        cells = [
            run_cell(world, size, args, Path(scratch), store) for world in args.worlds.split(",") for size in sizes
        ]
    print_cells(cells, args)
    print(f"\nbenchmark wall time: {time.perf_counter() - started:.0f} s")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
