"""Which types of objects can play a part in reaching the goal: the goal regressed through the schemas.

Nothing here grounds an action.  ``analyse_goal`` regresses the goal's atoms through the action
schemas on typed patterns (the backward fixpoint of pyperplan's relevance analysis, done on
patterns of objects and types instead of ground atoms) and finds each role's depth: how many new
roles lie between it and the goal.  ``analyse_goal_reading`` also says what it read of the facts
(:class:`GoalReads`), so that a caller whose facts change can tell when the answer may change.
"""

from __future__ import annotations

import itertools
from collections import defaultdict
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass

from relevance_plan.pddl.formulas import Atom, Formula, GroundAtom, effect_literals, literals, scoped_literals
from relevance_plan.pddl.model import Action, Domain, Problem
from relevance_plan.pddl.sexpr import check_deadline
from relevance_plan.relevance.analysis.facts import FactIndex, index_init
from relevance_plan.relevance.analysis.invariants import count_keeping_for

# A lifted goal pattern: (predicate, args), each arg ("obj", name) or ("type", type name).
Term = tuple[str, str]
GoalPattern = tuple[str, tuple[Term, ...]]


@dataclass(frozen=True)
class GoalAnalysis:
    relevant_predicates: frozenset[str]
    role_depth: Mapping[str, int]  # type -> fewest role introductions from the goal
    goal_variable_types: frozenset[str]  # types quantified in the goal


def analyse_goal(
    domain: Domain, problem: Problem, index: FactIndex | None = None, deadline: float | None = None
) -> GoalAnalysis:
    """Regress the goal through the schemas on typed patterns (no grounding).

    A pattern is (predicate, args) where each arg is a goal object or a type.
    An achiever's parameter that is not unified with the pattern is a new
    variable.  It is a *role* (any object of its type may serve: a cup, a
    gripper) unless the initial state determines it from an argument already
    known, e.g. the place an item is at or the thing stacked on it.
    Patterns that some initial fact already satisfies are not regressed
    further (a clear cup, a free gripper): the objects in the way of a
    particular one are closure's business, not the goal's.
    """
    index = index or index_init(problem, None, count_keeping_for(domain, problem.timed_literals))
    return _Regression(domain, problem, index, deadline).run()


_FAR = 1 << 30
_SCAN_FIRST = 1000  # initial facts scanned one by one before their classes are collected


