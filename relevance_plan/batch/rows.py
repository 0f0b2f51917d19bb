"""Store rows: a finished job (or the error that stopped it) as one row of the results store."""

from __future__ import annotations

import json
from datetime import datetime, timezone
from typing import TYPE_CHECKING, Any

from relevance_plan.batch.keys import canonical_json
from relevance_plan.errors import InputFileError, RelevancePlanError, UnsupportedFeatureError
from relevance_plan.planning.results import PlanResult, PlanStatus
from relevance_plan.relevance.sidecar import read_sidecar_for

if TYPE_CHECKING:
    from relevance_plan.batch.jobs import Job


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
        "timeout": float(job.options.timeout or 0.0),  # compare refuses jobs without one
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
        "plan_cost": result.plan_cost if result.status is PlanStatus.SOLVED else None,
        "message": result.message,
        "finished_at": _now(),
        "result_json": json.dumps(data, sort_keys=True),
    }


def error_row(job: Job, error: RelevancePlanError, elapsed: float) -> dict[str, Any]:
    """The store row of a job whose input the library rejected: 'unsupported' for legal PDDL the
    tool or the planner cannot take, else 'input-error'."""
    message = str(error)
    status = (PlanStatus.UNSUPPORTED if isinstance(error, UnsupportedFeatureError) else PlanStatus.INPUT_ERROR).value
    data = {
        "method": job.method,
        "status": status,
        "valid": False,
        "error": type(error).__name__,
        "message": message,
        "wall_time": round(elapsed, 4),
    }
    return {
        **_base_row(job),
        "status": status,
        "valid": 0,
        "exit_code": None,
        "wall_time": elapsed,
        "relevance_time": 0.0,
        "planner_time": 0.0,
        "objects_total": 0,
        "objects_kept": 0,
        "attempts": 0,
        "first_attempt_status": status,
        "plan_length": None,
        "plan_cost": None,
        "message": message,
        "finished_at": _now(),
        "result_json": json.dumps(data, sort_keys=True),
    }
