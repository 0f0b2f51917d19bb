"""Starting a command under the guard, with ``os`` alone.

Every planner run starts here (:func:`start_guarded`, through
``process.start_process_group``), and so does the launcher's head start,
which runs before anything else of the tool is imported: whatever this
module imports delays the planner on every run.  So it imports ``os``,
``sys``, ``time`` and the guard, and nothing that pulls in ``re``, ``enum``,
``typing``, ``pathlib`` or ``subprocess`` (together a large share of a fresh
interpreter's start).

A run's processes live in a cgroup of their own where Linux lets us make
one (``$RELEVANCE_PLAN_NO_CGROUP=1`` turns this off); the helpers for it
are here because the start needs them, and ``process`` uses them to stop
and remove it.
"""

from __future__ import annotations

import _signal  # signal's names without its enums
import errno
import itertools
import os
import sys
import time

from relevance_plan import errors
from relevance_plan.supervision import guard

LOG_FILE = "planner.log"
NO_CGROUP_ENV = "RELEVANCE_PLAN_NO_CGROUP"
SCRATCH_PREFIX = guard.SCRATCH_PREFIX
_GUARD_LAUNCH = guard.LAUNCH.format(folder=os.path.dirname(os.path.abspath(__file__)))


class Spawned:
    """A guard just started: its pid (= its process group and session), the run's cgroup (or None),
    the open log, the write end of the guard's pipe, ``time.monotonic()`` at the start, and the
    working folder's (device, inode) then (a planner may replace the folder with a link)."""

    __slots__ = ("pid", "cgroup", "log_fd", "guard_write", "started", "workdir_id")

    def __init__(
        self, pid: int, cgroup: str | None, log_fd: int, guard_write: int, started: float, workdir_id: tuple[int, int]
    ):
        self.pid = pid
        self.cgroup = cgroup
        self.log_fd = log_fd
        self.guard_write = guard_write
        self.started = started
        self.workdir_id = workdir_id


def usable_cores() -> int:
    """The cores this process may run on (its affinity, not the machine's count)."""
    try:
        return len(os.sched_getaffinity(0))
    except (AttributeError, OSError):
        return os.cpu_count() or 1


def scratch_folder(kind: str) -> str | None:
    """A new private folder ``relevance-plan-KIND-XXXX`` in the temporary folder (as ``tempfile``
    chooses it: ``$TMPDIR``, ``$TEMP``, ``$TMP``, then the usual places); None if none can be made."""
    candidates = [os.environ.get(name) for name in ("TMPDIR", "TEMP", "TMP")]
    for parent in [*filter(None, candidates), "/tmp", "/var/tmp", "/usr/tmp"]:
        for _ in range(8):
            path = os.path.join(os.path.abspath(parent), f"{SCRATCH_PREFIX}{kind}-{os.urandom(6).hex()}")
            try:
                os.mkdir(path, 0o700)
                return path
            except FileExistsError:
                continue
            except OSError:
                break
    return None


