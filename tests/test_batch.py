"""Batch comparison: the results store, resuming, crashes, Ctrl-C, Dask, the CLI and the demo."""

from __future__ import annotations

import contextlib
import json
import os
import re
import signal
import socket
import sqlite3
import subprocess
import sys
import textwrap
import threading
import time
import types
from pathlib import Path

import pytest
from support import REPO, TOOL, invoke, make_row, process_gone, write_store

from relevance_plan.batch.compare import compare
from relevance_plan.batch.executors import Workers, connect_scheduler
from relevance_plan.batch.jobs import build_jobs, run_job
from relevance_plan.batch.store import SCHEMA_VERSION, ResultStore
from relevance_plan.errors import InputFileError, SchedulerError, StoreError, UsageError
from relevance_plan.exitcodes import ExitCode
from relevance_plan.generators import WORLDS, Settings
from relevance_plan.planning.options import PlanOptions
from relevance_plan.planning.planners.fast_downward import adapter as fast_downward
from relevance_plan.relevance.selection.prune import Thresholds

ALL_METHODS = "relevance,pure,random,oracle"


# --------------------------------------------------------------------------- helpers


def tiny_suite(directory: Path, world: str = "coffee", count: int = 2, distractors: int = 5) -> Path:
    WORLDS[world].suite(count, 0, directory, Settings("simple", distractors=distractors))
    return directory


@pytest.fixture
def suite(tmp_path):
    return tiny_suite(tmp_path / "coffee-simple")


@pytest.fixture
def populated_store(tmp_path):
    """A valid store holding one hand-made row."""
    return write_store(tmp_path / "results.sqlite", [make_row("old", "a", "pure")])


def assert_one_line_error(result, code, fragment):
    assert result.exit_code == int(code), (result.exit_code, result.output)
    assert result.stderr.startswith("relevance-plan: error: ")
    assert result.stderr.count("\n") == 1, result.stderr
    assert fragment in result.stderr


def foreign_store(path: Path, schema_version: int) -> Path:
    """A SQLite file laid out like a store of another schema version."""
    connection = sqlite3.connect(path)
    connection.execute("CREATE TABLE meta (key TEXT PRIMARY KEY, value TEXT NOT NULL)")
    connection.execute(
        "INSERT INTO meta VALUES ('schema_version', ?), ('tool_version', '9.9.9')", (str(schema_version),)
    )
    connection.execute("CREATE TABLE results (problem_hash TEXT)")
    connection.commit()
    connection.close()
    return path


def snapshot(path: Path):
    """The store's bytes and its companion files (-wal, -shm, -journal)."""
    return path.read_bytes(), sorted(p.name for p in path.parent.glob(path.name + "*"))


def read_store(path: Path) -> list[dict]:
    """Rows read with plain sqlite3 (what a crashed run left behind)."""
    connection = sqlite3.connect(path)
    try:
        connection.row_factory = sqlite3.Row
        return [dict(r) for r in connection.execute("SELECT rowid, * FROM results ORDER BY rowid")]
    finally:
        connection.close()


def count_rows(path: Path) -> int:
    if not path.exists():  # connecting would create it
        return 0
    try:
        connection = sqlite3.connect(path, timeout=1)
        try:
            return connection.execute("SELECT COUNT(*) FROM results").fetchone()[0]
        finally:
            connection.close()
    except sqlite3.Error:
        return 0


def fake_planner(tmp_path: Path, body: str) -> Path:
    script = tmp_path / "fake-fast-downward.py"
    script.write_text("import os, signal, sys, time\n" + textwrap.dedent(body))
    return script


def free_port() -> int:
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        return sock.getsockname()[1]


# --------------------------------------------------------------------------- store


