"""Tests for ``generators/``: catalog, base scenes, problem generator, suites.

Planning checks run Fast Downward's driver (inside up-fast-downward) directly,
one fresh working directory per run, and validate plans with unified-planning
on the FULL problem.  The full-size generated problems take seconds to
minutes each with Fast Downward: that check is marked ``slow`` (run it with
``--runslow``, see ``tests/conftest.py``).
"""

from __future__ import annotations

import json
import os
import re
import signal
import subprocess
import sys
from pathlib import Path

import pytest
from support import DOMAINS, PROBLEMS, REPO, outputs_under_hash_seeds

if str(REPO) not in sys.path:  # the repository is not necessarily installed
    sys.path.insert(0, str(REPO))

from relevance_plan.errors import InputFileError, UsageError  # noqa: E402
from relevance_plan.generators import (  # noqa: E402
    CATALOG,
    CONSTRAINT_COUNTS,
    DISTRACTOR_RANGES,
    KITCHENWARE_TYPES,
    SCENES,
    WORLDS,
    Settings,
    find_world,
    kind_of,
    write_base_scenes,
)
from relevance_plan.generators.problem import blockers, goal_objects, relevant_objects  # noqa: E402

SUITES = [("coffee", "simple"), ("coffee", "hard"), ("cereal", "simple"), ("cereal", "hard")]
NAME = re.compile(r"^[a-z]+(_[a-z]+)*_[1-9][0-9]*$")


# --- helpers -----------------------------------------------------------------


def fast_downward(domain: Path, problem: Path, workdir: Path, timeout: float = 300) -> Path | None:
    """Run ``lama-first`` in ``workdir``; return the plan file, or None if no plan."""
    import up_fast_downward

    driver = Path(up_fast_downward.__file__).parent / "downward" / "fast-downward.py"
    workdir.mkdir(parents=True, exist_ok=True)
    command = [
        sys.executable,
        str(driver),
        "--plan-file",
        "sas_plan",
        "--alias",
        "lama-first",
        str(domain),
        str(problem),
    ]
    process = subprocess.Popen(
        command, cwd=workdir, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, start_new_session=True
    )
    try:
        output, _ = process.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        process.communicate()
        pytest.fail(f"Fast Downward timed out after {timeout} s on {problem.name}")
    plan = workdir / "sas_plan"
    if process.returncode == 0 and plan.exists():
        return plan
    (workdir / "fd.log").write_bytes(output)
    return None


def restrict_problem(text: str, keep: set[str]) -> str:
    """Drop every object not in ``keep`` and every init fact mentioning one.

    Works on the formatter's layout: one ``names - type`` line per type in
    ``:objects``, one atom per line in ``:init``.  The goal is kept as is.
    """
    out: list[str] = []
    section = None
    for line in text.splitlines():
        stripped = line.strip()
        if stripped.startswith("(:objects"):
            section = "objects"
        elif stripped.startswith("(:init"):
            section = "init"
        elif stripped.startswith("(:goal"):
            section = None
        elif section == "objects" and " - " in stripped:
            names, type_name = stripped.rsplit(" - ", 1)
            kept = [n for n in names.split() if n in keep]
            if kept:
                out.append("    " + " ".join(kept) + " - " + type_name)
            continue
        elif section == "init" and stripped.startswith("("):
            if all(arg in keep for arg in stripped.strip("()").split()[1:]):
                out.append(line)
            continue
        out.append(line)
    return "\n".join(out) + "\n"


def validate_on(domain: Path, problem: Path, plan: Path) -> None:
    """Assert that ``plan`` is valid on ``problem`` (unified-planning)."""
    from unified_planning.engines.plan_validator import SequentialPlanValidator
    from unified_planning.engines.results import ValidationResultStatus
    from unified_planning.io import PDDLReader
    from unified_planning.shortcuts import get_environment

    get_environment().credits_stream = None
    reader = PDDLReader()
    parsed = reader.parse_problem(str(domain), str(problem))
    parsed_plan = reader.parse_plan(parsed, str(plan))
    result = SequentialPlanValidator().validate(parsed, parsed_plan)
    assert result.status == ValidationResultStatus.VALID, f"{plan} is not valid on {problem.name}: {result}"


def init_atoms(text: str) -> list[tuple[str, ...]]:
    init = text.split("(:init", 1)[1].split("(:goal", 1)[0]
    return [tuple(m.split()) for m in re.findall(r"\(([^()]+)\)", init)]


