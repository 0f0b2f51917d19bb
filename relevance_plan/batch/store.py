"""The results store of batch runs: one SQLite file, one row per finished job.

The file is in WAL mode with ``synchronous=NORMAL``: every committed row
survives a ``kill -9`` of the writing process, and
readers (``relevance-plan report``) never block the writer.  Each finished
job is written in its own transaction, so an interrupted batch loses at most
the jobs that were still running; rerunning the same command skips every job
whose key is already stored.

A row's key is ``(problem_hash, method, config_hash, planner_version)``:

- ``problem_hash``: sha256 of the domain text, a NUL byte and the problem
  text (the files' bytes), so renaming or moving a suite keeps its results
  (a problem that cannot be read is keyed by its file name and the reason);
- ``config_hash``: sha256 of the canonical JSON of the options that influence
  the result (see ``batch.keys.config_fingerprint``);
- ``planner_version``: the up-fast-downward version (plus a digest of the
  driver file when ``$RELEVANCE_PLAN_FAST_DOWNWARD`` overrides it).

The ``meta`` table holds ``schema_version`` and the version of the tool that
created the store.  Schema 2 added ``plan_cost``: a schema-1 store is read as
it is (its rows' cost unknown) and migrated in place, one ``ALTER TABLE`` in
one transaction that keeps every row, only when a command writes into it
(``compare``).  A store of another schema version, one missing a
column, or a file that is not a SQLite database, raises ``StoreError`` and is
left untouched: nothing is written (not even the journal mode) before those
checks pass.  Creating a store is one ``BEGIN IMMEDIATE`` transaction that
looks for the tables and creates them only when missing, so two runs
creating the same new store at once both use it.  A store or folder that cannot be written is ``InputFileError``
(``check_store_writable``), found before a batch runs its first job; a
write that finds the disk full is one ``StoreError`` line, and a store
created by the failing run is removed again.
"""

from __future__ import annotations

import contextlib
import math
import os
import sqlite3
import stat
from pathlib import Path
from typing import Any, NamedTuple

from relevance_plan import __version__
from relevance_plan.errors import InputFileError, StoreError
from relevance_plan.io import parse_json

SCHEMA_VERSION = 2
OLDEST_SCHEMA_VERSION = 1  # the oldest a store may have to be read, or migrated when written to
# Columns each older schema version lacks, added by ``_migrate`` (all nullable: old rows keep NULL).
ADDED_IN: dict[int, tuple[str, ...]] = {2: ("plan_cost",)}
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
    ("plan_cost", "REAL"),  # PlanResult.plan_cost: the validated total-cost, or the length at unit cost
    ("timeout", "REAL NOT NULL"),
    ("message", "TEXT NOT NULL"),
    ("config_json", "TEXT NOT NULL"),  # the canonical JSON that config_hash hashes
    ("finished_at", "TEXT NOT NULL"),  # ISO 8601, UTC, when the job finished
    ("result_json", "TEXT NOT NULL"),  # PlanResult.to_json() (or the error) as JSON
)

COLUMNS: tuple[str, ...] = KEY_COLUMNS + tuple(name for name, _ in DATA_COLUMNS)
KEY_DECLARED: tuple[tuple[str, str], ...] = tuple((name, "TEXT NOT NULL") for name in KEY_COLUMNS)

_CREATE_RESULTS = (
    "CREATE TABLE results (\n"
    + "".join(f"    {name} {kind},\n" for name, kind in KEY_DECLARED)
    + "".join(f"    {name} {kind},\n" for name, kind in DATA_COLUMNS)
    + f"    PRIMARY KEY ({', '.join(KEY_COLUMNS)})\n)"
)


def _one_line(error: BaseException) -> str:
    return " ".join(str(error).split()) or type(error).__name__


# How SQLite reports a write that found no room (a full disk, a file-size limit).
_NO_ROOM = {"SQLITE_FULL", "SQLITE_IOERR_WRITE", "SQLITE_IOERR_SHMSIZE", "SQLITE_IOERR_TRUNCATE"}


def _full(error: sqlite3.Error) -> bool:
    return getattr(error, "sqlite_errorname", "") in _NO_ROOM


