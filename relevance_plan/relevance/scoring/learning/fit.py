"""Fitting a learned model: a logistic model of P(needed | features) on labelled training problems.

The labels come from solved problems (``relevance_plan.batch.learn`` plans
them); here the model is fitted on the objects' features
(``features.object_features``), deterministically (Newton's method, L2,
positives and negatives weighted equally per problem), and its threshold set
so that the first attempt keeps every needed object on most training
problems.  Fitting needs numpy (``pip install 'relevance-plan[learn]'``),
imported only here and only when a model is fitted; applying a model
(``scorer``) needs nothing extra.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field, replace
from typing import Any

from relevance_plan.errors import UsageError
from relevance_plan.pddl.model import Domain, Problem
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.scoring.learning.features import (
    GOAL_NAMED,
    GOAL_ZERO,
    NAMED,
    NAMED_FEATURES,
    FeatureConfig,
    Features,
    hub_predicates,
)
from relevance_plan.relevance.scoring.learning.learned_model import LearnedModel, domain_signature

L2 = 1.0  # ridge penalty of the logistic fit (on the summed, per-problem-balanced loss)
COVERAGE = 0.9  # the threshold keeps every needed object on this share of the training problems
MIN_THRESHOLD, MAX_THRESHOLD = 0.02, 0.9


@dataclass(frozen=True)
class LabelledProblem:
    """A training problem's objects, their features, and which of them a plan needed."""

    path: str
    objects: int
    positives: frozenset[str]
    vectors: Mapping[str, Features] = field(repr=False)
    solve_time: float = 0.0
    planner_runs: int = 1
    types: frozenset[str] = frozenset()  # the objects' types and their ancestors
    predicates: frozenset[str] = frozenset()  # the predicates of the facts naming objects


def with_hubs(config: FeatureConfig, domain: Domain, problems: Iterable[Problem]) -> FeatureConfig:
    """``config`` marking the predicates that are hubs on any training problem on every problem, so
    that small problems (where they may link few pairs) and large ones describe objects alike."""
    hubs = set(config.hubs)
    for problem in problems:
        hubs |= hub_predicates(PlanningTask(domain, problem))
    return replace(config, hubs=frozenset(hubs))


def fit_learned_model(
    domain: Domain, problems: Sequence[LabelledProblem], config: FeatureConfig, labels: str, seed: int
) -> LearnedModel:
    """A logistic model of P(needed | features) fitted on ``problems``, with its keep threshold."""
    try:
        import numpy as np
    except ImportError:
        raise UsageError("learn fits its model with numpy: pip install 'relevance-plan[learn]'") from None

    used = sorted({index for p in problems for v in p.vectors.values() for index in v if index >= NAMED})
    column = {index: NAMED + position for position, index in enumerate(used)}
    width = NAMED + len(used)
    rows, targets, weights = [], [], []
    for problem in problems:
        positives = len(problem.positives)
        negatives = problem.objects - positives
        for name in sorted(problem.vectors):
            row = np.zeros(width)
            for index, value in problem.vectors[name].items():
                row[index if index < NAMED else column[index]] = value
            rows.append(row)
            needed = name in problem.positives
            targets.append(1.0 if needed else 0.0)
            # each problem weighs the same, and within it the needed objects as much as the others
            weights.append(0.5 / max(positives if needed else negatives, 1))
    x, y, w = np.array(rows), np.array(targets), np.array(weights)
    theta = _newton(x, y, w, L2)
    named = tuple(float(v) for v in theta[:NAMED])
    hashed = {index: float(theta[column[index]]) for index in used if abs(theta[column[index]]) > 1e-9}
    learned_model = LearnedModel(
        domain=domain_signature(domain),
        config=config,
        named_weights=named,
        hashed_weights=hashed,
        threshold=0.5,
        seen_types=frozenset(),
        seen_predicates=frozenset(),
        labels=labels,
    )
    threshold = choose_threshold(learned_model, problems)
    seen_types, seen_predicates = _seen(problems)
    return replace(
        learned_model,
        threshold=threshold,
        seen_types=seen_types,
        seen_predicates=seen_predicates,
        training={
            "problems": len(problems),
            "objects": sum(p.objects for p in problems),
            "needed": sum(len(p.positives) for p in problems),
            "planner_runs": sum(p.planner_runs for p in problems),
            "seed": seed,
            "l2": L2,
            "features_used": len(used),
            "named_features": list(NAMED_FEATURES),
        },
    )


def _newton(x: Any, y: Any, w: Any, l2: float, iterations: int = 30) -> Any:
    """Weighted L2-regularised logistic regression by Newton's method (deterministic)."""
    import numpy as np

    theta = np.zeros(x.shape[1])
    penalty = np.full(x.shape[1], l2)
    penalty[0] = 1e-6  # the bias is not shrunk
    for _ in range(iterations):
        z = np.clip(x @ theta, -30, 30)
        p = 1.0 / (1.0 + np.exp(-z))
        gradient = x.T @ (w * (p - y)) + penalty * theta
        hessian = (x * (w * p * (1 - p))[:, None]).T @ x + np.diag(penalty)
        step = np.linalg.solve(hessian, gradient)
        theta = theta - step
        if float(np.max(np.abs(step))) < 1e-7:
            break
    return theta


def choose_threshold(learned_model: LearnedModel, problems: Sequence[LabelledProblem]) -> float:
    """The probability the first attempt keeps from: each training problem's lowest probability of a
    needed object; the threshold keeps every needed object on ``COVERAGE`` of the problems."""
    lowest = []
    for problem in problems:
        needed = [
            learned_model.probability(vector)
            for name in problem.positives
            if (vector := problem.vectors.get(name)) is not None and _judged(learned_model, vector)
        ]
        if needed:
            lowest.append(min(needed))
    if not lowest:
        return 0.5
    lowest.sort()
    index = int((1.0 - COVERAGE) * len(lowest))
    value = lowest[min(index, len(lowest) - 1)] * 0.999
    return min(max(value, MIN_THRESHOLD), MAX_THRESHOLD)


def _judged(learned_model: LearnedModel, vector: Features) -> bool:
    """Whether the scorer scores this object by the model (not a goal object, not ruled out)."""
    if vector.get(GOAL_NAMED):
        return False
    return not (learned_model.respect_goal_zero and vector.get(GOAL_ZERO))


def _seen(problems: Sequence[LabelledProblem]) -> tuple[frozenset[str], frozenset[str]]:
    types = frozenset(t for p in problems for t in p.types)
    predicates = frozenset(name for p in problems for name in p.predicates)
    return types, predicates
