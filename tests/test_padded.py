"""Padding any parsed problem with clones of objects the goal does not need (``generators.padded``)."""

from __future__ import annotations

import pytest

from relevance_plan.errors import UsageError
from relevance_plan.generators.padded import CLONE_MARK, pad_with_clones
from relevance_plan.pddl.formatter import format_problem
from relevance_plan.pddl.parser import read_domain, read_problem

DOMAIN = """(define (domain haul)
  (:requirements :typing :durative-actions :numeric-fluents :timed-initial-literals)
  (:types place vehicle parcel)
  (:constants depot - place)
  (:predicates (at ?v - vehicle ?p - place) (in ?c - parcel ?p - place) (road ?a ?b - place)
               (open ?p - place))
  (:functions (distance ?a ?b - place) (fuel ?v - vehicle))
  (:durative-action drive
    :parameters (?v - vehicle ?a ?b - place)
    :duration (= ?duration (distance ?a ?b))
    :condition (and (at start (at ?v ?a)) (over all (road ?a ?b)) (at start (>= (fuel ?v) 1)))
    :effect (and (at start (not (at ?v ?a))) (at end (at ?v ?b)) (at end (decrease (fuel ?v) 1)))))
"""

PROBLEM = """(define (problem haul-1) (:domain haul)
  (:objects Home Shop Loop Yard - place Van Truck - vehicle box crate - parcel)
  (:init (at Van home) (at truck yard) (in box home) (in crate shop)
         (road home shop) (road shop home) (road yard home) (road depot home) (road loop loop)
         (= (distance home shop) 3) (= (distance shop home) 3) (= (distance loop loop) 1)
         (= (fuel van) 5) (= (fuel truck) 2)
         (at 10 (open shop)) (at 20 (not (open shop))) (at 15 (open yard)))
  (:goal (and (at van shop) (in box home))))
"""


def task():
    domain = read_domain(DOMAIN)
    return domain, read_problem(PROBLEM, domain)


def clones_of(padded):
    """clone -> its source, read from the clone's name."""
    return {name: name.rsplit(CLONE_MARK, 1)[0] for name in padded.objects if CLONE_MARK in name}


def swapped(atom, source, clone):
    return (atom[0], *(clone if arg == source else arg for arg in atom[1:]))


# (at ?v ?p), (fuel ?v) change by the action and (open ?p) by timed literals; (in ?c ?p), (road ?a ?b)
# and (distance ?a ?b) never change
CHANGING = {"at", "fuel", "open"}


def gets(term, source):
    """Whether a clone of ``source`` gets this fact or value: static ones all, the state only as its first argument."""
    return source in term[1:] and (term[0] not in CHANGING or term[1] == source)


def test_each_clone_has_its_sources_type_static_facts_and_own_state():
    domain, problem = task()
    padded = pad_with_clones(domain, problem, 9, seed=3)
    clones = clones_of(padded)
    assert len(clones) == 9 and len(padded.objects) == len(problem.objects) + 9
    for clone, source in clones.items():
        assert padded.objects[clone] == problem.objects[source]
        facts = {atom for atom in padded.init if clone in atom[1:]}
        assert facts == {swapped(atom, source, clone) for atom in problem.init if gets(atom, source)}
        values = {term: value for term, value in padded.numeric_init.items() if clone in term[1:]}
        expected = {swapped(t, source, clone): v for t, v in problem.numeric_init.items() if gets(t, source)}
        assert values == expected
        timed = [literal for literal in padded.timed_literals if literal.atom and clone in literal.atom[1:]]
        assert len(timed) == sum(1 for literal in problem.timed_literals if literal.atom and gets(literal.atom, source))
    assert {"truck", "yard"} <= set(clones.values())  # the cases below are there
    for clone, source in clones.items():
        if source == "truck":  # a vehicle's own state: where it stands, its fuel
            assert ("at", clone, "yard") in padded.init and padded.numeric_init[("fuel", clone)] == 2
        if source == "yard":  # a place's static facts and timed literals, not what stands there
            assert ("road", clone, "home") in padded.init
            assert not any(atom[0] == "at" and clone in atom for atom in padded.init)
            assert any(literal.atom == ("open", clone) for literal in padded.timed_literals)
    # no vehicle stands in two places
    standing = [atom[1] for atom in padded.init if atom[0] == "at"]
    assert len(standing) == len(set(standing))
    # every occurrence: the loop road of a cloned 'loop' leads from the clone to the clone
    for clone, source in clones.items():
        if source == "loop":
            assert ("road", clone, clone) in padded.init and padded.numeric_init[("distance", clone, clone)] == 1
    # what the original had is all still there, the goal is the same
    assert problem.init <= padded.init
    assert set(problem.numeric_init.items()) <= set(padded.numeric_init.items())
    assert padded.goal == problem.goal and padded.metric == problem.metric


