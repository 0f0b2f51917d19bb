"""Determining relevance on the live scene: the relevant set and the first selection in force.

:class:`Determination` holds the determination in force, made with
sufficient cues: the paper's relevant set (the elements above the thresholds
and the goal's objects) and the first selection ``relevance-plan prune``
writes, with what it read (``reuse.py``) and the closure it watches.  It
says whether an event changed anything the selection read, makes the
selection again (in full, or the one in force kept on the new state), makes
the paper's relevance step on demand, and asks the human what the scores
lack.
"""

from __future__ import annotations

from dataclasses import replace

from relevance_plan.pddl.model import Domain, pinned_objects
from relevance_plan.relevance.analysis.constraint_rules import ConstraintRule, single_valued_predicates
from relevance_plan.relevance.analysis.goal_regression import GoalAnalysis, GoalReads
from relevance_plan.relevance.scoring.knowledge import KnowledgeModel
from relevance_plan.relevance.scoring.scorers import ScoreResult
from relevance_plan.relevance.selection.closure import ConstraintClosure, constraint_rules
from relevance_plan.relevance.selection.prune import Selection, prune_with_scores
from relevance_plan.relevance.selection.repair import RepairReads
from relevance_plan.relevance.setup import Scoring
from relevance_plan.session.reports import Ask
from relevance_plan.session.rescoring import LiveGoalScores
from relevance_plan.session.reuse import (
    EventChanges,
    LiveTask,
    SelectionBasis,
    analyse_now,
    analysis_read,
    goal_shape,
    selection_basis,
    selection_read,
)
from relevance_plan.session.state import SceneDelta
from relevance_plan.session.updates import SceneUpdates


