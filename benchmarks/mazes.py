"""Mazes with movable obstacles larger than any published, for Flax's MazeNamo domain, solvable by construction.

Flax's MazeNamo cells stop at 15x15.  ``maze_problem(size, level, seed, index)``
writes a problem of any size for the corpus's MazeNamo domain
(``corpus/flax/mazenamo_problems/domain.pddl``, pinned at Flax's commit) in the
same vocabulary: a square grid whose border is wall, a robot with a heading,
walls (obstacles that cannot move), heavy boxes (pushed only) and light boxes
(lifted, carried, put down or stacked on a heavy one), and the goal of the
robot standing on one cell.

How a problem is made, every draw from one seeded generator:

1. a route from a start cell near one corner to a goal cell near the opposite
   one, the cheapest under random cell costs (so it bends);
2. ``OBSTACLES_ON_ROUTE[level]`` boxes placed *on* the route where they can be
   cleared: a light box anywhere (lift it, step in, put it down behind), a
   heavy box where the route turns, with the cell straight beyond it kept free
   (push it there, then turn);
3. every other cell drawn at random: wall, heavy box, light box or free
   (``FILL``).

As a script (it takes well under a second a maze):
``python benchmarks/mazes.py 25 out/mazes --level expert --count 5 --seed 0``.

Step 2 is why a plan exists: ``witness_plan`` writes one (the route walked,
each placed box cleared as above), so a test checks solvability with a
validator instead of trusting the argument.  The route is not the only way:
the fill leaves other paths, some through boxes, as Flax's mazes do.
"""

from __future__ import annotations

import hashlib
import heapq
import random
from dataclasses import dataclass
from pathlib import Path

LEVELS = ("easy", "medium", "hard", "expert")
OBSTACLES_ON_ROUTE = {"easy": 0, "medium": 2, "hard": 4, "expert": 7}
FILL = (("wall", 0.30), ("heavy", 0.10), ("light", 0.14))  # the rest of the off-route cells is free
GENERATOR_VERSION = "1"
DOMAIN_NAME = "mazenamo"

# Headings: (row step, column step) and the domain's word for them.
STEPS = {"Up": (-1, 0), "Down": (1, 0), "Left": (0, -1), "Right": (0, 1)}
TURNED_LEFT = {"Up": "Left", "Left": "Down", "Down": "Right", "Right": "Up"}
TURNED_RIGHT = {after: before for before, after in TURNED_LEFT.items()}
OPPOSITE = {"Up": "Down", "Down": "Up", "Left": "Right", "Right": "Left"}
LINKS = {"Up": "upTo", "Down": "downTo", "Left": "leftTo", "Right": "rightTo"}  # (LINK a b): a lies that way of b

Cell = tuple[int, int]
DOMAIN = Path(__file__).resolve().parent / "corpus" / "flax" / "mazenamo_problems" / "domain.pddl"


@dataclass(frozen=True)
class Maze:
    """A drawn maze: what stands on each cell, the robot, the goal, and the route the witness plan walks."""

    size: int
    contents: dict[Cell, str]  # wall, heavy or light; a cell not in it is free
    start: Cell
    heading: str
    goal: Cell
    route: tuple[Cell, ...]

    def position(self, cell: Cell) -> str:
        return f"p{cell[0] * self.size + cell[1]}"

    def obstacle(self, cell: Cell) -> str:
        return f"o{cell[0] * self.size + cell[1]}"


def maze_rng(size: int, level: str, seed: int, index: int) -> random.Random:
    key = f"mazes/{GENERATOR_VERSION}/{size}/{level}/{seed}/{index}".encode()
    return random.Random(int.from_bytes(hashlib.sha256(key).digest()[:16], "big"))


def heading_between(a: Cell, b: Cell) -> str:
    step = (b[0] - a[0], b[1] - a[1])
    return next(name for name, delta in STEPS.items() if delta == step)


def ahead(cell: Cell, heading: str) -> Cell:
    delta = STEPS[heading]
    return (cell[0] + delta[0], cell[1] + delta[1])


