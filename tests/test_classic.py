"""Classic worlds without a knowledge model: inferred types, the relaxed-reachability check
and its repair, widening that doubles, going straight to the full problem, valid plans."""

import json

import pytest
from click.testing import CliRunner

from relevance_plan.cli import main
from relevance_plan.data import DOMAINS_DIR
from relevance_plan.generators import CLASSIC, worlds_of
from relevance_plan.generators.classic import generate_classic_problem
from relevance_plan.pddl.parser import read_domain, read_problem
from relevance_plan.planning.options import PlanOptions
from relevance_plan.planning.results import PlanStatus
from relevance_plan.planning.run import plan_task
from relevance_plan.planning.validation import ValidationStatus, validate_plan
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.reachability.exploration import relaxed_reachability
from relevance_plan.relevance.scoring.scorers import SCORERS, ScoreRequest
from relevance_plan.relevance.selection.prune import PruneSettings, Widening, prune_with_scores, widen

# Two cities, a truck in each, one airplane; the goal moves a package from city a to city b.
LOGISTICS_PROBLEM = """(define (problem tiny) (:domain logistics)
  (:objects pkg1 pkg2 pkg3 truck-a truck-b plane apt-a apt-b post-a post-b city-a city-b)
  (:init (package pkg1) (package pkg2) (package pkg3) (truck truck-a) (truck truck-b) (airplane plane)
         (location apt-a) (location apt-b) (location post-a) (location post-b) (airport apt-a) (airport apt-b)
         (city city-a) (city city-b)
         (in-city apt-a city-a) (in-city post-a city-a) (in-city apt-b city-b) (in-city post-b city-b)
         (at truck-a apt-a) (at truck-b apt-b) (at plane apt-b)
         (at pkg1 post-a) (at pkg2 post-b) (at pkg3 apt-a))
  (:goal (at pkg1 post-b)))
"""


def classic_task(world: str, text: str) -> PlanningTask:
    domain = read_domain((DOMAINS_DIR / world / "domain.pddl").read_text())
    return PlanningTask(domain, read_problem(text, domain))


def goal_scores(task):
    return SCORERS["goal"](task, ScoreRequest())


def test_types_are_inferred_from_static_unary_predicates():
    task = classic_task("logistics", LOGISTICS_PROBLEM)
    typing = task.typing
    assert typing.inferred
    assert task.object_type("truck-a") == "truck"
    assert task.object_type("apt-a") == "airport+location"
    assert typing.domain.is_subtype("airport+location", "location")  # an airport is a location
    params = {a.name: dict(a.parameters) for a in typing.domain.actions}
    assert params["load-truck"] == {"?p": "package", "?t": "truck", "?l": "location"}
    assert params["fly-airplane"]["?from"] == "airport+location"
    # role analysis now works as on the typed domain: a truck can serve the goal
    assert "truck" in task.goal_analysis.role_depth
    typed = classic_task(
        "logistics-typed",
        LOGISTICS_PROBLEM.replace(
            "(:objects pkg1 pkg2 pkg3 truck-a truck-b plane apt-a apt-b post-a post-b city-a city-b)",
            "(:objects pkg1 pkg2 pkg3 - package truck-a truck-b - truck plane - airplane apt-a apt-b - airport"
            " post-a post-b - location city-a city-b - city)",
        )
        .replace("(:domain logistics)", "(:domain logistics-typed)")
        .replace("(package pkg1) (package pkg2) (package pkg3) (truck truck-a) (truck truck-b) (airplane plane)", "")
        .replace(
            "(location apt-a) (location apt-b) (location post-a) (location post-b) (airport apt-a) (airport apt-b)", ""
        )
        .replace("(city city-a) (city city-b)", ""),
    )
    assert not typed.typing.inferred
    assert set(typed.goal_analysis.role_depth) == set(task.goal_analysis.role_depth)


