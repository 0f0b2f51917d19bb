"""The benchmark's generated mazes: seeded, in MazeNamo's vocabulary, and solvable by the plan they come with."""

from __future__ import annotations

from pathlib import Path

import pytest
from mazes import draw_maze, problem_text, witness_plan, write_mazes

from relevance_plan import prune
from relevance_plan.io import load_domain, load_problem
from relevance_plan.pddl.plans import read_plan
from relevance_plan.planning.validation import ValidationStatus, validate_plan

DOMAIN = Path(__file__).resolve().parent.parent / "benchmarks" / "corpus" / "flax" / "mazenamo_problems" / "domain.pddl"


def test_the_same_arguments_draw_the_same_maze_and_others_another():
    assert problem_text(draw_maze(12, "expert", 1, 0), "m") == problem_text(draw_maze(12, "expert", 1, 0), "m")
    assert problem_text(draw_maze(12, "expert", 1, 0), "m") != problem_text(draw_maze(12, "expert", 1, 1), "m")


@pytest.mark.parametrize("size,level", [(8, "expert"), (14, "hard"), (22, "expert")])
def test_every_maze_is_solved_by_its_witness_plan_on_the_problem_written(tmp_path, size, level):
    paths = write_mazes(tmp_path / "mazes", DOMAIN, size, level, 5, 2)
    domain = load_domain(tmp_path / "mazes" / "domain.pddl")
    for path in paths:
        problem = load_problem(path, domain)
        assert len(problem.objects) > size * size  # every cell, the robot and the obstacles
        plan = read_plan(path.with_suffix(".witness.plan").read_text())
        assert validate_plan(domain, problem, plan, ["builtin"]).status is ValidationStatus.VALID, path.name


def test_the_boxes_placed_on_the_route_must_be_moved_by_the_witness_plan():
    maze = draw_maze(16, "expert", 2, 0)
    on_route = [cell for cell in maze.route if cell in maze.contents]
    assert on_route and all(maze.contents[cell] in ("heavy", "light") for cell in on_route)
    moves = [step for step in witness_plan(maze) if step.startswith(("(push", "(pickUp"))]
    assert len(moves) == len(on_route)


def test_a_folder_holding_files_is_not_written_to(tmp_path):
    (tmp_path / "mine.txt").write_text("a user's file")
    with pytest.raises(ValueError, match="not empty"):
        write_mazes(tmp_path, DOMAIN, 8, "easy", 0, 1)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["mine.txt"]


def test_the_first_selection_of_a_generated_maze_keeps_a_way_not_the_grid(tmp_path):
    (path,) = write_mazes(tmp_path / "mazes", DOMAIN, 12, "expert", 1, 1)
    result = prune(tmp_path / "mazes" / "domain.pddl", path)
    assert len(result.kept) < len(load_problem(path, load_domain(DOMAIN)).objects) / 3