def _write_failure(error: sqlite3.Error) -> str:
    """What a failed write means, in words (a full disk says so rather than 'disk I/O error')."""
    if _full(error):
        return f"the disk is full or a file-size limit was reached ({_one_line(error)})"
    return _one_line(error)


def _companions(path: Path) -> list[Path]:
    """The files SQLite keeps beside a store."""
    return [path.with_name(path.name + suffix) for suffix in ("-wal", "-shm", "-journal")]


def _no_write_bit(path: Path) -> bool:
    # Refused even for root, who may write anyway: the user protected it.
    return not path.stat().st_mode & 0o222 or not os.access(path, os.W_OK)


def check_store_writable(path: str | os.PathLike) -> None:
    """``InputFileError`` unless a results store can be written at ``path``; nothing is created.

    A store in WAL mode keeps two files beside it, so its folder must be
    writable too.  Called before any job runs.
    """
    path = Path(path)
    try:
        info = path.stat()
    except FileNotFoundError:
        info = None
    except (OSError, ValueError) as error:
        reason = getattr(error, "strerror", None) or _one_line(error)
        raise InputFileError(f"cannot use the results store: {reason}", path=str(path)) from None
    if info is not None and not stat.S_ISREG(info.st_mode):
        raise InputFileError("results store is not a file", path=str(path))
    if info is not None and _no_write_bit(path):
        raise InputFileError("results store is read-only", path=str(path))
    folder = Path(os.path.realpath(path)).parent
    if not folder.is_dir():
        raise InputFileError("directory of the results store does not exist", path=str(path))
    if _no_write_bit(folder):
        raise InputFileError(
            "cannot write the results store: its folder is read-only (SQLite keeps two files beside it)",
            path=str(path),
        )


