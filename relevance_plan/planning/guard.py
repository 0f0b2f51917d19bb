"""Run a planner so that nothing it starts can outlive the tool.

Run as a script: ``python guard.py FD CGROUP COMMAND...``.  FD is the read
end of a pipe whose only write end the tool holds; CGROUP is a cgroup v2
directory the tool made for this run, or ``-``.  ``process.run_process_group``
starts the guard as the leader of a new session; the guard then

* joins CGROUP, so that everything it starts stays in that cgroup whatever
  it does with sessions and process groups (the tool kills the cgroup);
* becomes a child subreaper (Linux), so that a descendant whose parent dies
  (``setsid`` and a double fork, ``timeout``'s own process group, a daemon)
  is re-parented to the guard instead of to init: every process the planner
  starts stays a descendant of the guard, found by walking ``/proc``;
* runs COMMAND, and when it ends kills whatever it left behind.

When the tool dies, even by ``kill -9``, the kernel closes the write end;
the guard reads end-of-file, kills every descendant, removes the run's
scratch directory (its cwd) and leaves.  Fast Downward's driver forks its
translator and search, so a parent-death signal on the driver alone would
leave them running.

The guard exits as the planner did (a death by signal N as 256 - N, which
``process`` reads back as -N, as it does for the driver's own codes).

The module is imported too: :func:`kill_descendants` is the one sweep, used
by the guard and by the tool.  It needs the standard library only, and
imports little: the guard's start-up delays the planner's (``posix_spawn``
rather than ``subprocess``, ``shutil`` only to remove a scratch directory).
"""

import os
import select
import signal
import sys
import threading
import time
from collections.abc import Iterator

# Only a directory an adapter made for this run is removed (tempfile prefix "relevance-plan-").
SCRATCH_PREFIX = "relevance-plan-"
NO_CGROUP = "-"
PR_SET_CHILD_SUBREAPER = 36  # linux/prctl.h
# A planner's stray signals must not end the guard; these are reset to their default in the planner at exec.
_SHIELDED_SIGNALS = ("SIGTERM", "SIGINT", "SIGHUP", "SIGQUIT", "SIGUSR1", "SIGUSR2", "SIGALRM")
_GONE_STATES = (b"Z", b"X")  # a zombie has exited; X: dead
_EXIT = threading.Lock()  # held by whoever ends the guard: the planner's end or the tool's


# --------------------------------------------------------------------------- the sweep (also used by the tool)


def process_stats() -> Iterator[tuple[int, list[bytes]]]:
    """(pid, fields) of every process in /proc; the fields follow the command name in its stat file:
    state, ppid, pgrp, session, ... (the start time, field 22 of stat, is here 19)."""
    for entry in os.scandir("/proc"):
        if not entry.name.isdigit():
            continue
        try:
            with open(f"/proc/{entry.name}/stat", "rb") as stream:
                fields = stream.read().rsplit(b")", 1)[1].split()
        except (OSError, IndexError):
            continue  # gone meanwhile
        yield int(entry.name), fields


def _process_table() -> dict[int, list[tuple[int, bytes, bytes]]]:
    """parent pid -> [(pid, state, start time)] for every process in /proc."""
    children: dict[int, list[tuple[int, bytes, bytes]]] = {}
    for pid, fields in process_stats():
        children.setdefault(int(fields[1]), []).append((pid, fields[0], fields[19]))
    return children


def descendants(root: int) -> list[tuple[int, bytes, bytes]]:
    """(pid, state, start time) of every descendant of ``root``, parents before children."""
    table = _process_table()
    found: list[tuple[int, bytes, bytes]] = []
    queue = [root]
    while queue:
        for child in table.get(queue.pop(), ()):
            found.append(child)
            queue.append(child[0])
    return found


def _kill(pid: int, started: bytes) -> None:
    """SIGKILL ``pid`` if it is still the process that started at ``started`` (never a reused pid)."""
    try:
        handle = os.pidfd_open(pid)
    except (AttributeError, OSError):
        handle = None  # no pidfd (old kernel, macOS): the short pid-reuse window stays
    try:
        with open(f"/proc/{pid}/stat", "rb") as stream:
            if stream.read().rsplit(b")", 1)[1].split()[19] != started:
                return
        if handle is not None:
            signal.pidfd_send_signal(handle, signal.SIGKILL)
        else:
            os.kill(pid, signal.SIGKILL)
    except (OSError, IndexError):
        pass  # gone meanwhile
    finally:
        if handle is not None:
            os.close(handle)


def reap_children() -> None:
    """Reap whatever has died among our own children (orphans re-parented to a subreaper)."""
    while True:
        try:
            pid, _ = os.waitpid(-1, os.WNOHANG)
        except ChildProcessError:
            return
        if pid == 0:
            return


def kill_descendants(root: int, timeout: float = 2.0, reap: bool = False) -> bool:
    """SIGKILL every descendant of ``root`` (Linux, via /proc), again and again until none runs.

    A process killed before its children leaves them to the nearest
    subreaper: to ``root`` when ``root`` is the guard, so the next round finds
    them.  ``reap``: ``root`` is this process, so its dead children are
    reaped here.  True when none is left; False after ``timeout`` seconds.
    """
    if not os.path.isdir("/proc"):
        return False
    deadline = time.monotonic() + timeout
    while True:
        alive = [(pid, started) for pid, state, started in descendants(root) if state not in _GONE_STATES]
        if reap:
            reap_children()
        if not alive:
            return True
        if time.monotonic() > deadline:
            return False
        for pid, started in alive:
            _kill(pid, started)
        time.sleep(0.002)


