"""The former home of the Fast Downward runner, kept importable until its last callers move.

Fast Downward's adapter is ``fast_downward.py``, process supervision
``process.py``, the outcome of a run ``outcome.py``.
"""

from relevance_plan.planning.fast_downward import DEFAULT_CONFIG, FAST_DOWNWARD_ENV, run_fast_downward
from relevance_plan.planning.outcome import PlannerStatus, RunOutcome
from relevance_plan.planning.process import terminate_all_runs

__all__ = [
    "DEFAULT_CONFIG",
    "FAST_DOWNWARD_ENV",
    "PlannerStatus",
    "RunOutcome",
    "run_fast_downward",
    "terminate_all_runs",
]
