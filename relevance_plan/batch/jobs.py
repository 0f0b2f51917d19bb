"""Batch comparison of methods over benchmark suites: run → store (→ report).

A *job* is one (problem, method, seed) under one set of options.  ``compare``
builds every job, skips those whose key is already in the results store, and
runs the rest:

- locally, on ``jobs`` threads that each drive one planner subprocess
  (measured faster and more robust than a process pool: one killed planner
  affects only its own job).  Only the main thread writes to SQLite, one
  transaction per finished job, as the futures complete;
- or on a Dask cluster (``scheduler='tcp://HOST:PORT'``): the same jobs go
  out with ``client.submit(run_job, job, pure=False, retries=2)`` and the
  results land in the local store as they complete.  Workers must see the
  suite files under the same paths and have the same packages installed.

Ctrl-C (or SIGTERM) cancels the pending jobs, kills every running planner
(``runner.terminate_all_runs``), keeps every row already stored, and
re-raises ``KeyboardInterrupt``; rerunning the same command resumes.
"""

from __future__ import annotations

import concurrent.futures
import contextlib
import dataclasses
import hashlib
import json
import os
import re
import threading
import time
from collections import Counter
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from datetime import datetime, timezone
from functools import cached_property
from pathlib import Path
from typing import Any

from relevance_plan import __version__
from relevance_plan.batch.store import ResultKey, ResultStore
from relevance_plan.errors import InputFileError, PlannerError, RelevancePlanError, SchedulerError, UsageError
from relevance_plan.io import find_suite_problems, load_domain, read_bytes
from relevance_plan.planning import runner
from relevance_plan.planning.loop import (
    MAX_TIMEOUT,
    METHODS,
    PLAN_OPTION_FIELDS,
    PlanOptions,
    PlanResult,
    PlanStatus,
    plan_task,
)
from relevance_plan.planning.planners import make_planner
from relevance_plan.relevance.knowledge import find_model
from relevance_plan.relevance.sidecar import read_sidecar_for, sidecar_path
from relevance_plan.signals import stop_event_on_signals

DASK_INSTALL_HINT = "pip install 'relevance-plan[dask]'"
DEFAULT_SCHEDULER_TIMEOUT = 10.0
_STOP_GRACE = 30.0  # seconds to wait for running jobs after their planners were killed
_ADDRESS_RE = re.compile(
    r"^(?:(?:tcp|tls|ws|wss|ucx)://)?[^\s/:]+:\d+$|^(?:tcp|tls|ws|wss|ucx)://\[[0-9a-fA-F:.]+\]:\d+$"
)


# --------------------------------------------------------------------------- keys


def _sha256(data: bytes) -> str:
    return hashlib.sha256(data).hexdigest()


def _file_hash(path: str | os.PathLike | None) -> str | None:
    """sha256 of a file's bytes, None when there is no such file."""
    if path is None:
        return None
    try:
        return _sha256(read_bytes(path))
    except InputFileError:
        return None


def problem_hash(domain_path: str | os.PathLike, problem_path: str | os.PathLike) -> str:
    """sha256 of the domain text, a NUL byte, and the problem text."""
    domain = read_bytes(domain_path, "domain file")
    problem = read_bytes(problem_path, "problem file")
    return _sha256(domain + b"\0" + problem)


def planner_version(planner: str = "fast-downward", config: str = runner.DEFAULT_CONFIG) -> str:
    """The version of the planner a job runs (a changed planner must not reuse stored rows)."""
    return make_planner(planner, config).version()


def _model_file(options: PlanOptions, domain_path: str) -> str | None:
    """The knowledge-model file the run would use (as ``relevance.setup.resolve_model`` finds it)."""
    if options.model_path is not None:
        return options.model_path
    try:
        name = load_domain(domain_path).name
    except RelevancePlanError:
        return None  # the job itself will report the bad domain
    found = find_model(name, domain_path)
    return str(found) if found is not None else None


# How each PlanOptions field enters a job's configuration key.  Every field
# must be listed (a test checks it): a new option cannot silently reuse rows
# stored without it.
#   "always"  - part of every job's key;
#   "pruning" - part of the key of the methods that prune (not 'pure');
#   "derived" - enters through a derived value (below);
#   "method"  - the key has the method in its own column.
FINGERPRINT_RULES: dict[str, str] = {
    "method": "method",
    "planner": "always",
    "planner_config": "always",
    "timeout": "always",
    "memory_limit_mb": "always",
    "validators": "derived",  # the validators that will actually run
    "seed": "always",
    "thresholds": "derived",  # as tau_class and tau_element
    "relax": "pruning",
    "relax_factor": "pruning",
    "first_share": "pruning",
    "scorer": "pruning",
    "goal_filter": "pruning",
    "prefer_free": "pruning",
    "model_path": "derived",  # as the sha256 of the model file the run would use
    "objective": "pruning",
    "model_task": "pruning",
    "human": "pruning",
}


