"""The states one object of a type can be in: a sound over-approximation, for proofs.

An object's *state* here is how many true atoms it has of each *pattern* (an
atom about it with its other arguments left open: ``(inreceptacle w ?)`` is
``("inreceptacle", 0)``), counted up to a cap one above the most atoms of a
pattern any action requires or adds (the cap means "that many or more"; an
atom whose only argument is the object counts at most one).  The patterns
are the places where an action's atom has a variable that can be bound to
an object of the type (a parameter or a quantified variable of a type
related to it), whatever types the predicate declares: no atom an action can
read or change about the object goes uncounted.

Starting from every object's initial counts, an action acts on the object
through one of its parameters (or, through quantified effects only, through
none): it applies when the object has the atoms the action requires of it
at the top level of its precondition (two required atoms of one pattern that
the action keeps apart with ``(not (= ?s1 ?s2))`` need two) and none that it
forbids (``not (p ?x)`` where the object is p's only argument).  Its effect
is read as a planner applies it, deletes first and adds after (an atom both
deleted and added stays): a delete of an atom it required takes one away,
any other delete may; each conditional add or delete may or may not happen
(two of one pattern may change the count by two); a quantified effect may
leave any count; an add may name an atom the object had already.  Every
other condition (on other objects, numeric, on a derived predicate, inside
``or``, ``not`` or a quantifier) is taken as met.  So every state a real plan
can give the object is among the states found.

A state can *mark* atoms: an exploration started right after a chosen
action carries as marks the atoms that action certainly leaves (a pattern's
only such atom), and a mark is kept only while the marked atom is certainly
still there (a step that may delete an atom of the pattern leaves a state
with the mark dropped among its successors); a step whose required atom of
a pattern is the object's only one, and marked, is known to use that very
atom.  ``witness_proof`` proves with this that a goal atom keeps its witness
for good.

:func:`readable` says whether the analysis applies to a type: no durative
actions, no constant of the type (an action could name it without a
parameter) and no action with two parameters that may be the same object of
the type (no ``(not (= ?x ?y))`` between them); and an exploration gives up
past ``MAX_STATES`` states.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass
from itertools import combinations, product

from relevance_plan.pddl.formulas import TRUE, Atom, Equality, Not, conjuncts, effect_literals, is_variable
from relevance_plan.pddl.model import Action, Domain, Problem

ObjectPattern = tuple[str, int]  # (predicate, the object's position)
MAX_STATES = 20_000  # an exploration that finds more gives up


@dataclass(frozen=True)
class ObjectStep:
    """One action acting on the object bound to one of its parameters (``variable``)."""

    action: Action
    variable: str | None  # None: the action names such objects only through quantified variables
    requires: tuple[tuple[Atom, ObjectPattern], ...]  # top-level positive conditions on the object
    forbids: frozenset[ObjectPattern]  # top-level ``not (p ?x)`` with the object p's only argument
    adds: tuple[tuple[Atom, ObjectPattern], ...]  # unconditional adds about it
    deletes: tuple[tuple[Atom, ObjectPattern], ...]  # unconditional deletes about it
    may_add: tuple[ObjectPattern, ...]  # one entry per conditional add that may be about it
    may_delete: tuple[ObjectPattern, ...]  # one entry per conditional delete that may be about it
    distinct: frozenset[frozenset[str]]  # pairs of terms the action requires to differ
    may_set: frozenset[ObjectPattern] = frozenset()  # quantified effects that may leave any count

    @property
    def acts(self) -> bool:
        """Whether the step may change the object at all (a step through quantified variables only may not)."""
        return self.variable is not None or bool(self.may_add or self.may_delete or self.may_set)

    @property
    def patterns(self) -> frozenset[ObjectPattern]:
        """Every pattern of the object the step reads or may change."""
        pairs = (*self.requires, *self.adds, *self.deletes)
        return frozenset(
            {own for _, own in pairs} | self.forbids | set(self.may_add) | set(self.may_delete) | self.may_set
        )

    def need(self) -> dict[ObjectPattern, int]:
        """How many atoms of each pattern the object must have for the step to apply."""
        by_pattern: dict[ObjectPattern, list[Atom]] = {}
        for atom, own in self.requires:
            by_pattern.setdefault(own, []).append(atom)
        return {own: len(atoms) if self.apart(atoms) else 1 for own, atoms in by_pattern.items()}

    def apart(self, atoms: list[Atom]) -> bool:
        """Whether the atoms are pairwise certainly different."""
        return all(self.different(a, b) for a, b in combinations(atoms, 2))

    def different(self, one: Atom, other: Atom) -> bool:
        """Whether two atoms are certainly different atoms whatever the step's binding."""
        return one.predicate != other.predicate or any(
            x != y and (frozenset((x, y)) in self.distinct or not (is_variable(x) or is_variable(y)))
            for x, y in zip(one.args, other.args)
        )


