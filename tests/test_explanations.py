"""Every decision explained: the step that kept or dropped each object, one object's chain, the failing
atom of an invalid plan, where a list is left open, and the small promises of the command line."""

from __future__ import annotations

import json
import os
import subprocess

import pytest
from support import COFFEE_DOMAIN, PROBLEMS, REPO, TOOL, coffee_problem, invoke, one_line_error
from test_drafting import SCENE_MODEL, world

from relevance_plan.errors import PDDLParseError, counted
from relevance_plan.exitcodes import ExitCode
from relevance_plan.io import load_domain, load_problem
from relevance_plan.pddl.parser import read_domain, read_problem
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.selection import decisions
from relevance_plan.relevance.setup import ScoringOptions, score_problem


@pytest.fixture
def coffee(tmp_path):
    path = tmp_path / "coffee.pddl"
    path.write_text(coffee_problem(extra_plates=4))
    return path


def steps_of(domain_path, problem_path, *args) -> dict:
    data = json.loads(invoke("score", domain_path, problem_path, "--json", *args).stdout)
    return {name: (d["kept"], d["step"], d["reason"]) for name, d in data["decisions"].items()}


def test_score_names_the_step_that_kept_or_dropped_each_object(coffee):
    found = steps_of(COFFEE_DOMAIN, coffee)
    assert found["alice"][:2] == (True, decisions.GOAL)
    assert found["plastic_cup_1"][:2] == (False, decisions.SET_ASIDE)
    assert found["paper_cup_1"][:2] == (True, decisions.THRESHOLDS)
    # a napkin is relevant to the human, but no action toward the goal uses one
    napkin = steps_of(COFFEE_DOMAIN, PROBLEMS / "coffee-hard.pddl")["napkin_1"]
    assert napkin[:2] == (False, decisions.GOAL_FILTER) and "no action toward the goal can use a napkin" in napkin[2]
    assert (
        found["side_plate_3"][:2] == (False, decisions.CLASS_THRESHOLD) and "R(plate)=0.00" in found["side_plate_3"][2]
    )
    closed = [name for name, (kept, step, _) in found.items() if kept and step == decisions.CLOSURE]
    assert closed and all("(" in found[name][2] for name in closed)  # the fact that brought it back


def test_goal_objects_are_shown_at_relevance_one(coffee):
    data = json.loads(invoke("score", COFFEE_DOMAIN, coffee, "--json").stdout)
    assert data["scores"]["alice"] == 1.0
    scoring = score_problem(PlanningTask(*_task(COFFEE_DOMAIN, coffee)), ScoringOptions())
    assert scoring.scorer == "model" and scoring.scores.element_scores["alice"] == 1.0
    assert scoring.scores.explanations["alice"] == "named in the goal"


def _task(domain_path, problem_path):
    domain = load_domain(domain_path)
    return domain, load_problem(problem_path, domain)


def test_the_reachability_check_and_a_dependency_are_named_not_called_closure(tmp_path):
    domain_path, problems = world("laboratory")
    found = steps_of(domain_path, problems[0])  # the goal scorer: the door a relaxed plan passes
    assert found["prep_lab_door_1"][:2] == (True, decisions.REACHABILITY_CHECK)
    assert "relaxed plan" in found["prep_lab_door_1"][2]
    model = tmp_path / "relevance.yaml"
    model.write_text(
        SCENE_MODEL.format(scene="containment: in, access: open")
        + "dependencies:\n  - {predicate: fits, when_kept: 2, restore: 1, reason: the key that fits it}\n"
    )
    domain_path, problems = world("workshop")
    found = steps_of(domain_path, problems[0], "--model", model)
    assert found["toolbox_key_1"][:2] == (True, decisions.DEPENDENCY)
    assert found["toolbox_key_1"][2] == "declared dependency of toolbox_1 (fits toolbox_key_1 toolbox_1)"


