"""The tool's side of the ``up:NAME`` workers: one warm engine per run, started early, killed with the run.

A run of ``plan`` opens a :func:`worker_pool` and starts the worker of the
run's engine at once (``planners.supply``; ``up.worker``: it imports
unified-planning and the engine while the tool reads and scores), and each
attempt of ``UnifiedPlanningPlanner.run`` in that thread is then a request
to it instead of a new child process.  The worker runs under the guard
(``supervision``): it dies with the tool, the current cancel scope kills it
while it serves a request (the race's other side won), and an attempt that
overruns its time limit kills it; the next attempt starts a new one.  The
pool belongs to a thread of work (a context variable): the race's
full-problem thread works in a copy of its starter's context and so takes
the run's pool, while the pruned attempts beside it open a pool of their
own; ``--keep-work`` runs use the one-shot child (their files stay apart
per attempt).

The pruned attempts' pool is opened *beside* the run's: its worker is a copy
the run's worker forks off itself once it is ready and before it serves the
full problem (:class:`ForkedWorker`), so the race does not import
unified-planning twice on a machine whose second core is the pruned side's.
A worker that has served a request may have engine threads running and is
not copied; the pool then starts a worker of its own.
"""

from __future__ import annotations

import contextlib
import contextvars
import json
import select
import shutil
import socket
import sys
import tempfile
import threading
import time
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from relevance_plan import errors
from relevance_plan.supervision.process import (
    ForkedGroup,
    StartedGroup,
    log_tail,
    read_output,
    start_process_group,
)
from relevance_plan.supervision.spawn import LOG_FILE

SOCKET_NAME = "worker.sock"
# A Unix socket's path must fit in 108 bytes; a longer temporary folder means the one-shot child.
_MAX_SOCKET_PATH = 100
# Past an attempt's limit, the engine's own timeout may act for this long before the worker is killed
# (and must be started again: a second or more).
WORKER_GRACE = 1.0
_POLL = 0.05  # seconds between looks at a worker that has not connected yet
_FORK_ANSWER = 10.0  # seconds a ready worker may take to answer a request for a copy of itself
# The copy plans the race's pruned side, a guess: where the engine runs threads on every core (Aries),
# the two sides compete, and the full problem, which planning without pruning would run alone, keeps
# the priority (measured in docs/results.md, "Temporal and numeric planners").
COPY_NICE = 10
# The worker runs the tool's own code, wherever the tool was imported from (a checkout on a
# relative PYTHONPATH too: the worker's working folder is its own).
_PACKAGE_ROOT = str(Path(__file__).resolve().parents[4])
_LAUNCH = (
    "import sys; sys.path.insert(0, {root!r}); from relevance_plan.planning.planners.up.worker import main;"
    " sys.exit(main(sys.argv[1:]))"
)


@dataclass(frozen=True)
class WorkerAnswer:
    """One request's end: the child's exit code (None: no answer), and what it cost."""

    code: int | None
    wall_time: float
    cpu_time: float
    peak_memory_mb: float
    watchdog_fired: bool
    process_group: int
    log: str  # this request's part of the worker's log
    starting: bool = False  # the worker was still starting at the attempt's limit (and goes on starting)

    @property
    def exit_code(self) -> int:
        """The child's exit code; without an answer (killed at its limit, by the race, or died), -9."""
        return -9 if self.code is None else self.code


