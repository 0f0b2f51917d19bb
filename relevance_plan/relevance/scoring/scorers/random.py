"""Random relevance, the paper's baseline: uniform scores under the same thresholds.

Each PDDL type is a class with R(C) ~ U(0, 1); each element gets
R(e) = R(C) * U(0, 1).  Seeded from the seed and the problem name, so a run
is repeatable.
"""

from __future__ import annotations

import random as _random

from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.scoring.scorers.base import ScoreRequest, ScoreResult


def _rng(seed: int, problem_name: str) -> _random.Random:
    import hashlib  # here: every other command would pay for it at import

    digest = hashlib.sha256(f"{seed}:{problem_name}".encode()).digest()
    return _random.Random(int.from_bytes(digest[:8], "big"))


def score_randomly(task: PlanningTask, request: ScoreRequest) -> ScoreResult:
    rng = _rng(request.seed, task.problem.name)
    class_scores = {type_name: rng.random() for type_name in sorted(set(task.problem.objects.values()))}
    scores = {}
    for name, type_name in task.problem.objects.items():
        scores[name] = class_scores[type_name] * rng.random()
    return ScoreResult(
        "random",
        scores,
        element_class=dict(task.problem.objects),
        class_scores=class_scores,
        explanations={name: f"random (seed {request.seed})" for name in scores},
    )
