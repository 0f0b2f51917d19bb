"""The task's relaxed actions compiled for the exploration: join schemas and what the joins read.

``relaxed_task`` compiles a task once (cached per task: a repair runs several checks).  Each
relaxed action (derived rules included) becomes one :class:`JoinSchema` per way through its
top-level disjunctive conditions (``_ways_through``); the static one-argument conditions its
parameters' types imply are dropped.  Besides the schemas, a :class:`RelaxedTask` holds the
static predicates, the timed atoms, which schema a fact of each predicate triggers, the schemas
another dominates once some atoms without arguments are reached (``_dominated``), those that
saturate, and the class of many goal objects that share one exploration through a placeholder
(:class:`SharedClass`, found by ``_shared_class``).

Negative and quantified conditions and effect conditions are ignored here: a relaxation.
"""

from __future__ import annotations

import functools
import itertools
import math
import weakref
from collections import Counter, defaultdict
from collections.abc import Iterator, Mapping, Sequence, Set
from dataclasses import dataclass, field, replace

from relevance_plan.pddl.formulas import Atom, Formula, GroundAtom, Or, conjuncts, effect_literals
from relevance_plan.pddl.model import Domain
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.analysis.types import static_predicates

DISJUNCTIVE_WAYS = 16  # ways through an action's disjunctive conditions the check splits it into
SHARED_FROM = 8  # goal objects of one interchangeable class before they share one exploration
MEMBER = "#member"  # stands for every kept object of that class in the shared exploration (not a PDDL name)

Args = tuple[str, ...]  # a condition's or an effect's arguments: variables (``?x``) and names
Condition = tuple[str, Args]  # (predicate, args)
Binding = dict[str, str]  # variable -> object
TypedCondition = tuple[str, Args, tuple[str | None, ...]]  # a condition with its arguments' types (None: a name)
Step = tuple[str, ...]  # a ground action: (name, *objects)


def required_atoms(formula: Formula) -> Iterator[Condition]:
    """Positive atoms that must hold (top-level conjunction only; the rest is ignored: a relaxation)."""
    for part in conjuncts(formula):
        if isinstance(part, Atom):
            yield part.predicate, part.args


def _ways_through(formula: Formula) -> list[tuple[Condition, ...]]:
    """The positive atoms that must hold, one tuple per way through the top-level disjunctions
    (``(or (connected ?a ?b) (connected ?b ?a))``), as the translator splits an action; a disjunction
    with a branch that requires no atom, or one past ``DISJUNCTIVE_WAYS``, is ignored, like every
    other condition that is not a top-level atom: a relaxation."""
    base: list[Condition] = []
    choices: list[list[tuple[Condition, ...]]] = []
    for part in conjuncts(formula):
        if isinstance(part, Atom):
            base.append((part.predicate, part.args))
        elif isinstance(part, Or):
            branches = [
                tuple((atom.predicate, atom.args) for atom in conjuncts(branch) if isinstance(atom, Atom))
                for branch in part.parts
            ]
            if all(branches) and math.prod(map(len, choices)) * len(branches) <= DISJUNCTIVE_WAYS:
                choices.append(branches)
    return [tuple(base) + tuple(itertools.chain.from_iterable(way)) for way in itertools.product(*choices)]


@dataclass(frozen=True)
class JoinSchema:
    name: str
    parameters: tuple[str, ...]  # variables
    types: tuple[str, ...]
    pre: tuple[Condition, ...]
    add: tuple[tuple[str, Args, tuple[tuple[str, str], ...]], ...]  # (predicate, args, quantified (variable, type)s)
    ranged: frozenset[str] = frozenset()  # the types a quantified effect ranges over
    bound_by_pre: bool = False  # no quantified effect, and the conditions name every parameter
    in_effects: frozenset[str] = frozenset()  # the parameters the add effects name
    # bound by its conditions, and each add effect names distinct parameters only: once every atom
    # those effects could add over the kept objects is reached, the schema has nothing left to add
    saturable: bool = False


