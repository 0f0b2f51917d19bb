"""The knowledge model: the offline stand-in for the paper's GPT-4o answers.

One YAML file per domain (``domains/<name>/relevance.yaml``), schema version 1,
documented in ``docs/knowledge-model.md``.  It is validated on load; every
error names the file and the line of the offending entry.
"""

from __future__ import annotations

import functools
import math
import os
from collections.abc import Callable, Collection, Iterator, Mapping
from dataclasses import dataclass, field, replace
from pathlib import Path
from types import MappingProxyType
from typing import TYPE_CHECKING, Any, NoReturn

from relevance_plan.data import DOMAINS_DIR as REPOSITORY_DOMAINS
from relevance_plan.errors import ModelError, UsageError, printable
from relevance_plan.pddl.model import Domain
from relevance_plan.relevance.scoring.scene import PLACEMENT_CONDITIONS, SCENE_ROLES, ScenePredicates

if TYPE_CHECKING:  # for the annotations only: yaml itself is imported on first use (_yaml_loader)
    import yaml

SCHEMA_VERSION = 1


class _LineDict(dict[str, Any]):
    """A dict that remembers the line of each key (1-based)."""

    lines: dict[str, int]
    line: int


# A model is a few levels deep; far deeper nesting is an attack on the
# recursive YAML composer, not knowledge.
MAX_YAML_NESTING = 32


@functools.cache
def _yaml_loader() -> type[yaml.SafeLoader]:
    """The loader of knowledge models, made on first use: commands which read no model
    (``plan --method pure``) do not pay for importing yaml."""
    import yaml

    class _Loader(yaml.SafeLoader):
        """SafeLoader without aliases and with a nesting limit.

        An alias (``*name``) lets a 1.5 KB file expand into gigabytes (the
        "billion laughs"); a model never needs one, so any alias is refused.
        """

        _depth = 0

        def construct_object(self, node: yaml.Node, deep: bool = False) -> Any:
            """A value Python refuses to convert (an integer of thousands of digits) names its line."""
            try:
                return super().construct_object(node, deep=deep)
            except (ValueError, OverflowError) as error:
                raise ModelError(
                    f"invalid YAML value: {str(error).splitlines()[0]}", line=node.start_mark.line + 1
                ) from None

        def compose_node(self, parent: yaml.Node | None, index: int) -> yaml.Node | None:
            if self.check_event(yaml.AliasEvent):
                event = self.peek_event()  # type: ignore[no-untyped-call]
                raise ModelError(
                    "YAML aliases ('*name') are not allowed in a knowledge model", line=event.start_mark.line + 1
                )
            self._depth += 1
            try:
                if self._depth > MAX_YAML_NESTING:
                    mark = self.peek_event().start_mark  # type: ignore[no-untyped-call]
                    raise ModelError(f"YAML nested more than {MAX_YAML_NESTING} levels deep", line=mark.line + 1)
                return super().compose_node(parent, index)
            finally:
                self._depth -= 1

    _Loader.add_constructor(yaml.resolver.BaseResolver.DEFAULT_MAPPING_TAG, _construct_mapping)
    return _Loader


def _construct_mapping(loader: yaml.SafeLoader, node: yaml.MappingNode) -> _LineDict:
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


@dataclass(frozen=True)
class ModelClass:
    name: str
    types: tuple[str, ...]
    kinds: tuple[str, ...]
    kind_relevance: Mapping[str, float]
    default_kind_relevance: float
    fixed_relevance: float | None = None  # e.g. the human: always relevant
    from_contents: bool = False  # a place is as relevant as what it holds
    description: str = ""


@dataclass(frozen=True)
class Objective:
    name: str
    description: str
    goal_predicates: tuple[str, ...]
    activities: Mapping[str, float]  # P(T | O), T the activity (the paper's task)


@dataclass(frozen=True)
class Human:
    name: str
    description: str
    objective_activities: Mapping[str, Mapping[str, float]]  # objective -> P(T | O)
    activity_classes: Mapping[str, Mapping[str, float]]  # activity -> class -> P(C | T, O)
    kind_relevance: Mapping[str, Mapping[str, float]]  # class -> kind -> P(h | C, O)


