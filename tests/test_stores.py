"""Results stores that cannot be written, or only read: every such problem is found before the
first job, is one line with its documented exit code, and leaves the store as it was."""

from __future__ import annotations

import json
import os
import resource
import shutil
import sqlite3
import subprocess
from pathlib import Path

import pytest
from support import REPO, TOOL, make_row, one_line_error, run

from relevance_plan.batch.store import ResultStore
from relevance_plan.exitcodes import ExitCode
from relevance_plan.planning.planners.fast_downward import adapter as fast_downward

GRIPPER = REPO / "relevance_plan" / "data" / "domains" / "gripper" / "domain.pddl"
BROKEN_PROBLEM = "(define (problem p{}) (:domain gripper) (:objects a - "


# --------------------------------------------------------------------------- helpers


def can_mount_read_only() -> bool:
    try:
        return subprocess.run(["unshare", "-m", "true"], capture_output=True, timeout=10).returncode == 0
    except (OSError, subprocess.TimeoutExpired):
        return False


needs_mount = pytest.mark.skipif(not can_mount_read_only(), reason="needs unshare -m (a private mount namespace)")


def suite_of(tmp_path: Path, problems: int = 2, broken: bool = False) -> Path:
    """A gripper suite; ``broken`` problems fail to parse, so their jobs never start a planner."""
    suite = tmp_path / "suite"
    suite.mkdir()
    shutil.copy(GRIPPER, suite / "domain.pddl")
    for index in range(1, problems + 1):
        good = f"(define (problem p{index}) (:domain gripper) (:objects r1 r2) (:init (room r1)) (:goal (room r1)))"
        (suite / f"p{index}.pddl").write_text(BROKEN_PROBLEM.format(index) if broken else good)
    return suite


def marker_planner(tmp_path: Path) -> tuple[Path, dict]:
    """A stand-in planner that leaves a marker when a job starts it; the environment that selects it."""
    marker = tmp_path / "a-job-ran"
    script = tmp_path / "planner.py"
    script.write_text(f"import sys\nopen({str(marker)!r}, 'w').close()\nsys.exit(35)\n")
    return marker, {fast_downward.FAST_DOWNWARD_ENV: str(script)}


def populated_store(path: Path, rows: int = 3) -> Path:
    with ResultStore(path) as store:
        for index in range(rows):
            store.add(make_row("old", f"p{index}", "pure"))
    return path


def state(path: Path):
    """A store's bytes and the files beside it (None when it does not exist)."""
    files = sorted(p.name for p in path.parent.glob(path.name + "*"))
    return (path.read_bytes() if path.exists() else None), files


def tool(*args, env=None, limit_bytes=None, read_only=None) -> subprocess.CompletedProcess:
    """The command in a separate process: with a file-size limit, or with ``read_only`` mounted read-only."""
    command = [*TOOL, *map(str, args)]
    if read_only is not None:
        script = 'mount --bind "$1" "$1" && mount -o remount,ro,bind "$1" "$1" && shift && exec "$@"'
        command = ["unshare", "-m", "sh", "-c", script, "sh", str(read_only), *command]

    def limit():
        resource.setrlimit(resource.RLIMIT_FSIZE, (limit_bytes, limit_bytes))

    return subprocess.run(
        command,
        cwd=REPO,
        capture_output=True,
        text=True,
        timeout=300,
        env={**os.environ, "PYTHONDONTWRITEBYTECODE": "1", **(env or {})},
        preexec_fn=limit if limit_bytes is not None else None,
    )


def assert_one_line(finished: subprocess.CompletedProcess, codes, fragment: str) -> None:
    assert finished.returncode in codes, (finished.returncode, finished.stderr)
    assert finished.stderr.startswith("relevance-plan: error: ") and finished.stderr.count("\n") == 1, finished.stderr
    assert fragment in finished.stderr and "Traceback" not in finished.stderr


# --------------------------------------------------------------------------- reading


@needs_mount
def test_report_reads_a_valid_store_on_a_read_only_file_system(tmp_path):
    folder = tmp_path / "stores"
    folder.mkdir()
    store = populated_store(folder / "results.sqlite")
    before = state(store)
    finished = tool("report", store, read_only=folder)
    assert finished.returncode == 0, finished.stderr
    assert finished.stdout.startswith("| suite | metric | pure |") and "|  | n | 3 |" in finished.stdout
    finished = tool("report", store, "--json", read_only=folder)
    assert finished.returncode == 0 and len(json.loads(finished.stdout)) == 3
    assert state(store) == before


