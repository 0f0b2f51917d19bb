"""The worlds built for many objects: pure vs relevance vs oracle, and pruning time, in one run.

Planning: for each world and size, ``--count`` seeded problems (``relevance-plan
generate <world> --size N``) are planned in this process by ``plan_task`` with
Fast Downward ``lama-first``, three times: on the full problem (pure), with
the relevance method (goal scorer: no knowledge model applies to these
domains) and with the oracle (the generator's ``necessary`` set, read from
the problem's sidecar).  The race is off, so every run uses one core.  Every
plan is validated on the original problem.  A run that hits ``--timeout`` is
shown as ``>T``; a median over such runs is a lower bound, and so is a ratio
over it.

Pruning time: for each world at 500 and 5,000 objects, what ``plan_task``
does before the first planner call, in this process: read the domain and
problem, score, select (thresholds, goal filter, closure, reachability
repair), write the pruned problem.  Median of 3 per stage.  ``--prune-worlds``
times other worlds instead, our padded classic worlds included, and
``--prune-sizes`` other sizes (targets are printed for 500 and 5,000).

Worlds and planning sizes (objects per problem; pure lama-first takes from
about a second to tens of seconds at these):
scenegraph 200, 500, 1000; logistics-manygoals 120, 200;
miconic-manygoals 1000, 2000.  The ``-typed`` forms of the many-goal worlds
can be named with ``--worlds``; they take the untyped form's sizes.

Targets, printed next to the results:
  * geometric mean of pure/relevance over the scene-graph cells >= 10x;
  * relevance median <= 1.5x the oracle median, in every cell;
  * every plan valid on the original problem, no relevance failure;
  * pruning <= 0.3 s at 500 objects and <= 1 s at 5,000, in-process.

Tables go to standard output, one row per problem or pruning cell as it
finishes; a note per planner run and per timed pruning run goes to standard
error.  ``kept`` is what the first attempt planned on (``a->b``: widening
went on to b objects); kept = objects means relevance planned the full
problem.  Every planning run is stored in a results store (``--store``;
one suite per world and size), which ``relevance-plan report`` shows.

With the defaults (one problem per cell) the run takes about 2 minutes on 2
quiet cores: about 100 s of planning and 20 s of pruning time, most of it
many-goal miconic at 5,000 objects (about 3.5 s a run: reading 125,000
``above`` facts and exploring every move between the kept floors).
``--quick`` (smallest size of each world, pruning at 500 only) takes under a
minute.

    python benchmarks/bench_scale.py                             # everything, default sizes
    python benchmarks/bench_scale.py --quick                     # smoke check
    python benchmarks/bench_scale.py --count 3 --seed 2 --json rows.json
    python benchmarks/bench_scale.py --worlds scenegraph --sizes 300 600 --timeout 60
    python benchmarks/bench_scale.py --prune-only                # no planner at all
    python benchmarks/bench_scale.py --prune-only --prune-worlds grid ferry miconic
    python benchmarks/bench_scale.py --prune-only --prune-worlds grid --prune-sizes 1500 3500
    python benchmarks/bench_scale.py --no-prune-timing
"""

from __future__ import annotations

import argparse
import json
import statistics
import tempfile
import time
from dataclasses import asdict
from pathlib import Path

from base import (
    Laps,
    Measured,
    Store,
    add_store_option,
    add_worlds_option,
    geometric_mean,
    median,
    progress,
    run_method,
    show_ratio,
    show_time,
    table_header,
    table_row,
)

from relevance_plan.generators import CLASSIC, WORLDS, Settings, worlds_of
from relevance_plan.io import load_domain, load_problem, write_text_atomic
from relevance_plan.pddl.sexpr import collection_paused
from relevance_plan.planning.options import PlanOptions
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.setup import ScoringOptions, score_problem

