"""The live scene: objects, true facts and the goal, changed one event at a time.

Kept in memory only.  :class:`LiveIndex` holds the current facts exactly as
``facts.index_init`` indexes the written current state (the same lists in
the same order), but is updated fact by fact, so every stage of pruning reads
the live state as it would read a snapshot, without re-indexing it.
:meth:`LiveScene.snapshot_problem` is the current state as a Problem value
(built once per change, on first use); :meth:`LiveScene.problem_text`
renders it as PDDL in the user's spelling, for planning and snapshots.
"""

from __future__ import annotations

from bisect import bisect_left, insort
from collections.abc import Callable, Iterable, Iterator, Mapping
from dataclasses import dataclass, field
from types import MappingProxyType

from relevance_plan.pddl.formatter import format_problem
from relevance_plan.pddl.formulas import Formula, literals
from relevance_plan.pddl.model import Domain, Problem, Spelling
from relevance_plan.pddl.parser import read_problem
from relevance_plan.relevance.analysis.distances import ObjectGraph, walk_changed
from relevance_plan.relevance.analysis.invariants import count_keeping_for


def atom_objects(atom: tuple) -> Iterator[str]:
    """The distinct objects of a fact or a numeric term, each once (as ``index_init`` files them)."""
    if len(atom) == 3:
        yield atom[1]
        if atom[2] != atom[1]:
            yield atom[2]
    else:
        yield from dict.fromkeys(atom[1:])


