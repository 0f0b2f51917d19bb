"""learn and its models: hostile options, training sets and model files; learn stopped and killed."""

from __future__ import annotations

import json
import signal

from hostile.inputs import after, both, every, files, json_only, one_line, says, store
from hostile.scenario import INPUT, INTERRUPTED, MODEL, STORE, USAGE, Scenario, scenario_test

LEARN = ("learn", "D.pddl", "P.pddl", "-o", "m.json", "-q")
GATE_DOMAIN = """(define (domain gate)
  (:requirements :strips)
  (:predicates (open) (inside))
  (:action enter :parameters () :precondition (open) :effect (inside)))
"""
GATES = files(
    gate__domain_dot_pddl=GATE_DOMAIN,
    gate__shut_dot_pddl="(define (problem shut) (:domain gate) (:init) (:goal (inside)))",
    gate__open_dot_pddl="(define (problem open) (:domain gate) (:init (open)) (:goal (inside)))",
    gate__people_dot_pddl="(define (problem people) (:domain gate) (:objects ann bob) (:init (open)) (:goal (inside)))",
)

OPTIONS = [
    *(
        Scenario(
            f"learning/{option.strip('-')}-{label}",
            args=LEARN + (option, value),
            codes=(USAGE,),
            check=one_line(option),
            quick=label == "nan",
        )
        for option in ("--timeout", "--time-limit")
        for label, value in (("nan", "nan"), ("inf", "inf"), ("zero", "0"), ("negative", "-1"), ("huge", "1e999"))
    ),
    Scenario("learning/seed-not-a-number", args=LEARN + ("--seed", "x"), codes=(2,), check=one_line("--seed")),
    Scenario("learning/unknown-labels", args=LEARN + ("--labels", "magic"), codes=(USAGE,), check=one_line("--labels")),
    Scenario("learning/both-timeout-names", args=LEARN + ("--timeout", "5", "--time-limit", "5"), codes=(USAGE,)),
    Scenario("learning/no-training-problem", args=("learn", "D.pddl", "-o", "m.json"), codes=(USAGE,)),
]

TRAINING = [
    Scenario(
        "learning/model-to-standard-output-alone",
        args=("learn", "D.pddl", "P.pddl", "-o", "-", "-q", "--timeout", "30"),
        check=every(json_only, says("model written to standard output")),
        quick=True,
    ),
    Scenario(
        "learning/deprecated-time-limit-still-works",
        args=("learn", "D.pddl", "P.pddl", "-o", "m.json", "-q", "--time-limit", "30"),
        writes=("m.json",),
        check=says("--time-limit is deprecated"),
    ),
    Scenario(
        "learning/a-proved-unsolvable-problem-is-named-so",
        args=("learn", "gate/domain.pddl", "gate/shut.pddl", "-o", "m.json", "--timeout", "20"),
        setup=GATES,
        codes=(USAGE,),
        check=every(says("unsolvable (the planner proved it has no plan)"), lambda r: _not_said(r, "not solved")),
    ),
    Scenario(
        "learning/one-unsolvable-one-solved",
        args=("learn", "gate/domain.pddl", "gate/shut.pddl", "gate/people.pddl", "-o", "m.json", "--timeout", "20"),
        setup=GATES,
        writes=("m.json",),
        check=every(says("skipped (unsolvable"), says("learned from 1 problems (1 skipped)", where="stdout")),
    ),
    Scenario(
        "learning/solved-problems-without-objects",
        args=("learn", "gate/domain.pddl", "gate/open.pddl", "-o", "m.json", "-q", "--timeout", "20"),
        setup=GATES,
        codes=(USAGE,),
        check=one_line("no objects"),
    ),
    Scenario("learning/model-over-the-domain", args=("learn", "D.pddl", "P.pddl", "-o", "D.pddl"), codes=(USAGE,)),
    Scenario(
        "learning/model-in-a-missing-folder", args=("learn", "D.pddl", "P.pddl", "-o", "no/m.json"), codes=(INPUT,)
    ),
    Scenario(
        "learning/a-training-problem-that-is-a-pipe",
        shell="exec $TOOL learn D.pddl <(cat P.pddl) -o m.json -q",
        codes=(INPUT,),
        check=one_line("learn gives it to the planner"),
    ),
    Scenario("learning/a-missing-store", args=LEARN + ("--store", "none.sqlite"), codes=(INPUT,)),
    Scenario(
        "learning/a-store-that-is-text", args=LEARN + ("--store", "notes"), setup=files(notes="x"), codes=(STORE,)
    ),
    Scenario("learning/a-store-without-the-problem", args=LEARN + ("--store", "s.sqlite"), setup=store, codes=(USAGE,)),
    *(
        Scenario(
            f"learning/{name}-while-planning",
            args=("learn", "long/domain.pddl", "long/coffee-hard-001.pddl", "-o", "m.json", "-q", "--timeout", "60"),
            setup=lambda work: _long_training_problem(work),
            codes=codes,
            during=after(2.0, signum),
            writes=("long", "long/*"),
        )
        for name, signum, codes in (
            ("sigterm", signal.SIGTERM, (INTERRUPTED,)),
            ("sigint", signal.SIGINT, (INTERRUPTED,)),
            ("kill-9", signal.SIGKILL, (128 + signal.SIGKILL,)),
        )
    ),
]