class ResultStore:
    """A results store at ``path``; created when missing unless ``create=False``.

    ``read_only=True`` (reading commands) never creates or changes anything:
    a file that is not a store is refused and stays byte-identical, and a
    store on a read-only file system is read as it is.  A store this object
    created is removed again when writing to it failed before any row was in it.

    Use from one thread (the batch's main thread writes; workers only compute).
    """

    def __init__(self, path: str | os.PathLike, *, create: bool = True, read_only: bool = False):
        self.path = Path(path)
        self._connection: sqlite3.Connection | None = None
        self.missing_columns: tuple[str, ...] = ()  # of an older store read as it is (their values: None)
        exists = self.path.exists()
        if exists and not self.path.is_file():
            raise InputFileError("results store is not a file", path=str(self.path))
        if not exists:
            if not create or read_only:
                raise InputFileError("results store not found", path=str(self.path))
            if not self.path.parent.is_dir():
                raise InputFileError("directory of the results store does not exist", path=str(self.path))
        else:
            self._check_header()
            if read_only and self.path.stat().st_size == 0:
                raise StoreError("empty file, not a results store", path=str(self.path))
        self.created = False
        if not exists:
            self.created = self._create_whole()
        # Companion files this object makes SQLite create are folded away again on closing.
        self._tidy = not any(path.exists() for path in _companions(self.path))
        connection = self._connect_read_only() if read_only else self._connect()
        try:
            connection.row_factory = sqlite3.Row
            connection.execute(f"PRAGMA busy_timeout = {BUSY_TIMEOUT_MS}")
            self._check_or_create(connection, not read_only)
            if not read_only:
                connection.execute("PRAGMA journal_mode = WAL")
            connection.execute("PRAGMA synchronous = NORMAL")
            connection.execute("SELECT COUNT(*) FROM results").fetchone()  # the first read opens the WAL index
        except sqlite3.DatabaseError as error:
            self._abandon(connection)
            if self.created:
                message = f"cannot create the results store: {_write_failure(error)}"
                raise StoreError(message, path=str(self.path)) from None
            if _full(error):
                message = f"cannot write to the results store: {_write_failure(error)}"
                raise StoreError(message, path=str(self.path)) from None
            raise StoreError(f"not a usable results store ({_one_line(error)})", path=str(self.path)) from None
        except BaseException:
            self._abandon(connection)
            raise
        self._connection = connection

    # ------------------------------------------------------------------ opening

    def _create_whole(self) -> bool:
        """Make the new store beside its path, tables and WAL mode set, then link it into place: a run
        that creates the same store at this moment finds either no file or a whole one (never an
        empty file another connection is still setting up).  True if this object's file is the store."""
        building = self.path.with_name(f".{self.path.name}.{os.getpid()}.{id(self):x}.creating")
        try:
            connection = sqlite3.connect(building, isolation_level=None)
            try:
                self.meta = _create_tables(connection)
                connection.execute("PRAGMA journal_mode = WAL")
            finally:
                connection.close()
            os.link(building, self.path)
            return True
        except FileExistsError:
            return False  # another run made it first: this one opens theirs
        except sqlite3.Error as error:
            message = f"cannot create the results store: {_write_failure(error)}"
            raise StoreError(message, path=str(self.path)) from None
        except OSError as error:
            message = f"cannot create the results store: {error.strerror or error}"
            raise StoreError(message, path=str(self.path)) from None
        finally:
            for path in (building, *_companions(building)):
                with contextlib.suppress(OSError):
                    path.unlink()

    def _connect(self) -> sqlite3.Connection:
        try:
            return sqlite3.connect(self.path, isolation_level=None, timeout=BUSY_TIMEOUT_MS / 1000)
        except sqlite3.Error as error:
            raise StoreError(f"cannot open the results store: {_one_line(error)}", path=str(self.path)) from None

    def _connect_read_only(self) -> sqlite3.Connection:
        """Read-only: a file that is not a store stays byte-identical.

        SQLite reads a WAL store by creating its index file beside it; where
        that folder is read-only (a read-only file system) and no write is
        pending in a ``-wal`` file, the store is opened as immutable instead.
        """
        uri = self.path.resolve().as_uri()
        try:
            return _probed_connection(uri + "?mode=ro")
        except sqlite3.Error as error:
            wal = self.path.with_name(self.path.name + "-wal")
            if os.access(self.path.resolve().parent, os.W_OK) or (wal.exists() and wal.stat().st_size > 0):
                raise StoreError(f"cannot read the results store: {_one_line(error)}", path=str(self.path)) from None
        try:
            return _probed_connection(uri + "?immutable=1")
        except sqlite3.Error as error:
            raise StoreError(f"cannot read the results store: {_one_line(error)}", path=str(self.path)) from None

    def _abandon(self, connection: sqlite3.Connection) -> None:
        """Close after a failed open; a store this object created goes away again."""
        connection.close()
        if self.created:
            self._remove_files()
        else:
            self._fold_companions()

    def _fold_companions(self) -> None:
        """Let SQLite remove the ``-wal`` and ``-shm`` files this object left (a reader cannot).

        Only when they did not exist before: another process's files are its
        own.  A writing connection that closes last folds an empty WAL away
        without changing the store's bytes.
        """
        if not self._tidy or not any(path.exists() for path in _companions(self.path)):
            return
        if not os.access(self.path.parent, os.W_OK):
            return
        with contextlib.suppress(sqlite3.Error):
            connection = sqlite3.connect(self.path, isolation_level=None)
            try:
                connection.execute("SELECT COUNT(*) FROM sqlite_master").fetchone()  # opens the WAL, to close it
            finally:
                connection.close()

    def _remove_files(self) -> None:
        for path in (self.path, *_companions(self.path)):
            with contextlib.suppress(OSError):
                path.unlink()

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
        """Check the tables (``create``: inside one write transaction, creating or migrating them)."""
        if not create:
            self.meta, self.missing_columns = _checked_schema(connection, _tables(connection), False, self.path)
            return
        # IMMEDIATE takes the write lock first (waiting up to the busy timeout): a run that creates
        # the same new store at this moment either creates the tables or finds them made.
        connection.execute("BEGIN IMMEDIATE")
        try:
            tables = _tables(connection)
            if tables:
                self.meta, self.missing_columns = _checked_schema(connection, tables, True, self.path)
            else:
                self.meta = _create_tables(connection)
            connection.execute("COMMIT")
        except BaseException:
            _roll_back(connection)
            raise

    # ------------------------------------------------------------------ access

    @property
    def connection(self) -> sqlite3.Connection:
        if self._connection is None:
            raise StoreError("results store is closed", path=str(self.path))
        return self._connection

    def contains(self, key: ResultKey) -> bool:
        rows = self._query(
            "SELECT 1 FROM results WHERE problem_hash = ? AND method = ? AND config_hash = ? AND planner_version = ?",
            tuple(key),
        )
        return bool(rows)

    def _query(self, sql: str, parameters: tuple = ()) -> list[sqlite3.Row]:
        try:
            return self.connection.execute(sql, parameters).fetchall()
        except sqlite3.Error as error:
            raise StoreError(f"cannot read the results store: {_one_line(error)}", path=str(self.path)) from None

    def keys(self) -> set[ResultKey]:
        return {ResultKey(*row) for row in self._query(f"SELECT {', '.join(KEY_COLUMNS)} FROM results")}

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
            _roll_back(connection)
            message = f"cannot write to the results store: {_write_failure(error)}"
            raise StoreError(message, path=str(self.path)) from None
        return cursor.rowcount == 1

    def rows(self, suite: str | None = None) -> list[dict[str, Any]]:
        """Stored rows (with their ``rowid``) in insertion order, optionally of one suite.

        Each row is checked against the declared columns before anyone uses it (``check_row``): a
        row another program wrote, with text for a time or a list for its options, is a
        ``StoreError`` naming the row, never a crash of the report.
        """
        query = "SELECT rowid, * FROM results"
        parameters: tuple = ()
        if suite is not None:
            query += " WHERE suite = ?"
            parameters = (suite,)
        unknown = dict.fromkeys(self.missing_columns)
        rows = [{**dict(row), **unknown} for row in self._query(query + " ORDER BY rowid", parameters)]
        for row in rows:
            problem = check_row(row, self.missing_columns)
            if problem:
                raise StoreError(
                    f"row {row['rowid']} is not a result row of relevance-plan: {problem}", path=str(self.path)
                )
        return rows

    def __len__(self) -> int:
        return self._query("SELECT COUNT(*) FROM results")[0][0]

    def close(self) -> None:
        if self._connection is not None:
            self._connection.close()
            self._connection = None
            self._fold_companions()

    def __enter__(self) -> ResultStore:
        return self

    def __exit__(self, kind, error, traceback) -> None:
        # A store this run created and could not write a single row to is not left behind.
        discard = False
        if isinstance(error, StoreError) and self.created and self._connection is not None:
            with contextlib.suppress(StoreError):
                discard = len(self) == 0
        self.close()
        if discard:
            self._remove_files()


