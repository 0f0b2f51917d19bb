"""Temporal, numeric and PDDL3 inputs: read, pruned, refused by a planner in one line, timed plans validated."""

from __future__ import annotations

import json

from hostile.inputs import TEMPORAL_DOMAIN, TEMPORAL_PROBLEM, files, planner, says
from hostile.scenario import MISMATCH, OK, PDDL, UNSUPPORTED, Scenario, scenario_test

T, N = "temporal/domain.pddl", "numeric/domain.pddl"
TP = ("plan", T, "temporal/p1.pddl", "-q", "--plan-file", "out.plan")


def _bad_domain(name: str, old: str, new: str, codes: tuple) -> Scenario:
    """``score`` of the temporal domain with ``old`` replaced by ``new``."""
    return Scenario(
        f"temporal/{name}",
        args=("score", "temporal/baddomain.pddl", "temporal/p1.pddl"),
        setup=files(temporal__baddomain_dot_pddl=TEMPORAL_DOMAIN.replace(old, new)),
        codes=codes,
    )


def _bad_problem(name: str, old: str, new: str, codes: tuple) -> Scenario:
    """``score`` of the temporal problem with ``old`` replaced by ``new``."""
    return Scenario(
        f"temporal/{name}",
        args=("score", T, "temporal/bad.pddl"),
        setup=files(temporal__bad_dot_pddl=TEMPORAL_PROBLEM.replace(old, new)),
        codes=codes,
    )


TEMPORAL = [
    Scenario("temporal/score", args=("score", T, "temporal/p1.pddl")),
    Scenario("temporal/prune", args=("prune", T, "temporal/p1.pddl", "-o", "out.pddl"), writes=("out.pddl",)),
    Scenario(
        "temporal/fast-downward-refuses-in-one-line",
        args=TP + ("--planner", "fast-downward"),
        codes=(UNSUPPORTED,),
        quick=True,
    ),
    Scenario("temporal/timed-plan-validated", args=TP + ("--planner", planner("timed_plan.py")), writes=("out.plan",)),
    Scenario(
        "temporal/timed-plan-on-a-pruned-problem-json",
        args=TP + ("--json", "--planner", planner("timed_plan.py")),
        writes=("out.plan",),
        check=says('"status": "solved"', where="stdout"),
    ),
    Scenario(
        "temporal/watch-a-durative-scene",
        args=("watch", T, "temporal/p1.pddl", "--events", "ev.jsonl"),
        setup=files(ev_dot_jsonl=json.dumps({"event": "set", "fact": ["open", "x3"]}) + "\n"),
    ),
    _bad_domain("malformed-duration", "(= ?duration (dist ?a ?b))", "(> ?duration)", (PDDL,)),
    _bad_domain("duration-without-duration-variable", "(= ?duration (dist ?a ?b))", "(= (fuel) 3)", (PDDL,)),
    _bad_domain("undeclared-function", "(>= (fuel) (dist ?a ?b))", "(>= (battery) 1)", (PDDL,)),
    _bad_problem("negative-til-time", "(at 4 (open p2))", "(at -4 (open p2))", (PDDL,)),
    _bad_problem("til-of-an-unknown-object", "(at 4 (open p2))", "(at 4 (open p9))", (MISMATCH,)),
    _bad_problem("initial-value-not-a-number", "(= (fuel) 20)", "(= (fuel) lots)", (UNSUPPORTED, PDDL)),
    _bad_problem("huge-number", "(= (fuel) 20)", "(= (fuel) 1e999)", (OK, PDDL)),
    _bad_domain(
        "pddl-plus-process",
        "(:durative-action drive",
        "(:process leak :parameters () :precondition (and) :effect (decrease (fuel) (* #t 1))) (:durative-action drive",
        (UNSUPPORTED,),
    ),
    _bad_domain(
        "pddl-plus-requirement",
        ":timed-initial-literals)",
        ":timed-initial-literals :continuous-effects)",
        (UNSUPPORTED,),
    ),
    _bad_domain("object-fluents", "(fuel))", "(fuel) (tank) - place)", (UNSUPPORTED,)),
]

# numeric fluents, and PDDL3 preferences and constraints
NUMERIC_AND_PDDL3 = [
    Scenario("numeric/score", args=("score", N, "numeric/p1.pddl")),
    Scenario(
        "numeric/prune", args=("prune", N, "numeric/p1.pddl", "-o", "-"), check=says("(value c1)", where="stdout")
    ),
    Scenario(
        "numeric/fast-downward-refuses",
        args=("plan", N, "numeric/p1.pddl", "-q", "--planner", "fast-downward"),
        codes=(UNSUPPORTED,),
    ),
    Scenario(
        "pddl3/prune-keeps-constraints",
        args=("prune", "D.pddl", "P3.pddl", "-o", "-"),
        check=says(":constraints", "preference", where="stdout"),
    ),
    Scenario(
        "pddl3/fast-downward-refuses",
        args=("plan", "D.pddl", "P3.pddl", "-q", "--planner", "fast-downward"),
        codes=(UNSUPPORTED,),
    ),
]

SCENARIOS = TEMPORAL + NUMERIC_AND_PDDL3


test_temporal_numeric_and_pddl3 = scenario_test(SCENARIOS)
