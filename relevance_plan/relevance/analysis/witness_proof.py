"""A proof that a goal needs more witnesses than the problem has: the problem has no plan.

``witnesses`` finds goal atoms whose achievers use their witness up, and
whether the whole problem can give each its own; that finding is a judgement
from the action schemas, good enough to choose objects.  Before the tool
*says* a problem is unsolvable, this module proves it, and reads nothing of
that judgement but which predicate and achievers to try.

The argument, for one goal predicate P at a time:

* G is the set of *distinct* ground atoms of P that are top-level conjuncts
  of the goal and false initially.  Atoms compare as the parser leaves them
  (names lower-cased): ``(rel vase k1)`` written twice, in another letter
  case or inside a second ``and`` is one element of G.  An atom under ``or``,
  ``not``, ``imply`` or a quantifier is not in G (a plan need not make it
  true); an atom true initially is not (a plan need not add it).  Each g in G
  is true at the end of a plan and false at its start, so some step adds it;
  call the last one a(g).  No later step deletes g: a step that deletes and
  adds it (the add wins) would add it later still.
* Every action that adds an atom of P adds exactly one, without condition,
  quantifier or time, through a role of ``witnesses.consuming_roles``: a
  parameter, the witness, that is not an argument of the atom.  w(g) is the
  object a(g) binds to its action's witness.  It satisfies the action's
  top-level static preconditions (true in every state as they are
  initially), with g's objects for the atom's arguments, and has a type the
  parameter admits: it is among g's candidates, computed from those static
  facts over every object and constant (``witnesses.role_candidates``).
* w is one-to-one on G (below).  So G needs |G| distinct objects, each among
  its own candidates; a set S of atoms of G with fewer candidates in all than
  |S| (Hall's condition, ``witnesses.find_shortfall``) leaves every plan
  short: no plan exists.  Atoms of other predicates are counted apart (an
  object may witness an atom of P and one of Q at once).  The verdict also
  asks for the proof below when S is one atom with no candidate at all, where
  the counting alone would do: such a goal is left to a planner, as before,
  unless the whole argument goes through.
* Why w is one-to-one: let g1 != g2 have w(g1) = w(g2) = o.  After a(g1), o
  is only changed by steps that do not delete g1.  ``object_states`` finds
  the states o can be in from then on (a sound over-approximation of its
  facts); a step is left out where it certainly deletes g1 (below).  If no
  achiever of P applies to o as its witness in any of those states, no step
  after a(g1) has o as its witness, so a(g2) comes no later than a(g1); by
  the same reasoning a(g1) comes no later than a(g2).  They are one step,
  which adds one atom of P: g1 = g2, a contradiction.
* A step certainly deletes g1 when it deletes, without condition or
  quantifier, an atom of P each of whose arguments it ties to o exactly as
  the achiever tied g1's: the same constant, or the same chain of links from
  o.  A chain's links go through static facts that determine one object from
  another (the initial state says so: each item has one class), its first
  link possibly through an atom of o's that the achiever certainly left
  (added, or required and deleted by no effect that may name it), that was
  its only such atom of its kind and that is still o's only one of its kind
  (the vase is in the microwave the achiever put it in, and in nothing else).

Each assumption is checked, not assumed; where one fails there is no
verdict and the tool plans as usual:

* the types are read exactly: every object, constant, type parent, action
  parameter and quantified variable has one declared type (no ``either``;
  the tool's inferred classes of an untyped domain are never used here);
* no durative actions and no timed initial literals (facts that change
  without a step); P is not derived; derived predicates elsewhere, numeric
  conditions and effects, conditions on other objects and conditions inside
  ``or`` or quantifiers are taken as met;
* every adder of P has one role and one add of P, as above;
* for the distinctness: the achievers' witnesses have one type, no constant
  has a type related to it, and no action has two parameters that may bind
  the same object of it (``object_states.readable``); each achiever ties
  every argument of its atom; the exploration stays under its bound.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass

from relevance_plan.pddl.formulas import (
    TRUE,
    Atom,
    Exists,
    Forall,
    GroundAtom,
    conjuncts,
    effect_literals,
    is_variable,
    walk,
)
from relevance_plan.pddl.model import Domain, Problem, all_objects
from relevance_plan.relevance.analysis.facts import FactIndex
from relevance_plan.relevance.analysis.object_states import (
    ObjectPattern,
    ObjectState,
    ObjectStates,
    ObjectStep,
    readable,
    step_of,
)
from relevance_plan.relevance.analysis.types import static_predicates
from relevance_plan.relevance.analysis.witnesses import (
    WitnessNeed,
    WitnessRole,
    consuming_roles,
    find_shortfall,
    role_candidates,
)

Link = tuple[str, int, int]  # (predicate, the position it is read from, the position it gives)
Tie = tuple[Link, ...] | str  # how the achiever determines one argument of its atom: a chain from w, or a constant
First = tuple[tuple[Atom, int], ...]  # atoms of the witness's a chain may start with, each with the witness's place
MAX_CHAIN = 3  # links from the witness to one argument of the goal atom


@dataclass(frozen=True)
class _Proof:
    """What the proof for one achiever reads: the object states, the achiever's step and its ties."""

    states: ObjectStates
    predicate: str  # the goal's
    achiever: ObjectStep
    first: First  # the atoms the achiever certainly leaves, each its pattern's only one
    ties: tuple[Tie, ...]  # per argument of the goal atom
    functional: frozenset[Link]  # static links that determine one object from another

    def keeps_goal(self, step: ObjectStep, state: ObjectState) -> bool:
        return not _deletes_goal(self, step, state)


