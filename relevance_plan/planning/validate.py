"""Plan validation against the ORIGINAL problem.

Three validators, in a registry:
- ``builtin``: simulates the plan on our own model (typed STRIPS with ADL
  conditions, quantifiers, equality and conditional effects).  It costs
  milliseconds, so it runs on every plan, however large the problem.
- ``up``: unified-planning's ``SequentialPlanValidator`` (parses the files
  with UP's reader: seconds on large problems).
- ``val``: VAL's ``Validate`` when it is on PATH.
A validator that cannot run says so (``UNAVAILABLE``); that is never read as
valid or invalid.
"""

from __future__ import annotations

import enum
import itertools
import shutil
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass

from relevance_plan.pddl.reader import Domain, Formula, Problem, all_objects

PlanStep = tuple  # (action, arg1, arg2, ...), lower-case


class ValidationStatus(enum.Enum):
    VALID = "valid"
    INVALID = "invalid"
    UNAVAILABLE = "unavailable"


@dataclass(frozen=True)
class ValidationResult:
    status: ValidationStatus
    validator: str
    message: str = ""
    failed_step: int | None = None  # 1-based; None for a goal failure or success

    @property
    def valid(self) -> bool:
        return self.status is ValidationStatus.VALID


def parse_plan_text(text: str) -> tuple[PlanStep, ...]:
    """Read a plan in Fast Downward's format: one '(action arg ...)' per line, ';' comments."""
    steps = []
    for line in text.splitlines():
        line = line.strip()
        if not line or line.startswith(";"):
            continue
        line = line.split(";", 1)[0].strip()
        if line.startswith("(") and line.endswith(")"):
            line = line[1:-1]
        parts = line.lower().split()
        if parts:
            steps.append(tuple(parts))
    return tuple(steps)


def format_plan(steps: Sequence[PlanStep], problem: Problem | None = None, cost: int | None = None) -> str:
    """Fast Downward's plan format, with the user's own spelling of object names."""
    display = problem.display if problem is not None else (lambda name: name)
    lines = ["(" + " ".join([step[0]] + [display(arg) for arg in step[1:]]) + ")" for step in steps]
    lines.append(f"; cost = {len(steps)} (unit cost)" if cost is None else f"; cost = {cost}")
    return "\n".join(lines) + "\n"


# --------------------------------------------------------------------------- builtin


class _Simulator:
    def __init__(self, domain: Domain, problem: Problem):
        self.domain = domain
        self.problem = problem
        self.objects = all_objects(domain, problem)
        self._by_type: dict[str, tuple[str, ...]] = {}

    def objects_of(self, type_name: str) -> tuple[str, ...]:
        cached = self._by_type.get(type_name)
        if cached is None:
            cached = tuple(o for o, t in self.objects.items() if self.domain.is_subtype(t, type_name))
            self._by_type[type_name] = cached
        return cached

    def bindings(self, params, binding: Mapping[str, str]):
        pools = [self.objects_of(type_name) for _, type_name in params]
        names = [name for name, _ in params]
        for values in itertools.product(*pools):
            inner = dict(binding)
            inner.update(zip(names, values))
            yield inner

    def holds(self, formula: Formula, state: frozenset, binding: Mapping[str, str]) -> bool:
        kind = formula[0]
        if kind == "atom":
            args = tuple(binding.get(arg, arg) for arg in formula[2])
            if formula[1] == "=":
                return args[0] == args[1]
            return (formula[1],) + args in state
        if kind == "and":
            return all(self.holds(part, state, binding) for part in formula[1:])
        if kind == "or":
            return any(self.holds(part, state, binding) for part in formula[1:])
        if kind == "not":
            return not self.holds(formula[1], state, binding)
        if kind == "imply":
            return (not self.holds(formula[1], state, binding)) or self.holds(formula[2], state, binding)
        if kind == "exists":
            return any(self.holds(formula[2], state, inner) for inner in self.bindings(formula[1], binding))
        if kind == "forall":
            return all(self.holds(formula[2], state, inner) for inner in self.bindings(formula[1], binding))
        if kind == "true":
            return True
        raise ValueError(f"unknown formula kind {kind!r}")

    def effects(self, effect: Formula, state: frozenset, binding, adds: set, deletes: set) -> None:
        kind = effect[0]
        if kind == "atom":
            adds.add((effect[1],) + tuple(binding.get(arg, arg) for arg in effect[2]))
        elif kind == "not":
            atom = effect[1]
            deletes.add((atom[1],) + tuple(binding.get(arg, arg) for arg in atom[2]))
        elif kind == "and":
            for part in effect[1:]:
                self.effects(part, state, binding, adds, deletes)
        elif kind == "forall":
            for inner in self.bindings(effect[1], binding):
                self.effects(effect[2], state, inner, adds, deletes)
        elif kind == "when":
            # Conditions are evaluated in the state before the action.
            if self.holds(effect[1], state, binding):
                self.effects(effect[2], state, binding, adds, deletes)
        # ("cost",): numeric cost, no effect on the state


