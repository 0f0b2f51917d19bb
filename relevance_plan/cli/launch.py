"""The ``relevance-plan`` console script.

``plan`` gets a head start: when the command line says the full problem will
be planned with Fast Downward (a race, or ``--method pure``), the driver is
started on the user's files before the commands, the reader and the scorers
are imported (``planning/planners/fast_downward/head_start.py``).  Everything else goes straight to
the click commands of ``app.py``.

``plan`` also ends at once when it is done (:func:`_end_now`): the
interpreter's own teardown, which frees what the command built, is time
nobody waits for.
"""

from __future__ import annotations

import _signal as signal  # signal's names without its enums: this module delays the head start
import atexit
import os
import sys

TYPE_CHECKING = False  # typing's own flag would import typing
if TYPE_CHECKING:
    from collections.abc import Callable
    from types import FrameType
    from typing import Any

    _Handler = Callable[[int, FrameType | None], Any] | int | None

# Until the command installs its own handlers, these end a started head start like Ctrl-C ends a command.
_SIGNALS = ("SIGTERM", "SIGHUP", "SIGINT")


def main() -> None:
    arguments = sys.argv[1:]
    if arguments[:1] != ["plan"]:
        _commands(started=False)
        return
    try:
        _commands(started=_head_start(arguments[1:]))
    except SystemExit as end:
        _end_now(end)
        raise


def _commands(started: bool) -> None:
    previous = _stop_on_signals() if started else {}
    try:
        from relevance_plan.cli.app import LAUNCHED
        from relevance_plan.cli.app import main as commands

        for number, handler in previous.items():
            signal.signal(number, handler)
        commands(prog_name="relevance-plan", obj=LAUNCHED)
    finally:
        if started:
            from relevance_plan.planning.planners.fast_downward import head_start

            head_start.discard_pending()  # the command ended before it planned the full problem


def _end_now(end: SystemExit) -> None:
    """Exit as ``end`` would, skipping the interpreter's teardown, when that loses nothing: the
    exit handlers run here, no other thread is left to wait for, and the output is flushed.
    Otherwise return (the caller exits as usual)."""
    import threading

    if not isinstance(end.code, int | None) or threading.active_count() > 1:
        return
    atexit._run_exitfuncs()  # e.g. the finalizers of temporary folders left open
    try:
        sys.stdout.flush()
        sys.stderr.flush()
    except (OSError, ValueError):
        return  # the interpreter reports it, as it would have
    os._exit(end.code or 0)


def _head_start(arguments: list[str]) -> bool:
    try:
        from relevance_plan.planning.planners.fast_downward import head_start

        head_start.start_for_plan(arguments)
    except Exception:  # an optimisation only: the command itself reports what is wrong
        return False
    return True


def _stop_on_signals() -> dict[int, _Handler]:
    def stop(number: int, frame: FrameType | None) -> None:
        from relevance_plan.exitcodes import ExitCode
        from relevance_plan.planning.planners.fast_downward import head_start

        head_start.discard_pending()
        name = next((name for name in _SIGNALS if getattr(signal, name, None) == number), str(number))
        print(f"relevance-plan: interrupted by {name}", file=sys.stderr)
        os._exit(int(ExitCode.INTERRUPTED))  # nothing else has started yet

    previous: dict[int, _Handler] = {}
    for name in _SIGNALS:
        number = getattr(signal, name, None)
        if number is not None:
            previous[number] = signal.signal(number, stop)
    return previous