def unsolvable_by_witnesses(domain: Domain, problem: Problem, index: FactIndex) -> str:
    """Why the problem has no plan ("N distinct goal atoms need ..."), proved as the module's
    docstring says; "" when the proof does not go through (the tool then plans as usual)."""
    if domain.temporal or problem.timed_literals or not _types_exact(domain, problem):
        return ""
    goals = _distinct_goal_atoms(problem)
    roles = consuming_roles(domain, goals)
    objects = all_objects(domain, problem)
    for predicate in sorted(roles):
        if not _adds_through_roles(domain, predicate, roles[predicate]):
            continue
        needs = [_need(domain, index, objects, roles[predicate], atom) for atom in goals[predicate]]
        shortfall = find_shortfall(needs)
        if shortfall is None:
            continue
        if _witnesses_distinct(domain, problem, index, predicate, roles[predicate]):
            return shortfall.describe()
    return ""


def _distinct_goal_atoms(problem: Problem) -> dict[str, list[GroundAtom]]:
    """The goal's distinct top-level atoms false initially, by predicate, in the goal's order."""
    found: dict[str, list[GroundAtom]] = {}
    for part in conjuncts(problem.goal):
        if isinstance(part, Atom) and not any(is_variable(arg) for arg in part.args):
            atom = (part.predicate, *part.args)
            if atom not in problem.init and atom not in found.setdefault(part.predicate, []):
                found[part.predicate].append(atom)
    return {predicate: atoms for predicate, atoms in found.items() if atoms}


def _need(
    domain: Domain, index: FactIndex, objects: Mapping[str, str], roles: Sequence[WitnessRole], atom: GroundAtom
) -> WitnessNeed:
    """The goal atom with every object any of its achievers can use as its witness."""
    pool: dict[str, None] = {}
    for role in roles:
        pool.update(dict.fromkeys(role_candidates(domain, index, objects, role, atom)))
    return WitnessNeed(atom, tuple(pool))


# --------------------------------------------------------------------------- what the argument needs