def test_store_round_trip_in_wal_mode(tmp_path):
    path = tmp_path / "r.sqlite"
    row = make_row("s", "a", "pure")
    key = (row["problem_hash"], row["method"], row["config_hash"], row["planner_version"])
    with ResultStore(path) as store:
        assert not store.contains(key)
        assert store.add(row) is True
        assert store.add(row) is False  # a key is stored once
        assert store.contains(key)
        assert store.meta["schema_version"] == str(SCHEMA_VERSION)
    with ResultStore(path, create=False) as store:
        (stored,) = store.rows()
        assert stored["status"] == "solved" and stored["rowid"] == 1
        assert store.rows(suite="other") == []
        assert store.connection.execute("PRAGMA journal_mode").fetchone()[0] == "wal"
        assert store.connection.execute("PRAGMA synchronous").fetchone()[0] == 1  # NORMAL


def test_store_of_another_schema_version_is_refused_and_untouched(tmp_path):
    path = foreign_store(tmp_path / "future.sqlite", schema_version=99)
    before = snapshot(path)
    with pytest.raises(StoreError) as raised:
        ResultStore(path)
    message = str(raised.value)
    assert str(path) in message and "schema version 99" in message and "\n" not in message
    assert snapshot(path) == before


@pytest.mark.parametrize("content", [b"suite,method\nalpha,pure\n", b"\x00" * 100])
def test_non_sqlite_file_is_refused_and_untouched(tmp_path, content):
    path = tmp_path / "notes.sqlite"
    path.write_bytes(content)
    with pytest.raises(StoreError, match="not a SQLite database"):
        ResultStore(path)
    assert path.read_bytes() == content
    assert sorted(p.name for p in tmp_path.iterdir()) == ["notes.sqlite"]


def test_foreign_sqlite_database_is_refused(tmp_path):
    path = tmp_path / "other.db"
    connection = sqlite3.connect(path)
    connection.execute("CREATE TABLE people (name TEXT)")
    connection.commit()
    connection.close()
    before = snapshot(path)
    with pytest.raises(StoreError, match="no meta/results table"):
        ResultStore(path)
    assert snapshot(path) == before


def test_missing_store_is_not_created_when_reading(tmp_path):
    with pytest.raises(InputFileError):
        ResultStore(tmp_path / "none.sqlite", create=False)
    with pytest.raises(InputFileError):
        ResultStore(tmp_path / "no-such-dir" / "r.sqlite")
    assert list(tmp_path.iterdir()) == []


# --------------------------------------------------------------------------- jobs and keys


def test_build_jobs_and_keys(suite, tmp_path):
    jobs = build_jobs([suite], ALL_METHODS, (0, 1), PlanOptions(timeout=30))
    assert len(jobs) == 2 * 2 * 4
    assert {job.suite for job in jobs} == {"coffee-simple"}
    assert len({job.key for job in jobs}) == len(jobs)
    assert all(job.options.method == job.method and job.options.seed == job.seed for job in jobs)
    # Keys do not depend on where the suite lives...
    moved = tiny_suite(tmp_path / "elsewhere" / "coffee-simple")
    assert [j.key for j in build_jobs([moved], ALL_METHODS, (0, 1), PlanOptions(timeout=30))] == [j.key for j in jobs]
    # ...but on every option that can change the result, and only those of the method.
    looser = build_jobs([suite], ALL_METHODS, (0, 1), PlanOptions(timeout=30, thresholds=Thresholds(0.1, 0.1)))
    for old, new in zip(jobs, looser):
        assert (old.key == new.key) == (old.method == "pure")
    longer = build_jobs([suite], ALL_METHODS, (0, 1), PlanOptions(timeout=31))
    assert not {j.key for j in jobs} & {j.key for j in longer}


def test_build_jobs_rejects_bad_input(tmp_path, suite):
    with pytest.raises(InputFileError, match="suite directory not found"):
        build_jobs([tmp_path / "missing"], "pure")
    (tmp_path / "empty").mkdir()
    with pytest.raises(InputFileError):
        build_jobs([tmp_path / "empty"], "pure")
    with pytest.raises(UsageError, match="unknown method 'magic'"):
        build_jobs([suite], "relevance,magic")
    with pytest.raises(UsageError, match="seeds"):
        build_jobs([suite], "pure", "0,x")


