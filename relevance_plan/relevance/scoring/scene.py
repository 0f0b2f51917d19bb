"""The scene: elements (objects) grouped into classes, with their attributes.

Top-level attributes say what an element is (its PDDL type and its kind, the
object name without a trailing index: ``whole_milk_2`` is a ``whole_milk``).
Low-level attributes say where it is, read from the initial state: its place,
whether that place is a closed container, what it stands on, what stands on it.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, replace

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
    """Which predicates carry placement; the knowledge model may rename them, or say a role has none (None).

    ``location`` places a thing at a place (``at``), ``containment`` inside a container (``in``: a
    container is a place too, and the more specific one), ``support`` stands one thing on another
    (``on``); a place is accessible when ``access`` holds of it (``accessible``, ``open``) and
    ``closed`` does not (``locked``, ``sealed``); ``human_location`` says where a human is.
    ``written`` names the roles the model wrote itself: a default the domain lacks means none.
    """

    location: str | None = "at"
    support: str | None = "on"
    access: str | None = "accessible"
    human_location: str | None = "human-at"
    containment: str | None = None
    closed: str | None = None
    written: frozenset[str] = frozenset()

    def roles(self) -> dict[str, str | None]:
        """Role -> predicate (None: the domain has no such predicate)."""
        return {role: getattr(self, role) for role in SCENE_ROLES}

    def for_domain(self, domain: Domain) -> ScenePredicates:
        """The roles the model left to their defaults and the domain lacks, as none."""
        missing: dict[str, str | None] = {
            role: None
            for role, predicate in self.roles().items()
            if role not in self.written and predicate is not None and predicate not in domain.predicates
        }
        return replace(self, **missing) if missing else self  # type: ignore[arg-type]


SCENE_ROLES = ("location", "containment", "support", "access", "closed", "human_location")


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
    types: Mapping[str, str] | None = None,
) -> Scene:
    """The elements among ``objects`` (name -> type), described by the true ``facts`` about them;
    ``types``: every object's type, when ``objects`` are only some of them (the places' types
    decide which places the access predicate judges).  Past ``deadline`` (``time.monotonic()``),
    OutOfTimeError."""
    found = _SceneReading(predicates)
    for count, atom in enumerate(facts):
        if not count & 0xFFFF:
            check_deadline(deadline, "describing the scene")
        found.read(atom)
    place_of = {**found.located, **found.contained}  # inside a container is the more specific place
    places = set(place_of.values())
    closes = _access_checks(domain, predicates)
    types = objects if types is None else types
    elements = {}
    for count, (name, type_name) in enumerate(objects.items()):
        if not count & 0xFFFF:
            check_deadline(deadline, "describing the scene")
        place = place_of.get(name)
        conditions = set()
        if place is not None and name not in found.humans:
            blocked = closes(place, types.get(place), found.accessible, found.closed)
            conditions.add("in-closed-container" if blocked else "reachable")
            if place in found.human_places:
                conditions.add("near-human")
        if name in found.covered:
            conditions.add("covered")
        if name in found.stands_on:
            conditions.add("stacked")
        if name in places:
            conditions.add("holds-items")
        elements[name] = Element(
            name=name,
            type=type_name,
            types=domain.ancestors(type_name),
            kind=kind_of(name),
            place=place,
            stands_on=found.stands_on.get(name),
            covered=name in found.covered,
            conditions=frozenset(conditions),
        )
    return Scene(elements=elements, human_places=frozenset(found.human_places))


class _SceneReading:
    """What the scene predicates say, read one fact at a time."""

    def __init__(self, predicates: ScenePredicates):
        self.predicates = predicates
        self.located: dict[str, str] = {}
        self.contained: dict[str, str] = {}
        self.stands_on: dict[str, str] = {}
        self.covered: set[str] = set()
        self.accessible: set[str] = set()
        self.closed: set[str] = set()
        self.human_places: set[str] = set()
        self.humans: set[str] = set()

    def read(self, atom: GroundAtom) -> None:
        name, p = atom[0], self.predicates
        if len(atom) == 3:
            if name == p.human_location:
                self.humans.add(atom[1])
                self.human_places.add(atom[2])
                self.located.setdefault(atom[1], atom[2])  # a place matters to whoever is there too
            elif name == p.location:
                self.located.setdefault(atom[1], atom[2])  # an object's first place is the file's first
            elif name == p.containment:
                self.contained.setdefault(atom[1], atom[2])
            elif name == p.support:
                self.stands_on[atom[1]] = atom[2]
                self.covered.add(atom[2])
        elif len(atom) == 2:
            if name == p.access:
                self.accessible.add(atom[1])
            elif name == p.closed:
                self.closed.add(atom[1])


_Blocked = Callable[[str, "str | None", set[str], set[str]], bool]


def _access_checks(domain: Domain, predicates: ScenePredicates) -> _Blocked:
    """``blocked(place, its type, accessible places, closed places)``: whether a place keeps its items
    out of reach.  The access predicate judges only places of its parameter's type (an open drawer,
    not the floor it stands on); a place ``closed`` holds of is blocked whatever ``access`` says."""
    access = predicates.access
    parameters = domain.predicates.get(access) if access is not None else None
    judged = parameters[0][1] if parameters else None

    def blocked(place: str, type_name: str | None, accessible: set[str], closed: set[str]) -> bool:
        if place in closed:
            return True
        if access is None:
            return False
        if judged is not None and type_name is not None and not domain.is_subtype(type_name, judged):
            return False
        return place not in accessible

    return blocked


PLACEMENT_CONDITIONS = ("reachable", "in-closed-container", "near-human", "covered", "stacked", "holds-items")
