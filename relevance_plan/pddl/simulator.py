"""The builtin plan simulator: does a plan reach the goal of a problem, step by step?

Semantics:

* sequential plans: STRIPS with ADL conditions (negation, disjunction,
  implication, quantifiers, equality), conditional and universal effects;
  numeric fluents (comparisons; ``assign``, ``increase``, ``decrease``,
  ``scale-up``, ``scale-down``, all evaluated in the state before the step);
  derived predicates (stratified, recomputed after every step);
* timed plans (PDDL 2.1): each durative step is a start and an end
  happening; ``at start`` conditions are checked before the start,
  ``at end`` ones before the end, ``over all`` ones in every state strictly
  between; the duration must satisfy the action's duration constraint and
  not be negative (a zero duration makes its start and end one happening);
  happenings at the same instant must not interfere (PDDL 2.1's mutex, as
  VAL checks it: one deletes what another adds, one changes what another
  reads — a condition, a conditional effect's condition or a value an
  effect is computed from —, or both change one value other than by
  ``increase`` and ``decrease``, which commute and add up); timed initial
  literals happen at their times; the makespan (``total-time``) is the time
  of the plan's last happening, a timed literal's time not counting.

Values never set (VAL's rules, which the competitions' plans are judged by):

* an ``increase``, ``decrease``, ``scale-up`` or ``scale-down`` of a value
  never set starts from 0 (so an action-cost function that the problem does
  not initialise counts from 0, as in Fast Downward and VAL);
* an action-cost function — ``total-cost``, or a function that actions only
  increase and that only the metric reads — reads 0 until set, so the metric
  of a plan that never pays is 0 (Fast Downward's rule; VAL refuses to
  evaluate such a metric);
* any other read of a value never set — a condition, an effect's amount, an
  ``assign``, a duration, the goal — fails, naming the fluent.

Trajectory constraints and preferences are not checked (they are passed
through; preferences change a plan's quality, not its validity).
Every loop that enumerates bindings watches an optional deadline and raises
:class:`~relevance_plan.errors.SimulationTimeout` past it.
"""

from __future__ import annotations

import itertools
import time
from collections import defaultdict
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass, field

from relevance_plan.errors import SimulationTimeout
from relevance_plan.pddl import formulas as f
from relevance_plan.pddl.formatter import format_formula, format_number, format_step
from relevance_plan.pddl.model import (
    Action,
    DerivedPredicate,
    Domain,
    ObjectsOfType,
    Problem,
    TimedLiteral,
    all_objects,
)
from relevance_plan.pddl.plans import PlanStep

DURATION_TOLERANCE = 1e-3  # planners print durations with three decimals
SAME_INSTANT = 1e-9
_CHECK_EVERY = 4096  # bindings between deadline checks


class StepFailure(Exception):
    """A plan step (or the goal) fails; ``step`` is 1-based, None for the goal."""

    def __init__(self, message: str, step: int | None = None):
        super().__init__(message)
        self.message = message
        self.step = step


@dataclass
class WorldState:
    facts: set[f.GroundAtom]
    values: dict[f.GroundAtom, float]  # (function, args...) -> float

    def copy(self) -> WorldState:
        return WorldState(set(self.facts), dict(self.values))


