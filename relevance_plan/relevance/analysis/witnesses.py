"""Witnesses: the objects a goal atom is met through when it names none of them.

``(classrelation vase microwave)`` holds once any vase is in any microwave: the
goal names two classes, and a plan needs one vase and one microwave, its
*witnesses*.  Some achievers use their witness up: putting the vase into the
microwave leaves it there, and taking it out again deletes the goal atom, so a
second goal atom of the same kind, ``(classrelation vase bench)``, needs a
second vase.  The delete relaxation does not see this (one vase serves both in
a relaxed plan), so a selection that keeps one vase passes the relaxed check
and fails the planner.  This module finds, from the action schemas alone:

* which goal predicates are only ever achieved by actions that use a witness
  up (:func:`consuming_roles`): the achiever deletes a precondition on the
  witness (``holds ?a ?i``), and no action can make that precondition true
  again without deleting the goal atom (picking the vase up deletes the
  ``classrelation``) or without a fact the achiever made false;
* for each such goal atom of a problem, the objects that can be its witness
  (the static facts the achiever requires between the witness and the goal's
  objects: ``itemclass ?i vase``), best connected first (:func:`witness_needs`);
* whether a set of usable witnesses gives every goal atom its own
  (:func:`match_witnesses`, a bipartite matching), and when even the whole
  problem cannot, the goal atoms that are short and the objects they share
  (:func:`find_shortfall`: a set of goal atoms with fewer candidates than atoms).

Goal atoms are compared as the parser leaves them (names lower-cased): the
same atom written twice, or in another letter case, is one goal atom and
needs one witness.  The relaxed check (``reachability.exploration``) asks for that
matching on top of reaching the goal; the repair adds the best next
candidate of a goal atom left without one; widening tries the next witness
before anything else.  All of this is a judgement that guides the choice of
objects; ``witness_proof`` proves a shortfall before the tool calls a
problem unsolvable.
"""

from __future__ import annotations

import weakref
from collections.abc import Callable, Collection, Iterable, Mapping, Sequence
from dataclasses import dataclass, field

from relevance_plan.pddl.formatter import format_formula, format_parameters
from relevance_plan.pddl.formulas import (
    Atom,
    Exists,
    Formula,
    GroundAtom,
    conjuncts,
    effect_literals,
    is_variable,
    literals,
)
from relevance_plan.pddl.model import Action, Domain, Problem
from relevance_plan.relevance.analysis.distances import ObjectGraph, graph_distances
from relevance_plan.relevance.analysis.facts import FactIndex
from relevance_plan.relevance.analysis.types import static_predicates

# (predicate, positions): an atom about one object, the other arguments left open
Pattern = tuple[str, tuple[int, ...]]


@dataclass(frozen=True)
class WitnessRole:
    """One achiever of a goal predicate and the parameter it uses up."""

    action: str
    goal_args: tuple[str, ...]  # the achiever's arguments of the goal atom (variables or constants)
    witness: str  # the parameter used up (``?i``)
    witness_type: str
    consumed: tuple[Pattern, ...]  # the witness's preconditions the achiever makes false for good
    links: tuple[Atom, ...]  # the static top-level preconditions that name the witness


@dataclass(frozen=True)
class WitnessNeed:
    """A goal atom that needs a witness of its own, and the objects that can be it; or an existential
    goal ``(exists (?v - t) body)`` and the objects that can be its ``?v`` (``variable``, ``body``)."""

    goal: GroundAtom  # the goal atom; for an existential, its text in parts ("exists", "(?v - t)", "(body)")
    candidates: tuple[str, ...]  # best connected first
    consumed: tuple[Pattern, ...] = ()  # a reached fact of one of these about a candidate makes it usable
    variable: str = ""  # an existential's variable
    body: tuple[Atom, ...] = ()  # an existential's conditions: the atoms its witness must reach

    def grounded(self, name: str) -> list[GroundAtom]:
        """An existential's body with ``name`` for its variable."""
        return [(atom.predicate, *(name if arg == self.variable else arg for arg in atom.args)) for atom in self.body]


# --------------------------------------------------------------------------- the lifted analysis