def test_an_objective_no_model_knows_fails_the_comparison_before_any_job(suite, tmp_path):
    store = tmp_path / "r.sqlite"
    result = invoke("compare", suite, "--objective", "nosuch", "--methods", "pure", "--store", store, "--timeout", 10)
    assert result.exit_code == 35, result.output
    assert "unknown objective 'nosuch'" in result.output and "relevance.yaml" in result.output
    assert not store.exists()


# --------------------------------------------------------------------------- running


@pytest.mark.planner
def test_compare_stores_every_job_once_and_resumes(suite, tmp_path):
    store = tmp_path / "r.sqlite"
    summary = compare(
        [suite], ALL_METHODS, PlanOptions(timeout=60), store_path=store, workers=Workers(jobs=2), progress=None
    )
    assert (summary.total, summary.already_stored, summary.ran) == (8, 0, 8)
    rows = read_store(store)
    assert len(rows) == 8
    assert {r["status"] for r in rows} == {"solved"} and all(r["valid"] == 1 for r in rows)
    by_method = {r["method"]: r for r in rows if r["problem"] == "coffee-simple-001.pddl"}
    assert by_method["pure"]["objects_kept"] == by_method["pure"]["objects_total"]
    assert by_method["oracle"]["objects_kept"] < by_method["oracle"]["objects_total"]
    assert by_method["pure"]["world"] == "coffee" and by_method["pure"]["difficulty"] == "simple"
    result = json.loads(by_method["relevance"]["result_json"])
    assert result["status"] == "solved" and result["plan"]
    again = compare(
        [suite], ALL_METHODS, PlanOptions(timeout=60), store_path=store, workers=Workers(jobs=2), progress=None
    )
    assert (again.already_stored, again.ran) == (8, 0)
    assert read_store(store) == rows


@pytest.mark.planner
def test_input_error_becomes_a_row_not_a_crash(suite, tmp_path):
    (suite / "coffee-simple-009.pddl").write_text("(define (problem broken) (:domain coffee) (:objects a - ")
    store = tmp_path / "r.sqlite"
    summary = compare(
        [suite], "pure,relevance", PlanOptions(timeout=60), store_path=store, workers=Workers(jobs=2), progress=None
    )
    assert summary.ran == 6
    rows = read_store(store)
    broken = [r for r in rows if r["problem"] == "coffee-simple-009.pddl"]
    assert len(broken) == 2 and {r["status"] for r in broken} == {"input-error"}
    assert all("coffee-simple-009.pddl" in r["message"] for r in broken)
    assert all(r["exit_code"] is None for r in broken)
    assert {r["status"] for r in rows if r not in broken} == {"solved"}


@pytest.mark.planner
@pytest.mark.parametrize(
    "body, code",
    [("sys.exit(35)\n", 35), ("os.kill(os.getpid(), signal.SIGKILL)\n", -signal.SIGKILL)],
    ids=["exit-35", "killed"],
)
def test_planner_crash_is_recorded_with_its_exit_code(suite, tmp_path, monkeypatch, body, code):
    monkeypatch.setenv(fast_downward.FAST_DOWNWARD_ENV, str(fake_planner(tmp_path, body)))
    store = tmp_path / "r.sqlite"
    summary = compare(
        [suite], "pure,relevance", PlanOptions(timeout=30), store_path=store, workers=Workers(jobs=2), progress=None
    )
    assert summary.ran == 4 and summary.failed == 4
    rows = read_store(store)
    assert len(rows) == 4
    assert {(r["status"], r["exit_code"]) for r in rows} == {("planner-error", code)}
    assert all(
        r["planner_version"].endswith(tuple("0123456789abcdef")) and "+custom-" in r["planner_version"] for r in rows
    )


def test_missing_planner_stops_the_batch_and_stores_nothing(suite, tmp_path, monkeypatch):
    from relevance_plan.errors import PlannerError

    monkeypatch.setenv(fast_downward.FAST_DOWNWARD_ENV, str(tmp_path / "no-such-driver.py"))
    store = tmp_path / "r.sqlite"
    with pytest.raises(PlannerError):
        compare([suite], "pure", PlanOptions(timeout=30), store_path=store, workers=Workers(jobs=1), progress=None)
    assert read_store(store) == []