@dataclass(frozen=True)
class ModelDependency:
    """Keeping the object at ``when_kept`` of a ``predicate`` fact keeps the one at ``restore`` (0-based)."""

    predicate: str
    when_kept: int
    restore: int
    reason: str
    line: int | None = None  # where the model declares it, for errors found against a domain


def _no_lines() -> Mapping[tuple[str, ...], int]:
    return MappingProxyType({})


@dataclass(frozen=True)
class KnowledgeModel:
    path: str
    domain: str
    description: str
    entropy_bound: float
    unknown_class_relevance: float
    scene: ScenePredicates
    objectives: Mapping[str, Objective]
    activity_classes: Mapping[str, Mapping[str, float]]
    classes: Mapping[str, ModelClass]
    placement: Mapping[str, float]
    humans: Mapping[str, Human]
    dependencies: tuple[ModelDependency, ...] = field(default=())
    # the first selection is checked for relaxed reachability and repaired, as the goal scorer's is
    reachability_check: bool = False
    # the line of each key, by its path (("scene", "containment")): checks against a domain name it
    lines: Mapping[tuple[str, ...], int] = field(default_factory=_no_lines, compare=False, repr=False)

    def line_of(self, *keys: str) -> int | None:
        """The line of the entry at ``keys`` (None for a model built in code, or an entry not written)."""
        return self.lines.get(keys)

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

    def fail(self, message: str, mapping: Any = None, key: str | None = None) -> NoReturn:
        """Refuse the model, naming the line of ``key`` in ``mapping`` (of ``mapping`` itself without a
        key; of the document, line 1, without either)."""
        line = 1
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
            empty.line = getattr(parent, "line", 0)
            return empty
        if not isinstance(value, _LineDict):
            self.fail(f"'{key}' must be a mapping", parent, key)
        return value

    def probability(self, parent: _LineDict, key: str, what: str) -> float:
        value = parent[key]
        if not _finite_number(value):
            self.fail(f"{what} must be a number in [0, 1], got {printable(repr(value), 60)}", parent, key)
        if not 0.0 <= float(value) <= 1.0:
            self.fail(f"{what} = {value} is outside [0, 1]", parent, key)
        return float(value)

    def probabilities(self, parent: _LineDict, what: str | Callable[[str], str]) -> Mapping[str, float]:
        """``what`` names the values: a label (the key is appended) or a function of the key."""
        label = what if callable(what) else (lambda key: f"{what} '{key}'")
        return MappingProxyType({key: self.probability(parent, key, label(key)) for key in parent})

    def names(self, parent: _LineDict, key: str) -> tuple[str, ...]:
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


def parse_knowledge_model(text: str, path: str = "<model>") -> KnowledgeModel:
    """Validate and build a knowledge model from YAML text."""
    data = _load_yaml(text, path)
    check = _Checker(path)
    if not isinstance(data, _LineDict):
        check.fail("the model must be a YAML mapping")
    _read_old_names(check, data)
    check.known_keys(data, _TOP_LEVEL_KEYS, "the model")
    if data.get("version") != SCHEMA_VERSION:
        check.fail(f"'version' must be {SCHEMA_VERSION}", data, "version")
    domain = data.get("domain")
    if not isinstance(domain, str):
        check.fail("'domain' must name the PDDL domain the model is for", data, "domain")
    entropy_bound = data.get("entropy_bound", 1.0)
    if not _finite_number(entropy_bound) or entropy_bound < 0:
        check.fail("'entropy_bound' must be a finite non-negative number (nats)", data, "entropy_bound")
    defaults = check.mapping(data, "defaults", required=False)
    check.known_keys(defaults, {"unknown_class_relevance", "kind_relevance"}, "'defaults'")
    unknown_relevance = _optional_probability(check, defaults, "unknown_class_relevance", 0.05)
    default_kind = _optional_probability(check, defaults, "kind_relevance", 0.5)
    classes = _read_classes(check, check.mapping(data, "classes"), default_kind)
    activity_classes = _read_activities(check, check.mapping(data, "activities"), classes)
    objectives = _read_objectives(check, check.mapping(data, "objectives"), activity_classes)
    return KnowledgeModel(
        path=path,
        domain=domain.lower(),
        description=str(data.get("description", "")),
        entropy_bound=float(entropy_bound),
        unknown_class_relevance=unknown_relevance,
        scene=_read_scene(check, check.mapping(data, "scene", required=False)),
        objectives=MappingProxyType(objectives),
        activity_classes=MappingProxyType(activity_classes),
        classes=MappingProxyType(classes),
        placement=_read_placement(check, check.mapping(data, "placement", required=False)),
        humans=MappingProxyType(
            _read_humans(check, check.mapping(data, "humans", required=False), classes, activity_classes, objectives)
        ),
        dependencies=_read_dependencies(check, data),
        reachability_check=_read_flag(check, data, "reachability_check"),
        lines=MappingProxyType(dict(_key_lines(data))),
    )


