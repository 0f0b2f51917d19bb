"""Object classes for domains that declare no types.

Classic STRIPS domains say what an object is with static unary predicates:
``(truck t1)``, ``(ball b3)``, ``(location l2)``.  ``infer_types`` turns them
into declared types so that the goal analysis, closure and scoring treat an
untyped domain exactly as its typed version:

* an object's class is the set of static unary predicates true of it
  (``{airport, location}`` for an airport); objects with none are classed by
  the static predicates' argument positions they fill (``conn@0``), else they
  stay ``object``;
* a class's parent is the largest other class it contains, so an airport is
  a location;
* an action parameter gets the most specific class that every object
  satisfying its static unary preconditions belongs to.

A domain that declares types is returned unchanged.
"""

from __future__ import annotations

import dataclasses
from collections import defaultdict
from collections.abc import Collection, Mapping
from dataclasses import dataclass
from types import MappingProxyType

from relevance_plan.pddl.formulas import GroundAtom, effect_literals, literals
from relevance_plan.pddl.model import Domain, Problem


@dataclass(frozen=True)
class InferredTypes:
    domain: Domain  # the domain with inferred types (the given one when it declares types)
    problem: Problem  # the problem with each object's inferred type
    inferred: bool  # False when the domain declared its own types
    classes: tuple[tuple[str, tuple[str, ...]], ...] = ()  # (type name, its predicates) of every inferred class


def static_predicates(domain: Domain) -> frozenset[str]:
    """Predicates no action adds or deletes (derived predicates are never static)."""
    changed = {item.atom.predicate for action in domain.actions for item in effect_literals(action.effect)}
    changed |= domain.derived_predicates
    return frozenset(p for p in domain.predicates if p not in changed)


def declares_types(domain: Domain, problem: Problem) -> bool:
    if any(t != "object" for t in domain.types):
        return True
    return any(t != "object" for t in list(problem.objects.values()) + list(domain.constants.values()))


def _class_name(signature: frozenset[str]) -> str:
    return "+".join(sorted(signature)) if signature else "object"


def infer_types(domain: Domain, problem: Problem, by_predicate: Mapping[str, Collection[GroundAtom]]) -> InferredTypes:
    """Classes for the objects of an untyped problem from the static facts naming them (the problem
    unchanged where types are declared); ``by_predicate``: its initial facts by predicate (the fact
    index's)."""
    if declares_types(domain, problem):
        return InferredTypes(domain, problem, False)
    static = static_predicates(domain)
    unary = {p for p in static if len(domain.predicates.get(p, ())) == 1}
    names = list(domain.constants) + list(problem.objects)
    unary_of: dict[str, set[str]] = defaultdict(set)
    positions_of: dict[str, set[str]] = defaultdict(set)
    grouped = {p: atoms for p, atoms in by_predicate.items() if p in static and atoms}
    # each distinct object of a predicate's position once (a tall building's 125,000 ``above`` facts
    # name its 500 floors)
    for predicate, atoms in grouped.items():
        for position in range(1, len(next(iter(atoms)))):
            tag = predicate if predicate in unary else f"{predicate}@{position - 1}"
            into = unary_of if predicate in unary else positions_of
            for arg in {atom[position] for atom in atoms}:
                into[arg].add(tag)
    signature = {name: frozenset(unary_of[name] or positions_of[name]) for name in names}
    classes = sorted({s for s in signature.values() if s}, key=lambda s: (len(s), sorted(s)))
    if not classes:
        return InferredTypes(domain, problem, False)
    types: dict[str, str] = {"object": ""}
    for cls in classes:
        parents = [other for other in classes if other < cls]
        parent = max(parents, key=lambda s: (len(s), sorted(s))) if parents else None
        types[_class_name(cls)] = _class_name(parent) if parent else "object"

    def parameter_type(needed: frozenset[str]) -> str:
        if not needed:
            return "object"
        candidates = [cls for cls in classes if needed <= cls]
        if not candidates:
            return "object"
        for meet in sorted(candidates, key=len):
            name = _class_name(meet)
            if all(_is_subtype(types, _class_name(c), name) for c in candidates):
                return name
        return "object"

    actions = []
    for action in domain.actions:
        needed: dict[str, set[str]] = defaultdict(set)
        for literal, positive in literals(action.precondition):
            if not positive or literal.predicate not in static:
                continue
            args = literal.args
            if literal.predicate in unary:
                needed[args[0]].add(literal.predicate)
            else:
                for position, arg in enumerate(args):
                    needed[arg].add(f"{literal.predicate}@{position}")
        params = []
        for variable, declared in action.parameters:
            wanted = frozenset(needed[variable] & unary) or frozenset(needed[variable] - unary)
            params.append((variable, parameter_type(wanted) if declared == "object" else declared))
        actions.append(dataclasses.replace(action, parameters=tuple(params)))
    frozen_types = MappingProxyType(types)
    typed_domain = dataclasses.replace(
        domain,
        types=frozen_types,
        constants=MappingProxyType({c: _class_name(signature[c]) for c in domain.constants}),
        actions=tuple(actions),
    )
    typed_problem = dataclasses.replace(
        problem, objects=MappingProxyType({o: _class_name(signature[o]) for o in problem.objects})
    )
    return InferredTypes(typed_domain, typed_problem, True, tuple((_class_name(c), tuple(sorted(c))) for c in classes))


def _is_subtype(types: Mapping[str, str], type_name: str, of: str) -> bool:
    seen = set()
    while type_name and type_name not in seen:
        if type_name == of:
            return True
        seen.add(type_name)
        type_name = types.get(type_name, "")
    return of == "object"