def _types_exact(domain: Domain, problem: Problem) -> bool:
    """Whether every object, constant, type parent, parameter and quantified variable has one
    declared type (an ``(either ...)`` is read by different readers differently)."""
    known = set(domain.types) | {"object"}
    named = [*problem.objects.values(), *domain.constants.values(), *(p for p in domain.types.values() if p)]
    for action in domain.actions:
        named.extend(kind for _, kind in action.parameters)
        for node in (*walk(action.precondition), *walk(action.effect)):
            if isinstance(node, (Exists, Forall)):
                named.extend(kind for _, kind in node.parameters)
    return all(kind in known for kind in named)


def _adds_through_roles(domain: Domain, predicate: str, roles: Sequence[WitnessRole]) -> bool:
    """Whether every action that adds an atom of ``predicate`` adds one, without condition,
    quantifier or time, and has one role of ``roles`` (``predicate`` not derived)."""
    if predicate in domain.derived_predicates:
        return False
    adders = []
    for action in domain.actions:
        adds = [item for item in effect_literals(action.effect) if item.is_add and item.atom.predicate == predicate]
        if len(adds) > 1 or any(item.condition != TRUE or item.quantified or item.when for item in adds):
            return False
        if adds:
            adders.append(action.name)
    return sorted(adders) == sorted(role.action for role in roles)


def _witnesses_distinct(
    domain: Domain, problem: Problem, index: FactIndex, predicate: str, roles: Sequence[WitnessRole]
) -> bool:
    """Whether no object can be the witness of two goal atoms of ``predicate`` (the docstring's w is
    one-to-one): after any achiever, no achiever applies to its witness again."""
    types = {role.witness_type for role in roles}
    if len(types) != 1 or not readable(domain, next(iter(types))):
        return False
    states = ObjectStates(domain, problem, next(iter(types)))
    functional = _functional_links(domain, index)
    achievers = [_role_step(domain, role, states.type_name) for role in roles]
    before = states.explore(states.initial)
    if before is None:
        return False
    for role, step in zip(roles, achievers):
        first = _left_for_certain(step)
        ties = _ties_of_achiever(step, role, first, functional)
        if ties is None:
            return False
        proof = _Proof(states, predicate, step, first, ties, functional)
        after = states.explore(_right_after(proof, before), proof.keeps_goal)
        if after is None or any(states.applies(other, state) for other in achievers for state in after):
            return False
    return True


def _role_step(domain: Domain, role: WitnessRole, type_name: str) -> ObjectStep:
    action = next(action for action in domain.actions if action.name == role.action)
    return step_of(domain, action, role.witness, type_name)


def _left_for_certain(step: ObjectStep) -> First:
    """The witness's atoms the step certainly leaves, each the only such atom of its pattern (with
    the witness's place in it): its unconditional adds (an add wins over a delete), and the atoms
    it requires that no delete of the action may name."""
    deleted = [item for item in effect_literals(step.action.effect) if not item.is_add]
    found: dict[ObjectPattern, set[Atom]] = {}
    for atom, own in step.adds:
        found.setdefault(own, set()).add(atom)
    for atom, own in step.requires:
        if not any(_may_name(step, item.atom, atom, bool(item.quantified)) for item in deleted):
            found.setdefault(own, set()).add(atom)
    return tuple((atom, own[1]) for own, atoms in sorted(found.items()) if len(atoms) == 1 for atom in atoms)


def _may_name(step: ObjectStep, deleted: Atom, atom: Atom, quantified: bool) -> bool:
    """Whether a delete of ``deleted`` may remove ``atom`` under some binding (a quantified delete of
    the predicate may remove any of its atoms)."""
    if deleted.predicate != atom.predicate:
        return False
    return quantified or not step.different(deleted, atom)


def _right_after(proof: _Proof, before: set[ObjectState]) -> set[ObjectState]:
    """The witness's states right after the achiever, its certainly left atoms marked."""
    states, step = proof.states, proof.achiever
    marks = {states.index[(atom.predicate, place)] for atom, place in proof.first}
    return {
        ObjectState(after.counts, frozenset(i for i in marks if after.counts[i] > 0))
        for state in before
        if states.applies(step, state)
        for after in states.successors(step, state)
    }