def declared_objects(text: str) -> dict[str, str]:
    block = text.split("(:objects", 1)[1].split("(:init", 1)[0]
    objects = {}
    for line in block.splitlines():
        if " - " in line:
            names, type_name = line.strip().rsplit(" - ", 1)
            for name in names.split():
                objects[name] = type_name
    return objects


def domain_types(world: str) -> set[str]:
    text = (DOMAINS / world / "domain.pddl").read_text()
    block = re.sub(r";[^\n]*", "", text.split("(:types", 1)[1].split("(:predicates", 1)[0])
    return set(re.findall(r"[a-z][a-z-]*", block))


def check_sidecar(problem_text: str, sidecar: dict, scene) -> None:
    """Structural invariants of one generated problem and its sidecar."""
    objects = declared_objects(problem_text)
    assert len(objects) == sidecar["objects_total"] == scene.objects_total
    assert all(NAME.match(name) for name in objects)
    atoms = init_atoms(problem_text)
    items = [n for n, t in objects.items() if t not in ("surface", "container", "human")]
    at = {a[1]: a[2] for a in atoms if a[0] == "at"}
    on = {a[1]: a[2] for a in atoms if a[0] == "on"}
    on_base = {a[1] for a in atoms if a[0] == "on-base"}
    clear = {a[1] for a in atoms if a[0] == "clear"}
    # piles are physically consistent
    assert sorted(at) == sorted(items), "every item is at exactly one place"
    assert len([a for a in atoms if a[0] == "at"]) == len(items)
    assert len(set(on.values())) == len(on), "at most one item directly on another"
    for top, bottom in on.items():
        assert at[top] == at[bottom]
        assert top not in on_base and bottom not in clear
    for item in items:
        assert (item in on_base) != (item in on), f"{item}: on-base xor on another item"
        assert (item in clear) == (item not in on.values()), f"{item}: clear iff nothing on it"
    for top, bottom in sidecar["constraints"]:
        assert on[top] == bottom
    # ground-truth sets
    relevant, necessary = set(sidecar["relevant"]), set(sidecar["necessary"])
    assert relevant <= set(objects) and necessary <= set(objects)
    assert set(sidecar["roles"].values()) <= necessary
    assert set(goal_objects(scene)) <= necessary
    assert scene.robot_start in necessary and all(h.place in necessary for h in scene.humans)
    # The invariant: necessary is within relevant plus the pile-mates of the
    # chosen role objects and returned goal items (the blockers).
    assert necessary <= relevant | set(blockers(scene, sidecar["roles"]))
    assert set(relevant_objects(scene)) == relevant
    # everything stacked on or under a necessary item is necessary, and its place too
    for item in necessary & set(items):
        assert at[item] in necessary
        if item in on:
            assert on[item] in necessary
    for top, bottom in on.items():
        if bottom in necessary:
            assert top in necessary


# --- catalog -----------------------------------------------------------------

FORBIDDEN_TOKENS = {
    "cup",
    "cups",
    "mug",
    "bowl",
    "spoon",
    "teaspoon",
    "tablespoon",
    "milk",
    "creamer",
    "cream",
    "coffee",
    "espresso",
    "cereal",
    "granola",
    "sugar",
    "honey",
    "sweetener",
    "napkin",
    "napkins",
    "stir",
    "stirrer",
    "stick",
    "tea",
    "teapot",
    "ice",
    "juice",
    "water",
    "soda",
    "fruit",
    "straw",
}


def test_catalog_has_200_distinct_plausible_kinds():
    kinds = [kind for kind, _ in CATALOG]
    assert len(CATALOG) == 200 and len(set(kinds)) == 200
    both = domain_types("coffee") & domain_types("cereal")
    for kind, type_name in CATALOG:
        assert re.fullmatch(r"[a-z]+(_[a-z]+)*", kind), kind
        assert type_name in KITCHENWARE_TYPES and type_name in both, (kind, type_name)
        if kind != "tea_towel":  # a dish cloth, named like tea on purpose
            assert not FORBIDDEN_TOKENS & set(kind.split("_")), kind
    task_kinds = {kind_of(i.name) for scene in SCENES.values() for i in scene.items if scene.is_task_item(i.name)}
    assert not task_kinds & set(kinds)


# --- base scenes ---------------------------------------------------------------


