"""What each semantic label of a scene graph is: a class of the shipped vocabulary, and what it affords.

A label's name comes from the user's mapping (``--labels FILE``: YAML,
label -> name, under ``objects:`` and ``rooms:``), else from the graph's own
label space (spark-dsg's ``Labelspace`` in the graph's metadata).  A name
that is a class of the vocabulary, or one of its words, is that class.  Any
other name is placed by the text model (the ``text`` extra) under its
nearest class, with the similarity reported; below the floor, a file's
coarser name (Matterport3D's mpcat40 category) is tried as a name; failing
that, the label is a question: the import stops (insufficient cues) and
asks for the label in the mapping.  A label is never left out unsaid.
"""

from __future__ import annotations

import functools
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from enum import Enum
from pathlib import Path
from types import MappingProxyType
from typing import Any

from relevance_plan.data import DATA_DIR
from relevance_plan.errors import MissingExtraError, ModelError, printable

VOCABULARY_FILE = DATA_DIR / "scene_graphs" / "classes.yaml"
# A name is placed under the nearest class only this similar or more (the kinds' floor of free text,
# relevance.scoring.word_matching.DEFAULT_RULES; tests/test_scene_graphs.py checks it on names of both data sets).
DEFAULT_FLOOR = 0.55
SHOWN = 3
GENERIC_ROOM = "unknown_room"


class Kind(str, Enum):
    ITEM = "item"
    SURFACE = "surface"
    CONTAINER = "container"
    FIXTURE = "fixture"
    ROOM = "room"


@dataclass(frozen=True)
class GraphClass:
    name: str
    kind: Kind
    openable: bool = False
    words: tuple[str, ...] = ()


@dataclass(frozen=True)
class LabelVocabulary:
    things: Mapping[str, GraphClass]
    rooms: Mapping[str, GraphClass]

    def of(self, kind: str) -> Mapping[str, GraphClass]:
        return self.rooms if kind == "rooms" else self.things


def plain(text: str) -> str:
    return " ".join(text.replace("_", " ").replace("-", " ").replace("#", " ").split()).lower()


def _read_classes(entries: Any, rooms: bool, path: str) -> dict[str, GraphClass]:
    if not isinstance(entries, dict):
        raise ModelError("'things' and 'rooms' must each map class names to their entries", path=path)
    found = {}
    for name, entry in entries.items():
        entry = entry or {}
        if not isinstance(entry, dict) or not isinstance(entry.get("words", []), list):
            raise ModelError(f"class '{name}': an entry with 'kind' and a list of 'words'", path=path)
        kind = Kind.ROOM if rooms else Kind(entry.get("kind", "fixture"))
        words = tuple(plain(str(word)) for word in entry.get("words", []))
        found[str(name)] = GraphClass(str(name), kind, bool(entry.get("openable", False)), words)
    return found


@functools.lru_cache(maxsize=4)
def load_vocabulary(path: Path = VOCABULARY_FILE) -> LabelVocabulary:
    """The classes a label can be (``data/scene_graphs/classes.yaml`` unless told otherwise)."""
    import yaml

    from relevance_plan.io import read_text

    data = yaml.safe_load(read_text(path, "class vocabulary"))
    if not isinstance(data, dict):
        raise ModelError("the class vocabulary must be a mapping with 'things' and 'rooms'", path=str(path))
    things = _read_classes(data.get("things", {}), False, str(path))
    rooms = _read_classes(data.get("rooms", {}), True, str(path))
    return LabelVocabulary(MappingProxyType(things), MappingProxyType(rooms))


# --------------------------------------------------------------------------- the user's mapping


@dataclass(frozen=True)
class LabelMapping:
    """The user's names of labels, per layer kind (``objects``, ``rooms``)."""

    path: str | None
    names: Mapping[str, Mapping[int, str]]


NO_MAPPING = LabelMapping(None, MappingProxyType({}))


def read_label_mapping(path: str) -> LabelMapping:
    """``--labels FILE``: ``objects: {5: chair, ...}`` and ``rooms: {0: kitchen}`` (a bare mapping is the
    objects')."""
    import yaml

    from relevance_plan.io import read_text

    try:
        data = yaml.safe_load(read_text(path, "label mapping"))
    except yaml.YAMLError as error:
        mark = getattr(error, "problem_mark", None)
        line = mark.line + 1 if mark is not None else None
        raise ModelError(
            f"the label mapping is not valid YAML: {getattr(error, 'problem', error)}", path=path, line=line
        ) from None
    if not isinstance(data, dict):
        raise ModelError("the label mapping must map labels to names (or hold 'objects:' and 'rooms:')", path=path)
    sections = data if set(data) <= {"objects", "rooms"} else {"objects": data}
    names: dict[str, Mapping[int, str]] = {}
    for section, entries in sections.items():
        if not isinstance(entries, dict):
            raise ModelError(f"'{section}' must map labels to names", path=path)
        found = {}
        for label, name in entries.items():
            if isinstance(label, bool) or not isinstance(label, int) or not isinstance(name, str) or not name.strip():
                raise ModelError(
                    f"'{section}': {printable(str(label), 40)} -> {printable(str(name), 40)}: a label is an integer,"
                    " its name a word",
                    path=path,
                )
            found[label] = name.strip()
        names[section] = MappingProxyType(found)
    return LabelMapping(path, MappingProxyType(names))


# --------------------------------------------------------------------------- placing names


