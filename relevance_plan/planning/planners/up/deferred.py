"""ConfigSpace imported on first use, in the processes that run unified-planning engines.

unified-planning's ``Engine`` base class imports ``ConfigurationSpace`` from
ConfigSpace at start-up, to describe an engine's parameters for tuning;
ConfigSpace in turn imports scipy.stats.  That is about a second of a
core before an engine can take a problem (docs/planners.md gives the
measurement), and a one-shot solve never builds a configuration space.

:func:`defer_configspace` puts a stand-in module under the name
``ConfigSpace`` before unified-planning is imported.  Its
``ConfigurationSpace`` builds the real one, and any other name is looked
up in the real package; either imports ConfigSpace at that moment and
hands the name over to it.  Submodules (``ConfigSpace.util``) are found
through the real package's path.  The worker and the child call it first
thing; the user's own process is left alone.
"""

from __future__ import annotations

import importlib
import importlib.util
import sys
import types
from typing import Any

NAME = "ConfigSpace"


class _StandIn(types.ModuleType):
    def __getattr__(self, name: str) -> Any:
        if name.startswith("__"):  # the import system probes these: no reason to load anything
            raise AttributeError(name)
        return getattr(_real(), name)


def _real() -> types.ModuleType:
    """The real ConfigSpace, imported now if the stand-in still holds its place."""
    module = sys.modules.get(NAME)
    if isinstance(module, _StandIn):
        del sys.modules[NAME]
        module = importlib.import_module(NAME)
    assert module is not None
    return module


class ConfigurationSpace:
    """Stands in for ``ConfigSpace.ConfigurationSpace`` in the modules that imported the name early."""

    def __new__(cls, *args: Any, **kwargs: Any) -> Any:
        return _real().ConfigurationSpace(*args, **kwargs)


def defer_configspace() -> bool:
    """Put the stand-in in place unless ConfigSpace is imported already or not installed; whether it did."""
    if NAME in sys.modules:
        return False
    spec = importlib.util.find_spec(NAME)
    if spec is None or spec.submodule_search_locations is None:
        return False  # not installed (unified-planning will say so), or not the package we know
    stand_in = _StandIn(NAME, __doc__)
    stand_in.__path__ = list(spec.submodule_search_locations)
    stand_in.ConfigurationSpace = ConfigurationSpace  # type: ignore[attr-defined]
    sys.modules[NAME] = stand_in
    return True
