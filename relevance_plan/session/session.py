"""A live scene session: events in, a determination kept current, plans kept valid.

    session = Session(domain, problem, ScoringOptions(objective="drink-at-break"))
    report = session.handle({"event": "add", "object": "mug_2", "type": "cup", "facts": [...]})
    report.triggered, report.reason, report.selection.kept, report.ask

For each event the session checks it against the scene, applies it to the
live state (``state.py``: the facts indexed as a snapshot would be), updates
the scores it can affect (``rescoring.py``) and which elements pass the
thresholds, and runs the trigger check (``triggers.py``).  When a trigger
fires, relevance is determined again on the current state: the paper's
relevant set (the elements above the thresholds and the goal's objects,
:attr:`Session.relevant`) and the first selection ``relevance-plan prune``
writes (``Scoring.first_selection``: thresholds, closure, alternatives set
aside, the reachability repair), which the session reports as kept.  The
first selection is made in full only when the event changed something it
read (``reuse.py``); otherwise the one in force is kept, on the new state,
as a fresh determination would make it.  The paper's relevance step with
its own closure and repair (:attr:`Session.determination`) is made on
demand.

When the cues are insufficient the previous selection stays in force,
marked stale, with the question to ask; a ``cue``, ``human`` or ``goal``
event that settles it resumes.  With a planner, a determination that
changes the kept set (or a new goal, or a ``plan`` event) plans again with
the one attempt loop of ``planning.attempts``; a previous plan that is still
valid on the current full state is kept without calling the planner.

The session starts no process itself: the caller passes the planner as a
function from problem text and time limit to a ``RunOutcome``.  Its only
file access is loading the knowledge model, once, when it starts.
"""

from __future__ import annotations

import itertools
import os
import tempfile
import time
import weakref
from collections.abc import Callable
from dataclasses import replace
from pathlib import Path
from typing import TYPE_CHECKING

from relevance_plan.io import Source, is_pddl_text, load_sources, write_text_atomic
from relevance_plan.pddl.formatter import format_domain
from relevance_plan.pddl.formulas import Formula
from relevance_plan.pddl.model import Domain, Problem, pinned_objects
from relevance_plan.pddl.plans import Plan
from relevance_plan.pddl.writer import write_pruned_problem
from relevance_plan.planning.attempts import AttemptLoop, run_attempts
from relevance_plan.planning.methods import Method
from relevance_plan.planning.options import PlanOptions
from relevance_plan.planning.planners.base import RunOutcome
from relevance_plan.planning.results import PlanStatus
from relevance_plan.planning.summary import RunFacts, summarise
from relevance_plan.planning.validation import validate_plan
from relevance_plan.relevance.analysis import ConstraintRule, GoalAnalysis, GoalReads, single_valued_predicates
from relevance_plan.relevance.closure import ConstraintClosure, constraint_rules
from relevance_plan.relevance.knowledge import KnowledgeModel
from relevance_plan.relevance.prune import Selection, prune_with_scores
from relevance_plan.relevance.repair import RepairReads
from relevance_plan.relevance.scorers import ScoreResult
from relevance_plan.relevance.setup import Scoring, ScoringOptions, choose_scorer, resolve_knowledge_model
from relevance_plan.relevance.task import PlanningTask
from relevance_plan.session.events import Event, EventError, check_event, parse_event_line
from relevance_plan.session.reports import Ask, EventReport, PlanReport
from relevance_plan.session.rescoring import ALL, FullScores, LiveGoalScores, LiveModelScores, restrict
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
from relevance_plan.session.state import LiveScene, SceneDelta
from relevance_plan.session.triggers import TRIGGERS, Change, Trigger, check_triggers

if TYPE_CHECKING:  # the text package is imported only when free text is given
    from relevance_plan.relevance.text.matching import WordMatch

# Runs the planner on a problem (PDDL text of the current domain) within a time limit (None: none).
RunPlanner = Callable[[str, "float | None"], RunOutcome]