def consuming_roles(domain: Domain, predicates: Iterable[str]) -> dict[str, tuple[WitnessRole, ...]]:
    """Of ``predicates``, those every achiever of which uses a witness up -> those achievers' roles.

    A predicate with one achiever that uses nothing up (a truck unloading a
    package: the truck drives on) is left out: one witness may serve many
    goal atoms there.  Worked out once per domain and predicate."""
    analysis = _analysis_of(domain)
    found = {}
    for predicate in predicates:
        if predicate not in analysis.roles:
            analysis.roles[predicate] = _roles_of(analysis, predicate)
        roles = analysis.roles[predicate]
        if roles:
            found[predicate] = roles
    return found


@dataclass(frozen=True)
class _OnParameter:
    """One action's top-level conditions and effects on one of its parameters, as patterns."""

    action: Action
    variable: str
    needs: frozenset[Pattern]  # positive conditions of changing predicates
    forbids: frozenset[Pattern]
    adds: frozenset[Pattern]
    deletes: frozenset[Pattern]
    deleted_whole: frozenset[str]  # predicates it deletes an atom of whose arguments its conditions all tie to it


@dataclass
class _DomainAnalysis:
    domain: Domain
    static: frozenset[str]
    roles: dict[str, tuple[WitnessRole, ...]] = field(default_factory=dict)  # predicate -> roles (() for none)
    summaries: list[_OnParameter] | None = None

    @property
    def on_parameters(self) -> list[_OnParameter]:
        """Every action's conditions and effects on each of its parameters (read when first needed)."""
        if self.summaries is None:
            self.summaries = [
                _on_parameter(action, variable, self.static)
                for action in self.domain.actions
                for variable, _ in action.parameters
            ]
        return self.summaries


_ANALYSES: weakref.WeakKeyDictionary[Domain, _DomainAnalysis] = weakref.WeakKeyDictionary()


def _analysis_of(domain: Domain) -> _DomainAnalysis:
    analysis = _ANALYSES.get(domain)
    if analysis is None:
        analysis = _ANALYSES[domain] = _DomainAnalysis(domain, static_predicates(domain))
    return analysis


def _on_parameter(action: Action, variable: str, static: frozenset[str]) -> _OnParameter:
    needs: set[Pattern] = set()
    forbids: set[Pattern] = set()
    for atom, polarity in literals(action.precondition):
        if variable in atom.args and atom.predicate not in static:
            (needs if polarity else forbids).add(_pattern(atom, variable))
    adds: set[Pattern] = set()
    deletes: set[Pattern] = set()
    whole: set[str] = set()
    tied = _tied_to(action, variable)
    for item in effect_literals(action.effect):
        if variable in item.atom.args:
            (adds if item.is_add else deletes).add(_pattern(item.atom, variable))
        if not item.is_add and all(arg in tied for arg in item.atom.args if is_variable(arg)):
            whole.add(item.atom.predicate)
    return _OnParameter(
        action, variable, frozenset(needs), frozenset(forbids), frozenset(adds), frozenset(deletes), frozenset(whole)
    )


def _roles_of(analysis: _DomainAnalysis, predicate: str) -> tuple[WitnessRole, ...]:
    """The roles of every achiever of ``predicate``; () when one of them uses nothing up."""
    roles = []
    for action in analysis.domain.actions:
        for effect in effect_literals(action.effect):
            if not effect.is_add or effect.atom.predicate != predicate:
                continue
            found = None if effect.quantified else _consumed_role(analysis, action, effect.atom)
            if found is None:
                return ()
            roles.append(found)
    return tuple(roles)


def _consumed_role(analysis: _DomainAnalysis, action: Action, goal: Atom) -> WitnessRole | None:
    """The first parameter of ``action`` outside ``goal`` that achieving ``goal`` uses up, if any."""
    static = analysis.static
    bound = {arg for arg in goal.args if is_variable(arg)}
    positive = [atom for atom, polarity in literals(action.precondition) if polarity]
    deleted = {item.atom for item in effect_literals(action.effect) if not item.is_add}
    added = [item.atom for item in effect_literals(action.effect) if item.is_add]
    for witness, witness_type in action.parameters:
        if witness in bound:
            continue
        # a precondition on the witness alone (the other objects are not the goal's) that the achiever deletes
        spent = [
            atom
            for atom in positive
            if witness in atom.args
            and atom in deleted
            and atom not in added
            and not any(arg in bound for arg in atom.args if arg != witness)
        ]
        if not spent:
            continue
        after = {_pattern(atom, witness) for atom in added if witness in atom.args}
        after |= {_pattern(atom, witness) for atom in positive if witness in atom.args and atom not in deleted}
        reachable = _reachable_after(analysis, after, witness_type, goal.predicate)
        consumed = tuple(sorted({_pattern(atom, witness) for atom in spent}))
        if all(pattern not in reachable for pattern in consumed):
            return WitnessRole(action.name, goal.args, witness, witness_type, consumed, _links(action, witness, static))
    return None


