"""relevance-plan: prune what does not matter, then plan.

The names a library user needs, imported on first use (``import relevance_plan`` stays cheap)::

    import relevance_plan as rp
    rp.prune(domain, problem)        # -> Selection: the objects plan tries first, and the pruned text
    rp.plan(domain, problem)         # -> PlanResult: a plan validated on the original problem
    rp.Session(domain, problem)      # the live session: events in, relevance (and plans) out

``domain`` and ``problem`` are paths or PDDL text.
"""

from __future__ import annotations

import importlib

TYPE_CHECKING = False  # typing's own flag would import typing (the launcher's path stays light)
if TYPE_CHECKING:
    from typing import Any

__version__ = "0.12.0"  # the one place it is written: pyproject.toml reads it from here

_EXPORTS = {
    "prune": "relevance_plan.api",
    "plan": "relevance_plan.api",
    "Session": "relevance_plan.session",
    "EventReport": "relevance_plan.session",
    "PlanOptions": "relevance_plan.planning.options",
    "PlanResult": "relevance_plan.planning.results",
    "PlanStatus": "relevance_plan.planning.results",
    "ScoringOptions": "relevance_plan.relevance.setup",
    "Selection": "relevance_plan.relevance.selection.prune",
    "Thresholds": "relevance_plan.relevance.selection.prune",
    "Plan": "relevance_plan.pddl.plans",
    "read_domain": "relevance_plan.pddl.parser",
    "read_problem": "relevance_plan.pddl.parser",
    "RelevancePlanError": "relevance_plan.errors",
}

__all__ = ["__version__", *_EXPORTS]


def __getattr__(name: str) -> Any:
    module = _EXPORTS.get(name)
    if module is None:
        raise AttributeError(f"module 'relevance_plan' has no attribute {name!r}")
    value = getattr(importlib.import_module(module), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(__all__)
