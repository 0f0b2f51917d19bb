"""The neighbourhood of a selection in a network (``analysis.network``): where widening grows.

Where static links join everything, a failed selection lacks what lies next to it (a cell beside
the route to step aside into, the cell an obstacle can be pushed to), seldom something far away.
So widening there adds a ring: the network's members one link from a kept member.  A ring comes
in two sizes: its free members (nothing a blocker rule ties to them stands there), which cost the
planner little, and the whole ring, with what stands on the members kept so far.
"""

from __future__ import annotations

from collections.abc import Set

from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.selection.closure import ConstraintClosure


def ring(task: PlanningTask, kept: Set[str]) -> frozenset[str]:
    """The network's members one link away from a member of ``kept``, outside ``kept``."""
    network = task.network
    by_object = task.init_index.by_object
    around: set[str] = set()
    for name in kept & network.members:
        for fact in by_object.get(name, ()):
            if fact[0] in network.predicates:
                around.update(arg for arg in fact[1:] if arg not in kept)
    return frozenset(around)


def occupied(task: PlanningTask, closure: ConstraintClosure, names: Set[str]) -> frozenset[str]:
    """Those of ``names`` that a blocker rule's initial fact ties another object to (an obstacle
    stands on the cell): keeping one keeps its occupant too."""
    blockers = {(rule.predicate, rule.when_kept) for rule in closure.rules if rule.kind == "blocker"}
    if not blockers:
        return frozenset()
    by_object = task.init_index.by_object
    return frozenset(
        name
        for name in names
        if any(
            (fact[0], position) in blockers
            for fact in by_object.get(name, ())
            for position, arg in enumerate(fact[1:])
            if arg == name
        )
    )


def occupants(task: PlanningTask, closure: ConstraintClosure, names: Set[str]) -> frozenset[str]:
    """The objects a blocker rule's initial fact ties to one of ``names`` (the obstacles on the cells)."""
    blockers = [rule for rule in closure.rules if rule.kind == "blocker"]
    by_object = task.init_index.by_object
    found: set[str] = set()
    for name in names:
        for fact in by_object.get(name, ()):
            for rule in blockers:
                if fact[0] == rule.predicate and fact[1 + rule.when_kept] == name:
                    found.add(fact[1 + rule.restore])
    return frozenset(found)


def next_ring(task: PlanningTask, closure: ConstraintClosure, kept: Set[str], step: int) -> frozenset[str]:
    """What widening step ``step`` (from 0) adds: on even steps the ring's free members (the whole
    ring when none is free), on odd steps the whole ring and the occupants of the kept members
    (closure brings a network member's blockers back only on demand): an occupied cell of the new
    ring stays a wall until a later step keeps what stands on it, so obstacles come back from the
    way outwards, not all at once."""
    around = ring(task, kept)
    free = around - occupied(task, closure, around)
    if step % 2 == 0 and free:
        return free
    return around | (occupants(task, closure, kept) - kept)
