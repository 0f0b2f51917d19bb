"""The knowledge model: the offline stand-in for the paper's GPT-4o answers.

One YAML file per domain (``domains/<name>/relevance.yaml``), schema version 1,
documented in ``docs/knowledge-model.md``.  It is validated on load; every
error names the file and the line of the offending entry.
"""

from __future__ import annotations

import math
import os
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from types import MappingProxyType
from typing import Any

import yaml

from relevance_plan.data import DOMAINS_DIR as REPOSITORY_DOMAINS
from relevance_plan.errors import ModelError, UsageError
from relevance_plan.relevance.scene import PLACEMENT_CONDITIONS, ScenePredicates

SCHEMA_VERSION = 1


class _LineDict(dict):
    """A dict that remembers the line of each key (1-based)."""

    lines: dict
    line: int


# A model is a few levels deep; far deeper nesting is an attack on the
# recursive YAML composer, not knowledge.
MAX_YAML_NESTING = 32


class _Loader(yaml.SafeLoader):
    """SafeLoader without aliases and with a nesting limit.

    An alias (``*name``) lets a 1.5 KB file expand into gigabytes (the
    "billion laughs"); a model never needs one, so any alias is refused.
    """

    _depth = 0

    def compose_node(self, parent, index):
        if self.check_event(yaml.AliasEvent):
            event = self.peek_event()
            raise ModelError(
                "YAML aliases ('*name') are not allowed in a knowledge model", line=event.start_mark.line + 1
            )
        self._depth += 1
        try:
            if self._depth > MAX_YAML_NESTING:
                mark = self.peek_event().start_mark
                raise ModelError(f"YAML nested more than {MAX_YAML_NESTING} levels deep", line=mark.line + 1)
            return super().compose_node(parent, index)
        finally:
            self._depth -= 1


def _construct_mapping(loader: _Loader, node: yaml.MappingNode) -> _LineDict:
    mapping = _LineDict()
    mapping.lines = {}
    mapping.line = node.start_mark.line + 1
    for key_node, value_node in node.value:
        key = loader.construct_object(key_node, deep=True)
        if not isinstance(key, (str, int, float, bool)) or key is None:
            raise ModelError("mapping keys must be plain names", line=key_node.start_mark.line + 1)
        key = str(key)
        if key in mapping:
            raise ModelError(f"duplicate key '{key}'", line=key_node.start_mark.line + 1)
        mapping[key] = loader.construct_object(value_node, deep=True)
        mapping.lines[key] = key_node.start_mark.line + 1
    return mapping


_Loader.add_constructor(yaml.resolver.BaseResolver.DEFAULT_MAPPING_TAG, _construct_mapping)


@dataclass(frozen=True)
class ModelClass:
    name: str
    types: tuple
    kinds: tuple
    kind_relevance: Mapping[str, float]
    default_kind_relevance: float
    fixed_relevance: float | None = None  # e.g. the human: always relevant
    from_contents: bool = False  # a place is as relevant as what it holds
    description: str = ""


@dataclass(frozen=True)
class Objective:
    name: str
    description: str
    goal_predicates: tuple
    tasks: Mapping[str, float]  # P(T | O)


@dataclass(frozen=True)
class Human:
    name: str
    description: str
    objective_tasks: Mapping[str, Mapping[str, float]]  # objective -> P(T | O)
    task_classes: Mapping[str, Mapping[str, float]]  # task -> class -> P(C | T, O)
    kind_relevance: Mapping[str, Mapping[str, float]]  # class -> kind -> P(h | C, O)


@dataclass(frozen=True)
class Dependency:
    predicate: str
    when_kept: int  # 0-based
    restore: int
    reason: str


@dataclass(frozen=True)
class KnowledgeModel:
    path: str
    domain: str
    description: str
    entropy_bound: float
    unknown_class_relevance: float
    scene: ScenePredicates
    objectives: Mapping[str, Objective]
    task_classes: Mapping[str, Mapping[str, float]]
    classes: Mapping[str, ModelClass]
    placement: Mapping[str, float]
    humans: Mapping[str, Human]
    dependencies: tuple = field(default=())

    def objective_for_goal(self, goal_predicates: set[str]) -> list[str]:
        """Objectives whose goal predicates all appear in the problem's goal."""
        return [
            name
            for name, objective in self.objectives.items()
            if objective.goal_predicates and set(objective.goal_predicates) <= goal_predicates
        ]


