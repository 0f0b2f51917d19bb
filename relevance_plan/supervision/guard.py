"""Run a planner so that nothing it starts can outlive the tool.

Run as ``python -I -S -c "...import guard; guard.main()" FD CGROUP WORKDIR
LIMIT COMMAND...`` (:data:`LAUNCH`: imported, not run as a script, so that
its compiled bytecode is used).  FD is the read end of a pipe whose only
write end the tool holds; CGROUP is a cgroup v2 directory the tool made for
this run, or ``-``; WORKDIR is where the planner runs; LIMIT the planner's
address-space limit in MB, or ``-``.  ``spawn.start_guarded`` starts the
guard as the leader of a new session, moves it into CGROUP while its
interpreter starts (moving a process costs the kernel time better spent
beside the start-up than before the planner's) and then writes one byte:
``1`` in the cgroup, ``0`` not.  The guard then

* becomes a child subreaper (Linux), so that a descendant whose parent dies
  (``setsid`` and a double fork, ``timeout``'s own process group, a daemon)
  is re-parented to the guard instead of to init: every process the planner
  starts stays a descendant of the guard, found by walking ``/proc``, and in
  CGROUP whatever it does with sessions and process groups (the tool kills
  the cgroup);
* runs COMMAND, and when it ends kills whatever it left behind.

When the tool dies, even by ``kill -9``, the kernel closes the write end;
the guard reads end-of-file, kills every descendant, removes the run's
scratch directory (its cwd) and leaves.  Fast Downward's driver forks its
translator and search, so a parent-death signal on the driver alone would
leave them running.

The guard exits as the planner did (a death by signal N as 256 - N, which
``process`` reads back as -N, as it does for the driver's own codes).

The module is imported by the tool too: :func:`kill_descendants` is the one
sweep, used by the guard and by the tool.  It needs the standard library
only, and imports little, since the guard's start-up delays the planner's:
``_signal`` rather than ``signal`` (whose enums are slow to import), no thread
(the planner's end and the tool's are both file descriptors to wait on),
``posix_spawn`` rather than ``subprocess``, ``shutil`` only to remove a
scratch directory.
"""

import _signal as signal  # signal's own names without the enum module
import os
import select
import sys
import time

TYPE_CHECKING = False  # typing's own flag would import typing
if TYPE_CHECKING:
    from collections.abc import Iterator

# The guard's command line (``sys.argv[1:]`` are FD CGROUP WORKDIR LIMIT COMMAND...): this module imported
# from its folder, appended after the standard library's so that no name there is shadowed.
LAUNCH = "import sys; sys.path.append({folder!r}); import guard; guard.main()"

# Only a directory an adapter made for this run is removed (tempfile prefix "relevance-plan-").
SCRATCH_PREFIX = "relevance-plan-"
PLANNER_TMP = "tmp"  # the planner's temporary folder, inside its working folder
NO_CGROUP = "-"
NO_LIMIT = "-"
PR_SET_CHILD_SUBREAPER = 36  # linux/prctl.h
# A planner's stray signals must not end the guard; these are reset to their default in the planner at exec.
_SHIELDED_SIGNALS = ("SIGTERM", "SIGINT", "SIGHUP", "SIGQUIT", "SIGUSR1", "SIGUSR2", "SIGALRM")
_GONE_STATES = (b"Z", b"X")  # a zombie has exited; X: dead
_POLL = 0.01  # seconds between checks of the planner where no pidfd can wait for it


# --------------------------------------------------------------------------- the sweep (also used by the tool)


def process_stats() -> "Iterator[tuple[int, list[bytes]]]":
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


def kill_process(pid: int, started: bytes) -> None:
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


def start_time(pid: int) -> bytes | None:
    """When ``pid`` started (field 22 of its stat, in clock ticks since boot); None when it has gone
    or is a zombie: what tells a process from a later one given the same number."""
    try:
        with open(f"/proc/{pid}/stat", "rb") as stream:
            fields = stream.read().rsplit(b")", 1)[1].split()
    except (OSError, IndexError):
        return None
    return None if fields[0] in _GONE_STATES else fields[19]


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
            kill_process(pid, started)
        time.sleep(0.002)


# --------------------------------------------------------------------------- the guard


def _become_subreaper() -> bool:
    if not sys.platform.startswith("linux"):
        return False
    try:
        import ctypes

        libc = ctypes.CDLL(None, use_errno=True)
        return bool(libc.prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0) == 0)
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


def cgroup_members(cgroup: str) -> list[int]:
    """The pids in ``cgroup`` (none if it cannot be read)."""
    try:
        with open(os.path.join(cgroup, "cgroup.procs")) as stream:
            return [int(line) for line in stream if line.strip()]
    except (OSError, ValueError):
        return []


def kill_cgroup_members(cgroup: str) -> None:
    """SIGKILL every process of ``cgroup`` but this one."""
    for pid in cgroup_members(cgroup):
        if pid != os.getpid():
            try:
                os.kill(pid, signal.SIGKILL)
            except OSError:
                pass


def _remove_scratch(workdir: str) -> None:
    if os.path.basename(workdir).startswith(SCRATCH_PREFIX):
        import shutil

        shutil.rmtree(workdir, ignore_errors=True)