class Simulator:
    """Evaluates formulas and applies effects on one problem's objects."""

    def __init__(self, domain: Domain, problem: Problem, deadline: float | None = None):
        self.domain = domain
        self.problem = problem
        self.objects = all_objects(domain, problem)
        self.deadline = deadline
        self.objects_of = ObjectsOfType(domain, self.objects)
        self._member_sets: dict[str, frozenset[str]] = {}
        # per derived rule (by id: self.domain keeps it alive): the atoms its body needs, the variables' types
        # per derived rule or quantifier (by id: self.domain keeps it alive): what its body needs
        self._covers: dict[int, _Cover] = {}
        self._mentioned: dict[int, frozenset[str]] = {}
        self._work = 0
        self._strata = _strata(domain) if domain.derived else ()
        self.costs = cost_functions(domain, problem)
        # what effects read matters only for happenings at one time (a timed plan's interference check)
        self.track_reads = True
        self._condition_quantified: dict[int, bool] = {}

    # ---------------------------------------------------------------- bindings

    def step_label(self, number: int, step: PlanStep | None) -> str:
        """``step 3 (PickUp RedCup Kitchen)``: the step as the user's domain and problem spell its names."""
        shown = "" if step is None else " " + format_step(step.action, step.args, self.problem.spelling)
        return f"step {number}{shown}"

    def tick(self) -> None:
        self._work += 1
        if self._work % _CHECK_EVERY == 0 and self.deadline is not None and time.monotonic() > self.deadline:
            raise SimulationTimeout("plan validation ran out of time")

    def bindings(self, params: f.Parameters, binding: Mapping[str, str]) -> Iterator[dict[str, str]]:
        pools = [self.objects_of(type_name) for _, type_name in params]
        names = [name for name, _ in params]
        for values in itertools.product(*pools):
            self.tick()
            inner = dict(binding)
            inner.update(zip(names, values))
            yield inner

    # ---------------------------------------------------------------- conditions

    def holds(
        self, formula: f.Formula, state: WorldState, binding: Mapping[str, str], index: _StateFacts | None = None
    ) -> bool:
        """Does ``formula`` hold in ``state`` under ``binding``?  With ``index`` (the facts of
        ``state``, indexed), quantifiers try only the bindings the facts allow."""
        if isinstance(formula, f.Atom):
            return f.ground(formula, binding) in state.facts
        if isinstance(formula, f.And):
            return all(self.holds(part, state, binding, index) for part in formula.parts)
        if isinstance(formula, f.Or):
            return any(self.holds(part, state, binding, index) for part in formula.parts)
        if isinstance(formula, f.Not):
            return not self.holds(formula.body, state, binding, index)
        if isinstance(formula, f.Imply):
            return not self.holds(formula.condition, state, binding, index) or self.holds(
                formula.consequence, state, binding, index
            )
        if isinstance(formula, (f.Exists, f.Forall)) and index is not None:
            return self._quantified(formula, state, binding, index)
        if isinstance(formula, f.Exists):
            return any(
                self.holds(formula.body, state, inner, index) for inner in self.bindings(formula.parameters, binding)
            )
        if isinstance(formula, f.Forall):
            return all(
                self.holds(formula.body, state, inner, index) for inner in self.bindings(formula.parameters, binding)
            )
        if isinstance(formula, f.Equality):
            return binding.get(formula.left, formula.left) == binding.get(formula.right, formula.right)
        if isinstance(formula, f.Comparison):
            return _compare(
                formula.op, self.value(formula.left, state, binding), self.value(formula.right, state, binding)
            )
        if isinstance(formula, (f.Timed, f.Preference)):
            # a preference is soft: it never makes a plan invalid
            return True if isinstance(formula, f.Preference) else self.holds(formula.body, state, binding, index)
        raise StepFailure(f"cannot evaluate {type(formula).__name__} in a condition")

    def value(self, expression: f.Expression, state: WorldState, binding: Mapping[str, str]) -> float:
        if isinstance(expression, f.Number):
            return expression.value
        if isinstance(expression, f.Fluent):
            key = (expression.function, *(binding.get(a, a) for a in expression.args))
            found = state.values.get(key)
            if found is None:
                if expression.function in self.costs:
                    return 0.0
                raise StepFailure(f"the value of ({' '.join(key)}) is undefined")
            return found
        if isinstance(expression, f.NumericVariable):
            text = binding.get(expression.name)
            if text is None:
                raise StepFailure(f"{expression.name} has no value here")
            return float(text)
        values = [self.value(arg, state, binding) for arg in expression.args]
        if expression.op == "-" and len(values) == 1:
            return -values[0]
        result = values[0]
        for other in values[1:]:
            if expression.op == "+":
                result += other
            elif expression.op == "-":
                result -= other
            elif expression.op == "*":
                result *= other
            elif other == 0:
                raise StepFailure("division by zero in a numeric expression")
            else:
                result /= other
        return result

    # ---------------------------------------------------------------- effects

    def effects(
        self, effect: f.Formula, state: WorldState, binding: Mapping[str, str], when: str | None = None
    ) -> Effects:
        """What ``effect`` does in ``state`` (conditions and values read in ``state``); for a
        durative action, only its parts at ``when`` ("start" or "end")."""
        found = Effects(set(), set(), {})
        # quantified effect conditions are joined over an index of the state, as derived rules are
        index = _StateFacts(state.facts) if self._quantified_conditions(effect) else None
        self._collect(effect, state, binding, when, None, found, index)
        return found

    def _quantified_conditions(self, effect: f.Formula) -> bool:
        found = self._condition_quantified.get(id(effect))
        if found is None:
            found = self._condition_quantified[id(effect)] = any(
                isinstance(node, f.When)
                and any(isinstance(inner, (f.Exists, f.Forall)) for inner in f.walk(node.condition))
                for node in f.walk(effect)
            )
        return found

    def _collect(
        self,
        effect: f.Formula,
        state: WorldState,
        binding: Mapping[str, str],
        when: str | None,
        current: str | None,
        found: Effects,
        index: _StateFacts | None = None,
    ) -> None:
        if isinstance(effect, f.Atom):
            if current == when:
                found.adds.add(f.ground(effect, binding))
        elif isinstance(effect, f.Not) and isinstance(effect.body, f.Atom):
            if current == when:
                found.deletes.add(f.ground(effect.body, binding))
        elif isinstance(effect, f.And):
            for part in effect.parts:
                self._collect(part, state, binding, when, current, found, index)
        elif isinstance(effect, f.Forall):
            for inner in self.bindings(effect.parameters, binding):
                self._collect(effect.body, state, inner, when, current, found, index)
        elif isinstance(effect, f.When):
            # Conditions are read in the state before the happening; a timed condition
            # part is checked with the happening that carries the effect.
            if self.track_reads:
                found.reads |= _reads(effect.condition, binding)
            if self.holds(effect.condition, state, binding, index):
                self._collect(effect.effect, state, binding, when, current, found, index)
        elif isinstance(effect, f.Timed):
            self._collect(effect.body, state, binding, when, effect.when, found, index)
        elif isinstance(effect, f.NumericEffect):
            if current == when:
                self._numeric(effect, state, binding, found)

    def _numeric(self, effect: f.NumericEffect, state: WorldState, binding: Mapping[str, str], found: Effects) -> None:
        key = (effect.fluent.function, *(binding.get(a, a) for a in effect.fluent.args))
        amount = self.value(effect.value, state, binding)
        if self.track_reads:
            found.reads |= _reads(effect.value, binding)
        if effect.op in ADDITIVE:
            found.deltas[key] = found.deltas.get(key, 0.0) + (amount if effect.op == "increase" else -amount)
        else:
            new = amount if effect.op == "assign" else _update(effect.op, state.values.get(key), amount, key)
            if key in found.values and found.values[key] != new:
                raise StepFailure(f"two effects give ({' '.join(key)}) different values at once")
            found.values[key] = new
        if key in found.values and key in found.deltas:
            raise StepFailure(f"({' '.join(key)}) is assigned and updated at once")

    # ---------------------------------------------------------------- derived predicates

    def derive(self, state: WorldState) -> None:
        """Replace the derived facts of ``state`` by those its basic facts imply (stratified fixpoint).

        Semi-naive: after a stratum's first round, a rule is tried again only when a predicate its
        body mentions gained facts in the round before.  Within a stratum the rules read one
        another only positively, so the fixpoint does not depend on the order facts are found in."""
        if not self._strata:
            return
        derived = self.domain.derived_predicates
        state.facts = {fact for fact in state.facts if fact[0] not in derived}
        index = _StateFacts(state.facts)
        for stratum in self._strata:
            pending = list(stratum)
            while pending:
                gained: set[str] = set()
                for rule in pending:
                    # candidates are listed before any is added: the index is not changed while joined
                    for binding in list(self._rule_bindings(rule, index)):
                        fact = f.ground(rule.head, binding)
                        if fact not in state.facts and self.holds(rule.body, state, binding, index):
                            state.facts.add(fact)
                            index.add(fact)
                            gained.add(fact[0])
                pending = [rule for rule in stratum if gained & self._mentions(rule)]

    def _mentions(self, rule: DerivedPredicate) -> frozenset[str]:
        found = self._mentioned.get(id(rule))
        if found is None:
            found = frozenset(node.predicate for node in f.walk(rule.body) if isinstance(node, f.Atom))
            self._mentioned[id(rule)] = found
        return found

    def _rule_bindings(self, rule: DerivedPredicate, index: _StateFacts) -> Iterator[dict[str, str]]:
        """Bindings of ``rule``'s parameters under which its body may hold: those of the atoms the
        body needs (see :func:`_cover`), found in ``index``, rather than every object for every
        parameter; the caller checks the whole body."""
        cover = self._covers.get(id(rule))
        if cover is None:  # the same for every state: found once per rule
            cover = self._covers[id(rule)] = _Cover.of(rule.body, rule.parameters, positive=True)
        return self._candidates(cover, {}, index)

    def _quantified(
        self, formula: f.Exists | f.Forall, state: WorldState, binding: Mapping[str, str], index: _StateFacts
    ) -> bool:
        """``exists`` or ``forall`` tried only on the bindings under which its body (for ``forall``,
        the body's negation) may hold, found in ``index``; under every other binding the body holds
        (for ``exists``: fails), so the answer is the one every binding would give."""
        positive = isinstance(formula, f.Exists)
        cover = self._covers.get(id(formula))
        if cover is None:
            cover = self._covers[id(formula)] = _Cover.of(formula.body, formula.parameters, positive=positive)
        for inner in self._candidates(cover, binding, index):
            if self.holds(formula.body, state, inner, index) == positive:
                return positive
        return not positive

    def _candidates(self, cover: _Cover, binding: Mapping[str, str], index: _StateFacts) -> Iterator[dict[str, str]]:
        """``binding`` extended by each binding of the cover's variables that one of its alternatives
        allows (each once); a variable the alternative leaves open takes every object of its type."""
        outer = {k: v for k, v in binding.items() if k not in cover.types}
        names = tuple(v for v, _ in cover.parameters)
        seen: set[tuple[str, ...]] = set()
        for alternative in cover.alternatives:
            for joined in self._join(list(alternative), outer, cover.types, index):
                free = tuple((v, t) for v, t in cover.parameters if v not in joined)
                for full in self.bindings(free, joined):
                    key = tuple(full[v] for v in names)
                    if key not in seen:
                        seen.add(key)
                        inner = dict(binding)
                        inner.update(zip(names, key))
                        yield inner

    def _join(
        self, items: list[f.Atom | f.Equality], binding: dict[str, str], types: Mapping[str, str], index: _StateFacts
    ) -> Iterator[dict[str, str]]:
        """Bindings extending ``binding`` under which every item holds in ``index`` (the most bound
        item first); a variable not in ``types`` is the outer binding's, or stands for itself."""
        if not items:
            yield binding
            return
        best, best_score = 0, (-1, 0)
        for position, item in enumerate(items):
            if isinstance(item, f.Equality):
                score = (
                    1_000_000
                    if (item.left not in types or item.left in binding)
                    or (item.right not in types or item.right in binding)
                    else -1,
                    0,
                )
            else:
                bound = sum(1 for a in item.args if a not in types or a in binding)
                score = (bound, -len(index.facts(item.predicate)))
            if score > best_score:
                best, best_score = position, score
        item = items[best]
        rest = items[:best] + items[best + 1 :]
        if isinstance(item, f.Equality):
            left, right = item.left, item.right
            left_open = left in types and left not in binding
            right_open = right in types and right not in binding
            if left_open and right_open:  # nothing binds either side: no constraint from it
                yield from self._join(rest, binding, types, index)
                return
            if left_open or right_open:
                var, other = (left, right) if left_open else (right, left)
                value = binding.get(other, other)
                if value in self._members(types[var]):
                    yield from self._join(rest, {**binding, var: value}, types, index)
                return
            if binding.get(left, left) == binding.get(right, right):
                yield from self._join(rest, binding, types, index)
            return
        ground = [(i, binding.get(a, a)) for i, a in enumerate(item.args) if a not in types or a in binding]
        for fact in index.matching(item.predicate, ground):
            self.tick()
            found = self._match(item.args, fact, binding, types)
            if found is not None:
                yield from self._join(rest, found, types, index)

    def _match(
        self, args: tuple[str, ...], fact: f.GroundAtom, binding: dict[str, str], types: Mapping[str, str]
    ) -> dict[str, str] | None:
        """``binding`` extended so that ``args`` match ``fact``, each new value of its variable's type; or None."""
        if len(args) != len(fact) - 1:
            return None
        found = binding
        for arg, value in zip(args, fact[1:]):
            if arg in found:
                if found[arg] != value:
                    return None
            elif arg not in types:
                if arg != value:
                    return None
            elif value in self._members(types[arg]):
                if found is binding:
                    found = dict(binding)
                found[arg] = value
            else:
                return None
        return found

    def _members(self, type_name: str) -> frozenset[str]:
        cached = self._member_sets.get(type_name)
        if cached is None:
            cached = self._member_sets[type_name] = frozenset(self.objects_of(type_name))
        return cached


