"""What stays true of every object of one type in every reachable state: a lifted, sound analysis.

A *pattern* is an atom about one object with its other arguments left open:
``(inreceptacle w ?)`` is ``("inreceptacle", 0)``.  Two kinds of invariant
are found for the objects of a type:

* *at most one*: an object has at most one true atom of the pattern (a vase
  is in at most one receptacle);
* *exclusive*: an object never has true atoms of both patterns (a vase held
  is in no receptacle).

They are the greatest set of candidates that the initial state satisfies and
that every action keeps, assuming the candidates before it (the inductive
proof of mutexes planners' invariant synthesis uses, on one object's
patterns).  An action keeps "at most one p" when, adding a p atom about the
object, it adds only one and either requires a fact exclusive with p, or
requires ``not p`` (p has no other argument), or deletes the p atom it
requires; it keeps "p exclusive with q" when, adding p, it adds no q and q
was false before (a condition exclusive with q, or ``not q``) or it deletes
the q atom it requires.  Conditional and quantified effects count as adds
that may happen and deletes that may not.

The analysis answers only where it can read what an action does to the
object: a domain with durative actions, an action with two parameters that
may both be the object (no ``(not (= ?x ?y))`` between them), or a constant
of the type gets no invariants (None).  ``witnesses`` uses them to prove
that a goal needs more objects of a kind than the problem has.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass
from itertools import combinations

from relevance_plan.pddl.formulas import TRUE, Atom, Equality, Not, conjuncts, effect_literals
from relevance_plan.pddl.model import Action, Domain, Problem

Pattern = tuple[str, int]  # (predicate, the object's position)


@dataclass(frozen=True)
class Effects:
    """What one action requires and does of the object bound to one of its parameters."""

    requires: tuple[tuple[Atom, Pattern], ...]  # top-level positive conditions on it, with its pattern in each
    requires_not: frozenset[Pattern]  # top-level ``not (p ?x)`` where the object is p's only argument
    adds: tuple[tuple[Atom, Pattern], ...]  # unconditional adds on it
    may_add: frozenset[Pattern]  # conditional or quantified adds that may be about it
    deletes: frozenset[Atom]  # unconditional deletes
    may_delete: frozenset[Pattern]

    def added(self, pattern: Pattern) -> bool:
        return pattern in self.may_add or any(own == pattern for _, own in self.adds)

    def touched(self, pattern: Pattern) -> bool:
        """Whether the step may delete an atom of ``pattern`` about the object."""
        return pattern in self.may_delete or any(own == pattern for atom, own in self.requires if atom in self.deletes)


@dataclass(frozen=True)
class ObjectInvariants:
    """The invariants of the objects of one type (see the module's docstring)."""

    type_name: str
    at_most_one: frozenset[Pattern]
    exclusive_pairs: frozenset[frozenset[Pattern]]

    def exclusive(self, one: Pattern, other: Pattern) -> bool:
        return one != other and frozenset((one, other)) in self.exclusive_pairs


def occurrences(atom: Atom, variable: str) -> list[Pattern]:
    return [(atom.predicate, i) for i, arg in enumerate(atom.args) if arg == variable]


def effects_on(domain: Domain, action: Action, variable: str | None, type_name: str) -> Effects:
    """``action``'s conditions and effects on the object bound to ``variable`` (None: an object of
    ``type_name`` the action names through a quantified variable only)."""
    requires: list[tuple[Atom, Pattern]] = []
    requires_not: set[Pattern] = set()
    for part in conjuncts(action.precondition):
        if isinstance(part, Atom) and variable is not None:
            requires.extend((part, own) for own in occurrences(part, variable))
        elif isinstance(part, Not) and isinstance(part.body, Atom) and part.body.args == (variable,):
            requires_not.add((part.body.predicate, 0))
    adds: list[tuple[Atom, Pattern]] = []
    may_add: set[Pattern] = set()
    deletes: set[Atom] = set()
    may_delete: set[Pattern] = set()
    for item in effect_literals(action.effect):
        ranged = [name for name, kind in item.quantified if _compatible(domain, kind, type_name)]
        found = [own for name in [variable, *ranged] if name is not None for own in occurrences(item.atom, name)]
        if not found:
            continue
        if item.condition == TRUE and not item.quantified and item.when is None:
            if item.is_add:
                adds.extend((item.atom, own) for own in found)
            else:
                deletes.add(item.atom)
        (may_add if item.is_add else may_delete).update(found if item.quantified or item.condition != TRUE else ())
    return Effects(
        tuple(requires),
        frozenset(requires_not),
        tuple(adds),
        frozenset(may_add),
        frozenset(deletes),
        frozenset(may_delete),
    )


def steps_of(domain: Domain, type_name: str) -> list[Effects]:
    """Every way an action can act on an object of the type: through each parameter of the type, and
    through quantified variables of the type only."""
    steps = []
    for action in domain.actions:
        for variable in parameters_of_type(domain, action, type_name):
            steps.append(effects_on(domain, action, variable, type_name))
        wild = effects_on(domain, action, None, type_name)
        if wild.may_add or wild.may_delete:
            steps.append(wild)
    return steps


def parameters_of_type(domain: Domain, action: Action, type_name: str) -> list[str]:
    """The parameters of ``action`` an object of ``type_name`` can be bound to."""
    return [name for name, kind in action.parameters if _compatible(domain, kind, type_name)]


def _compatible(domain: Domain, one: str, other: str) -> bool:
    return domain.is_subtype(one, other) or domain.is_subtype(other, one)


def _distinct(action: Action, first: str, second: str) -> bool:
    """Whether ``action`` requires its two parameters to be different objects."""
    return any(
        isinstance(part, Not)
        and isinstance(part.body, Equality)
        and {part.body.left, part.body.right} == {first, second}
        for part in conjuncts(action.precondition)
    )


def analysable(domain: Domain, type_name: str) -> bool:
    """Whether every action's effect on an object of the type can be read through one parameter."""
    if domain.temporal or any(_compatible(domain, kind, type_name) for kind in domain.constants.values()):
        return False
    for action in domain.actions:
        params = parameters_of_type(domain, action, type_name)
        if any(not _distinct(action, a, b) for a, b in combinations(params, 2)):
            return False
    return True


def object_invariants(domain: Domain, problem: Problem, type_name: str) -> ObjectInvariants | None:
    """The invariants of the objects of ``type_name`` (None: the domain is not one the analysis reads)."""
    if not analysable(domain, type_name):
        return None
    patterns = sorted(_patterns(domain, type_name))
    at_most_one, pairs = _initially(domain, problem, type_name, patterns)
    steps = steps_of(domain, type_name)
    invariants = ObjectInvariants(type_name, frozenset(at_most_one), frozenset(pairs))
    while True:
        kept_one = {p for p in invariants.at_most_one if all(_keeps_one(step, p, invariants) for step in steps)}
        kept_pairs = {
            pair for pair in invariants.exclusive_pairs if all(_keeps_apart(step, pair, invariants) for step in steps)
        }
        if kept_one == invariants.at_most_one and kept_pairs == invariants.exclusive_pairs:
            return invariants
        invariants = ObjectInvariants(type_name, frozenset(kept_one), frozenset(kept_pairs))


def _patterns(domain: Domain, type_name: str) -> Iterator[Pattern]:
    derived = domain.derived_predicates
    for predicate, parameters in domain.predicates.items():
        if predicate in derived:
            continue
        for position, (_, kind) in enumerate(parameters):
            if _compatible(domain, kind, type_name):
                yield predicate, position


def _initially(
    domain: Domain, problem: Problem, type_name: str, patterns: list[Pattern]
) -> tuple[set[Pattern], set[frozenset[Pattern]]]:
    """The candidates the initial state satisfies."""
    objects = {name for name, kind in problem.objects.items() if _compatible(domain, kind, type_name)}
    counts: dict[str, dict[Pattern, int]] = {}
    for atom in problem.init:
        for position, arg in enumerate(atom[1:]):
            if arg in objects:
                seen = counts.setdefault(arg, {})
                seen[(atom[0], position)] = seen.get((atom[0], position), 0) + 1
    at_most_one = {p for p in patterns if all(seen.get(p, 0) <= 1 for seen in counts.values())}
    pairs = {
        frozenset(pair)
        for pair in combinations(patterns, 2)
        if not any(seen.get(pair[0]) and seen.get(pair[1]) for seen in counts.values())
    }
    return at_most_one, pairs


def false_before(step: Effects, pattern: Pattern, invariants: ObjectInvariants) -> bool:
    """Whether the step's conditions make every ``pattern`` atom about the object false before it."""
    return pattern in step.requires_not or any(invariants.exclusive(own, pattern) for _, own in step.requires)


def deletes_its_own(step: Effects, pattern: Pattern, invariants: ObjectInvariants) -> bool:
    """Whether the step requires a ``pattern`` atom and deletes it, the object having at most one."""
    return pattern in invariants.at_most_one and any(
        own == pattern and atom in step.deletes for atom, own in step.requires
    )


def _keeps_one(step: Effects, pattern: Pattern, invariants: ObjectInvariants) -> bool:
    added = {atom for atom, own in step.adds if own == pattern}
    if pattern in step.may_add or len(added) > 1:
        return False
    if not added:
        return True
    return false_before(step, pattern, invariants) or deletes_its_own(step, pattern, invariants)


def _keeps_apart(step: Effects, pair: frozenset[Pattern], invariants: ObjectInvariants) -> bool:
    one, other = sorted(pair)
    for added, kept_false in ((one, other), (other, one)):
        if not step.added(added):
            continue
        if step.added(kept_false):
            return False
        if not (false_before(step, kept_false, invariants) or deletes_its_own(step, kept_false, invariants)):
            return False
    return True


__all__ = [
    "Effects",
    "ObjectInvariants",
    "Pattern",
    "analysable",
    "deletes_its_own",
    "effects_on",
    "false_before",
    "object_invariants",
    "occurrences",
    "parameters_of_type",
    "steps_of",
]
