"""The tool's side of the ``up:NAME`` workers: one warm engine per run, started early, killed with the run.

A run of ``plan`` opens a :func:`worker_pool`; the registry's ``warm_up``
starts the worker of the run's engine at once (``up.worker``: it imports
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
from relevance_plan.supervision.process import StartedGroup, log_tail, read_output, start_process_group
from relevance_plan.supervision.spawn import LOG_FILE

SOCKET_NAME = "worker.sock"
# A Unix socket's path must fit in 108 bytes; a longer temporary folder means the one-shot child.
_MAX_SOCKET_PATH = 100
# Past an attempt's limit, the engine's own timeout may act for this long before the worker is killed
# (and must be started again: a second or more).
WORKER_GRACE = 1.0
_POLL = 0.05  # seconds between looks at a worker that has not connected yet
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


class EngineWorker:
    """One worker process for one engine; :meth:`solve` sends it one attempt's files."""

    def __init__(self, engine: str, env: dict[str, str] | None, memory_limit_mb: int | None):
        self.engine = engine
        self.memory_limit_mb = memory_limit_mb
        self._env = env
        self._folder = Path(tempfile.mkdtemp(prefix="relevance-plan-upw-"))
        self._group: StartedGroup | None = None
        self._listener: socket.socket | None = None
        self._connection: socket.socket | None = None
        self._stream: Any = None  # the connection as a binary file
        self.start_cost: float | None = None  # seconds from its start until it was ready
        try:
            self._start()
        except BaseException:
            self.close()
            raise

    def _start(self) -> None:
        address = str(self._folder / SOCKET_NAME)
        if len(address) > _MAX_SOCKET_PATH:
            raise errors.PlannerError(f"the temporary folder's path is too long for a socket: {address}")
        listener = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
        listener.bind(address)
        listener.listen(1)
        self._listener = listener
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
        """Wait (until ``until``, monotonic) for the worker to connect; False if it died or did not."""
        if self._connection is not None:
            return True
        assert self._listener is not None and self._group is not None
        while until is None or time.monotonic() < until:
            wait = _POLL if until is None else max(min(_POLL, until - time.monotonic()), 0.0)
            if select.select([self._listener], [], [], wait)[0]:
                self._connection, _ = self._listener.accept()
                self._stream = self._connection.makefile("rwb")
                self.start_cost = time.monotonic() - self._group.started
                return True
            if self._group.exited():
                return False
        return False

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
        group, self._group = self._group, None
        for handle in (self._stream, self._connection, self._listener):
            if handle is not None:
                with contextlib.suppress(OSError):
                    handle.close()
        self._stream = self._connection = self._listener = None
        if group is not None:
            group.stop()
        shutil.rmtree(self._folder, ignore_errors=True)


class WorkerPool:
    """The workers of one run, one per engine, all killed when the run ends."""

    def __init__(self, memory_limit_mb: int | None):
        self.memory_limit_mb = memory_limit_mb
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
            try:
                worker = EngineWorker(engine, env, self.memory_limit_mb)
            except (errors.PlannerError, OSError):
                self._refused.add(engine)
                return None
            self._workers[engine] = worker
            return worker

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
def worker_pool(memory_limit_mb: int | None) -> Iterator[WorkerPool]:
    """Engine workers for the run inside the block (this thread), killed when it ends."""
    pool = WorkerPool(memory_limit_mb)
    token = _POOL.set(pool)
    try:
        yield pool
    finally:
        _POOL.reset(token)
        pool.close()
