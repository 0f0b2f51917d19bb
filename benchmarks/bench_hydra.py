"""Hydra-format scene graphs at building scale: import time, and planning pruned against the unpruned import.

Each graph is built with spark-dsg itself (a row of rooms, a grid of places
in each, objects with a label space: items on surfaces and in containers,
fixtures), saved as Hydra JSON, then timed through the steps a user runs:
``scene-graph import`` (read with spark-dsg, classes, PDDL, sidecar), and
planning the imported problem with relevance (prune, plan, validate on the
original) against planning it unpruned (``--method pure``), each under
``--timeout``.  The goal is a class goal in words ("bring a cup to the kitchen",
which has none at first), met through any cup.

    python benchmarks/bench_hydra.py --objects 2000 --seeds 1 --timeout 120

Needs the hydra extra (spark-dsg).  A row per graph: objects, import
seconds, relevance and pure planning seconds, the ratio measured in this
run, and the objects the first selection kept.
"""

from __future__ import annotations

import argparse
import random
import sys
import tempfile
from dataclasses import replace
from pathlib import Path

import base

ROOMS = {0: "kitchen", 1: "bedroom", 2: "living room", 3: "bathroom", 4: "office"}
OBJECTS = {0: "cup", 1: "book", 2: "bottle", 3: "towel", 4: "table", 5: "shelf", 6: "cabinet", 7: "fridge", 8: "wall"}
ITEMS, HOLDERS = (0, 1, 2, 3), (4, 5, 6, 7)


def build_graph(objects: int, seed: int, path: Path) -> None:
    """A graph of about ``objects`` objects (one room per 100), saved to ``path`` as Hydra JSON."""
    import spark_dsg as dsg

    rng = random.Random(seed)
    graph = dsg.DynamicSceneGraph()
    graph.set_labelspace(dsg.Labelspace(OBJECTS), 2, 0)
    graph.set_labelspace(dsg.Labelspace(ROOMS), 4, 0)
    rooms = max(2, objects // 100)
    side = 4
    places = []
    for r in range(rooms):
        room = dsg.RoomNodeAttributes()
        room.semantic_label = r % len(ROOMS)
        room.position = [12.0 * r + 6, 6.0, 0.0]
        graph.add_node(dsg.DsgLayers.ROOMS, dsg.NodeSymbol("R", r).value, room)
        for i in range(side):
            for j in range(side):
                number = len(places)
                place = dsg.PlaceNodeAttributes()
                place.position = [12.0 * r + 3 * i, 3.0 * j, 0.0]
                node = dsg.NodeSymbol("p", number).value
                graph.add_node(dsg.DsgLayers.PLACES, node, place)
                graph.insert_edge(node, dsg.NodeSymbol("R", r).value)
                if j:
                    graph.insert_edge(node, dsg.NodeSymbol("p", number - 1).value)
                if i:
                    graph.insert_edge(node, dsg.NodeSymbol("p", number - side).value)
                places.append((node, place.position))
        if r:  # a door to the room before: the last column of one to the first of the next
            graph.insert_edge(places[-side * side][0], places[-side * side - side][0])
    _add_objects(graph, dsg, rng, objects, places)
    graph.save(str(path), include_mesh=False)


def _add_objects(graph, dsg, rng: random.Random, objects: int, places: list) -> None:
    holders = []
    kitchen = {node for node, _ in places[:16]}
    for index in range(objects):
        attributes = dsg.ObjectNodeAttributes()
        if index % 4 == 0 or not holders:
            label = rng.choice(HOLDERS + (8,))
            place, at = rng.choice(places)
            position = [at[0] + 0.5, at[1] + 0.5, 0.5]
            attributes.bounding_box = dsg.BoundingBox([1.0, 1.0, 1.0], position)
            if label != 8:
                holders.append((place, position))
        else:
            place, below = rng.choice(holders)
            # no cup in the kitchen (room 0, whose places come first): the goal is not met at the start
            label = rng.choice(ITEMS[1:] if place in kitchen else ITEMS)
            position = [below[0], below[1], 0.9]
        attributes.semantic_label = label
        attributes.position = position
        node = dsg.NodeSymbol("O", index).value
        graph.add_node(dsg.DsgLayers.OBJECTS, node, attributes)
        graph.insert_edge(place, node)


def measure_graph(objects: int, seed: int, timeout: float, folder: Path) -> list:
    from relevance_plan.planning.options import PlanOptions
    from relevance_plan.scene_graphs.importer import DOMAIN_FILE, ImportOptions, import_scene, read_graph

    graph_path = folder / f"graph-{objects}-{seed}.json"
    build_graph(objects, seed, graph_path)
    laps = base.Laps()
    options = ImportOptions(start="p(0)")
    result = import_scene(read_graph(str(graph_path), options), ["bring a cup to the kitchen"], options, "bench")
    laps.lap("import")
    problem = folder / f"problem-{objects}-{seed}.pddl"
    problem.write_text(result.text)
    plan_options = PlanOptions(timeout=timeout, race=False)
    _, relevance = base.run_method(DOMAIN_FILE, problem, plan_options)
    _, pure = base.run_method(DOMAIN_FILE, problem, replace(plan_options, method="pure"))
    return [
        len(result.scene.objects),
        f"{laps.times['import']:.2f}",
        base.show_time(relevance, timeout),
        base.show_time(pure, timeout),
        base.speedup(pure, relevance, validated=True),
        f"{relevance.first_kept} of {relevance.total}",
    ]


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        description=__doc__.splitlines()[0] + " Takes up to twice --timeout per graph (the unpruned run takes"
        " the whole of it past a few hundred objects)."
    )
    parser.add_argument("--objects", type=int, nargs="+", default=[1000, 3000], help="objects per graph")
    parser.add_argument("--seeds", type=int, default=1, help="graphs per size")
    parser.add_argument("--timeout", type=float, default=120.0, help="seconds per planning run")
    args = parser.parse_args(argv)
    base.table_header("graph objects | PDDL objects | import s | relevance s | pure s | pure / relevance | kept first")
    with tempfile.TemporaryDirectory(prefix="bench-hydra-") as scratch:
        for objects in args.objects:
            for seed in range(args.seeds):
                base.progress(f"{objects} objects, seed {seed}")
                base.table_row(objects, *measure_graph(objects, seed, args.timeout, Path(scratch)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