@dataclass(frozen=True)
class Placement:
    """One label read as a class: how (``vocabulary``, ``text model``, ``coarse name``, ``unnamed``), with
    the similarity and the runners-up; ``chosen`` is None for a question."""

    layer: str  # objects, rooms
    label: int | None
    name: str | None
    chosen: str | None
    how: str
    similarity: float = 1.0
    candidates: tuple[tuple[str, float], ...] = ()

    @property
    def question(self) -> str:
        nearest = ", ".join(f"{c} {s:.2f}" for c, s in self.candidates) or "none"
        if self.name is None:
            return f"{self.layer} label {self.label} has no name: what is it? (name it in --labels)"
        return (
            f"{self.layer} label {self.label} '{printable(self.name, 60)}' is like no class (nearest: {nearest}):"
            " what is it? (name it in --labels)"
        )

    def as_json(self) -> dict[str, Any]:
        return {
            "layer": self.layer,
            "label": self.label,
            "name": self.name,
            "class": self.chosen,
            "how": self.how,
            "similarity": round(self.similarity, 4),
            "candidates": [{"class": c, "similarity": round(s, 4)} for c, s in self.candidates],
        }


def spelled(name: str, classes: Mapping[str, GraphClass]) -> str | None:
    """The class ``name`` spells (its name or one of its words), if any."""
    said = plain(name)
    for entry in classes.values():
        if said == plain(entry.name):
            return entry.name
    for entry in classes.values():
        if said in entry.words:
            return entry.name
    return None


def nearest(texts: Sequence[str], classes: Mapping[str, GraphClass]) -> list[tuple[tuple[str, float], ...]]:
    """For each text, the most similar classes, best first (the text model; ``MissingExtraError``
    without it)."""
    from relevance_plan.text import load_text_model

    if not texts or not classes:
        return [() for _ in texts]
    model = load_text_model()
    owners, table = _phrase_table(model, tuple((c.name, p) for c in classes.values() for p in _phrases(c)))
    found = []
    for similarities in model.embed([plain(t) for t in texts]) @ table.T:
        best: dict[str, float] = {}
        for owner, similarity in zip(owners, similarities.tolist()):
            best[owner] = max(best.get(owner, -1.0), float(similarity))
        found.append(tuple(sorted(best.items(), key=lambda item: (-item[1], item[0]))[:SHOWN]))
    return found


def _phrases(entry: GraphClass) -> tuple[str, ...]:
    return tuple(dict.fromkeys((plain(entry.name), *entry.words)))


def _phrase_table(model: Any, entries: tuple[tuple[str, str], ...]) -> tuple[tuple[str, ...], Any]:
    from relevance_plan.text.cache import cache_key, read_cached, write_cached

    phrases = [phrase for _, phrase in entries]
    key = cache_key(model.fingerprint, phrases)
    table = read_cached(key, len(phrases), model.width)
    if table is None:
        table = model.embed(phrases)
        write_cached(key, table)
    return tuple(owner for owner, _ in entries), table


@dataclass(frozen=True)
class LabelQuery:
    layer: str  # objects, rooms
    label: int | None
    name: str | None
    coarse: str | None = None


def place_labels(
    queries: Sequence[LabelQuery], vocabulary: LabelVocabulary, floor: float = DEFAULT_FLOOR
) -> tuple[Placement, ...]:
    """Each label as a class of the vocabulary, or a question (see the module docstring)."""
    placed: list[Placement | None] = []
    unplaced: list[int] = []
    for i, query in enumerate(queries):
        classes = vocabulary.of(query.layer)
        if query.name is None:
            generic = query.layer == "rooms"
            placed.append(Placement(query.layer, query.label, None, GENERIC_ROOM if generic else None, "unnamed"))
            continue
        found = spelled(query.name, classes)
        placed.append(Placement(query.layer, query.label, query.name, found, "vocabulary") if found else None)
        if found is None:
            unplaced.append(i)
    if unplaced:
        placed = _by_meaning(queries, unplaced, placed, vocabulary, floor)
    return tuple(p for p in placed if p is not None)


def _by_meaning(
    queries: Sequence[LabelQuery],
    unplaced: list[int],
    placed: list[Placement | None],
    vocabulary: LabelVocabulary,
    floor: float,
) -> list[Placement | None]:
    try:
        matches = {i: _nearest_one(queries[i], vocabulary) for i in unplaced}
    except MissingExtraError as error:
        if all(_coarse(queries[i], vocabulary) for i in unplaced):
            matches = {i: () for i in unplaced}
        else:
            names = ", ".join(f"'{printable(queries[i].name or '', 40)}'" for i in unplaced[:5])
            raise MissingExtraError(
                f"labels the class vocabulary does not list ({names}): name them in --labels, or {error.message}"
            ) from None
    for i in unplaced:
        query, candidates = queries[i], matches[i]
        if candidates and candidates[0][1] >= floor:
            placed[i] = Placement(
                query.layer, query.label, query.name, candidates[0][0], "text model", candidates[0][1], candidates
            )
        elif (coarse := _coarse(query, vocabulary)) is not None:
            placed[i] = Placement(
                query.layer, query.label, query.name, coarse, f"coarse name '{query.coarse}'", 1.0, candidates
            )
        else:
            placed[i] = Placement(
                query.layer,
                query.label,
                query.name,
                None,
                "question",
                candidates[0][1] if candidates else 0.0,
                candidates,
            )
    return placed


def _nearest_one(query: LabelQuery, vocabulary: LabelVocabulary) -> tuple[tuple[str, float], ...]:
    return nearest([query.name or ""], vocabulary.of(query.layer))[0]


def _coarse(query: LabelQuery, vocabulary: LabelVocabulary) -> str | None:
    return spelled(query.coarse, vocabulary.of(query.layer)) if query.coarse else None
