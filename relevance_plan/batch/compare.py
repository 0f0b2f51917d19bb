"""``compare``: run → store.  Every job of some suites, each stored once; rerunning resumes.

``compare`` checks its options and the store first, builds every job,
skips those whose key is already stored, and hands the rest to an executor
(``executors.run_local`` or ``executors.run_dask``).  Only the main thread
writes to SQLite, one transaction per finished job.  Ctrl-C (or SIGTERM)
cancels the pending jobs, kills every running planner, keeps every row
already stored, and re-raises ``KeyboardInterrupt``.
"""

from __future__ import annotations

import contextlib
import os
import time
from collections import Counter
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import Any

from relevance_plan.batch.executors import (
    DEFAULT_SCHEDULER_TIMEOUT,
    SCHEDULER_ADDRESS,
    Workers,
    connect_scheduler,
    run_dask,
    run_local,
)
from relevance_plan.batch.jobs import Job, build_jobs
from relevance_plan.batch.store import ResultKey, ResultStore, check_store_writable
from relevance_plan.errors import UsageError, counted
from relevance_plan.limits import DEFAULT_TIMEOUT, MAX_TIMEOUT
from relevance_plan.planning.options import PlanOptions
from relevance_plan.planning.planners.registry import make_planner
from relevance_plan.planning.results import PlanStatus
from relevance_plan.progress import ProgressCallback, ProgressEvent, ignore
from relevance_plan.signals import stop_event_on_signals


@dataclass(frozen=True)
class CompareSummary:
    store_path: str
    total: int  # distinct jobs asked for
    already_stored: int  # skipped: their rows were in the store
    ran: int  # finished and stored by this run
    failed: int  # of those, status other than 'solved'
    statuses: dict
    elapsed: float
    scheduler: str | None = None
    keys: tuple = ()  # the ResultKey of every job asked for (to select this run's rows)

    def describe(self) -> str:
        counts = ", ".join(f"{count} {status}" for status, count in sorted(self.statuses.items()))
        return (
            f"{counted(self.total, 'job')}: {self.already_stored} already stored, {self.ran} run"
            + (f" ({counts})" if counts else "")
            + f" in {self.elapsed:.1f} s; results in {self.store_path}"
        )


class _Recorder:
    """Writes finished rows (main thread only), counts them and reports each one."""

    def __init__(self, store: ResultStore, total: int, progress: ProgressCallback):
        self.store = store
        self.total = total
        self.done = 0
        self.progress = progress
        self.statuses: Counter[str] = Counter()

    def __call__(self, row: dict[str, Any]) -> None:
        inserted = self.store.add(row)
        if inserted:
            self.statuses[row["status"]] += 1
        self.done += 1
        self.progress(ProgressEvent(done=self.done, total=self.total, failed=row["status"] != PlanStatus.SOLVED.value))


def check_compare_options(
    *,
    timeout: float = DEFAULT_TIMEOUT,
    jobs: int = 1,
    scheduler: str | None = None,
    scheduler_timeout: float = DEFAULT_SCHEDULER_TIMEOUT,
) -> None:
    """``UsageError`` for a bad option, before anything is written (``demo`` checks first too)."""
    if isinstance(jobs, bool) or not isinstance(jobs, int) or jobs < 1:
        raise UsageError(f"--jobs must be a positive integer, got {jobs!r}")
    if scheduler is not None and not SCHEDULER_ADDRESS.match(scheduler):
        raise UsageError(f"--scheduler must look like tcp://HOST:PORT, got '{scheduler}'")
    if not 0 < scheduler_timeout <= MAX_TIMEOUT:
        raise UsageError(f"--scheduler-timeout must be positive and at most {MAX_TIMEOUT:g} s, got {scheduler_timeout}")
    PlanOptions(timeout=timeout)  # checks --timeout


def _unique(jobs: Sequence[Job]) -> dict[ResultKey, Job]:
    unique: dict[ResultKey, Job] = {}
    for job in jobs:
        unique.setdefault(job.key, job)
    return unique


