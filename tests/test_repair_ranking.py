"""The repair's ranking of candidates (a best-first search, as sorting every object) and its ways to goal objects."""

from __future__ import annotations

import random

import pytest

from relevance_plan.data import DOMAINS_DIR
from relevance_plan.generators import WORLDS, Settings
from relevance_plan.io import load_domain
from relevance_plan.pddl.parser import read_problem
from relevance_plan.relevance.analysis.distances import NearestBetween, ObjectGraph, graph_distances, walk_bounds
from relevance_plan.relevance.analysis.facts import fan_in
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.selection.repair import REPAIR_MAX_FAN, RepairOrder
from relevance_plan.relevance.setup import ScoringOptions, score_problem

# (world, size): a building, many-goal worlds with trucks and airplanes, the grid, temporal and numeric ones
CASES = [
    ("scenegraph", 500),
    ("logistics-manygoals", 120),
    ("miconic-manygoals-typed", 300),
    ("grid-typed", None),
    ("ferry", None),
    ("driverlog-temporal", 60),
    ("zenotravel-numeric", 60),
]


def sized_task(world: str, seed: int, size: int | None = None) -> PlanningTask:
    generated = WORLDS[world].problem(seed, 1, Settings(size=size))
    folder = WORLDS[world].domain
    domain = load_domain(DOMAINS_DIR / folder / "domain.pddl")
    return PlanningTask(domain, read_problem(generated.pddl_text, domain))


def sorted_by_sums(task: PlanningTask, graph, sources, targets, hub, far) -> list[tuple[int, str]]:
    """Every object both walks reach, sorted as the repair ranks them (sum, hops toward, name)."""
    index = task.init_index
    back = graph_distances(index, graph, sources, hub)
    toward = graph_distances(index, graph, targets, hub)
    keys = sorted((back[n] + toward[n], toward[n], n) for n in back.keys() & toward.keys())
    return [(toward, name) for total, toward, name in keys if total < far]


@pytest.mark.parametrize(("world", "size"), CASES)
@pytest.mark.parametrize("max_fan", [REPAIR_MAX_FAN, None])
def test_the_search_gives_the_objects_in_the_order_of_sorting_them_all(world, size, max_fan):
    task = sized_task(world, 4, size)
    index = task.init_index
    names = sorted(name for name, atoms in index.by_object.items() if any(len(atom) > 2 for atom in atoms))
    rng = random.Random(world)
    searched = 0
    for trial in range(24):
        graph = ObjectGraph(index, max_fan, fan_in(index))
        # the scene's own hub mark, one low enough that many objects are hubs, and none
        hub = [task.hub_degree, 2, None][trial % 3]
        sources = set(rng.sample(names, 1 + trial % 4))
        # targets a walk from the sources reaches, and one anywhere
        reached = sorted(graph_distances(index, graph, sources, hub))
        targets = set(rng.sample(reached, min(len(reached), trial % 3))) | {rng.choice(names)}
        toward = graph_distances(index, graph, targets, hub)
        bounds = walk_bounds(index, graph, targets, toward, hub)
        if trial % 2:  # the bounds toward more objects than the targets hold too
            more = targets | set(rng.sample(names, 2))
            bounds = walk_bounds(index, graph, more, graph_distances(index, graph, more, hub), hub)
        far = len(index.by_object) + 1
        search = NearestBetween(index, graph, sources, toward, bounds, hub, far)
        found = [item for group in search.groups() for item in sorted(group)]
        assert search.exhausted
        expected = sorted_by_sums(task, graph, sources, targets, hub, far)
        searched += bool(expected)
        assert found == expected
    assert searched >= 12


def test_the_bounds_grow_by_at_most_one_a_link_and_never_pass_the_walk():
    task = sized_task("scenegraph", 2, 600)
    index = task.init_index
    graph = ObjectGraph(index, REPAIR_MAX_FAN, fan_in(index))
    hub = task.hub_degree
    targets = {next(name for name, kind in task.problem.objects.items() if kind == "place")}
    toward = graph_distances(index, graph, targets, hub)
    bounds = walk_bounds(index, graph, targets, toward, hub)
    assert bounds.keys() == toward.keys()
    assert all(bounds[n] <= toward[n] for n in toward)
    assert any(bounds[n] < toward[n] for n in toward)  # a room nearer than some of its places
    for name in toward:
        if len(index.by_object.get(name, ())) > hub:
            continue
        for other in graph.neighbours(name):
            assert bounds[name] <= bounds[other] + 1


