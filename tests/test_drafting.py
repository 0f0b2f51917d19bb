"""Drafting a knowledge model from a domain and its problems: structure, format, the check, planning with it.

The domains are tests/data/drafting/*: a workshop (keys and locked storage), a laboratory
(badges, sealed fridges, stacked tubes) and a hospital supply room (keycards, taped boxes,
nurses), each typed STRIPS with negative preconditions and four problems.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest
import yaml
from support import COFFEE_DOMAIN, COFFEE_MODEL, invoke

from relevance_plan.errors import ModelError
from relevance_plan.io import load_domain, load_problem
from relevance_plan.relevance import drafting
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.drafting.structure import find_dependencies, find_structure
from relevance_plan.relevance.scoring.knowledge import (
    check_knowledge_model_applies,
    load_knowledge_model,
    parse_knowledge_model,
)
from relevance_plan.relevance.scoring.scene import build_scene
from relevance_plan.relevance.selection.completion import lacking, strict_task
from relevance_plan.relevance.setup import ScoringOptions, score_problem

WORLDS = Path(__file__).parent / "data" / "drafting"
DOMAINS = ("workshop", "laboratory", "hospital")


def world(name: str) -> tuple[Path, list[Path]]:
    return WORLDS / name / "domain.pddl", sorted((WORLDS / name).glob("p*.pddl"))


def tasks_of(name: str) -> list[PlanningTask]:
    domain_path, problems = world(name)
    domain = load_domain(domain_path)
    return [PlanningTask(domain, load_problem(path, domain)) for path in problems]


@pytest.fixture(scope="module")
def drafted():
    """Each domain's drafted model (drafting takes a fraction of a second per domain)."""
    found = {}
    for name in DOMAINS:
        tasks = tasks_of(name)
        found[name] = (drafting.draft_model(tasks[0].domain, tasks, f"{name}.yaml"), tasks)
    return found


# --------------------------------------------------------------------------- what the schemas say


def test_the_scene_of_the_coffee_world_is_found_as_its_model_writes_it():
    roles = find_structure(load_domain(COFFEE_DOMAIN)).roles
    shipped = load_knowledge_model(COFFEE_MODEL).scene
    for role in ("location", "support", "access", "human_location"):
        assert roles[role].predicate == getattr(shipped, role), role
    assert roles["containment"].predicate is None and roles["closed"].predicate is None


@pytest.mark.parametrize(
    "name, expected",
    [
        ("workshop", {"location": "at", "containment": "in", "access": "open", "support": None}),
        ("laboratory", {"containment": "in-fridge", "access": "fridge-open", "support": "stacked-on"}),
        ("hospital", {"human_location": "nurse-at", "support": "box-on"}),
    ],
)
def test_scene_roles_come_from_the_action_schemas(name, expected):
    roles = find_structure(load_domain(world(name)[0])).roles
    assert {role: roles[role].predicate for role in expected} == expected
    assert all(finding.why for finding in roles.values())


def test_a_static_relation_to_something_held_is_a_dependency():
    domain = load_domain(world("laboratory")[0])
    found = {(d.predicate, d.when_kept, d.restore) for d in find_dependencies(domain, find_structure(domain))}
    # the door or fridge kept (position 2), the badge that opens it (position 1) comes back; never the reverse
    assert found == {("grants", 1, 0), ("authorises", 1, 0)}


# --------------------------------------------------------------------------- the drafted file


@pytest.mark.parametrize("name", DOMAINS)
def test_a_drafted_model_loads_and_names_only_the_domain_s_predicates(drafted, name):
    result, tasks = drafted[name]
    domain = tasks[0].domain
    model = check_knowledge_model_applies(parse_knowledge_model(result.text, "drafted.yaml"), domain)
    assert model.reachability_check and model.objectives and all(name.startswith("goal-") for name in model.objectives)
    scene = yaml.safe_load(result.text)["scene"]
    assert all(value == "none" or value in domain.predicates for value in scene.values()), scene
    assert {c for c in model.classes} >= {t for task in tasks for t in task.problem.objects.values()}


@pytest.mark.parametrize("name", DOMAINS)
def test_every_entry_of_a_drafted_model_says_where_it_came_from(drafted, name):
    text = drafted[name][0].text
    data = yaml.safe_load(text)
    lines = text.splitlines()
    # a scene role, a prior, a kind weight: each on a line with its comment
    for role in data["scene"]:
        assert any(line.startswith(f"  {role}:") and "#" in line for line in lines), role
    for priors in data["activities"].values():
        for class_name in priors:
            assert any(line.strip().startswith(f"{class_name}:") and "  # " in line for line in lines), class_name
    for class_name in data["classes"]:
        index = lines.index(f"  {class_name}:") if f"  {class_name}:" in lines else lines.index(f'  "{class_name}":')
        assert lines[index + 1].strip().startswith("#"), class_name


