"""The ``relevance-plan`` command: the only place that prints for the user and exits.

``main`` (the click group) is imported on first use, so that the launcher
(``launch.py``, the console script) can start work before the commands load.
"""

from __future__ import annotations

TYPE_CHECKING = False  # typing's own flag would import typing (the launcher's path stays light)
if TYPE_CHECKING:
    from typing import Any

__all__ = ["main"]


def __getattr__(name: str) -> Any:
    if name == "main":
        from relevance_plan.cli.app import main

        return main
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
