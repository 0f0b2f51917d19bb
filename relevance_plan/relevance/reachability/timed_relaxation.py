"""A sharper relaxed check for temporal and numeric problems, on a small kept set.

``relaxed_reachability`` (``exploration.py``) reads a durative action as one
action with all its conditions and ignores numbers.  Here, on the kept
objects only:

* a durative action is split into its start and its end: the start needs
  the at-start conditions and the over-all ones its own start effects do not
  add, and adds the at-start effects; the end needs the start, the at-end
  and over-all conditions, and adds the at-end effects (an at-end condition
  that the action's own start brings about is met, as it is in a plan);
* every ground numeric fluent has an interval of values reachable so far
  (the hull of its initial value and whatever assignments give it); an
  ``increase`` by an amount that can be positive widens it to ``+inf``
  (the action may repeat), a ``decrease`` to ``-inf``, a ``scale`` either way;
  a comparison holds if some values of the intervals of its two sides satisfy it.

Deletes, negative, disjunctive and quantified conditions and the conditions
of conditional effects are ignored, strict comparisons are read as non-strict:
all of it only admits more, so when the goal is not reached here no plan exists
on these objects (``False`` is a proof); when it is reached, nothing is known
(``True`` does not mean solvable).  Past a grounding budget the answer is ``None``.
"""

from __future__ import annotations

import functools
import itertools
import math
import time
from collections.abc import Iterator, Mapping, Set
from dataclasses import dataclass

from relevance_plan.pddl.formulas import (
    Arithmetic,
    Atom,
    Comparison,
    Expression,
    Fluent,
    Formula,
    Number,
    NumericVariable,
    Timed,
    conjuncts,
    conjuncts_timed,
    effect_literals,
    numeric_effects,
)
from relevance_plan.pddl.model import Action
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.analysis.types import static_predicates
from relevance_plan.relevance.reachability.budget import OutOfBudget

GROUND_BUDGET = 200_000  # candidate bindings tried before the check gives up (None: unknown)
SECONDS = 1.0  # and the whole check's bound (grounding and fixpoint): it must stay cheaper than a planner run
WIDEN_AFTER = 4  # rounds in which a fluent's bound moves before it is widened to infinity

Interval = tuple[float, float]  # (low, high), closed hull; low > high: no value yet
NOTHING: Interval = (math.inf, -math.inf)
EVERYTHING: Interval = (-math.inf, math.inf)
GroundFluent = tuple[str, ...]


@dataclass(frozen=True)
class _Snap:
    """A ground instantaneous part: a plain action, or a durative action's start or end."""

    pre: tuple[tuple[str, ...], ...]
    tests: tuple[Comparison, ...]  # ground comparisons
    add: tuple[tuple[str, ...], ...]
    numeric: tuple[tuple[str, GroundFluent, Expression], ...]  # (op, fluent, ground value expression)


def applies(task: PlanningTask) -> bool:
    """Whether the sharper check can refute what ``relaxed_reachability`` admits: only through numbers.

    Split into its start and its end, a durative action fires whenever the one action that
    ``relaxed_reachability`` reads it as fires (each part needs a subset of that action's
    conditions), so without numeric conditions, effects or goals the check admits at least as much
    and its time is lost (the tool's largest cost on a problem a planner solves in tenths of a second)."""
    domain = task.typing.domain
    if not (domain.temporal or domain.numeric):
        return False
    if any(True for _ in _comparisons(task.typing.problem.goal)):
        return True
    return any(part.tests or part.numeric for action in domain.relaxed_actions for part in _parts(action))


def timed_relaxed_reachability(task: PlanningTask, kept: Set[str], budget: int = GROUND_BUDGET) -> bool | None:
    """Whether the goal is reachable on ``kept`` under the relaxation above (None: gave up)."""
    try:
        check = _Check(task, kept, budget)
        return check.run()
    except OutOfBudget:
        return None


def _interval(expression: Expression, values: Mapping[GroundFluent, Interval], duration: Interval) -> Interval:
    if isinstance(expression, Number):
        return (expression.value, expression.value)
    if isinstance(expression, Fluent):
        return values.get((expression.function, *expression.args), NOTHING)
    if isinstance(expression, NumericVariable):
        return duration
    parts = [_interval(arg, values, duration) for arg in expression.args]
    if any(low > high for low, high in parts):
        return NOTHING
    op = expression.op
    if len(parts) == 1:
        low, high = parts[0]
        return (-high, -low) if op == "-" else (low, high)
    result = parts[0]
    for other in parts[1:]:
        result = _combine(op, result, other)
    return result


