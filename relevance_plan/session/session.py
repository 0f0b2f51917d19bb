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

The session is a thin front over three collaborators, one per
responsibility: :class:`~relevance_plan.session.updates.SceneUpdates`
applies the events (the scene, the options they set, the scores, what
passes the thresholds), :class:`~relevance_plan.session.determination.Determination`
determines relevance (the selection in force, what it read, what to ask),
and :class:`~relevance_plan.session.planning.SessionPlanner` plans.

The session starts no process itself: the caller passes the planner as a
function from problem text and time limit to a ``RunOutcome``.  Its only
file access is loading the knowledge model, once, when it starts.
"""

from __future__ import annotations

import os
import time
from dataclasses import replace
from typing import TYPE_CHECKING

from relevance_plan.io import Source, is_pddl_text, load_sources
from relevance_plan.pddl.model import Domain, Problem
from relevance_plan.pddl.writer import write_pruned_problem
from relevance_plan.planning.options import PlanOptions
from relevance_plan.relevance.scoring.knowledge import KnowledgeModel
from relevance_plan.relevance.scoring.scorers import ScoreResult
from relevance_plan.relevance.selection.prune import Selection
from relevance_plan.relevance.setup import ScoringOptions, resolve_knowledge_model
from relevance_plan.session.determination import Determination
from relevance_plan.session.events import EventError, check_event, parse_event_line
from relevance_plan.session.planning import RunPlanner, SessionPlanner, planner_in_folder
from relevance_plan.session.reports import Ask, EventReport, PlanReport
from relevance_plan.session.rescoring import ALL
from relevance_plan.session.reuse import SelectionBasis
from relevance_plan.session.state import LiveScene
from relevance_plan.session.triggers import TRIGGERS, Change, Trigger, check_triggers
from relevance_plan.session.updates import SceneUpdates, touched_names

if TYPE_CHECKING:  # the text package is imported only when free text is given
    from relevance_plan.relevance.scoring.word_matching import WordMatch

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
    ):
        domain_text = str(domain) if is_pddl_text(domain) else None
        if domain_path is None and not isinstance(domain, Domain) and domain_text is None:
            domain_path = os.fspath(domain)
        domain, problem = load_sources(domain, problem)
        domain_path = domain_path or domain.path
        self.domain = domain
        if model is None and options.scorer in (None, "model"):
            model = resolve_knowledge_model(domain, domain_path, options.model_path)
        self.model = model
        self.scene = LiveScene(domain, problem)
        self.updates = SceneUpdates(self.scene, model, options, domain_path)
        self.relevance = Determination(domain, model, self.updates)
        plan_options = plan_options or PlanOptions(thresholds=options.thresholds)
        run_planner = run_planner or planner_in_folder(self, plan_options, domain_path, domain_text or domain)
        self.planner = SessionPlanner(self.relevance, plan_options, run_planner, plan_in_loop)
        self.triggers: dict[str, Trigger] = TRIGGERS  # a registry of one's own may replace it
        self.seq = 0
        if not self.idle:
            self.relevance.determine()

    # ------------------------------------------------------------------ state

    @property
    def options(self) -> ScoringOptions:
        """The scoring options in force: the session's, with the goal, human and cues the events set."""
        return self.updates.options

    @property
    def selection(self) -> Selection | None:
        """The first selection in force (made with sufficient cues; stale while they are not)."""
        return self.relevance.selection

    @property
    def basis(self) -> SelectionBasis | None:
        """What the first selection in force read (None: the next one is made in full)."""
        return self.relevance.basis

    @property
    def run_planner(self) -> RunPlanner | None:
        return self.planner.run_planner

    @run_planner.setter
    def run_planner(self, run_planner: RunPlanner | None) -> None:
        self.planner.run_planner = run_planner

    @property
    def idle(self) -> bool:
        """Nobody to serve (no goal, no human): element and fact events trigger nothing."""
        return self.updates.idle

    @property
    def kept(self) -> frozenset:
        """The first selection in force: the objects ``prune`` keeps on the current state."""
        return self.relevance.kept

    @property
    def relevant(self) -> frozenset:
        """The paper's relevant set in force: above the thresholds (and the goal's objects), before
        the goal filter and without what closure put back."""
        return self.relevance.relevant

    @property
    def determination(self) -> Selection | None:
        """The paper's relevance step in force (thresholds, closure, and for the goal scorer the
        reachability repair: ``prune_with_scores`` with its default settings), made when asked for."""
        return self.relevance.paper_step()

    @property
    def sufficient(self) -> bool:
        return self.updates.scores.sufficient

    def current_scores(self) -> ScoreResult:
        """The scores of the current state (equal to scoring it from scratch)."""
        return self.updates.scores.result()

    def snapshot(self) -> tuple[str, str]:
        """(the current full problem, its pruned version) as PDDL text in the user's spelling."""
        problem = self.scene.read_problem()
        kept = self.kept & problem.objects.keys() if self.selection is not None else problem.objects.keys()
        return problem.text, write_pruned_problem(problem, kept)

    def ask(self, scores: ScoreResult | None = None) -> Ask | None:
        """The question for the human: the missing cue, or (without recorded preferences) which kinds."""
        return self.relevance.ask(scores)

    def plan(self) -> PlanReport:
        """A plan for the current state: the previous one if still valid, else the attempt loop."""
        return self.planner.plan()

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
        updates, relevance = self.updates, self.relevance
        watched_before = relevance.watched
        sufficient_before = updates.scores.sufficient
        functional_before, single_valued_before = self.scene.index.functional, relevance.single_valued
        changed, rescored, delta = updates.apply(event, relevance.selection is not None)
        if updates.scores.sufficient != sufficient_before:
            rescored = ALL
        crossed = updates.update_passing(rescored)
        linked = relevance.linked(delta, watched_before)
        rules_changed = relevance.closure_rules_changed(functional_before, single_valued_before, watched_before)
        remade = rescored is ALL or bool(linked) or rules_changed or relevance.serves(crossed)
        read = relevance.read(delta, rescored, remade)
        change = Change(
            event=event,
            idle=self.idle,
            changed=changed,
            touched=touched_names(event),
            kept=watched_before,
            linked=linked,
            crossed=frozenset(crossed),
            rules_changed=rules_changed,
            read=read,
            show=lambda name: self.scene.spelling.object(name),
        )
        reasons = check_triggers(change, self.triggers)
        previous = relevance.selection
        if changed:
            relevance.changes += 1
        made = None
        if reasons:
            made = relevance.determine(remade or bool(read) or relevance.basis is None)
        elif changed and self.idle:
            relevance.basis = None  # nobody is served: the selection in force stops following the scene
        report = replace(self._report(event.kind, reasons, previous, time.perf_counter() - started), made=made)
        if event.understood is not None:
            report = _with_cue_words(report, event.understood)
        plan = self.planner.plan_for(event, reasons, change, previous)
        return replace(report, plan=plan) if plan is not None else report

    def _rejected(self, kind: str, error: EventError) -> EventReport:
        return EventReport(
            self.seq,
            kind,
            error=error.message,
            sufficient=self.sufficient,
            stale=not self.sufficient and self.selection is not None,
            selection=self.selection,
            relevant_objects=self.relevant,
            spelling=self.scene.spelling,
        )

    def _report(self, kind: str, reasons: tuple, previous: Selection | None, seconds: float) -> EventReport:
        scores = self.updates.scores
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
            # what free text was taken for: with each determination, and whenever the cues fall short
            understood=self.updates.understood() if reasons or not scores.sufficient else (),
        )


def _with_cue_words(report: EventReport, match: WordMatch) -> EventReport:
    """A cue in words: what it was understood as, or (not understood) the question to ask."""
    if match.chosen is not None:
        return replace(report, understood=(match,))
    options = tuple(candidate.name for candidate in match.candidates)
    return replace(report, understood=(match,), ask=Ask(match.vocabulary.value, match.insufficiency, options))