@pytest.mark.planner
def test_run_job_returns_a_complete_row(suite):
    from relevance_plan.batch.store import COLUMNS

    (job,) = build_jobs([suite], "oracle", (0,), PlanOptions(timeout=30))[:1]
    row = run_job(job)
    assert set(row) == set(COLUMNS)
    assert row["status"] == "solved" and row["exit_code"] == 0 and row["plan_length"] > 0
    assert json.loads(row["config_json"])["method"] == "oracle"


# --------------------------------------------------------------------------- kill -9 and Ctrl-C


def start_compare(suite, store, *extra, env=None):
    command = [*TOOL, "compare", str(suite), "--store", str(store), *map(str, extra)]
    return subprocess.Popen(
        command, cwd=REPO, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env={**os.environ, **(env or {})}
    )


def run_compare(suite, store, *extra, timeout: float) -> subprocess.CompletedProcess:
    command = [*TOOL, "compare", str(suite), "--store", str(store), *map(str, extra)]
    return subprocess.run(command, cwd=REPO, capture_output=True, text=True, timeout=timeout)


@pytest.mark.planner
def test_resume_after_kill_9_loses_nothing_and_repeats_nothing(tmp_path):
    suite = tiny_suite(tmp_path / "coffee-simple", count=3)
    store = tmp_path / "results.sqlite"
    arguments = ("--methods", ALL_METHODS, "--timeout", 60, "--jobs", 1)
    process = start_compare(suite, store, *arguments)
    try:
        deadline = time.monotonic() + 120
        while count_rows(store) < 2 and process.poll() is None and time.monotonic() < deadline:
            time.sleep(0.02)
        os.kill(process.pid, signal.SIGKILL)
    finally:
        process.kill()
        process.communicate()
    assert process.returncode == -signal.SIGKILL

    connection = sqlite3.connect(store)
    assert connection.execute("PRAGMA integrity_check").fetchone()[0] == "ok"
    connection.close()
    survivors = read_store(store)
    assert 2 <= len(survivors) < 12, "the first run should have been killed half-way"

    finished = run_compare(suite, store, *arguments, timeout=300)
    assert finished.returncode == 0, finished.stderr
    done = len(survivors)
    assert f"12 jobs: {done} already stored, {12 - done} run" in finished.stdout
    rows = read_store(store)
    assert len(rows) == 12
    keys = [(r["problem_hash"], r["method"], r["config_hash"], r["planner_version"]) for r in rows]
    assert len(set(keys)) == 12
    assert {(r["problem"], r["method"]) for r in rows} == {
        (f"coffee-simple-00{i}.pddl", m) for i in (1, 2, 3) for m in ALL_METHODS.split(",")
    }
    # The rows committed before the kill are untouched: same rowid, same finish time, same result.
    assert rows[:done] == survivors

    third = run_compare(suite, store, *arguments, timeout=120)
    assert "12 jobs: 12 already stored, 0 run" in third.stdout
    assert read_store(store) == rows


