"""What one batch job is and how it runs.

A *job* is one method on one problem with one seed (and one planner) under
one set of options.  ``build_jobs`` makes every job of some suites;
``run_job`` runs one and returns its store row without touching the store,
so the same function runs in a local thread or on a Dask worker.
"""

from __future__ import annotations

import dataclasses
import os
import time
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from functools import cached_property
from pathlib import Path
from typing import Any

from relevance_plan.batch.keys import canonical_json, config_fingerprint, result_key
from relevance_plan.batch.rows import error_row, result_row
from relevance_plan.batch.store import ResultKey
from relevance_plan.batch.suites import find_suite_problems, suite_name
from relevance_plan.errors import InputFileError, PlannerError, RelevancePlanError, UsageError
from relevance_plan.planning.options import METHODS, Method, PlanOptions
from relevance_plan.planning.run import plan_task
from relevance_plan.sidecar import read_sidecar_for


@dataclass(frozen=True)
class Job:
    """One method on one problem with one seed; ``options`` carries method, seed and planner too.

    ``input_error`` says why the job cannot run at all (its problem has no
    domain file, or is not a regular file): it is then recorded, not planned.
    """

    domain_path: str | None
    problem_path: str
    suite: str
    method: Method
    seed: int
    options: PlanOptions
    input_error: str | None = None

    @cached_property
    def config(self) -> dict[str, Any]:
        """The options that influence the result (see ``keys.config_fingerprint``)."""
        # A job that cannot run never reads its files: a FIFO would block.
        domain = self.domain_path if self.input_error is None else None
        return config_fingerprint(self.options, domain, self.problem_path)

    @cached_property
    def key(self) -> ResultKey:
        return result_key(self.domain_path, self.problem_path, self.input_error, self.config, self.options)

    @property
    def problem(self) -> str:
        return Path(self.problem_path).name

    def describe(self) -> str:
        return f"{self.suite}/{self.problem} {self.method} {self.options.planner} seed {self.seed}"

    def columns(self) -> dict[str, Any]:
        """The job's own columns of its store row (``rows`` adds what the run gave)."""
        world, difficulty = _sidecar_fields(self.problem_path)
        return {
            **self.key._asdict(),
            "suite": self.suite,
            "problem": self.problem,
            "world": world,
            "difficulty": difficulty,
            "seed": self.seed,
            "timeout": float(self.options.timeout or 0.0),  # compare refuses jobs without one
            "config_json": canonical_json(self.config),
        }


def _sidecar_fields(problem_path: str) -> tuple[str | None, str | None]:
    """(world, difficulty) from the generator's sidecar, (None, None) without a usable one."""
    try:
        sidecar = read_sidecar_for(problem_path)
    except InputFileError:
        return None, None  # the job reports a bad sidecar when it needs one (the oracle)
    return (sidecar.world, sidecar.difficulty) if sidecar is not None else (None, None)


def parse_methods(methods: str | Iterable[str]) -> tuple[Method, ...]:
    """Methods from 'relevance,pure' or a sequence; duplicates dropped, order kept."""
    if isinstance(methods, str):
        methods = methods.split(",")
    chosen: list[Method] = []
    for method in (m.strip() for m in methods):
        if not method:
            continue
        if method not in METHODS:
            raise UsageError(f"unknown method '{method}' (choose from: {', '.join(METHODS)})")
        if method not in chosen:
            chosen.append(Method(method))
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
    """Every (problem, seed, planner, method) of every suite, problems in natural name order.

    A suite is a folder of problems in one of the layouts of
    ``suites.find_suite_problems`` (``generate``'s, the IPC's, potassco's,
    pddlgym's); its name in the store is the folder's name.  A problem
    without a domain or that is not a regular file becomes jobs that record
    the reason.  Raises ``InputFileError`` for a missing suite or one without
    problems, ``UsageError`` for an unknown method or bad seed.
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
        entries = find_suite_problems(directory)
        name = suite_name(directory)
        if name in named:
            if named[name] == directory:
                continue  # the same suite twice
            raise UsageError(f"two suites named '{name}' ({named[name]} and {directory}): rename one")
        named[name] = directory
        for entry in entries:
            domain = str(entry.domain) if entry.domain is not None else None
            for seed in seeds:
                for planner in planners or (base.planner,):
                    for method in methods:
                        options = dataclasses.replace(base, method=method, seed=seed, planner=planner)
                        jobs.append(Job(domain, str(entry.problem), name, method, seed, options, entry.error))
    return jobs


def run_job(job: Job) -> dict[str, Any]:
    """Run one job and return its store row (never writes to the store itself).

    A library error about this job's input (bad PDDL, bad sidecar, model that
    does not apply, no domain file, a problem that is not a regular file, ...)
    becomes a row with status 'input-error' and the error's message.
    ``PlannerError`` (no planner to run at all) is not about the problem: it
    propagates and stops the batch.  A planner crash is an ordinary result:
    status 'planner-error' with the planner's exit code.
    """
    started = time.perf_counter()
    if job.input_error is not None or job.domain_path is None:
        error = InputFileError(job.input_error or "no domain file found for this problem", path=job.problem_path)
        return error_row(job.columns(), error, time.perf_counter() - started)
    try:
        result = plan_task(job.domain_path, job.problem_path, job.options)
    except PlannerError:
        raise
    except RelevancePlanError as error:
        return error_row(job.columns(), error, time.perf_counter() - started)
    return result_row(job.columns(), result)
