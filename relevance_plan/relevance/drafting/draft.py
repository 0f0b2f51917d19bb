"""The draft itself: classes, objectives, priors and dependencies, each with where it came from.

A class per type the problems' objects have (its kinds from their names): a
place (a type things lie at or in) is as relevant as what it holds, a person
always relevant, and every other class gets, per objective, a prior
P(class | task) that is high when the goal names one of its objects or the
goal scorer chose one for a role, and low otherwise; within a class, the
kinds that were chosen are weighed high and the others low.  One task per
objective, so P(task | objective) = 1.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace
from types import MappingProxyType
from typing import NamedTuple

from relevance_plan.pddl.model import Domain
from relevance_plan.relevance.drafting.evidence import ProblemEvidence, describe_goal, members_by_class
from relevance_plan.relevance.drafting.structure import DomainStructure, DraftedDependency
from relevance_plan.relevance.scoring.scene import kind_of

HIGH = 0.9  # a class or kind the problems say is wanted
LOW = 0.1  # one they say is not (below the default thresholds, with any kind and placement)
UNSEEN_KIND = 0.5  # a kind of a wanted class no given problem shows


class Prior(NamedTuple):
    """A drafted probability and where it came from (its comment in the file)."""

    value: float
    why: str


@dataclass(frozen=True)
class ClassDraft:
    """A drafted class: which objects belong, and how its relevance is found."""

    name: str
    types: tuple[str, ...]  # empty for a class inferred in an untyped domain (its kinds say who belongs)
    kinds: tuple[str, ...]
    role: str  # "item", "place" (relevance from its contents) or "person" (always relevant)
    why: str


@dataclass(frozen=True)
class ObjectiveDraft:
    """A drafted objective: the goal predicates of some of the given problems, and those problems."""

    name: str
    description: str  # the goals in plain words: what free text is matched against
    goal_predicates: tuple[str, ...]
    problems: tuple[str, ...] = ()  # the file names, for the comment


@dataclass(frozen=True)
class Draft:
    """A knowledge model being drafted; the check (``check.py``) returns changed copies."""

    domain: Domain
    structure: DomainStructure
    classes: Mapping[str, ClassDraft]
    objectives: Mapping[str, ObjectiveDraft]
    priors: Mapping[tuple[str, str], Prior]  # (objective, item class) -> P(class | the objective's task)
    kinds: Mapping[tuple[str, str], Prior]  # (class, kind) -> P(kind | class)
    dependencies: tuple[DraftedDependency, ...]
    left_out: tuple[tuple[DraftedDependency, str], ...] = ()  # dependencies the check left out, and why

    def with_prior(self, objective: str, class_name: str, prior: Prior) -> Draft:
        return replace(self, priors=MappingProxyType({**self.priors, (objective, class_name): prior}))

    def with_kind(self, class_name: str, kind: str, prior: Prior) -> Draft:
        return replace(self, kinds=MappingProxyType({**self.kinds, (class_name, kind): prior}))

    def with_dependency(self, dependency: DraftedDependency) -> Draft:
        return replace(self, dependencies=(*self.dependencies, dependency))

    def without_dependency(self, dependency: DraftedDependency, why: str) -> Draft:
        kept = tuple(d for d in self.dependencies if d != dependency)
        return replace(self, dependencies=kept, left_out=(*self.left_out, (dependency, why)))


def first_draft(
    domain: Domain,
    structure: DomainStructure,
    evidence: Sequence[ProblemEvidence],
    dependencies: Sequence[DraftedDependency],
) -> Draft:
    """The draft from the domain's structure and what the goal scorer says of the given problems."""
    members = members_by_class(evidence)
    classes = {name: _class_draft(domain, structure, name, kinds) for name, kinds in sorted(members.items())}
    objectives = _objectives(evidence)
    priors: dict[tuple[str, str], Prior] = {}
    kinds: dict[tuple[str, str], Prior] = {}
    for objective in objectives.values():
        seen = [item for item in evidence if item.objective == objective.name]
        for class_draft in classes.values():
            if class_draft.role == "item":
                priors[(objective.name, class_draft.name)] = _prior(class_draft.name, seen)
    for class_draft in classes.values():
        if class_draft.role == "item" and any(priors[(o, class_draft.name)].value == HIGH for o in objectives):
            for kind in class_draft.kinds:
                kinds[(class_draft.name, kind)] = _kind_prior(class_draft.name, kind, evidence)
    return Draft(
        domain,
        structure,
        MappingProxyType(classes),
        MappingProxyType(objectives),
        MappingProxyType(priors),
        MappingProxyType(kinds),
        tuple(dependencies),
    )


def _class_draft(domain: Domain, structure: DomainStructure, name: str, kinds: Mapping[str, set[str]]) -> ClassDraft:
    declared = name in domain.types
    types = (name,) if declared else ()
    count = sum(len(found) for found in kinds.values())
    if name in structure.humans:
        role, why = "person", f"type '{name}' stands for a person: always relevant"
    elif name in structure.place_types or name in structure.robot_places:
        role, why = "place", f"things are at or in a '{name}': as relevant as what it holds"
    else:
        role, why = "item", f"type '{name}'" if declared else f"objects alike in their initial facts ('{name}')"
    return ClassDraft(name, types, tuple(sorted(kinds)), role, f"{why}; {count} objects in the problems")


def _objectives(evidence: Sequence[ProblemEvidence]) -> dict[str, ObjectiveDraft]:
    grouped: dict[str, list[ProblemEvidence]] = {}
    for item in evidence:
        grouped.setdefault(item.objective, []).append(item)
    objectives = {}
    for name, items in sorted(grouped.items()):
        described = dict.fromkeys(part for item in items for part in describe_goal(item.task))
        predicates = items[0].goal_predicates
        objectives[name] = ObjectiveDraft(name, "; ".join(described), predicates, tuple(item.name for item in items))
    return objectives


def _prior(class_name: str, seen: Sequence[ProblemEvidence]) -> Prior:
    """P(class | task) from the objective's problems: the goal's classes and the roles the goal scorer filled."""
    named = sorted({item.name for item in seen for n in item.task.goal_objects if item.class_of(n) == class_name})
    chosen = sorted({item.name for item in seen for n in item.chosen if item.class_of(n) == class_name})
    depths = [
        depth
        for item in seen
        for t, depth in item.task.goal_analysis.role_depth.items()
        if t == class_name or item.task.domain.is_subtype(class_name, t)
    ]
    role = f"a role {min(depths)} step(s) from the goal" if depths else "no role in reaching the goal"
    if named:
        return Prior(HIGH, f"named in the goal ({', '.join(named)}); {role}")
    if chosen:
        return Prior(HIGH, f"{role}; the goal scorer chose some ({', '.join(chosen)})")
    if depths:
        return Prior(LOW, f"{role}, but the goal scorer chose none")
    return Prior(LOW, f"{role} (goal regression)")


def _kind_prior(class_name: str, kind: str, evidence: Sequence[ProblemEvidence]) -> Prior:
    wanted = sorted(
        {
            item.name
            for item in evidence
            for n in item.task.goal_objects | item.chosen
            if item.class_of(n) == class_name and kind_of(n) == kind
        }
    )
    if wanted:
        return Prior(HIGH, f"named in the goal or chosen ({', '.join(wanted)})")
    return Prior(LOW, "never named in the goal nor chosen in the given problems")
