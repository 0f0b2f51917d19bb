"""Which initial facts tie one object to another so tightly that keeping one requires keeping the other.

Read off the action schemas and the initial state, never off names: a fact an action must undo
before the kept object can be used (``blocking_predicates``: unstacking, taking a plate off a
cup), a fact the kept object determines (a functional position of the index), and a predicate
with one initial fact that every action adding one also deletes (the robot's only position).
Closure (``selection.closure``) follows these rules.
"""

from __future__ import annotations

from dataclasses import dataclass

from relevance_plan.pddl.formulas import effect_literals, literals
from relevance_plan.pddl.model import Domain
from relevance_plan.relevance.analysis.facts import FactIndex


@dataclass(frozen=True)
class ConstraintRule:
    """Keeping the object at ``when_kept`` of a ``predicate`` fact keeps the one at ``restore``."""

    predicate: str
    when_kept: int  # 0-based argument position
    restore: int
    kind: str  # "blocker", "anchor", "singleton", "model"
    relation: str = ""  # what the knowledge model says a fact of it is ("on top of"); "" when it says nothing


def _condition_predicates(domain: Domain) -> set[str]:
    used: set[str] = set()
    for action in domain.relaxed_actions:
        used.update(atom.predicate for atom, _ in literals(action.precondition))
        for item in effect_literals(action.effect):
            used.update(atom.predicate for atom, _ in literals(item.condition))
    return used


def blocking_predicates(domain: Domain) -> set[tuple[str, int, int]]:
    """Binary relations whose removal frees something: (predicate, blocker_pos, blocked_pos).

    Found from schemas of the form 'precondition B(?a, ?b); deletes B(?a, ?b);
    adds U(?b)' where U is needed by some precondition: removing ?a is what
    makes ?b usable again (unstack in blocksworld, taking a plate off a cup).
    """
    needed = {
        atom.predicate
        for action in domain.relaxed_actions
        for atom, positive in literals(action.precondition)
        if positive
    }
    found = set()
    for action in domain.actions:
        pre = [atom for atom, positive in literals(action.precondition) if positive]
        effects = list(effect_literals(action.effect))
        deleted = {item.atom for item in effects if not item.is_add}
        added = [item.atom for item in effects if item.is_add]
        for atom in pre:
            if len(atom.args) != 2 or atom not in deleted:
                continue
            a, b = atom.args
            for add in added:
                if add.predicate in needed and add.args == (b,) and a != b:
                    found.add((atom.predicate, 0, 1))
    return found


def infer_constraint_rules(domain: Domain, index: FactIndex) -> tuple[ConstraintRule, ...]:
    """Closure rules read off the action schemas and the initial state."""
    used = _condition_predicates(domain)
    rules: list[ConstraintRule] = []
    for predicate, blocker, blocked in sorted(blocking_predicates(domain)):
        rules.append(ConstraintRule(predicate, blocked, blocker, "blocker"))
    for predicate, key, other in sorted(index.functional):
        if predicate in used:
            rules.append(ConstraintRule(predicate, key, other, "anchor"))
    return tuple(rules)


def single_valued_predicates(domain: Domain, index: FactIndex) -> frozenset[str]:
    """Predicates with one initial fact that stay single-valued: every action adding one deletes one.

    The robot's position is the typical case: pruning the place it stands on
    would leave it nowhere.
    """
    result = set()
    for predicate in index.singletons:
        (atom,) = index.by_predicate[predicate]
        if len(atom) < 2:
            continue
        adders = [
            action
            for action in domain.relaxed_actions
            if any(item.is_add and item.atom.predicate == predicate for item in effect_literals(action.effect))
        ]
        if adders and all(
            any(not item.is_add and item.atom.predicate == predicate for item in effect_literals(action.effect))
            for action in adders
        ):
            result.add(predicate)
    return frozenset(result)