def _plain(value: Any) -> Any:
    return float(value) if isinstance(value, float) else value


def config_fingerprint(options: PlanOptions, domain_path: str, problem_path: str) -> dict[str, Any]:
    """The options that influence a job's result, as a JSON-ready dict (see ``FINGERPRINT_RULES``).

    Besides the options: the tool version (a new release may prune or
    validate differently), for pruning methods the sha256 of the knowledge
    model the run would use, and for the oracle the sha256 of the sidecar
    (its ground truth).
    """
    from relevance_plan.planning.validate import default_validators

    unlisted = set(PLAN_OPTION_FIELDS) - set(FINGERPRINT_RULES)
    if unlisted:
        raise AssertionError(f"PlanOptions fields without a fingerprint rule: {sorted(unlisted)}")
    pruning = options.method != "pure"
    config: dict[str, Any] = {"tool_version": __version__, "method": options.method}
    for name, rule in FINGERPRINT_RULES.items():
        if rule == "always" or (rule == "pruning" and pruning):
            config[name] = _plain(getattr(options, name))
    config["validators"] = list(options.validators) if options.validators else list(default_validators())
    if pruning:
        config["tau_class"] = float(options.thresholds.tau_class)
        config["tau_element"] = float(options.thresholds.tau_element)
        config["model_hash"] = _file_hash(_model_file(options, domain_path))
        if options.method == "oracle" or options.scorer == "oracle":
            config["sidecar_hash"] = _file_hash(sidecar_path(problem_path))
    return config


def canonical_json(config: dict[str, Any]) -> str:
    """Sorted keys, no spaces: the same options always give the same text."""
    return json.dumps(config, sort_keys=True, separators=(",", ":"))


def config_hash(config: dict[str, Any]) -> str:
    """sha256 of the canonical JSON of ``config``."""
    return _sha256(canonical_json(config).encode("utf-8"))


# --------------------------------------------------------------------------- jobs


@dataclass(frozen=True)
class Job:
    """One method on one problem with one seed; ``options`` carries method and seed too."""

    domain_path: str
    problem_path: str
    suite: str
    method: str
    seed: int
    options: PlanOptions

    @cached_property
    def config(self) -> dict[str, Any]:
        """The options that influence the result (see ``config_fingerprint``)."""
        return config_fingerprint(self.options, self.domain_path, self.problem_path)

    @cached_property
    def key(self) -> ResultKey:
        return ResultKey(
            problem_hash=problem_hash(self.domain_path, self.problem_path),
            method=self.method,
            config_hash=config_hash(self.config),
            planner_version=planner_version(self.options.planner, self.options.planner_config),
        )

    @property
    def problem(self) -> str:
        return Path(self.problem_path).name

    def describe(self) -> str:
        return f"{self.suite}/{self.problem} {self.method} {self.options.planner} seed {self.seed}"


def parse_methods(methods: str | Iterable[str]) -> tuple[str, ...]:
    """Methods from 'relevance,pure' or a sequence; duplicates dropped, order kept."""
    if isinstance(methods, str):
        methods = methods.split(",")
    chosen: list[str] = []
    for method in (m.strip() for m in methods):
        if not method:
            continue
        if method not in METHODS:
            raise UsageError(f"unknown method '{method}' (choose from: {', '.join(METHODS)})")
        if method not in chosen:
            chosen.append(method)
    if not chosen:
        raise UsageError(f"no method given (choose from: {', '.join(METHODS)})")
    return tuple(chosen)


def parse_seeds(seeds: str | Iterable[int]) -> tuple[int, ...]:
    """Seeds from '0,1' or a sequence of ints; duplicates dropped, order kept."""
    if isinstance(seeds, str):
        try:
            values = [int(part) for part in seeds.split(",") if part.strip()]
        except ValueError:
            raise UsageError(f"--seeds must be comma-separated integers, got '{seeds}'") from None
    else:
        values = list(seeds)
    for value in values:
        if isinstance(value, bool) or not isinstance(value, int):
            raise UsageError(f"seeds must be integers, got {value!r}")
    chosen = list(dict.fromkeys(values))
    if not chosen:
        raise UsageError("no seed given")
    return tuple(chosen)


