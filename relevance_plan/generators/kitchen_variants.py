"""Temporal and numeric variants of the kitchen worlds: the same scenes with time or a battery.

``coffee-temporal`` and ``cereal-temporal`` have durative actions: a move
takes the static ``(distance ?from ?to)`` between two places, manipulation
takes fixed times, and the robot stays at the place while it works.
``coffee-numeric`` keeps instantaneous actions but gives the robot a
battery: a move needs and uses ``(distance ?from ?to)`` units of
``(battery)``, and ``recharge`` at the dock (the robot's start place) fills
it to ``(battery-capacity)``.

A variant problem is the kitchen problem of the same (difficulty, seed,
index, distractors) -- the same objects, distractors, facts, goal and
sidecar sets -- plus the numeric values, which come from a random stream of
their own (so the scene never depends on the variant).  The capacity is at
least twice the longest distance, so every trip can go through the dock:
the sidecar's ``necessary`` set stays sufficient (the dock is the robot's
start, which it always holds).  Each variant's domain folder ships a copy
of the base world's knowledge model with its own domain name.
"""

from __future__ import annotations

import functools
import hashlib
import math
import random
from dataclasses import dataclass
from pathlib import Path

from relevance_plan.errors import UsageError
from relevance_plan.generators.generate import (
    GENERATOR,
    GeneratedProblem,
    check_suite_arguments,
    generate_problem,
    problem_name,
    suite_manifest,
    write_kitchen_suite,
)
from relevance_plan.generators.problem import goal_objects, problem_goal, problem_init, problem_objects
from relevance_plan.generators.scenes import SceneLayout
from relevance_plan.pddl import formulas as f
from relevance_plan.pddl.formatter import format_problem
from relevance_plan.pddl.model import make_problem
from relevance_plan.progress import ProgressCallback

VARIANT_VERSION = "1"
TEMPORAL = "temporal"
NUMERIC = "numeric"

# Places lie on a square of this side; a distance is the rounded Euclidean one, at least 1.
FLOOR_SIDE = 12.0


@dataclass(frozen=True)
class KitchenVariant:
    name: str
    base: str  # the kitchen world whose scenes it uses
    kind: str  # TEMPORAL or NUMERIC


_VARIANTS: dict[str, KitchenVariant] = {
    variant.name: variant
    for variant in (
        KitchenVariant("coffee-temporal", "coffee", TEMPORAL),
        KitchenVariant("cereal-temporal", "cereal", TEMPORAL),
        KitchenVariant("coffee-numeric", "coffee", NUMERIC),
    )
}


# The variants this module makes (generators.worlds registers them).
VARIANT_NAMES = tuple(_VARIANTS)


def _variant(world: object) -> KitchenVariant:
    if world not in _VARIANTS:
        raise UsageError(f"unknown kitchen variant {world!r}: choose one of {', '.join(_VARIANTS)}")
    return _VARIANTS[world]


def variant_base(world: str) -> str:
    """The kitchen world whose scenes the variant ``world`` uses."""
    return _variant(world).base


def variant_rng(seed: int, world: str, difficulty: str, index: int) -> random.Random:
    """The stream of a variant's numbers (the scene has its own, shared with the base world)."""
    key = f"{GENERATOR}/variant/{VARIANT_VERSION}/{seed}/{world}/{difficulty}/{index}".encode()
    return random.Random(int.from_bytes(hashlib.sha256(key).digest()[:16], "big"))


def place_distances(scene: SceneLayout, rng: random.Random) -> dict[tuple[str, str], int]:
    """A distance for every ordered pair of distinct places, symmetric, from random floor positions."""
    position = {p.name: (rng.uniform(0, FLOOR_SIDE), rng.uniform(0, FLOOR_SIDE)) for p in scene.places}
    distances = {}
    for a in position:
        for b in position:
            if a != b:
                distances[(a, b)] = max(1, round(math.dist(position[a], position[b])))
    return distances


def variant_numbers(variant: KitchenVariant, scene: SceneLayout, rng: random.Random) -> tuple[list, dict]:
    """Extra facts and the numeric initial values of ``variant`` on ``scene``."""
    distances = place_distances(scene, rng)
    values: dict[tuple, float] = {("distance", a, b): d for (a, b), d in distances.items()}
    facts: list[tuple] = []
    if variant.kind == NUMERIC:
        longest = max(distances.values(), default=1)
        capacity = 2 * longest + rng.randint(0, longest)
        facts.append(("dock", scene.robot_start))
        values[("battery-capacity",)] = capacity
        values[("battery",)] = rng.randint(capacity // 4, capacity)
    return facts, values


def generate_variant_problem(
    world: str, difficulty: str, seed: int, index: int, distractors: int | None = None
) -> GeneratedProblem:
    """Problem ``index`` of a variant suite, as a ``GeneratedProblem`` (``scene`` is the kitchen scene)."""
    variant = _variant(world)
    kitchen = generate_problem(variant.base, difficulty, seed, index, distractors)
    scene = kitchen.scene
    facts, values = variant_numbers(variant, scene, variant_rng(seed, world, difficulty, index))
    objects = {name: type_name for type_name, names in problem_objects(scene).items() for name in names}
    goal = f.And(tuple(f.Atom(atom[0], tuple(atom[1:])) for atom in problem_goal(scene)))
    name = problem_name(world, difficulty, index)
    problem = make_problem(name, world, objects, problem_init(scene) + facts, goal, numeric_init=values)
    comment = (
        f"{name}: the {kitchen.name} scene ({kitchen.sidecar['distractor_count']} distractors) with "
        f"{'durations' if variant.kind == TEMPORAL else 'a battery'}\n"
        f"generated by {GENERATOR} version {VARIANT_VERSION}, seed {seed}, index {index}"
    )
    sidecar = {
        **kitchen.sidecar,
        "world": world,
        "base_world": variant.base,
        "variant": variant.kind,
        "goal_objects": goal_objects(scene),
    }
    return GeneratedProblem(name, format_problem(problem, comment), sidecar, scene)


def generate_variant_suite(
    world: str,
    difficulty: str,
    count: int,
    seed: int,
    out_dir: Path,
    distractors: int | None = None,
    progress: ProgressCallback | None = None,
    force: bool = False,
) -> list[Path]:
    """Write ``count`` problems of a variant into ``out_dir`` (the kitchen suites' layout and rules)."""
    variant = _variant(world)
    check_suite_arguments(variant.base, difficulty, count, seed, distractors)
    make = functools.partial(generate_variant_problem, world, difficulty, seed, distractors=distractors)
    manifest = suite_manifest(VARIANT_VERSION, world, difficulty, count, seed, distractors=distractors)
    return write_kitchen_suite(manifest, make, out_dir, progress, force)
