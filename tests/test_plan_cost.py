"""A plan's cost as `plan` and the store report it: VAL's "Final value" (the validated total-cost),
the length of a plan without action costs (unit cost), None where neither applies."""

from __future__ import annotations

import json

import pytest
from support import invoke, write_file

from relevance_plan.errors import counted
from relevance_plan.io import load_domain, load_problem
from relevance_plan.pddl.plans import read_plan
from relevance_plan.planning.summary import plan_cost_of
from relevance_plan.planning.validation import validate_plan

ROADS = """(define (domain roads)
  (:requirements :typing :action-costs)
  (:types place)
  (:predicates (at ?p - place) (road ?a ?b - place))
  (:functions (total-cost) (length ?a ?b - place))
  (:action drive :parameters (?a ?b - place)
    :precondition (and (at ?a) (road ?a ?b))
    :effect (and (not (at ?a)) (at ?b) (increase (total-cost) (length ?a ?b)))))
"""

TRIP = """(define (problem trip) (:domain roads)
  (:objects home shop far - place)
  (:init (at home) (road home shop) (road shop far) (road home far)
         (= (length home shop) 4) (= (length shop far) 5) (= (length home far) 30) (= (total-cost) 0))
  (:goal (at far))
  (:metric minimize (total-cost)))
"""

NO_COSTS_DOMAIN = (
    ROADS.replace(" :action-costs", "")
    .replace("(:functions (total-cost) (length ?a ?b - place))", "")
    .replace("(increase (total-cost) (length ?a ?b))", "")
)
NO_COSTS_PROBLEM = TRIP.replace(
    "(= (length home shop) 4) (= (length shop far) 5) (= (length home far) 30) (= (total-cost) 0)", ""
).replace("(:metric minimize (total-cost))", "")

TWO_LEGS = "(drive home shop)\n(drive shop far)\n; cost = 2 (unit cost)\n"


def task(tmp_path, domain_text, problem_text):
    tmp_path.mkdir(exist_ok=True)
    domain = load_domain(write_file(tmp_path, "domain.pddl", domain_text))
    return domain, load_problem(write_file(tmp_path, "problem.pddl", problem_text), domain)


def test_the_cost_of_a_problem_with_action_costs_is_the_validated_total_cost(tmp_path):
    domain, problem = task(tmp_path, ROADS, TRIP)
    plan = read_plan(TWO_LEGS)  # the planner's cost line is wrong on purpose: the validator's sum wins
    validation = validate_plan(domain, problem, plan, ("builtin",))
    assert validation.valid and validation.cost == 9
    assert plan_cost_of(problem, plan, validation, plan.cost) == 9


def test_without_action_costs_the_cost_is_the_length(tmp_path):
    domain, problem = task(tmp_path, NO_COSTS_DOMAIN, NO_COSTS_PROBLEM)
    plan = read_plan(TWO_LEGS.replace("2 (unit cost)", "77"))
    validation = validate_plan(domain, problem, plan, ("builtin",))
    assert validation.valid and validation.cost is None
    assert plan_cost_of(problem, plan, validation, plan.cost) == len(plan) == 2


def test_an_unvalidated_plan_of_a_costed_problem_keeps_the_planners_word(tmp_path):
    domain, problem = task(tmp_path, ROADS, TRIP)
    plan = read_plan(TWO_LEGS.replace("2 (unit cost)", "9"))
    validation = validate_plan(domain, problem, plan, ("none",))
    assert not validation.valid and validation.accepted
    assert plan_cost_of(problem, plan, validation, plan.cost) == 9
    assert plan_cost_of(problem, plan, validation, None) is None


@pytest.mark.planner
def test_plan_prints_the_cost_beside_the_length_and_in_json(tmp_path):
    domain = write_file(tmp_path, "domain.pddl", ROADS)
    problem = write_file(tmp_path, "problem.pddl", TRIP)
    plan_file = tmp_path / "trip.plan"
    result = invoke("plan", domain, problem, "--method", "pure", "--plan-file", plan_file, "--timeout", "60")
    assert result.exit_code == 0, result.output
    written = read_plan(plan_file.read_text())
    expected = validate_plan(*task(tmp_path / "check", ROADS, TRIP), written, ("builtin",)).cost
    assert expected in (9, 30)  # home-shop-far or the long road, whichever the planner found
    line = next(line for line in result.stdout.splitlines() if line.startswith("plan:"))
    assert f"{counted(len(written), 'step')}, cost {expected:g}," in line  # "1 step": the plan is one move
    assert written.cost == expected  # the plan file's cost line says the same
    data = json.loads(
        invoke("plan", domain, problem, "--method", "pure", "--plan-file", tmp_path / "j.plan", "--json").stdout
    )
    assert (
        data["plan_cost"]
        == validate_plan(
            *task(tmp_path / "check", ROADS, TRIP), read_plan((tmp_path / "j.plan").read_text()), ("builtin",)
        ).cost
    )


@pytest.mark.planner
def test_plan_reports_the_length_as_the_cost_without_action_costs(tmp_path):
    domain = write_file(tmp_path, "domain.pddl", NO_COSTS_DOMAIN)
    problem = write_file(tmp_path, "problem.pddl", NO_COSTS_PROBLEM)
    result = invoke("plan", domain, problem, "--method", "pure", "--plan-file", tmp_path / "p.plan", "--json")
    data = json.loads(result.stdout)
    assert data["plan_length"] == 1 and data["plan_cost"] == 1  # the direct road: one step
