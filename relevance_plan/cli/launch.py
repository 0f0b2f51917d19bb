"""The ``relevance-plan`` console script.

``plan`` gets a head start: when the command line says the full problem will
be planned with Fast Downward (a race, or ``--method pure``), the driver is
started on the user's files before the commands, the reader and the scorers
are imported (``planning/head_start.py``).  Everything else goes straight to
the click commands of ``app.py``.
"""

from __future__ import annotations

import os
import signal
import sys
from collections.abc import Callable
from types import FrameType
from typing import Any

# Until the command installs its own handlers, these end a started head start like Ctrl-C ends a command.
_SIGNALS = ("SIGTERM", "SIGHUP", "SIGINT")
_Handler = Callable[[int, FrameType | None], Any] | int | None


def main() -> None:
    arguments = sys.argv[1:]
    started = arguments[:1] == ["plan"] and _head_start(arguments[1:])
    previous = _stop_on_signals() if started else {}
    try:
        from relevance_plan.cli.app import main as commands

        for number, handler in previous.items():
            signal.signal(number, handler)
        commands(prog_name="relevance-plan")
    finally:
        if started:
            from relevance_plan.planning import head_start

            head_start.discard_pending()  # the command ended before it planned the full problem


def _head_start(arguments: list[str]) -> bool:
    try:
        from relevance_plan.planning import head_start

        head_start.start_for_plan(arguments)
    except Exception:  # an optimisation only: the command itself reports what is wrong
        return False
    return True


def _stop_on_signals() -> dict[int, _Handler]:
    def stop(number: int, frame: FrameType | None) -> None:
        from relevance_plan.exitcodes import ExitCode
        from relevance_plan.planning import head_start

        head_start.discard_pending()
        print(f"relevance-plan: interrupted by {signal.Signals(number).name}", file=sys.stderr)
        os._exit(int(ExitCode.INTERRUPTED))  # nothing else has started yet

    previous: dict[int, _Handler] = {}
    for name in _SIGNALS:
        number = getattr(signal, name, None)
        if number is not None:
            previous[number] = signal.signal(number, stop)
    return previous
