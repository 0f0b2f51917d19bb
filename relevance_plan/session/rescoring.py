"""Scores kept current event by event: each scorer's live form takes what an event changed
(``state.SceneDelta``) and says whose scores may differ.

:class:`LiveModelScores` follows the knowledge-model scorer stage by stage
(``scorers/knowledge_model.py``: context, one element, contents) and re-scores only
the elements an event can affect: the objects a fact names, the items of a
place that was opened or where a human stands, a place whose contents
changed.  Its :meth:`~LiveModelScores.result` equals ``score_by_knowledge_model`` on
the current state.

:class:`LiveGoalScores` follows the goal scorer (``scorers/goal.py``): the goal's
analysis is kept while no fact it read changes (``goal_regression.GoalReads``); an
object's score changes only when it is added, when it comes to share a fact
with a goal object or stops, when its role's number of candidates crosses
the populous mark (or changes while past it), or, for a populous role's
candidates, when the links that give their hops from the goal change.

:class:`FullScores` is the fallback for every other scorer (random,
learned, oracle): each change re-scores everything through
``relevance.setup.score_problem``.
"""

from __future__ import annotations

from dataclasses import replace

from relevance_plan.pddl.formulas import names_in
from relevance_plan.pddl.model import goal_objects
from relevance_plan.relevance.analysis.distances import graph_distances
from relevance_plan.relevance.analysis.goal_regression import GoalAnalysis, GoalReads, analyse_goal_reading
from relevance_plan.relevance.analysis.task import PlanningTask, hub_degree
from relevance_plan.relevance.analysis.types import InferredTypes, infer_types
from relevance_plan.relevance.scoring.knowledge import KnowledgeModel
from relevance_plan.relevance.scoring.scene import Element, build_scene
from relevance_plan.relevance.scoring.scorers import ScoreRequest, ScoreResult
from relevance_plan.relevance.scoring.scorers.goal import POPULOUS, goal_neighbours, goal_score, role_candidates
from relevance_plan.relevance.scoring.scorers.knowledge_model import (
    UNKNOWN_CLASS,
    KnowledgeContext,
    class_of,
    contents_explanation,
    insufficient_result,
    knowledge_context,
    score_element,
    scored_by_contents,
    scored_result,
    unknown_share_problem,
    with_goal_objects,
)
from relevance_plan.relevance.selection.prune import Thresholds
from relevance_plan.relevance.setup import ScoringOptions, score_problem
from relevance_plan.session.state import LiveScene, SceneDelta

ALL = None  # "every element may have changed"


def request_for(options: ScoringOptions, model: KnowledgeModel | None) -> ScoreRequest:
    """The request ``score_problem`` builds from the options (no oracle in a live session)."""
    return ScoreRequest(
        knowledge_model=model,
        objective=options.objective,
        activity=options.activity,
        human=options.human,
        seed=options.seed,
        place_kinds=options.place_kinds,
    )


class LiveModelScores:
    """The knowledge-model scorer kept current (see the module's docstring)."""

    scorer = "model"

    def __init__(self, scene: LiveScene, model: KnowledgeModel, options: ScoringOptions):
        self.scene = scene
        self._result: ScoreResult | None = None
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

    def set_options(self, options: ScoringOptions):
        """A new goal, human or cue: a new context, and every score again (returns ``ALL``)."""
        self.context = knowledge_context(self.scene.goal, request_for(options, self.model))
        self.rescore_all()
        return ALL

    def update(self, delta: SceneDelta):
        """Re-score what the scene's changes can affect; returns the elements whose score may differ
        (``ALL``: any)."""
        self._result = None
        if delta.goal:
            return ALL  # the caller sets the options again: a new goal is a new context
        for name in delta.objects_removed:
            self.forget(name)
        names = self._affected(delta.atoms) | set(delta.objects_added)
        names.update(arg for fluent in delta.values for arg in fluent[1:])
        names = {n for n in names if n in self.scene.objects}
        self.describe(names)
        return self.refresh(names)

    def _affected(self, facts) -> set:
        """Objects whose description a change of these facts can alter: the objects they name, and
        the items of a place opened (or where a human stands)."""
        names: set = set()
        predicates = self.predicates
        for fact in facts:
            names.update(fact[1:])
            if fact[0] in (predicates.access, predicates.human_location) and len(fact) > 1:
                names |= self.items_at(fact[-1])
        return names

    @property
    def decided(self) -> bool:
        return not self.context.insufficiency

    # ------------------------------------------------------------------ descriptions

    def describe_all(self) -> None:
        # in the written state's order (facts sorted): an object in two places reads the same first one
        facts = sorted(self.scene.facts)
        scene = build_scene(self.scene.domain, self.scene.objects, facts, self.predicates)
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
        scene = build_scene(self.scene.domain, described, sorted(facts), p, types=self.scene.objects)
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
        self._result = None
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
        """The scores of the current state, as ``score_by_knowledge_model`` gives them (the same value
        until something changes)."""
        if self._result is None:
            self._result = self._make_result()
        return self._result

    def _make_result(self) -> ScoreResult:
        context = self.context
        if context.insufficiency:
            return insufficient_result(self.scene.objects, context, context.insufficiency)
        unknown = tuple(sorted(self.members.get(UNKNOWN_CLASS, ())))
        problem = unknown_share_problem(len(self.scene.objects) - len(unknown), len(self.scene.objects))
        if problem:
            return insufficient_result(self.scene.objects, context, problem)
        named = set(names_in(self.scene.goal)) & self.scene.objects.keys()
        scores, explanations = with_goal_objects(dict(self.scores), dict(self.explanations), named)
        return scored_result(context, scores, dict(self.element_class), dict(self.class_scores), explanations, unknown)