class LiveIndex:
    """The current facts, indexed as ``facts.index_init`` indexes the written state (a ``FactIndex``).

    Each predicate's and each object's list holds its facts sorted (the
    order of the written state), then its numeric terms (``(distance a b)``,
    linking objects like a fact) in the order their values were first set.
    Which argument positions are functional, which predicates have a single
    fact, and how many facts share each value (``fan``) are kept by counts,
    so asking costs nothing like a pass over the facts.
    """

    def __init__(
        self, facts: Iterable[tuple] = (), terms: Iterable[tuple] = (), count_keeping: frozenset = frozenset()
    ):
        # (predicate, position) pairs where no action gives an object one more fact: functional
        # while fewer than half their objects have two (``index_init``'s rule)
        self.count_keeping = count_keeping
        self._degrees: dict[int, int] = {}  # degree -> how many objects have it
        self._predicates = _FactLists()
        self._objects = _FactLists(self._degrees)
        self.by_predicate: dict[str, list[tuple]] = self._predicates.items
        self.by_object: dict[str, list[tuple]] = self._objects.items
        # (predicate, position) -> value -> number of facts; a position is functional when no value
        # occurs in two facts (``index_init``'s test, for distinct facts)
        self._counts: dict[tuple[str, int], dict[str, int]] = {}
        self._clashes: dict[tuple[str, int], int] = {}
        self._singletons: set[str] = set()
        self._functional: frozenset | None = None
        # max_fan -> (the positions not followed, the graph): kept across changes, each change
        # dropping what it can alter (see object_graph)
        self._graphs: dict[float | None, tuple[frozenset, ObjectGraph]] = {}
        for fact in sorted(facts):  # in order: each insertion lands at the end of its lists
            self.add(fact)
        for term in terms:
            self.add_term(term)

    # ------------------------------------------------------------------ changes

    def add(self, fact: tuple) -> None:
        self._file(fact, _FactLists.insert, 1)

    def discard(self, fact: tuple) -> None:
        """Remove a fact that is there (the caller checks)."""
        self._file(fact, _FactLists.delete, -1)

    def add_term(self, term: tuple) -> None:
        """A numeric term ``(function, args...)`` whose value was set for the first time."""
        self._file(term, _FactLists.append, 1)

    def discard_term(self, term: tuple) -> None:
        self._file(term, _FactLists.remove_term, -1)

    def _file(self, atom: tuple, change: Callable[[_FactLists, str, tuple], None], step: int) -> None:
        """``change`` the lists of ``atom``'s predicate and of each of its objects, and the counts."""
        change(self._predicates, atom[0], atom)
        names = list(atom_objects(atom))
        for name in names:
            change(self._objects, name, atom)
        self._count(atom, step)
        if self._graphs:
            self._graphs_changed(atom, names, step)

    def _graphs_changed(self, atom: tuple, names: list[str], step: int) -> None:
        """What the kept graphs knew of ``names`` forgotten, and the walks the change can alter dropped."""
        degrees = {
            name: (len(self.by_object.get(name, ())) - step, len(self.by_object.get(name, ()))) for name in names
        }
        for max_fan, (_, graph) in self._graphs.items():
            for name in names:
                graph.found.pop(name, None)
            walks = graph.walks
            if not walks:
                continue

            def followed(predicate: str, position: int, max_fan: float | None = max_fan) -> bool:
                return max_fan is None or self.fan(predicate, position) <= max_fan

            for key in [
                key for key, walked in walks.items() if walk_changed(walked, atom, names, degrees, followed, key[1])
            ]:
                del walks[key]

    def object_graph(self, max_fan: float | None) -> ObjectGraph:
        """The links of the current facts as ``distances.ObjectGraph(self, max_fan, fan_in(self))``
        gives them, kept across changes with the walks made on it (``graph_distances``): a change
        drops what it can alter, and a position whose fan crosses ``max_fan`` makes a new graph."""
        unfollowed: frozenset[tuple[str, int]] = frozenset()
        if max_fan is not None:
            unfollowed = frozenset(
                (predicate, position)
                for predicate, atoms in self.by_predicate.items()
                for position in range(len(atoms[0]) - 1)
                if self.fan(predicate, position) > max_fan
            )
        kept = self._graphs.get(max_fan)
        if kept is not None and kept[0] == unfollowed:
            return kept[1]
        graph = ObjectGraph(self, max_fan, _LiveFans(self))
        graph.walks = {}
        self._graphs[max_fan] = (unfollowed, graph)
        return graph

    def _count(self, atom: tuple, step: int) -> None:
        predicate = atom[0]
        for position, value in enumerate(atom[1:]):
            counts = self._counts.setdefault((predicate, position), {})
            before = counts.get(value, 0)
            after = before + step
            if after:
                counts[value] = after
            else:
                del counts[value]
            # a value in two facts or more makes the position not functional (at a count-keeping
            # position, while such values are fewer than half: a value that comes or goes counts too)
            change = (after >= 2) - (before >= 2)
            if change:
                self._clashes[predicate, position] = self._clashes.get((predicate, position), 0) + change
                self._functional = None
            elif (
                (not before or not after)
                and self._clashes.get((predicate, position))
                and ((predicate, position) in self.count_keeping)
            ):
                self._functional = None
        if len(self.by_predicate.get(predicate, ())) == 1:
            self._singletons.add(predicate)
        else:
            self._singletons.discard(predicate)
        if len(self.by_predicate.get(predicate, ())) <= 1:  # a predicate came or went
            self._functional = None

    def set_count_keeping(self, positions: frozenset) -> None:
        """The count-keeping positions anew (fewer timed literals can add some)."""
        if positions != self.count_keeping:
            self.count_keeping = positions
            self._functional = None

    # ------------------------------------------------------------------ views

    def facts_of(self, name: str, predicate: str) -> list[tuple]:
        return [atom for atom in self.by_object.get(name, ()) if atom[0] == predicate]

    def degree(self, name: str) -> int:
        """How many facts and terms name the object (what ``hub_degree`` is compared with)."""
        return len(self.by_object.get(name, ()))

    def any_degree_between(self, low: int, high: int) -> bool:
        """Whether some object is named by more than ``low`` and at most ``high`` facts and terms."""
        return any(self._degrees.get(degree) for degree in range(low + 1, high + 1))

    def fan(self, predicate: str, position: int) -> float:
        """Facts per distinct object at ``position`` of ``predicate`` (``facts.fan_in``'s value)."""
        atoms = len(self.by_predicate.get(predicate, ()))
        return atoms / max(1, len(self._counts.get((predicate, position), ())))

    @property
    def functional(self) -> frozenset:
        if self._functional is None:
            found: set[tuple[str, int, int]] = set()
            for predicate, atoms in self.by_predicate.items():
                arity = len(atoms[0]) - 1
                for key in range(arity):
                    clashes = self._clashes.get((predicate, key), 0)
                    if not clashes or (
                        (predicate, key) in self.count_keeping and 2 * clashes < len(self._counts[predicate, key])
                    ):
                        found.update((predicate, key, other) for other in range(arity) if other != key)
            self._functional = frozenset(found)
        return self._functional

    @property
    def singletons(self) -> frozenset:
        return frozenset(self._singletons)