@dataclass(frozen=True)
class ObjectState:
    counts: tuple[int, ...]  # per pattern of ``ObjectStates.patterns``
    marked: frozenset[int] = frozenset()  # patterns whose marked atom (see the module's docstring) is still there


class ObjectStates:
    """The patterns, steps and initial states of the objects of one type (see the module's docstring)."""

    def __init__(self, domain: Domain, problem: Problem, type_name: str):
        self.domain = domain
        self.type_name = type_name
        self.steps = [
            step_of(domain, action, variable, type_name)
            for action in domain.actions
            for variable in [*parameters_of_type(domain, action, type_name), None]
        ]
        self.steps = [step for step in self.steps if step.acts]
        # what the actions touch, not what the predicates declare: no atom a step reads goes uncounted
        self.patterns = sorted(set().union(*(step.patterns for step in self.steps)))
        self.index = {pattern: i for i, pattern in enumerate(self.patterns)}
        most = max((n for step in self.steps for n in step.need().values()), default=1)
        most = max([most, *(len(step.adds) for step in self.steps)])
        # a count at the cap means "the cap or more"; an atom about the object alone is there or not
        self.caps = tuple(1 if len(domain.predicates[p]) == 1 else most + 1 for p, _ in self.patterns)
        objects = [name for name, kind in problem.objects.items() if compatible(domain, kind, type_name)]
        self.initial = {self._counted(problem.init, name) for name in objects}

    def _counted(self, facts: Iterable[tuple[str, ...]], name: str) -> ObjectState:
        counts = [0] * len(self.patterns)
        for fact in facts:
            for position, arg in enumerate(fact[1:]):
                i = self.index.get((fact[0], position))
                if arg == name and i is not None:
                    counts[i] = min(self.caps[i], counts[i] + 1)
        return ObjectState(tuple(counts))

    def applies(self, step: ObjectStep, state: ObjectState) -> bool:
        counts = state.counts
        return all(counts[self.index[own]] >= need for own, need in step.need().items()) and all(
            counts[self.index[own]] == 0 for own in step.forbids
        )

    def successors(self, step: ObjectStep, state: ObjectState) -> list[ObjectState]:
        """The states ``step`` may leave the object in (it applies)."""
        options: list[list[tuple[int, bool]]] = []  # per pattern: (count, still marked)
        for i, pattern in enumerate(self.patterns):
            options.append(sorted(self._after(step, pattern, state.counts[i], i in state.marked, self.caps[i])))
        return [
            ObjectState(tuple(c for c, _ in chosen), frozenset(i for i, (_, m) in enumerate(chosen) if m))
            for chosen in product(*options)
        ]

    def _after(
        self, step: ObjectStep, pattern: ObjectPattern, count: int, marked: bool, cap: int
    ) -> set[tuple[int, bool]]:
        """The pattern's count after the step, each way it may go, and whether its mark may stay:
        deletes first, then adds (see the module's docstring)."""
        adds = {atom for atom, own in step.adds if own == pattern}
        deletes = [atom for atom, own in step.deletes if own == pattern and atom not in adds]  # an add wins
        required = {atom for atom, own in step.requires if own == pattern}
        sure = [atom for atom in deletes if atom in required]  # atoms the object had
        fewest = len(sure) if step.apart(sure) else min(1, len(sure))
        most = len(deletes) + step.may_delete.count(pattern)
        results: set[tuple[int, bool]] = set()
        for gone in range(fewest, most + 1):
            for left in _minus(count, gone, cap):
                if gone == 0:
                    results.add((left, marked))  # nothing of the pattern went: the marked atom is there
                    continue
                results.add((left, False))  # the marked atom may be one that went
                if marked and left > 0:
                    results.add((left, True))  # or one that stays
        if adds:
            least = len(adds) if step.apart(list(adds)) else 1
            results = {(min(cap, total), m) for c, m in results for total in range(max(c, least), c + len(adds) + 1)}
        maybe = step.may_add.count(pattern)
        if maybe:
            results = {(min(cap, c + more), m) for c, m in results for more in range(maybe + 1)}
        if pattern in step.may_set:
            results |= {(c, False) for c in range(cap + 1)}
        return results

    def explore(
        self,
        starts: Iterable[ObjectState],
        allowed: Callable[[ObjectStep, ObjectState], bool] = lambda step, state: True,
    ) -> set[ObjectState] | None:
        """Every state reachable from ``starts`` by the steps ``allowed`` (None: more than MAX_STATES)."""
        seen = set(starts)
        frontier = list(seen)
        while frontier:
            state = frontier.pop()
            for step in self.steps:
                if not self.applies(step, state) or not allowed(step, state):
                    continue
                for following in self.successors(step, state):
                    if following not in seen:
                        seen.add(following)
                        frontier.append(following)
                        if len(seen) > MAX_STATES:
                            return None
        return seen


