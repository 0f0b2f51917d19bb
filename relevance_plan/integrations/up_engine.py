"""A unified-planning meta-engine: prune irrelevant objects, then plan.

``relevance[<planner>]`` wraps any oneshot planner of the unified-planning
library (``relevance[fast-downward]``, ``relevance[pyperplan]``, ...).  For each
problem it

1. exports the problem once with UP's ``PDDLWriter`` (on a clone: the writer
   reads ``initial_values``, which fills the problem's own dictionary of
   explicit initial values with every ground atom) and reads the text with
   our reader;
2. scores the objects with the scoring set-up every front end uses
   (``relevance.setup``: the knowledge model when one applies to the domain,
   else the domain-independent ``goal`` scorer; an engine cannot ask for
   cues, so insufficient cues fall back to the goal scorer);
3. runs the attempt loop of ``relevance-plan plan`` (``planning.attempts``) with
   the inner planner as its planner: each attempt gives the inner planner a
   UP problem restricted to the kept objects, maps its plan back to the
   original problem's actions and objects and validates it on the original
   problem; a failed attempt widens the selection, and the last attempt is
   the whole problem, so only that attempt can prove the problem unsolvable.

Register it with :func:`register_relevance_engine` (or an ``up.ini``
section, see ``docs/up.ini.example``) and ask for it by name::

    register_relevance_engine()
    with OneshotPlanner(name="relevance[fast-downward]") as planner:
        result = planner.solve(problem, timeout=60)

Options go through UP's ``params``: ``tau_class``, ``tau_element``,
``scorer`` (``goal``, ``model`` or ``random``), ``model`` (a knowledge-model
file), ``domain`` (the knowledge-model domain to look up under ``domains/``),
``widen_factor``, ``first_share`` and ``seed``; every other parameter goes to
the inner planner unchanged.
"""

from __future__ import annotations

import dataclasses
import math
import time
from collections.abc import Callable, Iterator, Set
from dataclasses import dataclass, field
from functools import cached_property
from typing import IO

import unified_planning as up
from unified_planning.engines import Engine, MetaEngine, OptimalityGuarantee
from unified_planning.engines.mixins import AnytimePlannerMixin, OneshotPlannerMixin
from unified_planning.engines.mixins.anytime_planner import AnytimeGuarantee
from unified_planning.engines.plan_validator import SequentialPlanValidator
from unified_planning.engines.results import (
    POSITIVE_OUTCOMES,
    LogLevel,
    LogMessage,
    PlanGenerationResult,
    PlanGenerationResultStatus,
    ValidationResultStatus,
)
from unified_planning.exceptions import UPUsageError, UPValueError
from unified_planning.io import PDDLWriter
from unified_planning.model import Problem, ProblemKind
from unified_planning.model.problem_kind_versioning import LATEST_PROBLEM_KIND_VERSION
from unified_planning.plans import ActionInstance, SequentialPlan

from relevance_plan.errors import RelevancePlanError, UsageError, counted
from relevance_plan.pddl.model import Domain
from relevance_plan.pddl.parser import read_domain, read_problem
from relevance_plan.pddl.plans import Plan, PlanStep
from relevance_plan.planning.attempts import AttemptLoop, run_attempts
from relevance_plan.planning.options import Method, PlanOptions
from relevance_plan.planning.planners.base import PlannerStatus, RunOutcome
from relevance_plan.planning.planners.up.adapter import UP_STATUS, up_status_name
from relevance_plan.planning.results import Attempt, PlanStatus
from relevance_plan.planning.summary import RunFacts, summarise
from relevance_plan.planning.validation import validate_plan
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.scoring.knowledge import KnowledgeModel, load_knowledge_model
from relevance_plan.relevance.scoring.scorers import SCORERS
from relevance_plan.relevance.selection.prune import DEFAULT_TAU, Selection, Thresholds, Widening, widen
from relevance_plan.relevance.setup import Scoring, given_cues, resolve_knowledge_model, score_problem, without_cues

ENGINE_NAME = "relevance"

# Scorers a user may choose through params; the oracle needs a generator's sidecar.
ENGINE_SCORERS = tuple(name for name in SCORERS if name != "oracle")