def _links(action: Action, witness: str, static: frozenset[str]) -> tuple[Atom, ...]:
    """The static atoms among the action's top-level conditions that name ``witness``: every binding
    the action applies with satisfies them (an atom inside ``or`` or a quantifier need not hold)."""
    return tuple(
        part
        for part in conjuncts(action.precondition)
        if isinstance(part, Atom) and part.predicate in static and witness in part.args
    )


def _pattern(atom: Atom, variable: str) -> Pattern:
    return atom.predicate, tuple(i for i, arg in enumerate(atom.args) if arg == variable)


def _reachable_after(
    analysis: _DomainAnalysis, true_after: set[Pattern], witness_type: str, goal_predicate: str
) -> set[Pattern]:
    """What can become true of the witness after the achiever, by actions that keep the goal atom.

    Of the witness only what the achiever says is known to hold (its effects,
    its preconditions it keeps, the static facts); every other fact about it
    is taken as false.  An action that deletes an atom of the goal's predicate
    whose every argument its conditions tie to the witness (taking the vase
    out of the microwave) is taken as deleting the goal atom, and is not used."""
    domain = analysis.domain
    types = {summary.action.name: dict(summary.action.parameters) for summary in analysis.on_parameters}
    usable = [
        summary
        for summary in analysis.on_parameters
        if _compatible(domain, types[summary.action.name][summary.variable], witness_type)
        and goal_predicate not in summary.deleted_whole
    ]
    true = set(true_after)
    made_false: set[Pattern] = set()
    changed = True
    while changed:
        changed = False
        for summary in usable:
            if not summary.needs <= true or any(p in true and p not in made_false for p in summary.forbids):
                continue
            if not (summary.adds <= true and summary.deletes <= made_false):
                true |= summary.adds
                made_false |= summary.deletes
                changed = True
    return true


def _compatible(domain: Domain, one: str, other: str) -> bool:
    return domain.is_subtype(one, other) or domain.is_subtype(other, one)


def _tied_to(action: Action, variable: str) -> set[str]:
    """The parameters the positive conditions of ``action`` tie to ``variable``, through each other."""
    conditions = [{arg for arg in atom.args if is_variable(arg)} for atom, polarity in literals(action.precondition)]
    tied = {variable}
    grown = True
    while grown:
        grown = False
        for variables in conditions:
            if variables & tied and not variables <= tied:
                tied |= variables
                grown = True
    return tied


# --------------------------------------------------------------------------- a problem's needs


def witness_needs(
    domain: Domain,
    problem: Problem,
    index: FactIndex,
    objects: Mapping[str, str],
    hub_degree: int,
    goal_atoms: Iterable[GroundAtom],
) -> tuple[WitnessNeed, ...]:
    """Each distinct goal atom (not true initially) whose predicate's achievers use a witness up,
    with its candidates: the objects (of ``objects``: name -> type) the achiever's static conditions
    admit, nearest first to the goal's other objects and to where the agent is."""
    initial = problem.init
    wanted = list(dict.fromkeys(atom for atom in goal_atoms if atom not in initial))  # an atom twice is one
    roles = consuming_roles(domain, {atom[0] for atom in wanted})
    pending = [atom for atom in wanted if atom[0] in roles]
    if not pending:
        return ()
    graph = ObjectGraph(index)
    static = static_predicates(domain)
    agents = _agents(index, static)
    from_agents = graph_distances(index, graph, agents, hub_degree) if agents else {}
    needs = []
    for atom in pending:
        pool: dict[str, None] = {}
        consumed: set[Pattern] = set()
        for role in roles[atom[0]]:
            pool.update(dict.fromkeys(role_candidates(domain, index, objects, role, atom)))
            consumed.update(role.consumed)
        anchors = _anchors(index, atom, pool.keys(), static)
        near = graph_distances(index, graph, anchors, hub_degree) if anchors else {}
        far = len(objects) + 1
        ranked = sorted(pool, key=lambda name: (near.get(name, far) + from_agents.get(name, far), name))
        needs.append(WitnessNeed(atom, tuple(ranked), tuple(sorted(consumed))))
    return tuple(needs)