def test_objectives_come_from_the_problems_goals(drafted):
    result, tasks = drafted["workshop"]
    objectives = result.model.objectives
    assert set(objectives) == {"goal-at", "goal-tested", "goal-tightened"}
    assert objectives["goal-at"].goal_predicates == ("at",)
    assert "torque wrench at workbench" in objectives["goal-at"].description
    # P(class | task): the goal's classes and the roles the goal scorer filled are high, the others low
    priors = result.model.activity_classes["goal-tightened"]
    assert priors["wrench"] > 0.5 and priors["bolt"] > 0.5 and priors["tool"] < 0.2 and priors["key"] < 0.2


# --------------------------------------------------------------------------- the check


@pytest.mark.parametrize("name", DOMAINS)
def test_a_drafted_model_prunes_no_worse_than_no_model_on_its_problems(drafted, name):
    result, tasks = drafted[name]
    assert result.matched, [check.describe() for check in result.checks]
    for task in tasks:
        scoring = score_problem(task, ScoringOptions(scorer="model"), knowledge_model=result.model)
        kept = scoring.first_selection().kept
        goal = score_problem(task, ScoringOptions(scorer="goal")).first_selection()
        strict = strict_task(task)
        # the first attempt has what it needs, even counting the locks the relaxed check passes over
        assert not lacking(strict, kept, scoring.scores.element_scores, result.model), task.problem.name
        needs = len(goal.kept) + len(lacking(strict, goal.kept, goal.scores.element_scores, None))
        assert len(kept) <= drafting.DRAFT_RATIO * needs, task.problem.name


def test_dependencies_that_keep_too_much_are_left_out_and_said(drafted):
    # a toolbox with two keys: a dependency keeps both (and the cabinet the spare is in); the
    # reachability check keeps the one a plan uses
    text = drafted["workshop"][0].text
    assert "dependencies: []" in text
    assert "#  - predicate: fits" in text and "left out" in text


def test_what_the_draft_cannot_match_is_said_in_the_file_and_by_the_command(tmp_path, monkeypatch):
    monkeypatch.setattr(drafting.check, "DRAFT_RATIO", 0.1)  # nothing can keep so little
    domain_path, problems = world("workshop")
    out = tmp_path / "relevance.yaml"
    result = invoke("draft-model", domain_path, *problems, "-o", out)
    assert result.exit_code == 0
    assert "not matched: p01-fetch-torque-wrench.pddl" in result.output
    assert "# Not matched: p01-fetch-torque-wrench.pddl" in out.read_text()
    load_knowledge_model(out)


def test_draft_model_writes_the_model_and_reports_each_problem(tmp_path):
    domain_path, problems = world("laboratory")
    out = tmp_path / "relevance.yaml"
    result = invoke("draft-model", domain_path, *problems, "-o", out, "--json")
    assert result.exit_code == 0, result.output
    data = json.loads(result.output)
    assert data["matched"] is True and data["output"] == str(out)
    assert [p["problem"] for p in data["problems"]] == [p.name for p in problems]
    assert all(p["kept"] <= p["objects"] and not p["lacks"] for p in data["problems"])
    # the goal scorer's first attempt lacks the badges (the doors' locks are negative preconditions)
    assert any("lab_badge_1" in p["goal_scorer_lacks"] for p in data["problems"])
    load_knowledge_model(out)


def test_draft_model_refuses_to_overwrite_an_input(tmp_path):
    domain_path, problems = world("workshop")
    result = invoke("draft-model", domain_path, *problems, "-o", problems[0])
    assert result.exit_code == 30 and "same file as the input" in result.output


# --------------------------------------------------------------------------- using a drafted model


@pytest.mark.planner
@pytest.mark.parametrize("name", ["workshop", "laboratory"])
def test_planning_with_a_drafted_model_solves_at_the_first_attempt(drafted, tmp_path, name):
    out = tmp_path / "relevance.yaml"
    out.write_text(drafted[name][0].text)
    domain_path, problems = world(name)
    for problem in problems[:2]:
        result = invoke(
            "plan", domain_path, problem, "--model", out, "--no-race", "--json", "--plan-file", tmp_path / "plan"
        )
        data = json.loads(result.output)
        assert data["status"] == "solved" and data["valid"], data["message"]
        assert data["first_attempt_status"] == "solved" and data["attempts"] == 1, problem.name


def watch_without_goal(drafted, tmp_path, name: str, goal: str, events: list[dict], *options: str) -> list[dict]:
    """``watch``'s lines for ``events`` on the first problem of ``name`` with its goal (``goal``) taken away."""
    model = tmp_path / "relevance.yaml"
    model.write_text(drafted[name][0].text)
    domain_path, problems = world(name)
    scene = tmp_path / "scene.pddl"
    scene.write_text(problems[0].read_text().replace(f"(:goal {goal})", "(:goal (and))"))
    lines = tmp_path / "events.jsonl"
    lines.write_text("".join(json.dumps(event) + "\n" for event in events))
    result = invoke("watch", domain_path, scene, "--model", model, "--events", lines, *options)
    return [json.loads(line) for line in result.output.splitlines()]


