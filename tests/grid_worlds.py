"""A maze with movable obstacles, small enough for a test: every cell is linked to its neighbours.

A robot walks between empty cells along static links, one predicate per direction (each cell
has one neighbour each way, as in Flax's MazeNamo), and can push an obstacle one cell on into
an empty cell; the goal puts the robot in a far corner.  Generated here (not a benchmark's
file) so that tests can place obstacles and rename every symbol.
"""

from __future__ import annotations

DIRECTIONS = {"north": (0, -1), "south": (0, 1), "east": (1, 0), "west": (-1, 0)}


def _grid_domain() -> str:
    """Per direction a static link (each cell has one neighbour that way), a walk and a push."""
    links = " ".join(f"({d} ?a - cell ?b - cell)" for d in DIRECTIONS)
    actions = []
    for d in DIRECTIONS:
        actions.append(
            f"""  (:action walk-{d}
    :parameters (?r - robot ?from - cell ?to - cell)
    :precondition (and (robot-at ?r ?from) ({d} ?from ?to) (empty ?to))
    :effect (and (robot-at ?r ?to) (not (robot-at ?r ?from))))
  (:action push-{d}
    :parameters (?r - robot ?o - obstacle ?from - cell ?via - cell ?to - cell)
    :precondition (and (robot-at ?r ?from) (obstacle-at ?o ?via) ({d} ?from ?via) ({d} ?via ?to) (empty ?to))
    :effect (and (robot-at ?r ?via) (not (robot-at ?r ?from)) (obstacle-at ?o ?to)
                 (not (obstacle-at ?o ?via)) (empty ?via) (not (empty ?to))))"""
        )
    return f"""(define (domain pushgrid)
  (:requirements :strips :typing)
  (:types cell robot obstacle)
  (:predicates {links}
               (robot-at ?r - robot ?c - cell) (obstacle-at ?o - obstacle ?c - cell) (empty ?c - cell))
{chr(10).join(actions)})
"""


GRID_DOMAIN = _grid_domain()


def cell(x: int, y: int) -> str:
    return f"c{x}-{y}"


def grid_problem(
    size: int, obstacles: dict[tuple[int, int], str] | None = None, goal: tuple[int, int] | None = None
) -> str:
    """A ``size`` x ``size`` grid, the robot at (0, 0), ``obstacles`` (cell -> name) placed, the goal
    the robot at ``goal`` (default: the opposite corner)."""
    obstacles = obstacles or {}
    goal = goal or (size - 1, size - 1)
    cells = [(x, y) for y in range(size) for x in range(size)]
    init = ["(robot-at bot c0-0)"]
    for x, y in cells:
        if (x, y) in obstacles:
            init.append(f"(obstacle-at {obstacles[(x, y)]} {cell(x, y)})")
        elif (x, y) != (0, 0):
            init.append(f"(empty {cell(x, y)})")
        for direction, (dx, dy) in DIRECTIONS.items():
            nx, ny = x + dx, y + dy
            if 0 <= nx < size and 0 <= ny < size:
                init.append(f"({direction} {cell(x, y)} {cell(nx, ny)})")
    objects = " ".join(cell(x, y) for x, y in cells) + " - cell bot - robot"
    if obstacles:
        objects += " " + " ".join(sorted(obstacles.values())) + " - obstacle"
    return (
        f"(define (problem grid-{size}) (:domain pushgrid) (:objects {objects})"
        f" (:init {' '.join(init)}) (:goal (robot-at bot {cell(*goal)})))"
    )


# Obstacles across the middle row but one gap, so that the way to the goal must turn.
def wall_with_gap(size: int, gap: int) -> dict[tuple[int, int], str]:
    row = size // 2
    return {(x, row): f"box{x}" for x in range(size) if x != gap}