# The engine's own parameters (``params=`` of the factory, given with the inner planner's) and their defaults.
ENGINE_PARAMETERS = {
    "tau_class": DEFAULT_TAU,
    "tau_element": DEFAULT_TAU,
    "scorer": None,
    "model": None,
    "domain": None,
    "widen_factor": 0.5,
    "first_share": 0.5,
    "seed": 0,
}

# What our PDDL reader handles (pddl.SUPPORTED_REQUIREMENTS).  The engine
# supports the intersection of this with the inner planner's kind.
_READER_FEATURES = {
    "problem_class": ("ACTION_BASED",),
    "typing": ("FLAT_TYPING", "HIERARCHICAL_TYPING"),
    "conditions_kind": (
        "NEGATIVE_CONDITIONS",
        "DISJUNCTIVE_CONDITIONS",
        "EXISTENTIAL_CONDITIONS",
        "UNIVERSAL_CONDITIONS",
        "EQUALITIES",
    ),
    "effects_kind": ("CONDITIONAL_EFFECTS", "FORALL_EFFECTS"),
    # Constant action costs become (increase (total-cost) N), which the reader accepts.
    "quality_metrics": ("ACTIONS_COST", "PLAN_LENGTH"),
    "actions_cost_kind": ("INT_NUMBERS_IN_ACTIONS_COST",),
}


def relevance_supported_kind() -> ProblemKind:
    """The problem features the relevance stage itself handles."""
    kind = ProblemKind(version=LATEST_PROBLEM_KIND_VERSION)
    for feature_class, features in _READER_FEATURES.items():
        for feature in features:
            getattr(kind, f"set_{feature_class}")(feature)
    return kind


