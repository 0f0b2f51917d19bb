"""Progress display: a live bar on a terminal, one final line otherwise."""

from __future__ import annotations

import sys
import time
from collections.abc import Iterator
from contextlib import contextmanager


class Progress:
    """Counts finished units of work; ``advance`` may be called from several threads via the caller's lock."""

    def __init__(self, total: int, description: str, live: bool):
        self.total = total
        self.description = description
        self.done = 0
        self.failures = 0
        self.started = time.perf_counter()
        self._live = None
        self._task = None
        if live:
            from rich.progress import BarColumn, MofNCompleteColumn, TextColumn, TimeElapsedColumn, TimeRemainingColumn
            from rich.progress import Progress as RichProgress

            self._live = RichProgress(
                TextColumn("{task.description}"),
                BarColumn(),
                MofNCompleteColumn(),
                TextColumn("failures {task.fields[failures]}"),
                TimeElapsedColumn(),
                TextColumn("ETA"),
                TimeRemainingColumn(),
                transient=False,
                redirect_stdout=False,
                redirect_stderr=False,
            )
            self._task = self._live.add_task(description, total=total, failures=0)
            self._live.start()

    def advance(self, failed: bool = False, note: str | None = None) -> None:
        self.done += 1
        self.failures += int(failed)
        if self._live is not None:
            self._live.update(self._task, advance=1, failures=self.failures)

    def close(self, summary: bool = True) -> None:
        if self._live is not None:
            self._live.stop()
        if not summary:
            return
        elapsed = time.perf_counter() - self.started
        print(
            f"{self.description}: {self.done}/{self.total} done, {self.failures} failed, {elapsed:.1f} s",
            file=sys.stderr,
        )


@contextmanager
def progress(total: int, description: str, live: bool | None = None) -> Iterator[Progress]:
    """A live bar when stderr is a terminal; otherwise only the final summary line."""
    if live is None:
        live = sys.stderr.isatty()
    reporter = Progress(total, description, live)
    try:
        yield reporter
    except BaseException:
        # The error is the one line the user needs; no "0/N done" before it.
        reporter.close(summary=False)
        raise
    reporter.close()