__all__ = ["Ask", "EventReport", "PlanReport", "RunPlanner", "Session", "planner_in_folder"]


class Session:
    """A live scene and its relevance, kept current one event at a time (see the module docstring).

    ``domain`` and ``problem`` are values, paths or PDDL text.  Without ``run_planner``, a
    ``plan`` event runs ``plan_options.planner`` on files in a private folder the session removes
    when it is garbage-collected.
    """

    def __init__(
        self,
        domain: Domain | Source,
        problem: Problem | Source,
        options: ScoringOptions = ScoringOptions(),
        *,
        model: KnowledgeModel | None = None,
        domain_path: str | None = None,
        plan_options: PlanOptions | None = None,
        run_planner: RunPlanner | None = None,
        plan_in_loop: bool = False,
        triggers: dict[str, Trigger] | None = None,
    ):
        domain_text = str(domain) if is_pddl_text(domain) else None
        if domain_path is None and not isinstance(domain, Domain) and domain_text is None:
            domain_path = os.fspath(domain)
        domain, problem = load_sources(domain, problem)
        domain_path = domain_path or domain.path
        self.domain = domain
        self.options = options
        if model is None and options.scorer in (None, "model"):
            model = resolve_knowledge_model(domain, domain_path, options.model_path)
        self.model = model
        self.scene = LiveScene(domain, problem)
        self.scores = _live_scores(self.scene, self.model, options, domain_path)
        self.plan_options = plan_options or PlanOptions(thresholds=options.thresholds)
        self.run_planner = run_planner or planner_in_folder(self, self.plan_options, domain_path, domain_text or domain)
        self.plan_in_loop = plan_in_loop
        self.triggers = TRIGGERS if triggers is None else triggers
        self.served: str | None = None  # the human of the last 'human' event
        self.seq = 0
        # The determination in force, made with sufficient cues: the paper's relevant set and the
        # first selection (what ``prune`` writes, reported as kept), with what it read.
        self._relevant: frozenset[str] = frozenset()
        self.selection: Selection | None = None
        self.basis: SelectionBasis | None = None
        self.watched: frozenset[str] = frozenset()  # the selection's closure: what the closure triggers watch
        self._determination: tuple[int, Selection] | None = None  # the relevance step, made on demand
        self._changes = 0  # how many events changed the scene, the goal or the cues
        self.passing: set = set()
        # (functional positions, closure rules by predicate) for the trigger check
        self._rules: tuple[frozenset, dict[str, list[ConstraintRule]]] | None = None
        self._singletons = self.scene.index.singletons
        self._single_valued = single_valued_predicates(domain, self.scene.index)
        self.plan_steps: Plan | None = None
        self.planned_kept: frozenset | None = None
        self.planned_goal: Formula | None = None
        self._recount_passing()
        if not self.idle:
            self._determine()

    # ------------------------------------------------------------------ state

    @property
    def idle(self) -> bool:
        """Nobody to serve (no goal, no human): element and fact events trigger nothing."""
        return self.scene.idle_goal and self.served is None

    @property
    def kept(self) -> frozenset:
        """The first selection in force: the objects ``prune`` keeps on the current state."""
        return self.selection.kept if self.selection is not None else frozenset()

    @property
    def relevant(self) -> frozenset:
        """The paper's relevant set in force: above the thresholds (and the goal's objects), before
        the goal filter and without what closure put back."""
        return self._relevant

    @property
    def determination(self) -> Selection | None:
        """The paper's relevance step in force (thresholds, closure, and for the goal scorer the
        reachability repair: ``prune_with_scores`` with its default settings), made when asked for."""
        if self.selection is None:
            return None
        current = self._determination is not None and self._determination[0] == self._changes
        if not current and self.scores.sufficient:  # else the one in force stays, stale
            task = self._live_task(self._analysed())
            step = prune_with_scores(task, self.scores.result(), self.options.thresholds, self.model)
            self._determination = (self._changes, step)
        return self._determination[1] if self._determination is not None else None

    @property
    def sufficient(self) -> bool:
        return self.scores.sufficient

    def current_scores(self) -> ScoreResult:
        """The scores of the current state (equal to scoring it from scratch)."""
        return self.scores.result()

    def snapshot(self) -> tuple[str, str]:
        """(the current full problem, its pruned version) as PDDL text in the user's spelling."""
        problem = self.scene.read_problem()
        kept = self.kept & problem.objects.keys() if self.selection is not None else problem.objects.keys()
        return problem.text, write_pruned_problem(problem, kept)

    # ------------------------------------------------------------------ events

    def handle_line(self, line: str) -> EventReport:
        try:
            data = parse_event_line(line)
        except EventError as error:
            self.seq += 1
            return self._rejected("?", error)
        return self.handle(data)

    def handle(self, data: dict) -> EventReport:
        started = time.perf_counter()
        self.seq += 1
        if not isinstance(data, dict):
            return self._rejected("?", EventError("an event must be a JSON object"))
        kind = str(data.get("event", "?"))
        try:
            event = check_event(data, self.scene, self.model)
        except EventError as error:
            return self._rejected(kind, error)
        watched_before = self.watched
        sufficient_before = self.scores.sufficient
        functional_before, single_valued_before = self.scene.index.functional, self._single_valued
        changed, rescored, delta = self._apply(event)
        if self.scores.sufficient != sufficient_before:
            rescored = ALL
        crossed = self._update_passing(rescored)
        linked = self._linked(delta, watched_before)
        rules_changed = self._closure_rules_changed(functional_before, single_valued_before, watched_before)
        remade = rescored is ALL or bool(linked) or rules_changed or self._serves(crossed)
        read = self._read(delta, rescored, remade)
        change = Change(
            event=event,
            idle=self.idle,
            changed=changed,
            touched=self._touched(event),
            kept=watched_before,
            linked=linked,
            crossed=frozenset(crossed),
            rules_changed=rules_changed,
            read=read,
            show=self._show,
        )
        reasons = check_triggers(change, self.triggers)
        previous = self.selection
        if changed:
            self._changes += 1
        made = None
        if reasons:
            made = self._determine(remade or bool(read) or self.basis is None)
        elif changed and self.idle:
            self.basis = None  # nobody is served: the selection in force stops following the scene
        report = replace(self._report(event.kind, reasons, previous, time.perf_counter() - started), made=made)
        if event.understood is not None:
            report = self._with_cue_words(report, event.understood)
        plan = self._plan_for(event, reasons, change, previous)
        return replace(report, plan=plan) if plan is not None else report

    def _plan_for(self, event: Event, reasons: tuple, change: Change, previous: Selection | None) -> PlanReport | None:
        """The plan this event asks for: on a ``plan`` event, or (planning in the loop) after a
        determination that changed the kept set, the goal, or a fact about a kept object."""
        if event.kind == "plan":
            if self.run_planner is None:
                return PlanReport(PlanStatus.INPUT_ERROR, message="this session has no planner")
            return self.plan()
        kept_before = previous.kept if previous is not None else frozenset()
        if (
            reasons
            and self.plan_in_loop
            and self.selection is not None
            and self.sufficient
            and not self.scene.idle_goal
            and (
                self.selection.kept != self.planned_kept
                or self.scene.goal != self.planned_goal
                or change.touched & (kept_before | change.kept)
            )
        ):
            return self.plan()
        return None

    def _with_cue_words(self, report: EventReport, match: WordMatch) -> EventReport:
        """A cue in words: what it was understood as, or (not understood) the question to ask."""
        if match.chosen is not None:
            return replace(report, understood=(match,))
        options = tuple(candidate.name for candidate in match.candidates)
        return replace(report, understood=(match,), ask=Ask(match.vocabulary.value, match.insufficiency, options))

    def _rejected(self, kind: str, error: EventError) -> EventReport:
        return EventReport(
            self.seq,
            kind,
            error=error.message,
            sufficient=self.scores.sufficient,
            stale=not self.scores.sufficient and self.selection is not None,
            selection=self.selection,
            relevant_objects=self.relevant,
            spelling=self.scene.spelling,
        )

    def _show(self, name: str) -> str:
        return self.scene.spelling.object(name)

    def _touched(self, event: Event) -> frozenset:
        names = {event.name} if event.kind in ("add", "remove") else set()
        for fact in event.facts:
            names.update(fact[1:])
        if event.fluent is not None:
            names.update(event.fluent[1:])
        return frozenset(names)

    def _apply(self, event: Event) -> tuple[bool, object, SceneDelta]:
        """Change the scene; returns (whether anything changed, the elements whose scores may differ
        (``ALL``: any), what changed in the scene)."""
        scene = self.scene
        options = self.options
        if event.kind == "add":
            # check_event fills what each kind needs; the asserts only tell the type checker
            assert event.name is not None and event.type is not None and event.display is not None
            scene.add_object(event.name, event.type, event.display)
            for fact in event.facts:
                scene.set(fact)
        elif event.kind == "remove":
            assert event.name is not None
            scene.remove_object(event.name)
            if self.served == event.name:  # the human served left: their preferences and cues go too
                self.served = None
                options = replace(options, human=None, model_task=None)
        elif event.fluent is not None:
            assert event.value is not None
            scene.set_value(event.fluent, event.value)
        elif event.kind in ("set", "unset"):
            fact = event.facts[0]
            scene.set(fact) if event.kind == "set" else scene.unset(fact)
        elif event.kind == "goal":
            assert event.goal is not None
            if event.goal != scene.goal:
                scene.set_goal(event.goal)
        elif event.kind == "human":
            options = replace(options, human=event.profile, model_task=None)
            if event.name != self.served:
                self.served = event.name
                return self._rescore(scene.take_delta(), options, True)
        elif event.kind == "cue":
            if event.task is None and event.objective is None:
                return False, set(), scene.take_delta()  # words not understood: nothing changes, the report asks
            if event.task is not None:
                options = replace(options, model_task=event.task)
            else:
                options = replace(options, objective=event.objective)
            # the cue in force, said again: worth a determination only if none was made yet
            return self._rescore(scene.take_delta(), options, options == self.options and self.selection is None)
        return self._rescore(scene.take_delta(), options, False)

    def _rescore(self, delta: SceneDelta, options: ScoringOptions, served: bool) -> tuple[bool, object, SceneDelta]:
        """The scores after the scene's changes and the new options (a new goal, human or cue)."""
        rescored = self.scores.update(delta)
        if options != self.options or delta.goal:
            self.options = options
            again = self.scores.set_options(options)
            rescored = ALL if again is ALL or rescored is ALL else rescored | again
            return True, rescored, delta
        return bool(delta) or served, rescored, delta

    def _update_passing(self, rescored) -> set:
        """Update which elements pass the thresholds; returns those that crossed."""
        if rescored is ALL:
            before = set(self.passing)
            self._recount_passing()
            return before ^ self.passing
        crossed = set()
        thresholds = self.options.thresholds
        for name in set(rescored) | (self.passing - self.scene.objects.keys()):
            now = name in self.scene.objects and self.scores.passes(name, thresholds)
            if now != (name in self.passing):
                crossed.add(name)
                (self.passing.add if now else self.passing.discard)(name)
        return crossed

    def _recount_passing(self) -> None:
        thresholds = self.options.thresholds
        if self.scores.sufficient:
            self.passing = {n for n in self.scene.objects if self.scores.passes(n, thresholds)}
        else:
            self.passing = set()

    def _serves(self, crossed) -> bool:
        """Whether an element that crossed the thresholds can enter the first selection (the goal
        filter leaves out what no action toward the goal can use)."""
        if not crossed:
            return False
        if self.selection is None or not self.options.goal_filter:
            return True
        task = self.selection.task
        domain, roles = task.typing.domain, task.goal_analysis.role_depth
        goal = task.goal_objects
        types = self.scene.objects
        return any(
            name in goal or name not in types or any(t in roles for t in domain.ancestors(types[name]))
            for name in crossed
        )

    def _linked(self, delta: SceneDelta, watched: frozenset) -> frozenset:
        """Watched objects from which closure follows a fact that came or went (a plate put on the kept cup)."""
        if not watched or not delta.atoms:
            return frozenset()
        functional = self.scene.index.functional
        if self._rules is None or self._rules[0] != functional:
            by_predicate: dict[str, list[ConstraintRule]] = {}
            for rule in constraint_rules(self.domain, self.scene.index, self.model):
                by_predicate.setdefault(rule.predicate, []).append(rule)
            self._rules = (functional, by_predicate)
        rules = self._rules[1]
        return frozenset(
            atom[1 + rule.when_kept]
            for atom in delta.atoms
            for rule in rules.get(atom[0], ())
            if len(atom) > 1 + rule.when_kept and atom[1 + rule.when_kept] in watched
        )

    def _closure_rules_changed(
        self, functional_before: frozenset, single_valued_before: frozenset, watched: frozenset
    ) -> bool:
        """Whether closure from ``watched`` could follow other facts now: a single-valued predicate
        came or went, or a predicate became (or stopped being) functional at a position where
        some fact has a watched object."""
        index = self.scene.index
        if index.singletons != self._singletons:
            self._singletons = index.singletons
            self._single_valued = single_valued_predicates(self.domain, index)
        if self._single_valued != single_valued_before:
            return True
        for predicate, key, _ in index.functional ^ functional_before:
            for name in watched:
                if any(fact[1 + key] == name for fact in index.facts_of(name, predicate)):
                    return True
        return False

    def _read(self, delta: SceneDelta, rescored, remade: bool) -> str:
        """What the event changed that the first selection in force read ("" when nothing, or
        when the closure's and the thresholds' checks already say it is to be made again)."""
        basis = self.basis
        if basis is None or remade:
            return ""
        if analysis_read(basis, self.scene, delta):
            now = self._analysed() or analyse_now(self.scene)
            if now[0].role_depth != basis.analysed[0].role_depth:  # what pruning reads of it
                return "the goal's roles changed"
            self.basis = basis = replace(basis, analysed=now, goal_shape=goal_shape(now[1], self.scene.index))
        scores = frozenset(rescored)
        if scores & self.watched:
            return f"the score of {', '.join(sorted(self._show(n) for n in scores & self.watched)[:5])} changed"
        return selection_read(basis, self.scene, EventChanges(delta, scores, self.scene.spelling))

    # ------------------------------------------------------------------ determination

    def _determine(self, full: bool = True) -> bool | None:
        """The relevant set and the first selection on the current state, if the cues suffice: the
        selection in force kept (on the new state) unless ``full``; returns whether it was made
        again (None: the cues do not suffice)."""
        scores = self.scores.result()
        if not scores.sufficient:
            self.basis = None  # the previous selection stays in force, stale: the next one is made in full
            return None
        problem = self.scene.snapshot_problem()
        self._relevant = pinned_objects(problem, self.domain) | frozenset(self.passing)
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

        task = replace(self._live_task(self._analysed()), repair_observer=observe)
        # what passes the thresholds is kept up to date event by event: the selection need not look at every object
        scores.passing.setdefault(self.options.thresholds, frozenset(self.passing))
        self.selection = Scoring(task, self.model, scores, self.options).first_selection()
        closure = ConstraintClosure.of(task, self.model)
        self.basis = selection_basis(task, self.selection, reads[-1] if reads else None, closure)
        self.watched = closure(self.selection.selected | self.selection.set_aside)[0] | self.selection.kept
        return True

    def _live_task(self, analysed: tuple[GoalAnalysis, GoalReads] | None) -> LiveTask:
        """The current state as a task (``analysed``: the goal's analysis, when held already)."""
        return LiveTask(self.domain, self.scene.snapshot_problem(), live_index=self.scene.index, analysed=analysed)

    def _analysed(self) -> tuple[GoalAnalysis, GoalReads] | None:
        """The goal's analysis of the current state, when the scores hold it already."""
        scores = self.scores
        if isinstance(scores, LiveGoalScores):
            return scores.analysis, scores.reads
        return None

    def _report(self, kind: str, reasons: tuple, previous: Selection | None, seconds: float) -> EventReport:
        scores = self.scores
        result = scores.result() if not scores.sufficient else None
        before = previous.kept if previous is not None else frozenset()
        now = self.kept
        asking = (reasons or not scores.sufficient) and not self.idle
        return EventReport(
            seq=self.seq,
            event=kind,
            triggered=bool(reasons),
            reasons=reasons,
            sufficient=scores.sufficient,
            insufficiency=result.insufficiency if result is not None else "",
            stale=not scores.sufficient and self.selection is not None,
            selection=self.selection,
            relevant_objects=self.relevant,
            added=tuple(sorted(now - before)) if reasons else (),
            dropped=tuple(sorted(before - now)) if reasons else (),
            ask=self.ask() if asking else None,
            seconds=seconds,
            spelling=self.scene.spelling,
            understood=self._understood() if reasons else (),
        )

    def _understood(self) -> tuple:
        """What the free text in force (``--objective`` or ``--task`` in words) was taken for."""
        context = getattr(self.scores, "context", None)  # the live knowledge model's, without a full result
        if context is not None:
            return context.understood
        return () if isinstance(self.scores, LiveGoalScores) else self.scores.result().understood

    def ask(self, scores: ScoreResult | None = None) -> Ask | None:
        """The question for the human: the missing cue, or (without recorded preferences) which kinds."""
        model = self.model
        if model is None:
            return None
        scores = scores or self.scores.result()
        if not scores.sufficient:
            unclear = [m for m in scores.understood if m.chosen is None and m.vocabulary.value != "class"]
            if unclear:  # --objective or --task in words the model did not understand
                options = tuple(candidate.name for candidate in unclear[0].candidates)
                return Ask(unclear[0].vocabulary.value, unclear[0].insufficiency, options)
            if scores.objective is None:
                return Ask("objective", "What would you like to do?", tuple(model.objectives))
            if scores.task_entropy is not None and scores.task_entropy > model.entropy_bound:
                ranked = sorted(scores.task_distribution.items(), key=lambda item: (-item[1], item[0]))
                tasks = tuple(name for name, _ in ranked)
                return Ask("task", "Which would you like: " + ", ".join(tasks) + "?", tasks)
            return Ask("model", scores.insufficiency)
        if self.options.human is not None or self.selection is None or scores.scorer != "model":
            return None
        from relevance_plan.relevance.metrics import plan_inquiries
        from relevance_plan.relevance.scene import kind_of

        structural = {c.name for c in model.classes.values() if c.fixed_relevance is not None or c.from_contents}
        selected = self.relevant
        found = plan_inquiries(scores, selected, {n: kind_of(n) for n in selected}, structural)
        if not found.optional:
            return None
        return Ask("preference", "Which do you prefer: " + ", ".join(found.optional) + "?", found.optional)

    # ------------------------------------------------------------------ planning

    def plan(self) -> PlanReport:
        """A plan for the current state: the previous one if still valid, else the attempt loop."""
        if self.run_planner is None:
            return PlanReport(PlanStatus.INPUT_ERROR, message="this session has no planner")
        started = time.perf_counter()
        options = self.plan_options
        problem = self.scene.read_problem()
        task = PlanningTask(self.domain, problem)
        if self.plan_steps is not None:
            validation = validate_plan(self.domain, problem, self.plan_steps, options.validators)
            if validation.valid:
                self._planned(self.plan_steps)
                return PlanReport(
                    PlanStatus.SOLVED,
                    self.plan_steps,
                    "previous",
                    f"previous plan still valid on the current state ({validation.validator})",
                )
        selection = None
        scorer = None
        if self.selection is None and self.scores.sufficient:
            self._determine()  # an idle session holds no determination yet
        if options.method.prunes:
            if self.selection is None:
                return PlanReport(PlanStatus.INSUFFICIENT_CUES, message=self.scores.result().insufficiency)
            scores = self.scores.result()
            if not scores.sufficient:  # plan with the selection in force (stale)
                scores = restrict(self.selection.scores, problem.objects)
            scorer = scores.scorer
            selection = self._selection_on(task, scores, options)
        relevance_time = time.perf_counter() - started

        def call_planner(objects: Selection | None, limit: float | None) -> RunOutcome:
            return self.run_planner(problem.text if objects is None else objects.text, limit)

        attempts, widening = run_attempts(AttemptLoop(task, call_planner, options, started, self.model), selection)
        planner = attempts[0].outcome.planner if attempts else options.planner
        facts = RunFacts(task, started, relevance_time + widening, selection, planner=planner, scorer=scorer)
        result = summarise(facts, options, attempts)
        if result.status is PlanStatus.SOLVED:
            self._planned(result.plan)
        return PlanReport(result.status, result.plan, "planner", result.message, result)

    def _selection_on(self, task: PlanningTask, scores: ScoreResult, options: PlanOptions) -> Selection:
        """The first selection the attempt loop starts from, on ``task`` (the current state read back
        from its text): the one in force when the plan's options make the same one (the same scores,
        thresholds and narrowing), else made again."""
        scoring = Scoring(task, self.model, scores, options.scoring)
        same = (scoring.options.thresholds, scoring.options.goal_filter, scoring.options.prefer_free) == (
            self.options.thresholds,
            self.options.goal_filter,
            self.options.prefer_free,
        )
        selection = self.selection
        if (
            selection is None
            or self.basis is None  # stale, or made before the scene changed
            or not same
            or scoring.options.economical != self.options.economical
            or not options.narrows_first
            or not scores.sufficient
        ):
            return scoring.first_selection(options.narrows_first)
        problem = task.problem
        text = problem.text if selection.unpruned_reason else write_pruned_problem(problem, selection.kept)
        return replace(selection, task=task, scores=scores, text=text)

    def _planned(self, steps: Plan) -> None:
        self.plan_steps = steps
        self.planned_kept = self.kept
        self.planned_goal = self.scene.goal


