"""Process supervision: run a planner so that it can always be stopped, whole.

Every planner adapter runs its processes through :func:`run_process_group`:
a fresh working directory chosen by the caller, a session of its own led by
the guard (``guard.py``, which kills the group if this process dies, even by
``kill -9``), the output in a file log, a wall-clock watchdog that kills
the whole group, and the group's id kept reserved (its leader unreaped)
until every member is gone.  The process groups running now are registered,
so a batch's Ctrl-C can stop them all (:func:`terminate_all_runs`).  The
module is thread-safe: many runs may go at once from a thread pool.

VAL's ``Validate`` is the one other program the tool starts (:func:`run_val`).
"""

from __future__ import annotations

import contextlib
import functools
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time
from dataclasses import dataclass
from pathlib import Path

from relevance_plan import errors

LOG_FILE = "planner.log"
LOG_TAIL_LINES = 40
DEFAULT_WATCHDOG_GRACE = 5.0
_GUARD = Path(__file__).with_name("guard.py")


@dataclass(frozen=True)
class ProcessRun:
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


def watchdog_deadline(time_limit: float | None, grace: float | None = None) -> float | None:
    """Seconds after the start at which the watchdog kills the group: the limit plus a grace
    period (default max(5 s, 10 %)) for the planner's own limit to act first."""
    if time_limit is None:
        return None
    return time_limit + (grace if grace is not None else max(DEFAULT_WATCHDOG_GRACE, 0.1 * time_limit))


@contextlib.contextmanager
def work_directory(keep: str | None, prefix: str):
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
    try:
        return (workdir / LOG_FILE).read_text(errors="replace")
    except OSError:
        return ""


def log_tail(log: str) -> str:
    return "\n".join(log.splitlines()[-LOG_TAIL_LINES:])


# --------------------------------------------------------------------------- the active groups

# Process groups of the planners running now, so a batch's Ctrl-C can stop them all.
_ACTIVE_GROUPS: set[int] = set()
_ACTIVE_LOCK = threading.Lock()


def terminate_all_runs() -> int:
    """Kill every planner process group this process started and still waits for.

    Each group's leader stays unreaped until its waiting thread returns, so
    a group id here cannot belong to an unrelated process.  Returns how many.
    """
    with _ACTIVE_LOCK:
        groups = list(_ACTIVE_GROUPS)
    for pgid in groups:
        _kill_group(pgid)
    return len(groups)


