"""Argument positions at which no action gives an object one more fact than it had.

The analyses read "functional" positions off the facts (``facts.index_init``):
a position is functional when no object there has two facts, so the object at
the position determines the rest (the receptacle an item is in, the place
the agent is at).  That is a guess about the domain made from one state, and
one fact can overturn it: a live scene that sees an item in its new
receptacle before it sees it leave the old one holds, for one event, an item
in two receptacles, and every receptacle would turn into a role of the goal,
every object scored again, for a state the next event undoes.

:func:`count_keeping_positions` finds the positions where the domain's
actions never raise an object's count: a small invariant search (the mutex
groups of Fast Downward's invariant synthesis, restricted to one key).  A
*group* is a set of (predicate, position) pairs; an object's *count* is the
number of true facts of the group with that object at the group's position
(an item's ``in`` facts and its ``holding`` facts).  No action raises it
when every action that adds a fact of the group for an object also deletes
one for the same object that its precondition requires (placing an item
deletes the holding its precondition asks for; picking it deletes the ``in``
fact it needs).  An object with one fact there keeps at most one in every
state the actions reach; an object with two got them from outside the
actions (a report seen halfway, a slip of perception, or a problem written
so), and no action gives a third.

``index_init`` uses them so that a minority of such objects does not
decide what the position is: there, a position stays functional while fewer
than half of its objects have two facts (closure then keeps both facts'
objects, and a role tied to such an object stays as determined as elsewhere).
Predicates no action changes are left out: nothing in the domain bounds them,
so the facts alone decide.
"""

from __future__ import annotations

import functools
from collections.abc import Iterable, Iterator

from relevance_plan.pddl.formulas import TRUE, Atom, conjuncts, effect_literals
from relevance_plan.pddl.model import Action, Domain, TimedLiteral

# A group holds at most this many predicates (an item's ``in`` and ``holding`` are two).
MAX_GROUP = 4

Position = tuple[str, int]  # (predicate, 0-based argument position)


@functools.lru_cache(maxsize=32)
def count_keeping_positions(domain: Domain) -> frozenset[Position]:
    """The (predicate, position) pairs of changing predicates of two or more arguments that some
    group whose count no action raises contains (see the module's docstring); none for a durative
    domain, whose timed effects this search does not follow."""
    if domain.temporal:
        return frozenset()
    changing = {item.atom.predicate for action in domain.relaxed_actions for item in effect_literals(action.effect)}
    return frozenset(
        (predicate, position)
        for predicate, parameters in domain.predicates.items()
        if predicate in changing and len(parameters) >= 2
        for position in range(len(parameters))
        if _in_a_kept_group(domain, (predicate, position))
    )


def count_keeping_for(domain: Domain, timed_literals: Iterable[TimedLiteral] = ()) -> frozenset[Position]:
    """:func:`count_keeping_positions` for a problem: less the predicates its timed literals make
    true (facts that come from outside the actions, as many as the problem says)."""
    timed = {literal.atom[0] for literal in timed_literals if literal.atom is not None and not literal.negated}
    return frozenset(position for position in count_keeping_positions(domain) if position[0] not in timed)


def _in_a_kept_group(domain: Domain, start: Position) -> bool:
    """Whether some group holding ``start`` (one position per predicate) has a count no action raises."""
    stack = [{start[0]: start[1]}]
    seen: set[frozenset[Position]] = set()
    while stack:
        group = stack.pop()
        key = frozenset(group.items())
        if key in seen or len(group) > MAX_GROUP:
            continue
        seen.add(key)
        missing = _unbalanced(domain, group)
        if missing is None:
            return True
        stack.extend({**group, predicate: position} for predicate, position in missing if predicate not in group)
    return False


def _unbalanced(domain: Domain, group: dict[str, int]) -> list[Position] | None:
    """None when no action raises the group's count; else what could balance the first action that
    does: the (predicate, position) of each fact it requires and deletes for the object whose count
    it raises (empty when nothing can)."""
    for action in domain.relaxed_actions:
        adds = [item for item in effect_literals(action.effect) if item.is_add and item.atom.predicate in group]
        if not adds:
            continue
        added = adds[0]
        if len(adds) > 1 or added.condition != TRUE or added.quantified:
            return []  # two facts at once, or under a condition or a forall: not followed
        key = added.atom.args[group[added.atom.predicate]]
        found = list(_required_deletes(action, key))
        if any(group.get(predicate) == position for predicate, position in found):
            continue
        return found
    return None


def _required_deletes(action: Action, key: str) -> Iterator[Position]:
    """(predicate, position) of each fact the action's precondition requires and its effect deletes
    (unconditionally) with ``key`` at that position."""
    required = {part for part in conjuncts(action.precondition) if isinstance(part, Atom)}
    for item in effect_literals(action.effect):
        if item.is_add or item.condition != TRUE or item.quantified or item.atom not in required:
            continue
        for position, arg in enumerate(item.atom.args):
            if arg == key:
                yield item.atom.predicate, position