def validate_builtin(domain: Domain, problem: Problem, plan: Sequence[PlanStep]) -> ValidationResult:
    simulator = _Simulator(domain, problem)
    state = frozenset(problem.init)
    for number, step in enumerate(plan, start=1):
        action = domain.action(step[0])
        shown = "(" + " ".join(step) + ")"
        if action is None:
            return ValidationResult(
                ValidationStatus.INVALID, "builtin", f"step {number} {shown}: unknown action", number
            )
        args = step[1:]
        if len(args) != len(action.parameters):
            return ValidationResult(
                ValidationStatus.INVALID,
                "builtin",
                f"step {number} {shown}: expects {len(action.parameters)} arguments",
                number,
            )
        for arg, (_, type_name) in zip(args, action.parameters):
            if arg not in simulator.objects:
                return ValidationResult(
                    ValidationStatus.INVALID, "builtin", f"step {number} {shown}: unknown object '{arg}'", number
                )
            if not domain.is_subtype(simulator.objects[arg], type_name):
                return ValidationResult(
                    ValidationStatus.INVALID,
                    "builtin",
                    f"step {number} {shown}: '{arg}' is not of type {type_name}",
                    number,
                )
        binding = {name: arg for (name, _), arg in zip(action.parameters, args)}
        if not simulator.holds(action.precondition, state, binding):
            return ValidationResult(
                ValidationStatus.INVALID, "builtin", f"step {number} {shown}: precondition not satisfied", number
            )
        adds: set = set()
        deletes: set = set()
        simulator.effects(action.effect, state, binding, adds, deletes)
        state = frozenset((state - deletes) | adds)
    if not simulator.holds(problem.goal, state, {}):
        return ValidationResult(ValidationStatus.INVALID, "builtin", "the goal is not satisfied at the end of the plan")
    return ValidationResult(ValidationStatus.VALID, "builtin", f"{len(plan)} steps, goal reached")


# --------------------------------------------------------------------------- unified-planning


def validate_with_up(domain: Domain, problem: Problem, plan: Sequence[PlanStep]) -> ValidationResult:
    """Validate with unified-planning's sequential plan validator, from the original files."""
    if domain.path is None or problem.path is None:
        return ValidationResult(ValidationStatus.UNAVAILABLE, "up", "needs the domain and problem files on disk")
    try:
        from unified_planning.engines.plan_validator import SequentialPlanValidator
        from unified_planning.engines.results import ValidationResultStatus
        from unified_planning.io import PDDLReader
        from unified_planning.shortcuts import get_environment
    except ImportError as error:  # pragma: no cover - depends on the installation
        return ValidationResult(ValidationStatus.UNAVAILABLE, "up", f"unified-planning not importable: {error}")
    get_environment().credits_stream = None
    try:
        reader = PDDLReader()
        up_problem = reader.parse_problem(domain.path, problem.path)
        objects = {o.name.lower(): o for o in up_problem.all_objects}
        actions = {a.name.lower(): a for a in up_problem.actions}
        from unified_planning.plans import ActionInstance, SequentialPlan

        instances = []
        for number, step in enumerate(plan, start=1):
            if step[0] not in actions or any(arg not in objects for arg in step[1:]):
                return ValidationResult(
                    ValidationStatus.INVALID, "up", f"step {number}: unknown action or object", number
                )
            instances.append(ActionInstance(actions[step[0]], tuple(objects[arg] for arg in step[1:])))
        result = SequentialPlanValidator(environment=up_problem.environment).validate(
            up_problem, SequentialPlan(instances)
        )
    except Exception as error:  # UP raises many unrelated types; report, never guess
        return ValidationResult(ValidationStatus.UNAVAILABLE, "up", f"unified-planning failed: {error}".splitlines()[0])
    if result.status == ValidationResultStatus.VALID:
        return ValidationResult(ValidationStatus.VALID, "up", "valid")
    reason = str(getattr(result, "reason", "") or getattr(result, "log_messages", "") or "invalid")
    return ValidationResult(ValidationStatus.INVALID, "up", reason.splitlines()[0] if reason else "invalid")


# --------------------------------------------------------------------------- VAL


def val_available() -> bool:
    return shutil.which("Validate") is not None


def validate_with_val(domain: Domain, problem: Problem, plan: Sequence[PlanStep]) -> ValidationResult:
    from relevance_plan.planning.runner import run_val  # subprocess access lives in the runner module

    if not val_available():
        return ValidationResult(ValidationStatus.UNAVAILABLE, "val", "VAL's Validate is not on PATH")
    if domain.path is None or problem.path is None:
        return ValidationResult(ValidationStatus.UNAVAILABLE, "val", "needs the domain and problem files on disk")
    ok, message = run_val(domain.path, problem.path, format_plan(plan))
    if ok is None:
        return ValidationResult(ValidationStatus.UNAVAILABLE, "val", message)
    return ValidationResult(ValidationStatus.VALID if ok else ValidationStatus.INVALID, "val", message)


Validator = Callable[[Domain, Problem, Sequence[PlanStep]], ValidationResult]

VALIDATORS: dict[str, Validator] = {
    "builtin": validate_builtin,
    "up": validate_with_up,
    "val": validate_with_val,
}


def default_validators() -> tuple[str, ...]:
    """Always the builtin simulator; VAL as a second opinion when it is installed."""
    return ("builtin", "val") if val_available() else ("builtin",)


def validate_plan(
    domain: Domain, problem: Problem, plan: Sequence[PlanStep], validators: Sequence[str] | None = None
) -> ValidationResult:
    """Run each validator; the plan is valid only if every one that ran says so.

    If none could run, the result is UNAVAILABLE (the caller must say so loudly).
    """
    names = tuple(validators) if validators else default_validators()
    ran: list[ValidationResult] = []
    unavailable: list[ValidationResult] = []
    for name in names:
        result = VALIDATORS[name](domain, problem, plan)
        if result.status is ValidationStatus.INVALID:
            return result
        (ran if result.status is ValidationStatus.VALID else unavailable).append(result)
    if not ran:
        reasons = "; ".join(f"{r.validator}: {r.message}" for r in unavailable)
        return ValidationResult(ValidationStatus.UNAVAILABLE, "+".join(names), reasons)
    return ValidationResult(ValidationStatus.VALID, "+".join(r.validator for r in ran), ran[0].message)
