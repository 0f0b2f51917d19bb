"""Which objects pruning must keep so that a plan of the pruned problem is a plan of the original.

Pruning removes objects, their initial facts and their numeric values.  A
plan of the pruned problem names kept objects only, so the facts of a pruned
object keep their initial values in the original too — unless a formula
quantifies over its type.  Where that can change a verdict, the objects of
the type stay:

* a universal condition (``forall`` under positive polarity, ``exists``
  under negation) in the goal, a precondition, a durative condition or a
  duration constraint: the pruned problem would check fewer objects;
* any quantifier in the condition of a conditional effect: an effect could
  fire in the original and not in the pruned problem, or the other way round;
* any quantifier in a derived predicate's body or a trajectory constraint
  (conservative: their polarity of use is not tracked).

Existentials under positive polarity are safe (a witness among the kept
objects is a witness in the original), and so are universally quantified
effects on their own (they change facts of pruned objects that nothing
reads except through a quantifier already covered above).

One refinement keeps its meaning: in ``forall (?x - t) (imply (g ?x) φ)``
(or ``(or (not (g ?x)) φ)``) with ``g`` a static predicate, an object for
which ``g`` is false in the initial state satisfies the formula whatever
happens, so only the objects the guard admits must stay.  That is how an
untyped domain says "every passenger": ``(forall (?p) (imply (passenger ?p) (served ?p)))``.
"""

from __future__ import annotations

import functools
from collections.abc import Iterable, Iterator, Mapping
from dataclasses import dataclass

from relevance_plan.pddl import formulas as f
from relevance_plan.pddl.formatter import format_formula
from relevance_plan.pddl.model import Domain, Problem


@dataclass(frozen=True)
class KeptForSoundness:
    """Objects of ``type_name`` (those ``guard`` admits, if any) that a quantifier ranges over."""

    type_name: str
    where: str  # "the goal", "action 'stop'", ...
    formula: str  # the quantifier, as text (shortened)
    guard: str | None = None  # a static unary predicate that admits the objects that matter


def soundness_requirements(domain: Domain, problem: Problem) -> tuple[KeptForSoundness, ...]:
    """Every quantifier whose range must stay whole, with where it is (the goal's first)."""
    return _requirements(_problem_formulas(problem), _static_unary(domain)) + _domain_requirements(domain)


@functools.lru_cache(maxsize=16)
def _domain_requirements(domain: Domain) -> tuple[KeptForSoundness, ...]:
    return _requirements(_domain_formulas(domain), _static_unary(domain))


def _requirements(
    formulas: Iterable[tuple[str, f.Formula, str]], static: frozenset[str]
) -> tuple[KeptForSoundness, ...]:
    found: dict[tuple[str, str | None, str], KeptForSoundness] = {}
    for where, formula, mode in formulas:
        for quantifier, _ in _risky(formula, mode):
            guards = _guards(quantifier, static)
            text = _short(format_formula(quantifier))
            for variable, type_name in quantifier.parameters:
                item = KeptForSoundness(type_name, where, text, guards.get(variable))
                found.setdefault((type_name, item.guard, where), item)
    return tuple(found.values())


def objects_to_keep(
    domain: Domain, problem: Problem, requirements: tuple[KeptForSoundness, ...]
) -> dict[str, KeptForSoundness]:
    """Object -> the requirement that keeps it (the first one that applies)."""
    guards = {requirement.guard for requirement in requirements if requirement.guard}
    guarded: dict[str, set[str]] = {}
    if guards:
        for atom in problem.init:
            if len(atom) == 2 and atom[0] in guards:
                guarded.setdefault(atom[0], set()).add(atom[1])
    kept: dict[str, KeptForSoundness] = {}
    for requirement in requirements:
        admitted = guarded.get(requirement.guard, set()) if requirement.guard else None
        for name, type_name in problem.objects.items():
            if name in kept or not domain.is_subtype(type_name, requirement.type_name):
                continue
            if admitted is None or name in admitted:
                kept[name] = requirement
    return kept


def _problem_formulas(problem: Problem) -> Iterator[tuple[str, f.Formula, str]]:
    """(where, formula, mode): mode "condition" checks universal polarity, "any" every quantifier."""
    yield "the goal", problem.goal, "condition"
    if problem.constraints is not None:
        yield "the problem's constraints", problem.constraints, "any"


def _domain_formulas(domain: Domain) -> Iterator[tuple[str, f.Formula, str]]:
    if domain.constraints is not None:
        yield "the domain's constraints", domain.constraints, "any"
    for action in domain.actions:
        where = f"action '{action.name}'"
        yield where, action.precondition, "condition"
        if action.duration is not None:
            yield where, action.duration, "condition"
        for item in f.effect_literals(action.effect):
            if item.condition != f.TRUE:
                yield where, item.condition, "any"
        for _, condition, _, _ in f.numeric_effects(action.effect):
            if condition != f.TRUE:
                yield where, condition, "any"
    for rule in domain.derived:
        yield f"derived predicate '{rule.head.predicate}'", rule.body, "any"


def _risky(formula: f.Formula, mode: str) -> Iterator[tuple[f.Exists | f.Forall, bool]]:
    for quantifier, positive in f.quantifiers(formula):
        if _inside_preference(formula, quantifier):
            continue  # soft: a preference changes a plan's quality, never its validity
        universal = isinstance(quantifier, f.Forall) == positive
        if mode == "any" or universal:
            yield quantifier, positive


def _inside_preference(formula: f.Formula, target: f.Node) -> bool:
    return any(isinstance(node, f.Preference) and any(n is target for n in f.walk(node)) for node in f.walk(formula))


def _static_unary(domain: Domain) -> frozenset[str]:
    changed = {item.atom.predicate for action in domain.actions for item in f.effect_literals(action.effect)}
    changed |= domain.derived_predicates
    return frozenset(p for p, params in domain.predicates.items() if len(params) == 1 and p not in changed)


def _guards(quantifier: f.Exists | f.Forall, static: frozenset[str]) -> Mapping[str, str]:
    """Variable -> a static unary predicate that must hold of it for the body to matter."""
    body = quantifier.body
    if isinstance(quantifier, f.Exists):
        # under negation an existential is a universal: (not (exists (?x) (and (g ?x) φ)))
        parts = list(f.conjuncts(body)) if isinstance(body, f.And) else [body]
        positive = [p for p in parts if isinstance(p, f.Atom)]
    elif isinstance(body, f.Imply):
        positive = [p for p in f.conjuncts(body.condition) if isinstance(p, f.Atom)]
    elif isinstance(body, f.Or):
        positive = [p.body for p in body.parts if isinstance(p, f.Not) and isinstance(p.body, f.Atom)]
    else:
        return {}
    variables = {variable for variable, _ in quantifier.parameters}
    guards: dict[str, str] = {}
    for atom in positive:
        if atom.predicate in static and len(atom.args) == 1 and atom.args[0] in variables:
            guards.setdefault(atom.args[0], atom.predicate)
    return guards


def _short(text: str, limit: int = 80) -> str:
    return text if len(text) <= limit else text[: limit - 1] + "…"