def _not_said(result, needle: str) -> str | None:
    return f"stderr says {needle!r}" if needle in result.stderr else None


def _long_training_problem(work) -> None:
    from hostile.test_faults import _long_problem

    _long_problem(work)


def bad_learned_models() -> dict[str, str]:
    """Learned-model files that are not models, and what they hold instead."""
    model = {
        "format": "relevance-plan-learned-model",
        "version": 1,
        "domain": {"name": "coffee", "hash": "0" * 64},
        "features": {"kind": "wl-objects", "iterations": 2, "buckets": 8, "hash": "blake2b-64", "hubs": []},
        "labels": "plan",
        "threshold": 0.5,
        "seen_types": [],
        "seen_predicates": [],
        "weights": {"named": {}, "hashed": {}},
        "training": {},
    }
    return {
        "deep-nesting": "[" * 200_000 + "]" * 200_000,
        "deep-nesting-inside": json.dumps(model).replace(
            '"training": {}', '"training": ' + "[" * 50_000 + "]" * 50_000
        ),
        "infinite-threshold": json.dumps({**model, "threshold": 1e999}).replace("Infinity", "1e999"),
        "nan-buckets": json.dumps({**model, "features": {**model["features"], "buckets": float("nan")}}),
        "text-for-a-number": json.dumps({**model, "threshold": "0.5"}),
        "features-a-list": json.dumps({**model, "features": [2, 8]}),
        "weights-missing": json.dumps({key: value for key, value in model.items() if key != "weights"}),
        "huge-integer": json.dumps(model).replace('"iterations": 2', '"iterations": ' + "9" * 5000),
        "another-domain": json.dumps(model),
        "binary": "\x00\x01\x02 not json",
        "empty": "",
        "a-list": "[1, 2, 3]",
    }


MODELS = [
    *(
        Scenario(
            f"learning/learned-model-{label}",
            args=("score", "D.pddl", "P.pddl", "--scorer", "learned:bad.json"),
            setup=files(bad_dot_json=text),
            codes=(MODEL,),
            check=one_line("bad.json"),
            quick=label == "deep-nesting",
        )
        for label, text in bad_learned_models().items()
    ),
    *(
        Scenario(
            f"learning/learned-model-{label}-is-exit-31",
            args=("plan", "D.pddl", "P.pddl", "--scorer", f"learned:{target}", "-q", "--plan-file", "out.plan"),
            setup=setup,
            codes=(INPUT,),
            check=one_line(target),
            quick=label == "missing",
        )
        for label, target, setup in (
            ("missing", "nowhere.json", None),
            ("a-folder", "folder", files(folder__x="")),
            ("a-device", "zero.json", lambda work: (work / "zero.json").symlink_to("/dev/zero")),
        )
    ),
    Scenario(
        "learning/knowledge-model-missing-is-exit-31-too",
        args=("score", "D.pddl", "P.pddl", "--model", "nowhere.yaml"),
        codes=(INPUT,),
    ),
    Scenario(
        "learning/learned-model-of-a-store-with-bad-rows",
        args=LEARN + ("--store", "s.sqlite"),
        setup=both(store, lambda work: _spoil_store(work / "s.sqlite")),
        codes=(STORE,),
        check=one_line("row"),
    ),
]


def _spoil_store(path) -> None:
    import sqlite3

    connection = sqlite3.connect(path, isolation_level=None)
    connection.execute("UPDATE results SET result_json = '[1, 2]' WHERE rowid = 1")
    connection.close()


SCENARIOS = OPTIONS + TRAINING + MODELS


test_learning = scenario_test(SCENARIOS)
