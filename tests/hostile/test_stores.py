"""Bad results stores and batches, and bad knowledge models: refused in one line, nothing of the user's changed."""

from __future__ import annotations

import os
import signal
import sqlite3
from pathlib import Path

from support import REPO

from hostile.inputs import after, both, files, installed, link, one_line, planner, quiet_code, says, store, suite
from hostile.scenario import INPUT, INTERRUPTED, MODEL, OK, STORE, USAGE, Scenario, scenario_test


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


def _row_edit(assignment: str):
    """A setup: the store of ``store``, its first row changed by an SQL ``assignment`` (as another
    program could write it: SQLite keeps text in a REAL column), the columns' NOT NULL dropped."""

    def setup(work: Path) -> None:
        store(work)
        connection = sqlite3.connect(work / "s.sqlite", isolation_level=None)
        connection.execute("CREATE TABLE copied AS SELECT * FROM results")
        connection.execute("DROP TABLE results")
        connection.execute("ALTER TABLE copied RENAME TO results")
        connection.execute(f"UPDATE results SET {assignment} WHERE rowid = 1")
        connection.close()

    return setup


BAD_ROWS = {
    "wall-time-text": "wall_time = 'abc'",
    "wall-time-infinite": "wall_time = 9e999",
    "wall-time-negative": "wall_time = -1",
    "timeout-a-blob": "timeout = x'00ff'",
    "objects-a-fraction": "objects_total = 2.5",
    "seed-empty": "seed = NULL",
    "status-empty": "status = NULL",
    "config-a-list": "config_json = '[1, 2]'",
    "config-a-number": "config_json = '7'",
    "config-not-json": "config_json = '{'",
    "result-deep": "result_json = '" + "[" * 100_000 + "]" * 100_000 + "'",
    "result-a-string": "result_json = '\"plan\"'",
}
REPORT_OUTPUTS = {"table": (), "json": ("--json",), "csv": ("--csv",), "html": ("--html", "r.html")}
ROWS = [
    Scenario(
        f"stores/report-{output}-of-a-row-with-{label}",
        args=("report", "s.sqlite", *extra),
        setup=_row_edit(assignment),
        codes=(STORE,),
        check=one_line("row 1"),
        quick=label == "wall-time-text" and output == "table",
    )
    for label, assignment in BAD_ROWS.items()
    for output, extra in REPORT_OUTPUTS.items()
    if output == "table" or label in ("wall-time-text", "config-a-list", "result-deep")
]
OUTPUTS = [
    Scenario(
        "stores/report-html-to-standard-output",
        args=("report", "s.sqlite", "--html", "-"),
        setup=store,
        check=says("<!DOCTYPE html>", where="stdout"),
        quick=True,
    ),
    Scenario(
        "stores/report-html-and-json-both-to-stdout",
        args=("report", "s.sqlite", "--html", "-", "--json"),
        setup=store,
        codes=(USAGE,),
        check=one_line("--html -"),
    ),  # fmt: skip
    *(
        Scenario(
            f"stores/report-html-over-{what}",
            args=("report", "s.sqlite", "--plots", "plots", "--html", page),
            setup=both(store, files(plots__keep="")),
            codes=(USAGE,),
            check=one_line("would replace the plot"),
            needs=installed("matplotlib"),
        )
        for what, page in (
            ("its-cactus", "plots/cactus.png"),
            ("its-scatter", "plots/relevance-vs-pure.png"),
            ("a-suites-cactus", "plots/cactus-suite.png"),
        )
    ),  # fmt: skip
    *(
        Scenario(f"stores/{name}-dash", args=args, setup=store, codes=(USAGE,), check=one_line("'-'"))
        for name, args in (
            ("report-plots", ("report", "s.sqlite", "--plots", "-")),
            ("compare-store", ("compare", "suite", "--store", "-")),
        )
    ),
    Scenario("stores/report-dpi-nan", args=("report", "s.sqlite", "--dpi", "nan"), setup=store, codes=(2,)),
    Scenario(
        "stores/report-dpi-huge",
        args=("report", "s.sqlite", "--plots", "p", "--dpi", "100000"),
        setup=store,
        codes=(USAGE,),
        check=one_line("--dpi"),
    ),  # fmt: skip
]


def _big_store(work: Path, rows: int = 30_000) -> None:
    """The store of ``store`` grown to ``rows`` rows over many suites (copies of its rows, keyed apart)."""
    store(work)
    connection = sqlite3.connect(work / "s.sqlite", isolation_level=None)
    names = [row[1] for row in connection.execute("PRAGMA table_info(results)")]
    first = connection.execute("SELECT * FROM results").fetchall()
    copies = [
        tuple(f"{value}-{number}" if name in ("problem_hash", "suite") else value for name, value in zip(names, row))
        for number in range(rows // len(first))
        for row in first
    ]
    marks = ", ".join("?" * len(names))
    connection.execute("BEGIN")
    connection.executemany(f"INSERT INTO results ({', '.join(names)}) VALUES ({marks})", copies)
    connection.execute("COMMIT")
    connection.close()


def _no_temporary_plot(result) -> str | None:
    """What the interrupted report wrote are whole plots: no temporary file of a plot is left."""
    folder = result.work / "plots"
    left = sorted(path.name for path in folder.iterdir() if path.name.endswith(".tmp")) if folder.is_dir() else []
    return f"temporary plots left: {left[:3]}" if left else None


STOPPED = [
    Scenario(
        f"stores/report-plots-of-a-big-store-{name}",
        args=("report", "s.sqlite", "--plots", "plots", "--html", "r.html"),
        setup=_big_store,
        codes=(INTERRUPTED, OK),
        during=after(seconds, signum),
        check=_no_temporary_plot,
        writes=("plots", "plots/*", "r.html"),
        needs=installed("matplotlib"),
    )
    for name, signum, seconds in (("sigterm", signal.SIGTERM, 3.0), ("sigint", signal.SIGINT, 5.0))
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

SCENARIOS = STORES + ROWS + OUTPUTS + STOPPED + MODELS


test_stores_and_models = scenario_test(SCENARIOS)