# --------------------------------------------------------------------------- the schema


def _tables(connection: sqlite3.Connection) -> set[str]:
    return {row[0] for row in connection.execute("SELECT name FROM sqlite_master WHERE type = 'table'")}


def _checked_schema(
    connection: sqlite3.Connection, tables: set[str], writing: bool, path: Path
) -> tuple[dict[str, str], tuple[str, ...]]:
    """The meta table of an existing store, and the columns an older schema lacks (read as None);
    ``writing`` (inside the caller's transaction) migrates an older schema instead."""
    if not tables:
        raise StoreError("SQLite database without relevance-plan results (no tables)", path=str(path))
    if "meta" not in tables or "results" not in tables:
        raise StoreError("SQLite database without relevance-plan results (no meta/results table)", path=str(path))
    meta = dict(connection.execute("SELECT key, value FROM meta").fetchall())
    found = meta.get("schema_version")
    version = _version_number(found)
    if version is None or not OLDEST_SCHEMA_VERSION <= version <= SCHEMA_VERSION:
        creator = meta.get("tool_version", "an unknown version")
        raise StoreError(
            f"results store has schema version {found} (written by relevance-plan {creator}); this is "
            f"relevance-plan {__version__} with schema version {SCHEMA_VERSION}: use a new --store file",
            path=str(path),
        )
    later = {name for added, names in ADDED_IN.items() if added > version for name in names}
    present = {row[1] for row in connection.execute("PRAGMA table_info(results)")}
    missing = [name for name in COLUMNS if name not in present and name not in later]
    if missing:
        raise StoreError(
            f"results store lacks the column(s) {', '.join(missing)}: use a new --store file", path=str(path)
        )
    if later and writing:
        _migrate(connection, version, present)
        meta["schema_version"] = str(SCHEMA_VERSION)
    return meta, tuple(sorted(later)) if not writing else ()


