"""The sharper relaxed check for temporal and numeric problems: it refutes only what has no plan."""

from __future__ import annotations

import pytest

import relevance_plan as rp
from relevance_plan.data import DOMAINS_DIR
from relevance_plan.generators import WORLDS, Settings
from relevance_plan.io import load_sources
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.reachability.exploration import relaxed_reachability
from relevance_plan.relevance.reachability.timed_relaxation import timed_relaxed_reachability

ROVER_DOMAIN = """(define (domain rover)
  (:requirements :strips :typing :numeric-fluents :durative-actions)
  (:types rover place charger)
  (:predicates (at ?r - rover ?p - place) (road ?a - place ?b - place) (charger-at ?c - charger ?p - place)
               (armed ?r - rover) (ready ?r - rover))
  (:functions (battery ?r - rover))
  (:durative-action drive
    :parameters (?r - rover ?a - place ?b - place)
    :duration (= ?duration 3)
    :condition (and (at start (at ?r ?a)) (at start (road ?a ?b)) (at start (>= (battery ?r) 5)))
    :effect (and (at start (not (at ?r ?a))) (at end (at ?r ?b)) (at start (decrease (battery ?r) 5))))
  (:durative-action charge
    :parameters (?r - rover ?c - charger ?p - place)
    :duration (= ?duration 2)
    :condition (and (over all (at ?r ?p)) (at start (charger-at ?c ?p)))
    :effect (at end (increase (battery ?r) 4)))
  (:durative-action prime
    :parameters (?r - rover)
    :duration (= ?duration 1)
    :condition (and (at end (armed ?r)))
    :effect (and (at start (armed ?r)) (at end (ready ?r)))))
"""


def rover_problem(battery: float, goal: str = "(at r1 p2)") -> str:
    return f"""(define (problem rover-1) (:domain rover)
  (:objects r1 - rover p1 p2 - place c1 - charger)
  (:init (at r1 p1) (road p1 p2) (charger-at c1 p1) (= (battery r1) {battery}))
  (:goal {goal}))
"""


def task_of(domain: str, problem: str) -> PlanningTask:
    return PlanningTask(*load_sources(domain, problem))


def test_a_battery_no_kept_charger_can_fill_refutes_the_selection_the_delete_relaxation_admits():
    task = task_of(ROVER_DOMAIN, rover_problem(3))
    without_charger = {"r1", "p1", "p2"}
    assert relaxed_reachability(task, without_charger).reachable  # numbers ignored
    assert timed_relaxed_reachability(task, without_charger) is False
    assert timed_relaxed_reachability(task, without_charger | {"c1"}) is True  # charge, then drive


def test_enough_battery_and_an_end_condition_met_by_the_actions_own_start_are_admitted():
    task = task_of(ROVER_DOMAIN, rover_problem(7))
    assert timed_relaxed_reachability(task, {"r1", "p1", "p2"}) is True
    # prime needs (armed r1) at its end, which its own start adds: a plan exists
    task = task_of(ROVER_DOMAIN, rover_problem(7, "(ready r1)"))
    assert timed_relaxed_reachability(task, {"r1"}) is True


def test_a_numeric_goal_is_checked_against_the_reachable_interval():
    assert timed_relaxed_reachability(task_of(ROVER_DOMAIN, rover_problem(3, "(>= (battery r1) 10)")), {"r1"}) is False
    task = task_of(ROVER_DOMAIN, rover_problem(3, "(>= (battery r1) 10)"))
    assert timed_relaxed_reachability(task, {"r1", "p1", "c1"}) is True  # charging repeats


def test_the_repaired_selection_is_admitted_by_the_sharper_check():
    selection = rp.prune(ROVER_DOMAIN, rover_problem(3), scorer="goal")
    assert "c1" in selection.kept
    assert timed_relaxed_reachability(selection.task, selection.kept) is True


@pytest.mark.parametrize("world", ["driverlog-temporal", "zenotravel-numeric"])
@pytest.mark.parametrize("index", range(3))
def test_the_generated_worlds_full_problems_and_first_selections_are_admitted(world, index):
    # every generated problem is solvable: the check must never refute it, nor the first selection
    generated = WORLDS[world].problem(0, index, Settings(size=60))
    selection = rp.prune(DOMAINS_DIR / world / "domain.pddl", generated.pddl_text)
    assert timed_relaxed_reachability(selection.task, selection.task.problem.objects.keys()) is True
    assert timed_relaxed_reachability(selection.task, selection.kept) is True


