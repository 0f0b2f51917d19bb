"""How far objects are from each other: hops through the facts that link them.

:class:`ObjectGraph` is the objects' links (two objects in one fact are one hop apart, a
class-like position not followed past ``max_fan``); ``graph_distances`` walks it breadth-first,
``walk_bounds`` and :class:`NearestBetween` order objects by hops from two sides, and
:class:`GrowingDistances` follows a set of sources that only grows (the repair's).  A graph a
live session keeps holds its walks, which ``walk_changed`` says an event may change.
"""

from __future__ import annotations

import heapq
from collections.abc import Callable, Iterable, Iterator, Mapping

from relevance_plan.relevance.analysis.facts import FactIndex, fan_in


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