def _schemas(domain: Domain) -> list[JoinSchema]:
    """The relaxed actions (derived rules included) as join schemas; effect conditions are ignored."""
    result = []
    for action in domain.relaxed_actions:
        add = tuple(
            (item.atom.predicate, item.atom.args, tuple((v, t) for v, t in item.quantified if v in item.atom.args))
            for item in effect_literals(action.effect)
            if item.is_add
        )
        variables = tuple(v for v, _ in action.parameters)
        ranged = frozenset(t for _, _, quantified in add for _, t in quantified)
        in_effects = frozenset(a for _, args, _ in add for a in args if a in variables)
        types = tuple(t for _, t in action.parameters)
        for pre in _ways_through(action.precondition):
            named = {a for _, args in pre for a in args}
            bound = not ranged and all(v in named for v in variables)
            saturable = bound and all(
                len(set(args)) == len(args) and all(a in variables for a in args) for _, args, _ in add
            )
            result.append(JoinSchema(action.name, variables, types, pre, add, ranged, bound, in_effects, saturable))
    return result


@dataclass(frozen=True)
class SharedClass:
    """A class whose objects the exploration may stand for by one placeholder (see :func:`_shared_class`)."""

    name: str  # the class
    members: frozenset[str]  # its objects
    variable: Mapping[int, str]  # id(schema) -> the parameter that holds a member, for the schemas that have one


@dataclass(frozen=True)
class RelaxedTask:
    """What every check on one task shares (cached per task: a repair runs several checks)."""

    schemas: list[JoinSchema]
    static: frozenset[str]  # predicates no action and no timed literal changes
    timed: frozenset[GroundAtom]  # atoms a timed initial literal makes true
    # object -> the timed atoms that mention it (the initial facts' index has none of them)
    timed_by_object: Mapping[str, tuple[GroundAtom, ...]]
    nullary: frozenset[GroundAtom]  # initial and timed atoms without arguments
    shared: SharedClass | None = None
    # id(schema) -> the atoms without arguments that, once reached, make it add nothing new (see _dominated)
    dominated: Mapping[int, frozenset[GroundAtom]] = field(default_factory=dict)
    # predicate -> (schema, the condition it matches, the schema's other conditions with their types)
    triggers: Mapping[str, list[tuple[JoinSchema, int, list[TypedCondition]]]] = field(default_factory=dict)
    conditions: Mapping[int, list[TypedCondition]] = field(default_factory=dict)  # id(schema) -> its typed conditions
    # id(schema) -> the schemas the exploration may pass over once every atom they add is reached
    # (every floor reached: no more joins of ``up``); the placeholder's steps are never passed over,
    # as each member follows them
    saturable: Mapping[int, JoinSchema] = field(default_factory=dict)
    counted: frozenset[str] = frozenset()  # the predicates the saturable schemas add: their facts are counted


def relaxed_task(task: PlanningTask) -> RelaxedTask:
    """The task's relaxed actions and what the exploration reads besides the facts (computed once per task)."""
    cached = _RELAXED.get(task)
    if cached is None:
        problem = task.typing.problem
        timed = frozenset(
            literal.atom for literal in problem.timed_literals if literal.atom is not None and not literal.negated
        )
        static = static_predicates(task.typing.domain) - {
            literal.atom[0] for literal in problem.timed_literals if literal.atom
        }
        schemas = _relaxed_schemas(task)
        shared = None if problem.timed_literals else _shared_class(task, schemas)
        shared_steps = shared.variable if shared else {}
        triggers, conditions = _triggers(schemas)
        saturable = {id(s): s for s in schemas if s.saturable and id(s) not in shared_steps}
        cached = RelaxedTask(
            schemas,
            frozenset(static),
            timed,
            _timed_by_object(timed),
            _nullary(task, timed),
            shared,
            _dominated(task.typing.domain, schemas, shared_steps),
            triggers,
            conditions,
            saturable,
            frozenset(predicate for s in saturable.values() for predicate, _, _ in s.add),
        )
        _RELAXED[task] = cached
    return cached


def _nullary(task: PlanningTask, timed: Set[GroundAtom]) -> frozenset[GroundAtom]:
    """The initial and timed atoms without arguments."""
    by_predicate = task.init_index.by_predicate
    return frozenset(
        atom
        for predicate, parameters in task.typing.domain.predicates.items()
        if not parameters
        for atom in by_predicate.get(predicate, ())
        if atom in task.typing.problem.init
    ) | frozenset(atom for atom in timed if len(atom) == 1)


