"""Constraint closure: put back what the kept objects depend on.

Repeats until nothing changes: the object of a fact that an action must undo
before a kept object can be used (a plate on a kept cup, an obstacle in a
kept cell), the object a kept one's fact determines (its place, the
container that must be opened), the objects of a predicate with a single
initial fact (the robot's only position), and the dependencies a knowledge
model declares.  Every object put back carries the fact that brought it;
what the fact means is said only where the knowledge model says it (its
``support`` and ``containment`` roles), never read off a predicate's name.

``close_over_constraints`` is the worklist itself; ``ConstraintClosure`` runs
it on one task with that task's rules, and keeps besides what a quantifier
ranges over (``soundness``): the closure every pruning stage and the repair call.
"""

from __future__ import annotations

from collections import defaultdict
from collections.abc import Iterable, Set
from dataclasses import dataclass, replace

from relevance_plan.pddl.formatter import format_atom, format_step
from relevance_plan.pddl.model import UNSPELLED, Domain, Spelling
from relevance_plan.relevance.analysis.constraint_rules import (
    ConstraintRule,
    infer_constraint_rules,
    single_valued_predicates,
)
from relevance_plan.relevance.analysis.facts import FactIndex
from relevance_plan.relevance.analysis.soundness import SoundnessRequirement
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.scoring.knowledge import KnowledgeModel


@dataclass(frozen=True)
class Restored:
    name: str
    because_of: str  # the kept object that needed it ("" for singleton facts)
    rule: str  # "blocker", "anchor", "singleton", "model", "reachability", "soundness"
    fact: tuple[str, ...]  # the initial fact that ties them (for "reachability": the relaxed plan's step)
    note: str = ""  # for "soundness": the quantifier that ranges over the object
    relation: str = ""  # what the knowledge model says the fact is ("on top of"); "" when it says nothing

    def describe(self, spelling: Spelling = UNSPELLED) -> str:
        """Why it came back, every name as ``spelling`` (the problem's) writes it."""
        fact = format_atom(self.fact, spelling) if self.fact else ""
        kept = spelling.object(self.because_of)
        if self.rule == "blocker":
            # an action must undo the fact before the kept object can be used
            return f"{self.relation} {kept} {fact}" if self.relation else f"undoing {fact} frees {kept}"
        if self.rule == "anchor":
            return f"needed by {kept} {fact}"
        if self.rule == "reachability":
            if self.fact == ("goal",):
                return "the goal is unreachable without it, even ignoring deletes"
            return f"used by a relaxed plan to the goal {format_step(self.fact[0], self.fact[1:], spelling)}"
        if self.rule == "soundness":
            return self.note
        if self.rule == "singleton":
            return f"only initial fact of its predicate {fact}"
        return f"declared dependency of {kept} {fact}"


def close_over_constraints(
    kept: Set[str],
    rules: Iterable[ConstraintRule],
    index: FactIndex,
    candidates: Set[str],
    singleton_predicates: Set[str] = frozenset(),
    already: Set[str] = frozenset(),
    on_demand: Set[str] = frozenset(),
) -> tuple[frozenset[str], tuple[Restored, ...]]:
    """Return (closed kept set, what was put back and why); inputs are not changed.

    ``candidates`` are the prunable objects; domain constants never need restoring.
    ``already``: a part of ``kept`` that is closed already (with the singleton
    facts), so only what the rest needs is walked: growing a set one object
    at a time costs one walk in all.  The inferred rules are not followed from an object of
    ``on_demand`` (a network's member): kept without what blocks it, it stays blocked (a cell whose
    obstacle is pruned is a wall), and the reachability repair brings back what a relaxed plan needs.
    """
    rules_by_predicate: dict[str, list[ConstraintRule]] = defaultdict(list)
    for rule in rules:
        rules_by_predicate[rule.predicate].append(rule)
    result = set(kept)
    restored: list[Restored] = []

    def keep(name: str, because_of: str, rule: ConstraintRule, fact: tuple[str, ...], worklist: list[str]) -> None:
        if name in candidates and name not in result:
            result.add(name)
            restored.append(Restored(name, because_of, rule.kind, fact, relation=rule.relation))
            worklist.append(name)

    worklist: list[str] = sorted(result - set(already))
    singletons = () if already else sorted(singleton_predicates)  # a closed part holds them already
    for predicate in singletons:
        for fact in index.by_predicate.get(predicate, ()):
            for arg in fact[1:]:
                keep(arg, "", SINGLETON, fact, worklist)
    while worklist:
        name = worklist.pop()
        for fact in index.by_object.get(name, ()):
            for rule in rules_by_predicate.get(fact[0], ()):
                if fact[1 + rule.when_kept] == name and not (rule.kind in _ON_DEMAND and name in on_demand):
                    keep(fact[1 + rule.restore], name, rule, fact, worklist)
    return frozenset(result), tuple(restored)


