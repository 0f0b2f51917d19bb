"""When the first selection in force still holds: what it read, and whether an event changed any of it.

The first selection (``Scoring.first_selection``: thresholds, closure, the
alternatives set aside, the reachability repair) is a function of the
scene.  After a full determination the session keeps a
:class:`SelectionBasis`: what that determination read.  An event that
changes none of it leaves the selection as a fresh determination would make
it, so the session keeps it (on a new task and the new scores) instead of
determining again; :func:`selection_read` says what an event changed that
the selection read, "" when nothing.  What the closure reads (facts of the
watched objects at a rule's position, the rules themselves) and whether an
element crossed the thresholds are the other triggers' business
(``triggers.py``); this module adds the rest:

* the repair's own reads (``repair.RepairReads``): the facts of every object
  it explored or ranked, and the classes whose every member it compared;
* the links its rankings follow (``distances.ObjectGraph`` with the repair's
  fan limit): a fact that adds or drops a link from an object some link
  reaches, or that moves a predicate's fan across the limit, or an object
  across the hub mark, can change a distance;
* the scores it ranks by, for objects a link reaches;
* what the relaxed exploration reads beyond the explored objects' facts
  (static one-place facts that stand for types, facts without arguments,
  a class shared by many goal objects), the set-aside alternatives' static
  links, what a quantifier ranges over;
* the goal's analysis (what it read: ``goal_regression.GoalReads``; when the event
  changed some of it, the session analyses the goal again and compares);
* the task analyses the selection used: one this module does not know
  (added to ``PlanningTask`` later) stops all reuse until it is known here.

The repair's limits (bindings per check, which grow with the scene, and
its five seconds) are not applied again to a kept result: a result found
within them is kept as found.
"""

from __future__ import annotations

import functools
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from functools import cached_property

from relevance_plan.pddl.formatter import format_atom
from relevance_plan.pddl.formulas import Atom, conjuncts, literals
from relevance_plan.pddl.model import UNSPELLED, Domain, Spelling
from relevance_plan.relevance.analysis.constraint_rules import ConstraintRule, single_valued_predicates
from relevance_plan.relevance.analysis.facts import FactIndex
from relevance_plan.relevance.analysis.goal_regression import GoalAnalysis, GoalReads, analyse_goal_reading
from relevance_plan.relevance.analysis.network import find_network
from relevance_plan.relevance.analysis.task import PlanningTask, hub_degree
from relevance_plan.relevance.analysis.types import declares_types, infer_types, static_predicates
from relevance_plan.relevance.reachability.schemas import relaxed_task
from relevance_plan.relevance.selection.closure import ConstraintClosure
from relevance_plan.relevance.selection.prune import FULL_ABOVE, REPAIR_SCORERS, Selection
from relevance_plan.relevance.selection.repair import REPAIR_MAX_FAN, RepairReads
from relevance_plan.session.state import LiveIndex, LiveScene, SceneDelta

# The task analyses this module knows what they read; another one, once used, stops reuse.
KNOWN_ANALYSES = frozenset(
    {
        "init_index",  # the live index itself
        "typing",  # declared types: fixed; inferred ones: see selection_read
        "goal_analysis",  # its reads are kept (GoalReads)
        "goal_objects",  # the goal: a goal event determines in full
        "pinned_objects",  # the goal, the constraints, the metric
        "hub_degree",  # the scene's size: kept in the basis
        "kept_for_soundness",  # see selection_read: any change, when a quantifier ranges over objects
        "goal_distance",  # read by the sharper (numeric) check only, which reads everything
        "object_profiles",  # read by widening only
        "network",  # static links: kept in the basis, compared when a static fact changes (_task_inputs)
    }
)
ANALYSES = frozenset(name for name, value in vars(PlanningTask).items() if isinstance(value, cached_property))
# The goal's witnesses (class goals): when there are none, they read only whether each goal atom
# holds (a goal event determines in full; a goal atom's fact changing is checked in _task_inputs).
# When there are some, they read the whole scene (candidates, distances): not followed.
WITNESS_ANALYSES = frozenset({"witness_needs", "exists_needs", "witness_shortfall", "proved_unsolvable"})