def _minus(count: int, gone: int, cap: int) -> range:
    """The counts left when ``gone`` atoms are deleted from ``count`` ("the cap or more" may stay the cap)."""
    if count == cap:
        return range(max(0, cap - gone), cap + 1)
    return range(count - gone, count - gone + 1) if count >= gone else range(0)


def step_of(domain: Domain, action: Action, variable: str | None, type_name: str) -> ObjectStep:
    """``action`` acting on the object bound to ``variable`` (None: through quantified variables only)."""
    requires: list[tuple[Atom, ObjectPattern]] = []
    forbids: set[ObjectPattern] = set()
    distinct: set[frozenset[str]] = set()
    derived = domain.derived_predicates  # no pattern of the object's: a condition on one is taken as met
    for part in conjuncts(action.precondition):
        if isinstance(part, Atom) and variable is not None and part.predicate not in derived:
            requires.extend((part, own) for own in occurrences(part, variable))
        elif isinstance(part, Not) and isinstance(part.body, Atom) and variable and part.body.args == (variable,):
            forbids.add((part.body.predicate, 0))
    distinct.update(frozenset((equality.left, equality.right)) for equality in _inequalities(action))
    adds: list[tuple[Atom, ObjectPattern]] = []
    deletes: list[tuple[Atom, ObjectPattern]] = []
    may_add: list[ObjectPattern] = []
    may_delete: list[ObjectPattern] = []
    many: set[ObjectPattern] = set()
    for item in effect_literals(action.effect):
        ranged = [name for name, kind in item.quantified if compatible(domain, kind, type_name)]
        names = ([variable] if variable is not None else []) + ranged
        found = [own for name in names for own in occurrences(item.atom, name)]
        if not found:
            continue
        if item.quantified:
            many.update(found)  # a quantified effect may set any number of atoms
        elif item.condition == TRUE and item.when is None:
            (adds if item.is_add else deletes).extend((item.atom, own) for own in found)
        else:
            (may_add if item.is_add else may_delete).extend(found)
    return ObjectStep(
        action,
        variable,
        tuple(requires),
        frozenset(forbids),
        tuple(adds),
        tuple(deletes),
        tuple(sorted(may_add)),
        tuple(sorted(may_delete)),
        frozenset(distinct),
        frozenset(many),
    )


def occurrences(atom: Atom, variable: str) -> list[ObjectPattern]:
    return [(atom.predicate, i) for i, arg in enumerate(atom.args) if arg == variable]


def parameters_of_type(domain: Domain, action: Action, type_name: str) -> list[str]:
    """The parameters of ``action`` an object of ``type_name`` can be bound to."""
    return [name for name, kind in action.parameters if compatible(domain, kind, type_name)]


def compatible(domain: Domain, one: str, other: str) -> bool:
    return domain.is_subtype(one, other) or domain.is_subtype(other, one)


def readable(domain: Domain, type_name: str) -> bool:
    """Whether every action's effect on an object of the type can be read through one parameter."""
    if domain.temporal or any(compatible(domain, kind, type_name) for kind in domain.constants.values()):
        return False
    for action in domain.actions:
        params = parameters_of_type(domain, action, type_name)
        distinct = {frozenset((equality.left, equality.right)) for equality in _inequalities(action)}
        if any(frozenset((a, b)) not in distinct for a, b in combinations(params, 2)):
            return False
    return True


def _inequalities(action: Action) -> Iterator[Equality]:
    """The ``(= ?x ?y)`` of the action's top-level ``not (= ?x ?y)`` conditions."""
    for part in conjuncts(action.precondition):
        if isinstance(part, Not) and isinstance(part.body, Equality):
            yield part.body


__all__ = [
    "ObjectStates",
    "ObjectPattern",
    "ObjectState",
    "ObjectStep",
    "compatible",
    "occurrences",
    "readable",
    "step_of",
]