SIZES = {
    "scenegraph": (200, 500, 1000),
    "logistics-manygoals": (120, 200),
    "logistics-manygoals-typed": (120, 200),
    "miconic-manygoals": (1000, 2000),
    "miconic-manygoals-typed": (1000, 2000),
}
DEFAULT_WORLDS = ("scenegraph", "logistics-manygoals", "miconic-manygoals")
# the pruning table may take our padded classic worlds too
PRUNE_WORLDS = (*SIZES, *(world.name for world in worlds_of(CLASSIC)))
PRUNE_TARGETS = {500: 0.3, 5000: 1.0}  # objects -> seconds, in-process
SPEEDUP_TARGET = 10.0  # geometric mean of pure/relevance over the scene-graph cells
ORACLE_TARGET = 1.5  # relevance / oracle
METHODS = ("pure", "relevance", "oracle")
STAGES = ("read", "score", "select", "write", "total")


def write_problem(world: str, seed: int, index: int, size: int, folder: Path) -> tuple[Path, Path, dict]:
    """One generated problem with its sidecar next to it (the oracle reads it); returns (domain, problem, sidecar)."""
    problem = WORLDS[world].problem(seed, index, Settings(size=size))
    path = folder / f"{problem.name}-{size}.pddl"
    path.write_text(problem.pddl_text)
    path.with_suffix(".json").write_text(json.dumps(problem.sidecar))
    return WORLDS[world].domain_path, path, problem.sidecar


def prune_stages(domain_path: Path, problem_path: Path, out: Path) -> dict:
    """The steps of ``plan_task`` before its first planner call, timed one by one (with the garbage
    collector paused, as ``plan_task`` runs them)."""
    with collection_paused():
        return _prune_stages(domain_path, problem_path, out)


def _prune_stages(domain_path: Path, problem_path: Path, out: Path) -> dict:
    laps = Laps()
    domain = load_domain(domain_path)
    task = PlanningTask(domain, load_problem(problem_path, domain))
    laps.lap("read")
    scoring = score_problem(task, ScoringOptions(), method="relevance", domain_path=domain_path)
    laps.lap("score")
    selection = scoring.first_selection(narrow=True)
    laps.lap("select")
    write_text_atomic(out, selection.text)
    laps.lap("write")
    return {**laps.end(), "kept": len(selection.kept), "objects": len(task.problem.objects)}


def parse_args(argv: list[str] | None = None) -> argparse.Namespace:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    add_worlds_option(
        parser,
        SIZES,
        DEFAULT_WORLDS,
        f"worlds to run (default: {', '.join(DEFAULT_WORLDS)}; also: the -typed many-goal forms)",
    )
    parser.add_argument(
        "--sizes", nargs="+", type=int, default=None, metavar="N", help="planning sizes for every world chosen"
    )
    parser.add_argument("--count", type=int, default=1, help="problems per world and size (default: 1)")
    parser.add_argument("--seed", type=int, default=1, help="generator seed (default: 1)")
    parser.add_argument("--timeout", type=float, default=120.0, help="seconds per planner run (default: 120)")
    parser.add_argument("--quick", action="store_true", help="smallest size of each world, pruning at 500 only")
    what = parser.add_mutually_exclusive_group()
    what.add_argument("--no-prune-timing", action="store_true", help="planning only")
    what.add_argument("--prune-only", action="store_true", help="pruning time only (no planner is started)")
    parser.add_argument(
        "--prune-worlds",
        nargs="+",
        default=None,
        choices=list(PRUNE_WORLDS),
        metavar="WORLD",
        help="worlds of the pruning-time table (default: those of --worlds; also every classic world)",
    )
    parser.add_argument(
        "--prune-sizes",
        nargs="+",
        type=int,
        default=None,
        metavar="N",
        help="sizes of the pruning-time table (default: 500 and 5000; targets are printed for those)",
    )
    parser.add_argument("--json", type=Path, default=None, help="also write the raw rows here")
    add_store_option(parser)
    args = parser.parse_args(argv)
    if args.count < 1:
        parser.error("--count must be at least 1")
    if args.timeout <= 0:
        parser.error("--timeout must be positive")
    if args.sizes is not None and min(args.sizes) < 10:
        parser.error("--sizes must be at least 10")
    if args.prune_sizes is not None and min(args.prune_sizes) < 10:
        parser.error("--prune-sizes must be at least 10")
    return args


def planning_cells(args: argparse.Namespace) -> list[tuple[str, int]]:
    cells = []
    for world in args.worlds:
        sizes = tuple(args.sizes) if args.sizes else SIZES[world]
        cells += [(world, size) for size in (sizes[:1] if args.quick else sizes)]
    return cells


