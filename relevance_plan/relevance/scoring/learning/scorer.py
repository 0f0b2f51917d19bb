"""The learned scorer: a model's probability for each object, on the scale the thresholds read.

The first attempt keeps what the model says: a probability above the model's
``threshold`` maps above the default element threshold (``DEFAULT_TAU``), and
below it under, the map being monotone so the ranking that widening follows
is the model's.  Each widening halves the thresholds, which here lowers the
probability an object needs, much as PLOI's threshold schedule does; the
objects widening adds by rank come in by probability too.

Objects the model cannot judge (a type or a predicate it never saw in
training) score 1: they are kept.  With ``respect_goal_zero`` (the default),
objects the goal scorer rules out (no role in reaching the goal) score 0 and
are left to closure, as the goal scorer leaves them; goal objects score 1.
"""

from __future__ import annotations

from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.scoring.learning.features import object_features
from relevance_plan.relevance.scoring.learning.learned_model import LearnedModel
from relevance_plan.relevance.scoring.scorers.base import ScoreResult

# The default element threshold (relevance.selection.prune.DEFAULT_TAU, which imports the scorers): the model's
# own threshold maps onto it.
KEEP_AT = 0.2


def calibrated(probability: float, threshold: float) -> float:
    """``probability`` on the thresholds' scale: ``threshold`` maps to KEEP_AT, 0 to 0 and 1 to 1."""
    if probability <= threshold:
        return KEEP_AT * probability / threshold
    return KEEP_AT + (1.0 - KEEP_AT) * (probability - threshold) / (1.0 - threshold)


def score_learned(task: PlanningTask, learned_model: LearnedModel) -> ScoreResult:
    features = object_features(task, learned_model.config, only_judged=learned_model.respect_goal_zero)
    task.check_time("scoring the objects")
    goal_objects = task.goal_objects
    scores: dict[str, float] = {}
    explanations: dict[str, str] = {}
    for name, vector in features.vectors.items():
        unseen_type = [t for t in features.types[name] if t not in learned_model.seen_types and t != "object"]
        unseen_predicates = sorted(features.predicates[name] - learned_model.seen_predicates)
        if name in goal_objects:
            scores[name], explanations[name] = 1.0, "named in the goal"
        elif unseen_type or unseen_predicates:
            what = f"type {unseen_type[0]}" if unseen_type else f"predicate {unseen_predicates[0]}"
            scores[name], explanations[name] = 1.0, f"the model never saw its {what}: kept"
        elif learned_model.respect_goal_zero and features.goal_scores.get(name, 0.0) == 0.0:
            scores[name], explanations[name] = 0.0, "no role in reaching the goal (goal scorer)"
        else:
            probability = learned_model.probability(vector)
            scores[name] = calibrated(probability, learned_model.threshold)
            explanations[name] = f"learned: P(needed) = {probability:.3f} (keeps above {learned_model.threshold:.3f})"
    problem = task.typing.problem
    return ScoreResult(
        "learned",
        scores,
        element_class={name: problem.objects[name] for name in scores},
        explanations=explanations,
        # of many candidates for one role, the first attempt keeps those a relaxed plan needs, best ranked first
        alternatives=features.alternatives,
    )