def exists_needs(
    domain: Domain, index: FactIndex, objects: Mapping[str, str], hub_degree: int, goal: Formula
) -> tuple[WitnessNeed, ...]:
    """Each top-level existential of the goal over one variable whose body is a conjunction of atoms,
    with the objects that satisfy the body's static atoms, nearest first to the body's objects and
    to where the agent is."""
    existentials = []
    for part in dict.fromkeys(conjuncts(goal)):  # the same existential twice is one
        if not isinstance(part, Exists) or len(part.parameters) != 1:
            continue
        body = list(conjuncts(part.body))
        if body and all(isinstance(atom, Atom) for atom in body):
            existentials.append((part, tuple(atom for atom in body if isinstance(atom, Atom))))
    if not existentials:
        return ()  # the distances below cost a walk over the scene: only for a goal that needs them
    static = static_predicates(domain)
    graph = ObjectGraph(index)
    agents = _agents(index, static)
    from_agents = graph_distances(index, graph, agents, hub_degree) if agents else {}
    needs = []
    for part, atoms in existentials:
        variable, type_name = part.parameters[0]
        names = {name for name, kind in objects.items() if domain.is_subtype(kind, type_name)}
        for atom in atoms:
            if atom.predicate in static and variable in atom.args:
                names &= _admitted_by(index, atom, variable, {})
        anchors = {arg for atom in atoms for arg in atom.args if not is_variable(arg)}
        near = graph_distances(index, graph, anchors, hub_degree) if anchors else {}
        far = len(objects) + 1
        ranked = sorted(names, key=lambda name: (near.get(name, far) + from_agents.get(name, far), name))
        label = ("exists", f"({format_parameters(part.parameters)})", format_formula(part.body))
        needs.append(WitnessNeed(label, tuple(ranked), variable=variable, body=atoms))
    return tuple(needs)


def role_candidates(
    domain: Domain, index: FactIndex, objects: Mapping[str, str], role: WitnessRole, atom: GroundAtom
) -> list[str]:
    """The objects (of ``objects``: name -> type) of the witness's type that satisfy every static
    condition naming it, the goal atom's objects put in and the other parameters left open: every
    object the role's action can use up when it adds ``atom`` is among them (more may be)."""
    binding = {arg: value for arg, value in zip(role.goal_args, atom[1:]) if is_variable(arg)}
    names = [name for name, kind in objects.items() if domain.is_subtype(kind, role.witness_type)]
    for link in role.links:
        admitted = _admitted_by(index, link, role.witness, binding)
        names = [name for name in names if name in admitted]
    return names


def _admitted_by(index: FactIndex, link: Atom, witness: str, binding: Mapping[str, str]) -> set[str]:
    values = set()
    for fact in index.by_predicate.get(link.predicate, ()):
        value = None
        for arg, actual in zip(link.args, fact[1:]):
            if arg == witness:
                if value is not None and value != actual:
                    break
                value = actual
            elif binding.get(arg, arg if not is_variable(arg) else actual) != actual:
                break  # a constant or a goal object that differs
        else:
            if value is not None:
                values.add(value)
    return values


def _anchors(index: FactIndex, atom: GroundAtom, pool: Collection[str], static: frozenset[str]) -> set[str]:
    """What a witness of ``atom`` must get near: the goal's objects' members (the microwaves of the
    class ``microwave``), found through their static initial facts, other than the candidates."""
    anchors: set[str] = set()
    for name in atom[1:]:
        for fact in index.by_object.get(name, ()):
            if fact[0] in static:
                anchors.update(arg for arg in fact[1:] if arg != name and arg not in pool)
    return anchors or set(atom[1:])


