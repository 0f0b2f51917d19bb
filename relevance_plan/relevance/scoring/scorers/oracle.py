"""The oracle: the generator's ``necessary`` set (evaluation only)."""

from __future__ import annotations

from relevance_plan.errors import UsageError
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.scoring.scorers.base import ScoreRequest, ScoreResult


def score_by_oracle(task: PlanningTask, request: ScoreRequest) -> ScoreResult:
    if request.necessary is None:
        raise UsageError(
            "the oracle scorer needs the generator's sidecar (PROBLEM.json with a 'necessary' list)",
            path=task.problem.path,
        )
    scores = {name: 1.0 if name in request.necessary else 0.0 for name in task.problem.objects}
    explanations = {name: "in the sidecar's necessary set" if s else "not necessary" for name, s in scores.items()}
    return ScoreResult("oracle", scores, explanations=explanations)