class _Regression:
    """The backward fixpoint of :func:`analyse_goal`: patterns with the fewest role steps from the goal."""

    def __init__(self, domain: Domain, problem: Problem, index: FactIndex, deadline: float | None = None):
        self.domain = domain
        self.deadline = deadline
        self.index = index
        self.objects = dict(domain.constants)
        self.objects.update(problem.objects)
        self.problem = problem
        self.achievers: dict[str, list[tuple[Action, Atom, Formula]]] = defaultdict(list)
        for action in domain.relaxed_actions:
            for item in effect_literals(action.effect):
                if item.is_add:
                    self.achievers[item.atom.predicate].append((action, item.atom, item.condition))
        self.best: dict[GoalPattern, int] = {}
        self.rows: dict[str, frozenset[tuple[str, ...]]] = {}
        self.role_depth: dict[str, int] = {}
        # (predicate, args with each object that is not a constant as its type) -> what regress found
        self.shapes: dict[tuple[str, tuple[Term, ...]], tuple[list[tuple[str, tuple[Term, ...], int]], list[str]]] = {}

    def run(self) -> GoalAnalysis:
        goal_types: set[str] = set()
        frontier: list[tuple[GoalPattern, int]] = []
        for atom, _, scope in scoped_literals(self.problem.goal):
            variables = dict(scope)
            goal_types.update(variables.values())
            args = tuple(("type", variables[a]) if a in variables else ("obj", a) for a in atom.args)
            frontier.append(((atom.predicate, args), 0))
        self.role_depth = {t: 0 for t in goal_types}
        while frontier:
            check_deadline(self.deadline, "regressing the goal", self.problem.path)
            pattern, depth = frontier.pop()
            if self.best.get(pattern, _FAR) <= depth:
                continue
            self.best[pattern] = depth
            if not self.initially_satisfiable(pattern):
                frontier.extend(self.regress(pattern, depth))
        return GoalAnalysis(
            relevant_predicates=frozenset(p for p, _ in self.best),
            role_depth=self.role_depth,
            goal_variable_types=frozenset(goal_types),
        )

    def initially_satisfiable(self, pattern: GoalPattern) -> bool:
        # Some initial fact matches: some object of the right type already has
        # the property (a cup that is clear, a free gripper), so the pattern
        # need not be regressed; closure handles the objects in the way.
        predicate, args = pattern
        atoms = self.index.by_predicate.get(predicate, ())
        # A named object's own facts are usually far fewer than the predicate's (one floor's
        # against every (above f g) of a tall building): scan the shorter list.
        for kind, name in args:
            if kind == "obj" and len(self.index.by_object.get(name, ())) < len(atoms):
                atoms = self.index.by_object.get(name, ())
        if len(atoms) > _SCAN_FIRST and all(kind == "type" for kind, _ in args):
            # Classes only: the first facts usually answer; past them, the predicate's distinct rows
            # of classes do, once (150,000 plates stated before the one cup that is clear).
            return self._fits_any(itertools.islice(atoms, _SCAN_FIRST), predicate, args) or any(
                all(self.domain.is_subtype(row[i], a[1]) for i, a in enumerate(args))
                for row in self._class_rows(predicate)
            )
        return self._fits_any(atoms, predicate, args)

    def _fits_any(self, atoms: Iterable[GroundAtom], predicate: str, args: tuple[Term, ...]) -> bool:
        return any(
            atom[0] == predicate
            and all(
                atom[1 + i] == a[1]
                if a[0] == "obj"
                else self.domain.is_subtype(self.objects.get(atom[1 + i], "object"), a[1])
                for i, a in enumerate(args)
            )
            for atom in atoms
        )

    def _class_rows(self, predicate: str) -> frozenset[tuple[str, ...]]:
        """The classes of the objects of ``predicate``'s initial facts, one row per distinct tuple."""
        rows = self.rows.get(predicate)
        if rows is None:
            check_deadline(self.deadline, "regressing the goal", self.problem.path)
            kind = self.objects.get
            rows = self.rows[predicate] = frozenset(
                tuple([kind(arg, "object") for arg in atom[1:]]) for atom in self.index.by_predicate.get(predicate, ())
            )
        return rows

    def regress(self, pattern: GoalPattern, depth: int) -> list[tuple[GoalPattern, int]]:
        """The patterns the achievers of ``pattern`` need, with their depths; records new roles.

        Patterns that differ only in objects of the same types (two thousand packages' destinations)
        regress alike: the first one's answer is kept with each object as its position in the
        pattern, and the others' are filled in from it."""
        predicate, args = pattern
        constants = self.domain.constants
        shape = (
            predicate,
            tuple(
                ("of", self.objects.get(value, "")) if kind == "obj" and value not in constants else (kind, value)
                for kind, value in args
            ),
        )
        cached = self.shapes.get(shape)
        if cached is None:
            found, roles = self._regress(pattern)
            position = {value: i for i, (kind, value) in reversed(list(enumerate(args))) if kind == "obj"}
            cached = self.shapes[shape] = (
                [
                    (
                        name,
                        tuple(("at", str(position[v])) if k == "obj" and v in position else (k, v) for k, v in new),
                        step,
                    )
                    for (name, new), step in found
                ],
                roles,
            )
        templates, roles = cached
        for type_name in roles:
            if self.role_depth.get(type_name, _FAR) > depth + 1:
                self.role_depth[type_name] = depth + 1
        return [
            ((name, tuple(args[int(v)] if k == "at" else (k, v) for k, v in template)), depth + step)
            for name, template, step in templates
        ]

    def _regress(self, pattern: GoalPattern) -> tuple[list[tuple[GoalPattern, int]], list[str]]:
        """What :meth:`regress` finds for ``pattern``: the patterns with their depth from it, and the
        types of the roles its achievers introduce."""
        options = []
        for action, added, condition in self.achievers.get(pattern[0], ()):
            bound = _unify(self.domain, self.objects, action, added, pattern[1])
            if bound is not None:
                pre_atoms = [
                    (atom.predicate, atom.args)
                    for part in (action.precondition, condition)
                    for atom, positive in literals(part)
                    if positive
                ]
                options.append((action, bound, pre_atoms, _roles(action, bound, pre_atoms, self.index)))
        if not options:
            return [], []
        # Only the achievers that need the fewest new roles count: picking up a
        # cup needs nothing new, unstacking it from "some item" would make every
        # item look useful.
        fewest = min(len(option[3]) for option in options)
        found = []
        roles: list[str] = []
        for action, bound, pre_atoms, roles_here in options:
            if len(roles_here) != fewest:
                continue
            params = dict(action.parameters)
            roles.extend(params[var] for var in sorted(roles_here))
            for predicate_name, args in pre_atoms:
                # A condition on a newly introduced role is one step further away.
                next_depth = 1 if roles_here.intersection(args) else 0
                new_args = tuple(
                    bound[arg]
                    if arg in bound
                    else ("type", params.get(arg, "object"))
                    if arg.startswith("?")
                    else ("obj", arg)
                    for arg in args
                )
                found.append(((predicate_name, new_args), next_depth))
        return found, roles


