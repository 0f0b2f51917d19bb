"""The results store of batch runs: one SQLite file, one row per finished job.

The file is in WAL mode with ``synchronous=NORMAL``: every committed row
survives a ``kill -9`` of the writing process, and
readers (``relevance-plan report``) never block the writer.  Each finished
job is written in its own transaction, so an interrupted batch loses at most
the jobs that were still running; rerunning the same command skips every job
whose key is already stored.

A row's key is ``(problem_hash, method, config_hash, planner_version)``:

- ``problem_hash``: sha256 of the domain text, a NUL byte and the problem
  text (the files' bytes), so renaming or moving a suite keeps its results;
- ``config_hash``: sha256 of the canonical JSON of the options that influence
  the result (see ``batch.config_fingerprint``);
- ``planner_version``: the up-fast-downward version (plus a digest of the
  driver file when ``$RELEVANCE_PLAN_FAST_DOWNWARD`` overrides it).

The ``meta`` table holds ``schema_version`` and the version of the tool that
created the store.  A store of another schema version, or a file that is not
a SQLite database, raises ``StoreError`` and is left untouched: nothing is
written (not even the journal mode) before those checks pass.
"""

from __future__ import annotations

import os
import sqlite3
from collections.abc import Iterable
from pathlib import Path
from typing import Any, NamedTuple

from relevance_plan import __version__
from relevance_plan.errors import InputFileError, StoreError

SCHEMA_VERSION = 1
SQLITE_HEADER = b"SQLite format 3\x00"
BUSY_TIMEOUT_MS = 30_000


class ResultKey(NamedTuple):
    problem_hash: str
    method: str
    config_hash: str
    planner_version: str


KEY_COLUMNS = ResultKey._fields

# (name, SQL type) in table order, after the key columns.
DATA_COLUMNS: tuple[tuple[str, str], ...] = (
    ("suite", "TEXT NOT NULL"),
    ("problem", "TEXT NOT NULL"),  # file name inside the suite
    ("world", "TEXT"),
    ("difficulty", "TEXT"),
    ("seed", "INTEGER NOT NULL"),
    ("status", "TEXT NOT NULL"),  # PlanStatus value, e.g. solved, out-of-time, input-error
    ("valid", "INTEGER NOT NULL"),  # 1 if the plan was validated on the original problem
    ("exit_code", "INTEGER"),  # planner exit code of the last attempt (None without a planner run)
    ("wall_time", "REAL NOT NULL"),  # whole job: parsing, relevance, planning, validation
    ("relevance_time", "REAL NOT NULL"),
    ("planner_time", "REAL NOT NULL"),
    ("objects_total", "INTEGER NOT NULL"),
    ("objects_kept", "INTEGER NOT NULL"),
    ("attempts", "INTEGER NOT NULL"),
    ("first_attempt_status", "TEXT"),
    ("plan_length", "INTEGER"),
    ("timeout", "REAL NOT NULL"),
    ("message", "TEXT NOT NULL"),
    ("config_json", "TEXT NOT NULL"),  # the canonical JSON that config_hash hashes
    ("finished_at", "TEXT NOT NULL"),  # ISO 8601, UTC, when the job finished
    ("result_json", "TEXT NOT NULL"),  # PlanResult.to_json() (or the error) as JSON
)

COLUMNS: tuple[str, ...] = KEY_COLUMNS + tuple(name for name, _ in DATA_COLUMNS)

_CREATE_RESULTS = (
    "CREATE TABLE results (\n"
    + "".join(f"    {name} TEXT NOT NULL,\n" for name in KEY_COLUMNS)
    + "".join(f"    {name} {kind},\n" for name, kind in DATA_COLUMNS)
    + f"    PRIMARY KEY ({', '.join(KEY_COLUMNS)})\n)"
)


def _one_line(error: BaseException) -> str:
    return " ".join(str(error).split()) or type(error).__name__


