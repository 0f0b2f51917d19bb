"""Lifted analysis of a domain against a problem's initial state.

Nothing here grounds an action.  Two results feed the rest of the pipeline:

* ``infer_constraint_rules``: which initial facts tie one object to another
  so tightly that keeping one requires keeping the other (a fact an action
  must undo before the kept object can be used, a fact the kept object
  determines, the robot's only position), read off the schemas, not names;
* ``analyse_goal``: which types of objects can play a part in reaching the goal,
  found by regressing the goal through the action schemas (the backward
  fixpoint of pyperplan's relevance analysis, done on typed patterns instead
  of ground atoms).
"""

from __future__ import annotations

import heapq
import itertools
from collections import defaultdict
from collections.abc import Callable, Collection, Iterable, Iterator, Mapping
from dataclasses import dataclass
from typing import Protocol

from relevance_plan.pddl.formulas import Atom, Formula, GroundAtom, effect_literals, literals, scoped_literals
from relevance_plan.pddl.model import Action, Domain, Problem, numeric_facts
from relevance_plan.pddl.sexpr import check_deadline
from relevance_plan.relevance.invariants import count_keeping_for

# A lifted goal pattern: (predicate, args), each arg ("obj", name) or ("type", type name).
Term = tuple[str, str]
Pattern = tuple[str, tuple[Term, ...]]

# --------------------------------------------------------------------------- init-state facts


class FactIndex(Protocol):
    """What rule inference, closure and distances read of the true facts.

    :class:`InitIndex` is the initial state's; the live session keeps one that
    follows the scene as it changes.
    """

    @property
    def by_predicate(self) -> Mapping[str, Collection[GroundAtom]]: ...

    @property
    def by_object(self) -> Mapping[str, Collection[GroundAtom]]: ...

    @property
    def functional(self) -> frozenset[tuple[str, int, int]]: ...

    @property
    def singletons(self) -> frozenset[str]: ...


@dataclass(frozen=True)
class InitIndex:
    """The initial state indexed by predicate, for rule inference and closure."""

    by_predicate: Mapping[str, tuple[GroundAtom, ...]]
    by_object: Mapping[str, tuple[GroundAtom, ...]]
    functional: frozenset[tuple[str, int, int]]  # (predicate, key_position, other_position): key determines other

    @property
    def singletons(self) -> frozenset[str]:
        return frozenset(p for p, atoms in self.by_predicate.items() if len(atoms) == 1)


def index_init(
    problem: Problem, deadline: float | None = None, count_keeping: Collection[tuple[str, int]] = ()
) -> InitIndex:
    """Facts by predicate and by object; a numeric value's term ``(distance a b)`` counts as a fact,
    so the objects inside a function term are linked like those of a static fact.

    A position is functional when no object there has two facts; at one of ``count_keeping``
    (where no action gives an object one more fact: ``invariants.count_keeping_for``), also while
    fewer than half its objects have two, which no action gave them (an item seen in its new
    receptacle before it leaves the old one does not make every receptacle a role)."""
    by_predicate: dict[str, list[GroundAtom]] = defaultdict(list)
    by_object: dict[str, list[GroundAtom]] = defaultdict(list)
    # the exploration takes static facts in this order
    for count, atom in enumerate((*problem.facts_in_order(), *numeric_facts(problem))):
        if not count & 0xFFFF:
            check_deadline(deadline, "indexing the initial facts", problem.path)
        by_predicate[atom[0]].append(atom)
        if len(atom) == 3:  # most facts link two objects: no set for them
            by_object[atom[1]].append(atom)
            if atom[2] != atom[1]:
                by_object[atom[2]].append(atom)
        else:
            for arg in set(atom[1:]):
                by_object[arg].append(atom)
    functional: set[tuple[str, int, int]] = set()
    for predicate, atoms in by_predicate.items():
        arity = len(atoms[0]) - 1
        for key in range(arity):
            if _determines(atoms, key) or ((predicate, key) in count_keeping and _mostly_determines(atoms, key)):
                functional.update((predicate, key, other) for other in range(arity) if other != key)
    return InitIndex(
        by_predicate={p: tuple(a) for p, a in by_predicate.items()},
        by_object={o: tuple(a) for o, a in by_object.items()},
        functional=frozenset(functional),
    )


