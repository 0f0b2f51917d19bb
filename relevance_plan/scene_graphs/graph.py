"""A scene graph as plain values: what the importer reads of a Hydra graph, whoever loaded it.

Hydra's layers (spark-dsg's ``DsgLayers``): objects 2, places 3, rooms 4,
buildings 5; the agent's poses are layer 2 in a partition of their own (its
prefix letter, ``a`` = 97).  A node keeps its id (spark-dsg's ``NodeSymbol``
value), its symbol (``O(12)``), its semantic label and its position.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType

from relevance_plan.errors import SceneGraphError

OBJECTS, PLACES, ROOMS, BUILDINGS = 2, 3, 4, 5
LAYER_NAMES: Mapping[int, str] = MappingProxyType(
    {OBJECTS: "objects", PLACES: "places", ROOMS: "rooms", BUILDINGS: "buildings"}
)
# The layers whose nodes the importer reads; layer 1 is the mesh, which spark-dsg keeps apart from the nodes.
KNOWN_LAYERS = frozenset(LAYER_NAMES)

Vector = tuple[float, float, float]


@dataclass(frozen=True)
class GraphNode:
    id: int  # spark-dsg's node id (a NodeSymbol's value)
    symbol: str  # the NodeSymbol as spark-dsg prints it: O(12), p(657)
    layer: int
    partition: int
    label: int | None  # the semantic label, where the node's attributes carry one
    position: Vector
    box: tuple[Vector, Vector] | None = None  # an axis-aligned bounding box (lower, upper corner) when valid

    @property
    def is_agent_pose(self) -> bool:
        return self.layer == OBJECTS and self.partition != 0


@dataclass(frozen=True)
class SceneGraph:
    """The nodes, the undirected edges and the label names (layer -> label -> name) of one graph."""

    source: str  # the file (or stream) it came from, for messages
    nodes: Mapping[int, GraphNode]
    edges: tuple[tuple[int, int], ...]
    label_names: Mapping[int, Mapping[int, str]] = field(default_factory=dict)
    # the file's own coarser name of a label where it has one (Matterport3D's mpcat40 category)
    coarse_label_names: Mapping[int, Mapping[int, str]] = field(default_factory=dict)
    notes: tuple[str, ...] = ()

    def on_layer(self, layer: int) -> list[GraphNode]:
        """The layer's nodes (agent poses excluded from the objects), in id order."""
        return sorted((n for n in self.nodes.values() if n.layer == layer and not n.is_agent_pose), key=lambda n: n.id)

    def neighbours(self) -> dict[int, set[int]]:
        found: dict[int, set[int]] = {node: set() for node in self.nodes}
        for a, b in self.edges:
            found[a].add(b)
            found[b].add(a)
        return found


def check_graph(graph: SceneGraph, ignore_unknown_layers: bool = False) -> SceneGraph:
    """The graph, refused in one line when a node sits on a layer the importer does not know, a
    position is not finite, or an edge names a node the graph lacks; unknown layers are left out
    (and said so in ``notes``) when ``ignore_unknown_layers``."""
    unknown = sorted({n.layer for n in graph.nodes.values() if n.layer not in KNOWN_LAYERS})
    nodes = dict(graph.nodes)
    notes = list(graph.notes)
    if unknown:
        shown = ", ".join(map(str, unknown))
        if not ignore_unknown_layers:
            known = ", ".join(f"{name} {layer}" for layer, name in LAYER_NAMES.items())
            raise SceneGraphError(
                f"nodes on layer {shown}, which the importer does not read (it reads {known});"
                " --ignore-unknown-layers leaves them out",
                path=graph.source,
            )
        left = [n for n in nodes.values() if n.layer in unknown]
        for node in left:
            del nodes[node.id]
        notes.append(f"left out {len(left)} nodes on layer {shown} (--ignore-unknown-layers)")
    for node in nodes.values():
        if not all(math.isfinite(value) for value in node.position):
            raise SceneGraphError(
                f"node {node.symbol} has a position that is not finite: {node.position}", path=graph.source
            )
    edges = []
    for a, b in graph.edges:
        if a in nodes and b in nodes:
            edges.append((a, b))
        elif a in graph.nodes and b in graph.nodes:
            continue  # an edge to a node left out with its layer
        else:
            missing = a if a not in graph.nodes else b
            raise SceneGraphError(f"an edge names node {missing}, which the graph does not have", path=graph.source)
    return SceneGraph(
        graph.source, MappingProxyType(nodes), tuple(edges), graph.label_names, graph.coarse_label_names, tuple(notes)
    )