@pytest.mark.planner
@pytest.mark.parametrize("signum", [signal.SIGINT, signal.SIGTERM], ids=["ctrl-c", "sigterm"])
def test_ctrl_c_kills_running_planners_and_keeps_finished_rows(tmp_path, signum):
    suite = tiny_suite(tmp_path / "coffee-simple", count=3)
    markers = tmp_path / "markers"
    markers.mkdir()
    # Problem 001 crashes at once (a stored row); 002 hangs until killed; 003 must never start.
    planner = fake_planner(
        tmp_path,
        """
        name = os.path.basename(sys.argv[-1])
        open(os.path.join(os.environ["FAKE_PLANNER_MARKERS"], f"{name}.{os.getpid()}"), "w").close()
        if "002" in name:
            time.sleep(600)
        sys.exit(35)
    """,
    )
    store = tmp_path / "results.sqlite"
    env = {fast_downward.FAST_DOWNWARD_ENV: str(planner), "FAKE_PLANNER_MARKERS": str(markers)}
    process = start_compare(suite, store, "--methods", "pure", "--timeout", 300, "--jobs", 1, env=env)
    try:
        deadline = time.monotonic() + 60
        while not any(markers.glob("coffee-simple-002.pddl.*")) and time.monotonic() < deadline:
            assert process.poll() is None, process.communicate()
            time.sleep(0.05)
        (hanging,) = markers.glob("coffee-simple-002.pddl.*")
        planner_pid = int(hanging.name.rsplit(".", 1)[1])
        assert not process_gone(planner_pid)
        process.send_signal(signum)
        _, stderr = process.communicate(timeout=30)
    finally:
        if process.poll() is None:
            process.kill()
            process.communicate()
    assert process.returncode == ExitCode.INTERRUPTED, stderr
    assert "interrupted" in stderr
    deadline = time.monotonic() + 5
    while not process_gone(planner_pid) and time.monotonic() < deadline:
        time.sleep(0.05)
    assert process_gone(planner_pid), "the planner survived Ctrl-C"
    assert not any(markers.glob("coffee-simple-003.pddl.*"))
    rows = read_store(store)
    assert [(r["problem"], r["status"], r["exit_code"]) for r in rows] == [
        ("coffee-simple-001.pddl", "planner-error", 35)
    ]


# --------------------------------------------------------------------------- Dask


def test_dask_missing_says_how_to_install(monkeypatch):
    monkeypatch.setitem(sys.modules, "dask.distributed", None)
    with pytest.raises(SchedulerError, match=re.escape("pip install 'relevance-plan[dask]'")):
        connect_scheduler("tcp://127.0.0.1:1", timeout=1)


@pytest.mark.planner
def test_dask_cluster_runs_the_jobs_into_the_local_store(tmp_path):
    pytest.importorskip("distributed")
    suite = tiny_suite(tmp_path / "coffee-simple", count=1)
    port = free_port()
    address = f"tcp://127.0.0.1:{port}"
    processes = []
    try:
        processes.append(
            subprocess.Popen(
                [
                    sys.executable,
                    "-m",
                    "dask",
                    "scheduler",
                    "--host",
                    "127.0.0.1",
                    "--port",
                    str(port),
                    "--no-dashboard",
                ],
                cwd=tmp_path,
                stdout=subprocess.DEVNULL,
                stderr=subprocess.DEVNULL,
            )
        )
        processes.append(
            subprocess.Popen(
                [
                    sys.executable,
                    "-m",
                    "dask",
                    "worker",
                    address,
                    "--nworkers",
                    "1",
                    "--nthreads",
                    "2",
                    "--no-dashboard",
                    "--local-directory",
                    str(tmp_path / "dask-worker"),
                ],
                cwd=tmp_path,
                stdout=subprocess.DEVNULL,
                stderr=subprocess.DEVNULL,
            )
        )
        client = connect_scheduler(address, timeout=30)
        try:
            client.wait_for_workers(1, timeout=60)
        finally:
            client.close()
        store = tmp_path / "results.sqlite"
        on_cluster = {"store_path": store, "workers": Workers(scheduler=address), "progress": None}
        summary = compare([suite], ALL_METHODS, PlanOptions(timeout=60), **on_cluster)
        assert (summary.total, summary.ran, summary.failed) == (4, 4, 0)
        rows = read_store(store)
        assert sorted(r["method"] for r in rows) == sorted(ALL_METHODS.split(","))
        assert {r["status"] for r in rows} == {"solved"}
        again = compare([suite], ALL_METHODS, PlanOptions(timeout=60), **on_cluster)
        assert (again.already_stored, again.ran) == (4, 0)
    finally:
        for process in reversed(processes):  # the worker first, then the scheduler
            os.kill(process.pid, signal.SIGTERM)
            try:
                process.wait(timeout=20)
            except subprocess.TimeoutExpired:
                os.kill(process.pid, signal.SIGKILL)
                process.wait()