class RelevanceMetaEngine(MetaEngine, OneshotPlannerMixin, AnytimePlannerMixin):
    """Relevance-based object pruning in front of any oneshot planner.

    Instantiated by the factory as ``relevance[<planner>]``; keyword options
    are described in the module docstring.  The plan returned has always been
    validated on the original problem.  When the inner planner is also an
    anytime planner, so is this engine (``AnytimePlanner(name=...)``): it
    yields each better plan, validated on the original problem.
    """

    def __init__(self, *args, **kwargs):
        # Our parameters are taken out here; the rest belongs to the inner planner.
        own = {name: kwargs.pop(name, default) for name, default in ENGINE_PARAMETERS.items()}
        thresholds = Thresholds(float(own["tau_class"]), float(own["tau_element"]))
        scorer, widen_factor, first_share = own["scorer"], float(own["widen_factor"]), float(own["first_share"])
        if scorer is not None and scorer not in ENGINE_SCORERS:
            raise UsageError(f"unknown scorer '{scorer}' (choose from: {', '.join(ENGINE_SCORERS)})")
        if not 0.0 < widen_factor < 1.0:
            raise UsageError(f"widen_factor must be in (0, 1), got {own['widen_factor']}")
        if not 0.0 < first_share <= 1.0:
            raise UsageError(f"first_share must be in (0, 1], got {own['first_share']}")
        model = own["model"]
        self._model: KnowledgeModel | None = load_knowledge_model(model) if model is not None else None
        self._domain: str | None = own["domain"]
        # The same options object `plan` builds: the same loop makes the same choices.
        self._options = PlanOptions(
            method=Method.RELEVANCE,
            thresholds=thresholds,
            scorer=scorer,
            widen_factor=widen_factor,
            first_share=first_share,
            seed=int(own["seed"]),
            timeout=None,
        )
        MetaEngine.__init__(self, *args, **kwargs)
        OneshotPlannerMixin.__init__(self)
        AnytimePlannerMixin.__init__(self)

    # ---------------------------------------------------------------- engine API

    @property
    def name(self) -> str:
        return f"{ENGINE_NAME}[{self.engine.name}]"

    @staticmethod
    def satisfies(optimality_guarantee: OptimalityGuarantee) -> bool:
        # Pruning may remove what an optimal plan needs.
        return optimality_guarantee == OptimalityGuarantee.SATISFICING

    @staticmethod
    def is_compatible_engine(engine: type[Engine]) -> bool:
        if issubclass(engine, MetaEngine):
            # relevance[oversubscription[...]] would only be a weaker copy of relevance[...].
            return False
        classical = ProblemKind({"ACTION_BASED"}, version=LATEST_PROBLEM_KIND_VERSION)
        return engine.is_oneshot_planner() and engine.supports(classical)

    @staticmethod
    def _supported_kind(engine: type[Engine]) -> ProblemKind:
        return relevance_supported_kind().intersection(engine.supported_kind())

    @staticmethod
    def _supports(problem_kind: ProblemKind, engine: type[Engine]) -> bool:
        return problem_kind <= RelevanceMetaEngine._supported_kind(engine)

    @staticmethod
    def ensures(anytime_guarantee: AnytimeGuarantee) -> bool:
        # Each plan yielded is better than the last; pruning may hide the optimal plan.
        return anytime_guarantee == AnytimeGuarantee.INCREASING_QUALITY

    @classmethod
    def get_credits(cls, **kwargs):
        """None: the factory prints no credits banner for this engine, whatever the environment (the
        inner planner's credits are its own class's ``get_credits()``)."""
        return None

    # ---------------------------------------------------------------- solving

    def _solve(
        self,
        problem: up.model.AbstractProblem,
        heuristic: Callable[[up.model.state.State], float | None] | None = None,
        timeout: float | None = None,
        output_stream: IO[str] | None = None,
    ) -> PlanGenerationResult:
        assert isinstance(problem, Problem)
        assert isinstance(self.engine, OneshotPlannerMixin)
        problem.environment.credits_stream = None
        started = time.perf_counter()
        options = dataclasses.replace(self._options, timeout=timeout)
        messages: list[str] = []
        warning_lines: list[str] = []
        total = len(problem.all_objects)

        stage = None
        try:
            stage = _RelevanceStage.build(problem, self._choose_model, options, warning_lines)
            messages.append(
                f"scored {len(stage.scoring.task.problem.objects)} objects with the {stage.scoring.scorer} scorer"
            )
        except RelevancePlanError as error:
            # Our reader or scorer cannot handle this problem: the whole problem is the only attempt.
            warning_lines.append(f"relevance stage skipped, planning on the whole problem: {error}")
        inner = _InnerPlanner(self.engine, problem, stage, heuristic, output_stream)

        if stage is None:
            # Without our reader's view of the problem there is nothing to prune or widen.
            attempts = _solve_whole(inner, options, started)
            relevance_time = 0.0
        else:
            selection = stage.scoring.first_selection(options.narrows_first)
            relevance_time = time.perf_counter() - started
            loop = AttemptLoop(stage.scoring.task, inner, options, started, stage.scoring.knowledge_model)
            attempts, widening_time = run_attempts(loop, selection)
            relevance_time += widening_time
        for attempt in attempts:
            messages.append(describe_attempt(attempt, total))

        found = inner.lifted.get(attempts[-1].number) if attempts else None
        if stage is not None:
            facts = RunFacts(
                stage.scoring.task, started, relevance_time, planner=self.engine.name, scorer=stage.scoring.scorer
            )
            result = summarise(facts, options, attempts)
            status, summary = _final_status(result, found, attempts)
        else:
            status, summary = _final_status_whole(problem, found, attempts)
        final_kept = attempts[-1].objects_kept if attempts else total
        first_kept = attempts[0].objects_kept if attempts else total
        messages.append(
            f"{summary}; kept {final_kept} of {total} objects (first attempt {first_kept}),"
            f" {counted(len(attempts), 'attempt')}"
        )
        metrics = {
            "objects_total": str(total),
            "objects_kept": str(final_kept),
            "objects_kept_first_attempt": str(first_kept),
            "objects_removed_first_attempt": str(total - first_kept),
            "attempts": str(len(attempts)),
            "scorer": stage.scoring.scorer if stage is not None else "none",
            "relevance_time": f"{relevance_time:.4f}",
            "planner_time": f"{sum(a.outcome.wall_time for a in attempts):.4f}",
            "engine_internal_time": f"{time.perf_counter() - started:.4f}",
        }
        logs = [LogMessage(LogLevel.WARNING, f"{ENGINE_NAME}: {text}") for text in warning_lines]
        logs += [LogMessage(LogLevel.INFO, f"{ENGINE_NAME}: {text}") for text in messages]
        if inner.last_result is not None and inner.last_result.log_messages:
            logs += inner.last_result.log_messages
        return PlanGenerationResult(
            status, found if status in POSITIVE_OUTCOMES else None, self.name, metrics=metrics, log_messages=logs
        )

    def _get_solutions(
        self,
        problem: up.model.AbstractProblem,
        timeout: float | None = None,
        output_stream: IO[str] | None = None,
    ) -> Iterator[PlanGenerationResult]:
        """Each better plan, validated on the original problem, then the final result.

        The attempts are those of ``solve``: the first selection, widened while
        an attempt yields no valid plan, the whole problem last.  The inner
        planner's stream of plans for the first attempt that yields a valid one
        is followed to its end; its improving plans are yielded as
        ``INTERMEDIATE`` results.
        """
        assert isinstance(problem, Problem)
        if not self.engine.is_anytime_planner():
            raise UPUsageError(f"{self.engine.name} is not an anytime planner, so neither is {self.name}")
        problem.environment.credits_stream = None
        options = dataclasses.replace(self._options, timeout=timeout)
        warning_lines: list[str] = []
        try:
            stage = _RelevanceStage.build(problem, self._choose_model, options, warning_lines)
        except RelevancePlanError as error:
            warning_lines.append(f"relevance stage skipped, planning on the whole problem: {error}")
            stage = None
        search = _AnytimeSearch(self, problem, stage, options, output_stream, warning_lines)
        yield from search.run()

    def _choose_model(self, domain: Domain) -> KnowledgeModel | None:
        """The ``model`` param, else a shipped model for the ``domain`` param or the exported name."""
        if self._model is not None:
            return self._model
        # The writer names the domain '<problem name>-domain'.
        names = [self._domain] if self._domain is not None else [domain.name.removesuffix("-domain")]
        return resolve_knowledge_model(domain, None, None, names)