def test_a_domain_without_static_classes_is_left_untyped():
    text = (
        "(define (problem p) (:domain blocksworld) (:objects a b c) (:init (handempty) (ontable a) (ontable b)"
        " (on c a) (clear c) (clear b)) (:goal (on a b)))"
    )
    task = classic_task("blocksworld", text)
    assert not task.typing.inferred
    result = prune_with_scores(task, goal_scores(task))
    assert result.kept == {"a", "b", "c"}


def test_relaxed_check_rejects_a_set_without_a_vehicle_and_repair_adds_one_with_a_reason():
    task = classic_task("logistics", LOGISTICS_PROBLEM)
    without_vehicles = frozenset({"pkg1", "post-a", "post-b", "apt-a", "apt-b", "city-a", "city-b"})
    check = relaxed_reachability(task, without_vehicles)
    assert check.complete and not check.reachable
    assert check.unreached == (("at", "pkg1", "post-b"),)
    everything = relaxed_reachability(task, frozenset(task.problem.objects))
    assert everything.reachable and {"truck-a", "truck-b", "plane"} <= everything.plan_objects

    result = prune_with_scores(task, goal_scores(task), extra=without_vehicles, settings=PruneSettings(full_above=1.0))
    assert relaxed_reachability(task, result.kept).reachable
    assert {"plane", "truck-a", "truck-b"} <= result.kept
    reasons = {r.name: r for r in result.restored}
    repaired = {name for name, r in reasons.items() if r.rule == "reachability"}
    assert "plane" in repaired and not {"pkg2", "pkg3"} & repaired  # other packages are not needed
    assert not relaxed_reachability(task, result.kept - {"plane"}).reachable
    assert reasons["plane"].rule == "reachability"
    assert reasons["plane"].describe().startswith("used by a relaxed plan to the goal (")


def test_widening_at_least_doubles_the_kept_set():
    problem = generate_classic_problem("logistics", seed=3, index=1, size=200)
    task = classic_task("logistics", problem.pddl_text)
    first = prune_with_scores(task, goal_scores(task), settings=PruneSettings(goal_filter=True))
    assert len(first.kept) < 0.2 * len(task.problem.objects)
    second, extra = widen(first, Widening(0.5, goal_filter=True))
    assert len(second.kept) >= 2 * len(first.kept)
    assert first.kept <= second.kept
    third, _ = widen(second, Widening(0.5, goal_filter=True), extra)
    assert len(third.kept) >= 2 * len(second.kept)


def test_widening_goes_to_the_full_problem_when_it_would_keep_most_objects():
    problem = generate_classic_problem("logistics", seed=3, index=1, size=200)
    task = classic_task("logistics", problem.pddl_text)
    result = prune_with_scores(task, goal_scores(task), settings=PruneSettings(goal_filter=True))
    while len(result.kept) < len(task.problem.objects):
        before = len(result.kept)
        result, _ = widen(result, Widening(0.5, goal_filter=True))
        assert len(result.kept) == len(task.problem.objects) or len(result.kept) >= 2 * before
        if 2 * before > 0.8 * len(task.problem.objects):
            assert result.kept == frozenset(task.problem.objects)
            assert result.text == task.problem.text


@pytest.mark.planner
def test_an_unpruneable_problem_goes_straight_to_the_full_problem(tmp_path):
    problem = generate_classic_problem("gripper", seed=1, index=1, size=30, dense=True)
    task = classic_task("gripper", problem.pddl_text)
    result = prune_with_scores(task, goal_scores(task), settings=PruneSettings(goal_filter=True))
    assert result.kept == frozenset(task.problem.objects)
    domain_path, problem_path = tmp_path / "domain.pddl", tmp_path / "problem.pddl"
    domain_path.write_bytes((DOMAINS_DIR / "gripper" / "domain.pddl").read_bytes())
    problem_path.write_text(problem.pddl_text)
    planned = plan_task(domain_path, problem_path, PlanOptions(timeout=60))
    assert planned.status is PlanStatus.SOLVED and len(planned.attempts) == 1
    assert planned.attempts[0].objects_kept == planned.objects_total