class _FactLists:
    """Fact lists by key (a predicate, an object): each sorted, then its numeric terms in the order
    their values were first set.  With ``degrees`` (degree -> how many keys have it), each key's
    length is counted there too."""

    def __init__(self, degrees: dict[int, int] | None = None):
        self.items: dict[str, list[tuple]] = {}
        self._terms: dict[str, int] = {}  # how many numeric terms end each key's list
        self._degrees = degrees

    def insert(self, key: str, fact: tuple) -> None:
        items = self.items.get(key)
        if items is None:
            items = self.items[key] = []
        self._move_degree(len(items), 1)
        insort(items, fact, 0, len(items) - self._terms.get(key, 0))

    def append(self, key: str, term: tuple) -> None:
        items = self.items.setdefault(key, [])
        self._move_degree(len(items), 1)
        items.append(term)
        self._terms[key] = self._terms.get(key, 0) + 1

    def remove_term(self, key: str, term: tuple) -> None:
        self._move_degree(len(self.items[key]), -1)
        self.items[key].remove(term)
        self._terms[key] -= 1
        self._drop_if_empty(key)

    def delete(self, key: str, fact: tuple) -> None:
        items = self.items[key]
        self._move_degree(len(items), -1)
        del items[bisect_left(items, fact, 0, len(items) - self._terms.get(key, 0))]
        self._drop_if_empty(key)

    def _move_degree(self, degree: int, step: int) -> None:
        """A key's degree moves by ``step`` from ``degree`` (when degrees are counted)."""
        degrees = self._degrees
        if degrees is None:
            return
        if degree:
            degrees[degree] -= 1
        if degree + step:
            degrees[degree + step] = degrees.get(degree + step, 0) + 1

    def _drop_if_empty(self, key: str) -> None:
        if not self.items[key]:  # index_init has no entry for what has no fact
            del self.items[key]
            self._terms.pop(key, None)


class _LiveFans(Mapping[tuple[str, int], float]):
    """``facts.fan_in`` of a live index, each value read when asked."""

    def __init__(self, index: LiveIndex):
        self.index = index

    def __getitem__(self, key: tuple[str, int]) -> float:
        predicate, position = key
        atoms = self.index.by_predicate.get(predicate)
        if not atoms or not 0 <= position < len(atoms[0]) - 1:
            raise KeyError(key)
        return self.index.fan(predicate, position)

    def __iter__(self) -> Iterator[tuple[str, int]]:
        for predicate, atoms in self.index.by_predicate.items():
            for position in range(len(atoms[0]) - 1):
                yield predicate, position

    def __len__(self) -> int:
        return sum(len(atoms[0]) - 1 for atoms in self.index.by_predicate.values())


@dataclass
class SceneDelta:
    """What one event changed in the scene (see :meth:`LiveScene.take_delta`)."""

    added: list[tuple] = field(default_factory=list)  # facts and numeric terms the index gained
    removed: list[tuple] = field(default_factory=list)  # ... and lost
    objects_added: list[str] = field(default_factory=list)
    objects_removed: list[str] = field(default_factory=list)
    removed_types: dict[str, str] = field(default_factory=dict)  # each removed object's type
    values: list[tuple] = field(default_factory=list)  # numeric fluents whose value changed
    goal: bool = False

    def __bool__(self) -> bool:
        return bool(
            self.added or self.removed or self.objects_added or self.objects_removed or self.values or self.goal
        )

    @property
    def atoms(self) -> list[tuple]:
        """Every fact and numeric term that came or went."""
        return self.added + self.removed