class LiveGoalScores:
    """The goal scorer kept current (see the module's docstring); :meth:`result` equals
    ``score_by_goal`` on the current state."""

    scorer = "goal"
    sufficient = True  # the goal scorer always decides

    def __init__(self, scene: LiveScene):
        self.scene = scene
        self.scores: dict[str, float] = {}
        self.explanations: dict[str, str] = {}
        self.alternatives: set[str] = set()
        self._result: ScoreResult | None = None
        self.rescore_all()

    # ------------------------------------------------------------------ the goal's analysis

    def rescore_all(self) -> None:
        """A new analysis of the goal, and every object's score again."""
        self._analyse()
        self._rescore_all()

    def _analyse(self) -> None:
        scene = self.scene
        self.typing: InferredTypes = infer_types(scene.domain, scene.snapshot_problem(), scene.index.by_predicate)
        self.analysis: GoalAnalysis
        self.reads: GoalReads
        self.analysis, self.reads = analyse_goal_reading(self.typing.domain, self.typing.problem, scene.index)
        self._role_shape = self._roles_read()

    def _rescore_all(self) -> None:
        scene = self.scene
        problem = scene.snapshot_problem()
        self.goal_objects = goal_objects(problem, scene.domain)
        self.neighbours = self._neighbours()
        self.candidates = role_candidates(self.typing.domain, self.analysis.role_depth, self._types().values())
        self._distance: dict[str, int] | None = None
        self._result = None
        self.scores.clear()
        self.explanations.clear()
        self.alternatives.clear()
        # An object the goal does not name and that shares no fact with a goal object scores as its
        # type does, unless a role of its type is populous (then its hops count): score each type once.
        special = self.goal_objects | self.neighbours.keys()
        populous = {role for role, count in self.candidates.items() if count > POPULOUS}
        ancestors = self.typing.domain.ancestors
        by_type: dict[str, str] = {}  # type -> an object that scored for it
        for name, type_name in self._types().items():
            first = by_type.get(type_name)
            if first is None or name in special:
                self._score(name)
                if name not in special and populous.isdisjoint(ancestors(type_name)):
                    by_type[type_name] = name
            else:
                self.scores[name], self.explanations[name] = self.scores[first], self.explanations[first]

    def _types(self):
        """Each object's type, as the scorer reads it (an untyped domain's inferred classes)."""
        return self.typing.problem.objects if self.typing.inferred else self.scene.objects

    def _roles_read(self) -> tuple[frozenset, frozenset]:
        """The single-fact and functional predicates among those that decided the goal's roles."""
        index, predicates = self.scene.index, self.reads.role_predicates
        return (
            frozenset(p for p in index.singletons if p in predicates),
            frozenset(f for f in index.functional if f[0] in predicates),
        )

    def _neighbours(self) -> dict[str, str]:
        index, spelling = self.scene.index, self.scene.spelling
        return goal_neighbours(index.by_object, self.goal_objects, self.analysis.relevant_predicates, spelling)

    def _distances(self) -> dict[str, int]:
        """Hops from the goal's objects (``PlanningTask.goal_distance``), found when first needed."""
        if self._distance is None:
            hub = hub_degree(len(self.scene.objects))
            # as ``distances.object_distances``, on the links the live index keeps across events
            index = self.scene.index
            self._distance = graph_distances(index, index.object_graph(None), self.goal_objects, hub)
        return self._distance

    def _score(self, name: str) -> bool:
        """Score one object again; whether its score or its being an alternative changed."""
        score, why, populous = goal_score(
            self.typing.domain,
            self.analysis.role_depth,
            self.candidates,
            self._distances,
            name,
            self._types()[name],
            self.goal_objects,
            self.neighbours,
        )
        changed = self.scores.get(name) != score or (name in self.alternatives) != populous
        self.scores[name], self.explanations[name] = score, why
        (self.alternatives.add if populous else self.alternatives.discard)(name)
        return changed

    # ------------------------------------------------------------------ events

    def set_options(self, options: ScoringOptions) -> set:
        """The human and the cues do not enter the goal scorer: nothing changes."""
        return set()

    def update(self, delta: SceneDelta):
        """Score again what the scene's changes can affect; returns the objects whose score (or
        being an alternative) changed, or ``ALL``."""
        if not delta:
            return set()
        scene = self.scene
        if delta.goal or self.typing.inferred:  # a fact or an object can change the inferred classes
            self.rescore_all()
            return ALL
        domain, index = self.typing.domain, scene.index
        if self.reads.answers_change(domain, scene.type_of, index, delta.added, delta.removed) or (
            delta.atoms and self._roles_read() != self._role_shape
        ):
            before = self.analysis
            self._analyse()  # it read what changed: only analysing again tells whether it still holds
            if self.analysis != before:
                self._rescore_all()
                return ALL
        changed: set = set()
        for name in delta.objects_removed:
            self.scores.pop(name, None)
            self.explanations.pop(name, None)
            self.alternatives.discard(name)
            changed.add(name)
        changed |= self._recount(delta)
        if any(
            atom[0] in self.analysis.relevant_predicates and not self.goal_objects.isdisjoint(atom[1:])
            for atom in delta.atoms
        ):
            shared, self.neighbours = self.neighbours, self._neighbours()
            changed |= {n for n in shared.keys() ^ self.neighbours.keys() if n in scene.objects}
            changed |= {n for n in shared.keys() & self.neighbours.keys() if shared[n] != self.neighbours[n]}
        changed |= self._redistance(delta)
        for name in set(delta.objects_added) | changed:
            if name in scene.objects and self._score(name):
                changed.add(name)
        if changed:
            self._result = None
        return changed

    def _recount(self, delta: SceneDelta) -> set:
        """New role counts after objects came or went; the candidates of each role whose count changed
        while populous, or that became or stopped being populous (their explanations name the count)."""
        if not (delta.objects_added or delta.objects_removed) or not self.candidates:
            return set()
        before = self.candidates
        self.candidates = role_candidates(self.typing.domain, self.analysis.role_depth, self._types().values())
        roles = {
            role
            for role in before.keys() | self.candidates.keys()
            if before.get(role, 0) != self.candidates.get(role, 0)
            and max(before.get(role, 0), self.candidates.get(role, 0)) > POPULOUS
        }
        if not roles:
            return set()
        ancestors = self.typing.domain.ancestors
        return {name for name, type_name in self._types().items() if not roles.isdisjoint(ancestors(type_name))}

    def _redistance(self, delta: SceneDelta) -> set:
        """Hops from the goal again when a link came or went (or the scene's size moved the hub mark);
        the populous roles' candidates whose hops changed."""
        if self._distance is None:
            return set()
        if not (delta.objects_added or delta.objects_removed or any(len(atom) > 2 for atom in delta.atoms)):
            return set()
        before, self._distance = self._distance, None
        after = self._distances()
        populous = {role for role, count in self.candidates.items() if count > POPULOUS}
        ancestors = self.typing.domain.ancestors
        return {
            name
            for name, type_name in self._types().items()
            if before.get(name) != after.get(name) and not populous.isdisjoint(ancestors(type_name))
        }

    # ------------------------------------------------------------------ views

    def passes(self, name: str, thresholds: Thresholds) -> bool:
        """Whether the object passes the thresholds (``prune.select_relevant`` for one object)."""
        return thresholds.admits(None, self.scores.get(name, 0.0))

    def result(self) -> ScoreResult:
        if self._result is None:
            types = self._types()
            self._result = ScoreResult(
                "goal",
                dict(self.scores),
                element_class=dict(types),  # every object is scored
                explanations=dict(self.explanations),
                alternatives=frozenset(self.alternatives),
            )
        return self._result


class FullScores:
    """Any scorer, re-scored in full on every change (used when no live form exists)."""

    def __init__(self, scene: LiveScene, model: KnowledgeModel | None, options: ScoringOptions, domain_path=None):
        self.scene = scene
        self.model = model
        self.domain_path = domain_path
        self.options = options
        self._result: ScoreResult | None = None

    @property
    def scorer(self) -> str:
        return self.result().scorer

    def set_options(self, options: ScoringOptions):
        self.options = options
        self._result = None
        return ALL

    def update(self, delta: SceneDelta):
        if not delta:
            return set()
        self._result = None
        return ALL

    def items_at(self, place: str) -> set:
        return set()

    @property
    def sufficient(self) -> bool:
        return self.result().sufficient

    def passes(self, name: str, thresholds: Thresholds) -> bool:
        scores = self.result()
        return thresholds.admits(scores.class_score(name), scores.element_scores.get(name, 0.0))

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