def build_jobs(
    suites: Sequence[str | os.PathLike],
    methods: str | Iterable[str],
    seeds: str | Iterable[int] = (0,),
    base_options: PlanOptions | None = None,
    planners: Sequence[str] = (),
) -> list[Job]:
    """Every (problem, seed, method) of every suite, problems in file-name order.

    A suite is a directory with ``domain.pddl`` and problem files (what
    ``relevance-plan generate`` writes); its name in the store is the
    directory's name.  Raises ``InputFileError`` for a missing suite or one
    without problems, ``UsageError`` for an unknown method or bad seed.
    """
    methods = parse_methods(methods)
    seeds = parse_seeds(seeds)
    base = base_options if base_options is not None else PlanOptions()
    if not suites:
        raise UsageError("no suite directory given")
    named: dict[str, Path] = {}
    jobs: list[Job] = []
    for suite in suites:
        directory = Path(suite).resolve()
        domain, problems = find_suite_problems(directory)
        name = directory.name
        if name in named:
            if named[name] == directory:
                continue  # the same suite twice
            raise UsageError(f"two suites named '{name}' ({named[name]} and {directory}): rename one")
        named[name] = directory
        for problem in problems:
            for seed in seeds:
                for planner in planners or (base.planner,):
                    for method in methods:
                        options = dataclasses.replace(base, method=method, seed=seed, planner=planner)
                        jobs.append(Job(str(domain), str(problem), name, method, seed, options))
    return jobs


# --------------------------------------------------------------------------- one job


def _now() -> str:
    return datetime.now(timezone.utc).isoformat(timespec="milliseconds")


def _sidecar_fields(problem_path: str) -> tuple[str | None, str | None]:
    """(world, difficulty) from the generator's sidecar, (None, None) without a usable one."""
    try:
        sidecar = read_sidecar_for(problem_path)
    except InputFileError:
        return None, None  # the job reports a bad sidecar when it needs one (the oracle)
    return (sidecar.world, sidecar.difficulty) if sidecar is not None else (None, None)


def _base_row(job: Job) -> dict[str, Any]:
    world, difficulty = _sidecar_fields(job.problem_path)
    return {
        **job.key._asdict(),
        "suite": job.suite,
        "problem": job.problem,
        "world": world,
        "difficulty": difficulty,
        "seed": job.seed,
        "timeout": float(job.options.timeout),
        "config_json": canonical_json(job.config),
    }


def result_row(job: Job, result: PlanResult) -> dict[str, Any]:
    """The store row of a finished ``plan_task``."""
    data = result.to_json()
    log = data["attempt_log"]
    return {
        **_base_row(job),
        "status": data["status"],
        "valid": int(bool(data["valid"])),
        "exit_code": log[-1]["planner_exit_code"] if log else None,
        "wall_time": result.wall_time,
        "relevance_time": result.relevance_time,
        "planner_time": result.planner_time,
        "objects_total": result.objects_total,
        "objects_kept": result.objects_kept,
        "attempts": len(result.attempts),
        "first_attempt_status": data["first_attempt_status"],
        "plan_length": data["plan_length"],
        "message": result.message,
        "finished_at": _now(),
        "result_json": json.dumps(data, sort_keys=True),
    }


def error_row(job: Job, error: RelevancePlanError, elapsed: float) -> dict[str, Any]:
    """The store row of a job whose input the library rejected (status 'input-error')."""
    message = str(error)
    data = {
        "method": job.method,
        "status": PlanStatus.INPUT_ERROR.value,
        "valid": False,
        "error": type(error).__name__,
        "message": message,
        "wall_time": round(elapsed, 4),
    }
    return {
        **_base_row(job),
        "status": PlanStatus.INPUT_ERROR.value,
        "valid": 0,
        "exit_code": None,
        "wall_time": elapsed,
        "relevance_time": 0.0,
        "planner_time": 0.0,
        "objects_total": 0,
        "objects_kept": 0,
        "attempts": 0,
        "first_attempt_status": PlanStatus.INPUT_ERROR.value,
        "plan_length": None,
        "message": message,
        "finished_at": _now(),
        "result_json": json.dumps(data, sort_keys=True),
    }


def run_job(job: Job) -> dict[str, Any]:
    """Run one job and return its store row (never writes to the store itself).

    A library error about this job's input (bad PDDL, bad sidecar, model that
    does not apply, ...) becomes a row with status 'input-error' and the
    error's message.  ``PlannerError`` (no planner to run at all) is not about
    the problem: it propagates and stops the batch.  A planner crash is an
    ordinary result: status 'planner-error' with the planner's exit code.
    """
    started = time.perf_counter()
    try:
        result = plan_task(job.domain_path, job.problem_path, job.options)
    except PlannerError:
        raise
    except RelevancePlanError as error:
        return error_row(job, error, time.perf_counter() - started)
    return result_row(job, result)


