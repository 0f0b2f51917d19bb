"""spark-dsg, the one module that imports it: files and binary updates read into :class:`SceneGraph` values.

spark-dsg (MIT SPARK, BSD-3-Clause) reads Hydra's JSON and binary
encodings; it prints its warnings (an outdated encoding, say) on the
process's own standard output, so every call into it runs with that
descriptor caught, and what it said becomes a note instead of text in the
middle of a JSON report.
"""

from __future__ import annotations

import contextlib
import math
import os
import re
import tempfile
from collections.abc import Iterator
from types import MappingProxyType
from typing import Any

from relevance_plan.errors import MissingExtraError, SceneGraphError
from relevance_plan.scene_graphs.graph import OBJECTS, PLACES, ROOMS, GraphNode, SceneGraph

HYDRA_EXTRA_INSTALL = "pip install 'relevance-plan[hydra]'"
# A graph file larger than this is refused before it is read (a Hydra graph saved with its mesh can be
# large; without it, a building's graph is a few megabytes).
MAX_GRAPH_BYTES = 64 * 1024 * 1024
# Where the importer keeps the names the Matterport3D converter gives (metadata key -> layer -> label -> name).
COARSE_LABELS_KEY = "relevance_plan_coarse_label_names"


def spark_dsg() -> Any:
    """The ``spark_dsg`` module, or one line naming the extra that brings it."""
    try:
        import spark_dsg as module
    except ImportError:
        raise MissingExtraError(f"reading scene graphs needs the 'hydra' extra: {HYDRA_EXTRA_INSTALL}") from None
    return module


@contextlib.contextmanager
def native_output(said: list[str]) -> Iterator[None]:
    """Descriptors 1 and 2 caught in a temporary file while spark-dsg runs; what it wrote goes to ``said``."""
    import sys

    for stream in (sys.stdout, sys.stderr):
        with contextlib.suppress(Exception):
            stream.flush()
    with tempfile.TemporaryFile() as caught:
        saved = [os.dup(1), os.dup(2)]
        try:
            os.dup2(caught.fileno(), 1)
            os.dup2(caught.fileno(), 2)
            yield
        finally:
            os.dup2(saved[0], 1)
            os.dup2(saved[1], 2)
            for descriptor in saved:
                os.close(descriptor)
            caught.seek(0)
            text = caught.read(64 * 1024).decode("utf-8", errors="replace")
            said.extend(line.strip() for line in text.splitlines() if line.strip())


_JSON_ERROR = re.compile(r"^\[json\.exception\.[a-z_]+\.\d+\]\s*")
_JSON_LINE = re.compile(r"at line (\d+), column (\d+)")


def _refusal(error: Exception, source: str, what: str) -> SceneGraphError:
    text = str(error).strip().splitlines()[0] if str(error).strip() else type(error).__name__
    text = _JSON_ERROR.sub("", text)
    text = re.sub(r"^\[[^\]]*\.cpp:\d+\]\s*", "", text)
    where = _JSON_LINE.search(text)
    line = int(where.group(1)) if where else None
    return SceneGraphError(f"not a scene graph spark-dsg can read ({what}): {text}", path=source, line=line)


def check_graph_file(path: str, max_bytes: int = MAX_GRAPH_BYTES) -> None:
    """Refuse, before reading, a path that is no regular file or is larger than ``max_bytes``."""
    from relevance_plan.io import check_input_file

    check_input_file(path, "scene graph")
    try:
        size = os.stat(path).st_size
    except OSError as error:
        raise SceneGraphError(f"cannot read the scene graph: {error.strerror}", path=path) from None
    if size > max_bytes:
        raise SceneGraphError(
            f"the scene graph is {size / 2**20:.0f} MiB, more than the {max_bytes / 2**20:.0f} MiB this import reads"
            " (--max-graph-mb raises it; a graph saved without its mesh is much smaller)",
            path=path,
        )