def plan_all(args: argparse.Namespace, scratch: Path, store: Store) -> list[dict]:
    """Plan every cell, one row per problem as it goes."""
    rows = []
    cells = planning_cells(args)
    runs = len(cells) * args.count
    print(
        f"## Planning: lama-first, timeout {args.timeout:g} s per run, seed {args.seed},"
        f" {args.count} problem(s) per cell, no race; relevance = goal scorer"
    )
    table_header(
        "# | problem | objects | pure (s) | relevance (s) | "
        "of which pruning (s) | kept | attempts | oracle (s) | oracle kept | valid"
    )
    for world, size in cells:
        for index in range(1, args.count + 1):
            domain_path, problem_path, sidecar = write_problem(world, args.seed, index, size, scratch)
            row = {"world": world, "size": size, "problem": problem_path.stem, "objects": sidecar["objects_total"]}
            for method in METHODS:
                options = PlanOptions(method=method, timeout=args.timeout, race=False)
                row[method] = run = run_method(domain_path, problem_path, options, store, f"{world}-{size}")[1]
                progress(f"{row['problem']}: {method} {run.status} in {run.time:.1f} s")
            rows.append(row)
            rel, oracle = row["relevance"], row["oracle"]
            valid = all(row[m].valid for m in METHODS if row[m].solved)
            table_row(
                f"{len(rows)}/{runs}",
                row["problem"],
                row["objects"],
                show_time(row["pure"], args.timeout),
                show_time(rel, args.timeout),
                f"{rel.relevance_time:.2f}",
                _kept(rel),
                rel.attempts,
                show_time(oracle, args.timeout),
                oracle.first_kept,
                "yes" if valid else "NO",
            )
    return rows


def summarise_planning(rows: list[dict]) -> None:
    print()
    table_header(
        "world | size | objects | problems | pure median (s) | relevance median (s) | "
        "pure/relevance | oracle median (s) | relevance/oracle | kept median | oracle kept | attempts median | failures"
    )
    scene_ratios, all_ratios, over_oracle = [], [], []
    for world, size in dict.fromkeys((r["world"], r["size"]) for r in rows):
        mine = [r for r in rows if (r["world"], r["size"]) == (world, size)]
        pure_t, pure_low = _median_time(mine, "pure")
        rel_t, rel_low = _median_time(mine, "relevance")
        oracle_t, oracle_low = _median_time(mine, "oracle")
        # a censored numerator gives a lower bound, a censored denominator an upper one; both: unknown
        speedup = _ratio(pure_t, pure_low, rel_t, rel_low)
        to_oracle = _ratio(rel_t, rel_low, oracle_t, oracle_low)
        if speedup[0] is not None:
            all_ratios.append(speedup[0])
            if world == "scenegraph":
                scene_ratios.append(speedup[0])
        if to_oracle[0] is None or to_oracle[0] > ORACLE_TARGET:
            over_oracle.append(f"{world} {size} ({show_ratio(*to_oracle)})")
        failures = sum(not r["relevance"].solved or not r["relevance"].valid for r in mine)
        table_row(
            world,
            size,
            f"{median(r['objects'] for r in mine):.0f}",
            len(mine),
            f"{'>' if pure_low else ''}{pure_t:.2f}",
            f"{'>' if rel_low else ''}{rel_t:.2f}",
            show_ratio(*speedup),
            f"{'>' if oracle_low else ''}{oracle_t:.2f}",
            show_ratio(*to_oracle),
            f"{median(r['relevance'].first_kept for r in mine):.0f}",
            f"{median(r['oracle'].first_kept for r in mine):.0f}",
            f"{median(r['relevance'].attempts for r in mine):.0f}",
            failures,
        )
    invalid = [f"{r['problem']} ({m})" for r in rows for m in METHODS if r[m].solved and not r[m].valid]
    failed = [f"{r['problem']} ({r['relevance'].status})" for r in rows if not r["relevance"].solved]
    slower = [
        f"{r['problem']} ({r['relevance'].time:.1f} s vs {r['pure'].time:.1f} s)"
        for r in rows
        if r["pure"].solved and r["relevance"].time > r["pure"].time
    ]
    print()
    bound = " (a lower bound: some pure run timed out)" if any(r["pure"].timed_out for r in rows) else ""
    print(
        f"geometric mean pure/relevance over {len(scene_ratios)} scene-graph cell(s):"
        f" {show_ratio(geometric_mean(scene_ratios))}{bound} (target >= {SPEEDUP_TARGET:g}x)"
    )
    print(f"geometric mean pure/relevance over all {len(all_ratios)} cell(s): {show_ratio(geometric_mean(all_ratios))}")
    print(f"relevance <= {ORACLE_TARGET:g}x the oracle in every cell: {_missed(over_oracle)}")
    print(f"every plan valid on the original: {_missed(invalid)}")
    print(f"no relevance failure: {_missed(failed)}")
    print(f"relevance slower than pure: {', '.join(slower) or 'none'}")