def _timed_by_object(timed: Set[GroundAtom]) -> dict[str, tuple[GroundAtom, ...]]:
    """Object -> the timed atoms that mention it, each once, in sorted order."""
    found: dict[str, list[GroundAtom]] = defaultdict(list)
    for atom in sorted(timed):
        for name in dict.fromkeys(atom[1:]):
            found[name].append(atom)
    return {name: tuple(atoms) for name, atoms in found.items()}


def _triggers(
    schemas: Sequence[JoinSchema],
) -> tuple[dict[str, list[tuple[JoinSchema, int, list[TypedCondition]]]], dict[int, list[TypedCondition]]]:
    """Predicate -> (schema, the condition a fact of it matches, the schema's other conditions), and
    each schema's conditions, each with its arguments' types (None: a name)."""
    triggers: dict[str, list[tuple[JoinSchema, int, list[TypedCondition]]]] = defaultdict(list)
    conditions: dict[int, list[TypedCondition]] = {}
    for schema in schemas:
        type_of = dict(zip(schema.parameters, schema.types))
        typed = [
            (predicate, args, tuple(type_of.get(a) if a[0] == "?" else None for a in args))
            for predicate, args in schema.pre
        ]
        conditions[id(schema)] = typed
        for i, (predicate, _) in enumerate(schema.pre):
            triggers[predicate].append((schema, i, typed[:i] + typed[i + 1 :]))
    return dict(triggers), conditions


_RELAXED: weakref.WeakKeyDictionary[PlanningTask, RelaxedTask] = weakref.WeakKeyDictionary()


def _relaxed_schemas(task: PlanningTask) -> list[JoinSchema]:
    """The task's join schemas without the static one-argument conditions its parameters' types
    imply: in an untyped domain ``(truck ?t)`` is the type of ``?t`` and every candidate binding
    passes it, so joining on it only repeats the type check (the bulk of the work on the IPC's
    untyped STRIPS domains)."""
    domain, problem = task.typing.domain, task.typing.problem
    static = static_predicates(domain)
    by_predicate = task.init_index.by_predicate
    holders = {
        p: {atom[1] for atom in by_predicate.get(p, ())} for p in static if len(domain.predicates.get(p, ())) == 1
    }
    objects, constants = problem.objects, domain.constants
    declared = Counter(objects.values())  # type -> objects declared of it (the problem's name wins)
    declared.update(kind for name, kind in constants.items() if name not in objects)

    @functools.cache
    def implied(predicate: str, type_name: str) -> bool:
        # every member of the type holds it: as many holders of the type as members (counted, not listed)
        members = sum(count for kind, count in declared.items() if domain.is_subtype(kind, type_name))
        held = 0
        for name in holders[predicate]:
            kind = objects.get(name, constants.get(name))
            held += kind is not None and domain.is_subtype(kind, type_name)
        return held == members

    result = []
    for schema in _schemas(domain):
        type_of = dict(zip(schema.parameters, schema.types))
        pre = tuple(
            (predicate, args)
            for predicate, args in schema.pre
            if not (
                predicate in holders
                and len(args) == 1
                and args[0] in type_of
                and type_of[args[0]] != "object"
                and implied(predicate, type_of[args[0]])
            )
        )
        result.append(replace(schema, pre=pre))
    return result


DOMINANCE_SCHEMAS = 200  # past this many schemas the pairs are not compared
DOMINANCE_FREE = 3  # parameters of a dominating schema its add effect leaves to be matched


def _dominated(
    domain: Domain, schemas: Sequence[JoinSchema], shared_steps: Mapping[int, str]
) -> dict[int, frozenset[GroundAtom]]:
    """The schemas the relaxation may pass over once some atoms without arguments are reached: for
    each of the schema's add effects, another schema adds it with its parameters taken from this
    one's and with no condition this one lacks but those atoms.  Picking up a key while holding
    another (grid) adds what picking up with an empty arm and putting down add; once the arm has
    been empty, the exploration need not join every place with every pair of keys.  Dominating
    schemas have fewer conditions (or the same number and come first), so the relation has no
    cycle and what is passed over is always added by a schema that is not."""
    if len(schemas) > DOMINANCE_SCHEMAS:
        return {}
    simple = [(i, s) for i, s in enumerate(schemas) if s.bound_by_pre and not s.ranged and id(s) not in shared_steps]
    order = {id(s): (sum(1 for _, args in s.pre if args), i) for i, s in simple}
    result = {}
    for _, schema in simple:
        conditions = set(schema.pre)
        needs: set[GroundAtom] = set()
        for predicate, args, _ in schema.add:
            best: frozenset[GroundAtom] | None = None
            for _, other in simple:
                if order[id(other)] >= order[id(schema)]:
                    continue
                for other_predicate, other_args, _ in other.add:
                    if other_predicate == predicate and len(other_args) == len(args):
                        found = _covering(domain, schema, conditions, args, other, other_args)
                        if found is not None and (best is None or len(found) < len(best)):
                            best = found
            if best is None:
                break
            needs |= best
        else:
            if schema.add:
                result[id(schema)] = frozenset(needs)
    return result