_ON_DEMAND = frozenset({"blocker", "anchor"})  # the rules not followed from an object of ``on_demand``
SINGLETON = ConstraintRule("", 0, 0, "singleton")  # a predicate's only initial fact keeps its objects

# What a blocker rule's fact is, by the knowledge model's scene role of its predicate: the first
# argument stands on, or is inside, the second.
_RELATIONS = {"support": "on top of", "containment": "inside"}


def constraint_rules(
    domain: Domain, index: FactIndex, knowledge_model: KnowledgeModel | None
) -> tuple[ConstraintRule, ...]:
    """The rules inferred from the domain's schemas, and the dependencies the knowledge model declares;
    a rule whose predicate the model gives a scene role says what its fact is."""
    rules = list(infer_constraint_rules(domain, index))
    if knowledge_model is not None:
        roles = knowledge_model.scene.for_domain(domain).roles()
        relation = {roles[role]: words for role, words in _RELATIONS.items() if roles[role] is not None}
        rules = [
            replace(rule, relation=relation[rule.predicate])
            if rule.kind == "blocker" and (rule.restore, rule.when_kept) == (0, 1) and rule.predicate in relation
            else rule
            for rule in rules
        ]
        for dependency in knowledge_model.dependencies:
            rules.append(ConstraintRule(dependency.predicate, dependency.when_kept, dependency.restore, "model"))
    return tuple(rules)


@dataclass(frozen=True)
class ConstraintClosure:
    """Closure over constraints on one task, keeping what soundness needs; called as
    ``closure(names, already)`` -> (the closed set, what it put back and why)."""

    task: PlanningTask
    rules: tuple[ConstraintRule, ...]
    singletons: frozenset[str]  # predicates with a single initial fact
    on_demand: frozenset[str] = frozenset()  # the network's members: their blockers come back on demand

    @classmethod
    def of(cls, task: PlanningTask, knowledge_model: KnowledgeModel | None) -> ConstraintClosure:
        domain, index = task.domain, task.init_index
        rules = constraint_rules(domain, index, knowledge_model)
        network = task.network
        if network:
            # a link of a network ties each member to the next: followed, it keeps the whole grid,
            # so which members a plan needs is left to the reachability repair (the way, not the network)
            links = network.predicates
            rules = tuple(rule for rule in rules if not (rule.kind == "anchor" and rule.predicate in links))
        return cls(task, rules, single_valued_predicates(domain, index), network.members)

    def __call__(self, names: Set[str], already: Set[str] = frozenset()) -> tuple[frozenset[str], tuple[Restored, ...]]:
        """``names`` closed (``already``: a part of them this closure closed before, whose links were followed)."""
        # what a quantifier ranges over stays, so that a plan of the pruned problem is one of the original
        sound = self.task.kept_for_soundness
        missing = sorted(sound.always.keys() - set(names))
        closed, found = self._over_constraints(set(names) | set(missing), already)
        spelling = self.task.problem.spelling
        reasons = [soundness_reason(name, sound.always[name], spelling) for name in missing]
        added = closed - already
        while sound.linked:
            linked = sound.admitted(closed, added)
            if not linked:
                break
            reasons += (soundness_reason(name, req, spelling) for name, req in sorted(linked.items()))
            grown, more = self._over_constraints(closed | linked.keys(), closed)
            found += more
            added, closed = grown - closed, grown
        return closed, tuple(reasons) + found

    def _over_constraints(self, names: Set[str], already: Set[str]) -> tuple[frozenset[str], tuple[Restored, ...]]:
        task = self.task
        return close_over_constraints(
            names, self.rules, task.init_index, task.problem.objects.keys(), self.singletons, already, self.on_demand
        )


def soundness_reason(name: str, requirement: SoundnessRequirement, spelling: Spelling = UNSPELLED) -> Restored:
    admitted = f" with ({spelling.predicate(requirement.guard)} ...)" if requirement.guard else ""
    every = spelling.type(requirement.type_name)
    note = f"{requirement.where} quantifies over every {every}{admitted}: {requirement.formula}"
    return Restored(name, "", "soundness", (), note)