# --------------------------------------------------------------------------- compare


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
            f"{self.total} jobs: {self.already_stored} already stored, {self.ran} run"
            + (f" ({counts})" if counts else "")
            + f" in {self.elapsed:.1f} s; results in {self.store_path}"
        )


class _Quiet:
    """Stands in for a progress bar when progress is off."""

    def advance(self, failed: bool = False, note: str | None = None) -> None:
        pass


@contextlib.contextmanager
def _reporter(total: int, description: str, show: bool):
    if not show:
        yield _Quiet()
        return
    from relevance_plan.progress import progress

    with progress(total, description) as bar:
        yield bar


_POLL_SECONDS = 0.2  # how often a running batch looks at its stop event


class _Recorder:
    """Writes finished rows (main thread only) and counts them."""

    def __init__(self, store: ResultStore, bar):
        self.store = store
        self.bar = bar
        self.statuses: Counter = Counter()

    def __call__(self, row: dict[str, Any]) -> None:
        inserted = self.store.add(row)
        if inserted:
            self.statuses[row["status"]] += 1
        self.bar.advance(failed=row["status"] != PlanStatus.SOLVED.value)


def check_compare_options(
    *,
    timeout: float = 120.0,
    jobs: int = 1,
    scheduler: str | None = None,
    scheduler_timeout: float = DEFAULT_SCHEDULER_TIMEOUT,
) -> None:
    """``UsageError`` for a bad option, before anything is written (``demo`` checks first too)."""
    if isinstance(jobs, bool) or not isinstance(jobs, int) or jobs < 1:
        raise UsageError(f"--jobs must be a positive integer, got {jobs!r}")
    if scheduler is not None and not _ADDRESS_RE.match(scheduler):
        raise UsageError(f"--scheduler must look like tcp://HOST:PORT, got '{scheduler}'")
    if not 0 < scheduler_timeout <= MAX_TIMEOUT:
        raise UsageError(f"--scheduler-timeout must be positive and at most {MAX_TIMEOUT:g} s, got {scheduler_timeout}")
    PlanOptions(timeout=timeout)  # checks --timeout


def compare(
    suites: Sequence[str | os.PathLike],
    methods: str | Iterable[str],
    options: PlanOptions = PlanOptions(),
    *,
    planners: Sequence[str] = (),
    seeds: str | Iterable[int] = (0,),
    jobs: int = 1,
    store_path: str | os.PathLike = "results.sqlite",
    scheduler: str | None = None,
    scheduler_timeout: float = DEFAULT_SCHEDULER_TIMEOUT,
    progress: bool = True,
) -> CompareSummary:
    """Run every method (with every planner) on every problem of ``suites``; store one row per job.

    ``options`` are the ``plan`` options every job shares (its method, seed
    and planner are set per job; ``planners`` empty means ``options.planner``).
    Jobs already in the store are skipped, so rerunning an interrupted
    command resumes it.  ``jobs`` threads run locally; with ``scheduler``
    the Dask workers' threads run the jobs instead (``jobs`` is unused).
    Returns counts for this run; the numbers themselves come from
    ``report.build_report`` over the stored rows.

    Raises ``UsageError`` (bad argument, unknown method), ``InputFileError``
    (missing suite, suite without problems, store directory missing),
    ``StoreError`` (store of another schema version, not SQLite),
    ``SchedulerError`` (unreachable scheduler, Dask missing), ``PlannerError``
    (no planner at all) and ``KeyboardInterrupt`` after Ctrl-C/SIGTERM.
    """
    started = time.perf_counter()
    check_compare_options(jobs=jobs, scheduler=scheduler, scheduler_timeout=scheduler_timeout)
    for planner in planners or (options.planner,):
        make_planner(planner, options.planner_config, check=True)
    base = options
    all_jobs = build_jobs(suites, methods, seeds, base, planners)
    unique: dict[ResultKey, Job] = {}
    for job in all_jobs:
        unique.setdefault(job.key, job)

    # The scheduler is reached before the store is opened: an unreachable one leaves no empty store.
    client = connect_scheduler(scheduler, scheduler_timeout) if scheduler is not None else None
    try:
        with ResultStore(store_path) as store:
            stored = store.keys()
            pending = [job for key, job in unique.items() if key not in stored]
            recorder = None
            if pending:
                with (
                    stop_event_on_signals() as stop,
                    _reporter(len(pending), f"compare ({len(pending)} jobs)", progress) as bar,
                ):
                    recorder = _Recorder(store, bar)
                    if client is None:
                        _run_local(pending, jobs, recorder, stop)
                    else:
                        _run_dask(pending, client, scheduler, recorder, stop)
            statuses = dict(recorder.statuses) if recorder else {}
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


