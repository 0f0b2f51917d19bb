"""Scorers: each turns a planning task into relevance scores for its objects.

A scorer is a function ``score(task, request) -> ScoreResult`` registered in
``SCORERS``; the CLI's ``--scorer`` choices come from this dict.
"""

from __future__ import annotations

from typing import Callable

from .base import ScoreRequest, ScoreResult, Task
from .goal import score_by_goal
from .model import score_by_model
from .oracle import score_by_oracle
from .random import score_randomly

Scorer = Callable[[Task, ScoreRequest], ScoreResult]

SCORERS: dict[str, Scorer] = {
    "model": score_by_model,
    "goal": score_by_goal,
    "random": score_randomly,
    "oracle": score_by_oracle,
}

__all__ = ["SCORERS", "Scorer", "ScoreRequest", "ScoreResult", "Task"]