def _key_lines(mapping: _LineDict, above: tuple[str, ...] = ()) -> Iterator[tuple[tuple[str, ...], int]]:
    """(path of each key, its line), for every mapping of the model."""
    for key, value in mapping.items():
        yield (*above, key), mapping.lines[key]
        if isinstance(value, _LineDict):
            yield from _key_lines(value, (*above, key))


_TOP_LEVEL_KEYS = {
    "version",
    "domain",
    "description",
    "entropy_bound",
    "defaults",
    "scene",
    "objectives",
    "activities",
    "classes",
    "placement",
    "humans",
    "dependencies",
    "reachability_check",
}


# Keys by their names until 0.12, read for one more release: (the mappings they are in, old, new).
OLD_NAMES = (
    ("the model", "sufficiency_check", "reachability_check"),
    ("the model", "tasks", "activities"),
    ("objectives", "tasks", "activities"),
    ("humans", "tasks", "activities"),
)


def _read_old_names(check: _Checker, data: _LineDict) -> None:
    """Each key of ``OLD_NAMES`` moved to its new name, in place (the model as read, before any check);
    the two names given together fail."""
    for where, old, new in OLD_NAMES:
        section = data.get(where) if where != "the model" else None
        entries = [data] if where == "the model" else list(section.values()) if isinstance(section, dict) else []
        for entry in entries:
            if not isinstance(entry, _LineDict) or old not in entry:
                continue
            if new in entry:
                check.fail(f"give '{new}' only ('{old}' is its name until 0.12)", entry, old)
            entry.lines[new] = entry.lines[old]
            entry[new] = entry.pop(old)


def _read_flag(check: _Checker, data: _LineDict, key: str) -> bool:
    value = data.get(key, False)
    if not isinstance(value, bool):
        check.fail(f"'{key}' must be true or false", data, key)
    return value


def _finite_number(value: Any) -> bool:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return False
    try:
        return math.isfinite(value)
    except OverflowError:  # an integer too large for a float
        return False


def _load_yaml(text: str, path: str) -> Any:
    import yaml

    try:
        return yaml.load(text, Loader=_yaml_loader())  # noqa: S506 - a SafeLoader subclass
    except ModelError as error:
        raise ModelError(error.message, path=path, line=error.line) from None
    except yaml.YAMLError as error:
        mark = getattr(error, "problem_mark", None)
        problem = getattr(error, "problem", None) or str(error).splitlines()[0]
        raise ModelError(f"invalid YAML: {problem}", path=path, line=mark.line + 1 if mark else None) from None
    except (ValueError, OverflowError) as error:
        # e.g. an integer of thousands of digits: Python refuses to convert it
        raise ModelError(f"invalid YAML value: {str(error).splitlines()[0]}", path=path) from None