@pytest.mark.planner
@pytest.mark.parametrize("world", [world.name for world in worlds_of(CLASSIC)])
def test_relevance_plans_are_valid_on_the_original(tmp_path, world):
    problem = generate_classic_problem(world, seed=2, index=1, size=60)
    domain_path, problem_path = tmp_path / "domain.pddl", tmp_path / "problem.pddl"
    domain_path.write_bytes((DOMAINS_DIR / world / "domain.pddl").read_bytes())
    problem_path.write_text(problem.pddl_text)
    result = plan_task(domain_path, problem_path, PlanOptions(timeout=60))
    assert result.status is PlanStatus.SOLVED, result.message
    assert result.selection.scores.scorer == "goal"
    assert result.objects_kept < result.objects_total
    task = classic_task(world, problem.pddl_text)
    assert validate_plan(task.domain, task.problem, result.plan).status is ValidationStatus.VALID


@pytest.mark.planner
@pytest.mark.parametrize("method", ["pure", "oracle"])
def test_pure_and_oracle_plans_are_valid_on_the_original(tmp_path, method):
    problem = generate_classic_problem("logistics", seed=2, index=1, size=60)
    domain_path, problem_path = tmp_path / "domain.pddl", tmp_path / "problem.pddl"
    domain_path.write_bytes((DOMAINS_DIR / "logistics" / "domain.pddl").read_bytes())
    problem_path.write_text(problem.pddl_text)
    problem_path.with_suffix(".json").write_text(json.dumps(problem.sidecar))
    result = plan_task(domain_path, problem_path, PlanOptions(method=method, timeout=60))
    assert result.status is PlanStatus.SOLVED and result.valid


def test_generator_is_seeded_and_typed_variants_share_the_objects():
    first = generate_classic_problem("miconic", seed=5, index=2, size=50)
    assert first.pddl_text == generate_classic_problem("miconic", seed=5, index=2, size=50).pddl_text
    typed = generate_classic_problem("miconic-typed", seed=5, index=2, size=50)
    assert typed.sidecar["goal_objects"] == first.sidecar["goal_objects"]
    assert typed.sidecar["necessary"] == first.sidecar["necessary"]
    assert "- passenger" in typed.pddl_text and "(passenger " in first.pddl_text


def test_cli_generates_a_classic_suite(tmp_path):
    out = tmp_path / "grid"
    result = CliRunner().invoke(
        main,
        ["generate", "grid", "--count", "2", "--seed", "3", "--size", "60", "--out", str(out)],
        catch_exceptions=False,
    )
    assert result.exit_code == 0, result.output
    manifest = json.loads((out / "suite.json").read_text())
    assert manifest["world"] == "grid" and len(manifest["problems"]) == 2
    sidecar = json.loads((out / "grid-001.json").read_text())
    assert "necessary" not in sidecar and "no cheap ground truth" in sidecar["necessary_note"]
    assert (out / "domain.pddl").read_bytes() == (DOMAINS_DIR / "grid" / "domain.pddl").read_bytes()
    bad = CliRunner().invoke(main, ["generate", "grid", "--size", "3", "--out", str(tmp_path / "x")])
    assert bad.exit_code != 0 and "size must be at least 10" in bad.output
    assert len(bad.output.strip().splitlines()) == 1
    mixed = CliRunner().invoke(main, ["generate", "coffee", "--size", "50", "--out", str(tmp_path / "y")])
    assert mixed.exit_code != 0 and "--size applies to the classic worlds" in mixed.output
    unknown = CliRunner().invoke(main, ["generate", "nosuch", "--out", str(tmp_path / "z")])
    assert unknown.exit_code != 0 and "logistics-typed" in unknown.output
    assert len(unknown.output.strip().splitlines()) == 1