class LiveScene:
    """Objects (in the order they appeared), true facts, numeric values and the goal of the current scene."""

    def __init__(self, domain: Domain, problem: Problem):
        self.domain = domain
        self.name = problem.name
        self.objects: dict[str, str] = dict(problem.objects)
        # the objects by type, types in order of first appearance: the order of the written state
        self._by_type: dict[str, dict[str, None]] = {}
        for name, type_name in self.objects.items():
            self._by_type.setdefault(type_name, {})[name] = None
        # whether ``objects`` lists the objects grouped by type already (then a copy is the written order)
        self._grouped = list(self._by_type) == list(dict.fromkeys(self.objects.values()))
        self.display: dict[str, str] = {name: problem.display(name) for name in problem.objects}
        self.facts: set = set(problem.init)
        self.values: dict[tuple, float] = dict(problem.numeric_init)  # (function, args...) -> value
        terms = (term for term in self.values if len(term) > 1)
        self.index = LiveIndex(self.facts, terms, count_keeping_for(domain, problem.timed_literals))
        self.goal: Formula = problem.goal
        # carried into every written problem unchanged, minus what mentions a removed object
        self.timed_literals = problem.timed_literals
        self.constraints = problem.constraints
        self.metric = problem.metric
        self._snapshot: Problem | None = None
        self.delta = SceneDelta()  # what changed since the last take_delta

    def take_delta(self) -> SceneDelta:
        """What changed since the last call (an event's changes: the session takes them once per event)."""
        delta, self.delta = self.delta, SceneDelta()
        return delta

    # ------------------------------------------------------------------ changes

    def add_object(self, name: str, type_name: str, display: str) -> None:
        if type_name in self._by_type and self.objects[next(reversed(self.objects))] != type_name:
            self._grouped = False  # one more of a type whose group is not the last
        self.objects[name] = type_name
        self._by_type.setdefault(type_name, {})[name] = None
        self.display[name] = display
        self._snapshot = None
        self.delta.objects_added.append(name)

    def remove_object(self, name: str) -> list[tuple]:
        """Remove the object and every fact and value that mentions it; returns those facts."""
        gone = [atom for atom in self.index.by_object.get(name, ()) if atom in self.facts]
        for fact in gone:
            self.unset(fact)
        type_name = self.objects.pop(name)
        del self._by_type[type_name][name]
        if not self._by_type[type_name]:
            del self._by_type[type_name]
        del self.display[name]
        for fluent in [fluent for fluent in self.values if name in fluent[1:]]:
            del self.values[fluent]
            if len(fluent) > 1:
                self.index.discard_term(fluent)
                self.delta.removed.append(fluent)
        self.timed_literals = tuple(
            timed
            for timed in self.timed_literals
            if name not in (timed.atom or ())[1:] and name not in (timed.fluent or ())[1:]
        )
        self.index.set_count_keeping(count_keeping_for(self.domain, self.timed_literals))
        self._snapshot = None
        self.delta.objects_removed.append(name)
        self.delta.removed_types[name] = type_name
        return gone

    def set_value(self, fluent: tuple, value: float) -> bool:
        """A numeric fluent takes ``value``; False when it had it already."""
        if self.values.get(fluent) == value:
            return False
        if fluent not in self.values and len(fluent) > 1:
            self.index.add_term(fluent)
            self.delta.added.append(fluent)
        self.values[fluent] = value
        self._snapshot = None
        self.delta.values.append(fluent)
        return True

    def set(self, fact: tuple) -> bool:
        if fact in self.facts:
            return False
        self.facts.add(fact)
        self.index.add(fact)
        self._snapshot = None
        self.delta.added.append(fact)
        return True

    def unset(self, fact: tuple) -> bool:
        if fact not in self.facts:
            return False
        self.facts.discard(fact)
        self.index.discard(fact)
        self._snapshot = None
        self.delta.removed.append(fact)
        return True

    def set_goal(self, goal: Formula) -> None:
        self.goal = goal
        self._snapshot = None
        self.delta.goal = True

    # ------------------------------------------------------------------ views

    def type_of(self, name: str) -> str:
        """An object's (or a constant's) type."""
        return self.objects.get(name) or self.domain.constants.get(name, "object")

    @property
    def idle_goal(self) -> bool:
        """Whether the goal asks for nothing (``(and)``)."""
        return not any(True for _ in literals(self.goal))

    @property
    def spelling(self) -> Spelling:
        """The user's spelling of the domain's names and of the scene's objects (a view that follows
        the objects added and removed)."""
        return self.domain.spelling.with_objects(MappingProxyType(self.display))

    def ordered_objects(self) -> dict:
        """The objects grouped by type, types in order of first appearance (the order of :meth:`problem_text`)."""
        if self._grouped:
            return dict(self.objects)
        return {name: type_name for type_name, names in self._by_type.items() for name in names}

    def snapshot_problem(self) -> Problem:
        """The current state as a Problem value without source text (for pruning in memory); the
        same value until the scene changes."""
        if self._snapshot is None:
            self._snapshot = Problem(
                name=self.name,
                domain_name=self.domain.name,
                objects=MappingProxyType(self.ordered_objects()),
                init=frozenset(self.facts),
                goal=self.goal,
                text="",
                spelling=self.domain.spelling.with_objects(MappingProxyType(dict(self.display))),
                numeric_init=MappingProxyType(dict(self.values)),
                timed_literals=self.timed_literals,
                constraints=self.constraints,
                metric=self.metric,
            )
        return self._snapshot

    def problem_text(self) -> str:
        """The current state as PDDL in the user's spelling (objects grouped by type, facts sorted)."""
        return format_problem(self.snapshot_problem())

    def read_problem(self) -> Problem:
        """The current state as a Problem read back from :meth:`problem_text` (with source spans)."""
        return read_problem(self.problem_text(), self.domain)