def compare(
    suites: Sequence[str | os.PathLike],
    methods: str | Iterable[str],
    options: PlanOptions = PlanOptions(),
    *,
    planners: Sequence[str] = (),
    seeds: str | Iterable[int] = (0,),
    store_path: str | os.PathLike = "results.sqlite",
    workers: Workers = Workers(),
    progress: ProgressCallback | None = None,
) -> CompareSummary:
    """Run every method (with every planner) on every problem of ``suites``; store one row per job.

    ``options`` are the ``plan`` options every job shares (its method, seed
    and planner are set per job; ``planners`` empty means ``options.planner``).
    Jobs already in the store are skipped, so rerunning an interrupted
    command resumes it.  ``workers`` say where the jobs run (local threads or a Dask scheduler's workers).
    Returns counts for this run; the numbers themselves come from
    ``report.build_report`` over the stored rows.

    Every problem with the store is found before the first job runs.
    Raises ``UsageError`` (bad argument, unknown method), ``InputFileError``
    (missing suite, suite without problems, store or its folder missing or
    read-only), ``StoreError`` (not a store, another schema version, a
    missing column, a full disk), ``SchedulerError`` (unreachable scheduler,
    Dask missing), ``PlannerError`` (no planner at all) and
    ``KeyboardInterrupt`` after Ctrl-C/SIGTERM.
    """
    started = time.perf_counter()
    jobs, scheduler = workers.jobs, workers.scheduler
    check_compare_options(jobs=jobs, scheduler=scheduler, scheduler_timeout=workers.scheduler_timeout)
    if options.timeout is None:
        raise UsageError("compare needs a time limit per job: the timeout of every method's row")
    check_store_writable(store_path)
    for planner in planners or (options.planner,):
        make_planner(planner, options.planner_config, check=True)
    unique = _unique(build_jobs(suites, methods, seeds, options, planners))
    check_named_cues(list(unique.values()), options)

    # The scheduler is reached before the store is opened: an unreachable one leaves no empty store.
    client = connect_scheduler(scheduler, workers.scheduler_timeout) if scheduler is not None else None
    try:
        with ResultStore(store_path) as store:
            stored = store.keys()
            pending = [job for key, job in unique.items() if key not in stored]
            statuses = _run(pending, store, client, scheduler, jobs, progress or ignore)
    finally:
        if client is not None:
            with contextlib.suppress(Exception):
                client.close(timeout=10)
    ran = sum(statuses.values())
    return CompareSummary(
        store_path=str(store_path),
        total=len(unique),
        already_stored=len(unique) - len(pending),
        ran=ran,
        failed=ran - statuses.get(PlanStatus.SOLVED.value, 0),
        statuses=statuses,
        elapsed=time.perf_counter() - started,
        scheduler=scheduler,
        keys=tuple(unique),
    )


def check_named_cues(jobs: Sequence[Job], options: PlanOptions) -> None:
    """Raise what scoring raises (``ModelError``: an objective, activity or human the model does not know)
    when the cues the options give fail on the first problem of every domain of ``jobs``: such a
    comparison would fail every job, so it fails at once, as ``plan`` does."""
    if options.objective is None and options.activity is None and options.human is None:
        return
    from relevance_plan.errors import ModelError
    from relevance_plan.io import load_task
    from relevance_plan.relevance.analysis.task import PlanningTask
    from relevance_plan.relevance.setup import score_problem

    first_by_domain: dict[str, Job] = {}
    for job in jobs:
        if job.input_error is None and job.domain_path is not None:
            first_by_domain.setdefault(job.domain_path, job)
    failures: list[ModelError] = []
    for domain_path, job in first_by_domain.items():
        domain, problem = load_task(domain_path, job.problem_path)
        try:
            task = PlanningTask(domain, problem)
            score_problem(task, options.scoring, domain_path=domain_path, problem_path=job.problem_path)
        except ModelError as error:
            failures.append(error)
        else:
            return
    if failures:
        raise failures[0]


def _run(
    pending: Sequence[Job], store: ResultStore, client, scheduler, workers: int, progress: ProgressCallback
) -> dict[str, int]:
    """Run ``pending`` into ``store``; the count of each stored status."""
    if not pending:
        return {}
    with stop_event_on_signals() as stop:
        recorder = _Recorder(store, len(pending), progress)
        if client is None:
            run_local(pending, workers, recorder, stop)
        else:
            run_dask(pending, client, scheduler, recorder, stop)
    return dict(recorder.statuses)