@dataclass(frozen=True, eq=False)
class LiveTask(PlanningTask):
    """The current state as a planning task: its facts indexed by the live index, and the goal's
    analysis the session holds, with what it read.  The index is the live one (not copied):
    read it while the scene is the one the task was made for."""

    live_index: FactIndex
    analysed: tuple[GoalAnalysis, GoalReads] | None = None  # None: analysed on first use

    @property
    def init_index(self) -> FactIndex:
        return self.live_index

    @cached_property
    def goal_analysed(self) -> tuple[GoalAnalysis, GoalReads]:
        if self.analysed is not None:
            return self.analysed
        typing = self.typing
        return analyse_goal_reading(typing.domain, typing.problem, self.live_index, self.deadline)

    @property
    def goal_analysis(self) -> GoalAnalysis:
        return self.goal_analysed[0]

    @property
    def goal_reads(self) -> GoalReads:
        return self.goal_analysed[1]


@dataclass(frozen=True)
class SelectionBasis:
    """What one full determination of the first selection read (see the module's docstring)."""

    selection: Selection
    analysed: tuple[GoalAnalysis, GoalReads]  # the goal's analysis the selection used, and what it read
    goal_shape: tuple[frozenset, frozenset]  # the single-fact and functional predicates the analysis read
    repair: RepairReads | None  # None: no repair ran
    fan_sides: Mapping[tuple[str, int], bool]  # (predicate, position) -> whether a ranking follows links from it
    agents: frozenset[str]  # where the one agent is: a ranking's sources whatever is kept
    shared: str | None  # the class the relaxed exploration shares among many goal objects
    quantified: bool  # a quantifier ranges over objects: what the closure keeps for soundness can change
    goal_atoms: frozenset[tuple]  # the goal's atoms, whose truth decides whether the goal needs witnesses
    other_analyses: frozenset[str]  # analyses used that this module does not know
    functional: frozenset  # the functional positions of the facts, from which closure's rules come
    singletons: frozenset[str]  # the predicates with one fact, from which the single-valued ones come
    single_valued: frozenset[str]  # the single-valued predicates closure keeps the objects of
    rules: Mapping[str, tuple[ConstraintRule, ...]]  # closure's rules by predicate
    network: frozenset[str] = frozenset()  # the predicates of the task's network (``analysis.network``)


def selection_basis(
    task: LiveTask, selection: Selection, repair: RepairReads | None, closure: ConstraintClosure
) -> SelectionBasis:
    """The basis of ``selection``, just made on ``task`` (whose repair read ``repair``; ``closure``:
    the task's closure)."""
    index = task.live_index
    assert isinstance(index, LiveIndex)
    fan_sides = {}
    shared = None
    if repair is not None:
        fan_sides = {
            (predicate, position): _followed(index, predicate, position)
            for predicate, atoms in index.by_predicate.items()
            for position in range(len(atoms[0]) - 1)
        }
        found = relaxed_task(task).shared
        shared = found.name if found is not None else None
    sound = task.kept_for_soundness
    used = frozenset(name for name in ANALYSES if name in task.__dict__)
    without_witnesses = frozenset(name for name in used & WITNESS_ANALYSES if not task.__dict__[name])
    return SelectionBasis(
        selection=selection,
        analysed=task.goal_analysed,
        goal_shape=goal_shape(task.goal_reads, index),
        repair=repair,
        fan_sides=fan_sides,
        agents=agents(task.domain, index),
        shared=shared,
        quantified=bool(sound.always or sound.linked),
        goal_atoms=frozenset(
            (atom.predicate, *atom.args) for atom in conjuncts(task.problem.goal) if isinstance(atom, Atom)
        ),
        other_analyses=used - KNOWN_ANALYSES - without_witnesses,
        functional=index.functional,
        singletons=index.singletons,
        single_valued=closure.singletons,
        rules=rules_by_predicate(closure.rules),
        network=task.network.predicates,
    )


def rules_by_predicate(rules: Iterable[ConstraintRule]) -> dict[str, tuple[ConstraintRule, ...]]:
    found: dict[str, list[ConstraintRule]] = {}
    for rule in rules:
        found.setdefault(rule.predicate, []).append(rule)
    return {predicate: tuple(items) for predicate, items in found.items()}


def analysis_read(basis: SelectionBasis, scene: LiveScene, delta: SceneDelta) -> bool:
    """Whether the event changed what the goal's analysis read (an answer about a pattern, or a
    predicate's single fact or functional position it may have read): then only analysing the goal
    again tells whether the analysis still holds."""
    if not delta.atoms:
        return False
    reads = basis.analysed[1]
    if reads.answers_change(scene.domain, scene.type_of, scene.index, delta.added, delta.removed):
        return True
    return goal_shape(reads, scene.index) != basis.goal_shape