# --------------------------------------------------------------------------- validation helpers


class _Checker:
    def __init__(self, path: str):
        self.path = path

    def fail(self, message: str, mapping: Any = None, key: str | None = None):
        line = None
        if isinstance(mapping, _LineDict):
            line = mapping.lines.get(key, mapping.line) if key is not None else mapping.line
        raise ModelError(message, path=self.path, line=line)

    def mapping(self, parent: Any, key: str, required: bool = True) -> _LineDict:
        value = parent.get(key) if isinstance(parent, dict) else None
        if value is None:
            if required:
                self.fail(f"missing section '{key}'", parent)
            empty = _LineDict()
            empty.lines = {}
            empty.line = getattr(parent, "line", None)
            return empty
        if not isinstance(value, _LineDict):
            self.fail(f"'{key}' must be a mapping", parent, key)
        return value

    def probability(self, parent: _LineDict, key: str, what: str) -> float:
        value = parent[key]
        if isinstance(value, bool) or not isinstance(value, (int, float)) or math.isnan(value):
            self.fail(f"{what} must be a number in [0, 1], got {value!r}", parent, key)
        if not 0.0 <= float(value) <= 1.0:
            self.fail(f"{what} = {value} is outside [0, 1]", parent, key)
        return float(value)

    def probabilities(self, parent: _LineDict, what) -> Mapping[str, float]:
        """``what`` names the values: a label (the key is appended) or a function of the key."""
        label = what if callable(what) else (lambda key: f"{what} '{key}'")
        return MappingProxyType({key: self.probability(parent, key, label(key)) for key in parent})

    def names(self, parent: _LineDict, key: str) -> tuple:
        value = parent.get(key, [])
        if isinstance(value, str):
            value = [value]
        if not isinstance(value, list) or not all(isinstance(v, str) for v in value):
            self.fail(f"'{key}' must be a list of names", parent, key)
        return tuple(v.lower() for v in value)

    def known_keys(self, parent: _LineDict, allowed: set[str], where: str) -> None:
        for key in parent:
            if key not in allowed:
                self.fail(
                    f"unknown key '{key}' in {where} (expected one of: {', '.join(sorted(allowed))})", parent, key
                )