def test_base_scene_sizes_and_dependencies():
    sizes = {"coffee-simple": 19, "coffee-hard": 36, "cereal-simple": 18, "cereal-hard": 26}
    assert {name: scene.objects_total for name, scene in SCENES.items()} == sizes
    assert SCENES["coffee-simple"].dependencies == ()
    assert all(i.on is None for i in SCENES["coffee-simple"].items)
    assert all(i.on is None for i in SCENES["coffee-hard"].items)
    assert len(SCENES["cereal-simple"].dependencies) == 20
    assert len(SCENES["cereal-hard"].dependencies) == 20
    for scene in SCENES.values():
        for place in scene.places:
            assert place.accessible == (place.kind == "surface")
        types = domain_types(scene.world)
        assert {i.type for i in scene.items} <= types
        assert all(NAME.match(name) for name in scene.object_names())


def test_coffee_scenes_contain_the_papers_kinds():
    kinds = {kind_of(i.name): i.type for i in SCENES["coffee-simple"].items}
    for kind, type_name in [
        ("cold_brew_coffee", "coffee-source"),
        ("creamer", "whitener"),
        ("whole_milk", "whitener"),
        ("reduced_milk", "whitener"),
        ("plastic_cup", "cup"),
        ("paper_cup", "cup"),
        ("stir_stick", "stirrer"),
        ("napkin", "napkin"),
        ("ice_bucket", "ice-holder"),
    ]:
        assert kinds[kind] == type_name
    hard = {kind_of(i.name): i.type for i in SCENES["coffee-hard"].items}
    assert hard["mug"] == "cup" and hard["teaspoon"] == "stirrer"
    assert len(SCENES["coffee-hard"].places) > len(SCENES["coffee-simple"].places)


def test_committed_base_scenes_are_current(tmp_path):
    written = write_base_scenes(tmp_path)
    assert [p.name for p in written] == [f"{name}.pddl" for name in SCENES]
    for name in SCENES:
        for suffix in (".pddl", ".json"):
            assert (tmp_path / f"{name}{suffix}").read_bytes() == (PROBLEMS / f"{name}{suffix}").read_bytes(), (
                f"problems/{name}{suffix} is stale: run relevance_plan.generators.write_base_scenes('problems')"
            )
    for name, scene in SCENES.items():
        text = (PROBLEMS / f"{name}.pddl").read_text()
        sidecar = json.loads((PROBLEMS / f"{name}.json").read_text())
        assert sidecar["distractor_count"] == 0 and sidecar["constraints"] == []
        assert len(sidecar["dependencies"]) == len(scene.dependencies)
        check_sidecar(text, sidecar, scene)


# --- generated problems ----------------------------------------------------------


@pytest.mark.parametrize("world,difficulty", SUITES)
def test_generated_sizes_and_invariants(world, difficulty):
    low, high = DISTRACTOR_RANGES[(world, difficulty)]
    base = SCENES[f"{world}-{difficulty}"]
    counts = []
    for index in range(1, 41):
        problem = WORLDS[world].problem(11, index, Settings(difficulty))
        sidecar = problem.sidecar
        counts.append(sidecar["distractor_count"])
        assert low <= sidecar["distractor_count"] <= high
        assert sidecar["objects_total"] == base.objects_total + sidecar["distractor_count"]
        assert len(sidecar["distractors"]) == len(set(sidecar["distractors"])) == sidecar["distractor_count"]
        assert len(sidecar["constraints"]) == CONSTRAINT_COUNTS[(world, difficulty)]
        if world == "cereal":
            assert sidecar["dependencies"] == [d.as_dict() for d in base.dependencies]
            assert len(sidecar["dependencies"]) == 20
        else:
            covered = {(d["requires"], d["object"]) for d in sidecar["dependencies"] if d["kind"] == "covered"}
            assert {tuple(pair) for pair in sidecar["constraints"]} <= covered
        if (world, difficulty) == ("coffee", "simple"):
            assert len(sidecar["dependencies"]) == 3
        check_sidecar(problem.pddl_text, sidecar, problem.scene)
    assert len(set(counts)) >= 8, "distractor counts should spread over the range"


def test_same_arguments_same_problem_across_processes():
    script = (
        "import sys; sys.path.insert(0, sys.argv[1]);"
        "from generators import WORLDS, Settings;"
        "p = WORLDS['coffee'].problem(5, 2, Settings('hard'));"
        "sys.stdout.write(p.pddl_text + p.sidecar_text)"
    )
    outputs = outputs_under_hash_seeds(script, ("1", "2"), str(REPO))
    problem = WORLDS["coffee"].problem(5, 2, Settings("hard"))
    assert outputs[0] == outputs[1] == problem.pddl_text + problem.sidecar_text