def _mostly_determines(atoms: Iterable[GroundAtom], key: int) -> bool:
    """Whether fewer than half the objects at position ``key`` have two of ``atoms``."""
    seen: dict[str, tuple[str, ...]] = {}
    clashing: set[str] = set()
    for atom in atoms:
        rest = atom[1 : 1 + key] + atom[2 + key :]
        if seen.setdefault(atom[1 + key], rest) != rest:
            clashing.add(atom[1 + key])
    return 2 * len(clashing) < len(seen)


def _determines(atoms: Iterable[GroundAtom], key: int) -> bool:
    """Whether no object at position ``key`` has two of ``atoms`` (whose other arguments differ)."""
    seen: dict[str, tuple[str, ...]] = {}
    for atom in atoms:
        rest = atom[1 : 1 + key] + atom[2 + key :]
        if seen.setdefault(atom[1 + key], rest) != rest:
            return False
    return True


def fan_in(index: FactIndex) -> dict[tuple[str, int], float]:
    """(predicate, position) -> facts per distinct object at that position: high for class-like
    values (the shape of forty keys), about one for a place or an owner."""
    result = {}
    for predicate, atoms in index.by_predicate.items():
        arity = len(next(iter(atoms), ("",))) - 1
        for position in range(arity):
            values = {atom[1 + position] for atom in atoms}
            result[(predicate, position)] = len(atoms) / max(1, len(values))
    return result


def object_profiles(index: FactIndex, values: Mapping[GroundAtom, float]) -> dict[str, tuple[object, ...]]:
    """Each object's initial facts with its own name blanked out (numeric terms with their values):
    objects with the same profile are interchangeable in the initial state, so a second one rarely
    does what the first could not."""
    profiles: dict[str, tuple[object, ...]] = {}
    for name, atoms in index.by_object.items():
        blanked = ((tuple("" if arg == name else arg for arg in atom), values.get(atom)) for atom in atoms)
        profiles[name] = tuple(sorted(blanked, key=repr))
    return profiles


def object_distances(
    index: FactIndex,
    sources: Iterable[str],
    hub_degree: int | None = None,
    max_fan: float | None = None,
    fans: Mapping[tuple[str, int], float] | None = None,
) -> dict[str, int]:
    """Breadth-first hops from ``sources`` through initial facts (two objects in one fact are one hop apart).

    Objects in more than ``hub_degree`` facts get a distance but are not passed
    through; with ``max_fan``, a fact is not followed from an object at a
    position shared by more than ``max_fan`` facts on average (from a shape to
    every key of that shape), only toward it (``fans``: :func:`fan_in` of the index, when the
    caller has it).
    """
    return graph_distances(index, ObjectGraph(index, max_fan, fans), sources, hub_degree)


# A walk kept by a graph: (its sources, the hub mark) for graph_distances, with "bounds" for walk_bounds.
WalkKey = tuple[frozenset[str], int | None] | tuple[frozenset[str], int | None, str]
Walks = dict[WalkKey, dict[str, int]]


class ObjectGraph:
    """The links :func:`object_distances` walks, each object's found once, when first walked from:
    the repair ranks candidates by distance every round."""

    def __init__(
        self, index: FactIndex, max_fan: float | None = None, fans: Mapping[tuple[str, int], float] | None = None
    ):
        self.index = index
        self.max_fan = max_fan
        self.fans = fan_in(index) if fans is None and max_fan is not None else fans or {}
        self.found: dict[str, list[str]] = {}
        # walks already made, kept by a graph that outlives one task (a live session's: the index
        # drops each walk an event's facts can change); None: not kept
        self.walks: Walks | None = None

    def neighbours(self, name: str) -> list[str]:
        """The other objects of the facts a walk follows from ``name``, each once."""
        found = self.found.get(name)
        if found is None:
            linked: dict[str, None] = {}
            for atom in self.index.by_object.get(name, ()):
                if self.follows(atom, name):
                    linked.update(dict.fromkeys(atom[1:]))
            linked.pop(name, None)
            found = self.found[name] = list(linked)
        return found

    def follows(self, atom: tuple[str, ...], name: str) -> bool:
        """Whether a walk goes from ``name`` on through ``atom``, a fact of it: one that links it to
        another object, from a position not shared by more than ``max_fan`` facts on average."""
        if len(atom) < 3:
            return False
        return self.max_fan is None or self.fans.get((atom[0], atom.index(name) - 1), 0.0) <= self.max_fan