class EngineWorker:
    """One worker process for one engine; :meth:`solve` sends it one attempt's files."""

    def __init__(self, engine: str, env: dict[str, str] | None, memory_limit_mb: int | None):
        self.engine = engine
        self.memory_limit_mb = memory_limit_mb
        self._env = env
        self._folder = Path(tempfile.mkdtemp(prefix="relevance-plan-upw-"))
        self._group: StartedGroup | ForkedGroup | None = None
        self._listener: socket.socket | None = None
        self._connection: socket.socket | None = None
        self._stream: Any = None  # the connection as a binary file
        self.start_cost: float | None = None  # seconds from its start until it was ready
        self._lock = threading.Lock()  # the connection's: the race's two sides may both wait for it
        self._served = False  # it has served a request: copies of it are no longer safe
        self._copies: list[ForkedWorker] = []  # asked for before it was ready
        try:
            self._start()
        except BaseException:
            self.close()
            raise

    def _listen(self) -> str:
        """Listen on a new socket in the worker's folder; its address."""
        address = str(self._folder / SOCKET_NAME)
        if len(address) > _MAX_SOCKET_PATH:
            raise errors.PlannerError(f"the temporary folder's path is too long for a socket: {address}")
        listener = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
        listener.bind(address)
        listener.listen(1)
        self._listener = listener
        return address

    def _start(self) -> None:
        address = self._listen()
        command = [sys.executable, "-c", _LAUNCH.format(root=_PACKAGE_ROOT), self.engine, address]
        self._group = start_process_group(
            command,
            self._folder,
            what=f"up:{self.engine} worker",
            program=sys.executable,
            env=self._env,
            memory_limit_mb=self.memory_limit_mb,
        )

    def _ready(self, until: float | None) -> bool:
        """Wait (until ``until``, monotonic) for the worker to connect; False if it died or did not.
        The copies asked for meanwhile are made as soon as it is."""
        while True:
            with self._lock:
                if self._connection is not None:
                    return True
                listener = self._listener
                if listener is None or self._group is None:
                    return False  # closed
            # waited for without the lock: the pruned side must not queue behind the full side's
            # wait to give up its copy
            wait = _POLL if until is None else max(min(_POLL, until - time.monotonic()), 0.0)
            try:
                knocked = bool(select.select([listener], [], [], wait)[0])
            except (OSError, ValueError):  # closed meanwhile: the next round says so
                knocked = False
            with self._lock:
                if self._connection is not None:
                    return True  # another thread took the connection meanwhile
                if self._listener is None or self._group is None:
                    return False
                if knocked and select.select([self._listener], [], [], 0)[0]:
                    self._connection, _ = self._listener.accept()
                    self._stream = self._connection.makefile("rwb")
                    self.start_cost = time.monotonic() - self._group.started
                    copies, self._copies = self._copies, []
                    for copy in copies:
                        self._fork(copy)
                    return True
                if self._group.exited():
                    return False
            if until is not None and time.monotonic() >= until:
                return False

    def copy(self, copy: ForkedWorker) -> None:
        """Make ``copy`` a copy of this worker: now if it is ready, else once it is; refused (the copy
        says so) once it has served a request."""
        with self._lock:
            if self._served or self._group is None:
                copy.refuse()
            elif self._connection is None:
                self._copies.append(copy)
            else:
                self._fork(copy)

    def forget(self, copy: ForkedWorker) -> None:
        """``copy`` is no longer wanted: if it was not made yet, it will not be."""
        with self._lock:
            if copy in self._copies:
                self._copies.remove(copy)

    def _fork(self, copy: ForkedWorker) -> None:
        """Ask the ready, idle worker for ``copy`` (holding the lock)."""
        assert self._connection is not None and self._stream is not None
        try:
            self._connection.settimeout(_FORK_ANSWER)
            request = {"fork": copy.address, "log": copy.log_path, "nice": COPY_NICE}
            self._stream.write(json.dumps(request).encode() + b"\n")
            self._stream.flush()
            line = self._stream.readline()
            pid = int(json.loads(line)["pid"]) if line else None
        except (OSError, ValueError, KeyError, TypeError):
            pid = None
        if pid is None:
            copy.refuse()
        else:
            copy.adopt(pid)

    def wait_ready(self, until: float | None) -> bool:
        """Wait until the worker is ready (or ``until``, monotonic); whether it is."""
        assert self._group is not None
        with self._group.attended():
            return self._ready(until)

    @property
    def alive(self) -> bool:
        return self._group is not None and not self._group.exited()

    def solve(
        self, domain: str, problem: str, plan: str, verdict: str, time_limit: float | None, deadline: float | None
    ) -> WorkerAnswer | None:
        """One attempt; ``deadline`` (seconds from now) is the watchdog's, covering the wait for the
        worker to be ready.  None when the worker never became ready (the caller runs the child)."""
        started = time.monotonic()
        until = None if deadline is None else started + deadline
        assert self._group is not None
        with self._group.attended():
            if not self._ready(until):
                if self._group.exited():
                    return None
                # still starting at the attempt's limit: out of time, and left to start for the next attempt
                return WorkerAnswer(None, time.monotonic() - started, 0.0, 0.0, False, self._group.run.pgid, "", True)
            assert self._connection is not None and self._stream is not None
            with self._lock:
                self._served = True
            log_start = self._log_size()
            left = None if time_limit is None else max(time_limit - (time.monotonic() - started), 0.1)
            request = {"domain": domain, "problem": problem, "plan": plan, "verdict": verdict, "timeout": left}
            answer, fired = None, False
            try:
                self._stream.write(json.dumps(request).encode() + b"\n")
                self._stream.flush()
                self._connection.settimeout(None if until is None else max(until - time.monotonic(), 0.0))
                line = self._stream.readline()
                answer = json.loads(line) if line else None
            except TimeoutError:
                fired = True
                self._group.kill()
            except (OSError, ValueError):
                answer = None  # killed (the race's other side won) or crashed: no answer
        log = self._log_since(log_start)
        return WorkerAnswer(
            code=None if answer is None else int(answer["code"]),
            wall_time=time.monotonic() - started,
            cpu_time=0.0 if answer is None else float(answer["cpu_time"]),
            peak_memory_mb=0.0 if answer is None else float(answer["peak_memory_mb"]),
            watchdog_fired=fired,
            process_group=self._group.run.pgid,
            log=log,
        )

    def _log_size(self) -> int:
        try:
            return (self._folder / LOG_FILE).stat().st_size
        except OSError:
            return 0

    def _log_since(self, offset: int) -> str:
        text = read_output(self._folder / LOG_FILE)
        size = self._log_size()
        return log_tail(text[-(size - offset) :] if 0 <= offset < size else "")

    def close(self) -> None:
        """Kill the worker and whatever its engine started, reap it, remove its folder."""
        with self._lock:
            copies, self._copies = self._copies, []
        for copy in copies:
            copy.refuse()
        group, self._group = self._group, None
        for handle in (self._stream, self._connection, self._listener):
            if handle is not None:
                with contextlib.suppress(OSError):
                    handle.close()
        self._stream = self._connection = self._listener = None
        if group is not None:
            group.stop()
        shutil.rmtree(self._folder, ignore_errors=True)


