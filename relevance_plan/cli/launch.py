"""The ``relevance-plan`` console script.

``plan`` gets a head start: when the command line says the full problem will
be planned with Fast Downward (a race, or ``--method pure``), the driver is
started on the user's files before the commands, the reader and the scorers
are imported (``planning/head_start.py``).  Everything else goes straight to
the click commands of ``app.py``.
"""

from __future__ import annotations

import sys


def main() -> None:
    arguments = sys.argv[1:]
    started = arguments[:1] == ["plan"] and _head_start(arguments[1:])
    try:
        from relevance_plan.cli.app import main as commands

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