# --------------------------------------------------------------------------- the guard


def _become_subreaper() -> bool:
    if not sys.platform.startswith("linux"):
        return False
    try:
        import ctypes

        libc = ctypes.CDLL(None, use_errno=True)
        return libc.prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0) == 0
    except (OSError, AttributeError):
        return False


def join_cgroup(cgroup: str, pid: int = 0) -> bool:
    """Move ``pid`` (0: this process) into ``cgroup``; False if not permitted."""
    if cgroup == NO_CGROUP:
        return False
    try:
        with open(os.path.join(cgroup, "cgroup.procs"), "w") as stream:
            stream.write(str(pid or os.getpid()))
        return True
    except OSError:
        return False


def _leave_cgroup(cgroup: str) -> None:
    """Move back to the parent cgroup and remove ours, now empty but for us (best effort)."""
    if join_cgroup(os.path.dirname(cgroup)):
        try:
            os.rmdir(cgroup)
        except OSError:
            pass


def _kill_cgroup_members(cgroup: str) -> None:
    """SIGKILL every process of ``cgroup`` but this one (they were not our descendants)."""
    try:
        with open(os.path.join(cgroup, "cgroup.procs")) as stream:
            members = [int(line) for line in stream if line.strip()]
    except (OSError, ValueError):
        return
    for pid in members:
        if pid != os.getpid():
            try:
                os.kill(pid, signal.SIGKILL)
            except OSError:
                pass


def _remove_scratch(workdir: str) -> None:
    if os.path.basename(workdir).startswith(SCRATCH_PREFIX):
        import shutil

        shutil.rmtree(workdir, ignore_errors=True)


def _stop_everything(subreaper: bool, cgroup: str) -> None:
    """The tool is gone: kill every descendant, remove the run's scratch directory, leave."""
    _EXIT.acquire()  # the planner's end must not exit the guard halfway through this
    workdir = os.getcwd()
    if not subreaper:
        _stop_by_group(workdir)
        return
    kill_descendants(os.getpid(), timeout=5.0, reap=True)
    if cgroup != NO_CGROUP:
        _kill_cgroup_members(cgroup)
    _remove_scratch(workdir)
    if cgroup != NO_CGROUP:
        _leave_cgroup(cgroup)
    os._exit(1)


def _stop_by_group(workdir: str) -> None:
    """Without a subreaper: kill the whole group (the guard too); a detached child removes the
    scratch directory, which the dead tool can no longer remove."""
    if os.path.basename(workdir).startswith(SCRATCH_PREFIX):
        ready_read, ready_write = os.pipe()
        if os.fork() == 0:
            os.setsid()  # leave the group that is about to be killed
            os.close(ready_write)  # tells the guard we are out
            time.sleep(0.5)  # SIGKILL has landed: nobody writes there any more
            _remove_scratch(workdir)
            os._exit(0)
        os.close(ready_write)
        os.read(ready_read, 1)  # end-of-file once the cleaner has left the group
    os.killpg(0, signal.SIGKILL)


def _watch(fd: int, subreaper: bool, cgroup: str) -> None:
    while True:
        try:
            if not os.read(fd, 1):
                break
        except InterruptedError:
            continue
        except OSError:
            break
    _stop_everything(subreaper, cgroup)


def _tool_gone(fd: int) -> bool:
    """The tool never writes to the pipe: readable means end-of-file."""
    try:
        return bool(select.select([fd], [], [], 0)[0])
    except (OSError, ValueError):
        return False


def _shield() -> None:
    """Handlers that do nothing (not SIG_IGN, which the planner would inherit)."""
    for name in _SHIELDED_SIGNALS:
        signal.signal(getattr(signal, name), lambda signum, frame: None)


def _run(command: list[str], fd: int) -> int:
    """Run ``command`` to its end; its exit code (-N: killed by signal N)."""
    os.set_inheritable(fd, False)  # the planner must not hold the tool's pipe
    try:
        # as subprocess would: the signals Python ignores are the default again in the planner
        pid = os.posix_spawnp(command[0], command, os.environ, setsigdef=(signal.SIGPIPE, signal.SIGXFSZ))
    except OSError as error:
        print(f"guard: cannot start {command[0]}: {error.strerror or error}", file=sys.stderr)
        os._exit(127)
    try:
        _, status = os.waitpid(pid, 0)
    except ChildProcessError:  # reaped by the watcher, which ends the guard itself
        return 0
    return os.waitstatus_to_exitcode(status)


def main() -> None:
    fd, cgroup, command = int(sys.argv[1]), sys.argv[2], sys.argv[3:]
    join_cgroup(cgroup)
    subreaper = _become_subreaper()
    _shield()
    threading.Thread(target=_watch, args=(fd, subreaper, cgroup), daemon=True).start()
    code = _run(command, fd)
    with _EXIT:
        if subreaper:
            kill_descendants(os.getpid(), reap=True)  # whatever the planner left behind
        if _tool_gone(fd):  # died just now: nobody else will clean up
            _remove_scratch(os.getcwd())
            if cgroup != NO_CGROUP:
                _leave_cgroup(cgroup)
        os._exit(code & 0xFF if code >= 0 else (256 + code) & 0xFF)


if __name__ == "__main__":
    main()