class ForkedWorker(EngineWorker):
    """A copy that a run's worker forks off itself (``up.worker``'s fork request): the engine comes
    imported.  It waits for its parent to be ready before it can be; it runs under the parent's
    guard and is killed alone (``ForkedGroup``)."""

    def __init__(self, parent: EngineWorker):
        self.parent = parent
        self._refused = False
        super().__init__(parent.engine, None, parent.memory_limit_mb)

    def _start(self) -> None:
        self.address = self._listen()
        self.log_path = str(self._folder / LOG_FILE)
        self.parent.copy(self)

    def adopt(self, pid: int) -> None:
        """The parent forked it: ``pid`` leads its process group."""
        self._group = ForkedGroup(pid)

    def refuse(self) -> None:
        """The parent cannot fork it (it served a request, died or was closed)."""
        self._refused = True

    def _forked(self, until: float | None) -> bool:
        """Wait (until ``until``) for the parent to be ready, and so to have forked it; whether it did."""
        if self._group is None and not self._refused:
            self.parent._ready(until)
        return self._group is not None

    @property
    def alive(self) -> bool:
        return not self._refused and (self._group is None or not self._group.exited())

    def wait_ready(self, until: float | None) -> bool:
        return self._forked(until) and super().wait_ready(until)

    def solve(
        self, domain: str, problem: str, plan: str, verdict: str, time_limit: float | None, deadline: float | None
    ) -> WorkerAnswer | None:
        started = time.monotonic()
        if not self._forked(None if deadline is None else started + deadline):
            if self._refused or not self.parent.alive:
                return None  # the caller runs the child
            # the parent still starting at the attempt's limit: out of time, as a starting worker is
            pgid = self.parent._group.run.pgid if self.parent._group is not None else 0
            return WorkerAnswer(None, time.monotonic() - started, 0.0, 0.0, False, pgid, "", True)
        left = None if deadline is None else max(deadline - (time.monotonic() - started), 0.0)
        return super().solve(domain, problem, plan, verdict, time_limit, left)

    def close(self) -> None:
        self.parent.forget(self)
        self._refused = True
        super().close()