def _live_scores(
    scene: LiveScene, model: KnowledgeModel | None, options: ScoringOptions, domain_path: str | None
) -> LiveModelScores | LiveGoalScores | FullScores:
    """The live form of the scorer the options choose (the knowledge model's, the goal's), else
    the scorer re-run in full on every change."""
    scorer = choose_scorer(Method.RELEVANCE.value, model, options.scorer)
    # placing unknown kinds (--place-kinds) is the scorer's own step: scored in full on each change
    if scorer == "model" and model is not None and not options.place_kinds:
        return LiveModelScores(scene, model, options)
    if scorer == "goal" and options.learned_model_path is None:
        return LiveGoalScores(scene)
    return FullScores(scene, model, options, domain_path)


def planner_in_folder(owner: object, options: PlanOptions, domain_path: str | None, domain: str | Domain) -> RunPlanner:
    """A planner call that writes each problem into a private folder, removed with ``owner``
    (the domain too, from its text, when it has no file); each problem file goes once planned."""
    from relevance_plan.planning.planners.registry import make_planner

    folder = tempfile.TemporaryDirectory(prefix="relevance-plan-session-")
    weakref.finalize(owner, folder.cleanup)
    if domain_path is None:
        domain_path = str(
            write_text_atomic(
                Path(folder.name) / "domain.pddl", domain if isinstance(domain, str) else format_domain(domain)
            )
        )
    runs = itertools.count(1)

    def run(text: str, limit: float | None) -> RunOutcome:
        planner = make_planner(options.planner, options.planner_config)
        path = write_text_atomic(Path(folder.name) / f"problem-{next(runs)}.pddl", text)
        try:
            return planner.run(str(domain_path), str(path), time_limit=limit, memory_limit_mb=options.memory_limit_mb)
        finally:
            path.unlink(missing_ok=True)

    return run
