"""Executors: where a batch's jobs run, locally on threads or on a Dask cluster.

Both take the pending jobs, a ``record`` callback that the main thread calls
with each finished row, and a stop event (set by ``signals.stop_event_on_signals``):

- locally, ``workers`` threads each drive one planner subprocess (lighter
  than a process pool, and more robust: one killed planner affects only its
  own job, where a dead pool worker breaks every pending one);
- on Dask (``scheduler='tcp://HOST:PORT'``), the same jobs go out with
  ``client.submit(run_job, job, pure=False, retries=2)``.  Workers must see
  the suite files under the same paths and have the same packages installed.

On a stop (Ctrl-C, SIGTERM) or an error, pending jobs are cancelled, every
running planner is killed, rows that were complete are still recorded, and
the exception propagates.
"""

from __future__ import annotations

import concurrent.futures
import contextlib
import re
import socket
import struct
import threading
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

from relevance_plan.batch.jobs import Job, run_job
from relevance_plan.errors import SchedulerError
from relevance_plan.supervision.process import terminate_all_runs

DASK_INSTALL_HINT = "pip install 'relevance-plan[dask]'"
DEFAULT_SCHEDULER_TIMEOUT = 10.0
SCHEDULER_ADDRESS = re.compile(
    r"^(?:(?:tcp|tls|ws|wss|ucx)://)?[^\s/:]+:\d+$|^(?:tcp|tls|ws|wss|ucx)://\[[0-9a-fA-F:.]+\]:\d+$"
)
_STOP_GRACE = 30.0  # seconds to wait for running jobs after their planners were killed
_POLL_SECONDS = 0.2  # how often a running batch looks at its stop event

Record = Callable[[dict[str, Any]], None]


@dataclass(frozen=True)
class Workers:
    """Where a batch's jobs run: ``jobs`` local threads, or the Dask workers of ``scheduler``
    (``jobs`` unused then), reached within ``scheduler_timeout`` seconds."""

    jobs: int = 1
    scheduler: str | None = None
    scheduler_timeout: float = DEFAULT_SCHEDULER_TIMEOUT


# --------------------------------------------------------------------------- local


def run_local(pending: Sequence[Job], workers: int, record: Record, stop: threading.Event) -> None:
    """Run ``pending`` on ``workers`` threads; ``record`` each row in this (the main) thread."""
    pool = concurrent.futures.ThreadPoolExecutor(max_workers=workers, thread_name_prefix="relevance-plan-job")
    futures = [pool.submit(run_job, job) for job in pending]
    recorded: set = set()
    try:
        waiting = set(futures)
        while waiting:
            done, waiting = concurrent.futures.wait(
                waiting, timeout=_POLL_SECONDS, return_when=concurrent.futures.FIRST_COMPLETED
            )
            for future in done:
                row = future.result()  # an unexpected error stops the batch
                recorded.add(future)
                record(row)
            if stop.is_set():
                raise KeyboardInterrupt
    except BaseException as error:
        # Rows that were complete before the stop are genuine; keep them.
        finished = [
            f for f in futures if f not in recorded and f.done() and not f.cancelled() and f.exception() is None
        ]
        _stop_local(pool, futures)
        if isinstance(error, KeyboardInterrupt):
            for future in finished:
                record(future.result())
        raise
    pool.shutdown(wait=True)


def _stop_local(pool: concurrent.futures.ThreadPoolExecutor, futures: Sequence[concurrent.futures.Future]) -> None:
    """Cancel what has not started, kill running planners until every running job has returned."""
    pool.shutdown(wait=False, cancel_futures=True)
    deadline = time.monotonic() + _STOP_GRACE
    while True:
        try:
            # Again and again: a job between two attempts may start one more planner.
            terminate_all_runs()
            running = [f for f in futures if not f.done()]
            if not running or time.monotonic() > deadline:
                return
            concurrent.futures.wait(running, timeout=0.1)
        except KeyboardInterrupt:
            continue  # a second Ctrl-C: finish stopping the planners first


# --------------------------------------------------------------------------- Dask


def connect_scheduler(address: str, timeout: float = DEFAULT_SCHEDULER_TIMEOUT):
    """A ``dask.distributed.Client`` for ``address``; ``SchedulerError`` when unreachable, when what
    answers there is not a Dask scheduler, or when Dask is missing."""
    try:
        from dask.distributed import Client
    except ImportError:
        raise SchedulerError(f"Dask is not installed: {DASK_INSTALL_HINT}") from None
    started = time.monotonic()
    check_scheduler_greeting(address, timeout)
    left = max(timeout - (time.monotonic() - started), 0.1)
    try:
        return _closed_on_failure(Client)(address, timeout=left, set_as_default=False)
    except MemoryError:  # an answer read as a message of exabytes
        raise SchedulerError(f"the server at {address} is not a Dask scheduler (its answer is not Dask's)") from None
    except Exception as error:  # whatever else Dask's client makes of the answer, it is one line here
        detail = " ".join(str(error).split()) or type(error).__name__
        raise SchedulerError(f"cannot reach the Dask scheduler at {address}: {detail}") from None