class _StateFacts:
    """The facts of a state by predicate and by (predicate, position, value), kept up to date as
    facts are added."""

    def __init__(self, facts: set[f.GroundAtom]):
        self._by_predicate: dict[str, list[f.GroundAtom]] = defaultdict(list)
        self._by_argument: dict[tuple[str, int, str], list[f.GroundAtom]] = defaultdict(list)
        for fact in facts:
            self.add(fact)

    def add(self, fact: f.GroundAtom) -> None:
        self._by_predicate[fact[0]].append(fact)
        for position, value in enumerate(fact[1:]):
            self._by_argument[(fact[0], position, value)].append(fact)

    def facts(self, predicate: str) -> Sequence[f.GroundAtom]:
        return self._by_predicate.get(predicate, ())

    def matching(self, predicate: str, ground: Sequence[tuple[int, str]]) -> Sequence[f.GroundAtom]:
        """The facts of ``predicate`` with the fewest candidates among those having one of the
        given values at its position (the caller checks the rest)."""
        best = self.facts(predicate)
        for position, value in ground:
            found = self._by_argument.get((predicate, position, value), ())
            if len(found) < len(best):
                best = found
        return best


_MAX_ALTERNATIVES = 32


@dataclass(frozen=True)
class _Cover:
    """What must hold for a formula to hold under a binding of ``parameters``: one of the
    ``alternatives``, each a conjunction of positive atoms and equalities (an empty one: nothing
    known).  Variables of quantifiers inside are renamed apart (``?y#2``) and typed in ``types``
    with the parameters; they are joined like the parameters and then forgotten."""

    parameters: f.Parameters
    types: dict[str, str]
    alternatives: tuple[tuple[f.Atom | f.Equality, ...], ...]

    @staticmethod
    def of(formula: f.Formula, parameters: f.Parameters, positive: bool) -> _Cover:
        types = dict(parameters)
        renames = {v: v for v, _ in parameters}
        alternatives = _alternatives(formula, positive, types, renames, itertools.count())
        return _Cover(parameters, types, tuple(alternatives))


