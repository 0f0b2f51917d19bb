"""Seeded many-object problems for classic planning domains, in their classic forms.

Six worlds, each in the untyped STRIPS form of the IPC (a type is a static
unary predicate such as ``(truck t1)``) and in a typed variant
(``<world>-typed``): blocksworld, logistics, gripper, ferry, grid (keys and
locks) and miconic.  Every problem has a goal on a few objects among hundreds
or thousands, the way the learned-object-importance literature pads them.
The domain files were written for this project (``data/domains/<world>``).

``generate_classic_problem(world, seed, index, size)`` is pure.  One builder
per domain returns an ``Instance``: objects with their class, the dynamic and
static facts, the goal atoms and, where a cheap sufficient set exists, the
objects a plan needs.  The untyped text adds one unary fact per class
(``TYPE_FACTS``); the typed text declares the class as the object's type.

Their suites (:func:`write_classic_suite`) have the same layout as the
kitchen suites: ``domain.pddl``, ``<world>-NNN.pddl`` with a ``.json``
sidecar each, and ``suite.json``.
"""

from __future__ import annotations

import functools
import hashlib
import math
import random
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, NamedTuple

from relevance_plan.data import DOMAINS_DIR
from relevance_plan.errors import UsageError
from relevance_plan.generators.generate import suite_manifest, write_suite
from relevance_plan.pddl.formatter import format_problem_parts
from relevance_plan.pddl.model import Metric
from relevance_plan.progress import ProgressCallback

GENERATOR = "relevance_plan.generators"
CLASSIC_VERSION = "1"

NO_GROUND_TRUTH = "no cheap ground truth for this domain: 'necessary' is omitted (the oracle does not apply)"
SUFFICIENT_NOTE = "'necessary' is a sufficient set built by the generator (a plan exists on it), not proven minimal"


@dataclass
class Instance:
    objects: dict[str, str] = field(default_factory=dict)  # name -> class, in declaration order
    facts: list[tuple] = field(default_factory=list)  # initial atoms (type facts are added for the untyped form)
    goal: list[tuple] = field(default_factory=list)
    necessary: list[str] | None = None
    untyped_only: list[tuple] = field(default_factory=list)  # facts only the untyped domain has (ferry's not-eq)
    values: dict[tuple, float] = field(default_factory=dict)  # numeric initial values: (function, args...) -> v
    metric: Metric | None = None

    def add(self, cls: str, name: str) -> str:
        self.objects[name] = cls
        return name


# Untyped form: the unary facts that stand for each class.
TYPE_FACTS: dict[str, dict[str, tuple[str, ...]]] = {
    "blocksworld": {"block": ()},
    "logistics": {
        "package": ("package",),
        "truck": ("truck",),
        "airplane": ("airplane",),
        "location": ("location",),
        "airport": ("location", "airport"),
        "city": ("city",),
    },
    "gripper": {"room": ("room",), "ball": ("ball",), "gripper": ("gripper",)},
    "ferry": {"car": ("car",), "location": ("location",)},
    "grid": {"place": ("place",), "key": ("key",), "shape": ("shape",)},
    "miconic": {"passenger": ("passenger",), "floor": ("floor",)},
}

# Object count of the default size: big enough that pure Fast Downward takes seconds to minutes.
DEFAULT_SIZES: dict[str, int] = {
    "blocksworld": 300,
    "logistics": 400,
    "gripper": 400,
    "ferry": 400,
    "grid": 400,
    "miconic": 3000,
}