def without_search(monkeypatch):
    """The repair with every ranking made by sorting all objects, as before the search."""

    def exhausted(self):
        self.exhausted = True
        return iter(())

    monkeypatch.setattr(NearestBetween, "groups", exhausted)


@pytest.mark.parametrize(("world", "size"), CASES)
def test_the_repair_keeps_what_it_kept_when_every_ranking_sorted_all(world, size, monkeypatch):
    searches = []
    monkeypatch.setattr(NearestBetween, "groups", counted(NearestBetween.groups, searches))
    for seed in range(3):
        found = score_problem(sized_task(world, seed, size), ScoringOptions()).first_selection()
        with monkeypatch.context() as patched:
            without_search(patched)
            again = score_problem(sized_task(world, seed, size), ScoringOptions()).first_selection()
        assert found.kept == again.kept
        assert found.restored == again.restored
    if world in ("logistics-manygoals", "grid-typed"):
        assert searches  # the repair ranked by the search


def counted(groups, calls):
    def counting(self):
        calls.append(self)
        return groups(self)

    return counting


def building() -> tuple[PlanningTask, RepairOrder, str, str, str]:
    """A generated building, the repair's order on it, the robot's place, a receptacle there and
    the receptacle farthest from it."""
    task = sized_task("scenegraph", 3, 500)
    order = RepairOrder(task, {})
    index = task.init_index
    start = next(atom[2] for atom in index.by_predicate["agent-at"])
    hops = graph_distances(index, order.graph, [start], task.hub_degree)
    receptacles = sorted(name for name, kind in task.problem.objects.items() if kind == "receptacle")
    near = next(name for name in receptacles if ("receptacle-at", name, start) in task.problem.init)
    far = max((name for name in receptacles if name in hops), key=lambda name: (hops[name], name))
    return task, order, start, near, far


def test_a_way_through_a_door_brings_the_door():
    task, order, start, _, far = building()
    walk = order._path({far}, {start}, set())
    kinds = task.problem.objects
    places = [start] + [name for name in walk if kinds[name] == "place"]
    doors = {(atom[2], atom[3]): atom[1] for atom in task.init_index.by_predicate["door-between"]}
    crossed = [doors[step] for step in zip(places, places[1:]) if step in doors]
    assert crossed  # the way leaves the robot's room
    assert set(crossed) <= set(walk)


def test_a_goal_object_next_to_what_is_reached_does_not_hide_the_way_to_another():
    _, order, start, near, far = building()
    kept = {near}
    assert order._path({near}, {start}, kept) == []  # nothing to add on the way to the near one
    walk = order._path({near, far}, {start}, kept)
    assert walk and walk == order._path({far}, {start}, kept)


def missing_by_sorting(order: RepairOrder, kept: set[str]) -> list[str]:
    """The best member of each class ``kept`` lacks, every object ranked (score, hops from kept, name)."""
    present = {order.classes[name] for name in kept if name in order.classes}
    distance = graph_distances(order.task.init_index, order.graph, kept, order.hub)
    far = len(order.classes) + 1
    best: dict[str, tuple[float, int, str]] = {}
    for name, cls in order.classes.items():
        if cls not in present:
            key = (-order.scores.get(name, 0.0), distance.get(name, far), name)
            best[cls] = min(best.get(cls, key), key)
    return sorted(key[2] for key in best.values())


@pytest.mark.parametrize(("world", "size"), CASES)
def test_the_members_of_missing_classes_are_those_ranking_every_object_gives(world, size):
    task = sized_task(world, 5, size)
    rng = random.Random(world)
    names = sorted(task.problem.objects)
    # scores with many ties (the hops decide among them), and the scorer's own
    coarse = {name: rng.choice([0.0, 0.0, 0.5]) for name in names}
    for scores in (coarse, score_problem(task, ScoringOptions()).scores.element_scores):
        order = RepairOrder(task, scores)
        for trial in range(6):
            kept = set(rng.sample(names, 1 + trial))
            assert order.missing_classes(kept) == missing_by_sorting(order, kept)
