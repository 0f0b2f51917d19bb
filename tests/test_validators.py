"""The builtin validator agrees with unified-planning's on valid and broken plans."""

import pytest
from support import coffee_problem

from relevance_plan.io import load_domain
from relevance_plan.pddl.parser import read_domain, read_problem
from relevance_plan.pddl.plans import Plan, PlanStep, format_plan, read_plan
from relevance_plan.planning.validation import (
    ValidationStatus,
    validate_builtin,
    validate_plan,
    validate_with_up,
)


def plan_of(*steps: tuple) -> Plan:
    return Plan(tuple(PlanStep(step[0], tuple(step[1:])) for step in steps))


COFFEE_PLAN = """
(unstack dinner_plate_1 plastic_cup_1 counter_1)
(put-down dinner_plate_1 counter_1)
(pick cold_brew_1 counter_1)
(pour-coffee cold_brew_1 plastic_cup_1 counter_1)
(put-down cold_brew_1 counter_1)
(move counter_1 fridge_1)
(open fridge_1)
(pick creamer_1 fridge_1)
(move fridge_1 counter_1)
(add-whitener creamer_1 plastic_cup_1 counter_1)
(put-down creamer_1 counter_1)
(pick stir_stick_1 counter_1)
(stir stir_stick_1 plastic_cup_1 counter_1)
(put-down stir_stick_1 counter_1)
(pick plastic_cup_1 counter_1)
(move counter_1 table_1)
(serve-coffee plastic_cup_1 alice table_1)
; cost = 17 (unit cost)
"""


@pytest.fixture
def task(coffee_domain_path, tmp_path):
    problem_path = tmp_path / "p.pddl"
    problem_path.write_text(coffee_problem())
    domain = load_domain(coffee_domain_path)
    return domain, read_problem(problem_path.read_text(), domain, str(problem_path))


def test_valid_plan_is_valid_for_both_validators(task):
    domain, problem = task
    plan = read_plan(COFFEE_PLAN)
    assert len(plan) == 17
    assert validate_builtin(domain, problem, plan).status is ValidationStatus.VALID
    assert validate_with_up(domain, problem, plan).status is ValidationStatus.VALID


@pytest.mark.parametrize(
    "broken, step",
    [
        (lambda p: p[1:], 1),  # the plate is still on the cup: pick... fails at step 1 (put-down without holding)
        (lambda p: p[:-1], None),  # goal not reached
        (lambda p: p[:5] + p[6:], 6),  # skip the move to the fridge: open fails
        (lambda p: (PlanStep("pick", ("ghost_cup", "counter_1")),) + p, 1),  # unknown object
        (lambda p: (PlanStep("fly", ("counter_1",)),) + p, 1),  # unknown action
    ],
)
def test_broken_plans_are_invalid_for_both_validators(task, broken, step):
    domain, problem = task
    plan = Plan(broken(read_plan(COFFEE_PLAN).steps))
    builtin = validate_builtin(domain, problem, plan)
    assert builtin.status is ValidationStatus.INVALID
    assert builtin.failed_step == step
    assert validate_with_up(domain, problem, plan).status is ValidationStatus.INVALID


def test_adl_features_quantifiers_conditional_effects_equality():
    domain = read_domain(
        """(define (domain lights)
          (:requirements :adl)
          (:types lamp room)
          (:predicates (on ?l - lamp) (in ?l - lamp ?r - room) (lit ?r - room))
          (:action switch-all
            :parameters (?r - room)
            :precondition (exists (?l - lamp) (in ?l ?r))
            :effect (forall (?l - lamp) (when (in ?l ?r) (on ?l))))
          (:action mark
            :parameters (?r - room ?s - room)
            :precondition (and (not (= ?r ?s)) (forall (?l - lamp) (imply (in ?l ?r) (on ?l))))
            :effect (lit ?r)))"""
    )
    problem = read_problem(
        """(define (problem p) (:domain lights)
          (:objects a b - lamp kitchen hall - room)
          (:init (in a kitchen) (in b hall))
          (:goal (and (lit kitchen) (not (on b)))))""",
        domain,
    )
    good = plan_of(("switch-all", "kitchen"), ("mark", "kitchen", "hall"))
    assert validate_builtin(domain, problem, good).valid
    assert not validate_builtin(domain, problem, plan_of(("mark", "kitchen", "hall"))).valid
    assert not validate_builtin(
        domain, problem, plan_of(("switch-all", "kitchen"), ("mark", "kitchen", "kitchen"))
    ).valid
    assert not validate_builtin(
        domain, problem, plan_of(("switch-all", "hall"), ("switch-all", "kitchen"), ("mark", "kitchen", "hall"))
    ).valid


def test_no_runnable_validator_is_reported_not_guessed(task, monkeypatch):
    domain, problem = task
    from relevance_plan.planning.validation import val_program as val

    monkeypatch.setattr(val, "find_validate", lambda: None)
    result = validate_plan(domain, problem, read_plan(COFFEE_PLAN), validators=("val",))
    assert result.status is ValidationStatus.UNAVAILABLE
    assert not result.valid and "pip install 'relevance-plan[val]'" in result.message


def test_plan_format_round_trips_with_user_spelling(task):
    domain, problem = task
    plan = read_plan(COFFEE_PLAN)
    text = format_plan(plan, problem.spelling)
    assert read_plan(text) == plan
    assert text.rstrip().endswith("; cost = 17")
