"""Goals a person gives for an imported scene: atoms over its names, or words resolved to class goals.

``(on lamp_o11 table_o24)`` is read as PDDL over the imported objects.  Words
("bring a cup to the kitchen", "put something to drink on the table") are
split at their last relation word (on, onto, in, into, inside, to, at) into
what is moved and where; each part is matched to the vocabulary's classes
(spelled, else the text model's nearest, with its similarity), and the pair
becomes a class goal met through any object of the class (the witnesses of
``relevance.analysis.witnesses``): ``(class-in-room cup kitchen)`` for a room,
``(class-on bottle table)`` for a surface, ``(class-inside k l)`` for a
container.  Below the floor, or for a class the scene does not have, the
goal is a question.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Any

from relevance_plan.errors import MissingExtraError, printable
from relevance_plan.scene_graphs.classes import GraphClass, Kind, LabelVocabulary, nearest, plain, spelled
from relevance_plan.scene_graphs.naming import pddl_word
from relevance_plan.scene_graphs.problem import ImportedScene

# Sentences score lower against single words than a kind does (relevance.scoring.word_matching.DEFAULT_RULES).
GOAL_FLOOR = 0.45
_RELATION = re.compile(r"\s(onto|on top of|on|into|inside|in|to|at)\s")
_VERBS = ("please", "bring", "put", "place", "take", "move", "carry", "get", "fetch", "set", "leave", "drop")
_ARTICLES = ("the", "a", "an", "some", "any", "my")
GOAL_PREDICATES = {Kind.ROOM: "class-in-room", Kind.SURFACE: "class-on", Kind.CONTAINER: "class-inside"}


@dataclass(frozen=True)
class PartMatch:
    phrase: str
    chosen: str | None
    similarity: float
    candidates: tuple[tuple[str, float], ...]
    problem: str = ""  # why it is a question

    def as_json(self) -> dict[str, Any]:
        return {
            "phrase": self.phrase,
            "class": self.chosen,
            "similarity": round(self.similarity, 4),
            "candidates": [{"class": c, "similarity": round(s, 4)} for c, s in self.candidates],
        }


@dataclass(frozen=True)
class GoalResolution:
    """One goal as given and what it became: ``atom``, or None with ``question``."""

    text: str
    atom: tuple[str, ...] | None
    parts: tuple[PartMatch, ...] = ()
    question: str = ""

    def as_json(self) -> dict[str, Any]:
        return {
            "text": self.text,
            "atom": f"({' '.join(self.atom)})" if self.atom else None,
            "parts": [part.as_json() for part in self.parts],
            "question": self.question or None,
        }


def is_atoms(text: str) -> bool:
    return text.lstrip().startswith("(")


def split_words(text: str) -> tuple[str, str, str] | None:
    """(what is moved, the relation word, where), or None when the words name no place to put it."""
    said = " " + " ".join(re.sub(r"[^\w\s-]", " ", text.lower()).split()) + " "
    found = list(_RELATION.finditer(said))
    if not found:
        return None
    last = found[-1]
    what, where = said[: last.start()].split(), said[last.end() :].split()
    while what and what[0] in _VERBS:
        what = what[1:]
    while where and where[0] in _ARTICLES:
        where = where[1:]
    if not what or not where:
        return None
    return " ".join(what), last.group(1), " ".join(where)


def _bare(phrase: str) -> str:
    words = phrase.split()
    while words and words[0] in _ARTICLES:
        words = words[1:]
    return " ".join(words)


def _match(phrase: str, classes: dict[str, GraphClass], present: set[str], floor: float) -> PartMatch:
    """A class the phrase spells must be in the scene; a description is matched among the scene's classes."""
    bare = _bare(phrase)
    found = spelled(bare, classes) or (spelled(bare[:-1], classes) if bare.endswith("s") else None)
    if found is not None:
        if pddl_word(found) not in present:
            there = ", ".join(sorted(present)) or "none"
            return PartMatch(phrase, None, 1.0, ((found, 1.0),), f"the scene has no {found} (it has: {there})")
        return PartMatch(phrase, found, 1.0, ((found, 1.0),))
    here = {name: c for name, c in classes.items() if pddl_word(name) in present}
    try:
        candidates = nearest([phrase], here)[0]
    except MissingExtraError as error:
        raise MissingExtraError(f"a goal in words ('{printable(phrase, 60)}'): {error.message}") from None
    best, similarity = candidates[0] if candidates else (None, 0.0)
    if best is None or similarity < floor:
        shown = ", ".join(f"{c} {s:.2f}" for c, s in candidates) or "none"
        problem = f"'{phrase}' is like nothing the scene has (nearest: {shown}; floor {floor:.2f})"
        return PartMatch(phrase, None, similarity, candidates, problem)
    return PartMatch(phrase, best, similarity, candidates)


def resolve_words(
    text: str, scene: ImportedScene, vocabulary: LabelVocabulary, floor: float = GOAL_FLOOR
) -> GoalResolution:
    """A goal in words as a class goal over the scene's classes, or a question."""
    parts = split_words(text)
    if parts is None:
        return GoalResolution(
            text, None, question=f"'{printable(text, 80)}' says what to move but not where (on, in, to ...): where to?"
        )
    what, relation, where = parts
    present_items = {k for k, kind in scene.kinds.items() if kind is Kind.ITEM}
    items = {name: c for name, c in vocabulary.things.items() if c.kind is Kind.ITEM}
    moved = _match(what, items, present_items, floor)
    targets: dict[str, GraphClass] = {
        name: c for name, c in vocabulary.things.items() if c.kind in (Kind.SURFACE, Kind.CONTAINER)
    }
    if relation not in ("on", "onto", "on top of"):
        targets.update(vocabulary.rooms)
    present_targets = {k for k, kind in scene.kinds.items() if kind in GOAL_PREDICATES}
    target = _match(where, targets, present_targets, floor)
    if moved.chosen is None or target.chosen is None:
        return GoalResolution(text, None, (moved, target), "; ".join(p.problem for p in (moved, target) if p.problem))
    kind = scene.kinds[pddl_word(target.chosen)]
    atom = (GOAL_PREDICATES[kind], pddl_word(moved.chosen), pddl_word(target.chosen))
    return GoalResolution(text, atom, (moved, target))


def goal_atoms_text(resolutions: list[GoalResolution], atoms: list[str]) -> str:
    """The goal's conjunction body: the resolved class goals and the atoms given as PDDL."""
    parts = [f"({' '.join(r.atom)})" for r in resolutions if r.atom is not None]
    return " ".join(parts + [a.strip() for a in atoms])


def words_of(plain_text: str) -> str:
    return plain(plain_text)