def graph_distances(
    index: FactIndex, graph: ObjectGraph, sources: Iterable[str], hub_degree: int | None = None
) -> dict[str, int]:
    """Breadth-first hops from ``sources`` over ``graph``; an object in more than ``hub_degree``
    facts gets a distance but is not passed through."""
    distance = {name: 0 for name in sources}
    walks = graph.walks
    if walks is None:
        _walk(index, graph, distance, list(distance), 0, hub_degree)
        return distance
    key = (frozenset(distance), hub_degree)
    walked = walks.pop(key, None)
    if walked is None:
        _walk(index, graph, distance, list(distance), 0, hub_degree)
        walked = distance
    _keep(walks, key, walked)
    return dict(walked)


def _keep(walks: Walks, key: WalkKey, walked: dict[str, int]) -> None:
    """``walked`` kept as the most recently used, the least recently used dropped past the limit."""
    walks[key] = walked
    while len(walks) > MAX_KEPT_WALKS:
        del walks[next(iter(walks))]


def walk_bounds(
    index: FactIndex, graph: ObjectGraph, sources: Iterable[str], distance: Mapping[str, int], hub_degree: int | None
) -> dict[str, int]:
    """For each object the walk ``distance`` (``graph_distances`` from ``sources``) reached, the
    fewest hops from it, along the links a walk follows, to an object plus that object's own
    distance: a lower bound on what going on from it can still add up to, which, unlike
    ``distance`` itself, grows by at most one per link followed (a room is one hop from all its
    places, which need not be one hop from each other), as :class:`NearestBetween` needs."""
    walks = graph.walks
    key = (frozenset(sources), hub_degree, "bounds")
    kept = walks.pop(key, None) if walks is not None else None
    if walks is not None and kept is not None:
        _keep(walks, key, kept)
        return kept
    by_object = index.by_object
    before: dict[str, list[str]] = {}  # object -> the reached objects with a followed link to it
    for name in distance:
        if hub_degree is not None and len(by_object.get(name, ())) > hub_degree:
            continue  # an object passed through only as a source
        for other in graph.neighbours(name):
            before.setdefault(other, []).append(name)
    bound = dict(distance)
    levels: list[list[str]] = []
    for name, hops in distance.items():
        while len(levels) <= hops:
            levels.append([])
        levels[hops].append(name)
    hops = 0
    while hops < len(levels):
        for name in levels[hops]:
            if bound[name] != hops:
                continue
            for other in before.get(name, ()):
                if bound.get(other, hops + 2) > hops + 1:
                    bound[other] = hops + 1
                    if len(levels) == hops + 1:
                        levels.append([])
                    levels[hops + 1].append(other)
        hops += 1
    if walks is not None:
        _keep(walks, key, bound)  # dropped with the walk it bounds: it has the same objects
    return bound


