"""An imported problem's sidecar read back: which graph node each PDDL object is.

``scene-graph import`` writes ``PROBLEM.json`` beside ``PROBLEM.pddl``; its
``scene_graph.nodes`` maps each object's name to its node id and NodeSymbol
(or, for a class, the labels it stands for).  ``plan`` gives the plan in node
ids too and ``score --why`` names the nodes, whenever such a sidecar is
there.  Plain JSON: reading it needs no spark-dsg.
"""

from __future__ import annotations

import os
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any


@dataclass(frozen=True)
class NodeMap:
    path: str
    nodes: Mapping[str, Mapping[str, Any]]  # lower-cased PDDL name -> {"node", "symbol", "layer", ...}

    def describe(self, name: str) -> str:
        """``graph node O(12) (id 5692549928996306956)``, or what the object stands for."""
        entry = self.nodes.get(name.lower())
        if entry is None:
            return "not from the graph"
        if entry.get("node") is None:
            what = entry.get("note") or f"no graph node ({entry.get('layer')})"
            return f"{entry.get('layer', 'object')}: {what}"
        return f"graph node {entry.get('symbol')} (id {entry['node']}, {entry.get('layer')})"

    def step_nodes(self, args: Iterable[str]) -> list[dict[str, Any]]:
        found = []
        for arg in args:
            entry = self.nodes.get(arg.lower(), {})
            found.append({"name": arg, "node": entry.get("node"), "symbol": entry.get("symbol")})
        return found


def read_node_map(problem_path: str | os.PathLike[str] | None) -> NodeMap | None:
    """The node map of the sidecar beside ``problem_path``, or None when there is none (or it is not an
    import's): the callers then go on without node ids."""
    from relevance_plan.errors import InputFileError
    from relevance_plan.sidecar import read_sidecar, sidecar_path

    if problem_path is None:
        return None
    path = sidecar_path(problem_path)
    if not path.is_file():
        return None
    try:
        data = read_sidecar(path)
    except InputFileError:
        return None
    section = data.get("scene_graph")
    nodes = section.get("nodes") if isinstance(section, dict) else None
    if not isinstance(nodes, dict):
        return None
    return NodeMap(str(path), MappingProxyType({str(k).lower(): v for k, v in nodes.items() if isinstance(v, dict)}))


def plan_in_nodes(node_map: NodeMap, steps: Iterable[Any]) -> list[dict[str, Any]]:
    """Each plan step with the graph nodes of its arguments."""
    return [{"step": str(step), "action": step.action, "args": node_map.step_nodes(step.args)} for step in steps]
