"""The first selection of every shipped world, and of a seeded set of generated problems, is what it was.

``tests/data/first_selections.json`` holds, for each case, the objects ``prune`` kept with the
release it was recorded on.  A change that moves code about must leave every one of them as it
is; a change that means to change what is kept records the file anew and says so in the
changelog:

    python tests/test_selection_stability.py --record

Nothing here starts a planner; the whole set prunes in seconds.
"""

from __future__ import annotations

import json
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest

RECORD = Path(__file__).resolve().parent / "data" / "first_selections.json"
SEEDS = (1, 2)
# Sizes a little above each world's smallest, so that pruning has something to remove.
SIZED = {
    "blocksworld": 40,
    "logistics": 40,
    "gripper": 40,
    "ferry": 40,
    "grid": 40,
    "miconic": 40,
    "driverlog-temporal": 40,
    "zenotravel-numeric": 40,
    "scenegraph": 120,
    "logistics-manygoals": 60,
    "miconic-manygoals": 60,
}


def cases() -> Iterator[tuple[str, Path, str]]:
    """(case name, domain file, problem text): the shipped scenes, then generated problems by world and seed."""
    from relevance_plan.data import DOMAINS_DIR, PROBLEMS_DIR
    from relevance_plan.generators import (
        SIZED_WORLDS,
        WORLD_NAMES,
        generate_problem,
        generate_sized_problem,
        generate_variant_problem,
    )
    from relevance_plan.generators.kitchen_variants import KITCHEN_VARIANTS
    from relevance_plan.generators.sized import NEW_WORLDS

    for problem in sorted(PROBLEMS_DIR.glob("*.pddl")):
        yield f"shipped/{problem.stem}", DOMAINS_DIR / problem.stem.split("-")[0] / "domain.pddl", problem.read_text()
    for world in WORLD_NAMES:
        for difficulty in ("simple", "hard"):
            for seed in SEEDS:
                generated = generate_problem(world, difficulty, seed, 1)
                yield f"{world}/{difficulty}/{seed}", DOMAINS_DIR / world / "domain.pddl", generated.pddl_text
    for world in KITCHEN_VARIANTS:
        for seed in SEEDS:
            generated = generate_variant_problem(world, "simple", seed, 1)
            yield f"{world}/simple/{seed}", DOMAINS_DIR / world / "domain.pddl", generated.pddl_text
    for world in SIZED_WORLDS:
        size = SIZED.get(world.removesuffix("-typed"))
        if size is None:
            continue
        for seed in SEEDS:
            generated = generate_sized_problem(world, seed, 1, size)
            folder = NEW_WORLDS[world].domain if world in NEW_WORLDS else world
            yield f"{world}/{size}/{seed}", DOMAINS_DIR / folder / "domain.pddl", generated.pddl_text


def first_selection(domain: Path, problem_text: str) -> list[str]:
    import relevance_plan

    return sorted(relevance_plan.prune(str(domain), problem_text).kept)


def recorded() -> dict[str, list[str]]:
    return json.loads(RECORD.read_text(encoding="utf-8"))["kept"]


def test_the_record_covers_every_case():
    names = [name for name, _, _ in cases()]
    assert sorted(recorded()) == sorted(names)
    assert {name.split("/")[0] for name in names} == set(groups())


def groups() -> list[str]:
    from relevance_plan.generators import SIZED_WORLDS, WORLD_NAMES
    from relevance_plan.generators.kitchen_variants import KITCHEN_VARIANTS

    sized = [world for world in SIZED_WORLDS if world.removesuffix("-typed") in SIZED]
    return ["shipped", *WORLD_NAMES, *KITCHEN_VARIANTS, *sized]


@pytest.mark.parametrize("world", groups())
def test_first_selections_are_as_recorded(world):
    expected = recorded()
    changed = []
    for name, domain, text in cases():
        if name.split("/")[0] != world:
            continue
        kept = first_selection(domain, text)
        if kept != expected[name]:
            gone, new = sorted(set(expected[name]) - set(kept)), sorted(set(kept) - set(expected[name]))
            changed.append(f"{name}: no longer kept {gone}, now kept {new}")
    assert not changed, "\n".join(changed)


if __name__ == "__main__":
    if sys.argv[1:] != ["--record"]:
        raise SystemExit("usage: python tests/test_selection_stability.py --record")
    sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
    import relevance_plan

    kept = {name: first_selection(domain, text) for name, domain, text in cases()}
    RECORD.write_text(json.dumps({"release": relevance_plan.__version__, "kept": kept}, indent=1) + "\n")
    print(f"recorded {len(kept)} first selections in {RECORD}")
