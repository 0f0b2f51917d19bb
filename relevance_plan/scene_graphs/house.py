"""A Matterport3D ``.house`` file as a Hydra scene graph, built with spark-dsg (``spark_dsg.mp3d``).

spark-dsg parses the file (``load_mp3d_info``) and makes its rooms
(``get_rooms_from_mp3d_info``: each region's floor polygon, its label as a
room node's semantic label).  A house has no places and no edges, so this
module makes them the way the importer needs them:

- places on a grid (``PLACE_SPACING`` apart) inside each room's polygon, at
  least one per room, each a child of its room, linked to its neighbours on
  the grid;
- rooms whose polygons come within ``DOOR_GAP`` of each other (on one level)
  are linked through their two nearest places;
- each object (an ``O`` line) is a child of the nearest place of its region,
  its label the file's category, the category's name in the objects' label
  space and its mpcat40 name kept as the coarser name.

The rooms' label space names Matterport3D's region codes.
"""

from __future__ import annotations

import math
from typing import Any

from relevance_plan.errors import SceneGraphError
from relevance_plan.scene_graphs.dsg import COARSE_LABELS_KEY, check_graph_file, native_output, read_dsg, spark_dsg
from relevance_plan.scene_graphs.graph import OBJECTS, ROOMS, SceneGraph

PLACE_SPACING = 1.0  # metres between places on a room's grid
DOOR_GAP = 0.3  # metres: rooms this close are joined
UNLABELED = 65535  # the label of an object the file gives no category (its category index is -1)
# Matterport3D's region codes (its dataset documentation), as the rooms' label names.
REGION_NAMES = {
    "a": "bathroom", "b": "bedroom", "c": "closet", "d": "dining room", "e": "entryway", "f": "family room",
    "g": "garage", "h": "hallway", "i": "library", "j": "laundry room", "k": "kitchen", "l": "living room",
    "m": "meeting room", "n": "lounge", "o": "office", "p": "porch", "r": "rec room", "s": "stairs",
    "t": "toilet", "u": "utility room", "v": "tv room", "w": "gym", "x": "outdoor", "y": "balcony",
    "z": "other room", "B": "bar", "C": "classroom", "D": "dining booth", "S": "spa", "Z": "junk", "-": "room",
}  # fmt: skip


def load_house(path: str, max_bytes: int) -> SceneGraph:
    """The house at ``path`` as a scene graph (see the module docstring)."""
    check_graph_file(path, max_bytes)
    module = spark_dsg()
    from spark_dsg import mp3d

    said: list[str] = []
    try:
        with native_output(said):
            info = mp3d.load_mp3d_info(path)
            rooms = mp3d.get_rooms_from_mp3d_info(info, angle_deg=0.0)
    except (ValueError, IndexError, KeyError, TypeError, UnicodeDecodeError) as error:
        raise SceneGraphError(f"not a Matterport3D house file spark-dsg can read: {error}", path=path) from None
    if not rooms:
        raise SceneGraphError("the house file has no regions (R lines): no rooms to plan in", path=path)
    graph = module.DynamicSceneGraph()
    try:
        with native_output(said):
            places = _add_rooms_and_places(module, graph, rooms)
            _add_objects(module, graph, info, places)
    except (ValueError, RuntimeError, AttributeError) as error:
        raise SceneGraphError(f"cannot build a scene graph from the house: {error}", path=path) from None
    return read_dsg(graph, path, said)


def _add_rooms_and_places(module: Any, graph: Any, rooms: list) -> dict[int, list[tuple[int, tuple]]]:
    """Room nodes, their places and the links between them; region index -> [(place id, position)]."""
    import shapely.geometry

    graph.set_labelspace(module.Labelspace({ord(code): name for code, name in REGION_NAMES.items()}), ROOMS, 0)
    building = module.NodeSymbol("B", 0).value
    attributes = module.SemanticNodeAttributes()
    attributes.position = [float(sum(r.centroid[i] for r in rooms) / len(rooms)) for i in range(3)]
    graph.add_node(module.DsgLayers.BUILDINGS, building, attributes)
    places: dict[int, list[tuple[int, tuple]]] = {}
    count = 0
    for room in rooms:
        room_id = room.get_id().value
        graph.add_node(module.DsgLayers.ROOMS, room_id, _room_attributes(room))
        graph.insert_edge(room_id, building)
        polygon = room.get_polygon_xy()
        grid = _grid_points(polygon, shapely.geometry.Point) or [tuple(polygon.representative_point().coords[0])]
        mine = []
        for x, y in grid:
            place = module.NodeSymbol("p", count).value
            count += 1
            place_attributes = module.PlaceNodeAttributes()
            place_attributes.position = [x, y, float(room._min_z)]
            graph.add_node(module.DsgLayers.PLACES, place, place_attributes)
            graph.insert_edge(place, room_id)
            mine.append((place, (x, y, float(room._min_z))))
        places[room._index] = mine
        for i, (a, at) in enumerate(mine):
            for b, bt in mine[i + 1 :]:
                if math.dist(at[:2], bt[:2]) <= PLACE_SPACING * 1.5:
                    graph.insert_edge(a, b)
    _join_rooms(graph, rooms, places)
    return places