def analyse_now(scene: LiveScene) -> tuple[GoalAnalysis, GoalReads]:
    """The goal's analysis of the current state, and what it read."""
    typing = infer_types(scene.domain, scene.snapshot_problem(), scene.index.by_predicate)
    return analyse_goal_reading(typing.domain, typing.problem, scene.index)


def goal_shape(reads: GoalReads, index: FactIndex) -> tuple[frozenset, frozenset]:
    """The single-fact and functional predicates among those that can decide the goal's roles."""
    predicates = reads.role_predicates
    return (
        frozenset(p for p in index.singletons if p in predicates),
        frozenset(f for f in index.functional if f[0] in predicates),
    )


def agents(domain: Domain, index: FactIndex) -> frozenset[str]:
    """The objects of a changing predicate's only fact (the robot and its place): the repair's sources."""
    static = static_predicates(domain)
    return frozenset(
        arg
        for predicate in index.singletons
        if predicate not in static
        for atom in index.by_predicate[predicate]
        for arg in atom[1:]
    )


def _followed(index: FactIndex, predicate: str, position: int) -> bool:
    """Whether a ranking follows facts of ``predicate`` from the object at ``position`` (``ObjectGraph``)."""
    assert isinstance(index, LiveIndex)
    return index.fan(predicate, position) <= REPAIR_MAX_FAN


# --------------------------------------------------------------------------- the check


@dataclass(frozen=True)
class EventChanges:
    """An event's changes as the check reads them."""

    delta: SceneDelta
    scores: frozenset[str] | None  # objects whose score changed (None: any)
    spelling: Spelling = UNSPELLED  # the user's spelling of what the reasons name

    def show(self, name: str) -> str:
        return self.spelling.object(name)

    def type_of(self, scene: LiveScene, name: str) -> str:
        return scene.objects.get(name) or self.delta.removed_types.get(name, "object")


def selection_read(basis: SelectionBasis, scene: LiveScene, changes: EventChanges) -> str:
    """What the event changed that the selection in force read (beyond what the other triggers
    watch), as a short reason; "" when it changed nothing it read."""
    if basis.other_analyses:
        return f"the selection read {', '.join(sorted(basis.other_analyses))}, which the session does not follow"
    for check in (_task_inputs, _repair_reads, _finish_share):
        reason = check(basis, scene, changes)
        if reason:
            return reason
    return ""


def _task_inputs(basis: SelectionBasis, scene: LiveScene, changes: EventChanges) -> str:
    delta = changes.delta
    if not (delta.atoms or delta.objects_added or delta.objects_removed):
        return ""
    if basis.quantified:
        return "a quantifier ranges over the objects: what soundness keeps may change"
    if not declares_types(scene.domain, basis.selection.task.problem):
        return "the objects' classes are inferred from the facts"
    if basis.goal_atoms and not basis.goal_atoms.isdisjoint(delta.atoms):
        return "a goal atom came to hold or stopped holding: the goal's witnesses may change"
    static = static_predicates(scene.domain)
    if basis.selection.scores.alternatives and any(atom[0] in static for atom in delta.atoms):
        return "a static fact changed while alternatives are set aside"
    return _network_links(basis, scene, {atom[0] for atom in delta.atoms if len(atom) == 3 and atom[0] in static})


def _network_links(basis: SelectionBasis, scene: LiveScene, links: set[str]) -> str:
    """Whether a changed static link changes the network closure and widening follow."""
    if not links:
        return ""
    if links & basis.network:
        return "a link of the network changed"
    classes = {**scene.domain.constants, **scene.objects}
    if find_network(scene.domain, classes, scene.index).predicates != basis.network:
        return "the static links now make a network"
    return ""


def _repair_reads(basis: SelectionBasis, scene: LiveScene, changes: EventChanges) -> str:
    repair, delta = basis.repair, changes.delta
    if repair is None or not (
        delta.atoms or delta.objects_added or delta.objects_removed or changes.scores is None or changes.scores
    ):
        return ""
    if repair.objects is None:
        return "the reachability repair ranked every object"
    links = _Links(basis, scene, delta)
    for check in (_relaxed_inputs, _closure_rules, _ranked_links, _read_objects):
        reason = check(basis, scene, changes, links)
        if reason:
            return reason
    return ""