def start_guarded(
    command: list[str],
    workdir: str,
    *,
    what: str,
    program: str,
    env: dict[str, str] | None = None,
    memory_limit_mb: int | None = None,
) -> Spawned:
    """Start ``command`` (an argument list, never a shell string) in ``workdir`` under the guard, as
    the leader of a new session, its output to ``workdir/planner.log``.  ``PlannerError`` (naming
    ``what`` and ``program``) when it cannot start."""
    # The guard starts the command, so a missing program must be caught here.
    executable = command[0] if os.sep in command[0] else _which(command[0])
    if executable is None or not os.access(executable, os.X_OK) or os.path.isdir(executable):
        raise errors.PlannerError(f"cannot start {what}: {command[0]} is not an executable program", path=program)
    started = time.monotonic()
    # The guard stops the run when this process dies (its pipe's write end
    # closes, even on kill -9); os.pipe() fds are close-on-exec, so no other
    # child holds the write end.
    try:
        guard_read, guard_write = os.pipe()
    except OSError as error:
        raise _cannot_start(what, program, error) from None
    cgroup = new_cgroup()
    log_fd = -1
    try:
        # A file, not a pipe: nobody has to drain it while we wait.
        try:
            log_fd = os.open(os.path.join(workdir, LOG_FILE), os.O_RDWR | os.O_CREAT | os.O_TRUNC | os.O_CLOEXEC, 0o644)
        except OSError as error:
            if error.errno not in _OUT_OF_DESCRIPTORS:
                raise
            raise _cannot_start(what, program, error) from None
        folder = os.stat(workdir)
        limit = guard.NO_LIMIT if memory_limit_mb is None else str(memory_limit_mb)
        arguments = [guard_read, cgroup or guard.NO_CGROUP, workdir, limit]
        try:
            # -I -S: the guard needs the standard library only; skipping site saves start-up
            pid = os.posix_spawn(
                sys.executable,
                [sys.executable, "-I", "-S", "-c", _GUARD_LAUNCH, *map(str, arguments), *command],
                os.environ if env is None else env,
                file_actions=_file_actions(log_fd, guard_read),
                setsid=True,
                setsigdef=_DEFAULT_IN_CHILD,
                setsigmask=(),
            )
        except OSError as error:
            raise _cannot_start(what, program, error) from None
        finally:
            os.close(guard_read)
            guard_read = -1
        # Moved while the guard's interpreter starts; the guard starts the planner on our byte.
        if cgroup is not None and not guard.join_cgroup(cgroup, pid):
            remove_cgroup(cgroup)
            cgroup = None
        try:
            os.write(guard_write, b"0" if cgroup is None else b"1")
        except OSError:
            pass  # the guard died already: waiting for it reports how
    except BaseException:
        for fd in (log_fd, guard_read):
            if fd >= 0:
                os.close(fd)
        os.close(guard_write)
        if cgroup is not None:
            remove_cgroup(cgroup)
        raise
    return Spawned(pid, cgroup, log_fd, guard_write, started, (folder.st_dev, folder.st_ino))


_OUT_OF_DESCRIPTORS = (errno.EMFILE, errno.ENFILE)


def _cannot_start(what: str, program: str, error: OSError) -> errors.PlannerError:
    """The error for a start that failed; out of descriptors, it names the limit."""
    if error.errno == errno.EMFILE:
        why = f"too many open files for the limit on open files (ulimit -n {_descriptor_ceiling()}); raise it"
    elif error.errno == errno.ENFILE:
        why = "the system's table of open files is full"
    else:
        why = error.strerror or str(error)
    return errors.PlannerError(f"cannot start {what}: {why}", path=program)


# Python ignores these; a child should start with their defaults, as subprocess gives it.
_DEFAULT_IN_CHILD = (_signal.SIGPIPE, _signal.SIGXFSZ)


def _file_actions(log_fd: int, keep: int) -> list[tuple[int, ...] | tuple[int, int, str, int, int]]:
    """The guard's standard input from /dev/null, its output to the log, and no other descriptor of
    ours but ``keep`` (what ``subprocess`` does with ``close_fds``)."""
    actions: list[tuple[int, ...] | tuple[int, int, str, int, int]] = [
        (os.POSIX_SPAWN_OPEN, 0, os.devnull, os.O_RDONLY, 0),
        (os.POSIX_SPAWN_DUP2, log_fd, 1),
        (os.POSIX_SPAWN_DUP2, log_fd, 2),
    ]
    os.set_inheritable(keep, True)
    strangers = [fd for fd in _inheritable_descriptors() if fd > 2 and fd != keep]  # usually none
    ceiling = _descriptor_ceiling() if strangers else 0
    for fd in strangers:
        if fd < ceiling:
            actions.append((os.POSIX_SPAWN_CLOSE, fd))
        else:
            # posix_spawn refuses to close a descriptor at or above the limit ("Bad file descriptor"):
            # one a parent left open before lowering the limit (ulimit -n).  Never ours to pass on, and
            # not the one kept (a new descriptor takes the lowest free number), so it is closed at exec.
            os.set_inheritable(fd, False)
    return actions