def test_unreachable_scheduler_is_one_line_and_leaves_the_store_alone(suite, populated_store):
    before = snapshot(populated_store)
    closed = free_port()
    result = invoke(
        "compare",
        suite,
        "--methods",
        "pure",
        "--store",
        populated_store,
        "--scheduler",
        f"tcp://127.0.0.1:{closed}",
        "--scheduler-timeout",
        1,
        "-q",
    )
    assert_one_line_error(result, ExitCode.SCHEDULER, f"cannot reach the Dask scheduler at tcp://127.0.0.1:{closed}")
    assert snapshot(populated_store) == before


@pytest.fixture
def stranger():
    """A server on a local port that greets each connection with ``stranger.greeting`` (text, or nothing)."""
    listener = socket.create_server(("127.0.0.1", 0))
    listener.settimeout(0.1)
    state = {"greeting": b"", "stop": False, "open": []}

    def serve() -> None:
        while not state["stop"]:
            try:
                connection, _ = listener.accept()
            except OSError:
                continue
            state["open"].append(connection)
            with contextlib.suppress(OSError):
                connection.sendall(state["greeting"])

    thread = threading.Thread(target=serve, daemon=True)
    thread.start()
    server = types.SimpleNamespace(address=f"tcp://127.0.0.1:{listener.getsockname()[1]}", state=state)
    yield server
    state["stop"] = True
    thread.join()
    for connection in state["open"]:
        connection.close()
    listener.close()


@pytest.mark.parametrize(
    "greeting, fragment",
    [
        (b"HTTP/1.1 400 Bad Request\r\nContent-Length: 0\r\n\r\n" * 20, "is not a Dask scheduler"),
        (b"garbage " * 100, "is not a Dask scheduler"),
        (b"", "did not greet as Dask does within 2 s"),
    ],
)
def test_a_port_that_does_not_answer_as_a_scheduler_is_one_line(suite, populated_store, stranger, greeting, fragment):
    """Not out of memory (the client read text as a message length), and not a traceback when the
    half-started client is collected at the end: one line, the store untouched."""
    stranger.state["greeting"] = greeting
    before = snapshot(populated_store)
    started = time.monotonic()
    done = subprocess.run(
        [*TOOL, "compare", suite, "--methods", "pure", "--store", populated_store, "--scheduler", stranger.address,
         "--scheduler-timeout", "2", "-q"],
        capture_output=True, text=True, timeout=60,
    )  # fmt: skip
    assert done.returncode == ExitCode.SCHEDULER, done.stderr
    assert done.stderr.startswith("relevance-plan: error: ") and done.stderr.count("\n") == 1, done.stderr
    assert fragment in done.stderr
    assert time.monotonic() - started < 15 and snapshot(populated_store) == before


# --------------------------------------------------------------------------- CLI errors


def test_cli_bad_input_gives_one_line_and_its_exit_code(tmp_path, suite, populated_store):
    before = snapshot(populated_store)
    rows_before = read_store(populated_store)
    (tmp_path / "no-problems").mkdir()
    (tmp_path / "no-problems" / "domain.pddl").write_text((suite / "domain.pddl").read_text())
    cases = [
        ([tmp_path / "missing"], ALL_METHODS, ExitCode.INPUT_FILE, "suite directory not found"),
        ([tmp_path / "no-problems"], ALL_METHODS, ExitCode.INPUT_FILE, "suite has no problem files"),
        ([suite], "relevance,telepathy", ExitCode.USAGE, "unknown method 'telepathy'"),
    ]
    for suites, methods, code, fragment in cases:
        result = invoke("compare", *suites, "--methods", methods, "--store", populated_store, "-q")
        assert_one_line_error(result, code, fragment)
        assert snapshot(populated_store) == before
    assert read_store(populated_store) == rows_before


