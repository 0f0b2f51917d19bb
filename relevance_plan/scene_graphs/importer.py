"""One scene graph file in, one problem of the hydra domain out, with its sidecar: the import as a value.

The file is a Hydra graph (spark-dsg's JSON, or its binary encoding) or a
Matterport3D ``.house`` file.  Nothing is written here: the CLI writes the
problem, the domain and the sidecar once everything is known to be good.
"""

from __future__ import annotations

import hashlib
import os
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from relevance_plan.data import DOMAINS_DIR
from relevance_plan.errors import RelevancePlanError, SceneGraphError, UsageError
from relevance_plan.scene_graphs.classes import DEFAULT_FLOOR, NO_MAPPING, load_vocabulary, read_label_mapping
from relevance_plan.scene_graphs.dsg import MAX_GRAPH_BYTES, graph_from_binary, load_json_graph
from relevance_plan.scene_graphs.goals import GOAL_FLOOR, GoalResolution, is_atoms, resolve_words
from relevance_plan.scene_graphs.graph import SceneGraph, check_graph
from relevance_plan.scene_graphs.problem import ImportedScene, import_graph, problem_text

DOMAIN_FILE = DOMAINS_DIR / "hydra" / "domain.pddl"
SIDECAR_FORMAT = "relevance-plan scene-graph import 1"


@dataclass(frozen=True)
class ImportOptions:
    labels: str | None = None  # the user's label mapping (YAML)
    start: str | None = None  # the robot's place, when the graph has no agent poses (or to override them)
    class_floor: float = DEFAULT_FLOOR
    goal_floor: float = GOAL_FLOOR
    max_bytes: int = MAX_GRAPH_BYTES
    ignore_unknown_layers: bool = False


@dataclass(frozen=True)
class ImportResult:
    scene: ImportedScene
    resolutions: tuple[GoalResolution, ...] = ()
    text: str | None = None  # the problem; None when there are questions
    sidecar: dict[str, Any] = field(default_factory=dict)

    @property
    def questions(self) -> list[str]:
        return [p.question for p in self.scene.questions] + [r.question for r in self.resolutions if r.question]


def read_graph(path: str, options: ImportOptions = ImportOptions()) -> SceneGraph:
    """The file at ``path``, checked: a ``.house`` through the Matterport3D converter, else spark-dsg's own."""
    if Path(path).suffix.lower() == ".house":
        from relevance_plan.scene_graphs.house import load_house

        graph = load_house(path, options.max_bytes)
    else:
        graph = load_json_graph(path, options.max_bytes)
    return check_graph(graph, options.ignore_unknown_layers)


def import_scene(graph: SceneGraph, goals: Sequence[str], options: ImportOptions, name: str) -> ImportResult:
    """The graph as a problem with the goals given (atoms, or words resolved to class goals)."""
    vocabulary = load_vocabulary()
    mapping = read_label_mapping(options.labels) if options.labels else NO_MAPPING
    scene = import_graph(graph, vocabulary, mapping, options.class_floor, options.start)
    if scene.questions:
        return ImportResult(scene)
    atoms = [goal for goal in goals if is_atoms(goal)]
    for goal in atoms:
        _check_one_list(goal)
    resolutions = tuple(
        resolve_words(goal, scene, vocabulary, options.goal_floor) for goal in goals if not is_atoms(goal)
    )
    if any(r.atom is None for r in resolutions):
        return ImportResult(scene, resolutions)
    body = " ".join([f"({' '.join(r.atom)})" for r in resolutions if r.atom] + [goal.strip() for goal in atoms])
    text = problem_text(scene, body, name)
    _check_problem(text)
    return ImportResult(scene, resolutions, text, sidecar_of(scene, graph, resolutions, atoms))


def _check_one_list(goal: str) -> None:
    from relevance_plan.pddl.sexpr import parse_sexpr

    try:
        parse_sexpr(goal)
    except RelevancePlanError as error:
        raise UsageError(f"--goal '{goal[:80]}' is not one PDDL condition: {error.message}") from None


def _check_problem(text: str) -> None:
    """The written problem read back with the domain: a goal naming an object the scene lacks is refused."""
    from relevance_plan.io import load_domain
    from relevance_plan.pddl.parser import read_problem

    try:
        read_problem(text, load_domain(DOMAIN_FILE))
    except RelevancePlanError as error:
        raise UsageError(f"--goal: {error.message}") from None


def sidecar_of(
    scene: ImportedScene, graph: SceneGraph, resolutions: Sequence[GoalResolution], atoms: Sequence[str]
) -> dict[str, Any]:
    """The sidecar: every PDDL object's graph node, how each label became a class, how each goal was read."""
    return {
        "scene_graph": {
            "format": SIDECAR_FORMAT,
            "source": os.path.basename(graph.source),
            "sha256": _sha256(graph.source),
            "nodes": {name: ref.as_json() for name, ref in scene.refs.items()},
            "placements": [p.as_json() for p in scene.placements],
            "goals": [r.as_json() for r in resolutions] + [{"text": a, "atom": a} for a in atoms],
            "notes": list(scene.notes),
        }
    }


def _sha256(path: str) -> str | None:
    digest = hashlib.sha256()
    try:
        with open(path, "rb") as stream:
            for chunk in iter(lambda: stream.read(1 << 20), b""):
                digest.update(chunk)
    except OSError:
        return None
    return digest.hexdigest()


def binary_graph(data: bytes, source: str, options: ImportOptions = ImportOptions()) -> SceneGraph:
    if len(data) > options.max_bytes:
        raise SceneGraphError(
            f"a graph of {len(data) / 2**20:.0f} MiB, more than the {options.max_bytes / 2**20:.0f} MiB this reads",
            path=source,
        )
    return check_graph(graph_from_binary(data, source), options.ignore_unknown_layers)