def load_json_graph(path: str, max_bytes: int = MAX_GRAPH_BYTES) -> SceneGraph:
    """A Hydra scene graph file (spark-dsg's JSON, or its binary encoding) as a :class:`SceneGraph`."""
    check_graph_file(path, max_bytes)
    module = spark_dsg()
    said: list[str] = []
    try:
        with native_output(said):
            graph = module.DynamicSceneGraph.load(path)
    except (RuntimeError, ValueError, TypeError, OSError) as error:
        raise _refusal(error, path, "JSON") from None
    return read_dsg(graph, path, said)


def graph_from_binary(data: bytes, source: str) -> SceneGraph:
    """One scene graph in spark-dsg's binary encoding (what ``spark_dsg.zmq.DsgSender`` publishes)."""
    module = spark_dsg()
    said: list[str] = []
    try:
        with native_output(said):
            graph = module.DynamicSceneGraph.from_binary(data)
    except (RuntimeError, ValueError, TypeError) as error:
        raise _refusal(error, source, "binary update") from None
    return read_dsg(graph, source, said)


def read_dsg(graph: Any, source: str, said: list[str] | None = None) -> SceneGraph:
    """A spark-dsg ``DynamicSceneGraph`` as plain values."""
    nodes: dict[int, GraphNode] = {}
    for node in graph.nodes:
        nodes[node.id.value] = _node(node)
    for node in graph.unpartitioned_nodes if hasattr(graph, "unpartitioned_nodes") else ():
        nodes.setdefault(node.id.value, _node(node))
    edges = tuple((edge.source, edge.target) for edge in graph.edges)
    labels: dict[int, Any] = {}
    for layer in (OBJECTS, PLACES, ROOMS):
        names = _label_names(graph, layer)
        if names:
            labels[layer] = MappingProxyType(names)
    coarse = _coarse_names(graph)
    notes = tuple(f"spark-dsg: {line}" for line in (said or ()))
    return SceneGraph(source, MappingProxyType(nodes), edges, MappingProxyType(labels), coarse, notes)


def _node(node: Any) -> GraphNode:
    attributes = node.attributes
    label = getattr(attributes, "semantic_label", None)
    if label is not None and label == getattr(attributes, "NO_SEMANTIC_LABEL", -1):
        label = None
    position = tuple(float(value) for value in attributes.position)
    return GraphNode(
        id=int(node.id.value),
        symbol=str(node.id),
        layer=int(node.layer.layer),
        partition=int(node.layer.partition),
        label=int(label) if label is not None else None,
        position=(position[0], position[1], position[2]),
        box=_box(attributes),
    )


def _box(attributes: Any) -> tuple[tuple[float, float, float], tuple[float, float, float]] | None:
    box = getattr(attributes, "bounding_box", None)
    if box is None or not box.is_valid():
        return None
    centre = [float(value) for value in box.world_P_center]
    half = [float(value) / 2 for value in box.dimensions]
    if not all(math.isfinite(value) for value in centre + half):
        return None
    lower = (centre[0] - half[0], centre[1] - half[1], centre[2] - half[2])
    upper = (centre[0] + half[0], centre[1] + half[1], centre[2] + half[2])
    return lower, upper


def _label_names(graph: Any, layer: int) -> dict[int, str]:
    try:
        space = graph.get_labelspace(layer, 0)
    except (RuntimeError, ValueError, TypeError):
        return {}
    if not space:
        return {}
    return {int(label): str(name) for label, name in space.labels_to_names.items()}


def _coarse_names(graph: Any) -> Any:
    try:
        stored = graph.metadata.get().get(COARSE_LABELS_KEY, {})
    except (RuntimeError, ValueError, TypeError, AttributeError):
        return MappingProxyType({})
    found: dict[int, Any] = {}
    if isinstance(stored, dict):
        for layer, names in stored.items():
            if str(layer).isdigit() and isinstance(names, dict):
                found[int(layer)] = MappingProxyType(
                    {int(label): str(name) for label, name in names.items() if str(label).lstrip("-").isdigit()}
                )
    return MappingProxyType(found)