def _kill_group(pgid: int) -> None:
    try:
        os.killpg(pgid, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        # Group already gone (PermissionError: macOS reports a group of zombies so).
        pass


# --------------------------------------------------------------------------- waiting, watchdog, reaping


def _exit_code(wait_status: int) -> int:
    if os.WIFSIGNALED(wait_status):
        return -os.WTERMSIG(wait_status)
    code = os.WEXITSTATUS(wait_status)
    # The guard, and Fast Downward's driver, pass a child's death by signal N on as sys.exit(-N).
    return code - 256 if code > 128 else code


def _wait_for_group(pgid: int, deadline: float | None) -> tuple[int, float, float, bool]:
    """Wait for the group's leader; kill its whole group; reap it.

    Returns (wait status, cpu seconds, peak memory MB, watchdog fired).  The
    leader stays an unreaped zombie until the group is killed, so its pid
    (= the group id) cannot be reused by an unrelated process meanwhile.
    """
    fired = threading.Event()

    def watchdog() -> None:
        fired.set()
        _kill_group(pgid)

    timer: threading.Timer | None = None
    if deadline is not None:
        timer = threading.Timer(deadline, watchdog)
        timer.daemon = True
        timer.start()
    try:
        if hasattr(os, "waitid"):
            os.waitid(os.P_PID, pgid, os.WEXITED | os.WNOWAIT)
        else:  # macOS: no waitid; reap first and accept a tiny pid-reuse window
            _, status, usage = os.wait4(pgid, 0)
    finally:
        # Runs on KeyboardInterrupt too: the planner lives in its own session,
        # so the terminal's Ctrl-C never reached it.
        if timer is not None:
            timer.cancel()
            timer.join()  # a kill in flight must land before the pid is freed
        # Killing only the leader would leave a running translator orphaned.
        _kill_group(pgid)
        if hasattr(os, "waitid"):
            _await_group_death(pgid)
            _, status, usage = os.wait4(pgid, 0)
    cpu = usage.ru_utime + usage.ru_stime
    return status, cpu, usage.ru_maxrss / 1024.0, fired.is_set()


def _await_group_death(pgid: int, timeout: float = 2.0) -> None:
    """Wait until no member of the killed group still runs (Linux, via /proc).

    SIGKILL lands at once, but a process takes a moment to exit; the unreaped
    leader keeps the group id reserved meanwhile.  Without this, a caller
    could see the planner's children still running after the run returned.
    """
    if not os.path.isdir("/proc"):
        return
    deadline = time.monotonic() + timeout
    while _group_runs(pgid) and time.monotonic() < deadline:
        time.sleep(0.01)


def _group_runs(pgid: int) -> bool:
    for entry in os.scandir("/proc"):
        if not entry.name.isdigit():
            continue
        try:
            with open(f"/proc/{entry.name}/stat", "rb") as stream:
                fields = stream.read().rsplit(b")", 1)[1].split()
        except (OSError, IndexError):
            continue
        # fields: state, ppid, pgrp, ...; a zombie has exited already.
        if int(fields[2]) == pgid and fields[0] != b"Z":
            return True
    return False


def _limit_memory(megabytes: int) -> None:
    import resource

    limit = megabytes * 1024 * 1024
    resource.setrlimit(resource.RLIMIT_AS, (limit, limit))


# --------------------------------------------------------------------------- one run


def run_process_group(
    command: list[str],
    workdir: Path,
    deadline: float | None,
    *,
    what: str,
    program: Path | str,
    env: dict | None = None,
    memory_limit_mb: int | None = None,
) -> ProcessRun:
    """Run ``command`` (an argument list, never a shell string) in ``workdir`` as the leader
    of its own session, output to ``workdir/planner.log``.

    A watchdog kills the whole group ``deadline`` seconds after the start;
    the group is killed and reaped in every case (Ctrl-C included).
    ``what`` and ``program`` name the planner in the error raised when it
    cannot start.
    """
    # The guard starts the command, so a missing program must be caught here.
    executable = command[0] if os.sep in command[0] else shutil.which(command[0])
    if executable is None or not os.access(executable, os.X_OK) or os.path.isdir(executable):
        raise errors.PlannerError(f"cannot start {what}: {command[0]} is not an executable program", path=str(program))
    started = time.monotonic()
    # The guard kills the group when this process dies (its pipe's write end
    # closes, even on kill -9); os.pipe() fds are close-on-exec, so no other
    # child holds the write end.
    guard_read, guard_write = os.pipe()
    try:
        # A file, not a pipe: nobody has to drain it while we wait.
        with open(workdir / LOG_FILE, "wb") as log_file:
            try:
                process = subprocess.Popen(
                    # -I -S: the guard needs the standard library only; skipping site saves start-up
                    [sys.executable, "-I", "-S", str(_GUARD), str(guard_read), *command],
                    cwd=workdir,
                    stdin=subprocess.DEVNULL,
                    stdout=log_file,
                    stderr=subprocess.STDOUT,
                    start_new_session=True,
                    close_fds=True,
                    pass_fds=(guard_read,),
                    env=env,
                    preexec_fn=None if memory_limit_mb is None else functools.partial(_limit_memory, memory_limit_mb),
                )
            except OSError as error:
                raise errors.PlannerError(
                    f"cannot start {what}: {error.strerror or error}", path=str(program)
                ) from None
            finally:
                os.close(guard_read)
        # start_new_session: the guard leads its own group, pgid == pid.
        pgid = process.pid
        with _ACTIVE_LOCK:
            _ACTIVE_GROUPS.add(pgid)
        try:
            wait_status, cpu_time, peak_mb, fired = _wait_for_group(pgid, deadline)
        finally:
            with _ACTIVE_LOCK:
                _ACTIVE_GROUPS.discard(pgid)
    finally:
        os.close(guard_write)
    exit_code = _exit_code(wait_status)
    # We reaped it ourselves (for the rusage); tell Popen so it never waits.
    process.returncode = exit_code
    return ProcessRun(wait_status, exit_code, cpu_time, peak_mb, fired, time.monotonic() - started, pgid)


# --------------------------------------------------------------------------- VAL


def run_val(domain_path: str, problem_path: str, plan_text: str, timeout: float = 60.0) -> tuple[bool | None, str]:
    """Run VAL's ``Validate`` on a plan; (True/False, message), or (None, why) if it could not run."""
    validate = shutil.which("Validate")
    if validate is None:
        return None, "VAL's Validate is not on PATH"
    with tempfile.TemporaryDirectory(prefix="relevance-plan-val-") as tmp:
        plan_path = Path(tmp) / "plan"
        plan_path.write_text(plan_text)
        try:
            completed = subprocess.run(
                [validate, str(domain_path), str(problem_path), str(plan_path)],
                cwd=tmp,
                capture_output=True,
                text=True,
                timeout=timeout,
                stdin=subprocess.DEVNULL,
            )
        except (OSError, subprocess.TimeoutExpired) as error:
            return None, f"Validate could not run: {error}"
    output = completed.stdout + completed.stderr
    if "Plan valid" in output:
        return True, "Plan valid (VAL)"
    if "Plan failed" in output or "Goal not satisfied" in output or "Plan invalid" in output:
        lines = [line for line in output.splitlines() if line.strip()]
        return False, lines[-1] if lines else "invalid (VAL)"
    return None, f"Validate gave no verdict (exit {completed.returncode})"