_Alternatives = list[tuple[f.Atom | f.Equality, ...]]
_NOTHING_KNOWN: _Alternatives = [()]


def _alternatives(
    formula: f.Formula, positive: bool, types: dict[str, str], renames: dict[str, str], counter: Iterator[int]
) -> _Alternatives:
    """The alternatives of a :class:`_Cover` for ``formula`` (its negation when not ``positive``);
    ``renames`` maps the quantified variables in scope to their names in ``types``."""
    if isinstance(formula, f.Atom):
        if not positive:
            return _NOTHING_KNOWN
        return [(f.Atom(formula.predicate, tuple(renames.get(a, a) for a in formula.args)),)]
    if isinstance(formula, f.Equality):
        if not positive:
            return _NOTHING_KNOWN
        return [(f.Equality(renames.get(formula.left, formula.left), renames.get(formula.right, formula.right)),)]
    if isinstance(formula, f.Not):
        return _alternatives(formula.body, not positive, types, renames, counter)
    if isinstance(formula, f.Timed):
        return _alternatives(formula.body, positive, types, renames, counter)
    if isinstance(formula, f.Imply):
        parts: tuple[f.Formula, ...] = (f.Not(formula.condition), formula.consequence)
        return _alternatives(f.Or(parts), positive, types, renames, counter)
    if isinstance(formula, (f.And, f.Or)):
        if isinstance(formula, f.And) == positive:  # a conjunction: any part's alternatives, or several joined
            result: _Alternatives = [()]
            found = [_alternatives(part, positive, types, renames, counter) for part in formula.parts]
            for part_alternatives in sorted(found, key=len):
                if part_alternatives == _NOTHING_KNOWN or len(result) * len(part_alternatives) > _MAX_ALTERNATIVES:
                    continue
                result = [mine + theirs for mine in result for theirs in part_alternatives]
            return result
        result = []  # a disjunction: one of every part's alternatives
        for part in formula.parts:
            part_alternatives = _alternatives(part, positive, types, renames, counter)
            if () in part_alternatives:
                return _NOTHING_KNOWN
            result += part_alternatives
        return result if len(result) <= _MAX_ALTERNATIVES else _NOTHING_KNOWN
    if isinstance(formula, (f.Exists, f.Forall)) and isinstance(formula, f.Exists) == positive:
        # a witness of the inner quantifier is joined like a parameter, under a name of its own
        inner = dict(renames)
        for name, type_name in formula.parameters:
            inner[name] = f"{name}#{next(counter)}"
            types[inner[name]] = type_name
        return _alternatives(formula.body, positive, types, inner, counter)
    return _NOTHING_KNOWN