def _relaxed_inputs(basis: SelectionBasis, scene: LiveScene, changes: EventChanges, links: _Links) -> str:
    """What the relaxed exploration reads beyond the explored objects' facts."""
    delta, domain = changes.delta, scene.domain
    static = static_predicates(domain)
    for atom in delta.atoms:
        if len(atom) == 1 or (len(atom) == 2 and atom[0] in static):
            return f"the relaxed exploration reads {format_atom(atom, changes.spelling)}"
    if (delta.objects_added or delta.objects_removed) and scene.timed_literals:
        return "timed literals name the objects"
    guards = _type_guards(domain)
    for name in (*delta.objects_added, *delta.objects_removed):
        type_name = changes.type_of(scene, name)
        if basis.shared is not None and domain.is_subtype(type_name, basis.shared):
            return f"{changes.show(name)} is of the class the exploration shares among the goal's objects"
        own = {atom[0] for atom in scene.index.by_object.get(name, ()) if len(atom) == 2}
        own |= {atom[0] for atom in delta.removed if len(atom) == 2 and atom[1] == name}
        for predicate, guarded in guards:
            if predicate not in own and domain.is_subtype(type_name, guarded):
                spelling = changes.spelling
                every = f"every {spelling.type(guarded)} holds ({spelling.predicate(predicate)} ...)"
                return f"{changes.show(name)} changes whether {every}"
    return ""


def _closure_rules(basis: SelectionBasis, scene: LiveScene, changes: EventChanges, links: _Links) -> str:
    """Closure's rules, which the repair applies to every set it explores: the same for the objects it read."""
    index, repair = scene.index, basis.repair
    assert repair is not None and repair.objects is not None
    if not changes.delta.atoms:
        return ""
    if index.singletons != basis.singletons or index.functional != basis.functional:
        if single_valued_predicates(scene.domain, index) != basis.single_valued:
            return "a single-valued predicate came or went"
        for predicate, key, _ in index.functional ^ basis.functional:
            for name in repair.objects:
                if any(atom[1 + key] == name for atom in index.facts_of(name, predicate)):
                    return f"closure's rules for {changes.spelling.predicate(predicate)} changed"
    return ""


def _ranked_links(basis: SelectionBasis, scene: LiveScene, changes: EventChanges, links: _Links) -> str:
    """The links the repair's rankings follow: unchanged wherever a ranking may walk."""
    delta, index = changes.delta, scene.index
    assert basis.repair is not None
    if not basis.repair.ranked:
        return ""  # the first check reached the goal: nothing was ranked
    if links.hub_before != links.hub_after and index.any_degree_between(
        min(links.hub_before, links.hub_after), max(links.hub_before, links.hub_after)
    ):
        return "the scene's size moved the hub mark past some objects"
    if agents(scene.domain, index) != basis.agents:
        return "the agent's only fact changed"
    for atom in delta.atoms:
        for position in range(len(atom) - 1):
            if basis.fan_sides.get((atom[0], position), True) != _followed(index, atom[0], position):
                return f"the links of {changes.spelling.predicate(atom[0])} changed shape"
    for atom in delta.atoms:
        for name in dict.fromkeys(atom[1:]):
            if not links.walked(name):
                continue
            if len(atom) > 2 and _followed(index, atom[0], atom.index(name) - 1):
                return f"a link the repair follows changed: {format_atom(atom, changes.spelling)}"
            if links.hub_crossed(name):
                return f"{changes.show(name)} crossed the hub mark"
    for name in delta.objects_added:
        if links.walked(name):
            return f"a link leads to {changes.show(name)}"
    return ""


def _read_objects(basis: SelectionBasis, scene: LiveScene, changes: EventChanges, links: _Links) -> str:
    """The objects whose facts or rank the repair read, and the classes whose members it compared."""
    repair, delta = basis.repair, changes.delta
    assert repair is not None and repair.objects is not None
    touched = {name for atom in delta.atoms for name in atom[1:]}
    touched.update(delta.objects_added, delta.objects_removed)
    for name in sorted(touched & repair.objects):
        if name in delta.objects_removed or not _unseen_links(basis, scene, delta, name):
            return f"the reachability repair read {changes.show(name)}"
    for name in (*delta.objects_added, *delta.objects_removed):
        if changes.type_of(scene, name) in repair.classes:
            return f"the reachability repair compared every {changes.spelling.type(changes.type_of(scene, name))}"
    if changes.scores is None:
        return "every score may have changed"
    for name in sorted(changes.scores):
        if name in repair.objects or changes.type_of(scene, name) in repair.classes or links.walked(name):
            return f"the reachability repair ranks by the score of {changes.show(name)}"
    return ""