def _blocksworld(rng: random.Random, size: int, dense: bool = False) -> Instance:
    """A goal tower over 3-4 blocks among ``size``; each goal block sits inside a pile."""
    inst = Instance()
    blocks = [inst.add("block", f"b{i}") for i in range(1, size + 1)]
    goal_count = rng.randint(3, 4)
    goal_blocks = rng.sample(blocks, goal_count)
    others = [b for b in blocks if b not in goal_blocks]
    rng.shuffle(others)
    towers: list[list[str]] = []
    while others:
        height = rng.randint(1, 6)
        towers.append(others[:height])
        others = others[height:]
    for block in goal_blocks:
        tower = rng.choice(towers)
        tower.insert(rng.randint(0, len(tower)), block)
    inst.facts.append(("handempty",))
    below: dict[str, str | None] = {}
    above: dict[str, list[str]] = {}
    for tower in towers:
        inst.facts.append(("ontable", tower[0]))
        below[tower[0]] = None
        for lower, upper in zip(tower, tower[1:]):
            inst.facts.append(("on", upper, lower))
            below[upper] = lower
        inst.facts.append(("clear", tower[-1]))
        for position, block in enumerate(tower):
            above[block] = tower[position + 1 :]
    if dense:
        order = rng.sample(blocks, len(blocks))
        inst.goal = [("on", order[i], order[i + 1]) for i in range(len(order) - 1) if (i + 1) % 5]
    else:
        inst.goal = [("on", upper, lower) for upper, lower in zip(goal_blocks, goal_blocks[1:])]
    needed = set(goal_blocks)
    for block in goal_blocks:
        needed.update(above[block])
        if (support := below[block]) is not None:
            needed.add(support)
    inst.necessary = sorted(needed)
    return inst


class LogisticsMap(NamedTuple):
    city_locations: dict[str, list[str]]  # the airport first
    airport_of: dict[str, str]
    trucks_in: dict[str, list[str]]
    truck_at: dict[str, str]


def logistics_map(rng: random.Random, inst: Instance, cities_count: int, per_city: int = 3) -> LogisticsMap:
    """Cities with an airport and ``per_city - 1`` more locations each, and 1-3 trucks per city."""
    city_locations: dict[str, list[str]] = {}
    airport_of: dict[str, str] = {}
    trucks_in: dict[str, list[str]] = {}
    truck_at: dict[str, str] = {}
    for c in range(1, cities_count + 1):
        city = inst.add("city", f"city{c}")
        airport = inst.add("airport", f"apt{c}")
        airport_of[city] = airport
        locations = [airport] + [inst.add("location", f"loc{c}-{j}") for j in range(1, per_city)]
        city_locations[city] = locations
        for location in locations:
            inst.facts.append(("in-city", location, city))
        trucks_in[city] = []
        for t in range(1, rng.randint(1, 3) + 1):
            truck = inst.add("truck", f"truck{c}-{t}")
            trucks_in[city].append(truck)
            truck_at[truck] = rng.choice(locations)
            inst.facts.append(("at", truck, truck_at[truck]))
    return LogisticsMap(city_locations, airport_of, trucks_in, truck_at)