def test_cli_incompatible_or_foreign_store(tmp_path, suite):
    future = foreign_store(tmp_path / "future.sqlite", schema_version=0)
    text = tmp_path / "results.csv"
    text.write_text("not,a,database\n")
    for store, fragment in ((future, "schema version 0"), (text, "not a SQLite database")):
        before = snapshot(store)
        for command in (["compare", suite, "--methods", "pure", "--store", store, "-q"], ["report", store]):
            result = invoke(*command)
            assert_one_line_error(result, ExitCode.STORE, fragment)
            assert str(store) in result.stderr
            assert snapshot(store) == before


@pytest.mark.planner
def test_cli_compare_then_report(suite, tmp_path):
    store = tmp_path / "r.sqlite"
    result = invoke(
        "compare", suite, "--methods", "pure,oracle", "--store", store, "--timeout", 60, "--jobs", 2, "--seeds", "0,1"
    )
    assert result.exit_code == 0, result.output
    assert "8 jobs: 0 already stored, 8 run (8 solved)" in result.stdout
    assert "compare (8 jobs): 8/8 done, 0 failed" in result.stderr  # the final progress line
    report = invoke("report", store)
    assert report.exit_code == 0
    assert report.stdout.splitlines()[0] == "| suite | metric | pure | oracle |"
    assert "|  | n | 4 | 4 |" in report.stdout


@pytest.mark.planner
def test_demo_end_to_end(tmp_path):
    workdir = tmp_path / "demo"
    result = invoke("demo", "--workdir", workdir, "--tiny", "--timeout", 60, "--jobs", 2, "-q")
    assert result.exit_code == 0, result.output
    lines = result.stdout.splitlines()
    assert lines[0] == "| suite | metric | relevance | pure | random | oracle |"
    assert "| cereal-simple | time (s) |" in result.stdout and "| coffee-simple | time (s) |" in result.stdout
    assert f"results: {workdir / 'results.sqlite'}" in result.stdout
    rows = read_store(workdir / "results.sqlite")
    assert len(rows) == 2 * 4
    assert {r["status"] for r in rows} == {"solved"}
    # Running it again reuses every stored result.
    again = invoke("demo", "--workdir", workdir, "--tiny", "--timeout", 60, "--jobs", 2, "-q")
    assert again.exit_code == 0 and "(0 run now, 8 reused)" in again.stdout


# --------------------------------------------------------------------------- the demo's temporary folder


@pytest.mark.parametrize("outcome", ["finished", "failed", "interrupted"])
def test_a_demo_without_workdir_removes_its_temporary_folder(tmp_path, monkeypatch, outcome):
    import tempfile

    from relevance_plan.batch import demo
    from relevance_plan.batch.compare import CompareSummary

    def fake_compare(suites, methods, options, *, store_path, **_):
        ResultStore(store_path).close()
        if outcome == "failed":
            raise StoreError("cannot write to the results store", path=str(store_path))
        if outcome == "interrupted":
            raise KeyboardInterrupt
        return CompareSummary(str(store_path), 0, 0, 0, 0, {}, 0.0)

    monkeypatch.setattr(tempfile, "tempdir", str(tmp_path))
    monkeypatch.setattr(demo, "compare", fake_compare)
    if outcome == "finished":
        run = demo.run_demo(None, tiny=True, progress=None)
        assert run.workdir is None and run.store_path is None
    else:
        with pytest.raises((StoreError, KeyboardInterrupt)):
            demo.run_demo(None, tiny=True, progress=None)
    assert list(tmp_path.iterdir()) == []


def test_the_demo_says_its_temporary_folder_is_gone(tmp_path, monkeypatch):
    import tempfile

    from relevance_plan.batch import demo
    from relevance_plan.batch.compare import CompareSummary

    def fake_compare(suites, methods, options, *, store_path, **_):
        ResultStore(store_path).close()
        return CompareSummary(str(store_path), 8, 0, 8, 0, {"solved": 8}, 1.0)

    monkeypatch.setattr(tempfile, "tempdir", str(tmp_path))
    monkeypatch.setattr(demo, "compare", fake_compare)
    result = invoke("demo", "--tiny", "-q")
    assert result.exit_code == 0, result.output
    assert "temporary folder, now removed; --workdir DIR keeps" in result.stdout
    assert list(tmp_path.iterdir()) == []