ADDITIVE = frozenset({"increase", "decrease"})


@dataclass
class Effects:
    adds: set[f.GroundAtom]
    deletes: set[f.GroundAtom]
    values: dict[f.GroundAtom, float]  # assigned (assign, scale-up, scale-down)
    deltas: dict[f.GroundAtom, float] = field(default_factory=dict)  # increase and decrease, summed
    reads: set[tuple[str, ...]] = field(default_factory=set)  # read by the effects: ("fact"|"value", ...)

    def apply(self, state: WorldState) -> None:
        state.facts.difference_update(self.deletes - self.adds)  # add-after-delete, as the planners do
        state.facts.update(self.adds)
        state.values.update(self.values)
        for key, delta in self.deltas.items():
            state.values[key] = state.values.get(key, 0.0) + delta  # a value never set starts from 0

    def changes(self) -> set[tuple[str, ...]]:
        facts = {("fact",) + atom for atom in self.adds | self.deletes}
        return facts | {("value",) + key for key in (*self.values, *self.deltas)}

    def interferes(self, reads: set[tuple[str, ...]], other: Effects, other_reads: set[tuple[str, ...]]) -> bool:
        """PDDL 2.1's mutex between two happenings of one instant (``reads``: what each one's
        condition reads)."""
        if self.adds & other.deletes or self.deletes & other.adds:
            return True
        if self.changes() & (other_reads | other.reads) or other.changes() & (reads | self.reads):
            return True
        assigned, other_assigned = set(self.values), set(other.values)
        return bool(assigned & (other_assigned | set(other.deltas)) or other_assigned & set(self.deltas))


def _update(op: str, old: float | None, amount: float, key: f.GroundAtom) -> float:
    if old is None:
        old = 0.0  # VAL's rule: an update of a value never set starts from 0
    if op == "increase":
        return old + amount
    if op == "decrease":
        return old - amount
    if op == "scale-up":
        return old * amount
    if amount == 0:
        raise StepFailure("scale-down by zero")
    return old / amount