def test_distractor_override_scales_to_2000(tmp_path):
    paths = WORLDS["coffee"].suite(1, 3, tmp_path / "big", Settings("simple", distractors=2000))
    sidecar = json.loads(paths[0].with_suffix(".json").read_text())
    assert sidecar["distractor_count"] == 2000 and len(set(sidecar["distractors"])) == 2000
    assert sidecar["objects_total"] == 19 + 2000
    assert len({kind_of(n) for n in sidecar["distractors"]}) == 200
    assert "dinner_plate_3" in sidecar["distractors"]  # kinds repeat with indices (scene has dinner_plate_1)
    assert len(declared_objects(paths[0].read_text())) == 2019
    zero = WORLDS["cereal"].problem(3, 1, Settings("hard", distractors=0))
    assert zero.sidecar["distractor_count"] == 0 and zero.sidecar["objects_total"] == 26


# --- suites ------------------------------------------------------------------------


def read_tree(directory: Path) -> dict[str, bytes]:
    return {p.name: p.read_bytes() for p in sorted(directory.iterdir())}


def test_suite_layout_and_determinism(tmp_path):
    calls = []
    paths = WORLDS["cereal"].suite(
        3, 42, tmp_path / "a", Settings("simple"), progress=lambda e: calls.append((e.done, e.total))
    )
    assert calls == [(1, 3), (2, 3), (3, 3)]
    assert [p.name for p in paths] == [f"cereal-simple-00{i}.pddl" for i in (1, 2, 3)]
    tree = read_tree(tmp_path / "a")
    assert sorted(tree) == sorted(
        ["domain.pddl", "suite.json"] + [f"cereal-simple-00{i}{s}" for i in (1, 2, 3) for s in (".pddl", ".json")]
    )
    assert tree["domain.pddl"] == (DOMAINS / "cereal" / "domain.pddl").read_bytes()
    manifest = json.loads(tree["suite.json"])
    assert manifest["world"] == "cereal" and manifest["difficulty"] == "simple"
    assert manifest["count"] == 3 and manifest["seed"] == 42 and manifest["distractors"] is None
    assert [e["problem"] for e in manifest["problems"]] == [p.name for p in paths]
    sidecar = json.loads(tree["cereal-simple-002.json"])
    assert sidecar["seed"] == 42 and sidecar["index"] == 2 and sidecar["base_scene"] == "cereal-simple"
    assert tree["cereal-simple-002.json"].decode() == json.dumps(sidecar, sort_keys=True, indent=2) + "\n"
    assert tree["cereal-simple-002.pddl"].decode() == WORLDS["cereal"].problem(42, 2, Settings("simple")).pddl_text

    WORLDS["cereal"].suite(3, 42, tmp_path / "b", Settings("simple"))
    assert read_tree(tmp_path / "b") == tree
    WORLDS["cereal"].suite(3, 43, tmp_path / "c", Settings("simple"))
    other = read_tree(tmp_path / "c")
    assert all(other[f"cereal-simple-00{i}.pddl"] != tree[f"cereal-simple-00{i}.pddl"] for i in (1, 2, 3))


def test_suite_replaces_only_its_own_directories(tmp_path):
    target = tmp_path / "suite"
    WORLDS["coffee"].suite(3, 1, target, Settings("simple"))
    WORLDS["coffee"].suite(2, 1, target, Settings("hard"))  # a previous suite of ours: replaced
    assert sorted(p.name for p in target.iterdir()) == sorted(
        ["domain.pddl", "suite.json"] + [f"coffee-hard-00{i}{s}" for i in (1, 2) for s in (".pddl", ".json")]
    )
    foreign = tmp_path / "foreign"
    foreign.mkdir()
    (foreign / "notes.txt").write_text("mine")
    with pytest.raises(UsageError):
        WORLDS["coffee"].suite(1, 1, foreign, Settings("simple"))
    assert read_tree(foreign) == {"notes.txt": b"mine"}
    empty = tmp_path / "empty"
    empty.mkdir()
    WORLDS["coffee"].suite(1, 1, empty, Settings("simple"))
    assert (empty / "suite.json").exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["empty", "foreign", "suite"], "no staging left behind"


