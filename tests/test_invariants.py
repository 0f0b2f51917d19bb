"""Positions at which no action gives an object one more fact, and the functional positions they hold
while a minority of objects there have two facts."""

from __future__ import annotations

import pytest

from relevance_plan.data import DOMAINS_DIR
from relevance_plan.generators import WORLDS, Settings
from relevance_plan.io import load_domain
from relevance_plan.pddl.model import TimedLiteral
from relevance_plan.pddl.parser import read_domain, read_problem
from relevance_plan.relevance.analysis.facts import index_init
from relevance_plan.relevance.analysis.goal_regression import analyse_goal
from relevance_plan.relevance.analysis.invariants import count_keeping_for, count_keeping_positions
from relevance_plan.relevance.analysis.task import PlanningTask

SCENEGRAPH = DOMAINS_DIR / "scenegraph" / "domain.pddl"


def scene_task(size: int = 300, seed: int = 1, extra: tuple = ()) -> PlanningTask:
    """A generated scene graph, with ``extra`` facts added to its initial state."""
    domain = load_domain(SCENEGRAPH)
    text = WORLDS["scenegraph"].problem(seed, 1, Settings(size=size)).pddl_text
    if extra:
        facts = " ".join(f"({' '.join(fact)})" for fact in extra)
        text = text.replace("(:init", f"(:init {facts}", 1)
    return PlanningTask(domain, read_problem(text, domain))


def test_the_scene_graph_keeps_an_items_place_the_agents_place_and_the_hand():
    # placing an item takes it from the hand, picking it takes it from its receptacle: an item is in
    # one receptacle or one hand; moving takes the agent from where it was
    expected = {("in", 0), ("holding", 0), ("holding", 1), ("agent-at", 0)}
    assert count_keeping_positions(load_domain(SCENEGRAPH)) == expected


@pytest.mark.parametrize(
    "world,expected",
    [("gripper", {("at", 0), ("carry", 0), ("carry", 1)}), ("blocksworld", {("on", 0)}), ("grid", set())],
)
def test_the_classic_domains_keep_what_their_actions_swap(world, expected):
    assert count_keeping_positions(load_domain(DOMAINS_DIR / world / "domain.pddl")) == expected


TINY = """
(define (domain tiny) (:requirements :strips :typing :conditional-effects)
  (:types thing spot)
  (:predicates (at ?t - thing ?s - spot) (free ?t - thing) (link ?a - spot ?b - spot) (mark ?t - thing ?s - spot))
  (:action lift :parameters (?t - thing ?s - spot)
    :precondition (at ?t ?s) :effect (and (free ?t) (not (at ?t ?s))))
  (:action drop :parameters (?t - thing ?s - spot)
    :precondition (free ?t) :effect (and (at ?t ?s) (not (free ?t))))
  (:action stamp :parameters (?t - thing ?s - spot)
    :precondition (free ?t) :effect (when (free ?t) (mark ?t ?s))))
"""


def test_an_add_without_a_required_delete_or_under_a_condition_keeps_no_count():
    domain = read_domain(TINY)
    # at and free swap; link never changes (the facts alone decide); a mark is added and nothing taken
    assert count_keeping_positions(domain) == {("at", 0)}
    loose = read_domain(TINY.replace("(and (at ?t ?s) (not (free ?t)))", "(at ?t ?s)"))
    assert count_keeping_positions(loose) == set()


def test_a_timed_literal_that_adds_a_fact_frees_its_predicate():
    domain = load_domain(SCENEGRAPH)
    assert ("in", 0) not in count_keeping_for(domain, [TimedLiteral(5.0, ("in", "mug_1", "table_1"))])
    assert ("in", 0) in count_keeping_for(domain, [TimedLiteral(5.0, ("in", "mug_1", "table_1"), negated=True)])


def test_an_item_in_two_receptacles_leaves_the_goals_roles_and_closures_rules_as_they_were():
    task = scene_task()
    item, holder = next((f[1], f[2]) for f in sorted(task.problem.init) if f[0] == "in")
    other = next(f[2] for f in sorted(task.problem.init) if f[0] == "in" and f[2] != holder)
    seen_halfway = scene_task(extra=[("in", item, other)])
    assert ("in", 0, 1) in task.init_index.functional
    assert seen_halfway.init_index.functional == task.init_index.functional
    assert seen_halfway.goal_analysis == task.goal_analysis
    # without what the domain says, the one item would end the rule, and receptacles would become a role
    strict = index_init(seen_halfway.problem)
    assert ("in", 0, 1) not in strict.functional
    assert analyse_goal(task.domain, seen_halfway.problem, strict).role_depth != task.goal_analysis.role_depth


def test_items_in_two_receptacles_end_the_rule_once_they_are_half_of_them():
    task = scene_task(size=120)
    places = sorted((f[1], f[2]) for f in task.problem.init if f[0] == "in")
    receptacles = sorted({holder for _, holder in places})
    second = [("in", item, next(r for r in receptacles if r != holder)) for item, holder in places]
    half = len(places) // 2
    fewer = scene_task(size=120, extra=second[: half - (len(places) % 2 == 0)])
    assert ("in", 0, 1) in fewer.init_index.functional
    assert ("in", 0, 1) not in scene_task(size=120, extra=second[: (len(places) + 1) // 2]).init_index.functional


def test_a_fact_no_action_changes_decides_alone():
    task = scene_task()
    receptacle, place = next((f[1], f[2]) for f in sorted(task.problem.init) if f[0] == "receptacle-at")
    other = next(f[2] for f in sorted(task.problem.init) if f[0] == "receptacle-at" and f[2] != place)
    assert ("receptacle-at", 0, 1) in task.init_index.functional
    moved = scene_task(extra=[("receptacle-at", receptacle, other)])
    assert ("receptacle-at", 0, 1) not in moved.init_index.functional
