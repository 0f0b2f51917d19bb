"""Benchmark worlds (coffee, cereal), their base scenes and a seeded problem generator.

Public API::

    generate_suite(world, difficulty, count, seed, out_dir, distractors=None, progress=None) -> list[Path]
    generate_problem(world, difficulty, seed, index, distractors=None) -> GeneratedProblem
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
from relevance_plan.generators.scenes import DIFFICULTIES, SCENES, WORLD_NAMES, WORLDS, SceneLayout, kind_of

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
    "SCENES",
    "SceneLayout",
    "WORLDS",
    "WORLD_NAMES",
    "base_scene_problem",
    "generate_problem",
    "generate_suite",
    "kind_of",
    "write_base_scenes",
]