def _covering(
    domain: Domain, schema: JoinSchema, conditions: Set[Condition], args: Args, other: JoinSchema, other_args: Args
) -> frozenset[GroundAtom] | None:
    """The atoms without arguments ``other`` needs besides ``schema``'s conditions to add ``args``
    for every binding of ``schema`` (``other``'s parameters taken from ``schema``'s, types fitting);
    None if it cannot."""
    mapping: dict[str, str] = {}
    for mine, theirs in zip(args, other_args):
        if theirs[0] != "?":
            if mine != theirs:
                return None
        elif mine[0] != "?" or mapping.setdefault(theirs, mine) != mine:
            return None
    free = [v for v in other.parameters if v not in mapping]
    if len(free) > DOMINANCE_FREE:
        return None
    type_of = dict(zip(schema.parameters, schema.types))
    other_type = dict(zip(other.parameters, other.types))

    def assignments(i: int) -> Iterator[dict[str, str]]:
        if i == len(free):
            yield mapping
            return
        for value in schema.parameters:
            mapping[free[i]] = value
            yield from assignments(i + 1)
        del mapping[free[i]]

    for full in assignments(0):
        if not all(domain.is_subtype(type_of[full[v]], other_type[v]) for v in other.parameters):
            continue
        needs = []
        for predicate, pre_args in other.pre:
            if not pre_args:
                needs.append((predicate,))
            elif (predicate, tuple(full.get(a, a) for a in pre_args)) not in conditions:
                break
        else:
            return frozenset(needs)
    return None


def _shared_class(task: PlanningTask, schemas: Sequence[JoinSchema]) -> SharedClass | None:
    """The class of many goal objects that never meet: every action holds at most one of them, in a
    parameter only they fit, and adds only facts about it; no fact names two.  Then what one member
    can reach depends on the rest of the world and its own facts only, so the exploration runs once
    with a placeholder for all of them and each goal member follows the actions found for the
    placeholder from its own initial facts (packages in logistics, passengers in miconic: the bulk
    of a many-goal exploration)."""
    domain, problem = task.typing.domain, task.typing.problem
    classes = problem.objects
    goal = [(p, *args) for p, args in required_atoms(problem.goal)]
    in_goal: dict[str, set[str]] = defaultdict(set)
    for atom in goal:
        for arg in atom[1:]:
            if arg in classes:
                in_goal[classes[arg]].add(arg)
    by_object = task.init_index.by_object
    for name, found in sorted(in_goal.items(), key=lambda item: (-len(item[1]), item[0])):
        if len(found) < SHARED_FROM:
            break
        if name in domain.constants.values():
            continue  # a constant of the class could meet a member in an action
        members = frozenset(o for o, c in classes.items() if c == name)
        others = {c for c in classes.values() if c != name} | set(domain.constants.values())
        variable: dict[int, str] = {}
        for schema in schemas:
            holding = [(v, t) for v, t in zip(schema.parameters, schema.types) if domain.is_subtype(name, t)]
            if any(domain.is_subtype(name, t) for t in schema.ranged) or len(holding) > 1:
                break
            if not holding:
                continue
            v, t = holding[0]
            if not schema.bound_by_pre or any(domain.is_subtype(o, t) for o in others):
                break
            if any(v not in args for _, args, _ in schema.add):
                break
            variable[id(schema)] = v
        else:
            two = (
                atom
                for atom in (*goal, *(a for m in members for a in by_object.get(m, ())))
                if sum(arg in members for arg in atom[1:]) > 1
            )
            if variable and next(two, None) is None:
                return SharedClass(name, members, variable)
    return None
