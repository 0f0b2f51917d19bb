"""Process supervision: run a planner so that it can always be stopped, whole.

Every planner adapter runs its processes through :func:`run_process_group`:
a fresh working directory chosen by the caller, a session of its own led by
the guard (``guard.py``), the output in a file log, a wall-clock watchdog,
and the guard's pid kept reserved (unreaped) until every process of the run
is gone.  The runs going on now are registered, so a batch's Ctrl-C can stop
them all (:func:`terminate_all_runs`).  The module is thread-safe: many runs
may go at once from a thread pool.

A run is stopped whole at its time limit, when it ends, on Ctrl-C or
SIGTERM, and (by the guard) when the tool itself is killed.  How much
"whole" covers depends on the system:

* Linux with a writable cgroup v2 (the tool may create a cgroup below its
  own): the guard and everything it starts live in a cgroup of their own,
  killed at once (``cgroup.kill``).  Nothing the planner starts escapes,
  whatever it does with sessions, process groups or its own parents.
  ``$RELEVANCE_PLAN_NO_CGROUP=1`` turns this off.
* Linux otherwise: the guard is a child subreaper, so every process the
  planner starts stays its descendant (``setsid``, ``timeout``, double
  forks included); the descendants are found in ``/proc`` and killed until
  none is left.  Only a planner that kills its own guard with SIGKILL and
  leaves a process outside the guard's process group can escape.
* Elsewhere (macOS): the guard's process group.

VAL's ``Validate``, the one other program the tool starts, is found by ``val.py`` and run as a planner is.

The start itself is :mod:`spawn`'s (the launcher's head start uses it before
anything else is imported); this module waits for runs, stops them and
reads what they leave.
"""

from __future__ import annotations

import contextlib
import contextvars
import os
import shutil
import signal
import stat
import tempfile
import threading
import time
from collections.abc import Iterator
from pathlib import Path
from typing import BinaryIO, NamedTuple

from relevance_plan import errors
from relevance_plan.supervision import guard, spawn
from relevance_plan.supervision.spawn import LOG_FILE

LOG_TAIL_LINES = 40
# Past the time limit, the planner's own limit may act first for this long before the watchdog kills it.
DEFAULT_WATCHDOG_GRACE = 0.5
# What is read of a planner's output or plan file: its memory and time stay bounded whatever it writes.
MAX_OUTPUT_BYTES = 8 * 2**20
_LOW_SPACE_BYTES = 64 * 1024
_NO_SPACE_MARKERS = ("No space left on device", "[Errno 28]", "ENOSPC")


class ProcessRun(NamedTuple):
    wait_status: int
    exit_code: int  # -N: killed by signal N (or a program that passed its child's death on as exit -N)
    cpu_time: float
    peak_memory_mb: float
    watchdog_fired: bool
    wall_time: float
    process_group: int

    @property
    def killed_by_watchdog(self) -> bool:
        """The watchdog fired and the group died of it (not of its own exit just before)."""
        return self.watchdog_fired and os.WIFSIGNALED(self.wait_status)


class _GroupRun:
    """A run going on: the guard's pid (= its process group and session), its cgroup (if any), and
    whether the tool stopped it (then a guard that died of a signal died of ours).  A run another
    process forked (:class:`ForkedGroup`) has its leader's start time instead of a guard."""

    __slots__ = ("pgid", "cgroup", "stopped", "forked_start")

    def __init__(self, pgid: int, cgroup: str | None, forked_start: bytes | None = None):
        self.pgid = pgid
        self.cgroup = cgroup
        self.stopped = False
        self.forked_start = forked_start


def watchdog_deadline(time_limit: float | None, grace: float | None = None) -> float | None:
    """Seconds after the start at which the watchdog kills the run: the limit plus a short
    grace period for the planner's own limit to act first (default ``DEFAULT_WATCHDOG_GRACE``, a
    quarter of the limit when that is less: a run given the last 0.3 s of a --timeout ends then,
    not half a second later)."""
    if time_limit is None:
        return None
    if grace is None:
        grace = min(DEFAULT_WATCHDOG_GRACE, time_limit / 4)
    return time_limit + grace


# --------------------------------------------------------------------------- reading what a planner wrote


def _read_regular(path: Path, limit: int) -> tuple[bytes, int] | None:
    """(at most the last ``limit`` bytes, the full size) of a regular file; None if it is not one.

    Opened without blocking: a planner may have put a FIFO where its output was expected.
    """
    try:
        handle = os.open(path, os.O_RDONLY | os.O_NONBLOCK)
    except OSError:
        return None
    with os.fdopen(handle, "rb") as stream:
        info = os.fstat(handle)
        if not stat.S_ISREG(info.st_mode):
            return None
        if info.st_size > limit:
            stream.seek(info.st_size - limit)
        return stream.read(limit), info.st_size