def _combine(op: str, a: Interval, b: Interval) -> Interval:
    if op == "+":
        return (a[0] + b[0], a[1] + b[1])
    if op == "-":
        return (a[0] - b[1], a[1] - b[0])
    if op == "/":
        if b[0] <= 0 <= b[1]:
            return EVERYTHING
        b = (1 / b[1], 1 / b[0])
    products = [_times(x, y) for x in a for y in b]
    return (min(products), max(products))


def _times(x: float, y: float) -> float:
    return 0.0 if x == 0 or y == 0 else x * y  # 0 * inf is 0 for a bound that is exactly zero


def _admits(op: str, left: Interval, right: Interval) -> bool:
    if left[0] > left[1] or right[0] > right[1]:
        return False  # an undefined fluent satisfies no comparison
    if op in ("<", "<="):
        return left[0] <= right[1]
    if op in (">", ">="):
        return left[1] >= right[0]
    return left[0] <= right[1] and right[0] <= left[1]  # "=": the intervals meet


def _ground_expression(expression: Expression, binding: Mapping[str, str]) -> Expression:
    if isinstance(expression, Fluent):
        return Fluent(expression.function, tuple(binding.get(a, a) for a in expression.args))
    if isinstance(expression, Arithmetic):
        return Arithmetic(expression.op, tuple(_ground_expression(a, binding) for a in expression.args))
    return expression


def _atoms(formula: Formula) -> Iterator[Atom]:
    for part in conjuncts(formula):
        if isinstance(part, Atom):
            yield part


def _comparisons(formula: Formula) -> Iterator[Comparison]:
    for part in conjuncts(formula):
        if isinstance(part, Comparison):
            yield part


