"""The one registry of generated worlds: a name, its domain, one problem generator, one suite generator.

``WORLDS`` maps every world ``relevance-plan generate`` takes to a
:class:`World`, in the order the command lists them; the CLI, the demo, the
benchmarks and the tests look worlds up here and nowhere else::

    world = find_world("coffee")                      # UsageError for a name no world has
    world.problem(seed, index, Settings("hard"))      # one problem: name, PDDL text, sidecar
    world.suite(count, seed, out_dir, Settings(size=200))

Four families make them, each with its own module and the same two entry
points behind the world (``Settings`` carries what a family reads):

* ``kitchen`` (``generate``): coffee and cereal, by difficulty and distractors;
* ``kitchen-variant`` (``kitchen_variants``): those scenes with time or a battery;
* ``classic`` (``classic``): six IPC domains, untyped and typed, by size;
* ``many-object`` (``sized``): the newer worlds (temporal, numeric, scene
  graph, many goals), by size.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import relevance_plan.generators.classic as classic
import relevance_plan.generators.generate as generate
import relevance_plan.generators.kitchen_variants as kitchen_variants
import relevance_plan.generators.scenes as scenes
import relevance_plan.generators.sized as sized
from relevance_plan.data import DOMAINS_DIR
from relevance_plan.errors import UsageError
from relevance_plan.generators.generate import Generated
from relevance_plan.progress import ProgressCallback

KITCHEN = "kitchen"
KITCHEN_VARIANT = "kitchen-variant"
CLASSIC = "classic"
MANY_OBJECT = "many-object"
FAMILIES = (KITCHEN, KITCHEN_VARIANT, CLASSIC, MANY_OBJECT)


@dataclass(frozen=True)
class Settings:
    """How a world's problems are made besides (seed, index): a kitchen world's difficulty and
    distractor count (None: the paper's draw), a sized world's size (None: its default)."""

    difficulty: str = "simple"
    distractors: int | None = None
    size: int | None = None


# (world, seed, index, settings) -> one problem
ProblemGenerator = Callable[[str, int, int, Settings], Generated]
# (world, count, seed, folder, settings, progress, force) -> the problem files written
SuiteGenerator = Callable[[str, int, int, Path, Settings, "ProgressCallback | None", bool], list[Path]]
# (world, count, seed, settings): UsageError for a bad argument, before anything is written
SuiteCheck = Callable[[str, int, int, Settings], None]


@dataclass(frozen=True)
class World:
    """One generated world.

    ``domain`` is its folder of ``data/domains`` (and its problems' ``:domain``); ``base`` the
    world it is a form of (a kitchen variant's kitchen world, a typed form's untyped world), its
    own name otherwise.
    """

    name: str
    family: str  # one of FAMILIES
    domain: str
    base: str
    make_problem: ProblemGenerator
    make_suite: SuiteGenerator
    check_suite: SuiteCheck

    @property
    def domain_path(self) -> Path:
        return DOMAINS_DIR / self.domain / "domain.pddl"

    @property
    def sized(self) -> bool:
        """Made by size (``--size``); the kitchen worlds take a difficulty and distractors instead."""
        return self.family in (CLASSIC, MANY_OBJECT)

    def problem(self, seed: int, index: int, settings: Settings = Settings()) -> Generated:
        """Problem ``index`` of the world's suite (seed, settings): pure, the same bytes every time."""
        return self.make_problem(self.name, seed, index, settings)

    def check(self, count: int, seed: int, settings: Settings = Settings()) -> None:
        """``UsageError`` for a bad count, seed or setting, before anything is written."""
        self.check_suite(self.name, count, seed, settings)

    def suite(
        self,
        count: int,
        seed: int,
        out_dir: Path,
        settings: Settings = Settings(),
        progress: ProgressCallback | None = None,
        force: bool = False,
    ) -> list[Path]:
        """Write problems 1..``count`` into ``out_dir`` with their sidecars, the domain and
        ``suite.json`` (``generate.write_suite``'s layout and rules); the ``.pddl`` paths."""
        return self.make_suite(self.name, count, seed, Path(out_dir), settings, progress, force)


# --------------------------------------------------------------------------- the families' entry points


def _kitchen_problem(world: str, seed: int, index: int, settings: Settings) -> Generated:
    return generate.generate_problem(world, settings.difficulty, seed, index, settings.distractors)


def _kitchen_suite(
    world: str,
    count: int,
    seed: int,
    out_dir: Path,
    settings: Settings,
    progress: ProgressCallback | None,
    force: bool,
) -> list[Path]:
    difficulty, distractors = settings.difficulty, settings.distractors
    return generate.generate_suite(world, difficulty, count, seed, out_dir, distractors, progress, force)


def _check_kitchen(world: str, count: int, seed: int, settings: Settings) -> None:
    generate.check_suite_arguments(world, settings.difficulty, count, seed, settings.distractors)


def _variant_problem(world: str, seed: int, index: int, settings: Settings) -> Generated:
    return kitchen_variants.generate_variant_problem(world, settings.difficulty, seed, index, settings.distractors)


def _variant_suite(
    world: str,
    count: int,
    seed: int,
    out_dir: Path,
    settings: Settings,
    progress: ProgressCallback | None,
    force: bool,
) -> list[Path]:
    difficulty, distractors = settings.difficulty, settings.distractors
    return kitchen_variants.generate_variant_suite(
        world, difficulty, count, seed, out_dir, distractors, progress, force
    )


def _check_variant(world: str, count: int, seed: int, settings: Settings) -> None:
    base = kitchen_variants.variant_base(world)
    generate.check_suite_arguments(base, settings.difficulty, count, seed, settings.distractors)


def _classic_problem(world: str, seed: int, index: int, settings: Settings) -> Generated:
    return classic.generate_classic_problem(world, seed, index, settings.size)


def _classic_suite(
    world: str,
    count: int,
    seed: int,
    out_dir: Path,
    settings: Settings,
    progress: ProgressCallback | None,
    force: bool,
) -> list[Path]:
    return classic.write_classic_suite(world, count, seed, out_dir, settings.size, progress, force)


def _check_classic(world: str, count: int, seed: int, settings: Settings) -> None:
    classic.check_classic_arguments(world, count, seed, settings.size)


def _sized_problem(world: str, seed: int, index: int, settings: Settings) -> Generated:
    return sized.generate_sized_problem(world, seed, index, settings.size)


def _sized_suite(
    world: str,
    count: int,
    seed: int,
    out_dir: Path,
    settings: Settings,
    progress: ProgressCallback | None,
    force: bool,
) -> list[Path]:
    return sized.generate_sized_suite(world, count, seed, out_dir, settings.size, progress, force)


def _check_sized(world: str, count: int, seed: int, settings: Settings) -> None:
    sized.check_sized_arguments(world, count, seed, settings.size)


def _kitchen(name: str) -> World:
    return World(name, KITCHEN, name, name, _kitchen_problem, _kitchen_suite, _check_kitchen)


def _variant(name: str) -> World:
    base = kitchen_variants.variant_base(name)
    return World(name, KITCHEN_VARIANT, name, base, _variant_problem, _variant_suite, _check_variant)


def _classic(name: str) -> World:
    base = name.removesuffix("-typed")
    return World(name, CLASSIC, name, base, _classic_problem, _classic_suite, _check_classic)


def _many_object(name: str) -> World:
    base = name.removesuffix("-typed")
    domain = sized.domain_of(name)
    return World(name, MANY_OBJECT, domain, base, _sized_problem, _sized_suite, _check_sized)


WORLDS: dict[str, World] = {
    world.name: world
    for world in (
        *map(_kitchen, scenes.KITCHENS),
        *map(_variant, kitchen_variants.VARIANT_NAMES),
        *map(_classic, classic.CLASSIC_NAMES),
        *map(_many_object, sized.SIZED_NAMES),
    )
}


def find_world(name: object) -> World:
    """The world called ``name``; ``UsageError`` naming every world for a name no world has."""
    if not isinstance(name, str) or name not in WORLDS:
        raise UsageError(f"unknown world {name!r}: choose one of {', '.join(WORLDS)}")
    return WORLDS[name]


def worlds_of(family: str) -> tuple[World, ...]:
    """The worlds ``family`` makes, in the registry's order."""
    return tuple(world for world in WORLDS.values() if world.family == family)
