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
    from relevance_plan.generators import WORLDS

    for problem in sorted(PROBLEMS_DIR.glob("*.pddl")):
        yield f"shipped/{problem.stem}", DOMAINS_DIR / problem.stem.split("-")[0] / "domain.pddl", problem.read_text()
    for world in WORLDS.values():
        for name, settings in _settings(world):
            for seed in SEEDS:
                generated = world.problem(seed, 1, settings)
                yield f"{world.name}/{name}/{seed}", world.domain_path, generated.pddl_text


def _settings(world) -> list[tuple[str, object]]:
    """(the case's middle name, the settings) of each case of ``world``: a kitchen world's
    difficulties, a variant's simple one, a sized world's size from SIZED (none: not a case)."""
    from relevance_plan.generators import KITCHEN, KITCHEN_VARIANT, Settings

    if world.family == KITCHEN:
        return [(difficulty, Settings(difficulty)) for difficulty in ("simple", "hard")]
    if world.family == KITCHEN_VARIANT:
        return [("simple", Settings("simple"))]
    size = SIZED.get(world.base)
    return [] if size is None else [(str(size), Settings(size=size))]


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
    from relevance_plan.generators import WORLDS

    return ["shipped", *(name for name, world in WORLDS.items() if _settings(world))]


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