class _Check:
    def __init__(self, task: PlanningTask, kept: Set[str], budget: int):
        domain, problem = task.typing.domain, task.typing.problem
        self.domain = domain
        self.budget = budget
        self.deadline = time.monotonic() + SECONDS
        self.types_of = dict(domain.constants)
        self.types_of.update(problem.objects)
        allowed = (set(kept) & problem.objects.keys()) | set(domain.constants)
        self.allowed = allowed
        self.objects_by_type: dict[str, list[str]] = {}
        timed_predicates = {literal.atom[0] for literal in problem.timed_literals if literal.atom}
        self.static = static_predicates(domain) - timed_predicates - domain.derived_predicates
        # the facts and values of the kept objects only, through the index (it holds numeric terms too)
        self.facts: set[tuple[str, ...]] = set()
        self.values: dict[GroundFluent, Interval] = {}
        init, numeric_init = problem.init, problem.numeric_init
        by_object = task.init_index.by_object
        for name in sorted(allowed):
            for atom in by_object.get(name, ()):
                if all(arg in allowed for arg in atom[1:]):
                    if atom in init:
                        self.facts.add(atom)
                    value = numeric_init.get(atom)
                    if value is not None:
                        self.values[atom] = (value, value)
        for atom in init:
            if len(atom) == 1:
                self.facts.add(atom)
        for fluent, value in numeric_init.items():
            if len(fluent) == 1:
                self.values[fluent] = (value, value)
        self.facts |= {
            literal.atom
            for literal in problem.timed_literals
            if literal.atom is not None and not literal.negated and all(a in allowed for a in literal.atom[1:])
        }
        for literal in problem.timed_literals:
            if literal.fluent is not None and literal.value is not None:
                low, high = self.values.get(literal.fluent, NOTHING)
                self.values[literal.fluent] = (min(low, literal.value), max(high, literal.value))
        # a quantified numeric effect may change fluents this check does not track: it gives up
        if any(
            quantified for action in domain.relaxed_actions for _, _, quantified, _ in numeric_effects(action.effect)
        ):
            raise OutOfBudget
        self.goal_atoms = [(a.predicate, *a.args) for a in _atoms(problem.goal)]
        self.goal_tests = list(_comparisons(problem.goal))
        self.snaps: list[_Snap] = []
        for action in domain.relaxed_actions:
            self._ground(action)

    # ------------------------------------------------------------------ grounding

    def _objects(self, type_name: str) -> list[str]:
        found = self.objects_by_type.get(type_name)
        if found is None:
            found = self.objects_by_type[type_name] = sorted(
                o for o in self.allowed if self.domain.is_subtype(self.types_of.get(o, "object"), type_name)
            )
        return found

    def _ground(self, action: Action) -> None:
        variables = [v for v, _ in action.parameters]
        domains = [self._objects(t) for _, t in action.parameters]
        condition_atoms = list(_atoms(action.precondition))
        static = [a for a in condition_atoms if a.predicate in self.static]
        # each static condition is tested as soon as its last variable is bound
        position = {v: i for i, v in enumerate(variables)}
        checks: dict[int, list[Atom]] = {}
        for atom in static:
            last = max((position[a] for a in atom.args if a in position), default=-1)
            checks.setdefault(last, []).append(atom)
        if any(not self._holds(a, {}) for a in checks.get(-1, ())):
            return
        parts = _parts(action)
        spent = 0

        def extend(i: int, binding: dict[str, str]) -> Iterator[dict[str, str]]:
            nonlocal spent
            if i == len(variables):
                yield binding
                return
            for value in domains[i]:
                spent += 1
                if spent > self.budget or (spent & 1023 == 0 and time.monotonic() > self.deadline):
                    raise OutOfBudget
                binding[variables[i]] = value
                if all(self._holds(a, binding) for a in checks.get(i, ())):
                    yield from extend(i + 1, binding)
            binding.pop(variables[i], None)

        for binding in extend(0, {}):
            self._add_snaps(parts, dict(binding))
        self.budget -= spent

    def _each(self, quantified: tuple[tuple[str, str], ...]) -> Iterator[dict[str, str]]:
        """Every binding of a quantified effect's variables to kept objects (one empty one when none)."""
        names = [v for v, _ in quantified]
        for values in itertools.product(*(self._objects(t) for _, t in quantified)):
            yield dict(zip(names, values))

    def _holds(self, atom: Atom, binding: Mapping[str, str]) -> bool:
        return (atom.predicate, *(binding.get(a, a) for a in atom.args)) in self.facts

    def _add_snaps(self, parts: list[_Part], binding: Mapping[str, str]) -> None:
        marker: tuple[str, ...] | None = None
        if len(parts) == 2:
            marker = ("#started", str(id(parts[0])), *(binding[v] for v in sorted(binding)))
        get = binding.get
        for index, part in enumerate(parts):
            pre = tuple([(a.predicate, *[get(x, x) for x in a.args]) for a in part.pre])
            add = [(a.predicate, *[get(x, x) for x in a.args]) for a in part.plain_add]
            for a, quantified in part.quantified_add:  # one atom for each binding of the quantified variables
                add.extend((a.predicate, *[each.get(x, get(x, x)) for x in a.args]) for each in self._each(quantified))
            if marker is not None:
                if index == 1:
                    pre += (marker,)
                else:
                    add.append(marker)
            tests = tuple(
                Comparison(c.op, _ground_expression(c.left, binding), _ground_expression(c.right, binding))
                for c in part.tests
            )
            numeric = tuple(
                (op, (fluent.function, *[get(a, a) for a in fluent.args]), _ground_expression(value, binding))
                for op, fluent, value in part.numeric
            )
            self.snaps.append(_Snap(pre, tests, tuple(add), numeric))

    # ------------------------------------------------------------------ the fixpoint

    def run(self) -> bool:
        duration = (0.0, math.inf)
        moves: dict[tuple[GroundFluent, int], int] = {}
        pending = list(self.snaps)
        while True:
            if time.monotonic() > self.deadline:
                raise OutOfBudget
            changed = False
            waiting = []
            for snap in pending:
                if not all(fact in self.facts for fact in snap.pre) or not all(
                    _admits(t.op, _interval(t.left, self.values, duration), _interval(t.right, self.values, duration))
                    for t in snap.tests
                ):
                    waiting.append(snap)
                    continue
                for fact in snap.add:
                    if fact not in self.facts:
                        self.facts.add(fact)
                        changed = True
                if snap.numeric:
                    changed |= self._apply_numeric(snap, duration, moves)
                    waiting.append(snap)  # numeric effects may widen further as their operands do
            pending = waiting
            if not changed:
                break
        return all(atom in self.facts for atom in self.goal_atoms) and all(
            _admits(t.op, _interval(t.left, self.values, duration), _interval(t.right, self.values, duration))
            for t in self.goal_tests
        )

    def _apply_numeric(self, snap: _Snap, duration: Interval, moves: dict[tuple[GroundFluent, int], int]) -> bool:
        changed = False
        for op, fluent, value in snap.numeric:
            current = self.values.get(fluent, NOTHING)
            amount = _interval(value, self.values, duration)
            if amount[0] > amount[1]:
                continue
            low, high = current
            if op == "assign":
                low, high = min(low, amount[0]), max(high, amount[1])
            elif current[0] > current[1]:
                continue  # changing an undefined value is an error in a plan
            elif op in ("increase", "decrease"):
                up, down = (amount[1] > 0, amount[0] < 0) if op == "increase" else (amount[0] < 0, amount[1] > 0)
                high = math.inf if up else high
                low = -math.inf if down else low
            elif amount != (1.0, 1.0):  # scale-up / scale-down
                low, high = EVERYTHING
            if (low, high) != current:
                for side, old, new in ((0, current[0], low), (1, current[1], high)):
                    if old != new and not math.isinf(new):
                        count = moves[fluent, side] = moves.get((fluent, side), 0) + 1
                        if count > WIDEN_AFTER:  # an assignment chasing its own value: widen
                            low, high = (-math.inf, high) if side == 0 else (low, math.inf)
                self.values[fluent] = (low, high)
                changed = True
        return changed


