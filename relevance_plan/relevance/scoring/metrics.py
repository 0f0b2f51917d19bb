"""Relevance quality (Section V.B) and the robot's inquiries (Section V.C).

Precision, recall and F1 of a predicted set against a ground-truth set, and
N = |predicted| / |truth|, the object ratio that predicts downstream speed.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Set
from dataclasses import dataclass

from relevance_plan.relevance.scoring.scorers import ScoreResult


@dataclass(frozen=True)
class SetMetrics:
    precision: float
    recall: float
    f1: float
    ratio: float  # N

    def as_dict(self) -> dict[str, float]:
        return {"precision": self.precision, "recall": self.recall, "f1": self.f1, "N": self.ratio}


def set_metrics(predicted: Set[str], truth: Set[str]) -> SetMetrics:
    hits = len(predicted & truth)
    precision = hits / len(predicted) if predicted else (1.0 if not truth else 0.0)
    recall = hits / len(truth) if truth else 1.0
    f1 = 2 * precision * recall / (precision + recall) if precision + recall > 0 else 0.0
    ratio = len(predicted) / len(truth) if truth else float(len(predicted) > 0)
    return SetMetrics(precision, recall, f1, ratio)


def mean_metrics(values: Iterable[SetMetrics]) -> SetMetrics:
    values = list(values)
    if not values:
        return SetMetrics(0.0, 0.0, 0.0, 0.0)
    n = len(values)
    return SetMetrics(
        sum(v.precision for v in values) / n,
        sum(v.recall for v in values) / n,
        sum(v.f1 for v in values) / n,
        sum(v.ratio for v in values) / n,
    )


# --------------------------------------------------------------------------- inquiries

NECESSITY_THRESHOLD = 0.9


@dataclass(frozen=True)
class Inquiries:
    necessary: tuple[str, ...]  # kinds served without asking
    optional: tuple[str, ...]  # kinds the robot asks about
    relevant_kinds: tuple[str, ...]
    objects: int  # questions without relevance: one per object

    @property
    def with_necessity(self) -> int:
        return len(self.optional)

    @property
    def relevance_only(self) -> int:
        return len(self.relevant_kinds)

    @property
    def reduction(self) -> float:
        return 1.0 - self.with_necessity / self.objects if self.objects else 0.0


def plan_inquiries(
    scores: ScoreResult,
    selected: Set[str],
    kinds: Mapping[str, str],
    structural_classes: Set[str],
    necessity_threshold: float = NECESSITY_THRESHOLD,
) -> Inquiries:
    """Which kinds the robot serves without asking, and which it asks about.

    A relevant kind is necessary when its class relevance is high and it is
    the only relevant kind of its class (nothing to choose: the coffee);
    every other relevant kind is an optional question (which cup? which milk?).
    People and places are the scene, not things to offer.
    """
    by_class: dict[str, set[str]] = {}
    for name in selected:
        class_name = scores.element_class.get(name)
        if class_name is None or class_name in structural_classes:
            continue
        by_class.setdefault(class_name, set()).add(kinds[name])
    necessary: list[str] = []
    optional: list[str] = []
    for class_name, class_kinds in sorted(by_class.items()):
        high = scores.class_scores.get(class_name, 0.0) >= necessity_threshold
        (necessary if high and len(class_kinds) == 1 else optional).extend(sorted(class_kinds))
    relevant = sorted(set(necessary) | set(optional))
    return Inquiries(tuple(sorted(necessary)), tuple(sorted(optional)), tuple(relevant), len(kinds))
