"""Scores kept current event by event.

:class:`LiveModelScores` follows the knowledge-model scorer stage by stage
(``scorers/knowledge_model.py``: context, one element, contents) and re-scores only
the elements an event can affect: the objects a fact names, the items of a
place that was opened or where a human stands, a place whose contents
changed.  Its :meth:`~LiveModelScores.result` equals ``score_by_knowledge_model`` on
the current state.

:class:`FullScores` is the fallback for every other scorer (goal, random):
their scores can depend on the whole state (the goal scorer regresses the
goal through the initial state), so each change re-scores everything through
``relevance.setup.score_problem``.
"""

from __future__ import annotations

from dataclasses import replace

from relevance_plan.pddl.formulas import names_in
from relevance_plan.relevance.knowledge import KnowledgeModel
from relevance_plan.relevance.prune import Thresholds
from relevance_plan.relevance.scene import Element, build_scene
from relevance_plan.relevance.scorers import ScoreRequest, ScoreResult
from relevance_plan.relevance.scorers.knowledge_model import (
    UNKNOWN_CLASS,
    KnowledgeContext,
    class_of,
    contents_explanation,
    insufficient_result,
    knowledge_context,
    score_element,
    scored_by_contents,
    unknown_share_problem,
    with_goal_objects,
)
from relevance_plan.relevance.setup import ScoringOptions, score_problem
from relevance_plan.relevance.task import PlanningTask
from relevance_plan.session.state import LiveScene

ALL = None  # "every element may have changed"


def request_for(options: ScoringOptions, model: KnowledgeModel | None) -> ScoreRequest:
    """The request ``score_problem`` builds from the options (no oracle in a live session)."""
    return ScoreRequest(
        knowledge_model=model,
        objective=options.objective,
        model_task=options.model_task,
        human=options.human,
        seed=options.seed,
        place_kinds=options.place_kinds,
    )


