"""The scene: elements (objects) grouped into classes, with their attributes.

Top-level attributes say what an element is (its PDDL type and its kind, the
object name without a trailing index: ``whole_milk_2`` is a ``whole_milk``).
Low-level attributes say where it is, read from the initial state: its place,
whether that place is a closed container, what it stands on, what stands on it.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Mapping
from dataclasses import dataclass

from relevance_plan.pddl.formulas import GroundAtom
from relevance_plan.pddl.model import Domain
from relevance_plan.pddl.sexpr import check_deadline

_INDEX_SUFFIX = re.compile(r"[_\-]?\d+$")


def kind_of(name: str) -> str:
    """``whole_milk_2`` -> ``whole_milk``; ``cup1`` -> ``cup``; a name of digits stays itself."""
    stem = _INDEX_SUFFIX.sub("", name)
    return (stem or name).replace("-", "_")


@dataclass(frozen=True)
class ScenePredicates:
    """Which predicates carry placement; the knowledge model may rename them."""

    location: str = "at"
    support: str = "on"
    access: str = "accessible"
    human_location: str = "human-at"


@dataclass(frozen=True)
class Element:
    name: str
    type: str
    types: tuple[str, ...]  # the type and its ancestors, most specific first
    kind: str
    place: str | None
    stands_on: str | None
    covered: bool
    conditions: frozenset[str]  # placement conditions the knowledge model can weigh


@dataclass(frozen=True)
class Scene:
    elements: Mapping[str, Element]
    human_places: frozenset[str]


def build_scene(
    domain: Domain,
    objects: Mapping[str, str],
    facts: Iterable[GroundAtom],
    predicates: ScenePredicates = ScenePredicates(),
    deadline: float | None = None,
) -> Scene:
    """The elements among ``objects`` (name -> type), described by the true ``facts`` about them;
    past ``deadline`` (``time.monotonic()``), OutOfTimeError."""
    place_of: dict[str, str] = {}
    stands_on: dict[str, str] = {}
    covered: set[str] = set()
    accessible: set[str] = set()
    human_places: set[str] = set()
    humans: set[str] = set()
    for count, atom in enumerate(facts):
        if not count & 0xFFFF:
            check_deadline(deadline, "describing the scene")
        name = atom[0]
        if name == predicates.human_location and len(atom) == 3:
            humans.add(atom[1])
        if name == predicates.location and len(atom) == 3:
            place_of.setdefault(atom[1], atom[2])
        elif name == predicates.support and len(atom) == 3:
            stands_on[atom[1]] = atom[2]
            covered.add(atom[2])
        elif name == predicates.access and len(atom) == 2:
            accessible.add(atom[1])
        elif name == predicates.human_location and len(atom) == 3:
            human_places.add(atom[2])
            place_of.setdefault(atom[1], atom[2])  # a place matters to whoever is there too
    places = set(place_of.values())
    elements = {}
    for count, (name, type_name) in enumerate(objects.items()):
        if not count & 0xFFFF:
            check_deadline(deadline, "describing the scene")
        place = place_of.get(name)
        conditions = set()
        if place is not None and name not in humans:
            conditions.add("in-closed-container" if place not in accessible else "reachable")
            if place in human_places:
                conditions.add("near-human")
        if name in covered:
            conditions.add("covered")
        if name in stands_on:
            conditions.add("stacked")
        if name in places:
            conditions.add("holds-items")
        elements[name] = Element(
            name=name,
            type=type_name,
            types=domain.ancestors(type_name),
            kind=kind_of(name),
            place=place,
            stands_on=stands_on.get(name),
            covered=name in covered,
            conditions=frozenset(conditions),
        )
    return Scene(elements=elements, human_places=frozenset(human_places))


PLACEMENT_CONDITIONS = ("reachable", "in-closed-container", "near-human", "covered", "stacked", "holds-items")
