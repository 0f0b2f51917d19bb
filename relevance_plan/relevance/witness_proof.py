"""A proof that a goal needs more witnesses than the problem has: the problem has no plan.

``witnesses`` finds goal atoms whose achievers use their witness up, and
whether the whole problem can give each its own; that finding is a judgement
from the action schemas, good enough to choose objects.  Before the tool
*says* a problem is unsolvable, this module proves it, soundly:

1. Every action that adds an atom of the goal's predicate adds one, without
   condition or quantifier, through a role of ``witnesses.consuming_roles``.
2. Take a goal atom g false initially and the last step of a plan that adds
   it, with witness w.  No later step deletes g.  The states w can be in
   after that step are found with ``object_states`` (a sound
   over-approximation of one object's facts), leaving out the steps that
   certainly delete g.  If no achiever of the predicate applies to w in any
   of them, w cannot be the witness of a later goal atom of the predicate.
3. A step certainly deletes g when it deletes an atom of the predicate each
   of whose arguments it ties to w exactly as the achiever tied g's: through
   static facts that determine one object from another (the initial state
   says so: each item has one class), and through the atom of w's that the
   achiever added and that is still w's only one of its kind (the vase is in
   the microwave the achiever put it in, and in nothing else).
4. So the goal atoms of the predicate that are false initially need pairwise
   different witnesses, each among its candidates (the objects the
   achiever's static conditions admit); when no matching gives each its own,
   no plan reaches the goal.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from relevance_plan.pddl.formulas import TRUE, Atom, conjuncts, effect_literals, is_variable
from relevance_plan.pddl.model import Domain, Problem
from relevance_plan.relevance.analysis import FactIndex
from relevance_plan.relevance.object_states import ObjectStates, State, Step, readable, step_of
from relevance_plan.relevance.types import static_predicates
from relevance_plan.relevance.witnesses import WitnessNeed, WitnessRole, consuming_roles, match_witnesses

Link = tuple[str, int, int]  # (predicate, the position it is read from, the position it gives)
MAX_CHAIN = 3  # links from the witness to one argument of the goal atom


@dataclass(frozen=True)
class _Proof:
    """What the proof for one role reads: the object states, the achiever's step and its ties."""

    states: ObjectStates
    predicate: str  # the goal's
    achiever: Step
    ties: tuple[tuple[Link, ...] | str, ...]  # per argument of the goal atom: its chain from w, or a constant
    functional: frozenset[Link]  # static links that determine one object from another

    def keeps_goal(self, step: Step, state: State) -> bool:
        return not _deletes_goal(self, step, state)


def unsolvable_by_witnesses(
    domain: Domain, problem: Problem, index: FactIndex, needs: Sequence[WitnessNeed], reason: str
) -> str:
    """``reason`` ("N goal atoms need ...") proved to leave the problem without a plan; "" when the
    proof does not go through (the tool then plans as usual)."""
    if not reason:
        return ""
    _, unmatched = match_witnesses(needs, lambda need, name: True)
    short = sorted({need.goal[0] for need in unmatched})
    roles = consuming_roles(domain, short)
    for predicate in short:
        if not _predicate_proved(domain, problem, index, predicate, roles.get(predicate, ())):
            return ""
    return reason


def _predicate_proved(
    domain: Domain, problem: Problem, index: FactIndex, predicate: str, roles: Sequence[WitnessRole]
) -> bool:
    if not roles or predicate in domain.derived_predicates or not _adds_one_plainly(domain, predicate):
        return False
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
        ties = _ties_of_achiever(step, role, functional)
        if ties is None:
            return False
        proof = _Proof(states, predicate, step, ties, functional)
        after = states.explore(_right_after(proof, before), proof.keeps_goal)
        if after is None or any(states.applies(other, state) for other in achievers for state in after):
            return False
    return True


def _adds_one_plainly(domain: Domain, predicate: str) -> bool:
    """Whether each action adds at most one atom of ``predicate``, without condition or quantifier."""
    for action in domain.actions:
        adds = [item for item in effect_literals(action.effect) if item.is_add and item.atom.predicate == predicate]
        if len(adds) > 1 or any(item.condition != TRUE or item.quantified or item.when for item in adds):
            return False
    return True


def _role_step(domain: Domain, role: WitnessRole, type_name: str) -> Step:
    action = next(action for action in domain.actions if action.name == role.action)
    return step_of(domain, action, role.witness, type_name)


def _right_after(proof: _Proof, before: set[State]) -> set[State]:
    """The witness's states right after the achiever, its atoms the achiever added or kept marked."""
    states, step = proof.states, proof.achiever
    kept = {own for atom, own in step.requires if atom not in {a for a, _ in step.deletes}}
    marks = frozenset(states.index[own] for own in {own for _, own in step.adds} | kept)
    return {
        State(after.counts, marks)
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
    step: Step, role: WitnessRole, functional: frozenset[Link]
) -> tuple[tuple[Link, ...] | str, ...] | None:
    """How the achiever determines each argument of its goal atom from the witness (None: one it does not)."""
    assert step.variable is not None
    dynamic = [atom for atom, _ in step.adds] + [
        atom for atom, _ in step.requires if atom not in {a for a, _ in step.deletes}
    ]
    static = _conditions(step)
    ties: list[tuple[Link, ...] | str] = []
    for arg in role.goal_args:
        if not is_variable(arg):
            ties.append(arg)
            continue
        chain = _chain(step.variable, arg, dynamic, static, functional)
        if chain is None:
            return None
        ties.append(chain)
    return tuple(ties)


def _chain(
    witness: str,
    target: str,
    first: Sequence[Atom],
    static: Sequence[Atom],
    functional: frozenset[Link],
) -> tuple[Link, ...] | None:
    """The shortest chain of links from ``witness`` to ``target``: its first link an atom of ``first``
    (atoms of the witness's) or a functional static one, the others functional static atoms of ``static``."""
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


def _links_from(
    term: str, first: Sequence[Atom], static: Sequence[Atom], functional: frozenset[Link]
) -> list[tuple[Link, str]]:
    """The links a chain may take from ``term``, each with the term it leads to."""
    found = []
    for atom in [*first, *static]:
        for start, arg in enumerate(atom.args):
            if arg != term:
                continue
            for end, value in enumerate(atom.args):
                link = (atom.predicate, start, end)
                if end != start and (atom in first or link in functional):
                    found.append((link, value))
    return found


def _conditions(step: Step) -> list[Atom]:
    """The step's action's top-level positive conditions (the chains' static links are among them)."""
    return [part for part in conjuncts(step.action.precondition) if isinstance(part, Atom)]


def _deletes_goal(proof: _Proof, step: Step, state: State) -> bool:
    """Whether ``step`` certainly deletes the goal atom the achiever made true (see the module's docstring)."""
    if step.variable is None:
        return False
    states = proof.states
    # a required atom of the witness is the achiever's own when it is the witness's only one of its pattern
    own = [
        atom
        for atom, pattern in step.requires
        if states.index[pattern] in state.marked and state.counts[states.index[pattern]] == 1
    ]
    static = _conditions(step)
    for item in effect_literals(step.action.effect):
        atom = item.atom
        if item.is_add or item.condition != TRUE or item.quantified or atom.predicate != proof.predicate:
            continue
        if all(
            arg == tie if isinstance(tie, str) else _chain(step.variable, arg, own, static, proof.functional) == tie
            for arg, tie in zip(atom.args, proof.ties)
        ):
            return True
    return False


__all__ = ["unsolvable_by_witnesses"]
