"""parse -> format -> parse gives an equal model, names spelled as written included, for every shipped
domain and problem and every PDDL fixture of the tests, and every domain file of the repository's corpus
(benchmarks/corpus)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from support import WORLDS, coffee_problem
from test_names_as_written import MAZE_DOMAIN, MAZE_PROBLEM, MIXED_DOMAIN, MIXED_PROBLEM

from relevance_plan.data import DOMAINS_DIR, PROBLEMS_DIR
from relevance_plan.errors import RelevancePlanError
from relevance_plan.generators.padded import BLOCKSWORLD_DOMAIN, GRIPPER_DOMAIN, blocksworld_problem, gripper_problem
from relevance_plan.pddl.formatter import format_domain, format_problem
from relevance_plan.pddl.model import Domain, Problem
from relevance_plan.pddl.parser import read_domain, read_problem

TEMPORAL_NUMERIC = """(define (domain delivery)
  (:requirements :typing :durative-actions :numeric-fluents :timed-initial-literals :derived-predicates
                 :preferences :constraints :duration-inequalities)
  (:types place - object truck parcel - locatable locatable)
  (:predicates (at ?x - locatable ?p - place) (in ?p - parcel ?t - truck) (open ?p - place) (road ?a ?b - place)
               (ready ?t - truck))
  (:functions (fuel ?t - truck) (distance ?a ?b - place) (total-cost))
  (:derived (ready ?t - truck) (exists (?p - place) (and (at ?t ?p) (open ?p))))
  (:durative-action drive
    :parameters (?t - truck ?a ?b - place)
    :duration (and (>= ?duration (distance ?a ?b)) (<= ?duration (* 2 (distance ?a ?b))))
    :condition (and (at start (at ?t ?a)) (over all (road ?a ?b)) (at start (>= (fuel ?t) (distance ?a ?b))))
    :effect (and (at start (not (at ?t ?a))) (at end (at ?t ?b))
                 (at start (decrease (fuel ?t) (distance ?a ?b))) (at end (increase (total-cost) 1))))
  (:action load
    :parameters (?p - parcel ?t - truck ?x - place)
    :precondition (and (at ?p ?x) (at ?t ?x) (ready ?t) (preference quick (open ?x)))
    :effect (and (not (at ?p ?x)) (in ?p ?t) (forall (?q - parcel) (when (in ?q ?t) (increase (total-cost) 0.5))))))
"""
TEMPORAL_NUMERIC_PROBLEM = """(define (problem deliver-1) (:domain delivery)
  (:objects depot market - place T1 - truck p1 p2 - parcel)
  (:init (at T1 depot) (at p1 depot) (road depot market) (= (fuel T1) 10.5) (= (distance depot market) 3)
         (= (total-cost) 0) (at 5 (open depot)) (at 20 (not (open depot))) (at 2.5 (= (fuel T1) 12)))
  (:goal (and (at p1 market) (preference fast (in p2 T1))))
  (:constraints (and (always (>= (fuel T1) 0)) (within 30 (at p1 market)) (sometime-before (at T1 market) (in p1 T1))))
  (:metric minimize (+ (total-cost) (* 3 (is-violated fast)) (total-time))))
"""


def domain_key(domain: Domain) -> tuple:
    return (
        domain.name,
        domain.requirements,
        dict(domain.types),
        dict(domain.constants),
        dict(domain.predicates),
        dict(domain.functions),
        domain.actions,
        domain.derived,
        domain.constraints,
        domain.spelling,  # every name as the user wrote it
    )


def problem_key(problem: Problem) -> tuple:
    return (
        problem.name,
        dict(problem.objects),
        problem.init,
        dict(problem.numeric_init),
        problem.timed_literals,
        problem.goal,
        problem.constraints,
        problem.metric,
        problem.spelling,
    )


def round_trip(domain_text: str, problem_text: str | None) -> None:
    domain = read_domain(domain_text)
    again = read_domain(format_domain(domain))
    assert domain_key(again) == domain_key(domain)
    if problem_text is not None:
        problem = read_problem(problem_text, domain)
        assert problem_key(read_problem(format_problem(problem), again)) == problem_key(problem)


SHIPPED = [
    (folder.name, folder / "domain.pddl", sorted(PROBLEMS_DIR.glob(f"{folder.name}-*.pddl")))
    for folder in sorted(DOMAINS_DIR.iterdir())
]


@pytest.mark.parametrize("name, domain, problems", SHIPPED, ids=[s[0] for s in SHIPPED])
def test_every_shipped_domain_and_problem_round_trips(name, domain, problems):
    text = domain.read_text()
    round_trip(text, None)
    for problem in problems:
        round_trip(text, problem.read_text())


FIXTURES = {
    "coffee": (DOMAINS_DIR / "coffee" / "domain.pddl").read_text(),
    "blocksworld": BLOCKSWORLD_DOMAIN,
    "gripper": GRIPPER_DOMAIN,
    "temporal-numeric": TEMPORAL_NUMERIC,
}


@pytest.mark.parametrize(
    "domain, problem",
    [
        (FIXTURES["coffee"], coffee_problem(extra_plates=3)),
        (BLOCKSWORLD_DOMAIN, blocksworld_problem(20, seed=1)),
        (GRIPPER_DOMAIN, gripper_problem(30)),
        (TEMPORAL_NUMERIC, TEMPORAL_NUMERIC_PROBLEM),
        (MIXED_DOMAIN, MIXED_PROBLEM),
        (MAZE_DOMAIN, MAZE_PROBLEM),
        *((domain, make(1)) for domain, make in WORLDS.values()),
    ],
    ids=["coffee", "blocksworld", "gripper", "temporal-numeric", "mixed-case", "mini-maze", *WORLDS],
)
def test_every_test_fixture_round_trips(domain, problem):
    round_trip(domain, problem)


CORPUS = Path(__file__).resolve().parent.parent / "benchmarks" / "corpus"


def test_the_corpus_domains_round_trip():
    """Every domain file of the corpus: its manifest says which files are domains (pddlgym's
    ``NAME.pddl`` included); a domain the reader refuses is the acceptance sweep's business."""
    manifest = json.loads((CORPUS / "MANIFEST.json").read_text(encoding="utf-8"))
    paths = [CORPUS / entry["path"] for entry in manifest["files"] if entry.get("role") == "domain"]
    checked = 0
    for domain_path in paths:
        try:
            text = domain_path.read_text(errors="replace")
            read_domain(text)
        except RelevancePlanError:
            continue
        round_trip(text, None)
        checked += 1
    assert len(paths) >= 150 and checked >= len(paths) * 9 // 10
