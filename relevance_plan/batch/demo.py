"""A small end-to-end comparison: generate two suites, compare the four methods, report.

With the defaults (3 problems per world, 30 distractors each) pure planning
takes seconds per problem where the pruned methods take a fraction of one
(the README says how long the whole demo takes).  A work
directory given by the caller keeps the suites, the results store and
nothing else (running the demo again there reuses the stored results);
without one, the demo runs in a temporary folder and removes it.
"""

from __future__ import annotations

import dataclasses
import os
import tempfile
from dataclasses import dataclass
from pathlib import Path

from relevance_plan.batch.compare import CompareSummary, check_compare_options, compare
from relevance_plan.batch.executors import Workers
from relevance_plan.batch.report import build_report, format_report
from relevance_plan.batch.store import KEY_COLUMNS, ResultStore
from relevance_plan.errors import InputFileError, UsageError
from relevance_plan.planning.options import METHODS, PlanOptions
from relevance_plan.progress import ProgressCallback

DEMO_SUITES = (("coffee", "simple"), ("cereal", "simple"))
DEMO_SEED = 0
DEMO_DISTRACTORS = 30
TINY_COUNT = 1
TINY_DISTRACTORS = 5
STORE_NAME = "results.sqlite"


@dataclass(frozen=True)
class DemoRun:
    workdir: Path | None  # None: the demo ran in a temporary folder, removed since
    store_path: Path | None
    suites: tuple
    summary: CompareSummary
    table: str


def _check_demo_options(count, timeout, jobs, distractors, tiny) -> tuple[int, int]:
    """(count, distractors) after ``--tiny``; ``UsageError`` for a bad option, before anything is written."""
    if distractors is not None and (
        isinstance(distractors, bool) or not isinstance(distractors, int) or distractors < 0
    ):
        raise UsageError(f"--distractors must be a non-negative integer, got {distractors!r}")
    PlanOptions(timeout=timeout)
    if tiny:
        # An explicit --distractors still wins; --tiny only changes the defaults.
        count, distractors = TINY_COUNT, TINY_DISTRACTORS if distractors is None else distractors
    elif distractors is None:
        distractors = DEMO_DISTRACTORS
    if isinstance(count, bool) or not isinstance(count, int) or count < 1:
        raise UsageError(f"--count must be a positive integer, got {count!r}")
    check_compare_options(timeout=timeout, jobs=jobs)
    return count, distractors


def run_demo(
    workdir: str | os.PathLike | None,
    count: int = 3,
    timeout: float = 60.0,
    jobs: int = 2,
    *,
    distractors: int | None = None,
    tiny: bool = False,
    progress: ProgressCallback | None = None,
) -> DemoRun:
    """Generate coffee-simple and cereal-simple suites (``count`` problems each,
    seed 0, ``distractors`` distractors), compare relevance, pure, random and
    oracle into ``workdir/results.sqlite``, and return what was produced.

    ``tiny=True`` (for tests) means 1 problem per world with 5 distractors
    (an explicit ``distractors`` wins).  ``workdir=None`` runs in a temporary
    folder that is removed before returning, also after an error or Ctrl-C.
    Every option is checked before anything is written.
    """
    count, distractors = _check_demo_options(count, timeout, jobs, distractors, tiny)
    if workdir is not None:
        return _run_in(Path(workdir), count, timeout, jobs, distractors, progress)
    with tempfile.TemporaryDirectory(prefix="relevance-plan-demo-") as temporary:
        run = _run_in(Path(temporary), count, timeout, jobs, distractors, progress)
    return dataclasses.replace(run, workdir=None, store_path=None, suites=())


def _run_in(
    workdir: Path, count: int, timeout: float, jobs: int, distractors: int, progress: ProgressCallback | None
) -> DemoRun:
    from relevance_plan.generators.worlds import WORLDS, Settings

    try:
        workdir.mkdir(parents=True, exist_ok=True)
    except OSError as error:
        raise InputFileError(f"cannot create the demo directory: {error.strerror}", path=str(workdir)) from None
    suites = []
    for world, difficulty in DEMO_SUITES:
        suite = workdir / "suites" / f"{world}-{difficulty}"
        WORLDS[world].suite(count, DEMO_SEED, suite, Settings(difficulty, distractors))
        suites.append(suite)
    store_path = workdir / STORE_NAME
    options = PlanOptions(timeout=timeout)
    summary = compare(suites, METHODS, options, store_path=store_path, workers=Workers(jobs=jobs), progress=progress)
    wanted = set(summary.keys)
    # Read through a writing connection: closing it folds the store's WAL back in, leaving one file.
    with ResultStore(store_path, create=False) as store:
        rows = [row for row in store.rows() if tuple(row[name] for name in KEY_COLUMNS) in wanted]
    table = format_report(build_report(rows), "markdown")
    return DemoRun(workdir, store_path, tuple(suites), summary, table)
