"""Store rows: a finished job (or the error that stopped it) as one row of the results store.

A row is the job's own columns (``jobs.Job.columns``: its key, suite,
problem, seed, options) and what the run gave; this module knows nothing
else of jobs.
"""

from __future__ import annotations

import json
from collections.abc import Mapping
from datetime import datetime, timezone
from typing import Any

from relevance_plan.errors import RelevancePlanError, UnsupportedFeatureError
from relevance_plan.planning.results import PlanResult, PlanStatus


def _now() -> str:
    return datetime.now(timezone.utc).isoformat(timespec="milliseconds")


def result_row(job_columns: Mapping[str, Any], result: PlanResult) -> dict[str, Any]:
    """The store row of a finished ``plan_task``; ``job_columns`` are the job's own."""
    row = row_from_json(job_columns, result.to_json())
    # the result's own figures, unrounded (the JSON rounds them)
    return {
        **row,
        "wall_time": result.wall_time,
        "relevance_time": result.relevance_time,
        "planner_time": result.planner_time,
    }


def row_from_json(job_columns: Mapping[str, Any], data: Mapping[str, Any]) -> dict[str, Any]:
    """The store row of a run from its ``plan --json`` output (a benchmark that runs the command)."""
    log = data["attempt_log"]
    return {
        **job_columns,
        "status": data["status"],
        "valid": int(bool(data["valid"])),
        "exit_code": log[-1]["planner_exit_code"] if log else None,
        "wall_time": data["wall_time"],
        "relevance_time": data["relevance_time"],
        "planner_time": data["planner_time"],
        # the columns are NOT NULL: a count the run never established (null in result_json) is 0 there
        "objects_total": data["objects_total"] or 0,
        "objects_kept": data["objects_kept"] or 0,
        "attempts": len(log),
        "first_attempt_status": data["first_attempt_status"],
        "plan_length": data["plan_length"],
        "plan_cost": data["plan_cost"] if data["status"] == PlanStatus.SOLVED.value else None,
        "message": data["message"],
        "finished_at": _now(),
        "result_json": json.dumps(data, sort_keys=True),
    }


def error_row(job_columns: Mapping[str, Any], error: RelevancePlanError, elapsed: float) -> dict[str, Any]:
    """The store row of a job whose input the library rejected: 'unsupported' for legal PDDL the
    tool or the planner cannot take, else 'input-error'."""
    message = str(error)
    status = (PlanStatus.UNSUPPORTED if isinstance(error, UnsupportedFeatureError) else PlanStatus.INPUT_ERROR).value
    data = {
        "method": job_columns["method"],
        "status": status,
        "valid": False,
        "error": type(error).__name__,
        "message": message,
        "wall_time": round(elapsed, 4),
    }
    return {
        **job_columns,
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