class ResultStore:
    """A results store at ``path``; created when missing unless ``create=False``.

    ``read_only=True`` (reading commands) never creates or changes anything:
    a file that is not a store is refused and stays byte-identical.

    Use from one thread (the batch's main thread writes; workers only compute).
    """

    def __init__(self, path: str | os.PathLike, *, create: bool = True, read_only: bool = False):
        self.path = Path(path)
        self._connection: sqlite3.Connection | None = None
        exists = self.path.exists()
        if exists and not self.path.is_file():
            raise InputFileError("results store is not a file", path=str(self.path))
        if not exists:
            if not create:
                raise InputFileError("results store not found", path=str(self.path))
            if not self.path.parent.is_dir():
                raise InputFileError("directory of the results store does not exist", path=str(self.path))
        else:
            self._check_header()
            if read_only and self.path.stat().st_size == 0:
                raise StoreError("empty file, not a results store", path=str(self.path))
        try:
            if not read_only:
                connection = sqlite3.connect(self.path, isolation_level=None, timeout=BUSY_TIMEOUT_MS / 1000)
            else:
                # Reading commands open read-only: a file that is not a store stays byte-identical.
                uri = self.path.resolve().as_uri() + "?mode=ro"
                connection = sqlite3.connect(uri, uri=True, isolation_level=None, timeout=BUSY_TIMEOUT_MS / 1000)
        except sqlite3.Error as error:
            raise StoreError(f"cannot open the results store: {_one_line(error)}", path=str(self.path)) from None
        try:
            connection.row_factory = sqlite3.Row
            connection.execute(f"PRAGMA busy_timeout = {BUSY_TIMEOUT_MS}")
            self._check_or_create(connection, not read_only)
            if not read_only:
                connection.execute("PRAGMA journal_mode = WAL")
            connection.execute("PRAGMA synchronous = NORMAL")
        except sqlite3.DatabaseError as error:
            connection.close()
            raise StoreError(f"not a usable results store ({_one_line(error)})", path=str(self.path)) from None
        except BaseException:
            connection.close()
            raise
        self._connection = connection

    # ------------------------------------------------------------------ opening

    def _check_header(self) -> None:
        try:
            with open(self.path, "rb") as stream:
                header = stream.read(len(SQLITE_HEADER))
        except OSError as error:
            raise InputFileError(f"cannot read the results store: {error.strerror}", path=str(self.path)) from None
        # An empty file is what SQLite itself treats as an empty database.
        if header and header != SQLITE_HEADER:
            raise StoreError("not a SQLite database (not a results store)", path=str(self.path))

    def _check_or_create(self, connection: sqlite3.Connection, create: bool = True) -> None:
        tables = {row[0] for row in connection.execute("SELECT name FROM sqlite_master WHERE type = 'table'")}
        if not tables:
            if not create:
                raise StoreError("SQLite database without relevance-plan results (no tables)", path=str(self.path))
            self._create(connection)
            return
        if "meta" not in tables or "results" not in tables:
            raise StoreError(
                "SQLite database without relevance-plan results (no meta/results table)", path=str(self.path)
            )
        meta = dict(connection.execute("SELECT key, value FROM meta").fetchall())
        found = meta.get("schema_version")
        if found != str(SCHEMA_VERSION):
            creator = meta.get("tool_version", "an unknown version")
            raise StoreError(
                f"results store has schema version {found} (written by relevance-plan {creator}); this is "
                f"relevance-plan {__version__} with schema version {SCHEMA_VERSION}: use a new --store file",
                path=str(self.path),
            )
        self.meta = meta

    def _create(self, connection: sqlite3.Connection) -> None:
        connection.execute("BEGIN IMMEDIATE")
        try:
            connection.execute("CREATE TABLE meta (key TEXT PRIMARY KEY, value TEXT NOT NULL)")
            connection.executemany(
                "INSERT INTO meta (key, value) VALUES (?, ?)",
                [("schema_version", str(SCHEMA_VERSION)), ("tool_version", __version__)],
            )
            connection.execute(_CREATE_RESULTS)
            connection.execute("CREATE INDEX results_suite ON results (suite, method)")
            connection.execute("COMMIT")
        except BaseException:
            connection.execute("ROLLBACK")
            raise
        self.meta = {"schema_version": str(SCHEMA_VERSION), "tool_version": __version__}

    # ------------------------------------------------------------------ access

    @property
    def connection(self) -> sqlite3.Connection:
        if self._connection is None:
            raise StoreError("results store is closed", path=str(self.path))
        return self._connection

    def contains(self, key: ResultKey) -> bool:
        row = self.connection.execute(
            "SELECT 1 FROM results WHERE problem_hash = ? AND method = ? AND config_hash = ? AND planner_version = ?",
            tuple(key),
        ).fetchone()
        return row is not None

    def keys(self) -> set[ResultKey]:
        return {ResultKey(*row) for row in self.connection.execute(f"SELECT {', '.join(KEY_COLUMNS)} FROM results")}

    def add(self, row: dict[str, Any]) -> bool:
        """Insert one finished job in its own transaction; False if its key was already stored."""
        missing = [name for name in COLUMNS if name not in row]
        if missing:
            raise StoreError(f"result row lacks column(s) {', '.join(missing)}", path=str(self.path))
        values = tuple(row[name] for name in COLUMNS)
        placeholders = ", ".join("?" for _ in COLUMNS)
        connection = self.connection
        try:
            connection.execute("BEGIN IMMEDIATE")
            cursor = connection.execute(
                f"INSERT OR IGNORE INTO results ({', '.join(COLUMNS)}) VALUES ({placeholders})", values
            )
            connection.execute("COMMIT")
        except sqlite3.Error as error:
            if connection.in_transaction:
                connection.execute("ROLLBACK")
            raise StoreError(f"cannot write to the results store: {_one_line(error)}", path=str(self.path)) from None
        return cursor.rowcount == 1

    def rows(self, suite: str | None = None) -> list[dict[str, Any]]:
        """Stored rows (with their ``rowid``) in insertion order, optionally of one suite."""
        query = "SELECT rowid, * FROM results"
        parameters: tuple = ()
        if suite is not None:
            query += " WHERE suite = ?"
            parameters = (suite,)
        return [dict(row) for row in self.connection.execute(query + " ORDER BY rowid", parameters)]

    def __len__(self) -> int:
        return self.connection.execute("SELECT COUNT(*) FROM results").fetchone()[0]

    def close(self) -> None:
        if self._connection is not None:
            self._connection.close()
            self._connection = None

    def __enter__(self) -> ResultStore:
        return self

    def __exit__(self, *exc) -> None:
        self.close()


def read_rows(path: str | os.PathLike, suite: str | None = None) -> list[dict[str, Any]]:
    """Rows of an existing store (``InputFileError`` if it is missing; never creates one)."""
    with ResultStore(path, create=False, read_only=True) as store:
        return store.rows(suite)


def add_rows(store: ResultStore, rows: Iterable[dict[str, Any]]) -> int:
    """Add several rows, one transaction each; the number actually inserted."""
    return sum(store.add(row) for row in rows)
