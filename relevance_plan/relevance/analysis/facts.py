"""The true facts indexed as every analysis reads them: by predicate, by object, and the
positions at which one object determines the others.

``index_init`` indexes a problem's initial state (a numeric term such as ``(distance a b)`` counts
as a fact); :class:`FactIndex` is what the analyses read of an index, which the live session's
follows the scene as it changes.  ``fan_in`` and ``object_profiles`` are read off an index.
"""

from __future__ import annotations

from collections import defaultdict
from collections.abc import Collection, Iterable, Mapping
from dataclasses import dataclass
from typing import Protocol

from relevance_plan.pddl.formulas import GroundAtom
from relevance_plan.pddl.model import Problem, numeric_facts
from relevance_plan.pddl.sexpr import check_deadline


class FactIndex(Protocol):
    """What rule inference, closure and distances read of the true facts.

    :class:`InitIndex` is the initial state's; the live session keeps one that
    follows the scene as it changes.
    """

    @property
    def by_predicate(self) -> Mapping[str, Collection[GroundAtom]]: ...

    @property
    def by_object(self) -> Mapping[str, Collection[GroundAtom]]: ...

    @property
    def functional(self) -> frozenset[tuple[str, int, int]]: ...

    @property
    def singletons(self) -> frozenset[str]: ...


@dataclass(frozen=True)
class InitIndex:
    """The initial state indexed by predicate, for rule inference and closure."""

    by_predicate: Mapping[str, tuple[GroundAtom, ...]]
    by_object: Mapping[str, tuple[GroundAtom, ...]]
    functional: frozenset[tuple[str, int, int]]  # (predicate, key_position, other_position): key determines other

    @property
    def singletons(self) -> frozenset[str]:
        return frozenset(p for p, atoms in self.by_predicate.items() if len(atoms) == 1)


def index_init(
    problem: Problem, deadline: float | None = None, count_keeping: Collection[tuple[str, int]] = ()
) -> InitIndex:
    """Facts by predicate and by object; a numeric value's term ``(distance a b)`` counts as a fact,
    so the objects inside a function term are linked like those of a static fact.

    A position is functional when no object there has two facts; at one of ``count_keeping``
    (where no action gives an object one more fact: ``invariants.count_keeping_for``), also while
    fewer than half its objects have two, which no action gave them (an item seen in its new
    receptacle before it leaves the old one does not make every receptacle a role)."""
    by_predicate: dict[str, list[GroundAtom]] = defaultdict(list)
    by_object: dict[str, list[GroundAtom]] = defaultdict(list)
    # the exploration takes static facts in this order
    for count, atom in enumerate((*problem.facts_in_order(), *numeric_facts(problem))):
        if not count & 0xFFFF:
            check_deadline(deadline, "indexing the initial facts", problem.path)
        by_predicate[atom[0]].append(atom)
        if len(atom) == 3:  # most facts link two objects: no set for them
            by_object[atom[1]].append(atom)
            if atom[2] != atom[1]:
                by_object[atom[2]].append(atom)
        else:
            for arg in set(atom[1:]):
                by_object[arg].append(atom)
    functional: set[tuple[str, int, int]] = set()
    for predicate, atoms in by_predicate.items():
        arity = len(atoms[0]) - 1
        for key in range(arity):
            if _determines(atoms, key) or ((predicate, key) in count_keeping and _mostly_determines(atoms, key)):
                functional.update((predicate, key, other) for other in range(arity) if other != key)
    return InitIndex(
        by_predicate={p: tuple(a) for p, a in by_predicate.items()},
        by_object={o: tuple(a) for o, a in by_object.items()},
        functional=frozenset(functional),
    )


def _mostly_determines(atoms: Iterable[GroundAtom], key: int) -> bool:
    """Whether fewer than half the objects at position ``key`` have two of ``atoms``."""
    seen: dict[str, tuple[str, ...]] = {}
    clashing: set[str] = set()
    for atom in atoms:
        rest = atom[1 : 1 + key] + atom[2 + key :]
        if seen.setdefault(atom[1 + key], rest) != rest:
            clashing.add(atom[1 + key])
    return 2 * len(clashing) < len(seen)


def _determines(atoms: Iterable[GroundAtom], key: int) -> bool:
    """Whether no object at position ``key`` has two of ``atoms`` (whose other arguments differ)."""
    seen: dict[str, tuple[str, ...]] = {}
    for atom in atoms:
        rest = atom[1 : 1 + key] + atom[2 + key :]
        if seen.setdefault(atom[1 + key], rest) != rest:
            return False
    return True


def fan_in(index: FactIndex) -> dict[tuple[str, int], float]:
    """(predicate, position) -> facts per distinct object at that position: high for class-like
    values (the shape of forty keys), about one for a place or an owner."""
    result = {}
    for predicate, atoms in index.by_predicate.items():
        arity = len(next(iter(atoms), ("",))) - 1
        for position in range(arity):
            values = {atom[1 + position] for atom in atoms}
            result[(predicate, position)] = len(atoms) / max(1, len(values))
    return result


def object_profiles(index: FactIndex, values: Mapping[GroundAtom, float]) -> dict[str, tuple[object, ...]]:
    """Each object's initial facts with its own name blanked out (numeric terms with their values):
    objects with the same profile are interchangeable in the initial state, so a second one rarely
    does what the first could not."""
    profiles: dict[str, tuple[object, ...]] = {}
    for name, atoms in index.by_object.items():
        blanked = ((tuple("" if arg == name else arg for arg in atom), values.get(atom)) for atom in atoms)
        profiles[name] = tuple(sorted(blanked, key=repr))
    return profiles