def _anytime_when_inner_is(cls) -> bool:
    """Anytime exactly when the inner planner is (``relevance[fast-downward]`` is, ``relevance[pyperplan]`` not)."""
    inner = getattr(cls, "_engine_class", None)
    return inner is not None and inner.is_anytime_planner()


# unified-planning's engine metaclass marks every class built on AnytimePlannerMixin as anytime,
# after the class body: this engine decides per inner planner, so its answer is set here.
RelevanceMetaEngine.is_anytime_planner = classmethod(_anytime_when_inner_is)


# --------------------------------------------------------------------------- the relevance stage


@dataclass(frozen=True)
class _RelevanceStage:
    """The problem as our reader sees it, its scores, and the map back to UP names."""

    scoring: Scoring
    up_names: dict  # reader name (lower-cased writer name) -> the UP object's own name
    action_names: dict  # reader action name -> the UP action's own name

    @classmethod
    def build(cls, problem: Problem, choose_model, options: PlanOptions, warnings: list):
        # One export.  The writer reads problem.initial_values, which fills the
        # problem's explicit initial values with every ground atom: write a clone.
        writer = PDDLWriter(problem.clone())
        domain_text = writer.get_domain()
        problem_text = writer.get_problem()
        domain = read_domain(domain_text, "<unified-planning domain>")
        task = PlanningTask(domain, read_problem(problem_text, domain, "<unified-planning problem>"))
        up_names = {name: writer.get_item_named(name).name for name in task.problem.objects}
        action_names = {action.name: writer.get_item_named(action.name).name for action in domain.actions}
        model = choose_model(domain)
        scoring_options = options.scoring
        if scoring_options.scorer == "model" and model is None:
            warnings.append("no knowledge model applies to this problem: using the goal scorer")
            scoring_options = dataclasses.replace(scoring_options, scorer="goal")
        if model is None and given_cues(scoring_options):
            # An engine cannot stop to say so: the warning is the visible fallback.
            warnings.append(
                f"no knowledge model applies to this problem: {', '.join(given_cues(scoring_options))} unused"
            )
            scoring_options = without_cues(scoring_options)
        scoring = score_problem(task, scoring_options, knowledge_model=model)
        if not scoring.scores.sufficient:
            # An engine cannot ask the human: fall back to what the goal alone says.
            warnings.append(
                f"the {scoring.scorer} scorer has too little to go on ({scoring.scores.insufficiency}):"
                " using the goal scorer"
            )
            scoring = score_problem(
                task, dataclasses.replace(without_cues(scoring_options), scorer="goal"), knowledge_model=None
            )
            scoring = dataclasses.replace(scoring, knowledge_model=None)
        return cls(scoring, up_names, action_names)

    def removed_objects(self, selection: Selection | None) -> frozenset:
        if selection is None:
            return frozenset()
        return frozenset(self.up_names[name] for name in selection.removed)

    @cached_property
    def _reader_names(self) -> tuple[dict, dict]:
        """UP names -> the names our reader gave the exported problem (objects, actions)."""
        objects = {up: reader for reader, up in self.up_names.items()}
        actions = {up: reader for reader, up in self.action_names.items()}
        return objects, actions

    def reader_plan(self, plan: SequentialPlan) -> Plan:
        """A plan of the original UP problem in our reader's names (what the validators check)."""
        objects, actions = self._reader_names
        return Plan(
            tuple(
                PlanStep(actions[step.action.name], tuple(objects[p.object().name] for p in step.actual_parameters))
                for step in plan.actions
            )
        )


