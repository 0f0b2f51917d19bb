"""The builtin validator: the simulator of ``pddl/simulator.py`` run on the original problem.

It covers ADL, numeric fluents, derived predicates and PDDL 2.1 timed plans,
and costs milliseconds, so it runs on every plan, however large the problem,
and it watches the deadline.  It does not check hard trajectory constraints
(PDDL3), so on a problem with them it cannot run.  The simulator's core (the
semantics of formulas, effects and happenings) is the formula layer's, in
``pddl/``; :func:`simulate` is its entry point for a whole plan: run it from
the initial state, check the goal, read the cost and the metric.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from relevance_plan.errors import SimulationTimeout, counted
from relevance_plan.pddl.formulas import Fluent, Modal, Node, Preference, children, walk
from relevance_plan.pddl.model import Domain, Problem
from relevance_plan.pddl.plans import Plan, PlanStep
from relevance_plan.planning.validation.verdicts import ValidationResult, ValidationStatus

TYPE_CHECKING = False
if TYPE_CHECKING:
    from relevance_plan.pddl.simulator import Simulator, WorldState


def validate_builtin(domain: Domain, problem: Problem, plan: Plan, deadline: float | None = None) -> ValidationResult:
    if any(_hard(constraint) for constraint in (domain.constraints, problem.constraints) if constraint is not None):
        return ValidationResult(
            status=ValidationStatus.UNAVAILABLE, validator="builtin", message="it does not check trajectory constraints"
        )
    try:
        result = simulate(domain, problem, plan, deadline)
    except SimulationTimeout as error:
        return ValidationResult(status=ValidationStatus.OUT_OF_TIME, validator="builtin", message=error.message)
    status = ValidationStatus.VALID if result.valid else ValidationStatus.INVALID
    return ValidationResult(
        status=status,
        validator="builtin",
        message=result.message,
        failed_step=result.failed_step,
        cost=result.cost,
        metric=result.metric,
    )


def _hard(constraint: Node) -> bool:
    """Whether a constraint has a part outside preferences (preferences are soft: never a plan's validity)."""
    if isinstance(constraint, Preference):
        return False
    return isinstance(constraint, Modal) or any(_hard(part) for part in children(constraint))


# --------------------------------------------------------------------------- the simulator's entry point


@dataclass(frozen=True)
class Simulation:
    """What the simulator found running a whole plan on a problem."""

    valid: bool
    message: str
    failed_step: int | None = None
    cost: float | None = None  # the total-cost fluent at the end, when the problem has one
    makespan: float | None = None  # timed plans
    metric: float | None = None  # the value of the problem's :metric at the end, when it can be evaluated
    metric_note: str = ""  # why the metric has no value (preferences, a value never set)


def simulate(
    domain: Domain, problem: Problem, plan: Plan | Sequence[PlanStep], deadline: float | None = None
) -> Simulation:
    """Run ``plan`` on ``problem``; a timed plan (steps with start times) gets PDDL 2.1 semantics."""
    from relevance_plan.pddl.simulator import Simulator, StepFailure, run_plan, why_false  # only when a plan is checked

    steps = plan.steps if isinstance(plan, Plan) else tuple(plan)
    simulator = Simulator(domain, problem, deadline)
    try:
        state, makespan = run_plan(simulator, steps)
        if not simulator.holds(problem.goal, state, {}):
            unmet = why_false(simulator, problem.goal, state, {})
            raise StepFailure(f"the goal is not satisfied at the end of the plan: {unmet}")
    except StepFailure as failure:
        return Simulation(False, failure.message, failure.step)
    cost = state.values.get(("total-cost",))
    if cost is None and "total-cost" in domain.functions:
        cost = 0.0
    metric, note = _metric(simulator, state, len(steps) if makespan is None else makespan)
    what = counted(len(steps), "step") + (f", makespan {makespan:g}" if makespan is not None else "")
    return Simulation(True, f"{what}, goal reached", cost=cost, makespan=makespan, metric=metric, metric_note=note)


def _metric(simulator: Simulator, state: WorldState, total_time: float) -> tuple[float | None, str]:
    """The problem's metric in the final state, or None and why not.  ``total-time`` is the
    makespan of a timed plan and, as in VAL, the number of steps of a sequential one."""
    from relevance_plan.pddl.simulator import StepFailure, WorldState

    metric = simulator.problem.metric
    if metric is None:
        return None, ""
    nodes = list(walk(metric.expression))
    if any(isinstance(node, Fluent) and node.function == "is-violated" for node in nodes):
        return None, "the metric counts violated preferences, which are not evaluated"
    final = WorldState(state.facts, {**state.values, ("total-time",): float(total_time)})
    try:
        return simulator.value(metric.expression, final, {}), ""
    except StepFailure as failure:
        return None, f"the metric cannot be evaluated: {failure.message}"