def test_the_class_table_keeps_a_class_when_the_element_table_keeps_one_of_its_objects():
    """``kept`` of a class is what the element table says of its objects, in the table and in JSON; a
    class above tau_c none of whose objects passes tau_e is not kept (the sweeteners of coffee-hard)."""
    problem = PROBLEMS / "coffee-hard.pddl"
    data = json.loads(invoke("score", COFFEE_DOMAIN, problem, "--json").stdout)
    kept_of: dict[str, list[bool]] = {}
    for name, class_name in data["element_class"].items():
        kept_of.setdefault(class_name, []).append(data["decisions"][name]["kept"])
    for class_name, entry in data["classes"].items():
        objects = kept_of.get(class_name, [])
        assert entry["kept"] == any(objects), class_name
        assert (entry["objects_kept"], entry["objects"]) == (sum(objects), len(objects)), class_name
    assert data["classes"]["sweetener"]["relevance"] > data["tau_class"] and not data["classes"]["sweetener"]["kept"]
    rows = {}
    for line in invoke("score", COFFEE_DOMAIN, problem).stdout.split("\n\n")[1].splitlines()[1:]:
        class_name, _, kept = line.split(maxsplit=2)
        rows[class_name] = kept
    assert rows == {
        c: f"{'yes' if e['kept'] else 'no'} ({e['objects_kept']} of {e['objects']})" for c, e in data["classes"].items()
    }


def test_insufficient_cues_are_said_once_on_stderr(coffee):
    for why in ((), ("--why", "paper_cup_1")):
        result = invoke("score", COFFEE_DOMAIN, coffee, "--objective", "drink-at-break", *why)
        assert result.exit_code == ExitCode.INSUFFICIENT_CUES
        assert result.stdout == "", why
        assert "insufficient cues: objective ambiguous" in one_line_error(result.stderr)


def test_the_summary_counts_what_each_step_kept(coffee):
    output = invoke("score", COFFEE_DOMAIN, coffee).stdout
    (summary,) = [line for line in output.splitlines() if line.startswith("kept ")]
    assert "named in the goal" in summary and "relevant" in summary and "by closure" in summary
    assert "restored by closure" not in output


def test_why_follows_one_object_back_to_what_the_goal_needs(tmp_path):
    model = tmp_path / "relevance.yaml"
    model.write_text(
        SCENE_MODEL.format(scene="containment: in, access: open")
        + "dependencies:\n  - {predicate: fits, when_kept: 2, restore: 1, reason: the key that fits it}\n"
    )
    domain_path, problems = world("workshop")
    output = invoke("score", domain_path, problems[0], "--model", model, "--why", "Drawer_Key_1").stdout
    lines = output.splitlines()
    assert lines[0].startswith("drawer_key_1: kept (dependency): declared dependency of drawer_1")
    assert any(line.startswith("  because drawer_1 is kept (closure)") for line in lines)
    assert any(line.startswith("  because torque_wrench_1 is kept (goal)") for line in lines)
    data = json.loads(invoke("score", domain_path, problems[0], "--model", model, "--why", "hook_2", "--json").stdout)
    assert data["kept"] is False and data["step"] and data["because"] == [] and data["class"] == "place"
    result = invoke("score", domain_path, problems[0], "--why", "torque_wrench")
    assert result.exit_code == ExitCode.USAGE and "did you mean: torque_wrench_1" in one_line_error(result.stderr)


# --------------------------------------------------------------------------- validate and the reader


def test_validate_names_the_failing_atom(tmp_path):
    domain_path, problems = world("workshop")
    plan = tmp_path / "plan"
    plan.write_text("(pick torque_wrench_1 storeroom_1)\n")
    result = invoke("validate", domain_path, problems[0], plan)
    assert result.exit_code == ExitCode.PLAN_INVALID
    assert "precondition not satisfied: (robot-at storeroom_1) is false" in result.stdout
    assert "INVALID: plan of 1 step (builtin)" in result.stdout
    plan.write_text("(move entrance_1 workbench_1)\n")
    result = invoke("validate", domain_path, problems[0], plan)
    assert (
        "the goal is not satisfied at the end of the plan: (at torque_wrench_1 workbench_1) is false" in result.stdout
    )
    plan.write_text("(move entrance_1 entrance_1)\n")
    assert "(robot-at entrance_1) is true" in invoke("validate", domain_path, problems[0], plan).stdout


def test_a_failing_comparison_says_its_values():
    domain = read_domain(
        "(define (domain d) (:requirements :numeric-fluents) (:functions (fuel))"
        " (:action go :parameters () :precondition (>= (fuel) 10) :effect (decrease (fuel) 10)))"
    )
    problem = read_problem("(define (problem p) (:domain d) (:init (= (fuel) 3)) (:goal (< (fuel) 0)))", domain)
    from relevance_plan.pddl.plans import Plan, PlanStep
    from relevance_plan.planning.validation import simulate

    found = simulate(domain, problem, Plan((PlanStep("go", ()),)))
    assert found.message == "step 1 (go): precondition not satisfied: (>= (fuel) 10) is false (3 >= 10)"