def _alone_in(cgroup: str) -> bool:
    """Whether this process is the only one left in ``cgroup`` (then there is nothing to sweep)."""
    return cgroup != NO_CGROUP and cgroup_members(cgroup) == [os.getpid()]


def _stop_everything(subreaper: bool, cgroup: str) -> None:
    """The tool is gone: kill every descendant, remove the run's scratch directory, leave."""
    workdir = os.getcwd()
    if not subreaper:
        _stop_by_group(workdir)
        return
    kill_descendants(os.getpid(), timeout=5.0, reap=True)
    if cgroup != NO_CGROUP:
        kill_cgroup_members(cgroup)  # they were not our descendants
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


def _tool_gone(fd: int) -> bool:
    """The tool writes nothing after its first byte: readable means end-of-file."""
    try:
        return bool(select.select([fd], [], [], 0)[0])
    except (OSError, ValueError):
        return False


def _shield() -> None:
    """Handlers that do nothing (not SIG_IGN, which the planner would inherit)."""
    for name in _SHIELDED_SIGNALS:
        signal.signal(getattr(signal, name), lambda signum, frame: None)


def _spawn(command: list[str], fd: int) -> int:
    """Start ``command``; its pid."""
    os.set_inheritable(fd, False)  # the planner must not hold the tool's pipe
    try:
        # as subprocess would: the signals Python ignores are the default again in the planner
        return os.posix_spawnp(command[0], command, os.environ, setsigdef=(signal.SIGPIPE, signal.SIGXFSZ))
    except OSError as error:
        print(f"guard: cannot start {command[0]}: {error.strerror or error}", file=sys.stderr)
        os._exit(127)


def _wait(pid: int, fd: int) -> int | None:
    """The exit code of ``pid`` once it ends (-N: killed by signal N), or None as soon as the tool is gone."""
    try:
        handle: int | None = os.pidfd_open(pid)  # readable once the planner has ended
    except (AttributeError, OSError):
        handle = None  # no pidfd (old kernel, macOS): look every _POLL seconds
    watched = [fd] if handle is None else [fd, handle]
    while True:
        ready = select.select(watched, [], [], None if handle is not None else _POLL)[0]
        if fd in ready:
            return None  # the tool never writes to the pipe (after its first byte): readable means end-of-file
        ended, status = os.waitpid(pid, os.WNOHANG)
        if ended:
            return os.waitstatus_to_exitcode(status)


def _await_go(fd: int, cgroup: str) -> str:
    """Wait for the tool's byte; the cgroup the guard is in (``-``: none).  Leaves if the tool is gone."""
    try:
        said = os.read(fd, 1)
    except OSError:
        said = b""
    if not said:  # the tool died before the planner started
        _remove_scratch(os.getcwd())
        if cgroup != NO_CGROUP:
            _leave_cgroup(cgroup)
        os._exit(1)
    return cgroup if said == b"1" else NO_CGROUP


def _limit_memory(megabytes: str) -> None:
    """The planner's address-space limit, set on the guard (inherited by the planner)."""
    if megabytes != NO_LIMIT:
        import resource

        limit = int(megabytes) * 1024 * 1024
        resource.setrlimit(resource.RLIMIT_AS, (limit, limit))


def _private_temporary_folder() -> str | None:
    """The planner's temporary folder: ``tmp`` in its working folder, made here and named by
    ``$TMPDIR``, ``$TEMP`` and ``$TMP``.  What a planner leaves in the temporary folder (an engine's
    log files, its copies of the problem, a component killed before it cleaned up) goes with the
    working folder, whatever the planner does; None when it cannot be made (the planner then
    keeps the tool's)."""
    try:
        os.mkdir(PLANNER_TMP, 0o700)
    except OSError:
        return None
    path = os.path.join(os.getcwd(), PLANNER_TMP)
    for name in ("TMPDIR", "TEMP", "TMP"):
        os.environ[name] = path
    return path


def _remove_temporary_folder(path: str | None) -> None:
    """The planner's temporary folder, once every process of the run has ended (a --keep-work
    folder keeps the planner's files, not its temporary ones).  A link put in its place is not followed."""
    if path is not None and os.path.isdir(path) and not os.path.islink(path):
        import shutil

        shutil.rmtree(path, ignore_errors=True)


def main() -> None:
    fd, cgroup, workdir, limit, command = int(sys.argv[1]), sys.argv[2], sys.argv[3], sys.argv[4], sys.argv[5:]
    os.chdir(workdir)
    cgroup = _await_go(fd, cgroup)
    _limit_memory(limit)
    subreaper = _become_subreaper()
    _shield()
    temporary = _private_temporary_folder()
    code = _wait(_spawn(command, fd), fd)
    if code is None:
        _stop_everything(subreaper, cgroup)
        return
    if subreaper and not _alone_in(cgroup):
        kill_descendants(os.getpid(), reap=True)  # whatever the planner left behind
    _remove_temporary_folder(temporary)
    if _tool_gone(fd):  # died just now: nobody else will clean up
        _remove_scratch(os.getcwd())
        if cgroup != NO_CGROUP:
            _leave_cgroup(cgroup)
    os._exit(code & 0xFF if code >= 0 else (256 + code) & 0xFF)


if __name__ == "__main__":
    main()