class NearestBetween:
    """The objects in order of hops from ``sources`` plus hops ``toward`` (a walk from other
    objects, with its :func:`walk_bounds` or those of a walk from more objects), fewest first,
    then fewest hops toward: what sorting every object the two walks reach by that sum gives,
    found by walking from ``sources`` only as far as the sums asked for need (a best-first search
    the bounds guide).  ``far``: the hops of an object a walk does not reach; the search stops
    (``exhausted``) before the first sum of ``far`` or more, where objects one of the walks misses come in."""

    def __init__(
        self,
        index: FactIndex,
        graph: ObjectGraph,
        sources: Iterable[str],
        toward: Mapping[str, int],
        bounds: Mapping[str, int],
        hub_degree: int | None,
        far: int,
    ):
        self.exhausted = False
        self._index, self._graph, self._hub, self._far = index, graph, hub_degree, far
        self._toward, self._bounds = toward, bounds
        self._hops: dict[str, int] = {}
        self._open: list[tuple[int, str]] = []
        self._done: list[tuple[int, int, str]] = []  # (sum, hops toward, name) of objects whose hops are known
        for name in sources:
            self._hops[name] = 0
        self._finished = set(self._hops)
        for name in sorted(self._finished):  # sources pass their links on whatever their count of facts
            self._finish(name, 0, True)

    def _finish(self, name: str, hops: int, source: bool = False) -> None:
        toward = self._toward.get(name)
        if toward is not None:
            heapq.heappush(self._done, (hops + toward, toward, name))
        if not source and self._hub is not None and len(self._index.by_object.get(name, ())) > self._hub:
            return
        bounds, known = self._bounds, self._hops
        for other in self._graph.neighbours(name):
            if known.get(other, hops + 2) > hops + 1:
                known[other] = hops + 1
                heapq.heappush(self._open, (hops + 1 + bounds.get(other, 0), other))

    def groups(self) -> Iterator[list[tuple[int, str]]]:
        """The objects, a sum at a time: (hops toward, name) of every object with that sum."""
        opened, done, known, finished = self._open, self._done, self._hops, self._finished
        while True:
            least = opened[0][0] if opened else None
            if done and done[0][0] < self._far and (least is None or done[0][0] < least):
                total = done[0][0]
                group = []
                while done and done[0][0] == total:
                    _, toward, name = heapq.heappop(done)
                    group.append((toward, name))
                yield group
                continue
            if least is None or least >= self._far:
                self.exhausted = True
                return
            _, name = heapq.heappop(opened)
            if name in finished:
                continue
            finished.add(name)
            self._finish(name, known[name])


# Walks a kept graph holds at the most (each as large as the part of the scene it reaches).
MAX_KEPT_WALKS = 32


def shared_graph(index: FactIndex, max_fan: float | None) -> ObjectGraph:
    """The graph of ``index``'s links for ``max_fan``: the index's own when it keeps one across
    changes (a live session's), else a new one."""
    kept = getattr(index, "object_graph", None)
    return kept(max_fan) if kept is not None else ObjectGraph(index, max_fan, fan_in(index))


def walk_changed(
    walked: Mapping[str, int],
    atom: tuple[str, ...],
    names: Iterable[str],
    degrees: Mapping[str, tuple[int, int]],
    followed: Callable[[str, int], bool],
    hub_degree: int | None,
) -> bool:
    """Whether a fact (or numeric term) ``atom`` of ``names`` coming or going can change the walk
    ``walked``: only through an object the walk reached, by a link followed from it, or by its
    count of facts crossing ``hub_degree`` (``degrees``: name -> (before, after))."""
    for name in names:
        if name not in walked:
            continue
        if len(atom) >= 3 and followed(atom[0], atom.index(name) - 1):
            return True
        before, after = degrees[name]
        if hub_degree is not None and (before > hub_degree) != (after > hub_degree):
            return True
    return False


def _walk(
    index: FactIndex, graph: ObjectGraph, distance: dict[str, int], frontier: list[str], hops: int, hub: int | None
) -> None:
    """Breadth-first from ``frontier`` (at ``hops``), giving each object its hops where they are fewer."""
    for _ in _levels(index, graph, distance, frontier, hops, hub):
        pass


def _levels(
    index: FactIndex, graph: ObjectGraph, distance: dict[str, int], frontier: list[str], hops: int, hub: int | None
) -> Iterator[list[str]]:
    """:func:`_walk`, a hop at a time: the objects each hop gave fewer hops."""
    by_object, found, neighbours = index.by_object, graph.found, graph.neighbours
    while frontier:
        hops += 1
        following = []
        for name in frontier:
            if hub is not None and hops > 1 and len(by_object.get(name, ())) > hub:
                continue
            near = found.get(name)
            for other in neighbours(name) if near is None else near:
                if distance.get(other, hops + 1) > hops:
                    distance[other] = hops
                    following.append(other)
        if following:
            yield following
        frontier = following


