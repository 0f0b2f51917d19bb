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
  (conservative: their polarity of use is not tracked);
* a universally quantified effect whose atom or fluent does not name the
  variable: it sets a kept fact (or adds to a number) once per object.

Existentials under positive polarity are safe (a witness among the kept
objects is a witness in the original), and so are universally quantified
effects on the variable's own facts (they change facts of pruned objects
that nothing reads except through a quantifier already covered above).

One refinement keeps its meaning: where the body holds whenever an atom on
the variable is false (``(forall (?x - t) (imply (g ?x) φ))``, ``(or (not (g
?x)) φ)``, ``(not (p ?o ?x))``; for an existential, whenever it is true: a
conjunct), and no effect makes that atom true of an object no action
parameter names, an object never named at that place in the atom's initial
or timed facts leaves the atom false in every state a plan of the pruned
problem reaches; only the objects so named must stay.  Where the atom's
other terms are no quantified variable, they name kept objects there, so
only a fact whose other objects are kept can match (``KeptObjects.linked``).
That is how an untyped domain says "every passenger", ``(forall (?p) (imply
(passenger ?p) (served ?p)))``, and how a scene graph says "in no
receptacle", ``(forall (?r - receptacle) (not (inreceptacle ?o ?r)))``: only
the receptacles holding a kept item stay.
"""

from __future__ import annotations

import functools
import itertools
from collections.abc import Callable, Iterable, Iterator, Mapping, Set
from dataclasses import dataclass

from relevance_plan.pddl import formulas as f
from relevance_plan.pddl.formatter import format_formula
from relevance_plan.pddl.model import Domain, Problem, Spelling


@dataclass(frozen=True)
class SoundnessRequirement:
    """Objects of ``type_name`` (those ``guard`` admits, if any) that a quantifier ranges over."""

    type_name: str
    where: str  # "the goal", "action 'stop'", ... (names as the user wrote them)
    formula: str  # the quantifier, as text in the user's spelling (shortened)
    guard: str | None = None  # a predicate whose facts name the objects that matter ...
    guard_position: int = 0  # ... at this place among its arguments ...
    linked: bool = False  # ... in a fact whose other objects are kept (the atom's other terms name kept objects)


def soundness_requirements(domain: Domain, problem: Problem) -> tuple[SoundnessRequirement, ...]:
    """Every quantifier whose range must stay whole, with where it is (the goal's first)."""
    problem_part = _requirements(_problem_formulas(problem), _never_gained(domain), problem.spelling)
    return problem_part + _domain_requirements(domain)


@functools.lru_cache(maxsize=16)
def _domain_requirements(domain: Domain) -> tuple[SoundnessRequirement, ...]:
    never_gained = _never_gained(domain)
    return _requirements(_domain_formulas(domain), never_gained, domain.spelling) + _effects_over_others(
        domain, never_gained
    )


def _effects_over_others(domain: Domain, never_gained: Callable[[str, int], bool]) -> tuple[SoundnessRequirement, ...]:
    """A universally quantified effect whose atom or fluent does not name its variable (``(forall (?p)
    (when (boarded ?p) (overloaded)))``, ``(forall (?p) (increase (load) (weight ?p)))``) sets a kept
    fact once for every object, pruned ones too: each object of the range stays, or only those the
    condition's atoms can admit (see ``_guards``)."""
    found: dict[tuple[str, str | None, int, str], SoundnessRequirement] = {}
    spelling = domain.spelling
    for action in domain.actions:
        where = f"action '{spelling.action(action.name)}'"
        effects: list[tuple[f.Formula, tuple[str, ...], f.Formula, f.Parameters]] = [
            (item.atom, item.atom.args, item.condition, item.quantified)
            for item in f.effect_literals(action.effect)
            if item.quantified
        ]
        effects += [
            (effect, effect.fluent.args, condition, quantified)
            for effect, condition, quantified, _ in f.numeric_effects(action.effect)
            if quantified
        ]
        for effect, named, condition, quantified in effects:
            others = [(variable, type_name) for variable, type_name in quantified if variable not in named]
            if not others:
                continue
            settling = [part for part in f.conjuncts(condition) if isinstance(part, f.Atom)]
            bound = _bound_variables(condition) | {variable for variable, _ in quantified}
            guards = _guarding_atoms(settling, {variable for variable, _ in others}, never_gained, bound)
            variables = " ".join(variable for variable, _ in others)
            text = _short(f"(forall ({variables}) ... {format_formula(effect, spelling)})")
            for variable, type_name in others:
                item = SoundnessRequirement(type_name, where, text, *guards.get(variable, (None, 0, False)))
                found.setdefault((type_name, item.guard, item.guard_position, where), item)
    return tuple(found.values())


def _requirements(
    formulas: Iterable[tuple[str, f.Formula, str, f.Parameters]],
    never_gained: Callable[[str, int], bool],
    spelling: Spelling,
) -> tuple[SoundnessRequirement, ...]:
    found: dict[tuple[str, str | None, int, str], SoundnessRequirement] = {}
    for where, formula, mode, effect_variables in formulas:
        bound = _bound_variables(formula) | {variable for variable, _ in effect_variables}
        for quantifier, _ in _risky(formula, mode):
            guards = _guards(quantifier, never_gained, bound)
            text = _short(format_formula(quantifier, spelling))
            for variable, type_name in quantifier.parameters:
                item = SoundnessRequirement(type_name, where, text, *guards.get(variable, (None, 0, False)))
                found.setdefault((type_name, item.guard, item.guard_position, where), item)
    return tuple(found.values())


def _bound_variables(formula: f.Formula) -> frozenset[str]:
    """Every variable a quantifier of ``formula`` binds: unlike an action's parameters, one that
    may stand for a pruned object in the original."""
    return frozenset(
        variable
        for node in f.walk(formula)
        if isinstance(node, (f.Exists, f.Forall))
        for variable, _ in node.parameters
    )


@dataclass(frozen=True)
class KeptObjects:
    """What the soundness rule keeps: ``always`` whatever else is kept; each of ``linked`` once
    all the other objects of one of its guard's facts are kept (the receptacle holding a kept item)."""

    always: Mapping[str, SoundnessRequirement]
    linked: Mapping[str, tuple[SoundnessRequirement, tuple[frozenset[str], ...]]]  # -> (requirement, facts' others)

    @functools.cached_property
    def _by_partner(self) -> Mapping[str, tuple[tuple[str, SoundnessRequirement, frozenset[str]], ...]]:
        index: dict[str, list[tuple[str, SoundnessRequirement, frozenset[str]]]] = {}
        for name, (requirement, partner_sets) in self.linked.items():
            for partners in partner_sets:
                for partner in partners:
                    index.setdefault(partner, []).append((name, requirement, partners))
        return {partner: tuple(entries) for partner, entries in index.items()}

    def admitted(self, kept: Set[str], added: Iterable[str]) -> dict[str, SoundnessRequirement]:
        """The linked objects outside ``kept`` that a fact naming one of ``added`` (a part of ``kept``:
        what is new since the last look) links to kept objects only."""
        found: dict[str, SoundnessRequirement] = {}
        for partner in added:
            for name, requirement, partners in self._by_partner.get(partner, ()):
                if name not in kept and name not in found and partners <= kept:
                    found[name] = requirement
        return found


def objects_to_keep(domain: Domain, problem: Problem, requirements: tuple[SoundnessRequirement, ...]) -> KeptObjects:
    """Each object a requirement keeps, with the first requirement that applies."""
    places: dict[str, set[int]] = {}
    for requirement in requirements:
        if requirement.guard:
            places.setdefault(requirement.guard, set()).add(requirement.guard_position)
    # (predicate, place) -> object named there -> the other objects of each such fact
    named: dict[tuple[str, int], dict[str, set[frozenset[str]]]] = {}
    if places:
        objects = problem.objects
        timed = (item.atom for item in problem.timed_literals if item.atom is not None and not item.negated)
        for atom in itertools.chain(problem.init, timed):
            for position in places.get(atom[0], ()):
                if len(atom) > position + 1:
                    others = frozenset(a for i, a in enumerate(atom[1:]) if i != position and a in objects)
                    named.setdefault((atom[0], position), {}).setdefault(atom[position + 1], set()).add(others)
    always: dict[str, SoundnessRequirement] = {}
    linked: dict[str, tuple[SoundnessRequirement, set[frozenset[str]]]] = {}
    for requirement in requirements:
        facts = named.get((requirement.guard, requirement.guard_position), {}) if requirement.guard else None
        for name, type_name in problem.objects.items():
            if name in always or not domain.is_subtype(type_name, requirement.type_name):
                continue
            if facts is None:
                always[name] = requirement
                continue
            partner_sets = facts.get(name)
            if partner_sets is None:
                continue  # never named there: the atom stays false of it
            if not requirement.linked or frozenset() in partner_sets:
                always[name] = requirement
            else:
                linked.setdefault(name, (requirement, set()))[1].update(partner_sets)
    return KeptObjects(
        always,
        {name: (req, tuple(sorted(sets, key=sorted))) for name, (req, sets) in linked.items() if name not in always},
    )


def _problem_formulas(problem: Problem) -> Iterator[tuple[str, f.Formula, str, f.Parameters]]:
    """(where, formula, mode, the variables of the quantified effect it conditions): mode
    "condition" checks universal polarity, "any" every quantifier."""
    yield "the goal", problem.goal, "condition", ()
    if problem.constraints is not None:
        yield "the problem's constraints", problem.constraints, "any", ()


def _domain_formulas(domain: Domain) -> Iterator[tuple[str, f.Formula, str, f.Parameters]]:
    if domain.constraints is not None:
        yield "the domain's constraints", domain.constraints, "any", ()
    spelling = domain.spelling
    for action in domain.actions:
        where = f"action '{spelling.action(action.name)}'"
        yield where, action.precondition, "condition", ()
        if action.duration is not None:
            yield where, action.duration, "condition", ()
        for item in f.effect_literals(action.effect):
            if item.condition != f.TRUE:
                yield where, item.condition, "any", item.quantified
        for _, condition, quantified, _ in f.numeric_effects(action.effect):
            if condition != f.TRUE:
                yield where, condition, "any", quantified
    for rule in domain.derived:
        yield f"derived predicate '{spelling.predicate(rule.head.predicate)}'", rule.body, "any", ()


def _risky(formula: f.Formula, mode: str) -> Iterator[tuple[f.Exists | f.Forall, bool]]:
    for quantifier, positive in f.quantifiers(formula):
        if _inside_preference(formula, quantifier):
            continue  # soft: a preference changes a plan's quality, never its validity
        universal = isinstance(quantifier, f.Forall) == positive
        if mode == "any" or universal:
            yield quantifier, positive


def _inside_preference(formula: f.Formula, target: f.Node) -> bool:
    return any(isinstance(node, f.Preference) and any(n is target for n in f.walk(node)) for node in f.walk(formula))


def _never_gained(domain: Domain) -> Callable[[str, int], bool]:
    """Whether no effect can make the predicate true of an object, at that place, that no action
    parameter names: such an object keeps the atom false if its initial and timed facts do."""
    derived = domain.derived_predicates
    gained = {
        (item.atom.predicate, position)
        for action in domain.actions
        for item in f.effect_literals(action.effect)
        if item.is_add and item.quantified
        for position, term in enumerate(item.atom.args)
        if term in {variable for variable, _ in item.quantified}
    }
    return lambda predicate, position: (
        predicate in domain.predicates and predicate not in derived and (predicate, position) not in gained
    )


def _guards(
    quantifier: f.Exists | f.Forall, never_gained: Callable[[str, int], bool], bound: Set[str]
) -> Mapping[str, tuple[str, int, bool]]:
    """Variable -> (predicate, place) of an atom on it whose falsity settles the body the way that
    makes the object not count (true for a universal, false for an existential)."""
    body = quantifier.body
    if isinstance(quantifier, f.Exists):
        parts = list(f.conjuncts(body)) if isinstance(body, f.And) else [body]
        settling = [p for p in parts if isinstance(p, f.Atom)]
    elif isinstance(body, f.Not) and isinstance(body.body, f.Atom):
        settling = [body.body]
    elif isinstance(body, f.Imply):
        settling = [p for p in f.conjuncts(body.condition) if isinstance(p, f.Atom)]
    elif isinstance(body, f.Or):
        settling = [p.body for p in body.parts if isinstance(p, f.Not) and isinstance(p.body, f.Atom)]
    else:
        return {}
    return _guarding_atoms(settling, {variable for variable, _ in quantifier.parameters}, never_gained, bound)


def _guarding_atoms(
    settling: Iterable[f.Atom], variables: Set[str], never_gained: Callable[[str, int], bool], bound: Set[str]
) -> Mapping[str, tuple[str, int, bool]]:
    """Variable -> (predicate, place, linked): ``linked`` when no other term of the atom is a
    quantified variable, so in a plan of the pruned problem each names a kept object (an action's
    parameter, a goal object) or a constant, and only facts whose other objects are kept can match."""
    guards: dict[str, tuple[str, int, bool]] = {}
    for atom in settling:
        for position, term in enumerate(atom.args):
            if term in variables and never_gained(atom.predicate, position):
                others = atom.args[:position] + atom.args[position + 1 :]
                guards.setdefault(term, (atom.predicate, position, not any(other in bound for other in others)))
    return guards


def _short(text: str, limit: int = 80) -> str:
    return text if len(text) <= limit else text[: limit - 1] + "…"