def why_false(simulator: Simulator, formula: f.Formula, state: WorldState, binding: Mapping[str, str]) -> str:
    """The part of ``formula`` that fails in ``state``, named: the atom that is false (or true, under
    a ``not``), the comparison with its values, the quantifier's failing instance."""
    spelling = simulator.problem.spelling
    shown = format_formula(f.substitute(formula, binding), spelling)
    if isinstance(formula, f.Atom):
        return f"{shown} is false"
    if isinstance(formula, f.Not) and isinstance(formula.body, f.Atom):
        return f"{format_formula(f.substitute(formula.body, binding), spelling)} is true"
    if isinstance(formula, f.And):
        for part in formula.parts:
            if not simulator.holds(part, state, binding):
                return why_false(simulator, part, state, binding)
    if isinstance(formula, f.Imply):
        return f"{format_formula(f.substitute(formula.condition, binding), spelling)} holds, but " + why_false(
            simulator, formula.consequence, state, binding
        )
    if isinstance(formula, f.Comparison):
        try:
            left, right = (simulator.value(side, state, binding) for side in (formula.left, formula.right))
        except StepFailure as failure:
            return f"{shown} cannot be evaluated: {failure.message}"
        return f"{shown} is false ({format_number(left)} {formula.op} {format_number(right)})"
    if isinstance(formula, f.Forall):
        for inner in simulator.bindings(formula.parameters, binding):
            if not simulator.holds(formula.body, state, inner):
                instance = ", ".join(f"{name} = {spelling.object(inner[name])}" for name, _ in formula.parameters)
                return f"{shown} fails for {instance}: {why_false(simulator, formula.body, state, inner)}"
    if isinstance(formula, (f.Timed, f.Preference)):
        return why_false(simulator, formula.body, state, binding)
    return f"{shown} is false"


def _compare(op: str, left: float, right: float) -> bool:
    if op == "<":
        return left < right
    if op == "<=":
        return left <= right
    if op == ">":
        return left > right
    if op == ">=":
        return left >= right
    return abs(left - right) <= 1e-9 * max(1.0, abs(left), abs(right))


def _strata(domain: Domain) -> tuple[tuple[DerivedPredicate, ...], ...]:
    """Derived rules in strata: a rule that reads a derived predicate negatively comes after its rules."""
    derived = domain.derived_predicates
    level = {predicate: 0 for predicate in derived}
    for _ in range(len(derived) + 1):
        changed = False
        for rule in domain.derived:
            head = rule.head.predicate
            for atom, positive in f.literals(rule.body):
                if atom.predicate in derived:
                    needed = level[atom.predicate] + (0 if positive else 1)
                    if needed > level[head]:
                        level[head] = needed
                        changed = True
        if not changed:
            break
    top = max(level.values(), default=0)
    return tuple(tuple(r for r in domain.derived if level[r.head.predicate] == i) for i in range(top + 1))


def initial_state(problem: Problem) -> WorldState:
    return WorldState(set(problem.init), dict(problem.numeric_init))


def cost_functions(domain: Domain, problem: Problem) -> frozenset[str]:
    """The action-cost functions, which read 0 until set: ``total-cost``, and every function that
    actions only increase and that nothing but the metric reads (a cost by another name)."""
    increased: set[str] = set()
    other: set[str] = set()
    parts: list[f.Node] = [rule.body for rule in domain.derived]
    parts += [problem.goal]
    for action in domain.actions:
        parts += [action.precondition, action.effect] + ([action.duration] if action.duration is not None else [])
    stack = parts
    while stack:
        node = stack.pop()
        if isinstance(node, f.NumericEffect):
            (increased if node.op == "increase" else other).add(node.fluent.function)
            stack.append(node.value)  # the target is not a read; the amount is
            continue
        if isinstance(node, f.Fluent):
            other.add(node.function)
        stack.extend(f.children(node))
    in_metric = set()
    if problem.metric is not None:
        in_metric = {node.function for node in f.walk(problem.metric.expression) if isinstance(node, f.Fluent)}
    return frozenset({"total-cost"} | ((increased & in_metric) - other))


# --------------------------------------------------------------------------- running a plan


def run_plan(simulator: Simulator, steps: Sequence[PlanStep]) -> tuple[WorldState, float | None]:
    """Run ``steps`` from the problem's initial state: the final state and, for a timed plan
    (steps with start times, a temporal domain or timed literals: PDDL 2.1 semantics), its
    makespan (None for a sequential plan).  :class:`StepFailure` names the step that fails."""
    problem = simulator.problem
    if any(step.time is not None for step in steps) or simulator.domain.temporal or problem.timed_literals:
        return _run_timed(simulator, steps)
    return _run_sequential(simulator, steps), None


# --------------------------------------------------------------------------- sequential plans


def _run_sequential(simulator: Simulator, steps: Sequence[PlanStep]) -> WorldState:
    simulator.track_reads = False  # one step at a time: nothing can interfere
    state = initial_state(simulator.problem)
    simulator.derive(state)
    for number, step in enumerate(steps, start=1):
        action, binding = _bind(simulator, step, number)
        if action.durative:
            raise StepFailure(
                f"{simulator.step_label(number, step)}: a durative action needs a start time and a duration", number
            )
        try:
            if not simulator.holds(action.precondition, state, binding):
                unmet = why_false(simulator, action.precondition, state, binding)
                raise StepFailure(f"precondition not satisfied: {unmet}")
            effects = simulator.effects(action.effect, state, binding)
        except StepFailure as failure:
            raise StepFailure(f"{simulator.step_label(number, step)}: {failure.message}", number) from None
        effects.apply(state)
        simulator.derive(state)
    return state