def walk_levels(index: FactIndex, graph: ObjectGraph, sources: Iterable[str], hub: int | None) -> Iterator[list[str]]:
    """The objects :func:`graph_distances` puts 1, 2, ... hops from ``sources``, a hop at a time:
    for a caller that stops at the first hop where it finds what it looks for."""
    distance = dict.fromkeys(sources, 0)
    return _levels(index, graph, distance, list(distance), 0, hub)


class GrowingDistances:
    """:func:`graph_distances` from a set of sources that only grows (the objects a growing
    exploration reached): each call walks from the new sources only, where they bring objects nearer."""

    def __init__(self, index: FactIndex, graph: ObjectGraph, hub_degree: int | None = None):
        self.index = index
        self.graph = graph
        self.hub = hub_degree
        self.sources: frozenset[str] = frozenset()
        self.distance: dict[str, int] = {}

    def __call__(self, sources: Iterable[str]) -> dict[str, int]:
        sources = frozenset(sources)
        if not sources >= self.sources:
            self.sources, self.distance = frozenset(), {}
        new = [name for name in sources - self.sources if self.distance.get(name) != 0]
        self.sources = sources
        for name in new:
            self.distance[name] = 0
        _walk(self.index, self.graph, self.distance, sorted(new), 0, self.hub)
        return self.distance


# --------------------------------------------------------------------------- constraint rules


@dataclass(frozen=True)
class ConstraintRule:
    """Keeping the object at ``when_kept`` of a ``predicate`` fact keeps the one at ``restore``."""

    predicate: str
    when_kept: int  # 0-based argument position
    restore: int
    kind: str  # "blocker", "anchor", "singleton", "model"
    relation: str = ""  # what the knowledge model says a fact of it is ("on top of"); "" when it says nothing


def _precondition_predicates(domain: Domain) -> set[str]:
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
    used = _precondition_predicates(domain)
    rules: list[ConstraintRule] = []
    for predicate, blocker, blocked in sorted(blocking_predicates(domain)):
        rules.append(ConstraintRule(predicate, blocked, blocker, "blocker"))
    for predicate, key, other in sorted(index.functional):
        if predicate in used:
            rules.append(ConstraintRule(predicate, key, other, "anchor"))
    return tuple(rules)


# --------------------------------------------------------------------------- goal regression


@dataclass(frozen=True)
class GoalAnalysis:
    relevant_predicates: frozenset[str]
    role_depth: Mapping[str, int]  # type -> fewest role introductions from the goal
    goal_variable_types: frozenset[str]  # types quantified in the goal


def analyse_goal(
    domain: Domain, problem: Problem, index: FactIndex | None = None, deadline: float | None = None
) -> GoalAnalysis:
    """Regress the goal through the schemas on typed patterns (no grounding).

    A pattern is (predicate, args) where each arg is a goal object or a type.
    An achiever's parameter that is not unified with the pattern is a new
    variable.  It is a *role* (any object of its type may serve: a cup, a
    gripper) unless the initial state determines it from an argument already
    known, e.g. the place an item is at or the thing stacked on it.
    Patterns that some initial fact already satisfies are not regressed
    further (a clear cup, a free gripper): the objects in the way of a
    particular one are closure's business, not the goal's.
    """
    index = index or index_init(problem, None, count_keeping_for(domain, problem.timed_literals))
    return _Regression(domain, problem, index, deadline).run()


_FAR = 1 << 30
_SCAN_FIRST = 1000  # initial facts scanned one by one before their classes are collected