@dataclass(frozen=True)
class GoalReads:
    """What :func:`analyse_goal` read of the facts: the patterns it asked whether some fact satisfies
    (by predicate) with the answers, and the predicates whose single fact or functional positions
    can decide a role (those of the conditions of the achievers it regressed through).  While no
    answer changes and those predicates keep their single facts and functional positions, the
    analysis of the same goal comes out the same."""

    patterns: Mapping[str, tuple[tuple[GoalPattern, bool], ...]]  # predicate -> (pattern, answer)
    role_predicates: frozenset[str]

    def answers_change(
        self,
        domain: Domain,
        type_of: Callable[[str], str],
        index: FactIndex,
        added: Iterable[GroundAtom],
        removed: Iterable[GroundAtom],
    ) -> bool:
        """Whether facts that came (``added``) or went (``removed``, from ``index`` already) change
        an answer: a pattern now satisfied that was not, or one no fact satisfies any more
        (``type_of``: an object's type)."""
        for fact in added:
            if any(
                not answer and _fits(domain, type_of, pattern, fact)
                for pattern, answer in self.patterns.get(fact[0], ())
            ):
                return True
        for fact in removed:
            for pattern, answer in self.patterns.get(fact[0], ()):
                if answer and _fits(domain, type_of, pattern, fact) and not _satisfied(domain, type_of, index, pattern):
                    return True
        return False


def _fits(domain: Domain, type_of: Callable[[str], str], pattern: GoalPattern, fact: GroundAtom) -> bool:
    args = pattern[1]
    return len(args) == len(fact) - 1 and all(
        value == name if kind == "obj" else domain.is_subtype(type_of(value), name)
        for (kind, name), value in zip(args, fact[1:])
    )


def _satisfied(domain: Domain, type_of: Callable[[str], str], index: FactIndex, pattern: GoalPattern) -> bool:
    """Whether some fact satisfies ``pattern`` (the facts of an object it names, when it names one)."""
    named = [name for kind, name in pattern[1] if kind == "obj"]
    facts = index.by_object.get(named[0], ()) if named else index.by_predicate.get(pattern[0], ())
    return any(fact[0] == pattern[0] and _fits(domain, type_of, pattern, fact) for fact in facts)


class _ReadingRegression(_Regression):
    """The regression of :func:`analyse_goal`, noting each pattern it asks about."""

    def __init__(self, domain: Domain, problem: Problem, index: FactIndex, deadline: float | None = None):
        super().__init__(domain, problem, index, deadline)
        self.asked: dict[GoalPattern, bool] = {}

    def initially_satisfiable(self, pattern: GoalPattern) -> bool:
        answer = self.asked[pattern] = super().initially_satisfiable(pattern)
        return answer

    def reads(self) -> GoalReads:
        patterns: dict[str, list[tuple[GoalPattern, bool]]] = defaultdict(list)
        for pattern, answer in self.asked.items():
            patterns[pattern[0]].append((pattern, answer))
        regressed = {pattern[0] for pattern, satisfied in self.asked.items() if not satisfied}
        role_predicates = {
            atom.predicate
            for predicate in regressed
            for action, _, condition in self.achievers.get(predicate, ())
            for part in (action.precondition, condition)
            for atom, _ in literals(part)
        }
        return GoalReads({p: tuple(found) for p, found in patterns.items()}, frozenset(role_predicates))


def analyse_goal_reading(
    domain: Domain, problem: Problem, index: FactIndex, deadline: float | None = None
) -> tuple[GoalAnalysis, GoalReads]:
    """:func:`analyse_goal`, and what it read of the facts (for a caller that keeps the analysis
    while the facts change)."""
    regression = _ReadingRegression(domain, problem, index, deadline)
    return regression.run(), regression.reads()


def _unify(
    domain: Domain, objects: Mapping[str, str], action: Action, added: Atom, pattern_args: tuple[Term, ...]
) -> dict[str, Term] | None:
    """Bind the achiever's parameters to the pattern's objects and types, or None if they clash."""
    params = dict(action.parameters)
    bound: dict[str, Term] = {}
    for arg, want in zip(added.args, pattern_args):
        if arg.startswith("?"):
            declared = params.get(arg, "object")
            if want[0] == "obj":
                kind = objects.get(want[1])
                if kind is None or not domain.is_subtype(kind, declared):
                    return None
                bound[arg] = want
            elif domain.is_subtype(declared, want[1]):
                bound[arg] = ("type", declared)
            elif domain.is_subtype(want[1], declared):
                bound[arg] = ("type", want[1])
            else:
                return None
        elif want[0] == "obj" and want[1] != arg:
            return None
    return bound


def _roles(
    action: Action, bound: Mapping[str, Term], pre_atoms: list[tuple[str, tuple[str, ...]]], index: FactIndex
) -> set[str]:
    """New parameters the initial state does not determine from known ones."""
    anchored = set(bound)
    new_vars = [name for name, _ in action.parameters if name not in bound]
    changed = True
    while changed:
        changed = False
        for var in new_vars:
            if var in anchored:
                continue
            for predicate_name, args in pre_atoms:
                if var not in args:
                    continue
                position = args.index(var)
                if predicate_name in index.singletons or any(
                    (other in anchored or not other.startswith("?"))
                    and (predicate_name, j, position) in index.functional
                    for j, other in enumerate(args)
                    if j != position
                ):
                    anchored.add(var)
                    changed = True
                    break
    return {var for var in new_vars if var not in anchored}