def read_output(path: str | os.PathLike[str], limit: int = MAX_OUTPUT_BYTES) -> str:
    """A planner's output file as text: all of it, or its last ``limit`` bytes from a line start ('' if unreadable)."""
    found = _read_regular(Path(path), limit)
    if found is None:
        return ""
    data, size = found
    if size > limit:
        data = data[data.find(b"\n") + 1 :]
    return data.decode("utf-8", errors="replace")


@contextlib.contextmanager
def work_directory(keep: str | None, prefix: str) -> Iterator[Path]:
    """Where one planner run works: ``keep`` (created if needed, left behind), else a temporary
    directory removed afterwards."""
    if keep is not None:
        path = Path(keep)
        path.mkdir(parents=True, exist_ok=True)
        yield path
        return
    with tempfile.TemporaryDirectory(prefix=prefix) as tmp:
        yield Path(tmp)


def read_log(workdir: Path) -> str:
    return read_output(workdir / LOG_FILE)


def log_tail(log: str) -> str:
    return "\n".join(log.splitlines()[-LOG_TAIL_LINES:])


def read_plan_file(path: str | os.PathLike[str], limit: int = MAX_OUTPUT_BYTES) -> str | None:
    """The text of a plan file a planner wrote; None if there is none.

    ``PlanFormatError`` when it is larger than ``limit`` bytes or not a regular file.
    """
    path = Path(path)
    if not os.path.lexists(path):
        return None
    found = _read_regular(path, limit)
    if found is None:
        raise errors.PlanFormatError("the plan file is not a regular file", path=str(path))
    data, size = found
    if size > limit:
        raise errors.PlanFormatError(
            f"the plan file is {size / 2**20:.0f} MB, over the limit of {limit // 2**20} MB", path=str(path)
        )
    return data.decode("utf-8", errors="replace")


# --------------------------------------------------------------------------- stopping a run


class CancelScope:
    """The runs one line of work starts; :meth:`cancel` stops them, and any started later, at once.

    The attempt loop's race plans the full problem in a thread beside the
    pruned attempts: whichever finds a valid plan first cancels the other.
    """

    def __init__(self) -> None:
        self._lock = threading.Lock()
        self._runs: set[_GroupRun] = set()
        self._cancelled = False

    @property
    def cancelled(self) -> bool:
        return self._cancelled

    def cancel(self) -> None:
        with self._lock:
            self._cancelled = True
            runs = list(self._runs)
        for run in runs:
            _stop(run)

    def _enter(self, run: _GroupRun) -> bool:
        """Register ``run``; False when the scope was cancelled already (the caller stops it)."""
        with self._lock:
            if self._cancelled:
                return False
            self._runs.add(run)
            return True

    def _leave(self, run: _GroupRun) -> None:
        with self._lock:
            self._runs.discard(run)


# A thread starts with no scope; run_process_group registers its runs in the current one.
_SCOPE: contextvars.ContextVar[CancelScope | None] = contextvars.ContextVar("relevance_plan_scope", default=None)


@contextlib.contextmanager
def cancel_scope(scope: CancelScope) -> Iterator[CancelScope]:
    """Runs started inside the block (in this thread) belong to ``scope``."""
    token = _SCOPE.set(scope)
    try:
        yield scope
    finally:
        _SCOPE.reset(token)


# The runs going on now, so a batch's Ctrl-C can stop them all.
_ACTIVE_GROUPS: set[_GroupRun] = set()
_ACTIVE_LOCK = threading.Lock()


def terminate_all_runs() -> int:
    """Kill every planner run this process started and still waits for.

    Each guard stays unreaped until its waiting thread returns, so a pid
    here cannot belong to an unrelated process.  Returns how many.
    """
    with _ACTIVE_LOCK:
        runs = list(_ACTIVE_GROUPS)
    for run in runs:
        _stop(run)
    return len(runs)