UPLINK_DOMAIN = """(define (domain uplink)
  (:requirements :strips :typing :durative-actions :timed-initial-literals :numeric-fluents)
  (:types probe station)
  (:predicates (measured ?p - probe) (visible ?s - station ?p - probe) (sent ?p - probe))
  (:functions (send-time ?s - station))
  (:durative-action measure
    :parameters (?p - probe)
    :duration (= ?duration 2)
    :condition ()
    :effect (at end (measured ?p)))
  (:durative-action send
    :parameters (?s - station ?p - probe)
    :duration (= ?duration (send-time ?s))
    :condition (and (at start (measured ?p)) (over all (visible ?s ?p)))
    :effect (at end (sent ?p))))
"""


def uplink_problem(stations: int, numeric: bool) -> str:
    names = " ".join(f"s{i}" for i in range(stations))
    windows = " ".join(f"(at 10 (visible s{i} p1)) (at 30 (not (visible s{i} p1)))" for i in range(stations))
    times = " ".join(f"(= (send-time s{i}) 4)" for i in range(stations)) if numeric else ""
    return f"""(define (problem uplink-1) (:domain uplink)
  (:objects p1 - probe {names} - station)
  (:init {windows} {times})
  (:goal (sent p1)))
"""


@pytest.mark.parametrize("numeric", [True, False], ids=["with-numeric-values", "facts-only"])
def test_a_fact_only_a_timed_literal_makes_true_is_reached_by_the_delete_relaxation(numeric):
    # the window of visibility opens at 10: a plan waits for it, so one station is enough
    domain = UPLINK_DOMAIN
    if not numeric:
        domain = domain.replace("(:functions (send-time ?s - station))", "").replace("(send-time ?s)", "4")
    task = task_of(domain, uplink_problem(12, numeric))
    assert relaxed_reachability(task, {"p1", "s0"}).reachable
    selection = rp.prune(domain, uplink_problem(12, numeric), scorer="goal")
    assert len(selection.kept) == 2  # the probe and one station, not all twelve


WATERING_DOMAIN = """(define (domain watering)
  (:requirements :typing :numeric-fluents)
  (:types agent tap plant)
  (:functions (carrying ?a - agent) (poured ?p - plant))
  (:action load
    :parameters (?a - agent ?t - tap)
    :precondition (<= (carrying ?a) 4)
    :effect (increase (carrying ?a) 1))
  (:action pour
    :parameters (?a - agent ?p - plant)
    :precondition (>= (carrying ?a) 1)
    :effect (and (decrease (carrying ?a) 1) (increase (poured ?p) 1))))
"""


def test_a_class_the_selection_lacks_is_tried_before_more_members_of_a_tied_class():
    # thirty agents, tied with the tap at score 0 and first by name: one agent and the tap suffice
    agents = [f"a{i:02}" for i in range(30)]
    problem = f"""(define (problem watering-1) (:domain watering)
  (:objects {" ".join(agents)} - agent zt - tap p1 - plant)
  (:init {" ".join(f"(= (carrying {a}) 0)" for a in agents)} (= (poured p1) 0))
  (:goal (>= (poured p1) 2)))
"""
    selection = rp.prune(WATERING_DOMAIN, problem, scorer="goal")
    assert "zt" in selection.kept
    assert len(selection.kept) == 3  # p1, one agent, the tap
    assert timed_relaxed_reachability(selection.task, selection.kept) is True


def test_without_numeric_conditions_effects_or_goals_the_check_is_skipped_for_it_cannot_refute():
    import random

    from relevance_plan.relevance.reachability.timed_relaxation import applies

    assert applies(task_of(ROVER_DOMAIN, rover_problem(3)))
    # durations read from functions, but no number in a condition, an effect or the goal
    generated = WORLDS["driverlog-temporal"].problem(0, 0, Settings(size=30))
    domain_text = (DOMAINS_DIR / "driverlog-temporal" / "domain.pddl").read_text()
    task = task_of(domain_text, generated.pddl_text)
    assert task.domain.temporal and task.domain.numeric and not applies(task)
    # each part of a split durative action needs a subset of the whole action's conditions:
    # whatever the delete relaxation admits, the sharper check admits too
    names = sorted(task.problem.objects)
    admitted = 0
    for seed in range(25):
        subset = set(random.Random(seed).sample(names, len(names) - 1 - seed % 12))  # 1 to 12 left out
        if relaxed_reachability(task, subset).reachable:
            admitted += 1
            assert timed_relaxed_reachability(task, subset) is True
    assert admitted >= 5  # the property was tested at all (8 of the 25 subsets when written)