def _bind(simulator: Simulator, step: PlanStep, number: int) -> tuple[Action, dict[str, str]]:
    action = simulator.domain.action(step.action)
    if action is None:
        raise StepFailure(f"{simulator.step_label(number, step)}: unknown action", number)
    if len(step.args) != len(action.parameters):
        raise StepFailure(f"{simulator.step_label(number, step)}: expects {len(action.parameters)} arguments", number)
    for arg, (_, type_name) in zip(step.args, action.parameters):
        if arg not in simulator.objects:
            raise StepFailure(f"{simulator.step_label(number, step)}: unknown object '{arg}'", number)
        if not simulator.domain.is_subtype(simulator.objects[arg], type_name):
            spelling = simulator.problem.spelling
            shown = f"'{spelling.object(arg)}' is not of type {spelling.type(type_name)}"
            raise StepFailure(f"{simulator.step_label(number, step)}: {shown}", number)
    return action, {name: arg for (name, _), arg in zip(action.parameters, step.args)}


# --------------------------------------------------------------------------- timed plans


@dataclass(frozen=True)
class _Happening:
    time: float
    order: int  # ends before starts at one instant is not assumed: ties keep plan order
    kind: str  # "start", "end", "instant", "til"
    number: int  # 1-based step number (0 for a timed literal)
    step: PlanStep | None = None
    action: Action | None = None
    binding: Mapping[str, str] | None = None
    literal: TimedLiteral | None = None
    duration: float | None = None  # a start whose given duration is checked in the state it starts in


def _run_timed(simulator: Simulator, steps: Sequence[PlanStep]) -> tuple[WorldState, float]:
    state = initial_state(simulator.problem)
    simulator.derive(state)
    happenings = _happenings(simulator, steps, state)
    happenings.sort(key=lambda h: (h.time, h.order))
    running: dict[int, _Happening] = {}  # step number -> its start happening, while it runs
    index = 0
    makespan = 0.0
    while index < len(happenings):
        group = [happenings[index]]
        while index + len(group) < len(happenings) and (
            happenings[index + len(group)].time - group[0].time <= SAME_INSTANT
        ):
            group.append(happenings[index + len(group)])
        index += len(group)
        _apply_group(simulator, state, group, running)
        if any(happening.kind != "til" for happening in group):
            makespan = max(makespan, group[0].time)  # timed literals after the last step do not count
        for start in running.values():
            _check_invariant(simulator, state, start)
    return state, makespan


def _happenings(simulator: Simulator, steps: Sequence[PlanStep], state: WorldState) -> list[_Happening]:
    happenings: list[_Happening] = []
    for number, step in enumerate(steps, start=1):
        action, binding = _bind(simulator, step, number)
        start = step.time if step.time is not None else float(number - 1)
        if not action.durative:
            happenings.append(_Happening(start, len(happenings), "instant", number, step, action, binding))
            continue
        duration = _duration(simulator, action, step, binding, state, number)
        timed = dict(binding)
        timed["?duration"] = repr(duration)
        given = duration if step.duration is not None else None
        happenings.append(_Happening(start, len(happenings), "start", number, step, action, timed, duration=given))
        happenings.append(_Happening(start + duration, len(happenings), "end", number, step, action, timed))
    for literal in simulator.problem.timed_literals:
        happenings.append(_Happening(literal.time, len(happenings), "til", 0, literal=literal))
    return happenings


def _duration(
    simulator: Simulator, action: Action, step: PlanStep, binding: Mapping[str, str], state: WorldState, number: int
) -> float:
    """The step's duration.  One the plan gives is checked against the action's constraint when the
    step starts, in the values its fluents have then (a rover's recharge lasts as long as its
    energy at that time says); one it leaves out is taken from the constraint in the initial
    values, before the plan runs, since the end must be placed in time (durations in the IPC
    domains that omit them depend on static functions)."""
    assert action.duration is not None
    duration = step.duration
    if duration is None:
        exact = [c for c in f.conjuncts(action.duration) if isinstance(c, f.Comparison) and c.op == "="]
        if not exact:
            raise StepFailure(f"{simulator.step_label(number, step)}: no duration given", number)
        other = exact[0].right if exact[0].left == f.NumericVariable("?duration") else exact[0].left
        duration = simulator.value(other, state, binding)
        _check_duration(simulator, action, step, binding, state, number, duration)
    # A zero duration puts the start and the end in one happening, as VAL does; VAL also takes a
    # negative one, placing the end before the start, which PDDL 2.1 does not allow.
    if duration < 0:
        raise StepFailure(f"{simulator.step_label(number, step)}: duration {duration:g} is negative", number)
    return duration


