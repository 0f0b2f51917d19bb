"""The static links that tie objects of one class into a network: a grid's cells, a maze's.

A static binary predicate whose facts join objects of the same class (or of a class and one of
its subclasses), each to a single next one (the cell above), links them; when those facts tie
many objects together, closure following them from any one reaches the rest.  Closure must not
follow such a link as a dependency (the cell above a kept cell is not needed because the kept
one is): which cells a plan uses is a question of the way, answered by the relaxed plan of the
repair, not by the links.  Read off the domain's schemas and the initial state, never off names.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

from relevance_plan.pddl.model import Domain
from relevance_plan.relevance.analysis.facts import FactIndex
from relevance_plan.relevance.analysis.types import static_predicates

# A link predicate is a network only when its facts join at least this many objects: a counter's
# few levels (``next n0 n1``) stay dependencies, as they were, while a grid's cells do not.
NETWORK_MIN_OBJECTS = 25


@dataclass(frozen=True)
class Network:
    """The link predicates of a task and the objects they join."""

    predicates: frozenset[str]
    members: frozenset[str]

    def __bool__(self) -> bool:
        return bool(self.predicates)


NO_NETWORK = Network(frozenset(), frozenset())


def find_network(domain: Domain, classes: Mapping[str, str], index: FactIndex) -> Network:
    """The static binary predicates whose initial facts join objects of related classes
    (``classes``: object -> its class, declared or inferred), where they join enough objects."""
    predicates: set[str] = set()
    members: set[str] = set()
    # only links closure would follow (a member determines the next: ``FactIndex.functional``); a
    # road map's many roads per place never chained the closure, so nothing changes there
    followed = {predicate for predicate, _, _ in index.functional}
    for predicate in sorted(static_predicates(domain) & followed):
        facts = index.by_predicate.get(predicate, ())
        if not facts or any(len(fact) != 3 for fact in facts):
            continue
        joined: set[str] = set()
        for _, first, second in facts:
            if first == second or not _related(domain, classes.get(first), classes.get(second)):
                break
            joined.update((first, second))
        else:
            if len(joined) >= NETWORK_MIN_OBJECTS:
                predicates.add(predicate)
                members |= joined
    return Network(frozenset(predicates), frozenset(members)) if predicates else NO_NETWORK


def _related(domain: Domain, first: str | None, second: str | None) -> bool:
    if first is None or second is None:
        return False
    return first in domain.ancestors(second) or second in domain.ancestors(first)