def _agents(index: FactIndex, static: frozenset[str]) -> set[str]:
    """Where the one agent is: the objects of a changing predicate's only initial fact."""
    return {
        arg
        for predicate in index.singletons
        if predicate not in static
        for atom in index.by_predicate[predicate]
        for arg in atom[1:]
    }


# --------------------------------------------------------------------------- matching


def match_witnesses(
    needs: Sequence[WitnessNeed], usable: Callable[[WitnessNeed, str], bool]
) -> tuple[dict[GroundAtom, str], tuple[WitnessNeed, ...]]:
    """Distinct usable witnesses for as many goal atoms as can have one, better-ranked candidates
    first; returns (goal atom -> witness, the needs left without one)."""
    options = [[name for name in need.candidates if usable(need, name)] for need in needs]
    owner, unmatched = _maximum_matching(options)
    return {needs[i].goal: name for name, i in owner.items()}, tuple(needs[i] for i in unmatched)


def _maximum_matching(options: Sequence[Sequence[str]]) -> tuple[dict[str, int], list[int]]:
    """A maximum matching of needs (by index) to the names they may take, earlier options first
    (augmenting paths): (name -> the need it serves, the needs left without a name)."""
    owner: dict[str, int] = {}

    def assign(i: int, seen: set[str]) -> bool:
        for name in options[i]:
            if name in seen:
                continue
            seen.add(name)
            if name not in owner or assign(owner[name], seen):
                owner[name] = i
                return True
        return False

    unmatched = [i for i in range(len(options)) if not assign(i, set())]
    return owner, unmatched


@dataclass(frozen=True)
class Shortfall:
    """Goal atoms that each need a witness of their own, and every object that can be one of them:
    fewer objects than atoms, so no choice gives each its own (Hall's condition fails)."""

    atoms: tuple[GroundAtom, ...]
    candidates: tuple[str, ...]

    def describe(self) -> str:
        """ "2 distinct goal atoms need an object of their own each ((a), (b)) and only 1 can be one (x)"."""
        atoms = ", ".join("(" + " ".join(atom) + ")" for atom in self.atoms)
        if len(self.atoms) == 1:
            head = f"1 goal atom needs an object to be met through ({atoms})"
        else:
            head = f"{len(self.atoms)} distinct goal atoms need an object of their own each ({atoms})"
        if not self.candidates:
            return f"{head} and no object can be one"
        return f"{head} and only {len(self.candidates)} can be one ({', '.join(self.candidates)})"


def find_shortfall(needs: Sequence[WitnessNeed]) -> Shortfall | None:
    """Goal atoms of ``needs`` (distinct atoms) that cannot each have a candidate of their own, with
    the candidates they share; None when every need can have its own.

    From a need a maximum matching leaves without a candidate, the needs reached by alternating
    paths (a candidate, the need it serves, that need's candidates, ...) have one candidate fewer
    than their number: each reached candidate serves one of them, and the first has none."""
    owner, unmatched = _maximum_matching([need.candidates for need in needs])
    if not unmatched:
        return None
    reached, names, queue = {unmatched[0]}, set(), [unmatched[0]]
    while queue:
        for name in needs[queue.pop()].candidates:
            if name in names:
                continue
            names.add(name)
            served = owner.get(name)
            if served is None:
                return None  # an augmenting path: the matching was not maximum (not expected)
            if served not in reached:
                reached.add(served)
                queue.append(served)
    atoms = tuple(needs[i].goal for i in sorted(reached))
    if len(set(atoms)) != len(atoms) or len(names) >= len(atoms):
        return None  # the same goal atom twice, or no shortfall after all: nothing to say
    return Shortfall(atoms, tuple(sorted(names)))


def shortfall_reason(needs: Sequence[WitnessNeed]) -> str:
    """Why the whole problem cannot give every goal atom a witness of its own ("" when it can):
    the goal atoms that are short and every candidate they share (:func:`find_shortfall`)."""
    shortfall = find_shortfall(needs)
    return shortfall.describe() if shortfall is not None else ""


__all__ = [
    "Shortfall",
    "WitnessNeed",
    "WitnessRole",
    "consuming_roles",
    "exists_needs",
    "find_shortfall",
    "match_witnesses",
    "role_candidates",
    "shortfall_reason",
    "witness_needs",
]
