"""Worlds where everything is linked: the first selection follows the way, not the whole grid."""

from __future__ import annotations

import re

import pytest
from grid_worlds import GRID_DOMAIN, cell, grid_problem, wall_with_gap

from relevance_plan import api
from relevance_plan.pddl.parser import read_domain, read_problem
from relevance_plan.relevance.analysis.network import NETWORK_MIN_OBJECTS
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.selection.closure import ConstraintClosure
from relevance_plan.relevance.selection.neighbourhood import next_ring, ring
from relevance_plan.relevance.selection.prune import Widening, alternative_route, widen


def task_of(problem_text: str, domain_text: str = GRID_DOMAIN) -> PlanningTask:
    domain = read_domain(domain_text)
    return PlanningTask(domain, read_problem(problem_text, domain))


def test_the_grid_links_are_found_as_a_network_and_nothing_else_is():
    task = task_of(grid_problem(6, wall_with_gap(6, 4)))
    assert task.network.predicates == {"north", "south", "east", "west"}
    assert task.network.members == {cell(x, y) for x in range(6) for y in range(6)}


def test_a_few_linked_objects_are_no_network():
    # a 3 x 3 grid links 9 cells: too few to be a network, so closure follows its links as before
    task = task_of(grid_problem(3))
    assert 9 < NETWORK_MIN_OBJECTS
    assert not task.network


def test_the_first_selection_keeps_a_route_not_the_grid():
    problem = grid_problem(8)
    selection = api.prune(GRID_DOMAIN, problem, scorer="goal")
    cells = {name for name in selection.kept if name.startswith("c")}
    # a route from corner to corner has 15 cells; the grid has 64
    assert 15 <= len(cells) <= 20, sorted(cells)
    rules = {item.rule for item in selection.restored}
    assert "anchor" not in rules and "reachability" in rules


def test_an_obstacle_on_the_way_comes_back_with_a_cell_to_push_it_to():
    # a full wall of obstacles across row 4: the robot must push one of them on
    problem = grid_problem(8, {(x, 4): f"box{x}" for x in range(8)})
    selection = api.prune(GRID_DOMAIN, problem, scorer="goal")
    boxes = {name for name in selection.kept if name.startswith("box")}
    assert 1 <= len(boxes) <= 2, sorted(boxes)
    reasons = {item.name: item for item in selection.restored}
    assert all(reasons[box].rule == "reachability" for box in boxes)
    assert len(selection.kept) < 0.5 * len(selection.task.problem.objects)


def test_obstacles_off_the_way_stay_out():
    # the goal along the first row; the obstacles fill the last two rows
    obstacles = {(x, y): f"box{x}-{y}" for x in range(8) for y in (6, 7)}
    selection = api.prune(GRID_DOMAIN, grid_problem(8, obstacles, goal=(7, 0)), scorer="goal")
    assert not {name for name in selection.kept if name.startswith("box")}
    assert len(selection.kept) <= 10


def test_renamed_symbols_give_the_same_selection():
    problem = grid_problem(8, wall_with_gap(8, 3))
    words = {"north": "zz1", "south": "zz2", "east": "zz6", "west": "zz7", "robot-at": "zz3", "obstacle-at": "zz4"}
    words |= {"empty": "zz5", "cell": "tt1", "robot": "tt2", "obstacle": "tt3", "pushgrid": "dd"}

    def rename(text: str) -> str:
        text = re.sub(r"\bc(\d+)-(\d+)\b", r"node\2x\1", text)
        text = re.sub(r"\bbox(\d+)\b", r"thing\1", text)
        for old, new in words.items():
            text = re.sub(rf"(?<![\w-]){re.escape(old)}(?![\w])", new, text)
        text = text.replace("walk-", "qqa").replace("push-", "qqb")
        return text

    plain = api.prune(GRID_DOMAIN, problem, scorer="goal")
    renamed = api.prune(rename(GRID_DOMAIN), rename(problem), scorer="goal")
    assert len(renamed.kept) == len(plain.kept) < len(plain.task.problem.objects) // 2
    assert renamed.task.network.predicates == {"zz1", "zz2", "zz6", "zz7"}


def test_widening_in_a_network_adds_a_ring_not_the_double():
    problem = grid_problem(10)
    first = api.prune(GRID_DOMAIN, problem, scorer="goal")
    task = first.task
    around = ring(task, first.kept)
    assert around and not around & first.kept
    widened, _ = widen(first, Widening(0.5, step=0))
    assert first.kept < widened.kept
    assert widened.kept - first.kept <= around | {"bot"}
    assert len(widened.kept) < 2 * len(first.kept)


def test_odd_rings_bring_what_stands_on_the_kept_cells_and_even_ones_only_free_cells():
    problem = grid_problem(8, wall_with_gap(8, 6))
    task = task_of(problem)
    selection = api.prune(GRID_DOMAIN, problem, scorer="goal")
    assert {name for name in selection.kept if name.startswith("box")} == {"box0"}  # pushed down column 0
    closure = ConstraintClosure.of(task, None)
    walls = {cell(x, 4) for x in range(8) if x != 6}
    free = next_ring(task, closure, selection.kept, 0)
    assert free and not free & walls and not {name for name in free if name.startswith("box")}
    kept = selection.kept | {cell(3, 4)}  # a cell kept while its obstacle is pruned: a wall
    assert "box3" not in closure(kept)[0]  # closure leaves a network member's blocker to the repair
    full = next_ring(task, closure, kept, 1)
    assert {name for name in full if name.startswith("box")} == {"box3"}
    assert ring(task, kept) <= full


@pytest.mark.planner
def test_a_plan_through_a_maze_is_found_on_a_pruned_problem_and_valid_on_the_original():
    problem = grid_problem(9, wall_with_gap(9, 8))
    result = api.plan(GRID_DOMAIN, problem, timeout=60, race=False)
    assert result.status.value == "solved" and result.valid
    assert result.objects_kept < result.objects_total


def test_the_first_widening_adds_another_way_that_avoids_the_failed_one():
    selection = api.prune(GRID_DOMAIN, grid_problem(8), scorer="goal")
    task, first = selection.task, selection.kept
    other = alternative_route(selection, None)
    anchored = {arg for name in selection.selected for fact in task.init_index.by_object[name] for arg in fact[1:]}
    avoided = (first & task.network.members) - selection.selected - anchored
    assert avoided and other and not (other & avoided)
    # the other way reaches the goal corner from the start on cells of its own
    assert {cell(0, 0), cell(7, 7)} <= other | selection.selected | anchored
    widened, _ = widen(selection, Widening(0.5, step=0))
    assert other - first <= widened.kept and len(widened.kept) < len(task.problem.objects) / 2
