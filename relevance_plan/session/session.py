"""A live scene session: events in, a determination kept current, plans kept valid.

    session = Session(domain, problem, ScoringOptions(objective="drink-at-break"))
    report = session.handle({"event": "add", "object": "mug_2", "type": "cup", "facts": [...]})
    report.triggered, report.reason, report.selection.kept, report.ask

For each event the session checks it against the scene, applies it, updates
the scores of the elements it can affect (``rescoring.py``), runs the
trigger check (``triggers.py``) and, only when a trigger fires, determines
relevance again on the current state, in two steps: the paper's relevance
(threshold + closure, ``relevance.prune.prune_with_scores``: its ``selected``
is the relevant set, :attr:`Session.relevant`), and on top of it the same
first selection ``relevance-plan prune`` writes (goal filter, blocked and
spare alternatives set aside: ``Scoring.first_selection``), which is what
the session reports as kept.  The triggers watch the first step's kept set, a
superset of the first selection's, so an event that fires none changes
neither.  When
the cues are insufficient the previous selection stays in force, marked
stale, with the question to ask; a ``cue``, ``human`` or ``goal`` event that
settles it resumes.  With a planner, a determination that changes the kept
set (or a new goal, or a ``plan`` event) plans again with the one attempt
loop of ``planning.loop``; a previous plan that is still valid on the current
full state is kept without calling the planner.

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
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field, replace
from pathlib import Path
from types import MappingProxyType
from typing import TYPE_CHECKING, Any

from relevance_plan.io import Source, is_pddl_text, load_sources, write_text_atomic
from relevance_plan.pddl.formatter import format_domain
from relevance_plan.pddl.formulas import Formula
from relevance_plan.pddl.model import Domain, Problem
from relevance_plan.pddl.plans import Plan
from relevance_plan.pddl.writer import write_pruned_problem
from relevance_plan.planning.loop import PlanOptions, run_attempts, summarise
from relevance_plan.planning.planners.base import RunOutcome
from relevance_plan.planning.results import PlanResult, PlanStatus
from relevance_plan.planning.validate import validate_plan
from relevance_plan.relevance.analysis import ConstraintRule, FactIndex, single_valued_predicates
from relevance_plan.relevance.closure import constraint_rules
from relevance_plan.relevance.knowledge import KnowledgeModel
from relevance_plan.relevance.prune import Selection, prune_with_scores
from relevance_plan.relevance.scorers import ScoreResult
from relevance_plan.relevance.setup import Scoring, ScoringOptions, choose_scorer, resolve_knowledge_model
from relevance_plan.relevance.task import PlanningTask
from relevance_plan.session.events import Event, EventError, check_event, parse_event_line
from relevance_plan.session.rescoring import ALL, FullScores, LiveModelScores, restrict
from relevance_plan.session.state import LiveScene
from relevance_plan.session.triggers import TRIGGERS, Change, Trigger, check_triggers

if TYPE_CHECKING:  # the text package is imported only when free text is given
    from relevance_plan.relevance.text.matching import WordMatch

# Runs the planner on a problem (PDDL text of the current domain) within a time limit (None: none).
RunPlanner = Callable[[str, "float | None"], RunOutcome]


@dataclass(frozen=True)
class Ask:
    """What to ask the human: the missing cue, the question, the choices."""

    cue: str  # "objective", "task", "model" (insufficient cues) or "preference" (which kind)
    question: str
    options: tuple = ()


@dataclass(frozen=True)
class PlanReport:
    status: PlanStatus
    steps: Plan = Plan()
    source: str = "planner"  # "planner" or "previous" (still valid: the planner was not called)
    message: str = ""
    result: PlanResult | None = None


@dataclass(frozen=True)
class EventReport:
    seq: int
    event: str
    triggered: bool = False
    reasons: tuple = ()
    error: str | None = None
    sufficient: bool = True
    insufficiency: str = ""
    stale: bool = False  # the selection in force predates insufficient cues
    selection: Selection | None = None  # the first selection in force (after the event), as ``prune`` writes it
    relevant_objects: frozenset = frozenset()  # the paper's relevant set in force (names; see Session.relevant)
    added: tuple = ()  # kept now, not before (names)
    dropped: tuple = ()
    ask: Ask | None = None
    seconds: float = 0.0  # trigger check + determination
    plan: PlanReport | None = None
    display: Mapping[str, str] = field(default_factory=dict, repr=False)  # object -> the user's spelling
    understood: tuple[WordMatch, ...] = ()  # free text (a cue in words, --objective TEXT) and what it was taken for

    @property
    def reason(self) -> str:
        return "; ".join(self.reasons)

    def show(self, name: str) -> str:
        """An object's name in the user's spelling (a name that left the scene as given)."""
        return self.display.get(name, name)

    @property
    def kept(self) -> list[str]:
        """The objects the selection in force keeps, in the user's spelling, sorted."""
        return sorted(self.show(n) for n in (self.selection.kept if self.selection is not None else ()))

    @property
    def relevant(self) -> list[str]:
        """The paper's relevant set in force (above the thresholds, before the goal filter), in the
        user's spelling, sorted: every kept object is in it or was put back (``selection.restored``)."""
        return sorted(self.show(n) for n in self.relevant_objects)

    def to_json(self) -> dict[str, Any]:
        """The event's report as ``watch`` prints it (names in the user's spelling)."""
        data: dict[str, Any] = {
            "seq": self.seq,
            "event": self.event,
            "triggered": self.triggered,
            "reason": self.reason,
            "sufficient": self.sufficient,
            "stale": self.stale,
        }
        if self.error is not None:
            data["error"] = self.error
        if not self.sufficient:
            data["insufficiency"] = self.insufficiency
        if self.triggered:
            data["kept"] = self.kept
            data["relevant"] = self.relevant
            restored = self.selection.restored if self.selection is not None else ()
            data["restored"] = [{"object": self.show(r.name), "reason": r.reason} for r in restored]
            data["removed"] = len(self.selection.removed) if self.selection is not None else None
        data["added"] = [self.show(n) for n in self.added]
        data["dropped"] = [self.show(n) for n in self.dropped]
        ask = self.ask
        data["ask"] = None if ask is None else {"cue": ask.cue, "question": ask.question, "options": list(ask.options)}
        if self.understood:
            data["understood"] = [match.as_json() for match in self.understood]
        data["determination_ms"] = round(self.seconds * 1000, 3)
        if self.plan is not None:
            data["plan_status"] = self.plan.status.value
            data["plan"] = ["(" + " ".join([s.action, *map(self.show, s.args)]) + ")" for s in self.plan.steps]
            data["plan_source"] = self.plan.source
            data["plan_message"] = self.plan.message
        return data


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
        scorer = choose_scorer("relevance", self.model, options.scorer)
        self.scores: LiveModelScores | FullScores
        # placing unknown kinds (--place-kinds) is the scorer's own step: scored in full on each change
        if scorer == "model" and self.model is not None and not options.place_kinds:
            self.scores = LiveModelScores(self.scene, self.model, options)
        else:
            self.scores = FullScores(self.scene, self.model, options, domain_path)
        self.plan_options = plan_options or PlanOptions(thresholds=options.thresholds)
        self.run_planner = run_planner or planner_in_folder(self, self.plan_options, domain_path, domain_text or domain)
        self.plan_in_loop = plan_in_loop
        self.triggers = TRIGGERS if triggers is None else triggers
        self.served: str | None = None  # the human of the last 'human' event
        self.seq = 0
        # the last determination made with sufficient cues: relevance (thresholds + closure) and the
        # first selection narrowed from it (what ``prune`` writes and the session reports as kept)
        self.determination: Selection | None = None
        self.selection: Selection | None = None
        self.passing: set = set()
        # (functional positions, closure rules by predicate) for the trigger check
        self._rules: tuple[frozenset, dict[str, list[ConstraintRule]]] | None = None
        self._singletons = self.scene.index.singletons
        self._single_valued = single_valued_predicates(domain, _IndexView(self.scene))
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
        return self.determination.selected if self.determination is not None else frozenset()

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
        kept_before = self.determination.kept if self.determination is not None else frozenset()
        sufficient_before = self.scores.sufficient
        functional_before, single_valued_before = self.scene.index.functional, self._single_valued
        changed, rescored = self._apply(event)
        if self.scores.sufficient != sufficient_before:
            rescored = ALL
        crossed = self._update_passing(rescored)
        change = Change(
            event=event,
            idle=self.idle,
            changed=changed,
            touched=self._touched(event),
            kept=kept_before,
            linked=self._linked(event, kept_before),
            crossed=frozenset(crossed),
            rules_changed=self._closure_rules_changed(functional_before, single_valued_before, kept_before),
            show=self._show,
        )
        reasons = check_triggers(change, self.triggers)
        previous = self.selection
        if reasons:
            self._determine()
        seconds = time.perf_counter() - started
        report = self._report(event.kind, reasons, previous, seconds)
        if event.understood is not None:
            report = self._with_cue_words(report, event.understood)
        plan = None
        if event.kind == "plan" and self.run_planner is not None:
            plan = self.plan()
        elif event.kind == "plan":
            plan = PlanReport(PlanStatus.INPUT_ERROR, message="this session has no planner")
        elif (
            reasons
            and self.plan_in_loop
            and self.selection is not None
            and self.sufficient
            and not self.scene.idle_goal
            and (
                self.selection.kept != self.planned_kept
                or self.scene.goal != self.planned_goal
                or change.touched & kept_before
            )
        ):
            plan = self.plan()
        return replace(report, plan=plan) if plan is not None else report

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
            display=MappingProxyType(self.scene.display),
        )

    def _show(self, name: str) -> str:
        return self.scene.display.get(name, name)

    def _touched(self, event: Event) -> frozenset:
        names = {event.name} if event.kind in ("add", "remove") else set()
        for fact in event.facts:
            names.update(fact[1:])
        if event.fluent is not None:
            names.update(event.fluent[1:])
        return frozenset(names)

    def _apply(self, event: Event) -> tuple[bool, object]:
        """Change the scene; returns (whether anything changed, the elements whose scores may differ)."""
        scene, scores = self.scene, self.scores
        if event.kind == "add":
            # check_event fills what each kind needs; the asserts only tell the type checker
            assert event.name is not None and event.type is not None and event.display is not None
            scene.add_object(event.name, event.type, event.display)
            for fact in event.facts:
                scene.set(fact)
            names = self._affected(event.facts) | {event.name}
            scores.describe(names)
            return True, scores.refresh(names)
        if event.kind == "remove":
            assert event.name is not None
            gone = scene.remove_object(event.name)
            scores.forget(event.name)
            names = self._affected(gone) - {event.name}
            scores.describe(names)
            if self.served == event.name:  # the human served left: their preferences and cues go too
                self.served = None
                self._set_options(replace(self.options, human=None, model_task=None))
                return True, ALL
            return True, scores.refresh(names)
        if event.fluent is not None:
            assert event.value is not None
            if not scene.set_value(event.fluent, event.value):
                return False, set()
            names = {n for n in event.fluent[1:] if n in scene.objects}
            scores.describe(names)
            return True, scores.refresh(names)
        if event.kind in ("set", "unset"):
            fact = event.facts[0]
            if not (scene.set(fact) if event.kind == "set" else scene.unset(fact)):
                return False, set()
            names = self._affected([fact])
            scores.describe(names)
            return True, scores.refresh(names)
        if event.kind == "goal":
            assert event.goal is not None
            if event.goal == scene.goal:
                return False, set()
            scene.goal = event.goal
            self._set_options(self.options)
            return True, ALL
        if event.kind == "human":
            options = replace(self.options, human=event.profile, model_task=None)
            if event.name == self.served and options == self.options:
                return False, set()
            self.served = event.name
            self._set_options(options)
            return True, ALL
        if event.kind == "cue":
            if event.task is None and event.objective is None:
                return False, set()  # words not understood: nothing changes, the report asks
            if event.task is not None:
                options = replace(self.options, model_task=event.task)
            else:
                options = replace(self.options, objective=event.objective)
            if options == self.options:
                # the cue in force, said again: worth a determination only if none was made yet
                return self.determination is None, ALL if self.determination is None else set()
            self._set_options(options)
            return True, ALL
        return False, set()  # plan

    def _set_options(self, options: ScoringOptions) -> None:
        self.options = options
        self.scores.set_options(options)

    def _affected(self, facts) -> set:
        """Objects whose description a change of these facts can alter."""
        names: set = set()
        predicates = self.model.scene if self.model is not None else None
        for fact in facts:
            names.update(fact[1:])
            if (
                predicates is not None
                and fact[0] in (predicates.access, predicates.closed, predicates.human_location)
                and len(fact) > 1
            ):
                names |= self.scores.items_at(fact[-1])
        return {n for n in names if n in self.scene.objects}

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

    def _linked(self, event: Event, kept: frozenset) -> frozenset:
        """Kept objects from which closure follows the event's fact (a plate put on the kept cup)."""
        if event.kind not in ("set", "unset") or not kept or not event.facts:
            return frozenset()
        functional = self.scene.index.functional
        if self._rules is None or self._rules[0] != functional:
            by_predicate: dict[str, list[ConstraintRule]] = {}
            for rule in constraint_rules(self.domain, _IndexView(self.scene), self.model):
                by_predicate.setdefault(rule.predicate, []).append(rule)
            self._rules = (functional, by_predicate)
        fact = event.facts[0]
        return frozenset(
            fact[1 + rule.when_kept] for rule in self._rules[1].get(fact[0], ()) if fact[1 + rule.when_kept] in kept
        )

    def _closure_rules_changed(
        self, functional_before: frozenset, single_valued_before: frozenset, kept: frozenset
    ) -> bool:
        """Whether closure from ``kept`` could follow other facts now: a single-valued predicate
        came or went, or a predicate became (or stopped being) functional at a position where
        some fact has a kept object."""
        index = self.scene.index
        if index.singletons != self._singletons:
            self._singletons = index.singletons
            self._single_valued = single_valued_predicates(self.domain, _IndexView(self.scene))
        if self._single_valued != single_valued_before:
            return True
        for predicate, key, _ in index.functional ^ functional_before:
            for name in kept:
                if any(fact[1 + key] == name for fact in index.facts_of(name, predicate)):
                    return True
        return False

    def _recount_passing(self) -> None:
        thresholds = self.options.thresholds
        self.passing = {n for n in self.scene.objects if self.scores.passes(n, thresholds)}

    # ------------------------------------------------------------------ determination

    def _determine(self) -> None:
        """Relevance (threshold + closure) and the first selection on the current state, if the cues suffice."""
        scores = self.scores.result()
        if not scores.sufficient:
            return  # the previous selection stays in force, stale
        task = _LiveTask(self.scene.domain, self.scene.snapshot_problem(), _IndexView(self.scene))
        self.determination = prune_with_scores(task, scores, self.options.thresholds, self.model)
        self.selection = Scoring(task, self.model, scores, self.options).first_selection()

    def _report(self, kind: str, reasons: tuple, previous: Selection | None, seconds: float) -> EventReport:
        scores = self.scores.result()
        before = previous.kept if previous is not None else frozenset()
        now = self.kept
        return EventReport(
            seq=self.seq,
            event=kind,
            triggered=bool(reasons),
            reasons=reasons,
            sufficient=scores.sufficient,
            insufficiency=scores.insufficiency,
            stale=not scores.sufficient and self.selection is not None,
            selection=self.selection,
            relevant_objects=self.relevant,
            added=tuple(sorted(now - before)) if reasons else (),
            dropped=tuple(sorted(before - now)) if reasons else (),
            ask=self.ask(scores) if (reasons or not scores.sufficient) and not self.idle else None,
            seconds=seconds,
            display=MappingProxyType(self.scene.display),
            understood=scores.understood if reasons else (),
        )

    def ask(self, scores: ScoreResult | None = None) -> Ask | None:
        """The question for the human: the missing cue, or (without recorded preferences) which kinds."""
        scores = scores or self.scores.result()
        model = self.model
        if not scores.sufficient:
            if model is None:
                return None
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
        if model is None or self.options.human is not None or self.determination is None or scores.scorer != "model":
            return None
        from relevance_plan.relevance.metrics import plan_inquiries
        from relevance_plan.relevance.scene import kind_of

        structural = {c.name for c in model.classes.values() if c.fixed_relevance is not None or c.from_contents}
        selected = self.determination.selected
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
        if options.method != "pure":
            if self.selection is None:
                return PlanReport(PlanStatus.INSUFFICIENT_CUES, message=self.scores.result().insufficiency)
            scores = self.scores.result()
            if not scores.sufficient:  # plan with the selection in force (stale)
                scores = restrict(self.selection.scores, problem.objects)
            scorer = scores.scorer
            selection = Scoring(task, self.model, scores, options.scoring).first_selection(options.narrows_first)
        relevance_time = time.perf_counter() - started

        def call_planner(objects: Selection | None, limit: float | None) -> RunOutcome:
            return self.run_planner(problem.text if objects is None else objects.text, limit)

        attempts, widening = run_attempts(task, selection, call_planner, options, started=started, model=self.model)
        result = summarise(
            task,
            options,
            attempts,
            started,
            relevance_time + widening,
            selection,
            scorer=scorer,
            planner=attempts[0].outcome.planner if attempts else options.planner,
        )
        if result.status is PlanStatus.SOLVED:
            self._planned(result.plan)
        return PlanReport(result.status, result.plan, "planner", result.message, result)

    def _planned(self, steps: Plan) -> None:
        self.plan_steps = steps
        self.planned_kept = self.kept
        self.planned_goal = self.scene.goal


def planner_in_folder(owner: object, options: PlanOptions, domain_path: str | None, domain: str | Domain) -> RunPlanner:
    """A planner call that writes each problem into a private folder, removed with ``owner``
    (the domain too, from its text, when it has no file)."""
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
        return planner.run(str(domain_path), str(path), time_limit=limit, memory_limit_mb=options.memory_limit_mb)

    return run


@dataclass(frozen=True, eq=False)
class _LiveTask(PlanningTask):
    """The current state as a planning task, its facts indexed by the live index rather than again."""

    live_index: FactIndex

    @property
    def init_index(self) -> FactIndex:
        return self.live_index


class _IndexView:
    """The live index as ``analysis.InitIndex`` (singleton predicates' facts as tuples)."""

    def __init__(self, scene: LiveScene):
        index = scene.index
        self.by_object = index.by_object
        self.functional = index.functional
        self.singletons = index.singletons
        self.by_predicate = {p: tuple(index.by_predicate[p]) for p in self.singletons}
