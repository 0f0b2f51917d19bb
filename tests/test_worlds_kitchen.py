"""The temporal and numeric kitchen worlds are the kitchen scenes plus time or a battery: same objects,
distractors, facts, goal and sufficient sets; the shipped knowledge model applies to them."""

from __future__ import annotations

import pytest

from relevance_plan.data import DOMAINS_DIR
from relevance_plan.generators import KITCHEN_VARIANT, WORLDS, Settings, worlds_of
from relevance_plan.pddl.parser import read_domain, read_problem
from relevance_plan.relevance.scoring.knowledge import (
    check_knowledge_model_applies,
    find_knowledge_model,
    load_knowledge_model,
)

VARIANTS = [w.name for w in worlds_of(KITCHEN_VARIANT)]
CASES = [(world, difficulty) for world in VARIANTS for difficulty in ("simple", "hard")]


def parsed(folder: str, text: str):
    domain = read_domain((DOMAINS_DIR / folder / "domain.pddl").read_text())
    return domain, read_problem(text, domain)


@pytest.mark.parametrize("world,difficulty", CASES)
@pytest.mark.parametrize("distractors", [None, 40])
def test_variant_is_the_kitchen_problem_plus_numbers(world, difficulty, distractors):
    variant = WORLDS[world]
    kitchen = WORLDS[variant.base].problem(8, 3, Settings(difficulty, distractors))
    problem = variant.problem(8, 3, Settings(difficulty, distractors))
    _, base = parsed(variant.base, kitchen.pddl_text)
    _, timed = parsed(world, problem.pddl_text)
    assert dict(timed.objects) == dict(base.objects) and timed.goal == base.goal
    added = timed.init - base.init
    assert base.init <= timed.init
    assert added == ({("dock", kitchen.scene.robot_start)} if world.endswith("-numeric") else set())
    for key in ("distractors", "constraints", "necessary", "relevant", "roles", "objects_total"):
        assert problem.sidecar[key] == kitchen.sidecar[key], key
    assert problem.sidecar["world"] == world and problem.sidecar["base_world"] == variant.base
    places = [p.name for p in kitchen.scene.places]
    distances = {k: v for k, v in timed.numeric_init.items() if k[0] == "distance"}
    assert set(distances) == {("distance", a, b) for a in places for b in places if a != b}
    assert all(v >= 1 and v == distances[("distance", k[2], k[1])] for k, v in distances.items())


def test_the_battery_always_allows_a_trip_through_the_dock():
    for index in range(1, 30):
        problem = WORLDS["coffee-numeric"].problem(1, index, Settings("hard"))
        _, parsed_problem = parsed("coffee-numeric", problem.pddl_text)
        values = parsed_problem.numeric_init
        longest = max(v for k, v in values.items() if k[0] == "distance")
        assert values[("battery-capacity",)] >= 2 * longest
        assert 0 <= values[("battery",)] <= values[("battery-capacity",)]
        assert problem.scene.robot_start in problem.sidecar["necessary"]


@pytest.mark.parametrize("world", sorted(VARIANTS))
def test_the_base_worlds_knowledge_model_is_shipped_for_the_variant(world):
    base = WORLDS[world].base
    path = find_knowledge_model(world, None)
    assert path == DOMAINS_DIR / world / "relevance.yaml"
    # A copy with its own domain name: every other line is the base world's.
    lines = path.read_text().splitlines()
    base_lines = (DOMAINS_DIR / base / "relevance.yaml").read_text().splitlines()
    assert [line for line in lines if not line.startswith("domain:")] == [
        line for line in base_lines if not line.startswith("domain:")
    ]
    assert f"domain: {world}" in lines
    domain = read_domain((DOMAINS_DIR / world / "domain.pddl").read_text())
    check_knowledge_model_applies(load_knowledge_model(path), domain)


def test_a_variant_needs_a_known_difficulty_and_a_non_negative_distractor_count():
    from relevance_plan.errors import UsageError
    from relevance_plan.generators.kitchen_variants import generate_variant_problem

    with pytest.raises(UsageError, match="difficulty"):
        WORLDS["coffee-temporal"].problem(1, 1, Settings("medium"))
    with pytest.raises(UsageError, match="distractors"):
        WORLDS["cereal-temporal"].problem(1, 1, Settings("simple", distractors=-1))
    with pytest.raises(UsageError, match="kitchen variant"):
        generate_variant_problem("coffee", "simple", 1, 1)


@pytest.mark.parametrize("world", sorted(VARIANTS))
def test_prune_scores_a_variant_with_the_shipped_model(tmp_path, world):
    import json

    from support import invoke

    invoke("generate", world, "--count", "1", "--seed", "2", "--distractors", "20", "--out", tmp_path / "suite")
    problem = tmp_path / "suite" / f"{world}-simple-001.pddl"
    result = invoke("prune", tmp_path / "suite" / "domain.pddl", problem, "-o", tmp_path / "pruned.pddl", "--json")
    assert result.exit_code == 0, result.output
    report = json.loads(result.stdout)
    assert report["scorer"] == "model" and report["sufficient"]
    assert len(report["kept"]) < report["objects_total"]
    assert set(json.loads(problem.with_suffix(".json").read_text())["goal_objects"]) <= set(report["kept"])
