"""Bad results stores and batches, and bad knowledge models: refused in one line, nothing of the user's changed."""

from __future__ import annotations

import os
import sqlite3
from pathlib import Path

from support import REPO

from hostile.inputs import both, files, link, planner, quiet_code, says, store, suite
from hostile.scenario import INPUT, MODEL, STORE, USAGE, Scenario, scenario_test


def _store_missing_a_column(work: Path) -> None:
    with sqlite3.connect(work / "s.sqlite") as connection:
        connection.execute("CREATE TABLE results (problem_hash TEXT, method TEXT)")
        connection.execute("CREATE TABLE meta (key TEXT PRIMARY KEY, value TEXT)")
        connection.execute("INSERT INTO meta VALUES ('schema_version', '1')")


COMPARE = ("compare", "suite", "--methods", "pure", "--store", "s.sqlite", "-q", "--timeout", "30")
STORES = [
    Scenario(
        "stores/compare-into-a-store-missing-a-column",
        args=COMPARE + ("--planner", planner("never.py")),
        setup=both(suite, _store_missing_a_column),
        codes=(STORE,),
        budget=10,
    ),
    Scenario(
        "stores/report-a-store-missing-a-column",
        args=("report", "s.sqlite"),
        setup=_store_missing_a_column,
        codes=(STORE,),
    ),
    Scenario("stores/report-a-text-file", args=("report", "notes"), setup=files(notes="hello\n"), codes=(STORE,)),
    Scenario(
        "stores/compare-store-is-the-domain",
        args=("compare", "suite", "--store", "suite/domain.pddl"),
        setup=suite,
        codes=(USAGE, STORE),
    ),
    Scenario(
        "stores/dangling-problem-link-is-one-job",
        args=COMPARE + ("--planner", planner("timed_plan.py")),
        setup=both(suite, link("suite/p02.pddl", "gone.pddl")),
        writes=("s.sqlite*",),
        check=says("2 jobs", where="stdout"),
    ),
    Scenario(
        "stores/fifo-problem-is-one-job",
        args=COMPARE + ("--planner", planner("timed_plan.py")),
        setup=both(suite, lambda w: os.mkfifo(w / "suite" / "p02.pddl")),
        writes=("s.sqlite*",),
        budget=30,
    ),
    Scenario(
        "stores/full-disk-leaves-no-empty-store",
        shell="ulimit -f 1; $TOOL compare suite --methods pure "
        "--store s.sqlite -q --planner '" + planner("timed_plan.py") + "'; echo exit=$?; test ! -e s.sqlite"
        " || test -s s.sqlite",
        setup=suite,
        writes=("s.sqlite*",),
        check=quiet_code(0, STORE, INPUT, one_line=True),
    ),
    Scenario(
        "stores/report-json-and-csv-together",
        args=("report", "s.sqlite", "--json", "--csv"),
        setup=store,
        codes=(USAGE,),
    ),
]


def bad_models() -> dict[str, str]:
    text = (REPO / "domains" / "coffee" / "relevance.yaml").read_text()
    return {
        "entropy-bound-nan": text.replace("entropy_bound: 1.0", "entropy_bound: .nan"),
        "scene-predicate-as-a-list": text.replace("location: at", "location: [at, on]"),
        "scene-predicate-the-domain-lacks": text.replace("location: at", "location: floats-at"),
        "dependency-on-an-unknown-predicate": text.replace(
            "dependencies: []", "dependencies: [{predicate: glued, when_kept: 1, restore: 2, reason: x}]"
        ),
        "dependency-position-beyond-arity": text.replace(
            "dependencies: []", "dependencies: [{predicate: at, when_kept: 1, restore: 7, reason: x}]"
        ),
        "integer-of-5000-digits": text.replace("entropy_bound: 1.0", "entropy_bound: " + "9" * 5000),
        "probability-above-one": text.replace("coffee: 0.98", "coffee: 1.98", 1),
        "not-a-mapping": "- just\n- a list\n",
        "alias-bomb": "a0: &a0 [x, x, x, x, x, x, x, x, x]\n"
        + "".join(f"a{i}: &a{i} [" + ", ".join([f"*a{i - 1}"] * 9) + "]\n" for i in range(1, 9)),
        "deep-nesting": "a: " + "[" * 5000 + "]" * 5000 + "\n",
        "binary": "\x00\x01\x02 not yaml",
    }


BAD_MODELS = [
    Scenario(
        f"models/{label}",
        args=("score", "D.pddl", "P.pddl", "--model", "bad.yaml"),
        setup=files(bad_dot_yaml=text),
        codes=(MODEL,),
        quick=label == "entropy-bound-nan",
    )
    for label, text in bad_models().items()
]
BROKEN = files(relevance_dot_yaml="version: [unclosed\n")
MODELS = BAD_MODELS + [
    Scenario(
        "models/broken-model-beside-the-domain-is-not-needed-by-goal",
        args=("score", "D.pddl", "P.pddl", "--scorer", "goal"),
        setup=BROKEN,
    ),
    Scenario(
        "models/broken-model-beside-the-domain-refused-by-model",
        args=("score", "D.pddl", "P.pddl", "--scorer", "model"),
        setup=BROKEN,
        codes=(MODEL,),
    ),
]

SCENARIOS = STORES + MODELS


test_stores_and_models = scenario_test(SCENARIOS)
