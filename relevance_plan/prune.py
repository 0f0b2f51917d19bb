"""Score -> threshold -> closure -> pruned problem text, as one result value."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import AbstractSet, Sequence

from .analysis import ConstraintRule, infer_constraint_rules, single_valued_predicates
from .closure import Restored, close_over_constraints
from .knowledge import KnowledgeModel, check_threshold
from .scorers import SCORERS, ScoreRequest, ScoreResult, Task
from .errors import UsageError
from .writer import write_pruned_problem

DEFAULT_TAU = 0.2


@dataclass(frozen=True)
class Thresholds:
    tau_class: float = DEFAULT_TAU
    tau_element: float = DEFAULT_TAU

    def __post_init__(self):
        check_threshold(self.tau_class, "--tau-class")
        check_threshold(self.tau_element, "--tau-element")

    def scaled(self, factor: float) -> "Thresholds":
        return Thresholds(self.tau_class * factor, self.tau_element * factor)


@dataclass(frozen=True)
class PruneResult:
    task: Task
    scores: ScoreResult
    thresholds: Thresholds
    selected: frozenset  # passed the thresholds (plus goal objects)
    kept: frozenset  # after closure
    restored: tuple  # of Restored, in the order closure found them
    text: str = field(repr=False)  # the pruned problem in the user's own layout

    @property
    def removed(self) -> tuple:
        return tuple(name for name in self.task.problem.objects if name not in self.kept)

    @property
    def sufficient(self) -> bool:
        return self.scores.sufficient


def constraint_rules(task: Task, model: KnowledgeModel | None) -> tuple[ConstraintRule, ...]:
    rules = list(infer_constraint_rules(task.domain, task.init_index))
    if model is not None:
        for dependency in model.dependencies:
            rules.append(
                ConstraintRule(dependency.predicate, dependency.when_kept, dependency.restore, "model", dependency.reason)
            )
    return tuple(rules)


def can_serve_goal(task: Task, name: str) -> bool:
    """Whether the object can fill a role toward the goal (see ``analysis.analyse_goal``)."""
    roles = task.goal_analysis.role_depth
    return name in task.goal_objects or any(t in roles for t in task.domain.ancestors(task.problem.objects[name]))


def select_relevant(task: Task, scores: ScoreResult, thresholds: Thresholds, goal_filter: bool = False) -> frozenset:
    """Elements whose class passes tau_c (when classes are scored) and whose score passes tau_e.

    With ``goal_filter``, relevant objects no action toward the goal can use
    (a napkin the domain can only carry around) are left out too: relevant to
    the human, useless to the planner.  Closure still puts back what the kept
    objects need (their places, what stands on them).
    """
    selected = set(task.goal_objects & task.problem.objects.keys())
    for name, score in scores.element_scores.items():
        if scores.class_scores:
            class_name = scores.element_class.get(name)
            if scores.class_scores.get(class_name, 0.0) <= thresholds.tau_class:
                continue
        if score > thresholds.tau_element and (not goal_filter or can_serve_goal(task, name)):
            selected.add(name)
    return frozenset(selected)


def prune_with_scores(
    task: Task,
    scores: ScoreResult,
    thresholds: Thresholds = Thresholds(),
    model: KnowledgeModel | None = None,
    extra: AbstractSet[str] = frozenset(),
    goal_filter: bool = False,
) -> PruneResult:
    """Threshold the scores, add ``extra`` objects, close over constraints, write the text."""
    selected = select_relevant(task, scores, thresholds, goal_filter) | (frozenset(extra) & task.problem.objects.keys())
    kept, restored = close_over_constraints(
        selected,
        constraint_rules(task, model),
        task.init_index,
        candidates=task.problem.objects.keys(),
        singleton_predicates=single_valued_predicates(task.domain, task.init_index),
    )
    return PruneResult(
        task=task,
        scores=scores,
        thresholds=thresholds,
        selected=selected,
        kept=kept,
        restored=restored,
        text=write_pruned_problem(task.problem, kept),
    )


def score_task(task: Task, scorer: str, request: ScoreRequest) -> ScoreResult:
    if scorer not in SCORERS:
        raise UsageError(f"unknown scorer '{scorer}' (choose from: {', '.join(SCORERS)})")
    return SCORERS[scorer](task, request)


def widen(
    result: PruneResult,
    factor: float,
    extra: AbstractSet[str] = frozenset(),
    model: KnowledgeModel | None = None,
    goal_filter: bool = False,
) -> tuple[PruneResult, frozenset]:
    """One relaxation step: scale the thresholds by ``factor`` and put back the best-ranked
    quarter (at least 4) of the removed objects; returns the new result and the extra set."""
    ranked = ranked_by_score(result)
    extra = frozenset(extra) | frozenset(ranked[: max(4, len(ranked) // 4)])
    widened = prune_with_scores(result.task, result.scores, result.thresholds.scaled(factor), model, extra, goal_filter)
    return widened, extra


def ranked_by_score(result: PruneResult) -> Sequence[str]:
    """Pruned objects, most relevant first: the order in which relaxation adds them back."""
    scores = result.scores.element_scores
    return sorted(result.removed, key=lambda name: (-scores.get(name, 0.0), name))


__all__ = [
    "DEFAULT_TAU",
    "PruneResult",
    "Restored",
    "Thresholds",
    "constraint_rules",
    "prune_with_scores",
    "ranked_by_score",
    "widen",
    "score_task",
    "select_relevant",
]