# A Dask scheduler greets a new connection with one message: its length in 8 bytes (struct "Q", as
# Dask writes it), then the message, a few hundred bytes.  A length past this is not Dask's: read
# as one, it would have the client allocate it (a port answering text asks for exabytes).
_GREETING_LIMIT = 64 * 2**20
_PLAIN_TCP = re.compile(r"^(?:tcp://)?([^\s/:\[\]]+):(\d+)$")


def check_scheduler_greeting(address: str, timeout: float) -> None:
    """``SchedulerError`` when the server at a plain TCP ``address`` greets with something that is not
    Dask's (text, a web page), or says nothing within ``timeout`` seconds (a scheduler greets at
    once).  A server that cannot be reached, or closes the connection, is left to Dask's client to
    report; so are other protocols."""
    found = _PLAIN_TCP.match(address)
    if found is None:
        return
    host, port = found.group(1), int(found.group(2))
    deadline = time.monotonic() + timeout
    try:
        connection = socket.create_connection((host, port), timeout=timeout)
    except (OSError, ValueError):
        return
    greeting = b""
    with connection:
        try:
            while len(greeting) < 8:
                connection.settimeout(max(deadline - time.monotonic(), 0.01))
                chunk = connection.recv(8 - len(greeting))
                if not chunk:
                    return
                greeting += chunk
        except TimeoutError:
            raise SchedulerError(f"the server at {address} did not greet as Dask does within {timeout:g} s") from None
        except OSError:
            return
    if struct.unpack("Q", greeting)[0] > _GREETING_LIMIT:
        raise SchedulerError(f"the server at {address} is not a Dask scheduler (it answers {greeting!r}...)")


def _closed_on_failure(client_class):
    """Dask's client, made to end closed when its start fails: collected later, it has nothing left to
    close (Dask's own would try again, time out, and print a traceback after the tool's line)."""

    class Client(client_class):
        def start(self, **kwargs):
            try:
                return super().start(**kwargs)
            except BaseException:
                with contextlib.suppress(Exception):
                    self._loop_runner.stop()
                self.status = "closed"
                raise

    return Client


def _terminate_worker_runs() -> None:
    terminate_all_runs()


def run_dask(pending: Sequence[Job], client, address: str, record: Record, stop: threading.Event) -> None:
    """Run ``pending`` on the Dask cluster of ``client``; ``record`` each row here as it completes."""
    from dask.distributed import as_completed

    futures = [client.submit(run_job, job, pure=False, retries=2) for job in pending]
    recorded: set = set()
    try:
        finished = as_completed(futures, loop=client.loop)
        while not finished.is_empty():
            if stop.is_set():
                raise KeyboardInterrupt
            if not finished.has_ready():
                time.sleep(_POLL_SECONDS / 4)
                continue
            for future in finished.next_batch(block=False):
                row = _dask_row(future, address)
                recorded.add(future.key)
                record(row)
                future.release()
    except BaseException as error:
        _stop_dask(client, futures, recorded, record, interrupted=isinstance(error, KeyboardInterrupt))
        raise


def _dask_row(future, address: str) -> dict[str, Any]:
    killed: tuple[type[BaseException], ...] = ()
    with contextlib.suppress(ImportError):  # part of distributed, which ran the future
        from distributed import KilledWorker

        killed = (KilledWorker,)
    try:
        return future.result()
    except killed as error:
        raise SchedulerError(f"a Dask worker died running a job 3 times: {error}") from None
    except concurrent.futures.CancelledError:
        raise SchedulerError(f"lost the Dask scheduler at {address}; rerun to resume") from None


def _stop_dask(client, futures, recorded: set, record: Record, interrupted: bool) -> None:
    rows = []
    if interrupted:
        # Rows that were complete before the stop are genuine; fetch them before cancelling.
        for future in futures:
            if future.key not in recorded and future.status == "finished":
                with contextlib.suppress(Exception):
                    rows.append(future.result(timeout=5))
    with contextlib.suppress(Exception):
        client.cancel(futures)
    with contextlib.suppress(Exception):
        # Our planners run in the workers' processes; stop them too.
        client.run(_terminate_worker_runs)
    for row in rows:
        record(row)
