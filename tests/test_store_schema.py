"""The results store's schema over time and under several writers: an older store is read as it is and
migrated only when written to; two runs creating the same new store at once both finish."""

from __future__ import annotations

import json
import multiprocessing
import sqlite3
from pathlib import Path

import pytest
from support import invoke, make_row, write_store_rounds

from relevance_plan.batch.store import ADDED_IN, COLUMNS, DATA_COLUMNS, KEY_COLUMNS, SCHEMA_VERSION, ResultStore
from relevance_plan.exitcodes import ExitCode


def schema_one_store(path: Path, rows: list[dict]) -> Path:
    """A store laid out as schema version 1 wrote it (no plan_cost column), holding ``rows``."""
    added = set(ADDED_IN[2])
    columns = [name for name in COLUMNS if name not in added]
    kinds = dict(DATA_COLUMNS)
    connection = sqlite3.connect(path)
    connection.execute("CREATE TABLE meta (key TEXT PRIMARY KEY, value TEXT NOT NULL)")
    connection.execute("INSERT INTO meta VALUES ('schema_version', '1'), ('tool_version', '0.9.0')")
    definitions = [f"{name} TEXT NOT NULL" for name in KEY_COLUMNS]
    definitions += [f"{name} {kinds[name]}" for name in columns if name not in KEY_COLUMNS]
    connection.execute(f"CREATE TABLE results ({', '.join(definitions)}, PRIMARY KEY ({', '.join(KEY_COLUMNS)}))")
    for row in rows:
        connection.execute(
            f"INSERT INTO results ({', '.join(columns)}) VALUES ({', '.join('?' for _ in columns)})",
            tuple(row[name] for name in columns),
        )
    connection.commit()
    connection.close()
    return path


def files_of(path: Path) -> dict[str, bytes]:
    return {p.name: p.read_bytes() for p in sorted(path.parent.glob(path.name + "*"))}


OLD_ROWS = [make_row("s", "a", "pure", wall=2.0), make_row("s", "a", "relevance", wall=1.0)]


def test_report_reads_a_schema_one_store_as_it_is_with_costs_unknown(tmp_path):
    path = schema_one_store(tmp_path / "old.sqlite", OLD_ROWS)
    before = files_of(path)
    result = invoke("report", path, "--json")
    assert result.exit_code == 0, result.output
    jobs = json.loads(result.stdout)
    assert [job["method"] for job in jobs] == ["pure", "relevance"]
    assert all("plan_cost" in job and job["plan_cost"] is None for job in jobs)
    table = invoke("report", path)
    assert table.exit_code == 0 and "cost" in table.stdout
    assert files_of(path) == before  # reading never migrates


def test_writing_into_a_schema_one_store_migrates_it_keeping_every_row(tmp_path):
    path = schema_one_store(tmp_path / "old.sqlite", OLD_ROWS)
    with ResultStore(path) as store:
        assert store.meta["schema_version"] == str(SCHEMA_VERSION)
        assert store.add(make_row("s", "b", "pure", cost=7.0)) is True
        assert store.add(OLD_ROWS[0]) is False  # its key was kept
    connection = sqlite3.connect(path)
    try:
        version = connection.execute("SELECT value FROM meta WHERE key = 'schema_version'").fetchone()[0]
        query = "SELECT problem, method, wall_time, plan_cost FROM results ORDER BY rowid"
        stored = connection.execute(query).fetchall()
    finally:
        connection.close()
    assert version == str(SCHEMA_VERSION)
    assert stored == [("a.pddl", "pure", 2.0, None), ("a.pddl", "relevance", 1.0, None), ("b.pddl", "pure", 1.0, 7.0)]
    with ResultStore(path, read_only=True) as store:  # a migrated store reads as a new one
        assert [row["plan_cost"] for row in store.rows()] == [None, None, 7.0]


def test_a_store_of_a_later_or_unknown_schema_is_still_refused(tmp_path):
    path = schema_one_store(tmp_path / "odd.sqlite", [])
    connection = sqlite3.connect(path)
    connection.execute("UPDATE meta SET value = 'x' WHERE key = 'schema_version'")
    connection.commit()
    connection.close()
    before = files_of(path)
    for command in (["report", path], ["report", path, "--json"]):
        result = invoke(*command)
        assert result.exit_code == int(ExitCode.STORE), result.output
        assert "schema version x" in result.stderr
    assert files_of(path) == before


def test_two_runs_creating_one_new_store_at_once_both_store_every_row(tmp_path):
    rounds, jobs = 20, 3
    context = multiprocessing.get_context("spawn")
    barrier = context.Barrier(2)
    writers = [
        context.Process(target=write_store_rounds, args=(barrier, str(tmp_path), rounds, name, jobs))
        for name in ("first", "second")
    ]
    for writer in writers:
        writer.start()
    for writer in writers:
        writer.join(timeout=300)
    assert [writer.exitcode for writer in writers] == [0, 0]
    expected = sorted(["shared.pddl"] + [f"{name}-{job}.pddl" for name in ("first", "second") for job in range(jobs)])
    for number in range(rounds):
        with ResultStore(tmp_path / f"round-{number}.sqlite", read_only=True) as store:
            problems = sorted(row["problem"] for row in store.rows())
        assert problems == expected, number


@pytest.mark.parametrize("version", ["0", "99"])
def test_other_schema_versions_are_refused_for_writing_too(tmp_path, version):
    path = schema_one_store(tmp_path / "v.sqlite", OLD_ROWS)
    connection = sqlite3.connect(path)
    connection.execute("UPDATE meta SET value = ? WHERE key = 'schema_version'", (version,))
    connection.commit()
    connection.close()
    before = files_of(path)
    from relevance_plan.errors import StoreError

    with pytest.raises(StoreError, match=f"schema version {version}"):
        ResultStore(path)
    assert files_of(path) == before


@pytest.mark.planner
def test_compare_into_a_schema_one_store_migrates_it_and_stores_costs(tmp_path):
    suite = tmp_path / "coffee-simple"
    made = invoke("generate", "coffee", "--difficulty", "simple", "--count", "1", "--seed", "1", "--out", suite)
    assert made.exit_code == 0, made.output
    path = schema_one_store(tmp_path / "old.sqlite", OLD_ROWS)
    result = invoke("compare", suite, "--methods", "pure", "--store", path, "--timeout", "60", "-q")
    assert result.exit_code == 0, result.output
    with ResultStore(path, read_only=True) as store:
        assert store.meta["schema_version"] == str(SCHEMA_VERSION)
        rows = store.rows()
    assert [(row["problem"], row["method"], row["plan_cost"]) for row in rows[:2]] == [
        ("a.pddl", "pure", None),
        ("a.pddl", "relevance", None),
    ]
    (new,) = rows[2:]
    assert new["status"] == "solved" and new["plan_cost"] == new["plan_length"]  # the coffee world has unit costs