class LiveModelScores:
    def __init__(self, scene: LiveScene, model: KnowledgeModel, options: ScoringOptions):
        self.scene = scene
        self.model = model
        self.predicates = model.scene
        self.elements: dict[str, Element] = {}
        self.element_class: dict[str, str] = {}
        self.members: dict[str, set] = {}
        self.scores: dict[str, float] = {}
        self.explanations: dict[str, str] = {}
        self.contents: dict[str, dict[str, float]] = {}  # place -> item -> score
        self.place_of: dict[str, str] = {}  # scored item -> the place its score counts for
        self.class_scores: dict[str, float] = {}
        self.context: KnowledgeContext = knowledge_context(scene.goal, request_for(options, model))
        self._dirty: set = set()  # places and classes that lost a member
        self.describe_all()
        self.rescore_all()

    # ------------------------------------------------------------------ context

    def set_options(self, options: ScoringOptions) -> None:
        """A new goal, human or cue: a new context, and every score again."""
        self.context = knowledge_context(self.scene.goal, request_for(options, self.model))
        self.rescore_all()

    @property
    def decided(self) -> bool:
        return not self.context.insufficiency

    # ------------------------------------------------------------------ descriptions

    def describe_all(self) -> None:
        scene = build_scene(self.scene.domain, self.scene.objects, self.scene.facts, self.predicates)
        for name, element in scene.elements.items():
            self._set_element(name, element)

    def describe(self, names) -> None:
        """Describe again the named elements (their place, what stands on them, ...)."""
        names = [
            n
            for n in names
            if n in self.scene.objects
            and not (n in self.element_class and scored_by_contents(self.element_class[n], self.model))
        ]
        if not names:
            return
        index, p = self.scene.index, self.predicates
        facts: set = set()
        for name in names:
            own = index.by_object.get(name, ())
            facts.update(own)
            for fact in own:
                if fact[0] in (p.location, p.containment, p.human_location) and len(fact) == 3 and fact[1] == name:
                    for role in (p.access, p.closed, p.human_location):
                        if role is not None:
                            facts.update(index.facts_of(fact[2], role))
        described = {name: self.scene.objects[name] for name in names}
        scene = build_scene(self.scene.domain, described, facts, p, types=self.scene.objects)
        for name, element in scene.elements.items():
            self._set_element(name, element)

    def _set_element(self, name: str, element: Element) -> None:
        self.elements[name] = element
        if name not in self.element_class:
            class_name = class_of(element, self.model)
            self.element_class[name] = class_name
            self.members.setdefault(class_name, set()).add(name)

    def forget(self, name: str) -> None:
        class_name = self.element_class.pop(name)
        self.members[class_name].discard(name)
        self.elements.pop(name, None)
        self.scores.pop(name, None)
        self.explanations.pop(name, None)
        old = self.place_of.get(name)
        self._move(name, None, None)
        self.contents.pop(name, None)
        self._dirty.update(n for n in (old,) if n is not None)
        self._dirty.update(next(iter(self.members[class_name]), None) for _ in (0,))  # class score again
        self._dirty.discard(None)
        if not self.members[class_name]:
            self.class_scores.pop(class_name, None)

    def items_at(self, place: str) -> set:
        index, p = self.scene.index, self.predicates
        return {
            f[1]
            for role in (p.location, p.containment, p.human_location)
            if role is not None
            for f in index.facts_of(place, role)
            if len(f) == 3 and f[2] == place
        }

    # ------------------------------------------------------------------ scores

    def rescore_all(self) -> None:
        self.scores.clear()
        self.explanations.clear()
        self.contents.clear()
        self.place_of.clear()
        if self.decided:
            self.refresh(list(self.scene.objects))

    def refresh(self, names) -> set:
        """Re-score the named elements (already described) and the places their scores count for.

        Returns the elements whose score changed and, for classes whose
        class score changed, all their members.
        """
        names = set(names) | self._dirty
        self._dirty = set()
        if not self.decided:
            return set()
        changed: set = set()
        places: set = set()
        for name in names:
            if name not in self.scene.objects:
                continue
            class_name = self.element_class[name]
            if scored_by_contents(class_name, self.model):
                places.add(name)
                continue
            element = self.elements[name]
            score, why = score_element(self.context, element, class_name)
            if self.scores.get(name) != score:
                changed.add(name)
            self.scores[name], self.explanations[name] = score, why
            old = self.place_of.get(name)
            places.update(p for p in (old, element.place) if p is not None)
            self._move(name, element.place, score)
        for place in places:
            if place in self.scene.objects and scored_by_contents(self.element_class[place], self.model):
                score = max(self.contents.get(place, {}).values(), default=0.0)
                if self.scores.get(place) != score:
                    changed.add(place)
                self.scores[place], self.explanations[place] = score, contents_explanation(score)
        classes = {self.element_class[n] for n in changed if n in self.element_class}
        classes |= {self.element_class[n] for n in names if n in self.element_class}
        for class_name in classes:
            members = self.members.get(class_name, ())
            if not members:
                self.class_scores.pop(class_name, None)
                continue
            if scored_by_contents(class_name, self.model):
                value = max((self.scores.get(m, 0.0) for m in members), default=0.0)
            else:
                value = self.context.class_relevance(class_name)
            if self.class_scores.get(class_name) != value:
                changed |= members
            self.class_scores[class_name] = value
        return changed

    def _move(self, name: str, place: str | None, score: float | None) -> None:
        old = self.place_of.pop(name, None)
        if old is not None:
            self.contents.get(old, {}).pop(name, None)
        if place is not None and score is not None:
            self.place_of[name] = place
            self.contents.setdefault(place, {})[name] = score

    @property
    def sufficient(self) -> bool:
        if not self.decided:
            return False
        unknown = len(self.members.get(UNKNOWN_CLASS, ()))
        return not unknown_share_problem(len(self.scene.objects) - unknown, len(self.scene.objects))

    def passes(self, name: str, thresholds: Thresholds) -> bool:
        """Whether the element passes the thresholds (``prune.select_relevant`` for one element)."""
        if not self.sufficient:
            return False
        class_score = self.class_scores.get(self.element_class.get(name, ""), 0.0) if self.class_scores else None
        return thresholds.admits(class_score, self.scores.get(name, 0.0))

    def result(self) -> ScoreResult:
        context = self.context
        if context.insufficiency:
            return insufficient_result(self.scene.objects, context, context.insufficiency)
        unknown = tuple(sorted(self.members.get(UNKNOWN_CLASS, ())))
        problem = unknown_share_problem(len(self.scene.objects) - len(unknown), len(self.scene.objects))
        if problem:
            return insufficient_result(self.scene.objects, context, problem)
        goal_objects = set(names_in(self.scene.goal)) & self.scene.objects.keys()
        scores, explanations = with_goal_objects(dict(self.scores), dict(self.explanations), goal_objects)
        return ScoreResult(
            "model",
            scores,
            element_class=dict(self.element_class),
            class_scores=dict(self.class_scores),
            explanations=explanations,
            unknown=unknown,
            objective=context.objective,
            task_distribution=context.distribution,
            task_entropy=context.entropy,
            understood=context.understood,
        )


class FullScores:
    """Any scorer, re-scored in full on every change (used when no incremental form exists)."""

    def __init__(self, scene: LiveScene, model: KnowledgeModel | None, options: ScoringOptions, domain_path=None):
        self.scene = scene
        self.model = model
        self.domain_path = domain_path
        self.options = options
        self._result: ScoreResult | None = None

    def set_options(self, options: ScoringOptions) -> None:
        self.options = options
        self._result = None

    def describe(self, names) -> None:
        self._result = None

    def describe_all(self) -> None:
        self._result = None

    def forget(self, name: str) -> None:
        self._result = None

    def items_at(self, place: str) -> set:
        return set()

    @property
    def sufficient(self) -> bool:
        return self.result().sufficient

    def passes(self, name: str, thresholds: Thresholds) -> bool:
        scores = self.result()
        return thresholds.admits(scores.class_score(name), scores.element_scores.get(name, 0.0))

    def refresh(self, names):
        self._result = None
        return ALL

    def result(self) -> ScoreResult:
        if self._result is None:
            task = PlanningTask(self.scene.domain, self.scene.snapshot_problem())
            self._result = score_problem(
                task, self.options, knowledge_model=self.model, domain_path=self.domain_path
            ).scores
        return self._result


def restrict(scores: ScoreResult, objects) -> ScoreResult:
    """A previous decision applied to the current objects: new objects score 0, gone ones are dropped."""
    return replace(
        scores,
        element_scores={name: scores.element_scores.get(name, 0.0) for name in objects},
        element_class={name: c for name, c in scores.element_class.items() if name in objects},
        explanations={name: e for name, e in scores.explanations.items() if name in objects},
        unknown=tuple(name for name in scores.unknown if name in objects),
    )