class _Regression:
    """The backward fixpoint of :func:`analyse_goal`: patterns with the fewest role steps from the goal."""

    def __init__(self, domain: Domain, problem: Problem, index: FactIndex, deadline: float | None = None):
        self.domain = domain
        self.deadline = deadline
        self.index = index
        self.objects = dict(domain.constants)
        self.objects.update(problem.objects)
        self.problem = problem
        self.achievers: dict[str, list[tuple[Action, Atom, Formula]]] = defaultdict(list)
        for action in domain.relaxed_actions:
            for item in effect_literals(action.effect):
                if item.is_add:
                    self.achievers[item.atom.predicate].append((action, item.atom, item.condition))
        self.best: dict[Pattern, int] = {}
        self.rows: dict[str, frozenset[tuple[str, ...]]] = {}
        self.role_depth: dict[str, int] = {}
        # (predicate, args with each object that is not a constant as its type) -> what regress found
        self.shapes: dict[tuple[str, tuple[Term, ...]], tuple[list[tuple[str, tuple[Term, ...], int]], list[str]]] = {}

    def run(self) -> GoalAnalysis:
        goal_types: set[str] = set()
        frontier: list[tuple[Pattern, int]] = []
        for atom, _, scope in scoped_literals(self.problem.goal):
            variables = dict(scope)
            goal_types.update(variables.values())
            args = tuple(("type", variables[a]) if a in variables else ("obj", a) for a in atom.args)
            frontier.append(((atom.predicate, args), 0))
        self.role_depth = {t: 0 for t in goal_types}
        while frontier:
            check_deadline(self.deadline, "regressing the goal", self.problem.path)
            pattern, depth = frontier.pop()
            if self.best.get(pattern, _FAR) <= depth:
                continue
            self.best[pattern] = depth
            if not self.initially_satisfiable(pattern):
                frontier.extend(self.regress(pattern, depth))
        return GoalAnalysis(
            relevant_predicates=frozenset(p for p, _ in self.best),
            role_depth=self.role_depth,
            goal_variable_types=frozenset(goal_types),
        )

    def initially_satisfiable(self, pattern: Pattern) -> bool:
        # Some initial fact matches: some object of the right type already has
        # the property (a cup that is clear, a free gripper), so the pattern
        # need not be regressed; closure handles the objects in the way.
        predicate, args = pattern
        atoms = self.index.by_predicate.get(predicate, ())
        # A named object's own facts are usually far fewer than the predicate's (one floor's
        # against every (above f g) of a tall building): scan the shorter list.
        for kind, name in args:
            if kind == "obj" and len(self.index.by_object.get(name, ())) < len(atoms):
                atoms = self.index.by_object.get(name, ())
        if len(atoms) > _SCAN_FIRST and all(kind == "type" for kind, _ in args):
            # Classes only: the first facts usually answer; past them, the predicate's distinct rows
            # of classes do, once (150,000 plates stated before the one cup that is clear).
            return self._fits_any(itertools.islice(atoms, _SCAN_FIRST), predicate, args) or any(
                all(self.domain.is_subtype(row[i], a[1]) for i, a in enumerate(args))
                for row in self._class_rows(predicate)
            )
        return self._fits_any(atoms, predicate, args)

    def _fits_any(self, atoms: Iterable[GroundAtom], predicate: str, args: tuple[Term, ...]) -> bool:
        return any(
            atom[0] == predicate
            and all(
                atom[1 + i] == a[1]
                if a[0] == "obj"
                else self.domain.is_subtype(self.objects.get(atom[1 + i], "object"), a[1])
                for i, a in enumerate(args)
            )
            for atom in atoms
        )

    def _class_rows(self, predicate: str) -> frozenset[tuple[str, ...]]:
        """The classes of the objects of ``predicate``'s initial facts, one row per distinct tuple."""
        rows = self.rows.get(predicate)
        if rows is None:
            check_deadline(self.deadline, "regressing the goal", self.problem.path)
            kind = self.objects.get
            rows = self.rows[predicate] = frozenset(
                tuple([kind(arg, "object") for arg in atom[1:]]) for atom in self.index.by_predicate.get(predicate, ())
            )
        return rows

    def regress(self, pattern: Pattern, depth: int) -> list[tuple[Pattern, int]]:
        """The patterns the achievers of ``pattern`` need, with their depths; records new roles.

        Patterns that differ only in objects of the same types (two thousand packages' destinations)
        regress alike: the first one's answer is kept with each object as its position in the
        pattern, and the others' are filled in from it."""
        predicate, args = pattern
        constants = self.domain.constants
        shape = (
            predicate,
            tuple(
                ("of", self.objects.get(value, "")) if kind == "obj" and value not in constants else (kind, value)
                for kind, value in args
            ),
        )
        cached = self.shapes.get(shape)
        if cached is None:
            found, roles = self._regress(pattern)
            position = {value: i for i, (kind, value) in reversed(list(enumerate(args))) if kind == "obj"}
            cached = self.shapes[shape] = (
                [
                    (
                        name,
                        tuple(("at", str(position[v])) if k == "obj" and v in position else (k, v) for k, v in new),
                        step,
                    )
                    for (name, new), step in found
                ],
                roles,
            )
        templates, roles = cached
        for type_name in roles:
            if self.role_depth.get(type_name, _FAR) > depth + 1:
                self.role_depth[type_name] = depth + 1
        return [
            ((name, tuple(args[int(v)] if k == "at" else (k, v) for k, v in template)), depth + step)
            for name, template, step in templates
        ]

    def _regress(self, pattern: Pattern) -> tuple[list[tuple[Pattern, int]], list[str]]:
        """What :meth:`regress` finds for ``pattern``: the patterns with their depth from it, and the
        types of the roles its achievers introduce."""
        options = []
        for action, added, condition in self.achievers.get(pattern[0], ()):
            bound = _unify(self.domain, self.objects, action, added, pattern[1])
            if bound is not None:
                pre_atoms = [
                    (atom.predicate, atom.args)
                    for part in (action.precondition, condition)
                    for atom, positive in literals(part)
                    if positive
                ]
                options.append((action, bound, pre_atoms, _roles(action, bound, pre_atoms, self.index)))
        if not options:
            return [], []
        # Only the achievers that need the fewest new roles count: picking up a
        # cup needs nothing new, unstacking it from "some item" would make every
        # item look useful.
        fewest = min(len(option[3]) for option in options)
        found = []
        roles: list[str] = []
        for action, bound, pre_atoms, roles_here in options:
            if len(roles_here) != fewest:
                continue
            params = dict(action.parameters)
            roles.extend(params[var] for var in sorted(roles_here))
            for predicate_name, args in pre_atoms:
                # A condition on a newly introduced role is one step further away.
                next_depth = 1 if roles_here.intersection(args) else 0
                new_args = tuple(
                    bound[arg]
                    if arg in bound
                    else ("type", params.get(arg, "object"))
                    if arg.startswith("?")
                    else ("obj", arg)
                    for arg in args
                )
                found.append(((predicate_name, new_args), next_depth))
        return found, roles