def _kill_group(pgid: int) -> None:
    try:
        os.killpg(pgid, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        # Group already gone (PermissionError: macOS reports a group of zombies so).
        pass


def _stop(run: _GroupRun, guard_exited: bool = False) -> None:
    """Kill every process of the run: its cgroup, the guard's descendants, the guard's group.

    Once the guard has exited it has no descendants (its orphans went to init), so ``guard_exited``
    spares the walk through /proc that looks for them.
    """
    run.stopped = True
    if run.forked_start is not None:
        # not our child: its number is ours to use only while its start time says it is still the same
        guard.kill_descendants(run.pgid)
        if guard.start_time(run.pgid) == run.forked_start:
            _kill_group(run.pgid)
        return
    if run.cgroup is not None:
        spawn.kill_cgroup(run.cgroup)
    if not guard_exited:
        # The guard, our unreaped child, anchors its descendants: kill them before it.
        guard.kill_descendants(run.pgid)
    _kill_group(run.pgid)


def _exit_code(wait_status: int) -> int:
    if os.WIFSIGNALED(wait_status):
        return -os.WTERMSIG(wait_status)
    code = os.WEXITSTATUS(wait_status)
    # The guard, and Fast Downward's driver, pass a child's death by signal N on as sys.exit(-N).
    return code - 256 if code > 128 else code


def _wait_for_run(run: _GroupRun, deadline: float | None) -> tuple[int, float, float, bool, bool]:
    """Wait for the guard; stop the whole run; reap the guard.

    Returns (wait status, cpu seconds, peak memory MB, watchdog fired, stopped by the tool before the
    guard ended: the watchdog, a cancelled scope, Ctrl-C).  The
    guard stays an unreaped zombie until every process of the run is gone,
    so its pid (= the group id) cannot be reused by an unrelated process meanwhile.
    """
    fired = threading.Event()

    def watchdog() -> None:
        fired.set()
        _stop(run)

    timer: threading.Timer | None = None
    if deadline is not None:
        timer = threading.Timer(deadline, watchdog)
        timer.daemon = True
        timer.start()
    exited = False
    try:
        if hasattr(os, "waitid"):
            os.waitid(os.P_PID, run.pgid, os.WEXITED | os.WNOWAIT)
        else:  # macOS: no waitid; reap first and accept a tiny pid-reuse window
            _, status, usage = os.wait4(run.pgid, 0)
        exited = True
    finally:
        # Runs on KeyboardInterrupt too: the planner lives in its own session,
        # so the terminal's Ctrl-C never reached it.
        if timer is not None:
            timer.cancel()
            timer.join()  # a kill in flight must land before the pid is freed
        ours = run.stopped
        # Killing only the guard would leave a running translator orphaned.
        _stop(run, guard_exited=exited)
        if hasattr(os, "waitid"):
            _await_run_death(run)
            _, status, usage = os.wait4(run.pgid, 0)
    cpu = usage.ru_utime + usage.ru_stime
    return status, cpu, usage.ru_maxrss / 1024.0, fired.is_set(), ours


def _await_run_death(run: _GroupRun, timeout: float = 2.0) -> None:
    """Wait until no process of the killed run still runs (Linux, via /proc).

    SIGKILL lands at once, but a process takes a moment to exit; the unreaped
    guard keeps the group id reserved meanwhile.  Without this, a caller
    could see the planner's children still running after the run returned.
    """
    if not os.path.isdir("/proc"):
        return
    deadline = time.monotonic() + timeout

    def running() -> bool:
        # Every process of the run is in its cgroup, whatever its group: no walk through /proc needed.
        return bool(guard.cgroup_members(run.cgroup)) if run.cgroup is not None else _group_runs(run.pgid)

    while running():
        if time.monotonic() > deadline:
            return
        time.sleep(0.005)


def _group_runs(pgid: int) -> bool:
    # a zombie has exited already
    return any(int(fields[2]) == pgid and fields[0] != b"Z" for _, fields in guard.process_stats())


# --------------------------------------------------------------------------- one run


def run_process_group(
    command: list[str],
    workdir: Path,
    deadline: float | None,
    *,
    what: str,
    program: Path | str,
    env: dict[str, str] | None = None,
    memory_limit_mb: int | None = None,
) -> ProcessRun:
    """Run ``command`` (an argument list, never a shell string) in ``workdir`` under the guard,
    as the leader of its own session, output to ``workdir/planner.log``.

    A watchdog stops the whole run ``deadline`` seconds after the start;
    the run is stopped and reaped in every case (Ctrl-C included).
    ``what`` and ``program`` name the planner in the error raised when it
    cannot start.  ``InputFileError`` when the run failed because the
    working folder's disk is full.
    """
    started = start_process_group(
        command, workdir, what=what, program=program, env=env, memory_limit_mb=memory_limit_mb
    )
    return started.finish(deadline)


class StartedGroup:
    """A run started by :func:`start_process_group`; :meth:`finish` waits for it (or :meth:`stop` ends it)."""

    def __init__(
        self,
        run: _GroupRun,
        workdir: Path,
        log_file: BinaryIO,
        guard_write: int,
        started: float,
        workdir_id: tuple[int, int],
    ):
        self.run = run
        self.workdir = workdir
        self.log_file = log_file
        self.guard_write = guard_write
        self.started = started  # time.monotonic() at the start
        self.workdir_id = workdir_id  # the working folder's (device, inode) at the start
        self._closed = False

    @classmethod
    def adopt(cls, spawned: spawn.Spawned, workdir: Path) -> StartedGroup:
        """The run ``spawned`` in ``workdir``, registered as going on (a batch's Ctrl-C stops it)."""
        run = _GroupRun(spawned.pid, spawned.cgroup)
        with _ACTIVE_LOCK:
            _ACTIVE_GROUPS.add(run)
        # A file, not a pipe: nobody has to drain it while we wait.
        log_file = open(spawned.log_fd, "w+b", closefd=True)  # noqa: SIM115 - closed by _close
        return cls(run, workdir, log_file, spawned.guard_write, spawned.started, spawned.workdir_id)

    def finish(self, deadline: float | None) -> ProcessRun:
        """Wait for the run, the watchdog firing ``deadline`` seconds after its start; reap it."""
        try:
            scope = _SCOPE.get()
            if scope is not None and not scope._enter(self.run):
                _stop(self.run)  # cancelled before it started: it ends at once and is reaped below
            left = None if deadline is None else max(deadline - (time.monotonic() - self.started), 0.0)
            try:
                wait_status, cpu_time, peak_mb, fired, ours = _wait_for_run(self.run, left)
            finally:
                if scope is not None:
                    scope._leave(self.run)
            _restore_workdir(self.workdir, self.log_file, self.workdir_id)
        finally:
            self._close()
        if os.WIFSIGNALED(wait_status) and not ours:
            _refuse_killed_guard(os.WTERMSIG(wait_status))
        exit_code = _exit_code(wait_status)
        if exit_code != 0:
            _refuse_full_disk(self.workdir)
        wall = time.monotonic() - self.started
        return ProcessRun(wait_status, exit_code, cpu_time, peak_mb, fired, wall, self.run.pgid)

    def attended(self) -> contextlib.AbstractContextManager[object]:
        """While inside, the run belongs to the current cancel scope (a long-lived worker serving one
        request): cancelling the scope kills it.  A scope cancelled already kills it at once."""
        return _attended(self.run)

    def exited(self) -> bool:
        """Whether the guard has ended (it stays unreaped, so its pid is still ours)."""
        if not hasattr(os, "waitid"):
            return False
        try:
            return os.waitid(os.P_PID, self.run.pgid, os.WEXITED | os.WNOHANG | os.WNOWAIT) is not None
        except ChildProcessError:
            return True

    def kill(self) -> None:
        """Kill every process of the run now (it is reaped by :meth:`stop`)."""
        _stop(self.run)

    def stop(self) -> None:
        """End the run and reap it (its result is not wanted)."""
        try:
            _stop(self.run)
            _wait_for_run(self.run, None)
        finally:
            self._close()

    def _close(self) -> None:
        if self._closed:
            return
        self._closed = True
        with _ACTIVE_LOCK:
            _ACTIVE_GROUPS.discard(self.run)
        self.log_file.close()
        os.close(self.guard_write)
        if self.run.cgroup is not None:
            spawn.remove_cgroup(self.run.cgroup)


@contextlib.contextmanager
def _attended(run: _GroupRun) -> Iterator[_GroupRun]:
    scope = _SCOPE.get()
    if scope is not None and not scope._enter(run):
        _stop(run)
    try:
        yield run
    finally:
        if scope is not None:
            scope._leave(run)


class ForkedGroup:
    """A process group that a supervised process forked off itself (a warm engine worker's copy).

    It is not the tool's child, and runs under its parent's guard (which
    stops it with the parent's run).  The tool stops it alone: its
    descendants, then its group, by number only while the leader's start
    time is the one seen at the start (its parent never reaps it, so the
    number stays its own meanwhile).  Registered as going on like every run.
    """

    def __init__(self, pid: int):
        self.started = time.monotonic()
        self.run = _GroupRun(pid, None, forked_start=guard.start_time(pid) or b"gone")
        with _ACTIVE_LOCK:
            _ACTIVE_GROUPS.add(self.run)

    def attended(self) -> contextlib.AbstractContextManager[object]:
        """As :meth:`StartedGroup.attended`."""
        return _attended(self.run)

    def exited(self) -> bool:
        return guard.start_time(self.run.pgid) != self.run.forked_start

    def kill(self) -> None:
        _stop(self.run)

    def stop(self) -> None:
        """Kill it and wait (briefly) until none of its processes runs."""
        try:
            _stop(self.run)
            _await_run_death(self.run)
        finally:
            with _ACTIVE_LOCK:
                _ACTIVE_GROUPS.discard(self.run)


def _refuse_killed_guard(signum: int) -> None:
    """``PlannerError``: the guard died of a signal the tool did not send (a ``kill -9`` from outside,
    the planner's own, the kernel's).  Its run is stopped whole by then; nothing supervises a
    planner any more, so its outcome means nothing, and the caller must not wait for another side
    (a race) to reach its time limit."""
    try:
        name = signal.Signals(signum).name
    except ValueError:
        name = f"signal {signum}"
    raise errors.PlannerError(f"the planner's guard was killed (by {name}); every process of its run was stopped")


def start_process_group(
    command: list[str],
    workdir: Path,
    *,
    what: str,
    program: Path | str,
    env: dict[str, str] | None = None,
    memory_limit_mb: int | None = None,
) -> StartedGroup:
    """Start ``command`` under the guard as :func:`run_process_group` does, without waiting for it."""
    spawned = spawn.start_guarded(
        command, str(workdir), what=what, program=str(program), env=env, memory_limit_mb=memory_limit_mb
    )
    return StartedGroup.adopt(spawned, workdir)


def _restore_workdir(workdir: Path, log_file: BinaryIO, workdir_id: tuple[int, int]) -> None:
    """Put back a working folder (and log) the planner removed or replaced, saying so in the log.

    The adapters read the log and remove the folder; a planner that deleted
    it would otherwise make its output vanish and the clean-up fail.  Every
    process of the run has ended by now, so nothing changes the folder
    meanwhile.  What the planner left in the folder's place (a link to a
    folder of the user's, a file) or the log's is removed as an entry and
    never followed: the tool writes nothing outside its own folder.  A
    directory put in the folder's place is moved aside, never emptied.
    """
    try:
        now = os.stat(workdir)  # followed: a --keep-work folder may be a link the user made
        ours = (now.st_dev, now.st_ino) == workdir_id
    except OSError:
        ours = False
    log_path = workdir / LOG_FILE
    if ours:
        try:
            entry, mine = os.lstat(log_path), os.fstat(log_file.fileno())
            if (entry.st_dev, entry.st_ino) == (mine.st_dev, mine.st_ino):
                return
        except OSError:
            pass
        what = "removed or replaced its log file"
    else:
        what = _clear_workdir_entry(workdir)
        if not what:
            return
    try:
        if not ours:
            workdir.mkdir(mode=0o700)
        if os.path.lexists(log_path):
            os.unlink(log_path)  # the entry, never what a link points to
        restored = os.open(log_path, os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_NOFOLLOW | os.O_CLOEXEC, 0o644)
        log_file.seek(0, os.SEEK_END)
        size = log_file.tell()
        log_file.seek(max(size - MAX_OUTPUT_BYTES, 0))
        with open(restored, "wb") as stream:
            shutil.copyfileobj(log_file, stream)
            stream.write(f"\nrelevance-plan: the planner {what} ({workdir})\n".encode())
    except OSError:
        pass


def _clear_workdir_entry(workdir: Path) -> str:
    """Clear the path of a working folder that is no longer ours; what the planner did ('' when the
    path cannot be cleared: then nothing is written there)."""
    try:
        entry = os.lstat(workdir)
    except FileNotFoundError:
        return "removed its working folder"
    except OSError:
        return ""
    try:
        if stat.S_ISDIR(entry.st_mode):
            os.rename(workdir, f"{workdir}-replaced-{os.urandom(4).hex()}")
            return "replaced its working folder with another folder, moved aside"
        os.unlink(workdir)
    except OSError:
        return ""
    kind = "a link" if stat.S_ISLNK(entry.st_mode) else "a file"
    return f"replaced its working folder with {kind}, removed without following it"


def _refuse_full_disk(workdir: Path) -> None:
    """``InputFileError`` when the planner failed for want of disk space in its working folder."""
    try:
        info = os.statvfs(workdir)
        free = info.f_bavail * info.f_frsize
    except OSError:
        return
    tail = log_tail(read_log(workdir))
    if free < _LOW_SPACE_BYTES or any(marker in tail for marker in _NO_SPACE_MARKERS):
        raise errors.InputFileError(
            f"no space left for the planner's files ({free // 1024} KB free in the temporary folder;"
            " set TMPDIR to a folder with room)",
            path=str(workdir.parent),
        )