def _check_duration(
    simulator: Simulator,
    action: Action,
    step: PlanStep | None,
    binding: Mapping[str, str],
    state: WorldState,
    number: int,
    duration: float,
) -> None:
    assert action.duration is not None
    for part in f.conjuncts(action.duration):
        if isinstance(part, f.Comparison) and not _duration_fits(simulator, part, duration, state, binding):
            raise StepFailure(
                f"{simulator.step_label(number, step)}: duration {duration:g} violates its constraint", number
            )


def _duration_fits(
    simulator: Simulator, part: f.Comparison, duration: float, state: WorldState, binding: Mapping[str, str]
) -> bool:
    timed = dict(binding)
    timed["?duration"] = repr(duration)
    left = simulator.value(part.left, state, timed)
    right = simulator.value(part.right, state, timed)
    if part.op == "=":
        return abs(left - right) <= DURATION_TOLERANCE + 1e-9 * abs(right)
    return _compare(part.op, left, right) or abs(left - right) <= DURATION_TOLERANCE


def _apply_group(
    simulator: Simulator, state: WorldState, group: list[_Happening], running: dict[int, _Happening]
) -> None:
    """Apply the happenings of one instant: conditions in the state before, then every effect at once."""
    found: list[tuple[_Happening, Effects, set[tuple[str, ...]]]] = []
    for happening in group:
        effects, reads = _happening_effects(simulator, state, happening)
        found.append((happening, effects, reads))
    for i, (first, first_effects, first_reads) in enumerate(found):
        for second, second_effects, second_reads in found[i + 1 :]:
            if first_effects.interferes(first_reads, second_effects, second_reads):
                both = f"{_describe(simulator, first)} and {_describe(simulator, second)}"
                raise StepFailure(f"{both} interfere at time {first.time:g}", first.number or second.number or None)
    for happening, effects, _ in found:
        effects.apply(state)
        if happening.kind == "start":
            running[happening.number] = happening
        elif happening.kind == "end":
            running.pop(happening.number, None)
    simulator.derive(state)


def _happening_effects(
    simulator: Simulator, state: WorldState, happening: _Happening
) -> tuple[Effects, set[tuple[str, ...]]]:
    literal = happening.literal
    if literal is not None:
        if literal.fluent is not None:
            effects = Effects(set(), set(), {literal.fluent: literal.value or 0.0})
        elif literal.atom is not None and literal.negated:
            effects = Effects(set(), {literal.atom}, {})
        else:
            effects = Effects({literal.atom} if literal.atom is not None else set(), set(), {})
        return effects, set()
    action, binding, number = happening.action, happening.binding, happening.number
    assert action is not None and binding is not None
    if happening.duration is not None:
        _check_duration(simulator, action, happening.step, binding, state, number, happening.duration)
    when = None if happening.kind == "instant" else happening.kind
    condition = action.precondition if when is None else _at(action.precondition, when)
    try:
        if not simulator.holds(condition, state, binding):
            unmet = why_false(simulator, condition, state, binding)
            raise StepFailure(f"{'precondition' if when is None else f'at {when} condition'} not satisfied: {unmet}")
        effects = simulator.effects(action.effect, state, binding, when)
    except StepFailure as failure:
        raise StepFailure(
            f"{simulator.step_label(number, happening.step)} ({_describe(simulator, happening)}): {failure.message}",
            number,
        ) from None
    return effects, _reads(condition, binding)


def _at(condition: f.Formula, when: str) -> f.And:
    """The part of a durative condition checked at ``when``."""
    return f.And(tuple(part.body for part in f.conjuncts_timed(condition) if part.when == when))


def _check_invariant(simulator: Simulator, state: WorldState, start: _Happening) -> None:
    action, binding = start.action, start.binding
    assert action is not None and binding is not None
    invariant = _at(action.precondition, "all")
    if invariant.parts and not simulator.holds(invariant, state, binding):
        unmet = why_false(simulator, invariant, state, binding)
        raise StepFailure(
            f"{simulator.step_label(start.number, start.step)}: over all condition broken while it runs: {unmet}",
            start.number,
        )


def _reads(condition: f.Node, binding: Mapping[str, str]) -> set[tuple[str, ...]]:
    reads = set()
    for node in f.walk(condition):
        if isinstance(node, f.Atom) and all(not f.is_variable(binding.get(a, a)) for a in node.args):
            reads.add(("fact", *f.ground(node, binding)))
        elif isinstance(node, f.Fluent):
            reads.add(("value", node.function, *(binding.get(a, a) for a in node.args)))
    return reads


def _describe(simulator: Simulator, happening: _Happening) -> str:
    if happening.kind == "til":
        return "a timed initial literal"
    return f"the {happening.kind} of {simulator.step_label(happening.number, happening.step)}"