class _InnerPlanner:
    """The inner engine as the attempt loop's planner: restrict, solve, turn the result into a RunOutcome."""

    def __init__(self, engine, problem: Problem, stage: _RelevanceStage | None, heuristic, output_stream):
        self.engine = engine
        self.problem = problem
        self.stage = stage
        self.heuristic = heuristic
        self.output_stream = output_stream
        self.last_result: PlanGenerationResult | None = None
        self.lifted: dict[int, SequentialPlan] = {}  # attempt number -> the plan on the original problem
        self.calls = 0

    def __call__(self, selection: Selection | None, limit: float | None) -> RunOutcome:
        self.calls += 1
        removed = self.stage.removed_objects(selection) if self.stage is not None else frozenset()
        target = restrict_problem(self.problem, removed)
        started = time.perf_counter()
        result = self.engine.solve(target, self.heuristic, limit, self.output_stream)
        wall = time.perf_counter() - started
        self.last_result = result
        status = UP_STATUS.get(result.status.name, PlannerStatus.PLANNER_CRASH)
        steps = Plan()
        if result.status in POSITIVE_OUTCOMES:
            lifted = lift_plan(result.plan, self.problem) if result.plan is not None else None
            if lifted is None:
                status = PlannerStatus.PLANNER_CRASH  # a solution without a plan we can read
            else:
                self.lifted[self.calls] = lifted
                # without our reader's view there is nothing to validate with: the caller uses UP's validator
                steps = self.stage.reader_plan(lifted) if self.stage is not None else Plan()
        return RunOutcome(
            status=status,
            exit_code=None,
            plan=steps,
            plan_cost=None,
            wall_time=wall,
            config=self.engine.name,
            planner=self.engine.name,
            raw_status=result.status.name,
            reason=f"{self.engine.name}: unified-planning status {result.status.name}",
            optimal=result.status is PlanGenerationResultStatus.SOLVED_OPTIMALLY,
        )