def test_watch_with_a_drafted_model_reports_relevance_for_an_objective_before_any_goal(drafted, tmp_path):
    goal = "(at torque_wrench_1 workbench_1)"
    (line,) = watch_without_goal(drafted, tmp_path, "workshop", goal, [{"event": "cue", "objective": "goal-at"}])
    assert line["triggered"] and line["sufficient"], line
    assert "torque_wrench_1" in line["relevant"] and "claw_hammer_1" not in line["relevant"]


def test_a_cue_repeating_the_objective_given_determines_relevance_when_none_was_made(drafted, tmp_path):
    cue = {"event": "cue", "objective": "goal-spun"}
    first, second = watch_without_goal(
        drafted, tmp_path, "laboratory", "(spun blood_sample_2)", [cue, cue], "--objective", "goal-spun"
    )
    assert first["triggered"] and "blood_sample_2" in first["relevant"] and "centrifuge_1" in first["relevant"]
    assert "saline_tube_1" not in first["relevant"]
    assert not second["triggered"]  # the same cue again changes nothing


# --------------------------------------------------------------------------- the format's additions


SCENE_MODEL = """
version: 1
domain: workshop
scene: {{{scene}}}
objectives:
  fetch: {{goal_predicates: [at], tasks: {{fetch: 1.0}}}}
tasks:
  fetch: {{tool: 0.9, wrench: 0.9}}
classes:
  tool: {{types: [tool, key, part, screwdriver, meter, bolt]}}
  wrench: {{types: [wrench]}}
  place: {{types: [area, storage, hook], relevance_from: contents}}
placement: {{in-closed-container: 0.5}}
"""


def test_a_scene_role_may_be_none_and_defaults_the_domain_lacks_are_none():
    domain = load_domain(world("workshop")[0])
    model = parse_knowledge_model(SCENE_MODEL.format(scene="support: none, human_location: null"), "m.yaml")
    applied = check_knowledge_model_applies(model, domain)
    assert applied.scene.support is None and applied.scene.human_location is None
    assert applied.scene.access is None  # 'accessible', a default the workshop lacks: none, not an error
    with pytest.raises(ModelError, match=r"scene.access 'accessible' is not a predicate.*'access: none'"):
        check_knowledge_model_applies(
            parse_knowledge_model(SCENE_MODEL.format(scene="access: accessible"), "m"), domain
        )
    with pytest.raises(ModelError, match="takes 2 argument"):
        check_knowledge_model_applies(parse_knowledge_model(SCENE_MODEL.format(scene="access: at"), "m"), domain)


def test_containment_gives_a_placement_factor_and_access_judges_only_its_places():
    domain_path, problems = world("workshop")
    domain = load_domain(domain_path)
    problem = load_problem(problems[0], domain)
    model = parse_knowledge_model(SCENE_MODEL.format(scene="containment: in, access: open"), "m.yaml")
    scene = build_scene(
        domain, problem.objects, problem.facts_in_order(), check_knowledge_model_applies(model, domain).scene
    )
    wrench = scene.elements["torque_wrench_1"]  # in the locked toolbox
    assert wrench.place == "toolbox_1" and "in-closed-container" in wrench.conditions
    assert "reachable" in scene.elements["rubber_mallet_1"].conditions  # on a workbench: 'open' is about storage
    assert "holds-items" in scene.elements["toolbox_1"].conditions
    locked = parse_knowledge_model(SCENE_MODEL.format(scene="containment: in, access: none, closed: locked"), "m")
    scene = build_scene(domain, problem.objects, problem.facts_in_order(), locked.scene)
    assert "in-closed-container" in scene.elements["torque_wrench_1"].conditions
    assert "reachable" in scene.elements["flathead_screwdriver_1"].conditions  # in the unlocked drawer_2
    scores = score_problem(PlanningTask(domain, problem), ScoringOptions(scorer="model"), knowledge_model=model).scores
    assert "in-closed-container 0.5" in scores.explanations["socket_wrench_1"]


def test_the_reachability_flag_is_read_under_its_old_name_too():
    old = parse_knowledge_model(SCENE_MODEL.format(scene="") + "sufficiency_check: true\n", "m.yaml")
    assert old.reachability_check
    with pytest.raises(ModelError, match="give 'reachability_check' only"):
        parse_knowledge_model(
            SCENE_MODEL.format(scene="") + "sufficiency_check: true\nreachability_check: true\n", "m.yaml"
        )


def test_reachability_check_must_be_true_or_false():
    with pytest.raises(ModelError, match="'reachability_check' must be true or false"):
        parse_knowledge_model(SCENE_MODEL.format(scene="") + "reachability_check: maybe\n", "m.yaml")