class Determination:
    """The relevant set and the first selection in force on the scene ``updates`` keeps current."""

    def __init__(self, domain: Domain, model: KnowledgeModel | None, updates: SceneUpdates):
        self.domain = domain
        self.model = model
        self.updates = updates
        self.relevant: frozenset[str] = frozenset()
        self.selection: Selection | None = None
        self.basis: SelectionBasis | None = None
        self.watched: frozenset[str] = frozenset()  # the selection's closure: what the closure triggers watch
        self.changes = 0  # how many events changed the scene, the goal or the cues
        self._step: tuple[int, Selection] | None = None  # the paper's relevance step, made on demand
        # (functional positions, closure rules by predicate) for the trigger check
        self._rules: tuple[frozenset, dict[str, list[ConstraintRule]]] | None = None
        index = updates.scene.index
        self._singletons = index.singletons
        self.single_valued = single_valued_predicates(domain, index)

    @property
    def kept(self) -> frozenset:
        """The first selection in force: the objects ``prune`` keeps on the current state."""
        return self.selection.kept if self.selection is not None else frozenset()

    def paper_step(self) -> Selection | None:
        """The paper's relevance step in force (thresholds, closure, and for the goal scorer the
        reachability repair: ``prune_with_scores`` with its default settings), made when asked for."""
        if self.selection is None:
            return None
        scores = self.updates.scores
        current = self._step is not None and self._step[0] == self.changes
        if not current and scores.sufficient:  # else the one in force stays, stale
            task = self.live_task(self.analysed())
            step = prune_with_scores(task, scores.result(), self.updates.options.thresholds, self.model)
            self._step = (self.changes, step)
        return self._step[1] if self._step is not None else None

    def determine(self, full: bool = True) -> bool | None:
        """The relevant set and the first selection on the current state, if the cues suffice: the
        selection in force kept (on the new state) unless ``full``; returns whether it was made
        again (None: the cues do not suffice)."""
        updates = self.updates
        scores = updates.scores.result()
        if not scores.sufficient:
            self.basis = None  # the previous selection stays in force, stale: the next one is made in full
            return None
        problem = updates.scene.snapshot_problem()
        self.relevant = pinned_objects(problem, self.domain) | frozenset(updates.passing)
        if not full and self.basis is not None and self.selection is not None:
            previous = self.selection.task
            assert isinstance(previous, LiveTask)
            task = replace(previous, problem=problem, analysed=self.basis.analysed, repair_observer=None)
            self.selection = replace(self.selection, task=task, scores=scores)
            self.basis = replace(self.basis, selection=self.selection)
            return False
        reads: list[RepairReads] = []

        def observe(kept: frozenset, repaired: object, read: RepairReads) -> None:
            reads.append(read)

        task = replace(self.live_task(self.analysed()), repair_observer=observe)
        # what passes the thresholds is kept up to date event by event: the selection need not look at every object
        scores.passing.setdefault(updates.options.thresholds, frozenset(updates.passing))
        self.selection = Scoring(task, self.model, scores, updates.options).first_selection()
        closure = ConstraintClosure.of(task, self.model)
        self.basis = selection_basis(task, self.selection, reads[-1] if reads else None, closure)
        self.watched = closure(self.selection.selected | self.selection.set_aside)[0] | self.selection.kept
        return True

    def live_task(self, analysed: tuple[GoalAnalysis, GoalReads] | None) -> LiveTask:
        """The current state as a task (``analysed``: the goal's analysis, when held already)."""
        scene = self.updates.scene
        return LiveTask(self.domain, scene.snapshot_problem(), live_index=scene.index, analysed=analysed)

    def analysed(self) -> tuple[GoalAnalysis, GoalReads] | None:
        """The goal's analysis of the current state, when the scores hold it already."""
        scores = self.updates.scores
        if isinstance(scores, LiveGoalScores):
            return scores.analysis, scores.reads
        return None

    # ------------------------------------------------------------------ what an event changed

    def serves(self, crossed) -> bool:
        """Whether an element that crossed the thresholds can enter the first selection (the goal
        filter leaves out what no action toward the goal can use)."""
        if not crossed:
            return False
        if self.selection is None or not self.updates.options.goal_filter:
            return True
        task = self.selection.task
        domain, roles = task.typing.domain, task.goal_analysis.role_depth
        goal = task.goal_objects
        types = self.updates.scene.objects
        return any(
            name in goal or name not in types or any(t in roles for t in domain.ancestors(types[name]))
            for name in crossed
        )

    def linked(self, delta: SceneDelta, watched: frozenset) -> frozenset:
        """Watched objects from which closure follows a fact that came or went (a plate put on the kept cup)."""
        if not watched or not delta.atoms:
            return frozenset()
        index = self.updates.scene.index
        functional = index.functional
        if self._rules is None or self._rules[0] != functional:
            by_predicate: dict[str, list[ConstraintRule]] = {}
            for rule in constraint_rules(self.domain, index, self.model):
                by_predicate.setdefault(rule.predicate, []).append(rule)
            self._rules = (functional, by_predicate)
        rules = self._rules[1]
        return frozenset(
            atom[1 + rule.when_kept]
            for atom in delta.atoms
            for rule in rules.get(atom[0], ())
            if len(atom) > 1 + rule.when_kept and atom[1 + rule.when_kept] in watched
        )

    def closure_rules_changed(
        self, functional_before: frozenset, single_valued_before: frozenset, watched: frozenset
    ) -> bool:
        """Whether closure from ``watched`` could follow other facts now: a single-valued predicate
        came or went, or a predicate became (or stopped being) functional at a position where
        some fact has a watched object."""
        index = self.updates.scene.index
        if index.singletons != self._singletons:
            self._singletons = index.singletons
            self.single_valued = single_valued_predicates(self.domain, index)
        if self.single_valued != single_valued_before:
            return True
        for predicate, key, _ in index.functional ^ functional_before:
            for name in watched:
                if any(fact[1 + key] == name for fact in index.facts_of(name, predicate)):
                    return True
        return False

    def read(self, delta: SceneDelta, rescored, remade: bool) -> str:
        """What the event changed that the first selection in force read ("" when nothing, or
        when the closure's and the thresholds' checks already say it is to be made again)."""
        basis = self.basis
        if basis is None or remade:
            return ""
        scene = self.updates.scene
        if analysis_read(basis, scene, delta):
            now = self.analysed() or analyse_now(scene)
            if now[0].role_depth != basis.analysed[0].role_depth:  # what pruning reads of it
                return "the goal's roles changed"
            self.basis = basis = replace(basis, analysed=now, goal_shape=goal_shape(now[1], scene.index))
        scores = frozenset(rescored)
        if scores & self.watched:
            shown = sorted(scene.spelling.object(n) for n in scores & self.watched)[:5]
            return f"the score of {', '.join(shown)} changed"
        return selection_read(basis, scene, EventChanges(delta, scores, scene.spelling))

    # ------------------------------------------------------------------ what to ask

    def ask(self, scores: ScoreResult | None = None) -> Ask | None:
        """The question for the human: the missing cue, or (without recorded preferences) which kinds."""
        model = self.model
        if model is None:
            return None
        scores = scores or self.updates.scores.result()
        if not scores.sufficient:
            unclear = [m for m in scores.understood if m.chosen is None and m.vocabulary.value != "class"]
            if unclear:  # --objective or --activity in words the model did not understand
                options = tuple(candidate.name for candidate in unclear[0].candidates)
                return Ask(unclear[0].vocabulary.value, unclear[0].insufficiency, options)
            if scores.objective is None:
                return Ask("objective", "What would you like to do?", tuple(model.objectives))
            if scores.activity_entropy is not None and scores.activity_entropy > model.entropy_bound:
                ranked = sorted(scores.activity_distribution.items(), key=lambda item: (-item[1], item[0]))
                activities = tuple(name for name, _ in ranked)
                return Ask("activity", "Which would you like: " + ", ".join(activities) + "?", activities)
            return Ask("model", scores.insufficiency)
        if self.updates.options.human is not None or self.selection is None or scores.scorer != "model":
            return None
        from relevance_plan.relevance.scoring.metrics import plan_inquiries
        from relevance_plan.relevance.scoring.scene import kind_of

        structural = {c.name for c in model.classes.values() if c.fixed_relevance is not None or c.from_contents}
        selected = self.relevant
        found = plan_inquiries(scores, selected, {n: kind_of(n) for n in selected}, structural)
        if not found.optional:
            return None
        return Ask("preference", "Which do you prefer: " + ", ".join(found.optional) + "?", found.optional)