def _logistics(rng: random.Random, size: int, dense: bool = False) -> Instance:
    """Tens of cities with trucks and an airport each, airplanes, a goal on 2-3 packages."""
    inst = Instance()
    cities_count = max(3, size // 20)
    airplanes_count = max(2, cities_count // 4)
    city_locations, airport_of, trucks_in, truck_at = logistics_map(rng, inst, cities_count)
    airplanes = []
    for a in range(1, airplanes_count + 1):
        plane = inst.add("airplane", f"plane{a}")
        airplanes.append(plane)
        inst.facts.append(("at", plane, rng.choice(list(airport_of.values()))))
    cities = list(city_locations)
    packages = max(3, size - len(inst.objects))
    where: dict[str, str] = {}
    for p in range(1, packages + 1):
        package = inst.add("package", f"pkg{p}")
        location = rng.choice(city_locations[rng.choice(cities)])
        where[package] = location
        inst.facts.append(("at", package, location))
    goal_packages = list(where) if dense else rng.sample(list(where), rng.randint(2, 3))
    city_of = {loc: city for city, locs in city_locations.items() for loc in locs}
    needed = set(goal_packages) | {airplanes[0]}
    for package in goal_packages:
        start_city = city_of[where[package]]
        target_city = rng.choice([c for c in cities if c != start_city])
        target = rng.choice(city_locations[target_city])
        inst.goal.append(("at", package, target))
        for city, location in ((start_city, where[package]), (target_city, target)):
            truck = trucks_in[city][0]
            needed.update({city, location, airport_of[city], truck, truck_at[truck]})
    plane_start = next(f[2] for f in inst.facts if f[0] == "at" and f[1] == airplanes[0])
    needed.add(plane_start)
    needed.add(city_of[plane_start])
    inst.necessary = sorted(needed)
    return inst


def _gripper(rng: random.Random, size: int, dense: bool = False) -> Instance:
    """Many rooms and balls; two grippers; 2-4 balls must go to given rooms."""
    inst = Instance()
    rooms = [inst.add("room", f"room{i}") for i in range(1, max(3, size // 4) + 1)]
    grippers = [inst.add("gripper", name) for name in ("left", "right")]
    balls = [inst.add("ball", f"ball{i}") for i in range(1, max(4, size - len(inst.objects)) + 1)]
    robby = rng.choice(rooms)
    inst.facts += [("at-robby", robby)] + [("free", g) for g in grippers]
    where = {}
    for ball in balls:
        where[ball] = rng.choice(rooms)
        inst.facts.append(("at", ball, where[ball]))
    needed = {robby, *grippers}
    _goal_moves(rng, inst, balls if dense else rng.sample(balls, rng.randint(2, 4)), where, rooms, needed)
    inst.necessary = sorted(needed)
    return inst


def _goal_moves(
    rng: random.Random,
    inst: Instance,
    movables: list[str],
    where: Mapping[str, str],
    places: list[str],
    needed: set[str],
) -> None:
    """A goal ``(at X target)`` for each of ``movables``, the target another of ``places``; the
    object, its place and its target are needed."""
    for thing in movables:
        target = rng.choice([place for place in places if place != where[thing]])
        inst.goal.append(("at", thing, target))
        needed.update({thing, where[thing], target})


def _ferry(rng: random.Random, size: int, dense: bool = False) -> Instance:
    """Many locations and cars; 2-3 cars must cross."""
    inst = Instance()
    locations = [inst.add("location", f"port{i}") for i in range(1, max(3, size // 4) + 1)]
    cars = [inst.add("car", f"car{i}") for i in range(1, max(4, size - len(inst.objects)) + 1)]
    ferry_at = rng.choice(locations)
    inst.facts += [("at-ferry", ferry_at), ("empty-ferry",)]
    inst.untyped_only += [("not-eq", a, b) for a in locations for b in locations if a != b]
    where = {}
    for car in cars:
        where[car] = rng.choice(locations)
        inst.facts.append(("at", car, where[car]))
    needed = {ferry_at}
    _goal_moves(rng, inst, cars if dense else rng.sample(cars, rng.randint(2, 3)), where, locations, needed)
    inst.necessary = sorted(needed)
    return inst


def _grid(rng: random.Random, size: int, dense: bool = False) -> Instance:
    """A square grid with locked cells of three shapes and keys; 1-2 keys must be brought to cells."""
    inst = Instance()
    keys_count = max(3, min(24, size // 20))
    side = max(3, int(math.sqrt(max(9, size - keys_count - 3))))
    shapes = [inst.add("shape", name) for name in ("circle", "square", "triangle")]
    cells = {(x, y): inst.add("place", f"p{x}-{y}") for y in range(side) for x in range(side)}
    locked = set()
    for cell in cells:
        if rng.random() < 0.08:
            locked.add(cell)
    start = rng.choice([c for c in cells if c not in locked])
    # Open cells reachable from the start without unlocking anything: goals stay solvable.
    component, frontier = {start}, [start]
    while frontier:
        x, y = frontier.pop()
        for nxt in ((x + 1, y), (x - 1, y), (x, y + 1), (x, y - 1)):
            if nxt in cells and nxt not in locked and nxt not in component:
                component.add(nxt)
                frontier.append(nxt)
    reachable = sorted(component)
    for (x, y), name in cells.items():
        for nxt in ((x + 1, y), (x - 1, y), (x, y + 1), (x, y - 1)):
            if nxt in cells:
                inst.facts.append(("conn", name, cells[nxt]))
        if (x, y) in locked:
            inst.facts += [("locked", name), ("lock-shape", name, rng.choice(shapes))]
        else:
            inst.facts.append(("open", name))
    inst.facts += [("at-robot", cells[start]), ("arm-empty",)]
    keys = []
    for k in range(1, keys_count + 1):
        key = inst.add("key", f"key{k}")
        keys.append(key)
        inst.facts.append(("key-shape", key, rng.choice(shapes)))
        inst.facts.append(("at", key, cells[rng.choice(reachable)]))
    # Goal keys start inside the start's open component (every key was placed there).
    for key in keys if dense else rng.sample(keys, rng.randint(1, 2)):
        inst.goal.append(("at", key, cells[rng.choice(reachable)]))
    inst.necessary = None
    return inst


def miconic_building(
    rng: random.Random, size: int, floor_every: int
) -> tuple[Instance, str, dict[str, tuple[str, str]]]:
    """A building of one floor per ``floor_every`` objects, the rest passengers, each with a trip between
    two floors and not boarded; returns it with the lift's floor and the trips (no goal yet)."""
    inst = Instance()
    floors = [inst.add("floor", f"f{i}") for i in range(1, max(4, size // floor_every) + 1)]
    passengers = [inst.add("passenger", f"pass{i}") for i in range(1, max(4, size - len(inst.objects)) + 1)]
    for i, lower in enumerate(floors):
        for upper in floors[i + 1 :]:
            inst.facts.append(("above", lower, upper))
    lift = rng.choice(floors)
    inst.facts.append(("lift-at", lift))
    trips: dict[str, tuple[str, str]] = {}
    for person in passengers:
        origin, destin = rng.sample(floors, 2)
        trips[person] = (origin, destin)
        inst.facts += [("origin", person, origin), ("destin", person, destin), ("not-boarded", person)]
    return inst, lift, trips


def _miconic(rng: random.Random, size: int, dense: bool = False) -> Instance:
    """Many floors and passengers; 2-4 passengers must be served."""
    inst, lift, trips = miconic_building(rng, size, 8)
    passengers = list(trips)
    needed = {lift}
    for person in passengers if dense else rng.sample(passengers, rng.randint(2, 4)):
        inst.goal.append(("served", person))
        needed.update({person, *trips[person]})
    inst.necessary = sorted(needed)
    return inst


_BUILDERS: dict[str, Callable[..., Instance]] = {
    "blocksworld": _blocksworld,
    "logistics": _logistics,
    "gripper": _gripper,
    "ferry": _ferry,
    "grid": _grid,
    "miconic": _miconic,
}

# The classic worlds, untyped then typed (generators.worlds registers them).
CLASSIC_NAMES: tuple[str, ...] = tuple(_BUILDERS) + tuple(f"{name}-typed" for name in _BUILDERS)


def _split(world: str) -> tuple[str, bool]:
    if world not in CLASSIC_NAMES:
        raise UsageError(f"unknown classic world {world!r}: choose one of {', '.join(CLASSIC_NAMES)}")
    typed = world.endswith("-typed")
    return (world[: -len("-typed")] if typed else world), typed


def check_int(label: str, value: object, minimum: int) -> None:
    if isinstance(value, bool) or not isinstance(value, int):
        raise UsageError(f"{label} must be an integer, not {value!r}")
    if value < minimum:
        raise UsageError(f"{label} must be at least {minimum}, not {value}")


def classic_rng(seed: int, world: str, index: int, size: int) -> random.Random:
    base, _ = _split(world)  # the typed variant of a problem has the same objects and facts
    key = f"{GENERATOR}/classic/{CLASSIC_VERSION}/{seed}/{base}/{index}/{size}".encode()
    return random.Random(int.from_bytes(hashlib.sha256(key).digest()[:16], "big"))


@dataclass(frozen=True)
class ClassicProblem:
    name: str
    pddl_text: str
    sidecar: dict[str, Any]


def format_instance(inst: Instance, world: str, name: str, comment: str) -> str:
    base, typed = _split(world)
    facts = list(inst.facts)
    if not typed:
        facts = [(predicate, obj) for obj, cls in inst.objects.items() for predicate in TYPE_FACTS[base][cls]]
        facts += list(inst.facts) + list(inst.untyped_only)
    objects: dict[str, list[str]] = {}
    for obj, cls in inst.objects.items():
        objects.setdefault(cls if typed else "object", []).append(obj)
    return format_problem_parts(name, world, objects, facts, inst.goal, comment)


def classic_problem_name(world: str, index: int, dense: bool = False) -> str:
    return f"{world}{'-dense' if dense else ''}-{index:03d}"


def generate_classic_problem(
    world: str, seed: int, index: int, size: int | None = None, dense: bool = False
) -> ClassicProblem:
    """Problem ``index`` of (world, seed, size); ``dense`` puts every movable object in the goal (the
    unpadded form, where nearly every object matters)."""
    base, typed = _split(world)
    check_int("seed", seed, -(1 << 62))
    check_int("index", index, 0)
    size = DEFAULT_SIZES[base] if size is None else size
    check_int("size", size, 10)
    inst = _BUILDERS[base](classic_rng(seed, world, index, size), size, dense)
    name = classic_problem_name(world, index, dense)
    comment = (
        f"{name}: {len(inst.objects)} objects, goal on {len(inst.goal)} atoms\n"
        f"generated by {GENERATOR} (classic version {CLASSIC_VERSION}), seed {seed}, index {index}, size {size}"
    )
    sidecar = instance_sidecar(inst, seed=seed, index=index, world=world, domain=base, typed=typed, size=size)
    sidecar["dense"] = dense
    return ClassicProblem(name, format_instance(inst, world, name, comment), sidecar)


def instance_sidecar(
    inst: Instance, *, seed: int, index: int, world: str, domain: str, typed: bool, size: int
) -> dict[str, Any]:
    """The sidecar of a generated instance: where it came from, its goal objects and its sufficient set."""
    sidecar: dict[str, Any] = {
        "seed": seed,
        "index": index,
        "world": world,
        "domain": domain,
        "form": "typed" if typed else "untyped",
        "difficulty": None,
        "size": size,
        "objects_total": len(inst.objects),
        "goal_objects": sorted({arg for atom in inst.goal for arg in atom[1:]}),
    }
    if inst.necessary is None:
        sidecar["necessary_note"] = NO_GROUND_TRUTH
    else:
        sidecar["necessary"] = inst.necessary
        sidecar["necessary_note"] = SUFFICIENT_NOTE
    return sidecar


def check_classic_arguments(world: str, count: int, seed: int, size: int | None) -> None:
    """Raise ``UsageError`` for a bad world, count, seed or size (before anything is written)."""
    _split(world)
    check_suite_numbers(count, seed, size)


def check_suite_numbers(count: int, seed: int, size: int | None) -> None:
    """Raise ``UsageError`` for a bad count, seed or size of any sized world's suite."""
    check_int("count", count, 1)
    check_int("seed", seed, -(1 << 62))
    if size is not None:
        check_int("size", size, 10)


def write_classic_suite(
    world: str,
    count: int,
    seed: int,
    out_dir: Path,
    size: int | None = None,
    progress: ProgressCallback | None = None,
    force: bool = False,
) -> list[Path]:
    """Write ``count`` problems of a classic world into ``out_dir`` (the kitchen suites' layout and rules)."""
    check_classic_arguments(world, count, seed, size)
    make = functools.partial(generate_classic_problem, world, seed, size=size)
    manifest = suite_manifest(CLASSIC_VERSION, world, None, count, seed, size=size)
    names = [classic_problem_name(world, index) for index in range(1, count + 1)]
    domain_path = DOMAINS_DIR / world / "domain.pddl"
    return write_suite(out_dir, domain_path, names, make, manifest, "objects_total", progress, force)
