"""Values shared by every scorer."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from relevance_plan.relevance.scoring.knowledge import KnowledgeModel

if TYPE_CHECKING:  # the text package is imported only when free text is given
    from relevance_plan.relevance.scoring.word_matching import WordMatch


@dataclass(frozen=True)
class ScoreRequest:
    knowledge_model: KnowledgeModel | None = None
    objective: str | None = None
    activity: str | None = None  # the knowledge model's activity (the paper's task T)
    human: str | None = None
    seed: int = 0
    place_kinds: bool = False  # kinds and types the model does not list are placed under their nearest class
    necessary: frozenset[str] | None = None  # the oracle's answer, from a generator sidecar


@dataclass(frozen=True)
class ScoreResult:
    scorer: str
    element_scores: Mapping[str, float]
    element_class: Mapping[str, str] = field(default_factory=dict)
    class_scores: Mapping[str, float] = field(default_factory=dict)  # empty: no class threshold
    explanations: Mapping[str, str] = field(default_factory=dict)
    sufficient: bool = True
    insufficiency: str = ""
    unknown: tuple[str, ...] = ()  # elements whose class the model does not know
    # one of many candidates for a role (fifty airplanes): a few may do, the first selection keeps those it needs
    alternatives: frozenset[str] = frozenset()
    objective: str | None = None
    activity_distribution: Mapping[str, float] = field(default_factory=dict)
    activity_entropy: float | None = None
    # free text mapped to the model's names (the objective, the task, object kinds), each with its similarity
    understood: tuple[WordMatch, ...] = ()
    # thresholds -> the elements they admit, found once per result (a live session keeps one result
    # across the events that change no score)
    passing: dict[object, frozenset[str]] = field(default_factory=dict, init=False, compare=False, repr=False)

    def class_score(self, name: str) -> float | None:
        """R(C) of the element's class; None when this scorer does not score classes."""
        if not self.class_scores:
            return None
        return self.class_scores.get(self.element_class.get(name, ""), 0.0)
