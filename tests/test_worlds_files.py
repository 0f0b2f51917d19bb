"""Every newer world (kitchen variants, temporal/numeric, scene graphs, many goals): it generates, its
domain and problems parse and round-trip through the formatter, the same seed gives the same bytes,
and ``relevance-plan generate`` writes its suites with the usual layout and rules."""

from __future__ import annotations

import json

import pytest
from support import invoke, one_line_error, outputs_under_hash_seeds

from relevance_plan.data import DOMAINS_DIR
from relevance_plan.generators import KITCHEN_VARIANT, MANY_OBJECT, WORLDS, Settings, worlds_of
from relevance_plan.pddl.formatter import format_domain, format_problem
from relevance_plan.pddl.parser import read_domain, read_problem

SMALL = {"scenegraph": 200, "miconic-manygoals": 200, "miconic-manygoals-typed": 200}


def generated(world: str, seed: int = 4, index: int = 2) -> tuple[str, str, dict]:
    """(domain folder, problem text, sidecar) of one small problem of ``world``."""
    if WORLDS[world].family == KITCHEN_VARIANT:
        problem = WORLDS[world].problem(seed, index, Settings("hard", distractors=12))
        return world, problem.pddl_text, problem.sidecar
    problem = WORLDS[world].problem(seed, index, Settings(size=SMALL.get(world, 80)))
    return WORLDS[world].domain, problem.pddl_text, problem.sidecar


ALL_NEW = sorted(world.name for family in (KITCHEN_VARIANT, MANY_OBJECT) for world in worlds_of(family))


@pytest.mark.parametrize("world", ALL_NEW)
def test_problem_parses_and_round_trips(world):
    folder, text, sidecar = generated(world)
    domain = read_domain((DOMAINS_DIR / folder / "domain.pddl").read_text())
    problem = read_problem(text, domain)
    assert problem.domain_name == domain.name
    assert len(problem.objects) == sidecar["objects_total"]
    again = read_problem(format_problem(problem), domain)
    assert dict(again.objects) == dict(problem.objects)
    assert again.init == problem.init and dict(again.numeric_init) == dict(problem.numeric_init)
    assert again.goal == problem.goal and again.metric == problem.metric
    assert format_problem(again) == format_problem(problem)
    assert set(sidecar["goal_objects"]) <= set(sidecar["necessary"]) <= set(problem.objects)


@pytest.mark.parametrize("folder", sorted({generated(world)[0] for world in ALL_NEW}))
def test_domain_parses_and_round_trips(folder):
    domain = read_domain((DOMAINS_DIR / folder / "domain.pddl").read_text())
    assert domain.name == folder
    text = format_domain(domain)
    again = read_domain(text)
    assert format_domain(again) == text
    assert [a.name for a in again.actions] == [a.name for a in domain.actions]
    assert all(a.durative for a in domain.actions) == folder.endswith("-temporal")
    assert domain.numeric == (folder.endswith("-numeric") or folder.endswith("-temporal"))


@pytest.mark.parametrize("world", ALL_NEW)
def test_same_seed_same_bytes_other_seed_other_problem(world):
    _, text, sidecar = generated(world)
    _, text_again, sidecar_again = generated(world)
    assert text == text_again and sidecar == sidecar_again
    assert generated(world, seed=5)[1] != text


def read_tree(directory):
    return {p.name: p.read_bytes() for p in sorted(directory.iterdir())}


@pytest.mark.parametrize(
    "world,options",
    [
        ("coffee-temporal", ["--difficulty", "hard", "--distractors", "7"]),
        ("cereal-temporal", []),
        ("coffee-numeric", ["--distractors", "0"]),
        ("driverlog-temporal", ["--size", "40"]),
        ("zenotravel-numeric", ["--size", "40"]),
        ("scenegraph", ["--size", "200"]),
        ("logistics-manygoals-typed", ["--size", "60"]),
        ("miconic-manygoals", ["--size", "60"]),
    ],
)
def test_cli_writes_identical_suites(tmp_path, world, options):
    for name in ("a", "b"):
        result = invoke("generate", world, "--count", "2", "--seed", "9", "--out", tmp_path / name, *options)
        assert result.exit_code == 0, result.output
    tree = read_tree(tmp_path / "a")
    assert tree == read_tree(tmp_path / "b")
    manifest = json.loads(tree["suite.json"])
    assert manifest["world"] == world and manifest["seed"] == 9 and len(manifest["problems"]) == 2
    assert tree["domain.pddl"] == WORLDS[world].domain_path.read_bytes()
    for entry in manifest["problems"]:
        sidecar = json.loads(tree[entry["sidecar"]])
        assert sidecar["world"] == world and sidecar["necessary"]
        assert entry["problem"].startswith(world + "-")
    if "--distractors" in options:
        count = int(options[options.index("--distractors") + 1])
        assert all(entry["distractor_count"] == count for entry in manifest["problems"])


@pytest.mark.parametrize(
    "arguments,message",
    [
        (["coffee-temporal", "--size", "50"], "--size applies to the classic worlds"),
        (["scenegraph", "--distractors", "5"], "--distractors applies to the kitchen worlds"),
        (["coffee-numeric", "--difficulty", "medium"], "unknown difficulty"),
        (["driverlog-temporal", "--size", "3"], "size must be at least 10"),
        (["nosuch"], "scenegraph"),
    ],
)
def test_cli_refuses_bad_options_in_one_line(tmp_path, arguments, message):
    result = invoke("generate", *arguments, "--out", tmp_path / "out")
    assert result.exit_code != 0
    assert message in one_line_error(result.stderr)
    assert not (tmp_path / "out").exists()


ACROSS_PROCESSES = (
    "import sys\n"
    "from relevance_plan.generators import WORLDS, Settings\n"
    "for world in ('scenegraph', 'driverlog-temporal', 'zenotravel-numeric', 'logistics-manygoals'):\n"
    "    sys.stdout.write(WORLDS[world].problem(3, 1, Settings(size=120)).pddl_text)\n"
    "sys.stdout.write(WORLDS['cereal-temporal'].problem(3, 1, Settings('hard')).pddl_text)\n"
)


def test_same_bytes_across_processes_and_hash_seeds():
    outputs = outputs_under_hash_seeds(ACROSS_PROCESSES)
    here = "".join(
        WORLDS[world].problem(3, 1, Settings(size=120)).pddl_text
        for world in ("scenegraph", "driverlog-temporal", "zenotravel-numeric", "logistics-manygoals")
    )
    here += WORLDS["cereal-temporal"].problem(3, 1, Settings("hard")).pddl_text
    assert outputs[0] == outputs[1] == here


def test_generate_names_every_world_of_the_registry_in_its_order():
    from support import invoke

    from relevance_plan.generators import WORLDS

    # click wraps the help at hyphens too: "driverlog-" may end a line
    shown = " ".join(invoke("generate", "--help").output.split()).replace("- ", "-")
    # a typed form is named as its untyped world's "(each also as NAME-typed)"
    missing = [name for name in WORLDS if name not in shown and name.removesuffix("-typed") not in shown]
    assert not missing and "NAME-typed" in shown
    unknown = invoke("generate", "no-such-world", "-o", "unused")
    assert unknown.exit_code == 30
    assert f"choose one of {', '.join(WORLDS)}" in unknown.stderr