@dataclass(frozen=True)
class _Part:
    pre: tuple[Atom, ...]
    tests: tuple[Comparison, ...]
    add: tuple[tuple[Atom, tuple[tuple[str, str], ...]], ...]  # (atom, its quantified (variable, type)s)
    numeric: tuple[tuple[str, Fluent, Expression], ...]

    @functools.cached_property
    def plain_add(self) -> tuple[Atom, ...]:
        return tuple(atom for atom, quantified in self.add if not quantified)

    @functools.cached_property
    def quantified_add(self) -> tuple[tuple[Atom, tuple[tuple[str, str], ...]], ...]:
        return tuple(item for item in self.add if item[1])


def _parts(action: Action) -> list[_Part]:
    """The action as one part, or a durative action as its start and its end (see the module docstring)."""

    def numbers(when: str | None) -> tuple[tuple[str, Fluent, Expression], ...]:
        return tuple(
            (effect.op, effect.fluent, effect.value)
            for effect, _, quantified, at in numeric_effects(action.effect)
            if not quantified and (when is None or (at or "start") == when)
        )

    def adds(when: str | None) -> tuple[tuple[Atom, tuple[tuple[str, str], ...]], ...]:
        return tuple(
            (item.atom, tuple((v, t) for v, t in item.quantified if v in item.atom.args))
            for item in effect_literals(action.effect)
            if item.is_add and (when is None or (item.when or "start") == when)
        )

    if not action.durative:
        condition = action.precondition
        return [_Part(tuple(_atoms(condition)), tuple(_comparisons(condition)), adds(None), numbers(None))]
    timed: dict[str, list[Formula]] = {"start": [], "end": [], "all": []}
    for part in conjuncts_timed(action.precondition):
        assert isinstance(part, Timed)
        timed[part.when].append(part.body)

    def atoms_at(when: str) -> list[Atom]:
        return [atom for body in timed[when] for atom in _atoms(body)]

    def tests_at(when: str) -> list[Comparison]:
        return [test for body in timed[when] for test in _comparisons(body)]

    start_adds = adds("start")
    added_at_start = {atom for atom, quantified in start_adds if not quantified}
    invariant = [atom for atom in atoms_at("all") if atom not in added_at_start]
    start = _Part(tuple(atoms_at("start") + invariant), tuple(tests_at("start")), start_adds, numbers("start"))
    end = _Part(
        tuple(atoms_at("end") + atoms_at("all")),
        tuple(tests_at("end") + tests_at("all")),
        adds("end"),
        numbers("end"),
    )
    return [start, end]


__all__ = ["applies", "timed_relaxed_reachability"]