def _optional_probability(check: _Checker, section: _LineDict, key: str, default: float) -> float:
    return check.probability(section, key, f"defaults.{key}") if key in section else default


def _read_scene(check: _Checker, section: _LineDict) -> ScenePredicates:
    check.known_keys(section, set(SCENE_ROLES), "'scene'")
    roles: dict[str, str | None] = {}
    for key, value in section.items():
        if value is None or (isinstance(value, str) and value.strip().lower() == NO_PREDICATE):
            roles[key] = None
            continue
        if not isinstance(value, str) or not value.strip() or any(c.isspace() or c in "()" for c in value):
            check.fail(f"scene.{key} must be one predicate name or '{NO_PREDICATE}', got {value!r}", section, key)
        roles[key] = value.lower()
    return ScenePredicates(**roles, written=frozenset(section))


# What the scene section writes for a role the domain has no predicate for.
NO_PREDICATE = "none"
# The arity each scene role's predicate must have.
SCENE_ARITY = {"location": 2, "containment": 2, "support": 2, "human_location": 2, "access": 1, "closed": 1}


def _read_classes(check: _Checker, section: _LineDict, default_kind: float) -> dict[str, ModelClass]:
    classes: dict[str, ModelClass] = {}
    for name, entry in section.items():
        if not isinstance(entry, _LineDict):
            check.fail(f"class '{name}' must be a mapping", section, name)
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
        listed = check.names(entry, "kinds")
        kinds = listed + tuple(k for k in kind_probs if k not in listed)
        types = check.names(entry, "types")
        if not kinds and not types:
            check.fail(f"class '{name}' needs 'types' or 'kinds' to say which objects belong to it", section, name)
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
    return classes


def _read_activities(
    check: _Checker, section: _LineDict, classes: Mapping[str, ModelClass]
) -> dict[str, Mapping[str, float]]:
    activity_classes: dict[str, Mapping[str, float]] = {}
    for activity, entry in section.items():
        if not isinstance(entry, _LineDict):
            check.fail(f"activity '{activity}' must map classes to P(class | activity, objective)", section, activity)
        for class_name in entry:
            if class_name not in classes:
                check.fail(f"activity '{activity}' names unknown class '{class_name}'", entry, class_name)
        activity_classes[activity] = check.probabilities(entry, functools.partial(_given, activity=activity))
    return activity_classes


def _given(class_name: str, activity: str) -> str:
    return f"P({class_name} | {activity})"


def _read_objectives(check: _Checker, section: _LineDict, activity_classes: Mapping[str, Any]) -> dict[str, Objective]:
    objectives: dict[str, Objective] = {}
    for name, entry in section.items():
        if not isinstance(entry, _LineDict):
            check.fail(f"objective '{name}' must be a mapping", section, name)
        check.known_keys(entry, {"description", "goal_predicates", "activities"}, f"objective '{name}'")
        activities = check.mapping(entry, "activities")
        probabilities = _activity_distribution(
            check, activities, f"P(activity | {name})", f"objective '{name}'", activity_classes
        )
        objectives[name] = Objective(
            name=name,
            description=str(entry.get("description", "")),
            goal_predicates=check.names(entry, "goal_predicates"),
            activities=probabilities,
        )
    return objectives


def _activity_distribution(
    check: _Checker, table: _LineDict, what: str, whose: str, activity_classes: Mapping[str, Any]
) -> Mapping[str, float]:
    """``table`` as P(activity | objective) (``what``, of ``whose`` entry): probabilities summing to 1, over
    activities the model has."""
    probabilities = check.probabilities(table, what)
    _check_distribution(check, table, probabilities, what)
    for activity in probabilities:
        if activity not in activity_classes:
            check.fail(f"{whose} names activity '{activity}' that has no entry under 'activities'", table, activity)
    return probabilities


def _read_placement(check: _Checker, section: _LineDict) -> Mapping[str, float]:
    for condition in section:
        if condition not in PLACEMENT_CONDITIONS:
            check.fail(
                f"unknown placement condition '{condition}' (expected one of: {', '.join(PLACEMENT_CONDITIONS)})",
                section,
                condition,
            )
    return check.probabilities(section, "placement factor")