@dataclass(eq=False)
class _AnytimeSearch:
    """The anytime engine's attempts: the inner planner's stream of plans on each object set,
    each plan mapped back and validated on the original problem, only better ones passed on."""

    meta: RelevanceMetaEngine
    problem: Problem
    stage: _RelevanceStage | None
    options: PlanOptions
    output: IO[str] | None
    warnings: list[str]
    started: float = field(default_factory=time.perf_counter, init=False)
    best: SequentialPlan | None = field(default=None, init=False)
    best_measure: float = field(default=math.inf, init=False)  # cost on the original problem (length without costs)
    attempts: int = field(default=0, init=False)
    last_status: PlanGenerationResultStatus | None = field(default=None, init=False)
    last_full: bool = field(default=False, init=False)
    kept: int = field(init=False)

    def __post_init__(self) -> None:
        self.kept = len(self.problem.all_objects)

    def run(self) -> Iterator[PlanGenerationResult]:
        total = len(self.problem.all_objects)
        selection = self.stage.scoring.first_selection(self.options.narrows_first) if self.stage else None
        extra: frozenset = frozenset()
        while True:
            tried = None if selection is None or len(selection.kept) >= total else selection
            full = tried is None
            limit = self._limit(final=full or not self.options.widen)
            if limit is not None and limit <= 0:
                break
            self.attempts += 1
            self.last_full = full
            self.kept = total if tried is None else len(tried.kept)
            found = yield from self._attempt(tried, limit)
            if found or full or not self.options.widen:
                break
            assert self.stage is not None and selection is not None
            goal_filter = self.options.goal_filter and self.options.narrows_first
            selection, extra = widen(
                selection, Widening(self.options.widen_factor, goal_filter), extra, self.stage.scoring.knowledge_model
            )
        yield self._final()

    def _limit(self, final: bool) -> float | None:
        if self.options.timeout is None:
            return None
        remaining = self.options.timeout - (time.perf_counter() - self.started)
        if final or remaining <= 0:
            return remaining
        return max(1.0, remaining * self.options.first_share)

    def _attempt(self, selection: Selection | None, limit: float | None):
        removed = self.stage.removed_objects(selection) if self.stage is not None else frozenset()
        target = restrict_problem(self.problem, removed)
        found = False
        for result in self.meta.engine.get_solutions(target, timeout=limit, output_stream=self.output):
            self.last_status = result.status
            lifted = lift_plan(result.plan, self.problem) if result.plan is not None else None
            measure = self._measure(lifted) if lifted is not None else None
            if lifted is None or measure is None or measure >= self.best_measure:
                continue
            self.best, self.best_measure, found = lifted, measure, True
            yield self._result(
                PlanGenerationResultStatus.INTERMEDIATE, f"plan of {counted(len(lifted.actions), 'step')}"
            )
        return found

    def _measure(self, plan: SequentialPlan) -> float | None:
        """The plan's cost (else length) if it is valid on the original problem, else None."""
        if self.stage is None:
            validator = SequentialPlanValidator(environment=self.problem.environment)
            valid = validator.validate(self.problem, plan).status is ValidationResultStatus.VALID
            return float(len(plan.actions)) if valid else None
        task = self.stage.scoring.task
        deadline = None
        if self.options.timeout is not None:
            remaining = self.options.timeout - (time.perf_counter() - self.started)
            deadline = time.monotonic() + max(remaining, 0.5)
        validation = validate_plan(
            task.domain, task.problem, self.stage.reader_plan(plan), self.options.validators, deadline
        )
        if not validation.valid:
            return None
        return validation.cost if validation.cost is not None else float(len(plan.actions))

    def _final(self) -> PlanGenerationResult:
        if self.best is not None:
            proven = self.last_full and self.last_status is PlanGenerationResultStatus.SOLVED_OPTIMALLY
            status = (
                PlanGenerationResultStatus.SOLVED_OPTIMALLY if proven else PlanGenerationResultStatus.SOLVED_SATISFICING
            )
            return self._result(status, "best plan validated on the original problem")
        if not self.last_full or self.last_status is None or self.last_status in POSITIVE_OUTCOMES:
            # a pruned problem's failure says nothing about the user's problem
            return self._result(PlanGenerationResultStatus.TIMEOUT, "out of time before a valid plan was found")
        return self._result(
            self.last_status, f"the inner planner reported {self.last_status.name} on the whole problem"
        )

    def _result(self, status: PlanGenerationResultStatus, summary: str) -> PlanGenerationResult:
        total = len(self.problem.all_objects)
        metrics = {
            "objects_total": str(total),
            "objects_kept": str(self.kept),
            "attempts": str(self.attempts),
            "scorer": self.stage.scoring.scorer if self.stage is not None else "none",
            "engine_internal_time": f"{time.perf_counter() - self.started:.4f}",
        }
        logs = [LogMessage(LogLevel.WARNING, f"{ENGINE_NAME}: {text}") for text in self.warnings]
        logs.append(LogMessage(LogLevel.INFO, f"{ENGINE_NAME}: {summary}; kept {self.kept} of {total} objects"))
        plan = self.best if status in POSITIVE_OUTCOMES or status is PlanGenerationResultStatus.INTERMEDIATE else None
        return PlanGenerationResult(status, plan, self.meta.name, metrics=metrics, log_messages=logs)