def _room_attributes(room: Any) -> Any:
    """spark-dsg's attributes of a room: 1.1.3 asks for a colour (grey here), later versions do not."""
    import inspect

    import numpy

    wants_colour = len(inspect.signature(room.get_attrs).parameters) > 0
    return room.get_attrs(numpy.array([128, 128, 128])) if wants_colour else room.get_attrs()


def _grid_points(polygon: Any, point: Any) -> list[tuple[float, float]]:
    left, bottom, right, top = polygon.bounds
    found = []
    steps_x = max(1, int((right - left) / PLACE_SPACING))
    steps_y = max(1, int((top - bottom) / PLACE_SPACING))
    for i in range(steps_x):
        for j in range(steps_y):
            x = left + (i + 0.5) * (right - left) / steps_x
            y = bottom + (j + 0.5) * (top - bottom) / steps_y
            if polygon.contains(point(x, y)):
                found.append((round(x, 4), round(y, 4)))
    return found


def _join_rooms(graph: Any, rooms: list, places: dict[int, list[tuple[int, tuple]]]) -> None:
    for i, room in enumerate(rooms):
        for other in rooms[i + 1 :]:
            same_level = room._min_z <= other._max_z and other._min_z <= room._max_z
            if not same_level or room.get_polygon_xy().distance(other.get_polygon_xy()) > DOOR_GAP:
                continue
            a, b = min(
                ((a, b) for a in places[room._index] for b in places[other._index]),
                key=lambda pair: math.dist(pair[0][1], pair[1][1]),
            )
            graph.insert_edge(a[0], b[0])


def _add_objects(module: Any, graph: Any, info: dict, places: dict[int, list[tuple[int, tuple]]]) -> None:
    categories = {c["category_index"]: c for c in info["C"]}
    names = {index: c["category_mapping_name"].replace("#", " ") for index, c in categories.items()}
    names[UNLABELED] = "unlabeled"
    graph.set_labelspace(module.Labelspace(names), OBJECTS, 0)
    coarse = {str(index): c["mpcat40_name"] for index, c in categories.items()}
    graph.metadata.add({COARSE_LABELS_KEY: {str(OBJECTS): coarse}})
    every_place = [entry for group in places.values() for entry in group]
    for entry in info["O"]:
        position = [float(value) for value in entry["pos"]]
        attributes = module.ObjectNodeAttributes()
        attributes.position = position
        category = entry["category_index"]
        attributes.semantic_label = category if category in categories else UNLABELED
        attributes.name = names.get(category, "unlabeled")
        half = [sum(abs(axis[k]) * radius for axis, radius in zip(_axes(entry), entry["r"])) for k in range(3)]
        attributes.bounding_box = module.BoundingBox([2 * h for h in half], position)
        node = module.NodeSymbol("O", entry["object_index"]).value
        graph.add_node(module.DsgLayers.OBJECTS, node, attributes)
        nearby = places.get(entry["region_index"]) or every_place
        place = min(nearby, key=lambda candidate: math.dist(candidate[1], position))
        graph.insert_edge(place[0], node)


def _axes(entry: dict) -> list[list[float]]:
    a0, a1 = [float(v) for v in entry["a0"]], [float(v) for v in entry["a1"]]
    a2 = [a0[1] * a1[2] - a0[2] * a1[1], a0[2] * a1[0] - a0[0] * a1[2], a0[0] * a1[1] - a0[1] * a1[0]]
    return [a0, a1, a2]