def parse_model(text: str, path: str = "<model>") -> KnowledgeModel:
    """Validate and build a knowledge model from YAML text."""
    try:
        data = yaml.load(text, Loader=_Loader)  # noqa: S506 - a SafeLoader subclass
    except ModelError as error:
        raise ModelError(error.message, path=path, line=error.line) from None
    except yaml.YAMLError as error:
        mark = getattr(error, "problem_mark", None)
        problem = getattr(error, "problem", None) or str(error).splitlines()[0]
        raise ModelError(f"invalid YAML: {problem}", path=path, line=mark.line + 1 if mark else None) from None
    check = _Checker(path)
    if not isinstance(data, _LineDict):
        check.fail("the model must be a YAML mapping")
    check.known_keys(
        data,
        {
            "version",
            "domain",
            "description",
            "entropy_bound",
            "defaults",
            "scene",
            "objectives",
            "tasks",
            "classes",
            "placement",
            "humans",
            "dependencies",
        },
        "the model",
    )
    if data.get("version") != SCHEMA_VERSION:
        check.fail(f"'version' must be {SCHEMA_VERSION}", data, "version")
    domain = data.get("domain")
    if not isinstance(domain, str):
        check.fail("'domain' must name the PDDL domain the model is for", data, "domain")
    entropy_bound = data.get("entropy_bound", 1.0)
    if isinstance(entropy_bound, bool) or not isinstance(entropy_bound, (int, float)) or entropy_bound < 0:
        check.fail("'entropy_bound' must be a non-negative number (nats)", data, "entropy_bound")

    defaults = check.mapping(data, "defaults", required=False)
    check.known_keys(defaults, {"unknown_class_relevance", "kind_relevance"}, "'defaults'")
    unknown_relevance = (
        check.probability(defaults, "unknown_class_relevance", "defaults.unknown_class_relevance")
        if "unknown_class_relevance" in defaults
        else 0.05
    )
    default_kind = (
        check.probability(defaults, "kind_relevance", "defaults.kind_relevance")
        if "kind_relevance" in defaults
        else 0.5
    )

    scene_section = check.mapping(data, "scene", required=False)
    check.known_keys(scene_section, {"location", "support", "access", "human_location"}, "'scene'")
    scene = ScenePredicates(**{key: str(value).lower() for key, value in scene_section.items()})

    classes: dict[str, ModelClass] = {}
    class_section = check.mapping(data, "classes")
    for name, entry in class_section.items():
        if not isinstance(entry, _LineDict):
            check.fail(f"class '{name}' must be a mapping", class_section, name)
        check.known_keys(
            entry, {"description", "types", "kinds", "kind_relevance", "relevance", "relevance_from"}, f"class '{name}'"
        )
        kind_section = check.mapping(entry, "kind_relevance", required=False)
        kind_probs = dict(check.probabilities(kind_section, f"kind relevance of class '{name}'"))
        default_here = kind_probs.pop("default", default_kind)
        fixed = check.probability(entry, "relevance", f"relevance of class '{name}'") if "relevance" in entry else None
        relevance_from = entry.get("relevance_from")
        if relevance_from not in (None, "contents"):
            check.fail("'relevance_from' must be 'contents'", entry, "relevance_from")
        kinds = check.names(entry, "kinds") + tuple(k for k in kind_probs if k not in check.names(entry, "kinds"))
        types = check.names(entry, "types")
        if not kinds and not types:
            check.fail(
                f"class '{name}' needs 'types' or 'kinds' to say which objects belong to it", class_section, name
            )
        classes[name] = ModelClass(
            name=name,
            types=types,
            kinds=kinds,
            kind_relevance=MappingProxyType(kind_probs),
            default_kind_relevance=default_here,
            fixed_relevance=fixed,
            from_contents=relevance_from == "contents",
            description=str(entry.get("description", "")),
        )

    task_section = check.mapping(data, "tasks")
    task_classes: dict[str, Mapping[str, float]] = {}
    for task, entry in task_section.items():
        if not isinstance(entry, _LineDict):
            check.fail(f"task '{task}' must map classes to P(class | task, objective)", task_section, task)
        for class_name in entry:
            if class_name not in classes:
                check.fail(f"task '{task}' names unknown class '{class_name}'", entry, class_name)
        task_classes[task] = check.probabilities(entry, lambda class_name, task=task: f"P({class_name} | {task})")

    objectives: dict[str, Objective] = {}
    objective_section = check.mapping(data, "objectives")
    for name, entry in objective_section.items():
        if not isinstance(entry, _LineDict):
            check.fail(f"objective '{name}' must be a mapping", objective_section, name)
        check.known_keys(entry, {"description", "goal_predicates", "tasks"}, f"objective '{name}'")
        tasks = check.mapping(entry, "tasks")
        probabilities = check.probabilities(tasks, f"P(task | {name})")
        _check_distribution(check, tasks, probabilities, f"P(task | {name})")
        for task in probabilities:
            if task not in task_classes:
                check.fail(f"objective '{name}' names task '{task}' that has no entry under 'tasks'", tasks, task)
        objectives[name] = Objective(
            name=name,
            description=str(entry.get("description", "")),
            goal_predicates=check.names(entry, "goal_predicates"),
            tasks=probabilities,
        )

    placement_section = check.mapping(data, "placement", required=False)
    for condition in placement_section:
        if condition not in PLACEMENT_CONDITIONS:
            check.fail(
                f"unknown placement condition '{condition}' (expected one of: {', '.join(PLACEMENT_CONDITIONS)})",
                placement_section,
                condition,
            )
    placement = check.probabilities(placement_section, "placement factor")

    humans: dict[str, Human] = {}
    human_section = check.mapping(data, "humans", required=False)
    for name, entry in human_section.items():
        if not isinstance(entry, _LineDict):
            check.fail(f"human '{name}' must be a mapping", human_section, name)
        check.known_keys(entry, {"description", "objectives", "tasks", "kind_relevance"}, f"human '{name}'")
        objective_tasks = {}
        for objective, tasks in check.mapping(entry, "objectives", required=False).items():
            if objective not in objectives:
                check.fail(f"human '{name}' names unknown objective '{objective}'", entry, "objectives")
            if not isinstance(tasks, _LineDict):
                check.fail(
                    f"human '{name}': objective '{objective}' must map tasks to probabilities", entry, "objectives"
                )
            probabilities = check.probabilities(tasks, f"{name}: P(task | {objective})")
            _check_distribution(check, tasks, probabilities, f"{name}: P(task | {objective})")
            for task in probabilities:
                if task not in task_classes:
                    check.fail(f"human '{name}' names task '{task}' that has no entry under 'tasks'", tasks, task)
            objective_tasks[objective] = probabilities
        preferences = {}
        for task, entry_classes in check.mapping(entry, "tasks", required=False).items():
            if not isinstance(entry_classes, _LineDict):
                check.fail(f"human '{name}': task '{task}' must map classes to probabilities", entry, "tasks")
            for class_name in entry_classes:
                if class_name not in classes:
                    check.fail(f"human '{name}' names unknown class '{class_name}'", entry_classes, class_name)
            preferences[task] = check.probabilities(entry_classes, f"{name}: P(class | {task})")
        kinds = {}
        for class_name, entry_kinds in check.mapping(entry, "kind_relevance", required=False).items():
            if class_name not in classes:
                check.fail(f"human '{name}' names unknown class '{class_name}'", entry, "kind_relevance")
            if not isinstance(entry_kinds, _LineDict):
                check.fail(
                    f"human '{name}': kind relevance of '{class_name}' must be a mapping", entry, "kind_relevance"
                )
            kinds[class_name] = check.probabilities(entry_kinds, f"{name}: P(kind | {class_name})")
        humans[name] = Human(
            name=name,
            description=str(entry.get("description", "")),
            objective_tasks=MappingProxyType(objective_tasks),
            task_classes=MappingProxyType(preferences),
            kind_relevance=MappingProxyType(kinds),
        )

    dependencies = []
    dependency_list = data.get("dependencies", [])
    if not isinstance(dependency_list, list):
        check.fail("'dependencies' must be a list", data, "dependencies")
    for entry in dependency_list:
        if not isinstance(entry, _LineDict):
            check.fail("each dependency must be a mapping", data, "dependencies")
        check.known_keys(entry, {"predicate", "when_kept", "restore", "reason"}, "a dependency")
        for key in ("predicate", "when_kept", "restore"):
            if key not in entry:
                check.fail(f"dependency needs '{key}'", entry)
        for key in ("when_kept", "restore"):
            if isinstance(entry[key], bool) or not isinstance(entry[key], int) or entry[key] < 1:
                check.fail(f"'{key}' is a 1-based argument position", entry, key)
        dependencies.append(
            Dependency(
                str(entry["predicate"]).lower(),
                entry["when_kept"] - 1,
                entry["restore"] - 1,
                str(entry.get("reason", "")),
            )
        )

    return KnowledgeModel(
        path=path,
        domain=domain.lower(),
        description=str(data.get("description", "")),
        entropy_bound=float(entropy_bound),
        unknown_class_relevance=unknown_relevance,
        scene=scene,
        objectives=MappingProxyType(objectives),
        task_classes=MappingProxyType(task_classes),
        classes=MappingProxyType(classes),
        placement=placement,
        humans=MappingProxyType(humans),
        dependencies=tuple(dependencies),
    )