@dataclass(frozen=True)
class GoalReads:
    """What :func:`analyse_goal` read of the facts: the patterns it asked whether some fact satisfies
    (by predicate) with the answers, and the predicates whose single fact or functional positions
    can decide a role (those of the conditions of the achievers it regressed through).  While no
    answer changes and those predicates keep their single facts and functional positions, the
    analysis of the same goal comes out the same."""

    patterns: Mapping[str, tuple[tuple[Pattern, bool], ...]]  # predicate -> (pattern, answer)
    role_predicates: frozenset[str]

    def answers_change(
        self,
        domain: Domain,
        type_of: Callable[[str], str],
        index: FactIndex,
        added: Iterable[GroundAtom],
        removed: Iterable[GroundAtom],
    ) -> bool:
        """Whether facts that came (``added``) or went (``removed``, from ``index`` already) change
        an answer: a pattern now satisfied that was not, or one no fact satisfies any more
        (``type_of``: an object's type)."""
        for fact in added:
            if any(
                not answer and _fits(domain, type_of, pattern, fact)
                for pattern, answer in self.patterns.get(fact[0], ())
            ):
                return True
        for fact in removed:
            for pattern, answer in self.patterns.get(fact[0], ()):
                if answer and _fits(domain, type_of, pattern, fact) and not _satisfied(domain, type_of, index, pattern):
                    return True
        return False