# --------------------------------------------------------------------------- writing


def read_only_store(tmp_path: Path) -> tuple[Path, Path | None]:
    store = populated_store(tmp_path / "results.sqlite")
    store.chmod(0o444)
    return store, None


def _locked_folder(tmp_path: Path, store: bool) -> tuple[Path, Path | None]:
    """A read-only folder, holding a store (``store``) or where a new one would go."""
    folder = tmp_path / "locked"
    folder.mkdir()
    path = populated_store(folder / "results.sqlite") if store else folder / "results.sqlite"
    folder.chmod(0o555)
    return path, None


def store_in_read_only_folder(tmp_path: Path) -> tuple[Path, Path | None]:
    return _locked_folder(tmp_path, store=True)


def new_store_in_read_only_folder(tmp_path: Path) -> tuple[Path, Path | None]:
    return _locked_folder(tmp_path, store=False)


def store_on_read_only_file_system(tmp_path: Path) -> tuple[Path, Path | None]:
    folder = tmp_path / "mounted"
    folder.mkdir()
    return populated_store(folder / "results.sqlite"), folder


@pytest.mark.parametrize(
    "make_store, fragment",
    [
        (read_only_store, "results store is read-only"),
        (store_in_read_only_folder, "its folder is read-only"),
        (new_store_in_read_only_folder, "its folder is read-only"),
        pytest.param(store_on_read_only_file_system, "read-only", marks=needs_mount),
    ],
    ids=["read-only-store", "read-only-folder", "new-store-in-read-only-folder", "read-only-file-system"],
)
def test_compare_refuses_a_store_it_cannot_write_before_any_job(tmp_path, make_store, fragment):
    suite = suite_of(tmp_path)
    marker, env = marker_planner(tmp_path)
    store, mounted = make_store(tmp_path)
    before = state(store)
    try:
        finished = tool("compare", suite, "--methods", "pure", "--store", store, "-q", env=env, read_only=mounted)
    finally:
        store.parent.chmod(0o755)
    assert_one_line(finished, {ExitCode.INPUT_FILE}, fragment)
    assert not marker.exists(), "a job ran before the store was checked"
    assert state(store) == before


def drop_column(path: Path, column: str) -> None:
    connection = sqlite3.connect(path)
    connection.execute(f"ALTER TABLE results DROP COLUMN {column}")
    connection.commit()
    connection.close()


@pytest.mark.parametrize("column", ["message", "result_json", "world"])
def test_a_store_missing_a_column_is_refused_before_any_job(tmp_path, column):
    suite = suite_of(tmp_path)
    marker, env = marker_planner(tmp_path)
    store = populated_store(tmp_path / "results.sqlite")
    drop_column(store, column)
    before = state(store)
    finished = tool("compare", suite, "--methods", "pure", "--store", store, "-q", env=env)
    assert_one_line(finished, {ExitCode.STORE}, f"lacks the column(s) {column}")
    assert not marker.exists(), "a job ran before the store was checked"
    assert_one_line(tool("report", store), {ExitCode.STORE}, f"lacks the column(s) {column}")
    assert state(store) == before


# --------------------------------------------------------------------------- a full disk


def integrity(path: Path) -> tuple[str, list]:
    connection = sqlite3.connect(path)
    try:
        check = connection.execute("PRAGMA integrity_check").fetchone()[0]
        rows = connection.execute("SELECT problem, method FROM results ORDER BY rowid").fetchall()
    finally:
        connection.close()
    return check, rows


@pytest.mark.parametrize("limit", [0, 8 * 1024, 20 * 1024])
def test_a_full_disk_while_creating_a_store_leaves_no_store(tmp_path, limit):
    suite = suite_of(tmp_path, problems=20, broken=True)
    store = tmp_path / "results.sqlite"
    finished = tool("compare", suite, "--methods", "pure", "--store", store, "-q", limit_bytes=limit)
    assert_one_line(finished, {ExitCode.STORE, ExitCode.INPUT_FILE}, "the disk is full or a file-size limit")
    assert "cannot rollback" not in finished.stderr
    assert state(store) == (None, [])


