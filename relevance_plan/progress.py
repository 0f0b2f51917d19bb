"""How long work reports its progress: one event type, one callback shape, for every front end.

Library code never prints: it calls ``progress(ProgressEvent(...))`` when it
has something to say (a step of the attempt loop, one more problem written,
one more job finished), and the front end decides how to show it (the CLI
draws a bar on a terminal, or one line per step; the Python API passes
nothing and hears nothing).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass


@dataclass(frozen=True)
class ProgressEvent:
    message: str = ""  # a step worth a line ("attempt 2: 40 of 200 objects")
    done: int | None = None  # units finished so far, when the work is counted
    total: int | None = None
    failed: bool = False  # the unit just finished failed (a job that did not solve)


ProgressCallback = Callable[[ProgressEvent], None]


def ignore(event: ProgressEvent) -> None:
    """The callback of a caller that wants no progress."""
