"""Planning the full problem beside the pruned attempts, so that a bad first guess costs nothing.

On a machine with a spare core, the attempt loop can start the user's full
problem at once, in a thread that waits on its planner process, while the
main thread scores, prunes and plans pruned problems.  The first decisive
answer wins and the other side's planner is stopped: a valid plan, or (from
the full problem only) a proof that the problem has none.  The total time is
then about the smaller of the two, whatever the first selection was.

The race's thread works in a copy of the context of the thread that started
it, so the run's warm planners (a unified-planning engine's worker, started
while the tool read the problem) serve the full problem there as they would
serve planning without pruning; the pruned attempts get planners of their own.
"""

from __future__ import annotations

import contextvars
import threading
from collections.abc import Callable
from typing import Generic, TypeVar

from relevance_plan.planning.methods import Method
from relevance_plan.supervision.process import CancelScope, cancel_scope
from relevance_plan.supervision.spawn import usable_cores

T = TypeVar("T")
THREAD_NAME = "relevance-plan-race"


def race_by_default(method: str) -> bool:
    """``plan``'s default: race when pruning may guess wrong and a second core is there to take it."""
    return method == Method.RELEVANCE and usable_cores() >= 2


class Race(Generic[T]):
    """``work`` run in its own thread; when ``decisive(result)``, ``loser`` is cancelled.

    ``loser`` is the scope of the caller's own planner runs.  :meth:`stop`
    cancels ``work``'s planner runs and waits for the thread.
    """

    def __init__(self, work: Callable[[], T], decisive: Callable[[T], bool], loser: CancelScope):
        self._work = work
        self._decisive = decisive
        self._loser = loser
        self._scope = CancelScope()
        self._done = threading.Event()
        self._result: T | None = None
        self._error: BaseException | None = None
        self._thread: threading.Thread | None = None

    def start(self, context: contextvars.Context | None = None) -> Race[T]:
        """Start ``work`` in its own thread, in ``context`` (default: a copy of this thread's)."""
        context = contextvars.copy_context() if context is None else context
        self._thread = threading.Thread(target=context.run, args=(self._main,), name=THREAD_NAME, daemon=True)
        self._thread.start()
        return self

    def _main(self) -> None:
        with cancel_scope(self._scope):
            try:
                self._result = self._work()
            except BaseException as error:  # handed to the caller by wait()
                self._error = error
        self._done.set()
        if self.won:
            self._loser.cancel()

    @property
    def won(self) -> bool:
        """Finished with a decisive result, or an error (and not stopped).

        An error is decisive: it says the planner cannot be run or supervised (its guard killed from
        outside, say), which the other side would learn only at its own time limit.
        :meth:`wait` raises it.
        """
        if not self._done.is_set() or self._scope.cancelled:
            return False
        if self._error is not None:
            return True
        return self._result is not None and self._decisive(self._result)

    def wait(self) -> T:
        """The result, once ``work`` has finished (its error re-raised here)."""
        self._done.wait()
        if self._error is not None:
            raise self._error
        assert self._result is not None
        return self._result

    @property
    def cancelled(self) -> bool:
        """Stopped by :meth:`stop` before ``work`` had finished."""
        return self._scope.cancelled

    def result(self) -> T | None:
        """``work``'s result once it has finished; None while it runs or when it raised."""
        return self._result if self._done.is_set() else None

    def stop(self) -> None:
        """Stop ``work``'s planner runs (if still going) and wait for the thread."""
        if not self._done.is_set():
            self._scope.cancel()
        if self._thread is not None:
            self._thread.join()
