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
    python benchmarks/bench_hydra.py --live 30 --objects 1000 3000

``--live UPDATES`` measures the live session instead: the graph saved again after each move of one
item, fed to ``scene-graph watch``'s session (``GraphSession``) update by update; a row gives the
whole update's time (read, import, diff, the events), the session's time per event, the same events
handed as a PDDL event stream to a plain ``Session`` on the imported problem, and after how many
updates the kept set equals ``prune``'s on that graph imported afresh.

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


def _moved(graph, dsg, rng: random.Random, holders: list) -> None:
    """One item of the graph moved onto another holder (a new place edge and position), as a robot's
    perception reports an object it saw elsewhere."""
    items = [node for node in graph.get_layer(dsg.DsgLayers.OBJECTS).nodes if node.attributes.semantic_label in ITEMS]
    item = rng.choice(items)
    label, node_id = item.attributes.semantic_label, item.id.value
    place, below = rng.choice(holders)
    graph.remove_node(node_id)
    attributes = dsg.ObjectNodeAttributes()
    attributes.semantic_label = label
    attributes.position = [below[0], below[1], 0.9]
    graph.add_node(dsg.DsgLayers.OBJECTS, node_id, attributes)
    graph.insert_edge(place, node_id)


def _holders(graph, dsg) -> list:
    """(place, position) of every object items can stand on or in."""
    found = []
    for node in graph.get_layer(dsg.DsgLayers.OBJECTS).nodes:
        if node.attributes.semantic_label in HOLDERS:
            found.append((node.get_parent(), list(node.attributes.position)))
    return found


def measure_live(objects: int, seed: int, updates: int, folder: Path) -> list:
    """A live session fed ``updates`` successive graphs (one item moved in each): per update the whole
    step (read, import, diff, events), per event the session's own time against the same events as a PDDL
    event stream on a plain session; after each update the kept set against ``prune`` on that graph."""
    import time

    import numpy as np
    import spark_dsg as dsg

    from relevance_plan.relevance.setup import ScoringOptions
    from relevance_plan.scene_graphs.importer import DOMAIN_FILE, ImportOptions
    from relevance_plan.scene_graphs.live import GraphSession, file_updates, scene_events
    from relevance_plan.session import Session

    first = folder / f"live-{objects}-{seed}-0.json"
    build_graph(objects, seed, first)
    graph = dsg.DynamicSceneGraph.load(str(first))
    rng, holders, paths = random.Random(seed), _holders(graph, dsg), [first]
    for number in range(1, updates + 1):
        _moved(graph, dsg, rng, holders)
        paths.append(folder / f"live-{objects}-{seed}-{number}.json")
        graph.save(str(paths[-1]), include_mesh=False)
    goals, options = ["bring a cup to the kitchen"], ImportOptions(start="p(0)")
    live = GraphSession(goals, options, ScoringOptions())
    step_ms, graph_event_ms, pddl_event_ms, same = [], [], [], 0
    plain = None
    for update, path in zip(file_updates([str(p) for p in paths]), paths):
        before = live.scene
        started = time.perf_counter()
        lines = live.apply(update)
        elapsed = time.perf_counter() - started
        assert "error" not in lines[-1], lines[-1]
        if plain is None:
            plain = Session(str(DOMAIN_FILE), live.session.scene.problem_text(), ScoringOptions())
            live.session.handle = _timed(live.session.handle, graph_event_ms)
        else:
            step_ms.append(elapsed * 1000)
            for event in scene_events(before, live.scene):
                began = time.perf_counter()
                plain.handle(event)
                pddl_event_ms.append((time.perf_counter() - began) * 1000)
        same += live.session.kept == _prune_kept(path, goals, options)
    return [
        len(live.scene.objects),
        f"{np.median(step_ms):.0f} / {np.percentile(step_ms, 95):.0f}",
        len(pddl_event_ms),
        f"{np.median(graph_event_ms):.1f} / {np.percentile(graph_event_ms, 95):.1f}",
        f"{np.median(pddl_event_ms):.1f} / {np.percentile(pddl_event_ms, 95):.1f}",
        f"{same} of {len(paths)}",
    ]


def _timed(handle, laps: list[float]):
    """``handle`` that also appends its milliseconds to ``laps``."""
    import time

    def timed(event):
        began = time.perf_counter()
        try:
            return handle(event)
        finally:
            laps.append((time.perf_counter() - began) * 1000)

    return timed


def _prune_kept(path: Path, goals: list[str], options) -> frozenset[str]:
    """What ``prune`` keeps on the graph at ``path`` imported afresh."""
    from relevance_plan.io import load_domain
    from relevance_plan.pddl.parser import read_problem
    from relevance_plan.relevance.analysis.task import PlanningTask
    from relevance_plan.relevance.setup import ScoringOptions, score_problem
    from relevance_plan.scene_graphs.importer import DOMAIN_FILE, import_scene, read_graph

    result = import_scene(read_graph(str(path), options), goals, options, "live")
    domain = load_domain(DOMAIN_FILE)
    task = PlanningTask(domain, read_problem(result.text, domain))
    return score_problem(task, ScoringOptions()).first_selection().kept


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        description=__doc__.splitlines()[0] + " Takes up to twice --timeout per graph (the unpruned run takes"
        " the whole of it past a few hundred objects)."
    )
    parser.add_argument("--objects", type=int, nargs="+", default=[1000, 3000], help="objects per graph")
    parser.add_argument("--seeds", type=int, default=1, help="graphs per size")
    parser.add_argument("--timeout", type=float, default=120.0, help="seconds per planning run")
    parser.add_argument(
        "--live",
        type=int,
        default=0,
        metavar="UPDATES",
        help="instead: a live session fed UPDATES successive graphs (one item moved in each) per size",
    )
    args = parser.parse_args(argv)
    if args.live:
        base.table_header(
            "graph objects | PDDL objects | update ms (median / p95) | events | graph stream ms an event"
            " (median / p95) | PDDL stream ms an event (median / p95) | kept = prune"
        )
        with tempfile.TemporaryDirectory(prefix="bench-hydra-live-") as scratch:
            for objects in args.objects:
                for seed in range(args.seeds):
                    base.progress(f"live, {objects} objects, seed {seed}")
                    base.table_row(objects, *measure_live(objects, seed, args.live, Path(scratch)))
        return 0
    base.table_header("graph objects | PDDL objects | import s | relevance s | pure s | pure / relevance | kept first")
    with tempfile.TemporaryDirectory(prefix="bench-hydra-") as scratch:
        for objects in args.objects:
            for seed in range(args.seeds):
                base.progress(f"{objects} objects, seed {seed}")
                base.table_row(objects, *measure_graph(objects, seed, args.timeout, Path(scratch)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
