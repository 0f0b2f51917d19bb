"""Immutable PDDL values: ``Domain``, ``Problem``, actions, derived predicates, metrics.

Built by ``parser.py``, written back by ``formatter.py`` (whole files) and
``writer.py`` (the user's own file minus pruned objects).  Names are
lower-cased, since PDDL compares them without case; a ``Spelling`` keeps how
the user wrote each declared name, for everything the tool shows or writes.
A problem also keeps the source spans the cutting writer needs.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Mapping
from dataclasses import dataclass, field, fields, replace
from types import MappingProxyType
from typing import Any, TypeVar

from relevance_plan.pddl.formulas import TRUE, Atom, Expression, Formula, GroundAtom, Parameters, names_in
from relevance_plan.pddl.sexpr import Item, Symbol

NUMBER = "number"  # the type of a numeric function

ObjectGroup = tuple[tuple[Symbol, ...], "Item | None"]  # the names of one ``a b - t`` group, and its type
# (start, end) of an :init entry and the objects it names; tuples of strings and numbers only, which
# the garbage collector stops tracking (200,000 facts stay out of its passes)
InitSpan = tuple[int, int, tuple[str, ...]]


K = TypeVar("K")
V = TypeVar("V")


def frozen(mapping: Mapping[K, V]) -> Mapping[K, V]:
    return MappingProxyType(dict(mapping))


def either_members(type_name: str) -> tuple[str, ...]:
    """``(either a b)`` -> ("a", "b"); a plain type -> (type,)."""
    if type_name.startswith("(either "):
        return tuple(type_name[len("(either ") : -1].split())
    return (type_name,)


_NONE: Mapping[str, str] = MappingProxyType({})


def _no_names() -> Mapping[str, str]:
    return _NONE


@dataclass(frozen=True, slots=True)
class Spelling:
    """How the user wrote each declared name, keyed by the lower-cased name the model compares.

    One table per kind of name, since PDDL lets an object share a predicate's name; the first
    declaration's spelling is the one kept.  A name no table holds (a variable, a name the tool
    made) is shown as the model holds it.  The plan writer, the formatter and the explanations
    show names through this, so a plan or a fact reads as the user's files do.
    """

    actions: Mapping[str, str] = field(default_factory=_no_names)
    predicates: Mapping[str, str] = field(default_factory=_no_names)  # and functions: either heads an atom
    types: Mapping[str, str] = field(default_factory=_no_names)
    constants: Mapping[str, str] = field(default_factory=_no_names)
    objects: Mapping[str, str] = field(default_factory=_no_names)  # the problem's

    def action(self, name: str) -> str:
        return self.actions.get(name, name)

    def predicate(self, name: str) -> str:
        return self.predicates.get(name, name)

    def type(self, name: str) -> str:
        if name.startswith("(either "):
            return "(either " + " ".join(map(self.type, either_members(name))) + ")"
        return self.types.get(name, name)

    def object(self, name: str) -> str:
        """An object's or a constant's spelling."""
        found = self.objects.get(name)
        return found if found is not None else self.constants.get(name, name)

    def with_objects(self, objects: Mapping[str, str]) -> Spelling:
        """This spelling (a domain's) with a problem's objects."""
        return replace(self, objects=objects)

    def __reduce__(self) -> tuple[Any, ...]:
        # read-only mapping views do not pickle: the tables travel as dicts and are frozen again
        return (_spelling, tuple(dict(getattr(self, part.name)) for part in fields(self)))


def _spelling(*tables: dict[str, str]) -> Spelling:
    return Spelling(*map(frozen, tables))


UNSPELLED = Spelling()  # every name as the model holds it


@dataclass(frozen=True, slots=True)
class Action:
    """An action schema; a durative action has a ``duration`` constraint and timed conditions and effects."""

    name: str
    parameters: Parameters
    precondition: Formula = TRUE  # a durative action's :condition
    effect: Formula = TRUE
    duration: Formula | None = None

    @property
    def durative(self) -> bool:
        return self.duration is not None


@dataclass(frozen=True, slots=True)
class DerivedPredicate:
    """``(:derived (p ?x ...) body)``: ``p`` holds of whatever satisfies ``body``."""

    head: Atom  # its arguments are the parameters' variables
    parameters: Parameters
    body: Formula


@dataclass(frozen=True, slots=True)
class Metric:
    direction: str  # "minimize" or "maximize"
    expression: Expression


@dataclass(frozen=True, slots=True)
class TimedLiteral:
    """``(at T fact)``, ``(at T (not fact))`` or ``(at T (= (f ...) v))`` in a problem's :init."""

    time: float
    atom: GroundAtom | None = None  # a fact that becomes true (or false when ``negated``)
    negated: bool = False
    fluent: GroundAtom | None = None  # (function, args...) that takes ``value``
    value: float | None = None


@dataclass(frozen=True, eq=False)
class Domain:
    name: str
    requirements: frozenset[str]
    types: Mapping[str, str]  # type -> parent type ("object" has parent "")
    constants: Mapping[str, str]  # constant -> type
    predicates: Mapping[str, Parameters]
    actions: tuple[Action, ...]
    path: str | None = None
    functions: Mapping[str, Parameters] = field(default_factory=dict)
    function_types: Mapping[str, str] = field(default_factory=dict)  # function -> "number" (no object fluents)
    derived: tuple[DerivedPredicate, ...] = ()
    constraints: Formula | None = None
    spelling: Spelling = field(default=UNSPELLED, repr=False)  # actions, predicates, functions, types, constants

    def ancestors(self, type_name: str) -> tuple[str, ...]:
        """The type itself and every supertype, most specific first."""
        chain = []
        seen = set()
        current = type_name
        while current and current not in seen:
            chain.append(current)
            seen.add(current)
            current = self.types.get(current, "object" if current != "object" else "")
        return tuple(chain)

    def is_subtype(self, type_name: str, of: str) -> bool:
        if of == "object":
            return True
        # asked once per object and type by the analyses: remembered per pair (a domain has few types)
        known = self.__dict__.get("_subtypes")
        if known is None:
            known = {}
            object.__setattr__(self, "_subtypes", known)
        answer = known.get((type_name, of))
        if answer is None:
            targets = either_members(of)
            answer = any(t in self.ancestors(member) for member in either_members(type_name) for t in targets)
            known[(type_name, of)] = answer
        return answer

    def action(self, name: str) -> Action | None:
        return self._actions_by_name.get(name)

    @property
    def _actions_by_name(self) -> Mapping[str, Action]:
        cached = self.__dict__.get("_action_index")
        if cached is None:
            cached = {action.name: action for action in self.actions}
            object.__setattr__(self, "_action_index", cached)
        return cached

    @property
    def relaxed_actions(self) -> tuple[Action, ...]:
        """The actions plus one pseudo-action per derived rule (its body as precondition, its head as
        effect): the view of the domain the relevance analysis works on.  Timed parts of durative
        actions are looked through by the walks of ``formulas``."""
        cached = self.__dict__.get("_relaxed_actions")
        if cached is None:
            rules = tuple(
                Action(f"(derive {rule.head.predicate})", rule.parameters, rule.body, rule.head)
                for rule in self.derived
            )
            cached = self.actions + rules
            object.__setattr__(self, "_relaxed_actions", cached)
        return cached

    @property
    def derived_predicates(self) -> frozenset[str]:
        return frozenset(rule.head.predicate for rule in self.derived)

    @property
    def temporal(self) -> bool:
        return any(action.durative for action in self.actions)

    @property
    def numeric(self) -> bool:
        """Numeric fluents beyond action costs (a ``total-cost`` only domain is not numeric)."""
        return any(name != "total-cost" for name in self.functions)


@dataclass(frozen=True, eq=False)
class Problem:
    name: str
    domain_name: str
    objects: Mapping[str, str]  # object -> type, in file order
    init: frozenset[GroundAtom]  # ground atoms that are true
    goal: Formula
    text: str = field(repr=False)
    path: str | None = None
    spelling: Spelling = field(default=UNSPELLED, repr=False)  # its domain's names and its objects
    numeric_init: Mapping[GroundAtom, float] = field(default_factory=dict, repr=False)  # (f, args...) -> value
    timed_literals: tuple[TimedLiteral, ...] = ()
    constraints: Formula | None = None
    metric: Metric | None = None
    requirements: frozenset[str] = frozenset()
    # Source layout, for cutting the file (see writer.py).
    object_groups: tuple[ObjectGroup, ...] = field(default=(), repr=False)
    init_spans: tuple[InitSpan, ...] = field(default=(), repr=False)  # every :init entry and its objects
    init_order: Mapping[GroundAtom, int] = field(default_factory=dict, repr=False)  # first stated, 0, 1, ...

    def display(self, name: str) -> str:
        """An object's (or a constant's) name as the user wrote it."""
        return self.spelling.object(name)

    def facts_in_order(self) -> Iterable[GroundAtom]:
        """The initial facts in the order the file first states them (sorted when ``init`` was
        changed since): never in the order a set happens to iterate, which follows the hash seed."""
        return self.init_order.keys() if self.init_order.keys() == self.init else sorted(self.init)

    def object_line(self, name: str) -> int | None:
        """The line that declares object ``name``, if the problem came from text."""
        for symbols, _ in self.object_groups:
            for symbol in symbols:
                if symbol.text.lower() == name:
                    return int(symbol.line)
        return None


def make_problem(
    name: str,
    domain_name: str,
    objects: Mapping[str, str],
    init: Iterable[GroundAtom],
    goal: Formula,
    *,
    numeric_init: Mapping[GroundAtom, float] | None = None,
    metric: Metric | None = None,
) -> Problem:
    """A problem built in code (no source text, names as written); ``init`` keeps its order when formatted."""
    order: dict[GroundAtom, int] = {}
    for atom in init:
        order.setdefault(tuple(atom), len(order))
    return Problem(
        name=name,
        domain_name=domain_name,
        objects=frozen(objects),
        init=frozenset(order),
        goal=goal,
        text="",
        spelling=UNSPELLED,
        numeric_init=frozen(numeric_init or {}),
        metric=metric,
        init_order=frozen(order),
    )


def all_objects(domain: Domain, problem: Problem) -> Mapping[str, str]:
    """Constants and objects with their types."""
    everything = dict(domain.constants)
    everything.update(problem.objects)
    return everything


class ObjectsOfType:
    """``objects_of(type_name)``: the objects of a type or of its subtypes, in ``objects``' order, each
    tuple computed on first use (a cache: the one mutable piece of this module)."""

    def __init__(self, domain: Domain, objects: Mapping[str, str]):
        self._domain = domain
        self._objects = objects
        self._found: dict[str, tuple[str, ...]] = {}

    def __call__(self, type_name: str) -> tuple[str, ...]:
        found = self._found.get(type_name)
        if found is None:
            is_subtype = self._domain.is_subtype
            found = self._found[type_name] = tuple(o for o, t in self._objects.items() if is_subtype(t, type_name))
        return found


def goal_objects(problem: Problem, domain: Domain) -> frozenset[str]:
    """Objects named in the goal (constants excluded: they are never pruned)."""
    return frozenset(name for name in names_in(problem.goal) if name in problem.objects) - set(domain.constants)


def pinned_objects(problem: Problem, domain: Domain) -> frozenset[str]:
    """Objects that must stay whatever their relevance: named in the goal, the trajectory
    constraints or the metric (pruning them would change what the problem asks)."""
    found = set(names_in(problem.goal))
    for part in (problem.constraints, problem.metric.expression if problem.metric else None):
        if part is not None:
            found.update(names_in(part))
    return frozenset(name for name in found if name in problem.objects)


def numeric_facts(problem: Problem) -> Iterator[GroundAtom]:
    """The initial numeric values' terms as facts ``(function, args...)``, for linking objects."""
    return (term for term in problem.numeric_init if len(term) > 1)
