"""What the goal's analysis and the reachability repair read (for a caller that keeps their results),
and the distances from a growing set of sources."""

from __future__ import annotations

import random

import pytest

from relevance_plan.data import DOMAINS_DIR
from relevance_plan.generators import WORLDS, Settings
from relevance_plan.io import load_domain
from relevance_plan.pddl.parser import read_problem
from relevance_plan.relevance.analysis.distances import GrowingDistances, ObjectGraph, graph_distances
from relevance_plan.relevance.analysis.facts import fan_in
from relevance_plan.relevance.analysis.goal_regression import analyse_goal, analyse_goal_reading
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.selection.repair import REPAIR_MAX_FAN
from relevance_plan.relevance.setup import ScoringOptions, score_problem
from relevance_plan.session.state import LiveIndex


def scenegraph_task(size: int, seed: int, **fields) -> PlanningTask:
    domain = load_domain(DOMAINS_DIR / "scenegraph" / "domain.pddl")
    problem = read_problem(WORLDS["scenegraph"].problem(seed, 1, Settings(size=size)).pddl_text, domain)
    return PlanningTask(domain, problem, **fields)


def test_growing_distances_equal_a_walk_from_all_the_sources_at_once():
    task = scenegraph_task(400, 3)
    index = task.init_index
    graph = ObjectGraph(index, REPAIR_MAX_FAN, fan_in(index))
    growing = GrowingDistances(index, graph, task.hub_degree)
    rng = random.Random(3)
    names = sorted(task.problem.objects)
    sources: set[str] = set()
    for _ in range(12):
        sources |= set(rng.sample(names, 3))
        assert growing(sources) == graph_distances(index, graph, sources, task.hub_degree)
    fewer = set(rng.sample(sorted(sources), 2))  # not a superset: walked afresh
    assert growing(fewer) == graph_distances(index, graph, fewer, task.hub_degree)


def test_a_hub_is_walked_through_only_as_a_source():
    task = scenegraph_task(300, 5)
    index = task.init_index
    graph = ObjectGraph(index)
    room = next(name for name, kind in task.problem.objects.items() if kind == "room")
    hub = len(index.by_object[room]) - 1  # the room is a hub, its places are not
    start = index.by_object[room][0][1]  # one of its places
    growing = GrowingDistances(index, graph, hub)
    assert growing([start]) == graph_distances(index, graph, [start], hub)
    assert growing([start, room]) == graph_distances(index, graph, [start, room], hub)
    assert len(growing([start, room])) > len(graph_distances(index, graph, [start], hub))


def test_the_analysis_says_which_patterns_it_asked_about():
    task = scenegraph_task(200, 1)
    typing = task.typing
    analysis, reads = analyse_goal_reading(typing.domain, typing.problem, task.init_index)
    assert analysis == analyse_goal(typing.domain, typing.problem, task.init_index)
    objects, index, domain = task.problem.objects, task.init_index, typing.domain
    goal_item = sorted(task.goal_objects & {n for n, t in objects.items() if t == "item"})[0]
    holder = next(atom for atom in index.by_object[goal_item] if atom[0] == "in")
    elsewhere = next(atom for atom in index.by_predicate["in"] if atom[2] != holder[2])
    other = (elsewhere[0], elsewhere[1], holder[2])  # an item the goal does not name, put where the goal item is
    assert not reads.answers_change(domain, objects.__getitem__, index, [other], [])
    # the goal item gone from its receptacle: nothing satisfies "it is in some receptacle" any more
    live = LiveIndex(task.problem.init)
    live.discard(holder)
    assert reads.answers_change(domain, objects.__getitem__, live, [], [holder])
    assert {"agent-at", "in"} <= reads.role_predicates


@pytest.mark.parametrize("size", [150, 600])
def test_the_repair_shows_its_observer_what_it_read_and_keeps_its_result(size):
    seen = []
    observed = scenegraph_task(size, 2, repair_observer=lambda kept, repaired, reads: seen.append((kept, reads)))
    plain = scenegraph_task(size, 2)
    first = score_problem(observed, ScoringOptions()).first_selection()
    assert first.kept == score_problem(plain, ScoringOptions()).first_selection().kept
    assert first.restored == score_problem(plain, ScoringOptions()).first_selection().restored
    (kept, reads), *_ = seen
    assert reads.objects is not None and kept <= reads.objects and first.kept <= reads.objects
    assert reads.ranked  # the draft does not reach the goal: the repair ranked objects to grow it
    assert len(reads.objects) < len(plain.problem.objects) / 2  # items in receptacles are never ranked