def _cheapest_route(rng: random.Random, size: int, start: Cell, goal: Cell) -> list[Cell]:
    """The cheapest inner-cell path from start to goal under random costs of 1 to 6 a cell."""
    inner = [(row, col) for row in range(1, size - 1) for col in range(1, size - 1)]
    cost = {cell: rng.randint(1, 6) for cell in inner}
    best, previous = {start: 0}, {}
    queue = [(0, start)]
    while queue:
        spent, cell = heapq.heappop(queue)
        if cell == goal:
            break
        if spent > best[cell]:
            continue
        for heading in STEPS:
            nxt = ahead(cell, heading)
            if nxt in cost and spent + cost[nxt] < best.get(nxt, 1 << 30):
                best[nxt] = spent + cost[nxt]
                previous[nxt] = cell
                heapq.heappush(queue, (best[nxt], nxt))
    route = [goal]
    while route[-1] != start:
        route.append(previous[route[-1]])
    return route[::-1]


def _corner_cell(rng: random.Random, size: int, far: bool) -> Cell:
    reach = max(1, (size - 2) // 4)
    low, high = (size - 1 - reach, size - 2) if far else (1, reach)
    return (rng.randint(low, high), rng.randint(low, high))


def _place_on_route(rng: random.Random, route: list[Cell], count: int, inside: set[Cell]) -> tuple[dict, set]:
    """Up to ``count`` boxes on the route that can be cleared; returns them and the cells kept free for them."""
    on_route = set(route)
    placed: dict[Cell, str] = {}
    kept_free: set[Cell] = set()
    for index in rng.sample(range(2, len(route) - 1), len(route) - 3):
        if len(placed) >= count:
            break
        cell = route[index]
        if any(route[index + offset] in placed for offset in (-1, 1)):
            continue  # one box at a time: the cells either side stay free
        coming = heading_between(route[index - 1], cell)
        beyond = ahead(cell, coming)
        turns = coming != heading_between(cell, route[index + 1])
        if turns and beyond in inside and beyond not in on_route and beyond not in kept_free and rng.random() < 0.6:
            placed[cell] = "heavy"
            kept_free.add(beyond)
        else:
            placed[cell] = "light"
    return placed, kept_free


def check_maze(size: int, level: str) -> None:
    """ValueError for a size or level no maze has."""
    if size < 6:
        raise ValueError(f"size {size}: a maze needs at least 6 cells a side")
    if level not in OBSTACLES_ON_ROUTE:
        raise ValueError(f"level {level!r}: choose one of {', '.join(LEVELS)}")


def draw_maze(size: int, level: str, seed: int, index: int) -> Maze:
    """Maze ``index`` of (size, level, seed); the same arguments give the same maze."""
    check_maze(size, level)
    rng = maze_rng(size, level, seed, index)
    start, goal = _corner_cell(rng, size, far=False), _corner_cell(rng, size, far=True)
    route = _cheapest_route(rng, size, start, goal)
    inside = {(row, col) for row in range(1, size - 1) for col in range(1, size - 1)}
    contents, kept_free = _place_on_route(rng, route, OBSTACLES_ON_ROUTE[level], inside)
    reserved = set(route) | kept_free
    for row in range(size):
        for col in range(size):
            cell = (row, col)
            if cell not in inside:
                contents[cell] = "wall"
            elif cell not in reserved:
                draw, threshold = rng.random(), 0.0
                for kind, share in FILL:
                    threshold += share
                    if draw < threshold:
                        contents[cell] = kind
                        break
    return Maze(size, contents, start, rng.choice(list(STEPS)), goal, tuple(route))


def problem_text(maze: Maze, name: str) -> str:
    """The maze as a MazeNamo problem (objects, links both ways, obstacles' facts, the goal)."""
    size, cells = maze.size, [(row, col) for row in range(maze.size) for col in range(maze.size)]
    objects = ["r - robot"] + [f"{maze.position(cell)} - pos" for cell in cells]
    objects += [f"{maze.obstacle(cell)} - obstacle" for cell in cells if cell in maze.contents]
    facts = [f"(rAt r {maze.position(maze.start)})", "(handempty)", f"(dirIs{maze.heading} r)"]
    for cell in cells:
        kind = maze.contents.get(cell)
        if kind is None:
            facts.append(f"(posEmpty {maze.position(cell)})")
            continue
        thing = maze.obstacle(cell)
        facts.append(f"(oAt {thing} {maze.position(cell)})")
        if kind != "wall":
            facts += [f"(is{kind.title()} {thing})", f"(isMoveable {thing})", f"(onGround {thing})", f"(clear {thing})"]
    for cell in cells:
        for heading, link in LINKS.items():
            other = ahead(cell, heading)
            if 0 <= other[0] < size and 0 <= other[1] < size:
                facts.append(f"({link} {maze.position(other)} {maze.position(cell)})")
    lines = [f"; {name}: a {size}x{size} maze for Flax's MazeNamo domain, solvable by construction"]
    lines += [f"(define (problem {name})", f"    (:domain {DOMAIN_NAME})", "    (:objects"]
    lines += [f"        {item}" for item in objects]
    lines += ["    )", "    (:init"] + [f"        {fact}" for fact in facts] + ["    )"]
    lines += ["    (:goal (and", f"        (rAt r {maze.position(maze.goal)})", "    ))", ")"]
    return "\n".join(lines) + "\n"


def witness_plan(maze: Maze) -> list[str]:
    """A plan along the route: walk it, lift each light box and put it down behind, push each heavy one aside."""
    plan: list[str] = []
    heading = maze.heading

    def face(wanted: str) -> None:
        nonlocal heading
        while heading != wanted:
            turn = "Right" if TURNED_RIGHT[heading] == wanted else "Left"
            plan.append(f"(turn{turn}When{heading} r)")
            heading = TURNED_RIGHT[heading] if turn == "Right" else TURNED_LEFT[heading]

    for here, there in zip(maze.route, maze.route[1:]):
        face(heading_between(here, there))
        p1, p2 = maze.position(here), maze.position(there)
        kind = maze.contents.get(there)
        if kind == "heavy":
            p3 = maze.position(ahead(there, heading))
            plan.append(f"(pushObstacleWhen{heading} r {maze.obstacle(there)} {p1} {p2} {p3})")
            continue
        if kind == "light":
            plan.append(f"(pickUpFromGroundWhen{heading} r {maze.obstacle(there)} {p1} {p2})")
        plan.append(f"(moveForwardWhen{heading} r {p1} {p2})")
        if kind == "light":
            face(OPPOSITE[heading])
            plan.append(f"(placeOnGroundWhen{heading} r {maze.obstacle(there)} {p2} {p1})")
    return plan


def write_mazes(folder: Path, domain: Path, size: int, level: str, seed: int, count: int) -> list[Path]:
    """``count`` mazes of (size, level, seed) as problem files in ``folder`` beside a copy of ``domain``;
    each with its witness plan (``NAME.witness.plan``).  The folder must be new or empty (a scratch folder)."""
    check_maze(size, level)  # before anything is written
    folder.mkdir(parents=True, exist_ok=True)
    if any(folder.iterdir()):
        raise ValueError(f"{folder}: not empty (mazes are written to a new folder)")
    (folder / "domain.pddl").write_bytes(domain.read_bytes())
    paths = []
    for index in range(count):
        name = f"maze_{size}x{size}_{level}_{seed}_{index}"
        maze = draw_maze(size, level, seed, index)
        path = folder / f"{name}.pddl"
        path.write_text(problem_text(maze, name), encoding="utf-8")
        (folder / f"{name}.witness.plan").write_text("\n".join(witness_plan(maze)) + "\n", encoding="utf-8")
        paths.append(path)
    return paths


def main() -> int:
    import argparse

    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("size", type=int, help="cells a side (at least 6)")
    parser.add_argument("folder", type=Path, help="a new folder: the problems, their witness plans and the domain")
    parser.add_argument("--level", default="expert", choices=LEVELS)
    parser.add_argument("--count", type=int, default=5)
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args()
    try:
        paths = write_mazes(args.folder, DOMAIN, args.size, args.level, args.seed, args.count)
    except ValueError as error:
        parser.error(str(error))
    print(f"wrote {len(paths)} mazes to {args.folder}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