def _functional_links(domain: Domain, index: FactIndex) -> frozenset[Link]:
    """(static predicate, from, to): the initial state gives each object at ``from`` one object at ``to``."""
    found = set()
    for predicate in static_predicates(domain):
        facts = index.by_predicate.get(predicate, ())
        arity = len(domain.predicates.get(predicate, ()))
        for start in range(arity):
            for end in range(arity):
                if start == end:
                    continue
                seen: dict[str, str] = {}
                if all(seen.setdefault(fact[1 + start], fact[1 + end]) == fact[1 + end] for fact in facts):
                    found.add((predicate, start, end))
    return frozenset(found)


def _ties_of_achiever(
    step: ObjectStep, role: WitnessRole, first: First, functional: frozenset[Link]
) -> tuple[Tie, ...] | None:
    """How the achiever determines each argument of its goal atom from the witness (None: one it does not)."""
    assert step.variable is not None
    static = _conditions(step)
    ties: list[Tie] = []
    for arg in role.goal_args:
        if not is_variable(arg):
            ties.append(arg)
            continue
        chain = _chain(step.variable, arg, first, static, functional)
        if chain is None:
            return None
        ties.append(chain)
    return tuple(ties)


def _chain(
    witness: str, target: str, first: First, static: Sequence[Atom], functional: frozenset[Link]
) -> tuple[Link, ...] | None:
    """The shortest chain of links from ``witness`` to ``target``: its first link through an atom of
    ``first`` (from the witness's place in it) or a functional static atom, the others through
    functional static atoms of ``static``."""
    if target == witness:
        return ()
    frontier: list[tuple[str, tuple[Link, ...]]] = [(witness, ())]
    for depth in range(MAX_CHAIN):
        following = []
        for term, chain in frontier:
            for link, value in _links_from(term, first if depth == 0 else (), static, functional):
                if value == target:
                    return (*chain, link)
                following.append((value, (*chain, link)))
        frontier = following
    return None


def _links_from(term: str, first: First, static: Iterable[Atom], functional: frozenset[Link]) -> list[tuple[Link, str]]:
    """The links a chain may take from ``term``, each with the term it leads to."""
    found = [
        ((atom.predicate, place, end), value)
        for atom, place in first
        for end, value in enumerate(atom.args)
        if end != place
    ]
    for atom in static:
        for start, arg in enumerate(atom.args):
            if arg != term:
                continue
            for end, value in enumerate(atom.args):
                link = (atom.predicate, start, end)
                if end != start and link in functional:
                    found.append((link, value))
    return found


def _conditions(step: ObjectStep) -> list[Atom]:
    """The step's action's top-level positive conditions (the chains' static links are among them)."""
    return [part for part in conjuncts(step.action.precondition) if isinstance(part, Atom)]


def _deletes_goal(proof: _Proof, step: ObjectStep, state: ObjectState) -> bool:
    """Whether ``step`` certainly deletes the goal atom the achiever made true (see the module's docstring)."""
    if step.variable is None:
        return False
    states = proof.states
    # a required atom is the achiever's own when its pattern's marked atom is still the witness's only one
    own = tuple(
        (atom, pattern[1])
        for atom, pattern in step.requires
        if states.index[pattern] in state.marked and state.counts[states.index[pattern]] == 1
    )
    static = _conditions(step)
    for item in effect_literals(step.action.effect):
        atom = item.atom
        if item.is_add or item.condition != TRUE or item.quantified or item.when or atom.predicate != proof.predicate:
            continue
        if all(
            arg == tie if isinstance(tie, str) else _chain(step.variable, arg, own, static, proof.functional) == tie
            for arg, tie in zip(atom.args, proof.ties)
        ):
            return True
    return False


__all__ = ["unsolvable_by_witnesses"]