def _unseen_links(basis: SelectionBasis, scene: LiveScene, delta: SceneDelta, name: str) -> bool:
    """Whether the event changed only links of ``name`` (an object the repair read) to objects it
    never read, which none of its choices can see: no exploration holds those objects (their facts
    are left out), closure does not follow the links from ``name``, and ``name`` keeps, before and
    after, a link to such an object (so no kept object of its class can stand in for it, whatever
    came or went, and it keeps the links that make it more than a thing to carry)."""
    repair = basis.repair
    assert repair is not None and repair.objects is not None
    read, constants, static = repair.objects, scene.domain.constants, static_predicates(scene.domain)
    rules = basis.rules

    def unseen(atom: tuple) -> bool:
        return len(atom) > 2 and all(
            other == name or (other not in read and other not in constants) for other in atom[1:]
        )

    changed = [atom for atom in delta.atoms if name in atom[1:]]
    for atom in changed:
        if atom[0] in static or not unseen(atom):
            return False
        if any(atom[1 + rule.when_kept] == name for rule in rules.get(atom[0], ())):
            return False
    after = scene.index.by_object.get(name, ())
    added = set(delta.added)
    before = [atom for atom in after if atom not in added] + [atom for atom in delta.removed if name in atom[1:]]
    return any(map(unseen, after)) and any(map(unseen, before))


def _finish_share(basis: SelectionBasis, scene: LiveScene, changes: EventChanges) -> str:
    """Whether the selection still keeps no more than its share of the scene (else: the full problem)."""
    delta = changes.delta
    if not (delta.objects_added or delta.objects_removed):
        return ""
    selection = basis.selection
    if selection.unpruned_reason:
        return "the selection keeps every object"
    full_above = FULL_ABOVE if selection.scores.scorer in REPAIR_SCORERS else 1.0
    if len(selection.kept) > full_above * len(scene.objects):
        return "the selection would keep most of the scene"
    return ""


@functools.lru_cache(maxsize=16)
def _type_guards(domain: Domain) -> frozenset[tuple[str, str]]:
    """(static one-place predicate, type) of the actions' conditions ``(p ?x)`` on a typed parameter:
    whether every object of the type holds ``p`` decides whether the exploration checks it."""
    static = static_predicates(domain)
    found = set()
    for action in domain.relaxed_actions:
        types = dict(action.parameters)
        for atom, positive in literals(action.precondition):
            if positive and atom.predicate in static and len(atom.args) == 1 and atom.args[0] in types:
                found.add((atom.predicate, types[atom.args[0]]))
    return frozenset(found)


class _Links:
    """Which objects the repair's rankings may walk from, before and after an event."""

    def __init__(self, basis: SelectionBasis, scene: LiveScene, delta: SceneDelta):
        assert basis.repair is not None and basis.repair.objects is not None
        self.index = scene.index
        self.delta = delta
        # the hub mark before and after the event (it follows the scene's size)
        self.hub_after = hub_degree(len(scene.objects))
        self.hub_before = hub_degree(len(scene.objects) - len(delta.objects_added) + len(delta.objects_removed))
        self.sources = basis.agents | basis.repair.objects

    def walked(self, name: str) -> bool:
        """Whether a ranking may walk from ``name``: one of its sources, or some link leads to it,
        before or after the event (no ranking reaches an object no link leads to)."""
        if name in self.sources:
            return True
        after = self.index.by_object.get(name, ())
        added = set(self.delta.added)
        before = [atom for atom in after if atom not in added]
        before += [atom for atom in self.delta.removed if name in atom[1:]]
        return self._linked_to(name, after) or self._linked_to(name, before)

    def _linked_to(self, name: str, atoms: Iterable[tuple]) -> bool:
        index = self.index
        return any(
            other != name and _followed(index, atom[0], atom.index(other) - 1)
            for atom in atoms
            if len(atom) > 2
            for other in atom[1:]
        )

    def hub_crossed(self, name: str) -> bool:
        after = self.index.degree(name)
        before = after - sum(name in atom[1:] for atom in self.delta.added)
        before += sum(name in atom[1:] for atom in self.delta.removed)
        return (before > self.hub_before) != (after > self.hub_after)