def time_pruning(args: argparse.Namespace, scratch: Path) -> list[dict]:
    sizes = args.prune_sizes or (list(PRUNE_TARGETS)[:1] if args.quick else list(PRUNE_TARGETS))
    print("## Pruning time in-process: read + score + select (closure, repair) + write, median of 3, no planner")
    table_header("world | size | objects | read | score | select | write | total (s) | target (s) | kept | within")
    rows = []
    out = scratch / "pruned.pddl"
    for world in args.prune_worlds or args.worlds:
        for size in sizes:
            domain_path, problem_path, _ = write_problem(world, args.seed, 1, size, scratch)
            runs = []
            for attempt in range(1, 4):
                runs.append(prune_stages(domain_path, problem_path, out))
                progress(f"pruning {world} at {size}: run {attempt}/3 {runs[-1]['total']:.2f} s")
            times = {stage: statistics.median(r[stage] for r in runs) for stage in STAGES}
            target = PRUNE_TARGETS.get(size)
            row = {"world": world, "size": size, "objects": runs[0]["objects"], "kept": runs[0]["kept"], **times}
            rows.append(row)
            within = "–" if target is None else "yes" if times["total"] <= target else "NO"
            table_row(
                world,
                size,
                row["objects"],
                *(f"{times[stage]:.3f}" for stage in STAGES),
                "–" if target is None else f"{target:g}",
                row["kept"],
                within,
            )
    over = [
        f"{r['world']} {r['size']} ({r['total']:.2f} s)"
        for r in rows
        if r["size"] in PRUNE_TARGETS and r["total"] > PRUNE_TARGETS[r["size"]]
    ]
    print()
    print(f"pruning <= 0.3 s at 500 objects and <= 1 s at 5,000, in-process: {_missed(over)}")
    return rows


def main(argv: list[str] | None = None) -> int:
    args = parse_args(argv)
    started = time.perf_counter()
    raw: dict = {}
    with tempfile.TemporaryDirectory(prefix="bench-scale-") as folder:
        scratch = Path(folder)
        if not args.prune_only:
            with Store(args.store, "bench_scale") as store:
                rows = plan_all(args, scratch, store)
            summarise_planning(rows)
            raw["planning"] = [{key: asdict(v) if key in METHODS else v for key, v in r.items()} for r in rows]
        if not args.no_prune_timing:
            if not args.prune_only:
                print()
            raw["pruning"] = time_pruning(args, scratch)
    print(f"\nwhole run: {time.perf_counter() - started:.0f} s")
    if args.json:
        args.json.write_text(json.dumps(raw, indent=2))
    return 0


def _median_time(rows: list[dict], method: str) -> tuple[float, bool]:
    """The median wall time of ``method``, and whether it is a lower bound (some run hit the time limit)."""
    return median(r[method].time for r in rows), any(r[method].timed_out for r in rows)


def _ratio(top: float, top_low: bool, bottom: float, bottom_low: bool) -> tuple[float | None, str]:
    if top_low and bottom_low:
        return None, ""
    return (top / bottom if bottom else None), (">" if top_low else "<" if bottom_low else "")


def _missed(misses: list[str]) -> str:
    return f"missed by {', '.join(misses)}" if misses else "met"


def _kept(run: Measured) -> str:
    if run.first_kept == run.kept:
        return f"{run.kept}/{run.total}"
    return f"{run.first_kept}->{run.kept}/{run.total}"


if __name__ == "__main__":
    raise SystemExit(main())