def _fits(domain: Domain, type_of: Callable[[str], str], pattern: Pattern, fact: GroundAtom) -> bool:
    args = pattern[1]
    return len(args) == len(fact) - 1 and all(
        value == name if kind == "obj" else domain.is_subtype(type_of(value), name)
        for (kind, name), value in zip(args, fact[1:])
    )


def _satisfied(domain: Domain, type_of: Callable[[str], str], index: FactIndex, pattern: Pattern) -> bool:
    """Whether some fact satisfies ``pattern`` (the facts of an object it names, when it names one)."""
    named = [name for kind, name in pattern[1] if kind == "obj"]
    facts = index.by_object.get(named[0], ()) if named else index.by_predicate.get(pattern[0], ())
    return any(fact[0] == pattern[0] and _fits(domain, type_of, pattern, fact) for fact in facts)


class _ReadingRegression(_Regression):
    """The regression of :func:`analyse_goal`, noting each pattern it asks about."""

    def __init__(self, domain: Domain, problem: Problem, index: FactIndex, deadline: float | None = None):
        super().__init__(domain, problem, index, deadline)
        self.asked: dict[Pattern, bool] = {}

    def initially_satisfiable(self, pattern: Pattern) -> bool:
        answer = self.asked[pattern] = super().initially_satisfiable(pattern)
        return answer

    def reads(self) -> GoalReads:
        patterns: dict[str, list[tuple[Pattern, bool]]] = defaultdict(list)
        for pattern, answer in self.asked.items():
            patterns[pattern[0]].append((pattern, answer))
        regressed = {pattern[0] for pattern, satisfied in self.asked.items() if not satisfied}
        role_predicates = {
            atom.predicate
            for predicate in regressed
            for action, _, condition in self.achievers.get(predicate, ())
            for part in (action.precondition, condition)
            for atom, _ in literals(part)
        }
        return GoalReads({p: tuple(found) for p, found in patterns.items()}, frozenset(role_predicates))


def analyse_goal_reading(
    domain: Domain, problem: Problem, index: FactIndex, deadline: float | None = None
) -> tuple[GoalAnalysis, GoalReads]:
    """:func:`analyse_goal`, and what it read of the facts (for a caller that keeps the analysis
    while the facts change)."""
    regression = _ReadingRegression(domain, problem, index, deadline)
    return regression.run(), regression.reads()


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


def _unify(
    domain: Domain, objects: Mapping[str, str], action: Action, added: Atom, pattern_args: tuple[Term, ...]
) -> dict[str, Term] | None:
    """Bind the achiever's parameters to the pattern's objects and types, or None if they clash."""
    params = dict(action.parameters)
    bound: dict[str, Term] = {}
    for arg, want in zip(added.args, pattern_args):
        if arg.startswith("?"):
            declared = params.get(arg, "object")
            if want[0] == "obj":
                kind = objects.get(want[1])
                if kind is None or not domain.is_subtype(kind, declared):
                    return None
                bound[arg] = want
            elif domain.is_subtype(declared, want[1]):
                bound[arg] = ("type", declared)
            elif domain.is_subtype(want[1], declared):
                bound[arg] = ("type", want[1])
            else:
                return None
        elif want[0] == "obj" and want[1] != arg:
            return None
    return bound


def _roles(
    action: Action, bound: Mapping[str, Term], pre_atoms: list[tuple[str, tuple[str, ...]]], index: FactIndex
) -> set[str]:
    """New parameters the initial state does not determine from known ones."""
    anchored = set(bound)
    new_vars = [name for name, _ in action.parameters if name not in bound]
    changed = True
    while changed:
        changed = False
        for var in new_vars:
            if var in anchored:
                continue
            for predicate_name, args in pre_atoms:
                if var not in args:
                    continue
                position = args.index(var)
                if predicate_name in index.singletons or any(
                    (other in anchored or not other.startswith("?"))
                    and (predicate_name, j, position) in index.functional
                    for j, other in enumerate(args)
                    if j != position
                ):
                    anchored.add(var)
                    changed = True
                    break
    return {var for var in new_vars if var not in anchored}