def _descriptor_ceiling() -> int:
    """The soft limit on descriptors (RLIMIT_NOFILE): every descriptor we may open is below it."""
    import resource  # only when a parent left descriptors open: not on every start

    soft, _ = resource.getrlimit(resource.RLIMIT_NOFILE)
    return soft if soft != resource.RLIM_INFINITY else 2**31


def _inheritable_descriptors() -> list[int]:
    """Our open descriptors that a child would inherit (ours are close-on-exec; a parent's may not be)."""
    try:
        names = os.listdir("/proc/self/fd" if os.path.isdir("/proc/self/fd") else "/dev/fd")
    except OSError:
        return []
    found = []
    for name in names:
        try:
            if os.get_inheritable(int(name)):
                found.append(int(name))
        except (OSError, ValueError):
            continue  # the listing's own descriptor, closed meanwhile
    return found


def _which(name: str) -> str | None:
    """``shutil.which`` for an executable file, without importing shutil (and its ``re``) on this path."""
    for folder in os.environ.get("PATH", os.defpath).split(os.pathsep):
        candidate = os.path.join(folder or ".", name)
        if os.path.isfile(candidate) and os.access(candidate, os.X_OK):
            return candidate
    return None


# --------------------------------------------------------------------------- cgroups

_OWN_CGROUP: list[str | None] = []  # found once
_CGROUP_NUMBERS = itertools.count(1)
_CGROUPS_REFUSED: set[str] = set()  # parents where creating a cgroup failed once: not tried again


def _own_cgroup() -> str | None:
    """This process's cgroup v2 directory, or None (no cgroup v2, or not mounted where we can see it)."""
    if not _OWN_CGROUP:
        _OWN_CGROUP.append(_find_own_cgroup())
    return _OWN_CGROUP[0]


def _find_own_cgroup() -> str | None:
    try:
        with open("/proc/self/cgroup") as stream:
            own = next(line[3:].strip() for line in stream if line.startswith("0::"))
        with open("/proc/self/mountinfo") as stream:
            for line in stream:
                fields = line.split()
                if "-" in fields and fields[fields.index("-") + 1] == "cgroup2":
                    root, mount_point = fields[3], fields[4].replace("\\040", " ")
                    break
            else:
                return None
    except (OSError, StopIteration, IndexError):
        return None
    if not own.startswith(root):
        return None
    return os.path.join(mount_point, own[len(root) :].lstrip("/"))


def new_cgroup() -> str | None:
    """A fresh cgroup below this process's own, or None where that is not available or not permitted."""
    if os.environ.get(NO_CGROUP_ENV) or not sys.platform.startswith("linux"):
        return None
    parent = _own_cgroup()
    if parent is None or parent in _CGROUPS_REFUSED:
        return None
    path = os.path.join(parent, f"relevance-plan-{os.getpid()}-{next(_CGROUP_NUMBERS)}")
    try:
        os.mkdir(path)
    except OSError:
        _CGROUPS_REFUSED.add(parent)
        return None
    return path


def kill_cgroup(cgroup: str) -> None:
    try:
        with open(os.path.join(cgroup, "cgroup.kill"), "w") as stream:
            stream.write("1")
    except OSError:
        guard.kill_cgroup_members(cgroup)  # before Linux 5.14: one by one


def remove_cgroup(cgroup: str, timeout: float = 2.0) -> None:
    deadline = time.monotonic() + timeout
    while True:
        try:
            os.rmdir(cgroup)
            return
        except FileNotFoundError:
            return
        except OSError:
            if time.monotonic() > deadline:
                return  # left behind, empty or not: never block the tool on it
            kill_cgroup(cgroup)
            time.sleep(0.01)