def _read_humans(
    check: _Checker,
    section: _LineDict,
    classes: Mapping[str, Any],
    activity_classes: Mapping[str, Any],
    objectives: Mapping[str, Any],
) -> dict[str, Human]:
    humans: dict[str, Human] = {}
    for name, entry in section.items():
        if not isinstance(entry, _LineDict):
            check.fail(f"human '{name}' must be a mapping", section, name)
        check.known_keys(entry, {"description", "objectives", "activities", "kind_relevance"}, f"human '{name}'")
        humans[name] = Human(
            name=name,
            description=str(entry.get("description", "")),
            objective_activities=MappingProxyType(_human_objectives(check, name, entry, activity_classes, objectives)),
            activity_classes=MappingProxyType(_human_activities(check, name, entry, classes)),
            kind_relevance=MappingProxyType(_human_kinds(check, name, entry, classes)),
        )
    return humans


def _human_tables(
    check: _Checker,
    name: str,
    entry: _LineDict,
    section: str,
    known: tuple[str, Collection[str]] | None,
    not_a_table: str,
) -> Iterator[tuple[str, _LineDict]]:
    """(key, table) of each entry of the human's ``section``, in order; a key not among ``known``
    (what they are, and their names) or a value that is not a table fails (``not_a_table`` says
    what it must be, ``{}`` standing for the key)."""
    for key, table in check.mapping(entry, section, required=False).items():
        if known is not None and key not in known[1]:
            check.fail(f"human '{name}' names unknown {known[0]} '{key}'", entry, section)
        if not isinstance(table, _LineDict):
            check.fail(f"human '{name}': {not_a_table.format(key)}", entry, section)
        yield key, table


def _human_objectives(
    check: _Checker, name: str, entry: _LineDict, activity_classes: Mapping[str, Any], objectives: Mapping[str, Any]
) -> dict[str, Mapping[str, float]]:
    found = {}
    for objective, activities in _human_tables(
        check,
        name,
        entry,
        "objectives",
        ("objective", objectives),
        "objective '{}' must map activities to probabilities",
    ):
        probabilities = _activity_distribution(
            check, activities, f"{name}: P(activity | {objective})", f"human '{name}'", activity_classes
        )
        found[objective] = probabilities
    return found


def _human_activities(
    check: _Checker, name: str, entry: _LineDict, classes: Mapping[str, Any]
) -> dict[str, Mapping[str, float]]:
    found = {}
    for activity, entry_classes in _human_tables(
        check, name, entry, "activities", None, "activity '{}' must map classes to probabilities"
    ):
        for class_name in entry_classes:
            if class_name not in classes:
                check.fail(f"human '{name}' names unknown class '{class_name}'", entry_classes, class_name)
        found[activity] = check.probabilities(entry_classes, f"{name}: P(class | {activity})")
    return found


def _human_kinds(
    check: _Checker, name: str, entry: _LineDict, classes: Mapping[str, Any]
) -> dict[str, Mapping[str, float]]:
    tables = _human_tables(
        check, name, entry, "kind_relevance", ("class", classes), "kind relevance of '{}' must be a mapping"
    )
    return {class_name: check.probabilities(kinds, f"{name}: P(kind | {class_name})") for class_name, kinds in tables}


# A dependency's argument position: PDDL predicates with more arguments than this do not exist.
MAX_POSITION = 64


def _read_dependencies(check: _Checker, data: _LineDict) -> tuple[ModelDependency, ...]:
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
        predicate = entry["predicate"]
        if not isinstance(predicate, str) or not predicate.strip() or any(c.isspace() for c in predicate):
            check.fail(f"a dependency's 'predicate' must be one predicate name, got {predicate!r}", entry, "predicate")
        for key in ("when_kept", "restore"):
            value = entry[key]
            if isinstance(value, bool) or not isinstance(value, int) or not 1 <= value <= MAX_POSITION:
                check.fail(f"'{key}' is a 1-based argument position (1 to {MAX_POSITION})", entry, key)
        dependencies.append(
            ModelDependency(
                predicate.lower(),
                entry["when_kept"] - 1,
                entry["restore"] - 1,
                str(entry.get("reason", "")),
                line=entry.line,
            )
        )
    return tuple(dependencies)


