"""What the benchmark scripts share: running, timing, statistics, corpus selection and the results store.

Every ``bench_*.py`` script imports this module (run it from the repository
root, with the package installed: ``python benchmarks/bench_x.py``; the
script's own folder is on the path, so ``import base`` needs no set-up).

- running: ``run_method`` plans one problem in this process with
  ``plan_task`` and returns its ``Measured`` figures (storing the run when
  given a ``Store``); ``run_timed`` runs a whole command and times it;
  ``Laps`` times the named steps of one run;
- statistics: ``median``, ``mean``, ``geometric_mean``, ``percentile``
  (``None`` values are left out; an empty list gives ``None``, or NaN for
  the geometric mean, as the tables print it);
- corpus selection: ``suite_entries`` and ``smallest_problems`` read a suite
  folder as ``compare`` does; ``corpus.py`` lists the corpus's folders;
- the results store: ``Store`` writes each run as one row of the project's
  own store (``relevance_plan.batch.store``, the rows ``compare`` writes),
  so ``relevance-plan report STORE`` (``--html``, ``--plots DIR``) shows a
  benchmark's comparison of methods; ``add_store_option`` gives a script its
  ``--store FILE`` option;
- tables: ``ratio`` and ``show_ratio`` print "12.3x", "–" for no value;
  ``table_header`` and ``table_row`` print a markdown table row by row.
"""

from __future__ import annotations

import argparse
import math
import statistics
import subprocess
import sys
import time
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from pathlib import Path

from relevance_plan.batch.jobs import Job
from relevance_plan.batch.rows import result_row
from relevance_plan.batch.store import ResultStore
from relevance_plan.batch.suites import SuiteProblem, find_suite_problems
from relevance_plan.planning.options import PlanOptions
from relevance_plan.planning.results import PlanResult, PlanStatus
from relevance_plan.planning.run import plan_task

REPO = Path(__file__).resolve().parent.parent
DOMAINS = REPO / "relevance_plan" / "data" / "domains"
OUT = REPO / "out"  # where a benchmark's results store goes unless --store names one (git ignores it)
MISSING = "–"


# --------------------------------------------------------------------------- statistics


def _present(values: Iterable[float | None]) -> list[float]:
    return [value for value in values if value is not None]


def median(values: Iterable[float | None]) -> float | None:
    """The median of the values that are there, None when none is."""
    present = _present(values)
    return statistics.median(present) if present else None


def mean(values: Iterable[float | None]) -> float | None:
    present = _present(values)
    return statistics.fmean(present) if present else None


def geometric_mean(values: Iterable[float | None]) -> float:
    """The geometric mean of the (positive) values that are there; NaN when none is."""
    present = _present(values)
    return statistics.geometric_mean(present) if present else math.nan


def percentile(values: Iterable[float], share: float) -> float:
    """The value at ``share`` (0 to 1) of the sorted values, nearest rank; NaN for no values."""
    ordered = sorted(values)
    if not ordered:
        return math.nan
    return ordered[min(len(ordered) - 1, int(round(share * (len(ordered) - 1))))]


def ratio(top: float | None, bottom: float | None) -> float | None:
    """top / bottom, None when either is missing or the bottom is zero."""
    if top is None or not bottom:
        return None
    return top / bottom


def show_ratio(value: float | None, bound: str = "", digits: int = 1) -> str:
    """A ratio as "12.3x" (``bound`` ">" or "<" before it when it is a bound), "–" when there is none."""
    if value is None or math.isnan(value):
        return MISSING
    return f"{bound}{value:.{digits}f}x"


def table_header(columns: str) -> None:
    """The head of a markdown table: its columns ("a | b | c") and the line under them."""
    print(f"| {columns} |")
    print("|" + "---|" * len(columns.split(" | ")))


def table_row(*cells: object) -> None:
    """One row of a markdown table, printed at once (a long run shows each row as it finishes)."""
    print("| " + " | ".join(str(cell) for cell in cells) + " |", flush=True)


# --------------------------------------------------------------------------- timing


class Laps:
    """Named steps of one run, timed one after the other: ``lap(name)`` ends a step, ``end()`` adds the total."""

    def __init__(self) -> None:
        self.started = self.mark = time.perf_counter()
        self.times: dict[str, float] = {}

    def lap(self, name: str) -> None:
        now = time.perf_counter()
        self.times[name] = now - self.mark
        self.mark = now

    def end(self) -> dict[str, float]:
        self.times["total"] = time.perf_counter() - self.started
        return self.times


@dataclass(frozen=True)
class Timed:
    """A whole command's wall time, exit code (-1: stopped at its time limit) and standard output."""

    seconds: float
    code: int
    stdout: str


def run_timed(
    command: Sequence[str], *, cwd: Path | None = None, env: dict[str, str] | None = None, timeout: float | None = None
) -> Timed:
    """Run ``command`` (an argument list, never a shell line) and time it; its output is captured."""
    started = time.perf_counter()
    try:
        done = subprocess.run(list(command), cwd=cwd, env=env, capture_output=True, text=True, timeout=timeout)
        code, stdout = done.returncode, done.stdout
    except subprocess.TimeoutExpired:
        code, stdout = -1, ""
    return Timed(time.perf_counter() - started, code, stdout)


def progress(message: str) -> None:
    """A note on standard error while a long run goes on (the tables stay on standard output)."""
    print(f"  ... {message}", file=sys.stderr, flush=True)


# --------------------------------------------------------------------------- one method on one problem


