"""What the CLI shows while long work runs: a live bar on a terminal, one summary line otherwise."""

from __future__ import annotations

import sys
import time
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

from relevance_plan.progress import ProgressEvent


class ProgressBar:
    """A progress callback that counts finished units (rich's bar when stderr is a terminal)."""

    def __init__(self, description: str, total: int | None, live: bool):
        self.description = description
        self.total = total or 0
        self.done = 0
        self.failures = 0
        self.started = time.perf_counter()
        self._live: Any = None
        self._task: Any = None
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
            self._task = self._live.add_task(description, total=self.total, failures=0)
            self._live.start()

    def __call__(self, event: ProgressEvent) -> None:
        if event.done is None:
            return
        if event.total is not None and event.total != self.total:
            if not self.total and self.description.endswith(("compare", "demo")):
                self.description += f" ({event.total} jobs)"
            self.total = event.total
            if self._live is not None:
                self._live.update(self._task, total=self.total)
        self.failures += int(event.failed)
        self.done = event.done
        if self._live is not None:
            self._live.update(self._task, completed=self.done, failures=self.failures)

    def close(self, summary: bool = True) -> None:
        if self._live is not None:
            self._live.stop()
        if summary and self.total:
            elapsed = time.perf_counter() - self.started
            print(
                f"{self.description}: {self.done}/{self.total} done, {self.failures} failed, {elapsed:.1f} s",
                file=sys.stderr,
            )


@contextmanager
def progress_bar(description: str, total: int | None = None, live: bool | None = None) -> Iterator[ProgressBar]:
    """A bar when stderr is a terminal, else only the final summary line; nothing after an error."""
    bar = ProgressBar(description, total, sys.stderr.isatty() if live is None else live)
    try:
        yield bar
    except BaseException:
        # The error is the one line the user needs; no "0/N done" before it.
        bar.close(summary=False)
        raise
    bar.close()