def test_sources_are_never_goal_objects_or_constants_and_every_type_gets_clones():
    domain, problem = task()
    padded = pad_with_clones(domain, problem, 6)
    sources = set(clones_of(padded).values())
    assert not sources & {"van", "shop", "box", "home", "depot"}  # named by the goal, or a constant
    assert sorted(padded.objects[clone] for clone in clones_of(padded)) == sorted(["place", "vehicle", "parcel"] * 2)


def test_the_same_seed_gives_the_same_problem():
    domain, problem = task()
    first, again = (format_problem(pad_with_clones(domain, problem, 7, seed=5)) for _ in range(2))
    assert first == again
    picks = {tuple(sorted(clones_of(pad_with_clones(domain, problem, 1, seed=s)).values())) for s in range(10)}
    assert len(picks) > 1  # the seed chooses among the sources of the first type


def test_the_padded_problem_round_trips_through_the_writer_in_the_users_spelling():
    domain, problem = task()
    padded = pad_with_clones(domain, problem, 12, seed=1)
    text = format_problem(padded)
    assert "Loop-pad1" in text or "Truck-pad1" in text  # the source's spelling, the clone's number
    again = read_problem(text, domain)
    assert dict(again.objects) == dict(padded.objects)
    assert again.init == padded.init and dict(again.numeric_init) == dict(padded.numeric_init)
    assert sorted(map(repr, again.timed_literals)) == sorted(map(repr, padded.timed_literals))
    assert again.goal == problem.goal


def test_clone_names_are_fresh():
    domain = read_domain(DOMAIN)
    problem = read_problem(PROBLEM.replace("crate - parcel", "crate crate-pad1 - parcel"), domain)
    padded = pad_with_clones(domain, problem, 6, seed=0)
    assert len(padded.objects) == len(problem.objects) + 6  # no clone took crate-pad1's name


def test_nothing_to_clone_is_said_not_skipped():
    domain = read_domain(DOMAIN)
    every = PROBLEM.replace("(in box home))))", "(in box home) (at truck loop) (in crate yard))))")
    problem = read_problem(every, domain)
    with pytest.raises(UsageError, match="goal names every object"):
        pad_with_clones(domain, problem, 3)
    assert pad_with_clones(domain, problem, 0) is problem
    with pytest.raises(UsageError, match="at least 0"):
        pad_with_clones(domain, problem, -1)


def test_the_padded_worlds_are_written_for_the_shipped_domains():
    from relevance_plan.data import DOMAINS_DIR
    from relevance_plan.generators import padded

    for name, text, problem in (
        ("blocksworld-typed", padded.BLOCKSWORLD_DOMAIN, padded.blocksworld_problem(5, seed=1)),
        ("gripper-typed", padded.GRIPPER_DOMAIN, padded.gripper_problem(5)),
    ):
        assert text == (DOMAINS_DIR / name / "domain.pddl").read_text(encoding="utf-8")
        domain = read_domain(text)
        assert read_problem(problem, domain).domain_name == domain.name == name
