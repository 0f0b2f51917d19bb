"""The live scene: objects, true facts and the goal, changed one event at a time.

Kept in memory only.  :class:`LiveIndex` mirrors ``analysis.InitIndex``
(facts by predicate and by object, which argument positions are functional)
but is updated fact by fact, so closure and the constraint rules can run on
the current state without re-indexing it.  :meth:`LiveScene.problem_text`
renders the current state as a PDDL problem in the user's spelling, for
determining from scratch, planning and snapshots.
"""

from __future__ import annotations

from collections import defaultdict
from collections.abc import Callable, Iterable
from types import MappingProxyType

from relevance_plan.pddl.formatter import format_problem
from relevance_plan.pddl.formulas import Formula, literals
from relevance_plan.pddl.model import Domain, Problem
from relevance_plan.pddl.parser import read_problem


class LiveIndex:
    """The current facts, indexed for closure; duck-types ``analysis.InitIndex``."""

    def __init__(self, facts: Iterable[tuple] = ()):
        self.by_predicate: dict[str, set] = defaultdict(set)
        self.by_object: dict[str, set] = defaultdict(set)
        self._by_object_predicate: dict[tuple[str, str], set] = defaultdict(set)
        # (predicate, position) -> value -> number of facts; a position is functional
        # when no value occurs in two facts (see analysis.index_init).
        self._counts: dict[tuple[str, int], dict[str, int]] = defaultdict(dict)
        self._clashes: dict[tuple[str, int], int] = defaultdict(int)
        for fact in facts:
            self.add(fact)

    def add(self, fact: tuple) -> None:
        self._change(fact, set.add, 1)

    def discard(self, fact: tuple) -> None:
        """Remove a fact that is there (the caller checks)."""
        self._change(fact, set.discard, -1)

    def _change(self, fact: tuple, change: Callable[[set, tuple], None], step: int) -> None:
        change(self.by_predicate[fact[0]], fact)
        for arg in set(fact[1:]):
            change(self.by_object[arg], fact)
            change(self._by_object_predicate[arg, fact[0]], fact)
        for position, value in enumerate(fact[1:]):
            counts = self._counts[fact[0], position]
            before = counts.get(value, 0)
            after = before + step
            if after:
                counts[value] = after
            else:
                del counts[value]
            # a value in two facts or more makes the position not functional
            self._clashes[fact[0], position] += (after >= 2) - (before >= 2)

    def facts_of(self, name: str, predicate: str) -> set:
        return self._by_object_predicate.get((name, predicate), set())

    @property
    def functional(self) -> frozenset:
        found: set[tuple[str, int, int]] = set()
        for predicate, facts in self.by_predicate.items():
            if not facts:
                continue
            arity = len(next(iter(facts))) - 1
            for key in range(arity):
                if not self._clashes.get((predicate, key)):
                    found.update((predicate, key, other) for other in range(arity) if other != key)
        return frozenset(found)

    @property
    def singletons(self) -> frozenset:
        return frozenset(p for p, facts in self.by_predicate.items() if len(facts) == 1)


class LiveScene:
    """Objects (in the order they appeared), true facts and the goal of the current scene."""

    def __init__(self, domain: Domain, problem: Problem):
        self.domain = domain
        self.name = problem.name
        self.objects: dict[str, str] = dict(problem.objects)
        self.display: dict[str, str] = {name: problem.display(name) for name in problem.objects}
        self.facts: set = set(problem.init)
        self.index = LiveIndex(self.facts)
        self.goal: Formula = problem.goal
        self.values: dict[tuple, float] = dict(problem.numeric_init)  # (function, args...) -> value
        # carried into every written problem unchanged, minus what mentions a removed object
        self.timed_literals = problem.timed_literals
        self.constraints = problem.constraints
        self.metric = problem.metric

    # ------------------------------------------------------------------ changes

    def add_object(self, name: str, type_name: str, display: str) -> None:
        self.objects[name] = type_name
        self.display[name] = display

    def remove_object(self, name: str) -> list[tuple]:
        """Remove the object and every fact that mentions it; returns those facts."""
        gone = list(self.index.by_object.get(name, ()))
        for fact in gone:
            self.unset(fact)
        del self.objects[name]
        del self.display[name]
        self.index.by_object.pop(name, None)
        self.values = {fluent: value for fluent, value in self.values.items() if name not in fluent[1:]}
        self.timed_literals = tuple(
            timed
            for timed in self.timed_literals
            if name not in (timed.atom or ())[1:] and name not in (timed.fluent or ())[1:]
        )
        return gone

    def set_value(self, fluent: tuple, value: float) -> bool:
        """A numeric fluent takes ``value``; False when it had it already."""
        if self.values.get(fluent) == value:
            return False
        self.values[fluent] = value
        return True

    def set(self, fact: tuple) -> bool:
        if fact in self.facts:
            return False
        self.facts.add(fact)
        self.index.add(fact)
        return True

    def unset(self, fact: tuple) -> bool:
        if fact not in self.facts:
            return False
        self.facts.discard(fact)
        self.index.discard(fact)
        return True

    # ------------------------------------------------------------------ views

    @property
    def idle_goal(self) -> bool:
        """Whether the goal asks for nothing (``(and)``)."""
        return not any(True for _ in literals(self.goal))

    def ordered_objects(self) -> dict:
        """The objects grouped by type, types in order of first appearance (the order of :meth:`problem_text`)."""
        by_type: dict[str, list[str]] = {}
        for name, type_name in self.objects.items():
            by_type.setdefault(type_name, []).append(name)
        return {name: type_name for type_name, names in by_type.items() for name in names}

    def snapshot_problem(self) -> Problem:
        """The current state as a Problem value without source text (for pruning in memory)."""
        return Problem(
            name=self.name,
            domain_name=self.domain.name,
            objects=MappingProxyType(self.ordered_objects()),
            init=frozenset(self.facts),
            goal=self.goal,
            text="",
            display_names=MappingProxyType(dict(self.display)),
            numeric_init=MappingProxyType(dict(self.values)),
            timed_literals=self.timed_literals,
            constraints=self.constraints,
            metric=self.metric,
        )

    def problem_text(self) -> str:
        """The current state as PDDL in the user's spelling (objects grouped by type, facts sorted)."""
        return format_problem(self.snapshot_problem())

    def read_problem(self) -> Problem:
        """The current state as a Problem read back from :meth:`problem_text` (with source spans)."""
        return read_problem(self.problem_text(), self.domain)
