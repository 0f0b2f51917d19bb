"""A unified-planning meta-engine: prune irrelevant objects, then plan.

``relevance[<planner>]`` wraps any oneshot planner of the unified-planning
library (``relevance[fast-downward]``, ``relevance[pyperplan]``, ...).  For each
problem it

1. exports the problem once with UP's ``PDDLWriter`` (on a clone: the writer
   reads ``initial_values``, which fills the problem's own dictionary of
   explicit initial values — FACTS.md) and reads the text with our reader;
2. scores the objects (the knowledge model when one applies to the domain,
   else the domain-independent ``goal`` scorer), thresholds them and closes
   the kept set over the initial state's constraints (``prune_with_scores``);
3. gives the inner planner a UP problem restricted to the kept objects,
   maps its plan back to the original problem's actions and objects and
   validates it there with UP's ``SequentialPlanValidator``;
4. when the pruned problem is unsolvable, the planner fails or runs out of
   its share of the time, or the plan does not validate, lowers the
   thresholds (factor 0.5), puts back the best-scored removed objects and
   tries again, as ``planning.plan_task`` does; the last attempt is the whole
   problem, so only that attempt can prove the problem unsolvable.

Register it with :func:`register_relevance_engine` (or an ``up.ini``
section, see ``docs/up.ini.example``) and ask for it by name::

    register_relevance_engine()
    with OneshotPlanner(name="relevance[fast-downward]") as planner:
        result = planner.solve(problem, timeout=60)

Options go through UP's ``params``: ``tau_class``, ``tau_element``,
``scorer`` (``goal``, ``model`` or ``random``), ``model`` (a knowledge-model
file), ``domain`` (the knowledge-model domain to look up under ``domains/``),
``relax_factor``, ``first_share`` and ``seed``; every other parameter goes to
the inner planner unchanged.
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from typing import IO, AbstractSet, Callable, Optional, Type

import unified_planning as up
from unified_planning.engines import Engine, MetaEngine, OptimalityGuarantee
from unified_planning.engines.mixins import OneshotPlannerMixin
from unified_planning.engines.plan_validator import SequentialPlanValidator
from unified_planning.engines.results import (
    POSITIVE_OUTCOMES,
    LogLevel,
    LogMessage,
    PlanGenerationResult,
    PlanGenerationResultStatus,
    ValidationResultStatus,
)
from unified_planning.exceptions import UPValueError
from unified_planning.io import PDDLWriter
from unified_planning.model import Problem, ProblemKind
from unified_planning.model.problem_kind_versioning import LATEST_PROBLEM_KIND_VERSION
from unified_planning.plans import ActionInstance, SequentialPlan

from relevance_plan.errors import RelevancePlanError, UsageError
from relevance_plan.relevance.knowledge import KnowledgeModel, load_model
from relevance_plan.pddl.reader import read_domain, read_problem
from relevance_plan.planning.loop import resolve_model
from relevance_plan.relevance.prune import DEFAULT_TAU, PruneResult, Thresholds, prune_with_scores, score_task, widen
from relevance_plan.relevance.scorers import SCORERS, ScoreRequest, ScoreResult, Task

ENGINE_NAME = "relevance"

# Scorers a user may choose through params; the oracle needs a generator's sidecar.
ENGINE_SCORERS = tuple(name for name in SCORERS if name != "oracle")

# The params this engine takes for itself; the others go to the inner planner.
OWN_PARAMS = frozenset({"tau_class", "tau_element", "scorer", "model", "domain", "relax_factor", "first_share", "seed"})

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

# Inner results after which trying the same problem with more objects is pointless:
# go straight to the whole problem instead.
_FAULTS = frozenset({PlanGenerationResultStatus.INTERNAL_ERROR, PlanGenerationResultStatus.UNSUPPORTED_PROBLEM})


def relevance_supported_kind() -> ProblemKind:
    """The problem features the relevance stage itself handles."""
    kind = ProblemKind(version=LATEST_PROBLEM_KIND_VERSION)
    for feature_class, features in _READER_FEATURES.items():
        for feature in features:
            getattr(kind, f"set_{feature_class}")(feature)
    return kind


@dataclass(frozen=True)
class Attempt:
    """One inner-planner run, for the log and the metrics."""

    number: int
    objects_kept: int
    thresholds: Thresholds | None  # None for the whole problem
    status: PlanGenerationResultStatus
    plan_valid: bool | None  # None: no plan to validate
    time_limit: float | None
    wall_time: float

    @property
    def full(self) -> bool:
        return self.thresholds is None

    def describe(self, total: int) -> str:
        what = (
            f"the whole problem ({total} objects)"
            if self.full
            else f"{self.objects_kept} of {total} objects (tau_class={self.thresholds.tau_class:g},"
            f" tau_element={self.thresholds.tau_element:g})"
        )
        outcome = self.status.name
        if self.plan_valid is not None:
            outcome += ", plan valid on the original problem" if self.plan_valid else ", plan INVALID on the original problem"
        limit = "no limit" if self.time_limit is None else f"limit {self.time_limit:.1f} s"
        return f"attempt {self.number}: {what}, {limit} -> {outcome} in {self.wall_time:.2f} s"


class RelevanceMetaEngine(MetaEngine, OneshotPlannerMixin):
    """Relevance-based object pruning in front of any oneshot planner.

    Instantiated by the factory as ``relevance[<planner>]``; keyword options
    are described in the module docstring.  The plan returned has always been
    validated on the original problem.
    """

    def __init__(
        self,
        *args,
        tau_class: float = DEFAULT_TAU,
        tau_element: float = DEFAULT_TAU,
        scorer: str | None = None,
        model: str | None = None,
        domain: str | None = None,
        relax_factor: float = 0.5,
        first_share: float = 0.5,
        seed: int = 0,
        **kwargs,
    ):
        # Our options are taken out here; the rest belongs to the inner planner.
        self._thresholds = Thresholds(float(tau_class), float(tau_element))
        if scorer is not None and scorer not in ENGINE_SCORERS:
            raise UsageError(f"unknown scorer '{scorer}' (choose from: {', '.join(ENGINE_SCORERS)})")
        if not 0.0 < float(relax_factor) < 1.0:
            raise UsageError(f"relax_factor must be in (0, 1), got {relax_factor}")
        if not 0.0 < float(first_share) <= 1.0:
            raise UsageError(f"first_share must be in (0, 1], got {first_share}")
        self._scorer = scorer
        self._model: KnowledgeModel | None = load_model(model) if model is not None else None
        self._domain = domain
        self._relax_factor = float(relax_factor)
        self._first_share = float(first_share)
        self._seed = int(seed)
        MetaEngine.__init__(self, *args, **kwargs)
        OneshotPlannerMixin.__init__(self)

    # ---------------------------------------------------------------- engine API

    @property
    def name(self) -> str:
        return f"{ENGINE_NAME}[{self.engine.name}]"

    @staticmethod
    def satisfies(optimality_guarantee: OptimalityGuarantee) -> bool:
        # Pruning may remove what an optimal plan needs.
        return optimality_guarantee == OptimalityGuarantee.SATISFICING

    @staticmethod
    def is_compatible_engine(engine: Type[Engine]) -> bool:
        if issubclass(engine, MetaEngine):
            # relevance[oversubscription[...]] would only be a weaker copy of relevance[...].
            return False
        classical = ProblemKind({"ACTION_BASED"}, version=LATEST_PROBLEM_KIND_VERSION)
        return engine.is_oneshot_planner() and engine.supports(classical)  # type: ignore[attr-defined]

    @staticmethod
    def _supported_kind(engine: Type[Engine]) -> ProblemKind:
        return relevance_supported_kind().intersection(engine.supported_kind())

    @staticmethod
    def _supports(problem_kind: ProblemKind, engine: Type[Engine]) -> bool:
        return problem_kind <= RelevanceMetaEngine._supported_kind(engine)

    @classmethod
    def get_credits(cls, **kwargs):
        inner = getattr(cls, "_engine_class", None)
        if inner is None:
            return None
        return inner.get_credits(**{key: value for key, value in kwargs.items() if key not in OWN_PARAMS})

    # ---------------------------------------------------------------- solving

    def _solve(
        self,
        problem: "up.model.AbstractProblem",
        heuristic: Optional[Callable[["up.model.state.State"], Optional[float]]] = None,
        timeout: Optional[float] = None,
        output_stream: Optional[IO[str]] = None,
    ) -> PlanGenerationResult:
        assert isinstance(problem, Problem)
        assert isinstance(self.engine, OneshotPlannerMixin)
        started = time.perf_counter()
        deadline = None if timeout is None else started + timeout
        messages: list[str] = []
        warning_lines: list[str] = []
        total = len(problem.all_objects)

        stage = None
        try:
            stage = _RelevanceStage.build(problem, self._choose_model, self._scorer, self._seed, messages, warning_lines)
        except RelevancePlanError as error:
            # Our reader or scorer cannot handle this problem: the whole problem is the only attempt.
            warning_lines.append(f"relevance stage skipped, planning on the whole problem: {error}")
        relevance_time = time.perf_counter() - started

        validator = SequentialPlanValidator(environment=problem.environment)
        attempts: list[Attempt] = []
        first_kept: int | None = None
        thresholds = self._thresholds
        current = stage.prune(thresholds) if stage is not None else None
        extra: frozenset = frozenset()
        last_result: PlanGenerationResult | None = None
        found: SequentialPlan | None = None
        while True:
            removed = stage.removed_objects(current) if current is not None else frozenset()
            full = not removed
            kept = total - len(removed)
            if first_kept is None:
                first_kept = kept
            remaining = None if deadline is None else deadline - time.perf_counter()
            if remaining is not None and remaining <= 0:
                break
            if remaining is None:
                limit = None
            elif full:
                limit = remaining
            else:
                limit = min(remaining, max(1.0, remaining * self._first_share))
            target = restrict_problem(problem, removed)
            attempt_started = time.perf_counter()
            result = self.engine.solve(target, heuristic, limit, output_stream)
            wall = time.perf_counter() - attempt_started
            last_result = result
            plan_valid = None
            if result.status in POSITIVE_OUTCOMES and result.plan is not None:
                candidate = lift_plan(result.plan, problem)
                plan_valid = candidate is not None and _is_valid(validator, problem, candidate)
                if plan_valid:
                    found = candidate
            attempts.append(
                Attempt(len(attempts) + 1, kept, None if full else thresholds, result.status, plan_valid, limit, wall)
            )
            messages.append(attempts[-1].describe(total))
            if found is not None or full:
                break
            if result.status in _FAULTS:
                warning_lines.append(f"the inner planner reported {result.status.name}: retrying on the whole problem")
                current = None
                continue
            # Widen: lower the thresholds and put back the best-ranked removed objects.
            widen_started = time.perf_counter()
            current, extra = widen(current, self._relax_factor, extra, stage.model)
            thresholds = current.thresholds
            relevance_time += time.perf_counter() - widen_started

        status, summary = _final_status(found, attempts, last_result)
        final_kept = attempts[-1].objects_kept if attempts else total
        messages.append(
            f"{summary}; kept {final_kept} of {total} objects"
            f" (first attempt {first_kept}), {len(attempts)} attempt(s)"
        )
        metrics = {
            "objects_total": str(total),
            "objects_kept": str(final_kept),
            "objects_kept_first_attempt": str(first_kept),
            "objects_removed_first_attempt": str(total - first_kept),
            "attempts": str(len(attempts)),
            "scorer": stage.scores.scorer if stage is not None else "none",
            "relevance_time": f"{relevance_time:.4f}",
            "planner_time": f"{sum(a.wall_time for a in attempts):.4f}",
            "engine_internal_time": f"{time.perf_counter() - started:.4f}",
        }
        logs = [LogMessage(LogLevel.WARNING, f"{ENGINE_NAME}: {text}") for text in warning_lines]
        logs += [LogMessage(LogLevel.INFO, f"{ENGINE_NAME}: {text}") for text in messages]
        if last_result is not None and last_result.log_messages:
            logs += last_result.log_messages
        return PlanGenerationResult(status, found, self.name, metrics=metrics, log_messages=logs)

    def _choose_model(self, domain_name: str) -> KnowledgeModel | None:
        """The ``model`` param, else a repository model for the ``domain`` param or the exported name."""
        if self._model is not None:
            return self._model
        if self._domain is not None:
            candidates = [self._domain]
        else:
            # The writer names the domain '<problem name>-domain'.
            candidates = [domain_name, domain_name.removesuffix("-domain")]
        for candidate in candidates:
            model = resolve_model(candidate, None, None)
            if model is not None:
                return model
        return None


# --------------------------------------------------------------------------- the relevance stage


@dataclass(frozen=True)
class _RelevanceStage:
    """The problem as our reader sees it, its scores, and the map back to UP names."""

    task: Task
    scores: ScoreResult
    model: KnowledgeModel | None
    up_names: dict  # reader name (lower-cased writer name) -> the UP object's own name

    @classmethod
    def build(cls, problem: Problem, choose_model, scorer: str | None, seed: int, messages: list, warnings: list):
        # One export.  The writer reads problem.initial_values, which fills the
        # problem's explicit initial values with every ground atom: write a clone.
        writer = PDDLWriter(problem.clone())
        domain_text = writer.get_domain()
        problem_text = writer.get_problem()
        domain = read_domain(domain_text, "<unified-planning domain>")
        task = Task(domain, read_problem(problem_text, domain, "<unified-planning problem>"))
        up_names = {name: writer.get_item_named(name).name for name in task.problem.objects}
        model = choose_model(domain.name)
        chosen = scorer or ("model" if model is not None else "goal")
        if chosen == "model" and model is None:
            warnings.append("no knowledge model applies to this problem: using the goal scorer")
            chosen = "goal"
        scores = score_task(task, chosen, ScoreRequest(model=model, seed=seed))
        if not scores.sufficient:
            warnings.append(f"the {chosen} scorer has too little to go on ({scores.insufficiency}): using the goal scorer")
            model = None
            scores = score_task(task, "goal", ScoreRequest(seed=seed))
        messages.append(f"scored {len(task.problem.objects)} objects with the {scores.scorer} scorer")
        return cls(task, scores, model, up_names)

    def prune(self, thresholds: Thresholds, extra: AbstractSet[str] = frozenset()) -> PruneResult:
        return prune_with_scores(self.task, self.scores, thresholds, self.model, extra)

    def removed_objects(self, result: PruneResult) -> frozenset:
        return frozenset(self.up_names[name] for name in result.removed)


# --------------------------------------------------------------------------- building and mapping back


def restrict_problem(problem: Problem, removed: AbstractSet[str]) -> Problem:
    """A new UP problem without the objects named in ``removed`` and the initial facts that mention them.

    Design choice: the pruned problem is built in UP directly rather than by
    reading the pruned PDDL text back with ``PDDLReader``.  It shares the
    original's fluents, actions, goals and metrics and keeps every name, so
    the inner planner's plan is a plan of the original problem up to object
    identity (``lift_plan`` maps it by name), and no PDDL is parsed a second
    time (the reader costs seconds at scale, and its problem would carry the
    writer's renamed names).  Only ``explicit_initial_values`` is read:
    ``initial_values`` would grow the user's problem (FACTS.md).  The user's
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


def lift_plan(plan: "up.plans.Plan", problem: Problem) -> SequentialPlan | None:
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


def _is_valid(validator: SequentialPlanValidator, problem: Problem, plan: SequentialPlan) -> bool:
    return validator.validate(problem, plan).status is ValidationResultStatus.VALID


def _final_status(found, attempts, last_result) -> tuple[PlanGenerationResultStatus, str]:
    if found is not None:
        summary = f"plan of {len(found.actions)} steps validated on the original problem"
        if attempts[-1].full and last_result.status is PlanGenerationResultStatus.SOLVED_OPTIMALLY:
            return PlanGenerationResultStatus.SOLVED_OPTIMALLY, summary
        return PlanGenerationResultStatus.SOLVED_SATISFICING, summary
    if not attempts or not attempts[-1].full:
        # The time ran out before the whole problem was tried: a pruned problem's
        # failure says nothing about the user's problem.
        return PlanGenerationResultStatus.TIMEOUT, "out of time before a valid plan was found"
    last = attempts[-1]
    if last.plan_valid is False:
        return PlanGenerationResultStatus.INTERNAL_ERROR, "the inner planner's plan for the whole problem does not validate"
    if last.status in POSITIVE_OUTCOMES:
        return PlanGenerationResultStatus.INTERNAL_ERROR, "the inner planner reported a solution without a plan"
    if last.status is PlanGenerationResultStatus.UNSOLVABLE_PROVEN:
        return last.status, "the problem is unsolvable (proven on the whole problem)"
    return last.status, f"the inner planner reported {last.status.name} on the whole problem"


# --------------------------------------------------------------------------- registration


def register_relevance_engine(environment: "up.environment.Environment | None" = None) -> None:
    """Add the ``relevance`` meta-engine to ``environment``'s factory (the global one by default).

    Afterwards every compatible oneshot planner ``P`` is also available as
    ``relevance[P]``, e.g. ``OneshotPlanner(name="relevance[fast-downward]")``.
    Planners added to the factory later get their ``relevance[...]`` variant
    automatically.  Calling this again does nothing.  Equivalent ``up.ini``
    section: ``[meta-engine relevance]`` (see ``docs/up.ini.example``).
    """
    factory = up.environment.get_environment(environment).factory
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
