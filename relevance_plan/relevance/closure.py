"""Constraint closure: put back what the kept objects depend on.

Repeats until nothing changes: whatever stands on a kept object (it must be
moved first), whatever a kept object stands on or sits in (its place, the
container that must be opened), the objects of a predicate with a single
initial fact (the robot's only position), and the dependencies a knowledge
model declares.  Every object put back carries the fact that brought it.
"""

from __future__ import annotations

from collections import defaultdict
from collections.abc import Iterable, Set
from dataclasses import dataclass

from relevance_plan.relevance.analysis import ConstraintRule, FactIndex


@dataclass(frozen=True)
class Restored:
    name: str
    because_of: str  # the kept object that needed it ("" for singleton facts)
    rule: str  # "blocker", "anchor", "singleton", "model", "reachability", "soundness"
    fact: tuple[str, ...]  # the initial fact that ties them
    note: str = ""  # for "soundness": the quantifier that ranges over the object

    @property
    def reason(self) -> str:
        fact = "(" + " ".join(self.fact) + ")"
        if self.rule == "blocker":
            return f"on top of {self.because_of} {fact}"
        if self.rule == "anchor":
            return f"needed by {self.because_of} {fact}"
        if self.rule == "reachability":
            if self.fact == ("goal",):
                return "the goal is unreachable without it, even ignoring deletes"
            return f"used by a relaxed plan to the goal ({' '.join(self.fact)})"
        if self.rule == "soundness":
            return self.note
        if self.rule == "singleton":
            return f"only initial fact of its predicate {fact}"
        return f"declared dependency of {self.because_of} {fact}"


def close_over_constraints(
    kept: Set[str],
    rules: Iterable[ConstraintRule],
    index: FactIndex,
    candidates: Set[str],
    singleton_predicates: Set[str] = frozenset(),
    already: Set[str] = frozenset(),
) -> tuple[frozenset[str], tuple[Restored, ...]]:
    """Return (closed kept set, what was put back and why); inputs are not changed.

    ``candidates`` are the prunable objects; domain constants never need restoring.
    ``already``: a part of ``kept`` that is closed already (with the singleton
    facts), so only what the rest needs is walked: growing a set one object
    at a time costs one walk in all.
    """
    rules_by_predicate: dict[str, list[ConstraintRule]] = defaultdict(list)
    for rule in rules:
        rules_by_predicate[rule.predicate].append(rule)
    result = set(kept)
    restored: list[Restored] = []

    def keep(name: str, because_of: str, rule: str, fact: tuple[str, ...], worklist: list[str]) -> None:
        if name in candidates and name not in result:
            result.add(name)
            restored.append(Restored(name, because_of, rule, fact))
            worklist.append(name)

    worklist: list[str] = sorted(result - set(already))
    singletons = () if already else sorted(singleton_predicates)  # a closed part holds them already
    for predicate in singletons:
        for fact in index.by_predicate.get(predicate, ()):
            for arg in fact[1:]:
                keep(arg, "", "singleton", fact, worklist)
    while worklist:
        name = worklist.pop()
        for fact in index.by_object.get(name, ()):
            for rule in rules_by_predicate.get(fact[0], ()):
                if fact[1 + rule.when_kept] == name:
                    keep(fact[1 + rule.restore], name, rule.kind, fact, worklist)
    return frozenset(result), tuple(restored)