def test_an_unclosed_list_is_reported_where_it_opens_and_where_the_file_ends():
    text = (world("workshop")[0]).read_text()
    broken = text.replace(
        "(and (robot-at ?a) (at ?i ?a) (hand-empty))", "(and (robot-at ?a) (at ?i ?a) (hand-empty)", 1
    )
    with pytest.raises(PDDLParseError) as raised:
        read_domain(broken, "domain.pddl")
    opened = text[: text.index("(:action pick")].count("\n") + 1
    following = text[: text.index("(:action put\n")].count("\n") + 1
    last = broken.rstrip("\n").count("\n") + 1
    assert raised.value.line == opened
    assert f"the list opened on line {opened} is probably never closed (line {following} starts" in str(raised.value)
    assert f"where the file ends on line {last}" in str(raised.value)
    with pytest.raises(PDDLParseError, match=r"the list opened on line 1 is never closed \(the file ends on line 1\)"):
        read_domain("(define (domain d) (:predicates (p))", "d.pddl")


# --------------------------------------------------------------------------- plan's summary


@pytest.mark.planner
def test_plan_s_summary_says_what_pruning_kept_whoever_won_the_race(tmp_path):
    domain_path, problems = world("workshop")
    for race in ("--race", "--no-race"):
        output = invoke("plan", domain_path, problems[0], race, "-q", "--plan-file", tmp_path / "plan").stdout
        (pruning,) = [line for line in output.splitlines() if line.startswith("pruning:")]
        assert pruning.startswith("pruning:     kept 5 of 54 objects (2 named in the goal"), pruning


# --------------------------------------------------------------------------- the command line's small promises


def test_counts_are_in_the_right_number():
    assert [counted(n, "step") for n in (0, 1, 2)] == ["0 steps", "1 step", "2 steps"]
    assert counted(1, "entry", "entries") == "1 entry" and counted(3, "entry", "entries") == "3 entries"


def test_examples_says_every_folder_it_wrote(tmp_path):
    result = invoke("examples", tmp_path / "kitchen")
    folders = sorted(p.name + "/" for p in (tmp_path / "kitchen").iterdir())
    assert folders == ["domains/", "examples/", "problems/"]
    assert result.stdout.strip().endswith(f"({', '.join(folders)})")
    count = sum(1 for _ in (tmp_path / "kitchen").rglob("*") if _.is_file())
    assert result.stdout.startswith(f"wrote {count} files to ")


def test_watch_takes_no_race_and_refuses_race(tmp_path):
    events = tmp_path / "events.jsonl"
    events.write_text('{"event": "remove", "object": "side_plate_1"}\n')
    scene = tmp_path / "scene.pddl"
    scene.write_text(coffee_problem(extra_plates=1))
    assert invoke("watch", COFFEE_DOMAIN, scene, "--events", events, "--no-race").exit_code == 0
    result = invoke("watch", COFFEE_DOMAIN, scene, "--events", events, "--race")
    assert result.exit_code == ExitCode.USAGE and "never races" in one_line_error(result.stderr)


def test_generate_takes_o_as_the_other_commands_do(tmp_path):
    result = invoke("generate", "coffee", "--count", "1", "-o", tmp_path / "suite")
    assert result.exit_code == 0 and "wrote 1 problem to" in result.stdout


def test_the_help_and_planners_say_where_fast_downward_is():
    from relevance_plan.planning.planners.fast_downward.command_line import driver_location

    assert "up-fast-downward" in invoke("--help").stdout and "relevance-plan planners" in invoke("--help").stdout
    (line,) = [line for line in invoke("planners").stdout.splitlines() if line.startswith("fast-downward")]
    assert driver_location() in line


def test_shell_completion_works_as_the_docs_say():
    env = {**os.environ, "_RELEVANCE_PLAN_COMPLETE": "bash_source"}
    script = subprocess.run(TOOL, env=env, capture_output=True, text=True, timeout=60)
    assert script.returncode == 0 and "complete -o nosort -F _relevance_plan_completion" in script.stdout
    env = {
        **os.environ,
        "_RELEVANCE_PLAN_COMPLETE": "bash_complete",
        "COMP_WORDS": "relevance-plan dr",
        "COMP_CWORD": "1",
    }
    words = subprocess.run(TOOL, env=env, capture_output=True, text=True, timeout=60)
    assert "plain,draft-model" in words.stdout.splitlines()
    documented = (REPO / "docs" / "command-reference.md").read_text()
    assert "_RELEVANCE_PLAN_COMPLETE=bash_source relevance-plan" in documented