@dataclass(frozen=True)
class Measured:
    """What the tables say about one ``plan_task`` run."""

    status: str
    solved: bool
    timed_out: bool
    valid: bool
    time: float  # the attempt loop's wall time: read, score, prune, plan, validate
    kept: int  # objects of the last attempt
    first_kept: int  # objects of the first pruned attempt (all of them when nothing was pruned)
    total: int
    attempts: int
    relevance_time: float


def measure(result: PlanResult) -> Measured:
    return Measured(
        status=result.status.value,
        solved=result.status is PlanStatus.SOLVED,
        timed_out=result.status is PlanStatus.OUT_OF_TIME,
        valid=result.valid,
        time=result.wall_time,
        kept=result.objects_kept,
        first_kept=result.first_kept,
        total=result.objects_total,
        attempts=len(result.attempts),
        relevance_time=result.relevance_time,
    )


def median_run(runs: Sequence[PlanResult]) -> PlanResult:
    """Of repeated runs, the one of median wall time (the lower of the middle two for an even count)."""
    return sorted(runs, key=lambda run: run.wall_time)[(len(runs) - 1) // 2]


def speedup(pure: Measured, relevance: Measured, validated: bool = False) -> str:
    """pure / relevance as "12.3x"; ">12.3x" when pure found no plan (a lower bound), "–" when relevance found
    none (``validated``: only a valid plan counts as found)."""

    def found(run: Measured) -> bool:
        return run.solved and (run.valid or not validated)

    if not found(relevance):
        return MISSING
    return f"{'' if found(pure) else '>'}{pure.time / relevance.time:.1f}x"


def show_time(run: Measured | None, timeout: float | None = None) -> str:
    """A run's seconds; ">T" when it hit ``timeout`` (given), else its status and seconds when unsolved."""
    if run is None:
        return MISSING
    if timeout is not None and run.timed_out:
        return f">{timeout:g}"
    return f"{run.time:.2f}" if run.solved else f"{run.status} ({run.time:.0f})"


def run_method(
    domain: Path, problem: Path, options: PlanOptions, store: Store | None = None, suite: str = ""
) -> tuple[PlanResult, Measured]:
    """``plan_task`` on one problem in this process, the run stored in ``store`` (under ``suite``) when given."""
    result = plan_task(domain, problem, options)
    if store is not None:
        store.add(suite, domain, problem, options, result)
    return result, measure(result)


# --------------------------------------------------------------------------- the results store


class Store:
    """The project's results store, one row per run as ``compare`` writes it; ``relevance-plan report`` reads it.

    ``path`` None: a new file ``out/SCRIPT-DATE-TIME.sqlite`` of the
    repository.  A store given by name that exists already keeps its rows
    (a run whose job it holds already is not stored again, as ``compare``
    skips it); a file that is not a store is refused and left as it is.
    """

    def __init__(self, path: Path | None, script: str):
        if path is None:
            path = new_store_path(script)
        self.path = path
        self.stored = 0
        self._store = ResultStore(path)

    def add(
        self, suite: str, domain: Path, problem: Path, options: PlanOptions, result: PlanResult, method: str = ""
    ) -> None:
        """Store one run; ``method`` labels it when the options' method does not name it (a scorer, an oracle)."""
        job = Job(str(domain), str(problem), suite, options.method, options.seed, options)
        row = result_row(job.columns(), result)
        if method:
            row["method"] = method
        self.add_row(row)

    def add_row(self, row: dict) -> None:
        """Store a row made by the script (``batch.rows.row_from_json`` of a command's ``--json`` report)."""
        self.stored += self._store.add(row)

    def close(self) -> None:
        self._store.close()
        print(
            f"{self.stored} run(s) stored in {self.path}: `relevance-plan report {self.path}` shows them"
            " (--html, --plots DIR)",
            file=sys.stderr,
        )

    def __enter__(self) -> Store:
        return self

    def __exit__(self, *error: object) -> None:
        self.close()


def new_store_path(script: str) -> Path:
    """``out/SCRIPT-DATE-TIME.sqlite`` (``-2``, ``-3``, ... when that file is there already)."""
    OUT.mkdir(exist_ok=True)
    stamp = time.strftime("%Y%m%d-%H%M%S")
    path, number = OUT / f"{script}-{stamp}.sqlite", 1
    while path.exists():
        number += 1
        path = OUT / f"{script}-{stamp}-{number}.sqlite"
    return path


def add_worlds_option(
    parser: argparse.ArgumentParser, worlds: Sequence[str], default: Sequence[str], help: str
) -> None:
    parser.add_argument("--worlds", nargs="+", default=list(default), choices=list(worlds), metavar="WORLD", help=help)


def add_store_option(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--store",
        type=Path,
        default=None,
        metavar="FILE",
        help="the results store to write every run to, for `relevance-plan report FILE`"
        " (default: a new file in out/; an existing store keeps its rows)",
    )


# --------------------------------------------------------------------------- corpus selection


def suite_entries(folder: Path) -> list[SuiteProblem]:
    """The problems of a suite folder (read as ``compare`` reads one) that have a domain and can run."""
    return [entry for entry in find_suite_problems(folder) if entry.domain is not None and entry.error is None]


def smallest_problems(folder: Path, count: int) -> list[SuiteProblem]:
    """The folder's ``count`` smallest problems (by file size, then name) that have a domain."""
    return sorted(suite_entries(folder), key=lambda entry: (entry.problem.stat().st_size, entry.problem.name))[:count]
