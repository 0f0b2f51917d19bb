"""Scorers: each turns a planning task into relevance scores for its objects.

A scorer is a function ``score(task, request) -> ScoreResult`` registered in
``SCORERS``; the CLI's ``--scorer`` choices come from this dict.

    base.py             ScoreRequest and ScoreResult, shared by every scorer
    goal.py             ``goal``: roles found by regressing the goal through the actions
    knowledge_model.py  ``model``: the paper's relevance model over a knowledge model
    random.py           ``random``: the paper's baseline
    oracle.py           ``oracle``: the generator's necessary set (evaluation only)

The learned scorer (``learned:MODEL``) is in ``relevance.scoring.learning``.
"""

from __future__ import annotations

from collections.abc import Callable

from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.scoring.scorers.base import ScoreRequest, ScoreResult
from relevance_plan.relevance.scoring.scorers.goal import score_by_goal
from relevance_plan.relevance.scoring.scorers.knowledge_model import score_by_knowledge_model
from relevance_plan.relevance.scoring.scorers.oracle import score_by_oracle
from relevance_plan.relevance.scoring.scorers.random import score_randomly

Scorer = Callable[[PlanningTask, ScoreRequest], ScoreResult]

SCORERS: dict[str, Scorer] = {
    "model": score_by_knowledge_model,
    "goal": score_by_goal,
    "random": score_randomly,
    "oracle": score_by_oracle,
}

__all__ = ["SCORERS", "Scorer", "ScoreRequest", "ScoreResult"]