def _migrate(connection: sqlite3.Connection, found: int, present: set[str]) -> None:
    """Bring an older store to ``SCHEMA_VERSION`` in the caller's transaction: new columns only."""
    kinds = dict(DATA_COLUMNS)
    for version in range(found + 1, SCHEMA_VERSION + 1):
        for name in ADDED_IN.get(version, ()):
            if name not in present:
                connection.execute(f"ALTER TABLE results ADD COLUMN {name} {kinds[name]}")
    connection.execute("UPDATE meta SET value = ? WHERE key = 'schema_version'", (str(SCHEMA_VERSION),))
    connection.execute("INSERT OR REPLACE INTO meta (key, value) VALUES ('migrated_by', ?)", (__version__,))


def _create_tables(connection: sqlite3.Connection) -> dict[str, str]:
    """The tables of a new store, in the caller's transaction; returns its meta table."""
    connection.execute("CREATE TABLE meta (key TEXT PRIMARY KEY, value TEXT NOT NULL)")
    connection.executemany(
        "INSERT INTO meta (key, value) VALUES (?, ?)",
        [("schema_version", str(SCHEMA_VERSION)), ("tool_version", __version__)],
    )
    connection.execute(_CREATE_RESULTS)
    connection.execute("CREATE INDEX results_suite ON results (suite, method)")
    return {"schema_version": str(SCHEMA_VERSION), "tool_version": __version__}


# Columns whose numbers cannot be negative (times, counts); every stored number is finite.
_NOT_NEGATIVE = frozenset(
    {
        "wall_time",
        "relevance_time",
        "planner_time",
        "timeout",
        "objects_total",
        "objects_kept",
        "attempts",
        "plan_length",
    }
)
# Columns holding a JSON object.
JSON_COLUMNS = ("config_json", "result_json")


def check_row(row: dict[str, Any], missing: tuple[str, ...] = ()) -> str:
    """What is wrong with a stored row ('' when nothing): each column of the kind its declared SQL type
    says (``missing``: columns an older store lacks, None), the JSON columns JSON objects."""
    for name, declared in KEY_DECLARED + DATA_COLUMNS:
        value = row.get(name)
        kind = declared.split()[0]
        if value is None:
            if "NOT NULL" in declared and name not in missing:
                return f"{name} is empty"
            continue
        if kind == "TEXT" and not isinstance(value, str):
            return f"{name} is {value!r}, not text"
        if kind in ("INTEGER", "REAL") and not _number(value, integer=kind == "INTEGER"):
            return f"{name} is {str(value)[:40]!r}, not {'an integer' if kind == 'INTEGER' else 'a finite number'}"
        if name in _NOT_NEGATIVE and value < 0:
            return f"{name} is {value!r}, below 0"
    for name in JSON_COLUMNS:
        try:
            found = parse_json(row[name])
        except ValueError as error:
            return f"{name} is not JSON ({error})"
        if not isinstance(found, dict):
            return f"{name} is not a JSON object"
    return ""


def _number(value: Any, integer: bool) -> bool:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return False
    return isinstance(value, int) if integer else math.isfinite(value)


def _version_number(text: str | None) -> int | None:
    try:
        return int(text) if text is not None else None
    except ValueError:
        return None


def _probed_connection(uri: str) -> sqlite3.Connection:
    """A connection to ``uri`` that has read once (SQLite opens files lazily, failing at the first read)."""
    connection = sqlite3.connect(uri, uri=True, isolation_level=None, timeout=BUSY_TIMEOUT_MS / 1000)
    try:
        connection.execute("SELECT COUNT(*) FROM sqlite_master").fetchone()
    except sqlite3.Error:
        connection.close()
        raise
    return connection


def _roll_back(connection: sqlite3.Connection) -> None:
    """Undo a failed transaction; SQLite may already have (after a full disk), which is fine."""
    if connection.in_transaction:
        with contextlib.suppress(sqlite3.Error):
            connection.execute("ROLLBACK")


def read_rows(path: str | os.PathLike, suite: str | None = None) -> list[dict[str, Any]]:
    """Rows of an existing store (``InputFileError`` if it is missing; never creates one)."""
    with ResultStore(path, create=False, read_only=True) as store:
        return store.rows(suite)