@pytest.mark.parametrize("room", [0, 8 * 1024, 16 * 1024], ids=["no-room", "8k", "16k"])
def test_a_full_disk_while_writing_keeps_every_stored_row(tmp_path, room):
    suite = suite_of(tmp_path, problems=40, broken=True)
    store = populated_store(tmp_path / "results.sqlite")
    _, before = integrity(store)
    limit = max(store.stat().st_size, 32 * 1024) + room  # SQLite's WAL index alone takes 32 KiB
    arguments = ("compare", suite, "--methods", "pure,relevance,random", "--store", store, "-q")
    finished = tool(*arguments, limit_bytes=limit)
    assert_one_line(finished, {ExitCode.STORE}, "the disk is full or a file-size limit was reached")
    assert "cannot rollback" not in finished.stderr
    check, after = integrity(store)
    assert check == "ok" and after[: len(before)] == before and len(after) < len(before) + 120


def test_a_full_disk_before_the_index_file_fits_is_one_line_and_changes_nothing(tmp_path):
    suite = suite_of(tmp_path, problems=2, broken=True)
    store = populated_store(tmp_path / "results.sqlite")
    before = store.read_bytes()
    finished = tool("compare", suite, "--methods", "pure", "--store", store, "-q", limit_bytes=store.stat().st_size)
    assert_one_line(finished, {ExitCode.STORE}, "the disk is full or a file-size limit was reached")
    assert store.read_bytes() == before
    # SQLite may leave its (empty) log and a partial index beside it: nothing of the store is in them.
    wal = store.with_name(store.name + "-wal")
    assert not wal.exists() or wal.stat().st_size == 0
    assert tool("report", store).returncode == 0


# --------------------------------------------------------------------------- rows another program wrote

BAD_ROWS = {
    "wall-time-text": {"wall_time": "abc"},
    "wall-time-infinite": {"wall_time": float("inf")},
    "timeout-negative": {"timeout": -5.0},
    "objects-a-fraction": {"objects_total": 2.5},
    "status-a-blob": {"status": b"\x00solved"},
    "config-a-list": {"config_json": "[1, 2]"},
    "config-not-json": {"config_json": "{'a': 1"},
    "result-nested-deep": {"result_json": "[" * 100_000 + "]" * 100_000},
    "seed-empty": {"seed": None},
}


@pytest.mark.parametrize("label", BAD_ROWS)
def test_a_row_of_the_wrong_kind_is_one_store_error_for_every_reader(tmp_path, label):
    """Written by another program (SQLite keeps text in a REAL column): every output of report, and
    learn --store, say which row in one line (exit 36), and leave the store and the folder as they were."""
    pytest.importorskip("matplotlib")
    store = tmp_path / "s.sqlite"
    with ResultStore(store) as writing:
        writing.add(make_row("suite", "p01", "relevance"))
    connection = sqlite3.connect(store, isolation_level=None)
    # NOT NULL columns too: the table is copied without its constraints
    connection.execute("CREATE TABLE copied AS SELECT * FROM results")
    connection.execute("DROP TABLE results")
    connection.execute("ALTER TABLE copied RENAME TO results")
    row = {**make_row("suite", "p02", "pure"), **BAD_ROWS[label]}
    columns, marks = ", ".join(row), ", ".join("?" * len(row))
    connection.execute(f"INSERT INTO results ({columns}) VALUES ({marks})", list(row.values()))
    connection.close()
    problem = tmp_path / "p02.pddl"
    problem.write_text("(define (problem p02) (:domain gripper) (:objects r1) (:init (room r1)) (:goal (room r1)))")
    before = store.read_bytes()
    outputs = ([], ["--json"], ["--csv"], ["--format", "latex"], ["--html", tmp_path / "r.html"], ["--plots", tmp_path])
    for extra in outputs:
        code, _, stderr = run("report", store, *extra)
        assert code == ExitCode.STORE and "row 2" in one_line_error(stderr), (extra, stderr)
    code, _, stderr = run("learn", GRIPPER, problem, "--store", store, "-o", tmp_path / "m.json")
    assert code == ExitCode.STORE and "row 2" in one_line_error(stderr)
    assert store.read_bytes() == before and sorted(p.name for p in tmp_path.iterdir()) == ["p02.pddl", "s.sqlite"]
