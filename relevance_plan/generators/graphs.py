"""Small graph helpers for the generators: connected random maps and shortest routes.

A graph is a dict from a node to the list of its neighbours (both directions
present), built in a fixed order so that a seeded generator stays
byte-identical.
"""

from __future__ import annotations

import math
import random
from collections import deque
from collections.abc import Mapping, Sequence

Graph = dict[str, list[str]]
Point = tuple[float, float]


def add_edge(graph: Graph, a: str, b: str) -> None:
    if b not in graph.setdefault(a, []):
        graph[a].append(b)
        graph.setdefault(b, []).append(a)


def spanning_tree(rng: random.Random, nodes: Sequence[str], graph: Graph) -> None:
    """Connect ``nodes`` into ``graph``: each node after the first joins a random earlier one."""
    for position, node in enumerate(nodes):
        graph.setdefault(node, [])
        if position:
            add_edge(graph, node, nodes[rng.randrange(position)])


def geometric_graph(points: Mapping[str, Point], neighbours: int) -> Graph:
    """Each node linked to its ``neighbours`` nearest ones, then the components joined by their
    closest pair: a connected map whose edges are mostly short."""
    names = list(points)
    graph: Graph = {name: [] for name in names}
    for name in names:
        nearest = sorted((math.dist(points[name], points[other]), other) for other in names if other != name)
        for _, other in nearest[:neighbours]:
            add_edge(graph, name, other)
    while True:
        parts = components(graph)
        if len(parts) == 1:
            return graph
        first, rest = parts[0], set().union(*parts[1:])
        _, a, b = min((math.dist(points[a], points[b]), a, b) for a in first for b in rest)
        add_edge(graph, a, b)


def components(graph: Graph) -> list[list[str]]:
    seen: set[str] = set()
    parts = []
    for start in graph:
        if start in seen:
            continue
        part, queue = [], deque([start])
        seen.add(start)
        while queue:
            node = queue.popleft()
            part.append(node)
            for other in graph[node]:
                if other not in seen:
                    seen.add(other)
                    queue.append(other)
        parts.append(part)
    return parts


def shortest_path(graph: Graph, start: str, goal: str) -> list[str]:
    """The nodes of a fewest-edges path from ``start`` to ``goal`` (both included); [] if none."""
    before: dict[str, str | None] = {start: None}
    queue = deque([start])
    while queue:
        node = queue.popleft()
        if node == goal:
            path = [node]
            while before[path[-1]] is not None:
                path.append(before[path[-1]])  # type: ignore[arg-type]
            return path[::-1]
        for other in graph[node]:
            if other not in before:
                before[other] = node
                queue.append(other)
    return []


def route(graph: Graph, stops: Sequence[str]) -> list[str]:
    """The nodes of shortest paths visiting ``stops`` in order (each node once, first visit order)."""
    visited: dict[str, None] = dict.fromkeys(stops[:1])
    for a, b in zip(stops, stops[1:]):
        leg = shortest_path(graph, a, b)
        if not leg:
            raise ValueError(f"no path from {a} to {b}")
        visited.update(dict.fromkeys(leg))
    return list(visited)


def random_points(rng: random.Random, names: Sequence[str], side: float) -> dict[str, Point]:
    return {name: (rng.uniform(0, side), rng.uniform(0, side)) for name in names}
