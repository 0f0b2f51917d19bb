#!/usr/bin/env python
"""Pure vs relevance with temporal and numeric planners at growing object counts.

For each world and size, one problem is generated (`relevance-plan generate`,
seeded), then planned in this process by `plan_task`, first on the full
problem (`--method pure`), then with relevance (`--method relevance`, no
race, so both use one core), with the same planner and time limit.  Every
plan reported as solved was validated on the original problem by the
builtin PDDL 2.1 simulator (or unified-planning's validator).  Prints one
row per run and pure / relevance per planner as a geometric mean over the
sizes both solved; a run that fails counts as the time limit.

Worlds: driverlog-temporal (LPG, Tamer, Aries), coffee-temporal with
distractors (LPG, Aries, Tamer), zenotravel-numeric (LPG, ENHSP when Java is
there, Tamer).  Aries and Tamer run on these worlds because the up child fits
each problem to them (whole-valued functions read as integers for Aries, the
type hierarchy flattened and undefined distances guarded for Tamer); Aries
takes no numeric effect by a function, so not zenotravel-numeric.

    python benchmarks/bench_temporal.py                  # the default grid: takes about 30 minutes
    python benchmarks/bench_temporal.py --quick          # the smallest sizes only: takes about 4 minutes
    python benchmarks/bench_temporal.py --timeout 120 --seed 3
"""

from __future__ import annotations

import argparse
import math
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from relevance_plan.errors import RelevancePlanError
from relevance_plan.planning.loop import PlanOptions, plan_task

# (world, how its size is given, sizes, planners)
from relevance_plan.planning.results import PlanStatus

# (world, how its size is given, sizes, planners)
GRID = (
    ("driverlog-temporal", "--size", (20, 60, 120), ("lpg", "up:tamer", "up:aries")),
    ("coffee-temporal", "--distractors", (10, 50, 100), ("lpg", "up:aries", "up:tamer")),
    ("zenotravel-numeric", "--size", (20, 60, 120), ("lpg", "up:enhsp", "up:tamer")),
)


def generate(world: str, flag: str, size: int, seed: int, folder: Path) -> tuple[Path, Path]:
    """One generated problem of ``world`` and its domain file."""
    out = folder / f"{world}-{size}"
    command = [sys.executable, "-m", "relevance_plan", "generate", world, "--count", "1", "--seed", str(seed)]
    command += ["--out", str(out), flag, str(size)]
    if flag == "--distractors":
        command += ["--difficulty", "simple"]
    subprocess.run(command, check=True, capture_output=True)
    problems = sorted(p for p in out.glob("*.pddl") if p.name != "domain.pddl")
    return out / "domain.pddl", problems[0]


def planner_available(name: str) -> str | None:
    """Why ``name`` cannot run here, or None."""
    if name == "up:enhsp" and shutil.which("java") is None:
        return "no Java runtime"
    try:
        from relevance_plan.planning.planners.registry import make_planner

        make_planner(name, check=True)
    except Exception as error:  # a missing engine: the row says why
        return str(error)
    return None


def run(domain: Path, problem: Path, method: str, planner: str, timeout: float):
    started = time.perf_counter()
    result = plan_task(domain, problem, PlanOptions(method=method, planner=planner, timeout=timeout, race=False))
    return result, time.perf_counter() - started


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0],
        epilog="The default grid takes about 30 minutes on 2 cores; --quick about 4 minutes.",
    )
    parser.add_argument("--timeout", type=float, default=60.0)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--quick", action="store_true", help="the smallest size of each world only")
    args = parser.parse_args(argv)

    ratios: dict[str, list[float]] = {}
    print(f"{'world':20} {'planner':9} {'objects':>7} {'pure s':>8} {'relevance s':>11} {'kept':>9} {'pure/rel':>8}")
    with tempfile.TemporaryDirectory(prefix="bench-temporal-") as scratch:
        for world, flag, sizes, planners in GRID:
            for size in sizes[:1] if args.quick else sizes:
                domain, problem = generate(world, flag, size, args.seed, Path(scratch))
                for planner in planners:
                    missing = planner_available(planner)
                    if missing:
                        print(f"{world:20} {planner:9} skipped: {missing}")
                        continue
                    try:
                        pure, pure_time = run(domain, problem, "pure", planner, args.timeout)
                        rel, rel_time = run(domain, problem, "relevance", planner, args.timeout)
                    except RelevancePlanError as error:
                        print(f"{world:20} {planner:9} refused: {error}")
                        continue
                    solved = (pure.status is PlanStatus.SOLVED, rel.status is PlanStatus.SOLVED)
                    pure_cell = f"{pure_time:8.2f}" if solved[0] else f"{pure.status.value:>8}"
                    rel_cell = f"{rel_time:11.2f}" if solved[1] else f"{rel.status.value:>11}"
                    kept = f"{rel.objects_kept}/{rel.objects_total}"
                    ratio = (pure_time if solved[0] else args.timeout) / (rel_time if solved[1] else args.timeout)
                    if any(solved):
                        ratios.setdefault(planner, []).append(ratio)
                    valid = all(r.valid for r, ok in zip((pure, rel), solved) if ok)
                    note = "" if valid else "  PLAN NOT VALIDATED"
                    print(
                        f"{world:20} {planner:9} {rel.objects_total:7} {pure_cell} {rel_cell} {kept:>9} "
                        f"{ratio:8.2f}{note}",
                        flush=True,
                    )
    print()
    for planner, values in ratios.items():
        mean = math.exp(sum(math.log(v) for v in values) / len(values))
        print(f"{planner}: pure / relevance geometric mean {mean:.2f} over {len(values)} problems")
    return 0


if __name__ == "__main__":
    sys.exit(main())