def _check_distribution(check: _Checker, section: _LineDict, probabilities: Mapping[str, float], what: str) -> None:
    if not probabilities:
        check.fail(f"{what} is empty", section)
    total = sum(probabilities.values())
    if abs(total - 1.0) > 0.01:
        check.fail(f"{what} sums to {total:.3f}, not 1", section)


def load_model(path: str | os.PathLike) -> KnowledgeModel:
    from relevance_plan.io import read_text

    return parse_model(read_text(path, "knowledge model"), str(path))


def find_model(domain_name: str, domain_path: str | None) -> Path | None:
    """The model next to the domain file, else ``domains/<domain name>/relevance.yaml``."""
    candidates = []
    if domain_path:
        candidates.append(Path(domain_path).resolve().parent / "relevance.yaml")
    candidates.append(REPOSITORY_DOMAINS / domain_name / "relevance.yaml")
    for candidate in candidates:
        if candidate.is_file():
            return candidate
    return None


def check_model_applies(model: KnowledgeModel, domain_name: str) -> None:
    if model.domain != domain_name:
        raise ModelError(f"model is for domain '{model.domain}', not '{domain_name}'", path=model.path)


def check_threshold(value: float, name: str) -> float:
    if not 0.0 <= value <= 1.0:
        raise UsageError(f"{name} must be in [0, 1], got {value}")
    return value
