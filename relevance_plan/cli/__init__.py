"""The ``relevance-plan`` command: the only place that prints for the user and exits.

- ``launch``: the console script; starts ``plan``'s head start before the commands load;
- ``app``: the command group and ``generate``, ``score``, ``prune``, ``plan``, ``examples``, ``exit-codes``;
- ``batch``: ``compare``, ``report``, ``sweep``, ``demo``, ``learn``; ``watch``; ``validate``
  (each imported when its command is asked for);
- ``common``: error handling and the option groups that build the options objects;
- ``paths`` and ``files``: the files a command names, checked before any work, and its output;
- ``display`` (progress while work runs) and ``exits`` (a run ended by its surroundings).

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