def _run_local(pending: Sequence[Job], workers: int, record: _Recorder, stop: threading.Event) -> None:
    pool = concurrent.futures.ThreadPoolExecutor(max_workers=workers, thread_name_prefix="relevance-plan-job")
    futures = [pool.submit(run_job, job) for job in pending]
    recorded: set = set()
    try:
        waiting = set(futures)
        while waiting:
            done, waiting = concurrent.futures.wait(
                waiting, timeout=_POLL_SECONDS, return_when=concurrent.futures.FIRST_COMPLETED
            )
            for future in done:
                row = future.result()  # an unexpected error stops the batch
                recorded.add(future)
                record(row)
            if stop.is_set():
                raise KeyboardInterrupt
    except BaseException as error:
        # Rows that were complete before the stop are genuine; keep them.
        finished = [
            f for f in futures if f not in recorded and f.done() and not f.cancelled() and f.exception() is None
        ]
        _stop_local(pool, futures)
        if isinstance(error, KeyboardInterrupt):
            for future in finished:
                record(future.result())
        raise
    pool.shutdown(wait=True)


def _stop_local(pool: concurrent.futures.ThreadPoolExecutor, futures: Sequence[concurrent.futures.Future]) -> None:
    """Cancel what has not started, kill running planners until every running job has returned."""
    pool.shutdown(wait=False, cancel_futures=True)
    deadline = time.monotonic() + _STOP_GRACE
    while True:
        try:
            # Again and again: a job between two attempts may start one more planner.
            runner.terminate_all_runs()
            running = [f for f in futures if not f.done()]
            if not running or time.monotonic() > deadline:
                return
            concurrent.futures.wait(running, timeout=0.1)
        except KeyboardInterrupt:
            continue  # a second Ctrl-C: finish stopping the planners first


# --------------------------------------------------------------------------- Dask


def connect_scheduler(address: str, timeout: float = DEFAULT_SCHEDULER_TIMEOUT):
    """A ``dask.distributed.Client`` for ``address``; ``SchedulerError`` when unreachable or Dask is missing."""
    try:
        from dask.distributed import Client
    except ImportError:
        raise SchedulerError(f"Dask is not installed: {DASK_INSTALL_HINT}") from None
    try:
        return Client(address, timeout=timeout, set_as_default=False)
    except (OSError, TimeoutError, ValueError) as error:
        detail = " ".join(str(error).split()) or type(error).__name__
        raise SchedulerError(f"cannot reach the Dask scheduler at {address}: {detail}") from None


def _terminate_worker_runs() -> None:
    runner.terminate_all_runs()


def _run_dask(pending: Sequence[Job], client, address: str, record: _Recorder, stop: threading.Event) -> None:
    from dask.distributed import as_completed

    try:
        from distributed import KilledWorker
    except ImportError:  # pragma: no cover - part of distributed
        KilledWorker = ()  # type: ignore[assignment]

    futures = [client.submit(run_job, job, pure=False, retries=2) for job in pending]
    recorded: set = set()
    try:
        finished = as_completed(futures, loop=client.loop)
        while not finished.is_empty():
            if stop.is_set():
                raise KeyboardInterrupt
            if not finished.has_ready():
                time.sleep(_POLL_SECONDS / 4)
                continue
            for future in finished.next_batch(block=False):
                try:
                    row = future.result()
                except KilledWorker as error:
                    raise SchedulerError(f"a Dask worker died running a job 3 times: {error}") from None
                except concurrent.futures.CancelledError:
                    raise SchedulerError(f"lost the Dask scheduler at {address}; rerun to resume") from None
                recorded.add(future.key)
                record(row)
                future.release()
    except BaseException as error:
        rows = []
        if isinstance(error, KeyboardInterrupt):
            # Rows that were complete before the stop are genuine; fetch them before cancelling.
            for future in futures:
                if future.key not in recorded and future.status == "finished":
                    with contextlib.suppress(Exception):
                        rows.append(future.result(timeout=5))
        with contextlib.suppress(Exception):
            client.cancel(futures)
        with contextlib.suppress(Exception):
            # Our planners run in the workers' processes; stop them too.
            client.run(_terminate_worker_runs)
        for row in rows:
            record(row)
        raise