def up_status(status: PlannerStatus) -> PlanGenerationResultStatus:
    """Ours as unified-planning says it (``planning.planners.up.adapter.UP_STATUS`` read backwards)."""
    return PlanGenerationResultStatus[up_status_name(status)]


def up_verdict(status: PlanStatus) -> PlanGenerationResultStatus:
    """The loop's verdict as unified-planning says it: a verdict spelled like a planner status
    (unsolvable, out-of-time, ...) maps as that status does; any other is an internal error."""
    try:
        return up_status(PlannerStatus(status.value))
    except ValueError:
        return PlanGenerationResultStatus.INTERNAL_ERROR


def describe_attempt(attempt: Attempt, total: int) -> str:
    thresholds = attempt.thresholds
    what = (
        f"the whole problem ({total} objects)"
        if attempt.full or thresholds is None
        else f"{attempt.objects_kept} of {total} objects (tau_class={thresholds.tau_class:g},"
        f" tau_element={thresholds.tau_element:g})"
    )
    outcome = attempt.outcome.raw_status or attempt.outcome.status.name
    if attempt.validation is not None:
        outcome += (
            ", plan valid on the original problem"
            if attempt.validation.valid
            else ", plan INVALID on the original problem"
        )
    limit = "no limit" if attempt.time_limit is None else f"limit {attempt.time_limit:.1f} s"
    return f"attempt {attempt.number}: {what}, {limit} -> {outcome} in {attempt.outcome.wall_time:.2f} s"


def _solve_whole(inner: _InnerPlanner, options: PlanOptions, started: float) -> list[Attempt]:
    """The one attempt when our reader cannot read the problem: the inner engine alone, its own verdict."""
    limit = None if options.timeout is None else options.timeout - (time.perf_counter() - started)
    if limit is not None and limit <= 0:
        return []
    outcome = inner(None, limit)
    return [
        Attempt(
            number=1,
            objects_kept=len(inner.problem.all_objects),
            thresholds=None,
            added_back=0,
            outcome=outcome,
            validation=None,
            time_limit=limit,
        )
    ]


def _final_status(result, found, attempts) -> tuple[PlanGenerationResultStatus, str]:
    if result.status is PlanStatus.SOLVED:
        summary = f"plan of {counted(len(found.actions), 'step')} validated on the original problem"
        if attempts[-1].full and attempts[-1].outcome.optimal:
            return PlanGenerationResultStatus.SOLVED_OPTIMALLY, summary
        return PlanGenerationResultStatus.SOLVED_SATISFICING, summary
    if not attempts or not attempts[-1].full:
        # The time ran out before the whole problem was tried: a pruned problem's
        # failure says nothing about the user's problem.
        return PlanGenerationResultStatus.TIMEOUT, "out of time before a valid plan was found"
    last = attempts[-1]
    if result.status is PlanStatus.NO_VALID_PLAN:
        if last.validation is not None:
            return (
                PlanGenerationResultStatus.INTERNAL_ERROR,
                "the inner planner's plan for the whole problem does not validate",
            )
        if last.outcome.status is PlannerStatus.SEARCH_INCOMPLETE:
            return (
                PlanGenerationResultStatus.UNSOLVABLE_INCOMPLETELY,
                "the inner planner found no plan for the whole problem",
            )
    if result.status is PlanStatus.UNSOLVABLE:
        return PlanGenerationResultStatus.UNSOLVABLE_PROVEN, "the problem is unsolvable (proven on the whole problem)"
    status = up_verdict(result.status)
    return (
        status,
        f"the inner planner reported {last.outcome.raw_status or last.outcome.status.name} on the whole problem",
    )


