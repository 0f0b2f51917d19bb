"""A scene graph as a problem of the hydra domain, every object traced to its graph node.

What comes from where:

- each place node is a ``place``; a place edge is ``connected`` both ways;
- each room node is a ``room`` of its class (``room-is``); a place is
  ``in-room`` of its parent room, or, without one, of the room of the nearest
  place (in steps along place edges) that has one, or of the nearest room;
- each object node is a ``thing`` of its class (``is-a``), ``at`` its parent
  place, or at the nearest place (by position) when it has none; its class's
  kind gives ``pickable``, ``supports``, ``holds-inside``, ``openable`` (closed
  at first); an item whose position lies inside a container's box is
  ``inside`` it, else one over a surface's box is ``on`` it (and at its place),
  else ``loose``; the class facts the goals use (``class-on``, ``class-inside``,
  ``class-in-room``) hold for what the scene already has;
- the agent (``robot``) stands where its latest pose is (the agent layer's
  last node and its place), else at the place ``start`` names, else at the
  first place.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType

from relevance_plan.errors import SceneGraphError
from relevance_plan.scene_graphs.classes import (
    DEFAULT_FLOOR,
    GENERIC_ROOM,
    NO_MAPPING,
    Kind,
    LabelMapping,
    LabelQuery,
    LabelVocabulary,
    Placement,
    place_labels,
)
from relevance_plan.scene_graphs.graph import OBJECTS, PLACES, ROOMS, GraphNode, SceneGraph
from relevance_plan.scene_graphs.naming import AGENT, node_name, pddl_word, symbol_parts

DOMAIN_NAME = "hydra-scene-graph"
LAYER_WORDS = {OBJECTS: "objects", PLACES: "places", ROOMS: "rooms"}
NO_ROOM = "no_room"  # the one room of a graph that has none
CELL = 2.0  # metres: the grid that finds the boxes an item may lie in or on
TYPE_ORDER = ("agent", "place", "room", "thing", "class")


@dataclass(frozen=True)
class NodeRef:
    """Where one PDDL object comes from: its graph node (None for a class or a made-up room) and label."""

    node: int | None
    symbol: str | None
    layer: str
    label: int | None = None
    label_name: str | None = None
    class_name: str | None = None
    note: str = ""

    def as_json(self) -> dict:
        found = {"node": self.node, "symbol": self.symbol, "layer": self.layer}
        for key, value in (("label", self.label), ("label_name", self.label_name), ("class", self.class_name)):
            if value is not None:
                found[key] = value
        if self.note:
            found["note"] = self.note
        return found


@dataclass(frozen=True)
class ImportedScene:
    source: str
    objects: Mapping[str, str] = field(default_factory=dict)  # name -> type
    facts: tuple[tuple[str, ...], ...] = ()
    refs: Mapping[str, NodeRef] = field(default_factory=dict)
    placements: tuple[Placement, ...] = ()
    notes: tuple[str, ...] = ()
    kinds: Mapping[str, Kind] = field(default_factory=dict)  # class -> its kind (rooms: Kind.ROOM)

    @property
    def questions(self) -> tuple[Placement, ...]:
        return tuple(p for p in self.placements if p.chosen is None)

    def names_of_class(self, class_name: str) -> list[str]:
        return sorted(name for name, ref in self.refs.items() if ref.class_name == class_name and ref.node is not None)


@dataclass
class _Building:
    """The scene as it is put together (``import_graph``'s working state)."""

    objects: dict[str, str] = field(default_factory=dict)
    facts: set[tuple[str, ...]] = field(default_factory=set)
    refs: dict[str, NodeRef] = field(default_factory=dict)
    names: dict[int, str] = field(default_factory=dict)  # node id -> name
    notes: list[str] = field(default_factory=list)

    def add(self, name: str, kind: str, ref: NodeRef) -> str:
        if name in self.objects:
            raise SceneGraphError(f"two nodes would both be named '{name}'", path=None)
        self.objects[name] = kind
        self.refs[name] = ref
        if ref.node is not None:
            self.names[ref.node] = name
        return name


def import_graph(
    graph: SceneGraph,
    vocabulary: LabelVocabulary,
    mapping: LabelMapping = NO_MAPPING,
    floor: float = DEFAULT_FLOOR,
    start: str | None = None,
) -> ImportedScene:
    """The graph as the hydra domain's objects and facts; with questions (and nothing else) when a
    label cannot be placed."""
    placements = _placements(graph, vocabulary, mapping, floor)
    if any(p.chosen is None for p in placements):
        return ImportedScene(graph.source, placements=placements, notes=graph.notes)
    chosen = {(p.layer, p.label): p for p in placements}
    built = _Building(notes=list(graph.notes))
    neighbours = graph.neighbours()
    places = graph.on_layer(PLACES)
    if not places:
        raise SceneGraphError("the graph has no places (layer 3): nowhere for the robot to stand", path=graph.source)
    for node in places:
        built.add(node_name(node.id, "place"), "place", NodeRef(node.id, node.symbol, "places"))
    for node in places:
        for other in neighbours[node.id]:
            if other in built.names and graph.nodes[other].layer == PLACES and other != node.id:
                built.facts.add(("connected", built.names[node.id], built.names[other]))
    _add_rooms(graph, built, chosen, neighbours)
    _add_things(graph, built, chosen, vocabulary, neighbours)
    _place_agent(graph, built, neighbours, start)
    kinds = _add_classes(built, vocabulary)
    return ImportedScene(
        graph.source,
        MappingProxyType(_ordered(built.objects)),
        tuple(sorted(built.facts)),
        MappingProxyType(dict(sorted(built.refs.items()))),
        placements,
        tuple(built.notes),
        MappingProxyType(kinds),
    )


def _ordered(objects: dict[str, str]) -> dict[str, str]:
    return dict(sorted(objects.items(), key=lambda item: (TYPE_ORDER.index(item[1]), item[0])))


def _label_query(graph: SceneGraph, mapping: LabelMapping, layer: int, label: int | None) -> LabelQuery:
    word = LAYER_WORDS[layer]
    if label is None:
        return LabelQuery(word, None, None)
    name = mapping.names.get(word, {}).get(label) or graph.label_names.get(layer, {}).get(label)
    return LabelQuery(word, label, name, graph.coarse_label_names.get(layer, {}).get(label))


def _placements(
    graph: SceneGraph, vocabulary: LabelVocabulary, mapping: LabelMapping, floor: float
) -> tuple[Placement, ...]:
    queries = []
    for layer in (OBJECTS, ROOMS):
        labels = sorted({n.label for n in graph.on_layer(layer)}, key=lambda label: (label is None, label or 0))
        queries += [_label_query(graph, mapping, layer, label) for label in labels]
    return place_labels(queries, vocabulary, floor)


def _add_rooms(graph: SceneGraph, built: _Building, chosen: dict, neighbours: dict[int, set[int]]) -> None:
    rooms = graph.on_layer(ROOMS)
    for room in rooms:
        placement = chosen[("rooms", room.label)]
        ref = NodeRef(room.id, room.symbol, "rooms", room.label, placement.name, placement.chosen)
        name = built.add(node_name(room.id, placement.chosen or GENERIC_ROOM), "room", ref)
        built.facts.add(("room-is", name, pddl_word(placement.chosen or GENERIC_ROOM)))
    if not rooms:
        built.add(NO_ROOM, "room", NodeRef(None, None, "rooms", class_name=GENERIC_ROOM, note="the graph has no rooms"))
        built.facts.add(("room-is", NO_ROOM, GENERIC_ROOM))
        built.notes.append("the graph has no rooms: every place is in one room, no_room")
    room_of = _rooms_of_places(graph, built, neighbours, rooms)
    for place, room_name in room_of.items():
        built.facts.add(("in-room", built.names[place], room_name))


def _rooms_of_places(
    graph: SceneGraph, built: _Building, neighbours: dict[int, set[int]], rooms: list[GraphNode]
) -> dict[int, str]:
    """Each place's room: its parent, else the nearest roomed place's (breadth first), else the nearest room."""
    places = [n.id for n in graph.on_layer(PLACES)]
    room_ids = {room.id for room in rooms}
    room_of: dict[int, str] = {}
    for place in places:
        parents = sorted(other for other in neighbours[place] if other in room_ids)
        if parents:
            room_of[place] = built.names[parents[0]]
    frontier = sorted(room_of)
    inherited = 0
    while frontier:
        following = []
        for place in frontier:
            for other in sorted(neighbours[place]):
                if other not in room_of and graph.nodes[other].layer == PLACES:
                    room_of[other] = room_of[place]
                    following.append(other)
                    inherited += 1
        frontier = following
    unreached = [place for place in places if place not in room_of]
    for place in unreached:
        here = graph.nodes[place].position
        room_of[place] = (
            built.names[min(rooms, key=lambda room: (math.dist(room.position, here), room.id)).id] if rooms else NO_ROOM
        )
    if inherited or (unreached and rooms):
        built.notes.append(
            f"{inherited} places without a room took the room of the nearest place with one,"
            f" {len(unreached) if rooms else 0} the nearest room"
        )
    return room_of


def _nearest_place(graph: SceneGraph, built: _Building, position: tuple[float, float, float]) -> str:
    places = graph.on_layer(PLACES)
    return built.names[min(places, key=lambda place: (math.dist(place.position, position), place.id)).id]


def _parent_place(node: GraphNode, graph: SceneGraph, built: _Building, neighbours: dict[int, set[int]]) -> str | None:
    parents = sorted(other for other in neighbours[node.id] if graph.nodes[other].layer == PLACES)
    return built.names[parents[0]] if parents else None


def _add_things(
    graph: SceneGraph, built: _Building, chosen: dict, vocabulary: LabelVocabulary, neighbours: dict[int, set[int]]
) -> None:
    placed_nearest = 0
    things: list[tuple[GraphNode, str, Kind]] = []
    for node in graph.on_layer(OBJECTS):
        placement = chosen[("objects", node.label)]
        entry = vocabulary.things[placement.chosen or ""]
        ref = NodeRef(node.id, node.symbol, "objects", node.label, placement.name, entry.name)
        name = built.add(node_name(node.id, entry.name), "thing", ref)
        built.facts.add(("is-a", name, pddl_word(entry.name)))
        place = _parent_place(node, graph, built, neighbours)
        if place is None:
            place = _nearest_place(graph, built, node.position)
            placed_nearest += 1
        built.facts.add(("at", name, place))
        if entry.kind is Kind.ITEM:
            built.facts.add(("pickable", name))
        elif entry.kind is Kind.SURFACE:
            built.facts.add(("supports", name))
        elif entry.kind is Kind.CONTAINER:
            built.facts.add(("holds-inside", name))
            built.facts |= {("openable", name), ("closed", name)} if entry.openable else {("opened", name)}
        things.append((node, name, entry.kind))
    if placed_nearest:
        built.notes.append(f"{placed_nearest} objects without a parent place are at the nearest place")
    _relate_items(built, things)


def _relate_items(built: _Building, things: list[tuple[GraphNode, str, Kind]]) -> None:
    """Each item inside the smallest container box that holds its position, else on the smallest surface
    box below it, else loose; an item on or in something is at that thing's place."""
    grid: dict[tuple[int, int], list[tuple[GraphNode, str, Kind]]] = {}
    for thing in things:
        node, _, kind = thing
        if kind in (Kind.SURFACE, Kind.CONTAINER) and node.box is not None:
            (x0, y0, _), (x1, y1, _) = node.box
            for i in range(math.floor(x0 / CELL), math.floor(x1 / CELL) + 1):
                for j in range(math.floor(y0 / CELL), math.floor(y1 / CELL) + 1):
                    grid.setdefault((i, j), []).append(thing)
    place_of = {fact[1]: fact[2] for fact in built.facts if fact[0] == "at"}
    for node, name, kind in things:
        if kind is not Kind.ITEM:
            continue
        cell = (math.floor(node.position[0] / CELL), math.floor(node.position[1] / CELL))
        holders = [h for h in grid.get(cell, ()) if h[1] != name and _holds(h, node.position)]
        if not holders:
            built.facts.add(("loose", name))
            continue
        holder = min(holders, key=lambda h: (h[2] is not Kind.CONTAINER, _volume(h[0]), h[0].id))
        relation = "inside" if holder[2] is Kind.CONTAINER else "on"
        built.facts.add((relation, name, holder[1]))
        built.facts.discard(("at", name, place_of[name]))
        built.facts.add(("at", name, place_of[holder[1]]))


def _holds(holder: tuple[GraphNode, str, Kind], position: tuple[float, float, float]) -> bool:
    box = holder[0].box
    assert box is not None
    (x0, y0, z0), (x1, y1, z1) = box
    if not (x0 <= position[0] <= x1 and y0 <= position[1] <= y1):
        return False
    if holder[2] is Kind.CONTAINER:
        return z0 <= position[2] <= z1
    return (z0 + z1) / 2 <= position[2] <= z1 + (z1 - z0) + 0.5  # above the surface's middle, not far over it


def _volume(node: GraphNode) -> float:
    assert node.box is not None
    (x0, y0, z0), (x1, y1, z1) = node.box
    return (x1 - x0) * (y1 - y0) * (z1 - z0)


def _place_agent(graph: SceneGraph, built: _Building, neighbours: dict[int, set[int]], start: str | None) -> None:
    poses = sorted((n for n in graph.nodes.values() if n.is_agent_pose), key=lambda n: (n.partition, n.id))
    latest = poses[-1] if poses else None
    if start is not None:
        place = _named_place(graph, built, start)
        how = f"at {place}, as --start says"
    elif latest is not None:
        place = _parent_place(latest, graph, built, neighbours) or _nearest_place(graph, built, latest.position)
        how = f"at {place}, the place of its latest pose {latest.symbol}"
    else:
        place = built.names[graph.on_layer(PLACES)[0].id]
        how = f"at {place}, the first place (the graph has no agent poses; --start chooses another)"
    ref = NodeRef(latest.id if latest else None, latest.symbol if latest else None, "agents", note=f"starts {how}")
    built.add(AGENT, "agent", ref)
    built.facts |= {("agent-at", AGENT, place), ("hand-free", AGENT)}
    built.notes.append(f"the robot starts {how}")


def _named_place(graph: SceneGraph, built: _Building, start: str) -> str:
    """``--start``: a place's PDDL name, its NodeSymbol (``p(657)``) or its node id."""
    wanted = start.strip().lower()
    for node in graph.on_layer(PLACES):
        name = built.names[node.id]
        if wanted in (name, node.symbol.lower(), str(node.id)):
            return name
    raise SceneGraphError(
        f"--start: no place '{start}' in the graph (give a place's name, symbol or node id)", path=graph.source
    )


def _add_classes(built: _Building, vocabulary: LabelVocabulary) -> dict[str, Kind]:
    """The class objects of the classes present, and the class facts the scene already makes true."""
    kinds: dict[str, Kind] = {}
    for ref in list(built.refs.values()):
        if ref.class_name is not None:
            entry = vocabulary.rooms.get(ref.class_name) if ref.layer == "rooms" else vocabulary.things[ref.class_name]
            kinds[pddl_word(ref.class_name)] = entry.kind if entry is not None else Kind.ROOM
    for class_name in sorted(kinds):
        if class_name in built.objects:
            raise SceneGraphError(f"class '{class_name}' has the name of another object", path=None)
        built.add(
            class_name,
            "class",
            NodeRef(None, None, "classes", class_name=class_name, note=_labels_of(built, class_name)),
        )
    is_a = {fact[1]: fact[2] for fact in built.facts if fact[0] in ("is-a", "room-is")}
    room = {fact[1]: fact[2] for fact in built.facts if fact[0] == "in-room"}
    at = {fact[1]: fact[2] for fact in built.facts if fact[0] == "at"}
    for fact in list(built.facts):
        if fact[0] in ("on", "inside"):
            built.facts.add(("class-on" if fact[0] == "on" else "class-inside", is_a[fact[1]], is_a[fact[2]]))
        elif fact[0] == "at":
            built.facts.add(("class-in-room", is_a[fact[1]], is_a[room[at[fact[1]]]]))
    return kinds


def _labels_of(built: _Building, class_name: str) -> str:
    labels = sorted(
        {
            f"{ref.layer} {ref.label}"
            for ref in built.refs.values()
            if ref.label is not None and pddl_word(ref.class_name or "") == class_name
        }
    )
    return "labels " + ", ".join(labels) if labels else ""


# --------------------------------------------------------------------------- the written problem


def problem_text(scene: ImportedScene, goal: str, name: str) -> str:
    """The problem as PDDL text: objects by type, facts sorted, ``goal`` (a conjunction's body)."""
    lines = [
        f"; Imported by relevance-plan from the scene graph {scene.source}:",
        f"; {len(scene.objects)} objects; the sidecar (.json) names the graph node of each.",
        f"(define (problem {pddl_word(name)})",
        f"  (:domain {DOMAIN_NAME})",
        "  (:objects",
    ]
    for kind in TYPE_ORDER:
        names = [n for n, t in scene.objects.items() if t == kind]
        for start in range(0, len(names), 8):
            lines.append("    " + " ".join(names[start : start + 8]) + f" - {kind}")
    lines.append("  )")
    lines.append("  (:init")
    lines += [f"    ({' '.join(fact)})" for fact in scene.facts]
    lines.append("  )")
    lines.append(f"  (:goal (and {goal}))")
    lines.append(")")
    return "\n".join(lines) + "\n"


def node_of(scene: ImportedScene, name: str) -> NodeRef | None:
    return scene.refs.get(name)


def symbol_of(node_id: int) -> str:
    character, index = symbol_parts(node_id)
    return f"{character}({index})" if character.isprintable() and character != "\0" else str(node_id)