def _check_distribution(check: _Checker, section: _LineDict, probabilities: Mapping[str, float], what: str) -> None:
    if not probabilities:
        check.fail(f"{what} is empty", section)
    total = sum(probabilities.values())
    if abs(total - 1.0) > 0.01:
        check.fail(f"{what} sums to {total:.3f}, not 1", section)


def load_knowledge_model(path: str | os.PathLike[str]) -> KnowledgeModel:
    from relevance_plan.io import read_text

    return parse_knowledge_model(read_text(path, "knowledge model"), str(path))


def shipped_knowledge_models() -> dict[str, Path]:
    """Domain name -> the knowledge model shipped for it (``data/domains/<world>/relevance.yaml``)."""
    return {
        folder.name: folder / "relevance.yaml"
        for folder in sorted(REPOSITORY_DOMAINS.iterdir())
        if (folder / "relevance.yaml").is_file()
    }


def find_knowledge_model(domain_name: str, domain_path: str | None) -> Path | None:
    """The model next to the domain file, else the one shipped for a domain of that name.

    The name is only ever a key of :func:`shipped_knowledge_models`, never part of a path:
    a domain called ``../..`` finds nothing.
    """
    if domain_path:
        beside = Path(domain_path).resolve().parent / "relevance.yaml"
        if beside.is_file():
            return beside
    return shipped_knowledge_models().get(domain_name)


def check_knowledge_model_applies(knowledge_model: KnowledgeModel, domain: Domain) -> KnowledgeModel:
    """Refuse a model for another domain, or one whose scene predicates or dependencies the domain
    lacks; returns the model with the scene roles it left to their defaults and the domain lacks as none."""
    if knowledge_model.domain != domain.name:
        raise ModelError(
            f"model is for domain '{knowledge_model.domain}', not '{domain.name}'",
            path=knowledge_model.path,
            line=knowledge_model.line_of("domain"),
        )
    scene = knowledge_model.scene.for_domain(domain)
    for role, predicate in scene.roles().items():
        if predicate is None:
            continue
        params = domain.predicates.get(predicate)
        if params is None:
            if role == "human_location":
                continue  # humans may come later (a live session adds them)
            raise ModelError(
                f"scene.{role} '{predicate}' is not a predicate of domain '{domain.name}'"
                f" (write '{role}: {NO_PREDICATE}' if the domain has none)",
                path=knowledge_model.path,
                line=knowledge_model.line_of("scene", role),
            )
        if len(params) != SCENE_ARITY[role]:
            raise ModelError(
                f"scene.{role} '{predicate}' takes {len(params)} argument(s), but a {role} predicate"
                f" takes {SCENE_ARITY[role]}",
                path=knowledge_model.path,
                line=knowledge_model.line_of("scene", role),
            )
    for dependency in knowledge_model.dependencies:
        params = domain.predicates.get(dependency.predicate)
        if params is None:
            raise ModelError(
                f"dependency on '{dependency.predicate}', which is not a predicate of domain '{domain.name}'",
                path=knowledge_model.path,
                line=dependency.line,
            )
        for position in (dependency.when_kept, dependency.restore):
            if position >= len(params):
                raise ModelError(
                    f"dependency on '{dependency.predicate}': position {position + 1} is beyond its"
                    f" {len(params)} argument(s)",
                    path=knowledge_model.path,
                    line=dependency.line,
                )
    return replace(knowledge_model, scene=scene) if scene != knowledge_model.scene else knowledge_model


def check_threshold(value: float, name: str) -> float:
    if not 0.0 <= value <= 1.0:
        raise UsageError(f"{name} must be in [0, 1], got {value}")
    return value