def _final_status_whole(problem: Problem, found, attempts) -> tuple[PlanGenerationResultStatus, str]:
    """Without our reader's view of the problem, unified-planning's own validator decides."""
    if not attempts:
        return PlanGenerationResultStatus.TIMEOUT, "out of time before a valid plan was found"
    last = attempts[-1]
    if found is not None and last.outcome.status is PlannerStatus.SOLVED:
        validator = SequentialPlanValidator(environment=problem.environment)
        if validator.validate(problem, found).status is ValidationResultStatus.VALID:
            return (
                PlanGenerationResultStatus.SOLVED_SATISFICING,
                f"plan of {counted(len(found.actions), 'step')} validated on the original problem",
            )
        return PlanGenerationResultStatus.INTERNAL_ERROR, "the inner planner's plan does not validate"
    return up_status(last.outcome.status), f"the inner planner reported {last.outcome.raw_status} on the whole problem"


# --------------------------------------------------------------------------- building and mapping back


def restrict_problem(problem: Problem, removed: Set[str]) -> Problem:
    """A new UP problem without the objects named in ``removed`` and the initial facts that mention them.

    Design choice: the pruned problem is built in UP directly rather than by
    reading the pruned PDDL text back with ``PDDLReader``.  It shares the
    original's fluents, actions, goals and metrics and keeps every name, so
    the inner planner's plan is a plan of the original problem up to object
    identity (``lift_plan`` maps it by name), and no PDDL is parsed a second
    time (the reader costs seconds at scale, and its problem would carry the
    writer's renamed names).  Only ``explicit_initial_values`` is read:
    ``initial_values`` would grow the user's problem.  The user's
    problem is never changed, even when nothing is removed: inner PDDL
    planners call ``initial_values`` on what they are given.
    """
    restricted = Problem(problem.name, problem.environment, initial_defaults=problem.initial_defaults)
    for fluent in problem.fluents:
        restricted.add_fluent(fluent, default_initial_value=problem.fluents_defaults.get(fluent))
    restricted.add_actions(problem.actions)
    restricted.add_objects([obj for obj in problem.all_objects if obj.name not in removed])
    for fluent_exp, value in problem.explicit_initial_values.items():
        if any(arg.is_object_exp() and arg.object().name in removed for arg in fluent_exp.args):
            continue
        restricted.set_initial_value(fluent_exp, value)
    for goal in problem.goals:
        restricted.add_goal(goal)
    for metric in problem.quality_metrics:
        restricted.add_quality_metric(metric)
    return restricted


def lift_plan(plan: up.plans.Plan, problem: Problem) -> SequentialPlan | None:
    """The plan with every action and object replaced by the original problem's, by name.

    Returns None when the plan is not sequential or names something the
    original problem does not have.
    """
    if not isinstance(plan, SequentialPlan):
        return None
    em = problem.environment.expression_manager
    steps = []
    try:
        for step in plan.actions:
            action = problem.action(step.action.name)
            arguments = []
            for parameter in step.actual_parameters:
                if parameter.is_object_exp():
                    arguments.append(em.ObjectExp(problem.object(parameter.object().name)))
                else:
                    arguments.append(parameter)
            steps.append(ActionInstance(action, tuple(arguments)))
    except UPValueError:
        return None
    return SequentialPlan(steps, problem.environment)


# --------------------------------------------------------------------------- registration


def register_relevance_engine(environment: up.environment.Environment | None = None) -> None:
    """Add the ``relevance`` meta-engine to ``environment``'s factory (the global one by default).

    Afterwards every compatible oneshot planner ``P`` is also available as
    ``relevance[P]``, e.g. ``OneshotPlanner(name="relevance[fast-downward]")``.
    Planners added to the factory later get their ``relevance[...]`` variant
    automatically.  Calling this again does nothing.  Equivalent ``up.ini``
    section: ``[meta-engine relevance]`` (see ``docs/up.ini.example``).
    The environment's credits stream is set to None: unified-planning's
    credits banner does not print.
    """
    environment = up.environment.get_environment(environment)
    environment.credits_stream = None  # no credits banners where this engine is used
    factory = environment.factory
    if any(name.startswith(f"{ENGINE_NAME}[") for name in factory.engines):
        return
    factory.add_meta_engine(ENGINE_NAME, __name__, RelevanceMetaEngine.__name__)


__all__ = [
    "ENGINE_NAME",
    "RelevanceMetaEngine",
    "lift_plan",
    "register_relevance_engine",
    "relevance_supported_kind",
    "restrict_problem",
]
