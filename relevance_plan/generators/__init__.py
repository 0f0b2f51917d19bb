"""Benchmark worlds, their base scenes and seeded problem generators.

Kitchen worlds (coffee, cereal) and their temporal and numeric variants take
a difficulty and a distractor count; every other world (the classic ones,
driverlog-temporal, zenotravel-numeric, scenegraph, the many-goal forms)
takes a size.  Public API::

    generate_suite(world, difficulty, count, seed, out_dir, distractors=None, progress=None) -> list[Path]
    generate_problem(world, difficulty, seed, index, distractors=None) -> GeneratedProblem
    generate_variant_suite(world, difficulty, count, seed, out_dir, distractors=None, progress=None) -> list[Path]
    generate_variant_problem(world, difficulty, seed, index, distractors=None) -> GeneratedProblem
    generate_sized_suite(world, count, seed, out_dir, size=None, progress=None) -> list[Path]
    generate_sized_problem(world, seed, index, size=None) -> ClassicProblem
    write_base_scenes(problems_dir) -> list[Path]

The generator never depends on the pruning code; it writes problems with
``relevance_plan.pddl.formatter.format_problem_parts``.
"""

from relevance_plan.generators.catalog import CATALOG, CATALOG_TYPES, KITCHENWARE_TYPES
from relevance_plan.generators.classic import CLASSIC_WORLDS, generate_classic_problem, generate_classic_suite
from relevance_plan.generators.generate import (
    CONSTRAINT_COUNTS,
    DISTRACTOR_RANGES,
    GENERATOR_VERSION,
    GeneratedProblem,
    base_scene_problem,
    generate_problem,
    generate_suite,
    write_base_scenes,
)
from relevance_plan.generators.kitchen_variants import (
    KITCHEN_VARIANTS,
    generate_variant_problem,
    generate_variant_suite,
)
from relevance_plan.generators.scenes import DIFFICULTIES, SCENES, WORLD_NAMES, WORLDS, SceneLayout, kind_of
from relevance_plan.generators.sized import SIZED_WORLDS, generate_sized_problem, generate_sized_suite

__all__ = [
    "CLASSIC_WORLDS",
    "generate_classic_problem",
    "generate_classic_suite",
    "CATALOG",
    "CATALOG_TYPES",
    "CONSTRAINT_COUNTS",
    "DIFFICULTIES",
    "DISTRACTOR_RANGES",
    "GENERATOR_VERSION",
    "GeneratedProblem",
    "KITCHENWARE_TYPES",
    "KITCHEN_VARIANTS",
    "SCENES",
    "SIZED_WORLDS",
    "SceneLayout",
    "WORLDS",
    "WORLD_NAMES",
    "base_scene_problem",
    "generate_problem",
    "generate_sized_problem",
    "generate_sized_suite",
    "generate_suite",
    "generate_variant_problem",
    "generate_variant_suite",
    "kind_of",
    "write_base_scenes",
]