class WorkerPool:
    """The workers of one run, one per engine, all killed when the run ends.

    ``beside``: the pool of the run this one works beside (the race's pruned side); an engine's
    worker here is then a copy of that pool's, while that one is idle.
    """

    def __init__(self, memory_limit_mb: int | None, beside: WorkerPool | None = None):
        self.memory_limit_mb = memory_limit_mb
        self._beside = beside
        self._workers: dict[str, EngineWorker] = {}
        self._refused: set[str] = set()  # engines whose worker could not start: the child runs them
        self._lock = threading.Lock()

    def start(self, engine: str, env: dict[str, str] | None) -> EngineWorker | None:
        """The engine's worker, started now if it is not running; None if it cannot start."""
        with self._lock:
            worker = self._workers.get(engine)
            if worker is not None and worker.alive:
                return worker
            if worker is not None:
                worker.close()  # killed at an overrun, or died: a new one for the next attempt
                del self._workers[engine]
            if engine in self._refused:
                return None
            parent = None if self._beside is None else self._beside.copyable(engine)
            try:
                worker = None if parent is None else ForkedWorker(parent)
                if worker is None or not worker.alive:  # refused at once: the parent has just got busy
                    if worker is not None:
                        worker.close()
                    worker = EngineWorker(engine, env, self.memory_limit_mb)
            except (errors.PlannerError, OSError):
                self._refused.add(engine)
                return None
            self._workers[engine] = worker
            return worker

    def copyable(self, engine: str) -> EngineWorker | None:
        """The engine's worker if it runs, has served no request, and is not itself a copy."""
        with self._lock:
            worker = self._workers.get(engine)
        usable = worker is not None and type(worker) is EngineWorker and worker.alive and not worker._served
        return worker if usable else None

    def wait_ready(self, engine: str, until: float | None) -> bool:
        """Wait for the engine's worker to be ready, if it was started (False if not, or not in time)."""
        with self._lock:
            worker = self._workers.get(engine)
        return worker is not None and worker.wait_ready(until)

    def retire(self, engine: str) -> None:
        """Kill the engine's worker now (it overran or did not answer); the next attempt starts another."""
        with self._lock:
            worker = self._workers.pop(engine, None)
        if worker is not None:
            worker.close()

    def close(self) -> None:
        with self._lock:
            workers, self._workers = list(self._workers.values()), {}
        for worker in workers:
            worker.close()


_POOL: contextvars.ContextVar[WorkerPool | None] = contextvars.ContextVar("relevance_plan_up_pool", default=None)


def current_pool() -> WorkerPool | None:
    """The pool of the run going on in this thread, if one is open."""
    return _POOL.get()


@contextlib.contextmanager
def worker_pool(memory_limit_mb: int | None, beside: bool = False) -> Iterator[WorkerPool]:
    """Engine workers for the run inside the block (this thread), killed when it ends; ``beside``:
    copies of the workers of the pool open until now, where they can be had."""
    pool = WorkerPool(memory_limit_mb, current_pool() if beside else None)
    token = _POOL.set(pool)
    try:
        yield pool
    finally:
        _POOL.reset(token)
        pool.close()
