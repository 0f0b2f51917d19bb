"""How every command stops on SIGINT, SIGTERM and SIGHUP: the one signal module.

Two ways, for two kinds of work:

* :func:`interrupt_on_signals` — a single run (``plan``, ``prune``,
  ``watch``...): the signal raises :class:`Interrupted` (a
  ``KeyboardInterrupt``), so every cleanup on the way out runs: the planner's
  process group is killed and reaped, temporary files are removed.  Signals
  after the first are ignored so that a second one cannot cut the cleanup short.
* :func:`stop_event_on_signals` — a batch (``compare``): the handler only sets
  an event, and the batch loop checks it at safe points.  A KeyboardInterrupt
  raised at an arbitrary instruction could land inside a lock another thread needs.

A single run may also be given a deadline (:func:`deadline_alarm`): SIGALRM
then stops it like the signals above, raising :class:`Interrupted` with
``signum`` SIGALRM, which the CLI reports as out of time.

Both only act in the main thread (elsewhere Python cannot install handlers)
and put back the previous handlers when the block ends.
"""

from __future__ import annotations

import contextlib
import os
import signal
import threading
import time
from collections.abc import Iterator

STOP_SIGNALS = (signal.SIGINT, signal.SIGTERM, signal.SIGHUP)
DEADLINE_SIGNAL = signal.SIGALRM


class Interrupted(KeyboardInterrupt):
    """SIGTERM or SIGHUP, raised like Ctrl-C so every cleanup on the way out runs."""

    def __init__(self, signum: int):
        super().__init__(signal.Signals(signum).name)
        self.signum = signum


@contextlib.contextmanager
def _handlers(handler, signals: tuple = STOP_SIGNALS) -> Iterator[None]:
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    previous = {signum: signal.signal(signum, handler) for signum in signals}
    try:
        yield
    finally:
        for signum, old in previous.items():
            signal.signal(signum, old)


@contextlib.contextmanager
def interrupt_on_signals() -> Iterator[None]:
    """While the block runs, SIGTERM and SIGHUP (and SIGALRM, see :func:`deadline_alarm`) stop it as
    Ctrl-C does (raise :class:`Interrupted`)."""
    stopping = False

    def stop(signum, frame):
        nonlocal stopping
        if stopping:
            return
        stopping = True
        if signum == signal.SIGINT:
            raise KeyboardInterrupt
        raise Interrupted(signum)

    with _handlers(stop, STOP_SIGNALS + (DEADLINE_SIGNAL,)):
        yield


def process_age() -> float:
    """Seconds since this process started (Linux: from /proc, to the clock tick; elsewhere 0), so that a
    deadline can count the interpreter's start and the imports too."""
    try:
        with open("/proc/self/stat", "rb") as stream:
            ticks = int(stream.read().rsplit(b")", 1)[1].split()[19])
        return max(time.clock_gettime(time.CLOCK_BOOTTIME) - ticks / os.sysconf("SC_CLK_TCK"), 0.0)
    except (OSError, ValueError, IndexError, AttributeError):
        return 0.0


@contextlib.contextmanager
def deadline_alarm(seconds: float | None) -> Iterator[None]:
    """Send SIGALRM to this process ``seconds`` from now, unless the block ends first.

    Inside :func:`interrupt_on_signals`, the alarm stops the block wherever
    it is (reading, scoring, waiting for a planner), every cleanup included:
    the backstop that holds a run's ``--timeout`` whatever step overruns it.
    Only in the main thread; None: no alarm.
    """
    if seconds is None or threading.current_thread() is not threading.main_thread():
        yield
        return
    signal.setitimer(signal.ITIMER_REAL, max(seconds, 0.001))
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)


@contextlib.contextmanager
def stop_event_on_signals() -> Iterator[threading.Event]:
    """An event that SIGINT, SIGTERM and SIGHUP set while the block runs (SIGINT is handled even
    if it was inherited as ignored)."""
    stop = threading.Event()

    def request_stop(signum, frame):
        stop.set()

    with _handlers(request_stop):
        yield stop