@pytest.mark.parametrize(
    "kwargs",
    [
        {"world": "tea"},
        {"difficulty": "medium"},
        {"count": 0},
        {"count": -3},
        {"distractors": -1},
        {"distractors": 2.5},
        {"count": True},
        {"seed": "7"},
    ],
)
def test_bad_arguments_raise_usage_error_and_write_nothing(tmp_path, kwargs):
    arguments = {"world": "coffee", "difficulty": "simple", "count": 2, "seed": 1, "distractors": None}
    arguments.update(kwargs)
    settings = Settings(arguments["difficulty"], arguments["distractors"])
    with pytest.raises(UsageError) as info:
        find_world(arguments["world"]).suite(arguments["count"], arguments["seed"], tmp_path / "out", settings)
    assert "\n" not in str(info.value)
    assert list(tmp_path.iterdir()) == []
    if "count" not in kwargs:  # the same checks guard the pure function
        with pytest.raises(UsageError):
            find_world(arguments["world"]).problem(arguments["seed"], 1, settings)


def test_unwritable_directory_raises_input_file_error(tmp_path):
    blocker = tmp_path / "a_file"
    blocker.write_text("not a directory")
    with pytest.raises(InputFileError):
        WORLDS["coffee"].suite(1, 1, blocker / "suite", Settings("simple"))
    with pytest.raises(InputFileError):
        WORLDS["coffee"].suite(1, 1, blocker, Settings("simple"))
    with pytest.raises(InputFileError):
        write_base_scenes(blocker / "problems")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a_file"]


# --- planning ----------------------------------------------------------------------


def _planning_cases():
    cases = [pytest.param(name, None, None, id=name) for name in SCENES]
    for world, difficulty in SUITES:
        for index in (1, 2):
            cases.append(pytest.param(f"{world}-{difficulty}", index, 4, id=f"{world}-{difficulty}-{index:03d}-d4"))
    return cases


def _write_case(tmp_path: Path, scene_name: str, index: int | None, distractors: int | None):
    world = scene_name.split("-")[0]
    if index is None:
        problem_path = PROBLEMS / f"{scene_name}.pddl"
        sidecar = json.loads(problem_path.with_suffix(".json").read_text())
    else:
        difficulty = scene_name.split("-")[1]
        problem = WORLDS[world].problem(2026, index, Settings(difficulty, distractors=distractors))
        problem_path = tmp_path / f"{problem.name}.pddl"
        problem_path.write_text(problem.pddl_text)
        sidecar = problem.sidecar
    restricted = tmp_path / "necessary.pddl"
    restricted.write_text(restrict_problem(problem_path.read_text(), set(sidecar["necessary"])))
    return DOMAINS / world / "domain.pddl", problem_path, restricted


def _check_necessary_restriction(tmp_path, domain, problem_path, restricted):
    plan = fast_downward(domain, restricted, tmp_path / "fd-necessary", timeout=120)
    assert plan is not None, "the necessary-restricted problem must be solvable"
    validate_on(domain, problem_path, plan)


@pytest.mark.planner
@pytest.mark.parametrize("scene_name,index,distractors", _planning_cases())
def test_full_and_necessary_problems_are_solvable(tmp_path, scene_name, index, distractors):
    """Base scenes and small generated problems: Fast Downward solves the full
    problem and the necessary-restricted one; both plans are valid on the full
    problem (unified-planning parses it)."""
    domain, problem_path, restricted = _write_case(tmp_path, scene_name, index, distractors)
    plan = fast_downward(domain, problem_path, tmp_path / "fd-full", timeout=120)
    assert plan is not None, f"{problem_path.name} must be solvable"
    validate_on(domain, problem_path, plan)
    _check_necessary_restriction(tmp_path, domain, problem_path, restricted)


@pytest.mark.planner
@pytest.mark.parametrize("world,difficulty", SUITES)
@pytest.mark.parametrize("index", [1, 2])
def test_necessary_restriction_of_paper_sized_problems(tmp_path, world, difficulty, index):
    """Default distractor ranges: the restriction to ``necessary`` is solvable
    and its plan is valid on the full problem (cheap: only the small problem
    is planned; the full one is parsed and validated by unified-planning)."""
    domain, problem_path, restricted = _write_case(tmp_path, f"{world}-{difficulty}", index, None)
    _check_necessary_restriction(tmp_path, domain, problem_path, restricted)


@pytest.mark.planner
@pytest.mark.slow
@pytest.mark.parametrize("world,difficulty", SUITES)
@pytest.mark.parametrize("index", [1, 2])
def test_paper_sized_problems_are_solvable(tmp_path, world, difficulty, index):
    """Default distractor ranges, full problem: 2-25 s each with lama-first."""
    domain, problem_path, _ = _write_case(tmp_path, f"{world}-{difficulty}", index, None)
    plan = fast_downward(domain, problem_path, tmp_path / "fd-full", timeout=600)
    assert plan is not None, f"{problem_path.name} must be solvable"
    validate_on(domain, problem_path, plan)
