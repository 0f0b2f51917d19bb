"""The cheap sufficiency check before any planner call: relaxed reachability on the kept objects.

``relaxed_reachability`` grounds the actions on the kept objects only (joins
over the positive preconditions, as Fast Downward's translator explores the
delete relaxation) and runs them to a fixpoint, ignoring deletes.  If the
goal's atoms are not reached, no plan exists on that object set.  When they
are, it returns the objects of a relaxed plan: what at least one way of
reaching the goal uses.  :class:`Exploration` is the same exploration on an
object set that may grow (the repair's, in ``repair.py``).

Many goal objects of one class that never meet in an action (packages,
passengers) share one exploration through a placeholder and then advance
together, one bit each (``_shared_class``); the answer and the kind of
relaxed plan are those of the object-by-object exploration.

The check over-approximates: negative and quantified conditions and effect
conditions are ignored, an action with a disjunctive condition becomes one
schema per way through it (or ignores the disjunction where a way requires
no atom), and a universally quantified effect adds
its atom for every kept object of the type, so "unreachable" is sound.  It gives up (and says so)
past a work budget, or a few seconds, rather than cost more than the planner would.
"""

from __future__ import annotations

import functools
import itertools
import math
import time
import weakref
from collections import Counter, defaultdict, deque
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence, Set
from dataclasses import dataclass, field, replace

from relevance_plan.pddl.formulas import Atom, Formula, GroundAtom, Or, conjuncts, effect_literals
from relevance_plan.pddl.model import Domain
from relevance_plan.relevance.task import PlanningTask
from relevance_plan.relevance.types import static_predicates
from relevance_plan.relevance.witnesses import WitnessNeed, match_witnesses

DEFAULT_BUDGET = 400_000  # bindings tried before the check gives up
DISJUNCTIVE_WAYS = 16  # ways through an action's disjunctive conditions the check splits it into
SHARED_FROM = 8  # goal objects of one interchangeable class before they share one exploration
MEMBER = "#member"  # stands for every kept object of that class in the shared exploration (not a PDDL name)

Args = tuple[str, ...]  # a condition's or an effect's arguments: variables (``?x``) and names
Condition = tuple[str, Args]  # (predicate, args)
Binding = dict[str, str]  # variable -> object
_Typed = tuple[str, Args, tuple[str | None, ...]]  # a condition with its arguments' types (None: a name)
Step = tuple[str, ...]  # a ground action: (name, *objects)


@dataclass(frozen=True)
class Reachability:
    reachable: bool
    complete: bool  # False: the budget ran out, nothing is known
    unreached: tuple[GroundAtom, ...] = ()  # goal atoms the relaxation does not reach
    plan: tuple[Step, ...] = ()  # ground relaxed-plan steps (action, *args)
    plan_objects: frozenset[str] = frozenset()  # the relaxed plan's objects and the goal atoms' witnesses
    # goal atom -> the object it is met through, where it needs one of its own (``witnesses``)
    witnesses: tuple[tuple[GroundAtom, str], ...] = ()


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
class _Schema:
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


def _schemas(domain: Domain) -> list[_Schema]:
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
            result.append(_Schema(action.name, variables, types, pre, add, ranged, bound, in_effects, saturable))
    return result


@dataclass(frozen=True)
class _Shared:
    """A class whose objects the exploration may stand for by one placeholder (see :func:`_shared_class`)."""

    name: str  # the class
    members: frozenset[str]  # its objects
    variable: Mapping[int, str]  # id(schema) -> the parameter that holds a member, for the schemas that have one


@dataclass(frozen=True)
class RelaxedTask:
    """What every check on one task shares (cached per task: a repair runs several checks)."""

    schemas: list[_Schema]
    static: frozenset[str]  # predicates no action and no timed literal changes
    timed: frozenset[GroundAtom]  # atoms a timed initial literal makes true
    # object -> the timed atoms that mention it (the initial facts' index has none of them)
    timed_by_object: Mapping[str, tuple[GroundAtom, ...]]
    nullary: frozenset[GroundAtom]  # initial and timed atoms without arguments
    shared: _Shared | None = None
    # id(schema) -> the atoms without arguments that, once reached, make it add nothing new (see _dominated)
    dominated: Mapping[int, frozenset[GroundAtom]] = field(default_factory=dict)
    # predicate -> (schema, the condition it matches, the schema's other conditions with their types)
    triggers: Mapping[str, list[tuple[_Schema, int, list[_Typed]]]] = field(default_factory=dict)
    conditions: Mapping[int, list[_Typed]] = field(default_factory=dict)  # id(schema) -> its typed conditions
    # id(schema) -> the schemas the exploration may pass over once every atom they add is reached
    # (every floor reached: no more joins of ``up``); the placeholder's steps are never passed over,
    # as each member follows them
    saturable: Mapping[int, _Schema] = field(default_factory=dict)
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
    schemas: Sequence[_Schema],
) -> tuple[dict[str, list[tuple[_Schema, int, list[_Typed]]]], dict[int, list[_Typed]]]:
    """Predicate -> (schema, the condition a fact of it matches, the schema's other conditions), and
    each schema's conditions, each with its arguments' types (None: a name)."""
    triggers: dict[str, list[tuple[_Schema, int, list[_Typed]]]] = defaultdict(list)
    conditions: dict[int, list[_Typed]] = {}
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


def _relaxed_schemas(task: PlanningTask) -> list[_Schema]:
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
    domain: Domain, schemas: Sequence[_Schema], shared_steps: Mapping[int, str]
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
    domain: Domain, schema: _Schema, conditions: Set[Condition], args: Args, other: _Schema, other_args: Args
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


def _shared_class(task: PlanningTask, schemas: Sequence[_Schema]) -> _Shared | None:
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
                return _Shared(name, members, variable)
    return None


@dataclass(frozen=True)
class _Achiever:
    """The ground step that first reached a fact, with its schema and binding (to walk back from)."""

    step: Step
    schema: _Schema
    binding: Binding


class OutOfBudget(Exception):
    pass


@dataclass
class Work:
    """Bindings tried by one check, against its budget and its deadline (``time.monotonic()``)."""

    limit: int
    deadline: float = math.inf
    done: int = 0

    def spend(self) -> None:
        self.done += 1
        # the clock is read once every 4,096 bindings: cheap, and still within milliseconds
        if self.done > self.limit or (not self.done & 4095 and time.monotonic() > self.deadline):
            raise OutOfBudget


def relaxed_reachability(
    task: PlanningTask, kept: Set[str], budget: int = DEFAULT_BUDGET, deadline: float = math.inf
) -> Reachability:
    """Whether the goal's positive atoms are reachable under the delete relaxation using ``kept`` objects only.

    Each fact is processed once, in the order it was reached; an action
    instance is found when the last of its preconditions is processed, by
    joining the others against the facts processed so far (semi-naive, as in
    Fast Downward's translator).
    """
    try:
        exploration = Exploration(task, kept, Work(budget, deadline))
        exploration.run()
    except OutOfBudget:
        return Reachability(False, False)
    return exploration.outcome()


class Exploration:
    """The delete-relaxed exploration of :func:`relaxed_reachability`, on an object set that may grow.

    :meth:`add` brings in more objects and :meth:`run` carries on from where
    it stopped, so growing a selection one object at a time costs about one
    exploration of the final set.
    """

    def __init__(self, task: PlanningTask, kept: Set[str], work: Work):
        relaxed = relaxed_task(task)
        self.domain = task.typing.domain
        self.work = work
        self.schemas = relaxed.schemas
        self.triggers, self.conditions, self.dominated = relaxed.triggers, relaxed.conditions, relaxed.dominated
        self.saturable, self.counted = relaxed.saturable, relaxed.counted
        self._take_objects(task, relaxed.shared, kept)
        self._prepare_placeholder()
        self._prepare_facts(task, relaxed)
        self._prepare_joins()
        self._reach_start(relaxed)

    def _take_objects(self, task: PlanningTask, shared: _Shared | None, kept: Set[str]) -> None:
        """The objects the exploration may use, and their types."""
        domain = self.domain
        self.shared = shared
        self.members = shared.members if shared else frozenset()  # of the shared class, kept or not
        # with a shared class, its kept members are not objects of the exploration: MEMBER stands for them
        self.kept_members: set[str] = set(kept) & self.members
        self.allowed = set(kept) - self.kept_members | set(domain.constants)
        objects = task.typing.problem.objects
        self.types_of: Mapping[str, str] = objects  # only read: a building's 50,000 names are not copied
        if domain.constants or shared is not None:
            self.types_of = {**domain.constants, **objects}
        if shared is not None:
            self.allowed.add(MEMBER)
            self.types_of = {**self.types_of, MEMBER: shared.name}
        self.of_type: dict[str, list[str]] = {}
        self.fits: dict[str, frozenset[str]] = {}
        self.variable_fits: dict[int, dict[str, frozenset[str]]] = {}

    def _prepare_placeholder(self) -> None:
        """The placeholder's steps and the members' bits (used with a shared class only)."""
        # the placeholder's steps, each with its conditions on the placeholder
        self.edges: list[tuple[tuple[GroundAtom, ...], tuple[GroundAtom, ...], Step, _Schema, Binding]] = []
        self.edges_from: dict[GroundAtom, list[int]] = defaultdict(list)
        self.edge_steps: set[Step] = set()
        # Which members have reached each of the placeholder's facts, as one integer with a bit per
        # member, and when each bit came (the step, None: initial): all members advance at once.
        self.bit_of: dict[str, int] = {}
        self.holders: dict[GroundAtom, int] = {}
        self.arrivals: dict[GroundAtom, list[tuple[int, int | None]]] = defaultdict(list)
        self.spreading: deque[GroundAtom] = deque()
        self.seeds: list[tuple[GroundAtom, str]] = []  # (pattern, member): a member's initial fact not yet spread
        self.edges_spread = 0  # the placeholder's steps fired at least once

    def _prepare_facts(self, task: PlanningTask, relaxed: RelaxedTask) -> None:
        """The goal, the facts reached (none yet) and what the initial ones are read from."""
        problem = task.typing.problem
        self.goal = [(p, *args) for p, args in required_atoms(problem.goal) if not any(a[0] == "?" for a in args)]
        self.missing = set(self.goal)
        self.witness_needs = task.witness_needs
        self.exists_needs = task.exists_needs
        self.witnesses: dict[GroundAtom, str] = {}
        self.stranded: frozenset[str] = frozenset()  # kept candidate witnesses no reached fact makes usable
        self.witness_facts: list[GroundAtom] = []  # what makes each matched witness usable (holds robot vase)
        self.facts: dict[GroundAtom, _Achiever | None] = {}  # the step that first reached each fact
        self.queue: deque[GroundAtom] = deque()
        self.by_object = task.init_index.by_object
        self.init = problem.init
        # the index also holds numeric terms, (distance a b), which are not facts
        self.numeric_terms = bool(problem.numeric_init)
        # timed initial literals that make a fact true count as reached: a plan may wait for them
        self.timed = relaxed.timed
        self.timed_by_object = relaxed.timed_by_object

    def _prepare_joins(self) -> None:
        """The indexes the joins read, and the counts that tell a saturated schema."""
        # Processed facts by (predicate, signature) and (predicate, position, value, signature), where
        # the signature is the classes of the fact's objects: a condition on a truck's place looks only
        # at the facts that place a truck, not at the hundred packages that may be there too.
        self.processed: dict[tuple[str | int | tuple[str, ...], ...], list[GroundAtom]] = defaultdict(list)
        self.signatures: dict[str, list[tuple[str, ...]]] = defaultdict(list)
        self.compatible_cache: dict[tuple[str, tuple[str | None, ...]], tuple[int, list[tuple[str, ...]]]] = {}
        # (schema, the values of the bound parameters its effects name) of applications with free parameters
        self.effects_added: set[tuple[object, ...]] = set()
        # applications that ranged over every kept object of some types: run again when those grow
        self.ranging: list[tuple[_Schema, Binding, frozenset[str]]] = []
        # how many reached facts of each (predicate, signature) the saturable schemas add
        self.reached: dict[tuple[str, tuple[str, ...]], int] = {}
        self.reached_signatures: dict[str, list[tuple[str, ...]]] = defaultdict(list)
        self.reached_total: dict[str, int] = {}
        self.saturated: set[int] = set()
        self.saturation_needs: dict[int, list[tuple[str, tuple[str, ...], int]]] = {}  # until objects are added

    def _reach_start(self, relaxed: RelaxedTask) -> None:
        """The initial facts over the kept objects, and the steps that need no dynamic fact."""
        # The initial static facts (a map, the floors above each other) are indexed at once and trigger
        # nothing: every dynamic fact is processed after them, and its joins find them.  Only the
        # schemas whose conditions are all static need a join of their own.
        static = relaxed.static
        self._reach_initial(self.allowed | self.kept_members, relaxed.nullary, static)
        for schema in self.schemas:
            if not schema.pre:
                self.apply(schema, {})
            elif all(predicate in static for predicate, _ in schema.pre):
                self.apply_joined(schema, self.conditions[id(schema)], {}, self.fits_of(schema))

    def _reach_initial(
        self, names: Set[str], also: Set[GroundAtom] = frozenset(), static: Set[str] = frozenset()
    ) -> None:
        """The initial (and timed) facts over allowed objects that mention one of ``names``; those of a
        ``static`` predicate are processed at once (they trigger nothing), the others queued."""
        # In an order that follows neither the hash seed nor a sort of every fact (90,000 ``above``
        # facts between the floors kept): names by name, each one's facts in the file's order.
        found = dict.fromkeys(sorted(also))
        allowed, members, init, timed = self.allowed, self.members, self.init, self.timed
        fits, shares = allowed.issuperset, members.isdisjoint
        all_facts = not self.numeric_terms
        timed_by_object = self.timed_by_object
        for name in sorted(names):
            # a fact only a timed literal makes true is reached too: a plan may wait for it
            for atom in itertools.chain(self.by_object.get(name, ()), timed_by_object.get(name, ())):
                args = atom[1:]
                if not members or shares(args):
                    if fits(args) and (all_facts or atom in init or atom in timed):
                        found[atom] = None
                    continue
                pattern = self._pattern(atom)
                if pattern is not None and fits(pattern[1:]) and atom in init:
                    found[pattern] = None
                    self.seeds.append((pattern, next(arg for arg in args if arg in members)))
        facts, counted, missing = self.facts, self.counted, self.missing
        indexed: list[GroundAtom] = []
        queued: list[GroundAtom] = []
        for atom in found:
            if atom in facts:
                continue
            facts[atom] = None
            if atom[0] in counted:
                self._count(atom)
            missing.discard(atom)
            (indexed if atom[0] in static else queued).append(atom)
        self._index(indexed)
        # sorted: the same objects give the same relaxed plan whatever order they came in
        self.queue.extend(sorted(queued))

    def _pattern(self, atom: GroundAtom) -> GroundAtom | None:
        """``atom`` with its member of the shared class as MEMBER (None: that member is not kept)."""
        args = []
        for arg in atom[1:]:
            if arg in self.members:
                if arg not in self.kept_members:
                    return None
                arg = MEMBER
            args.append(arg)
        return (atom[0], *args)

    def _index(self, facts: Iterable[GroundAtom]) -> None:
        """Make ``facts`` visible to the joins, in their order (a floor's 600 ``above`` facts at once)."""
        processed, signatures, types = self.processed, self.signatures, self.types_of
        for fact in facts:
            predicate = fact[0]
            if len(fact) == 3 and fact[1] in types and fact[2] in types:  # most facts: no loop
                signature: tuple[str, ...] = (types[fact[1]], types[fact[2]])
                processed[(predicate, 0, fact[1], signature)].append(fact)
                processed[(predicate, 1, fact[2], signature)].append(fact)
            else:
                signature = tuple([types.get(arg, "object") for arg in fact[1:]])
                for position, value in enumerate(fact[1:]):
                    processed[(predicate, position, value, signature)].append(fact)
            known = signatures[predicate]
            if signature not in known:
                known.append(signature)
            processed[(predicate, signature)].append(fact)

    def _count(self, fact: GroundAtom) -> None:
        type_of = self.types_of.get
        key = (fact[0], tuple([type_of(arg, "object") for arg in fact[1:]]))
        count = self.reached.get(key)
        if count is None:
            self.reached_signatures[fact[0]].append(key[1])
        self.reached[key] = (count or 0) + 1
        self.reached_total[fact[0]] = self.reached_total.get(fact[0], 0) + 1

    def _saturated(self, schema: _Schema) -> bool:
        """Whether every atom ``schema`` could add over the kept objects is reached (kept objects
        are distinct facts, each of a signature that fits: counting them is enough)."""
        if id(schema) in self.saturated:
            return True
        needs = self.saturation_needs.get(id(schema))
        if needs is None:
            type_of = dict(zip(schema.parameters, schema.types))
            needs = self.saturation_needs[id(schema)] = [
                (predicate, types, math.prod(len(self.objects_of(t)) for t in types))
                for predicate, args, _ in schema.add
                for types in [tuple(type_of[a] for a in args)]
            ]
        for predicate, types, need in needs:
            if self.reached_total.get(predicate, 0) < need:
                return False  # the common answer, found without looking at signatures
            have = sum(
                self.reached[(predicate, signature)]
                for signature in self.reached_signatures.get(predicate, ())
                if all(self.domain.is_subtype(c, t) for c, t in zip(signature, types))
            )
            if have < need:
                return False
        self.saturated.add(id(schema))
        return True

    def add(self, names: Set[str]) -> None:
        """Bring ``names`` into the kept set; :meth:`run` then explores what they make reachable."""
        new = {name for name in names if name not in self.allowed and name not in self.kept_members}
        if not new:
            return
        self.kept_members |= new & self.members
        self.allowed |= new - self.kept_members
        grown = set()
        for type_name, members in self.of_type.items():
            fitting = sorted(
                o for o in new - self.kept_members if self.domain.is_subtype(self.types_of.get(o, "object"), type_name)
            )
            if fitting:
                members.extend(fitting)
                self.fits[type_name] = frozenset(members)
                grown.add(type_name)
        self.variable_fits.clear()
        self.saturated.clear()
        self.saturation_needs.clear()
        self._reach_initial(new)
        for schema, binding, ranged in list(self.ranging):
            if not grown.isdisjoint(ranged):
                self.apply(schema, binding, again=new)

    def outcome(self) -> Reachability:
        unreached = tuple(atom for atom in self.goal if atom not in self.facts)
        if unreached:
            return Reachability(False, True, unreached)
        shortfall = self.shortfall()
        if shortfall:
            return Reachability(False, True, tuple(need.goal for need in shortfall))
        # the relaxed plan reaches the goal and makes every witness usable: the way to each is kept
        plan, objects = _relaxed_plan(self.facts, [*self.goal, *self.witness_facts])
        objects.update(self.witnesses.values())
        witnesses = tuple(sorted(self.witnesses.items()))
        return Reachability(True, True, (), tuple(plan), frozenset(objects) - set(self.domain.constants), witnesses)

    def shortfall(self) -> tuple[WitnessNeed, ...]:
        """The goal atoms left without a witness of their own and the existentials no kept object
        satisfies yet (none while a goal atom is unreached); ``witnesses`` and ``stranded`` say
        what the kept objects give.  The exploration runs to its end first: the goal is reached long
        before every candidate is."""
        self.witnesses, self.stranded, self.witness_facts = {}, frozenset(), []
        if self.missing or not (self.witness_needs or self.exists_needs):
            return ()
        if self.queue:
            self.run(exhaust=True)
        return self._matched_shortfall()

    def _matched_shortfall(self) -> tuple[WitnessNeed, ...]:
        """Distinct usable witnesses for the goal atoms that need one of their own and for the
        existentials (an existential's witness satisfies its body with reached facts); returns the
        needs left without one, whose kept candidates go to ``stranded``."""
        needs = self.witness_needs + self.exists_needs
        wanted = {pattern[0] for need in needs for pattern in need.consumed}
        # (predicate, position, object) -> a reached fact with the object there
        reached: dict[tuple[str, int, str], GroundAtom] = {}
        for fact in self.facts:
            if fact[0] in wanted:
                for i, arg in enumerate(fact[1:]):
                    reached.setdefault((fact[0], i, arg), fact)

        def made_usable(need: WitnessNeed, name: str) -> list[GroundAtom] | None:
            """The reached facts that make ``name`` usable as the need's witness (None: it is not)."""
            seen = MEMBER if name in self.kept_members else name
            if seen != MEMBER and name not in self.allowed:
                return None
            if need.body:
                grounded = need.grounded(name)
                return grounded if all(fact in self.facts for fact in grounded) else None
            for predicate, at in need.consumed:
                facts = {reached.get((predicate, i, seen)) for i in at}
                if len(facts) == 1 and None not in facts:
                    return [fact for fact in facts if fact is not None]
            return None

        matched, unmatched = match_witnesses(needs, lambda need, name: made_usable(need, name) is not None)
        self.witnesses = matched
        by_goal = {need.goal: need for need in needs}
        self.witness_facts = [fact for goal, name in matched.items() for fact in made_usable(by_goal[goal], name) or ()]
        # the kept candidates the needs left without a witness cannot use yet: the way to them is missing
        self.stranded = frozenset(
            name
            for need in unmatched
            for name in need.candidates
            if (name in self.allowed or name in self.kept_members) and made_usable(need, name) is None
        )
        return unmatched

    def objects_of(self, type_name: str) -> list[str]:
        if type_name not in self.of_type:
            self.of_type[type_name] = sorted(
                o for o in self.allowed if self.domain.is_subtype(self.types_of.get(o, "object"), type_name)
            )
            self.fits[type_name] = frozenset(self.of_type[type_name])
        return self.of_type[type_name]

    def fits_of(self, schema: _Schema) -> dict[str, frozenset[str]]:
        """Each typed parameter of ``schema`` -> the kept objects of its type (untyped: anything)."""
        fits = self.variable_fits.get(id(schema))
        if fits is None:
            fits = {}
            for variable, type_name in zip(schema.parameters, schema.types):
                if type_name != "object":
                    self.objects_of(type_name)
                    fits[variable] = self.fits[type_name]
            self.variable_fits[id(schema)] = fits
        return fits

    def run(self, exhaust: bool = False) -> None:
        """Explore until the goal is reached (with ``exhaust``, until nothing new is)."""
        saturable, dominated, facts = self.saturable, self.dominated, self.facts
        saturated, variable_fits = self.saturated, self.variable_fits
        while self.queue and (self.missing or exhaust):
            fact = self.queue.popleft()
            self._index((fact,))
            for schema, i, rest in self.triggers.get(fact[0], ()):
                key = id(schema)
                if key in saturable and (key in saturated or self._saturated(schema)):
                    continue
                needs = dominated.get(key)
                if needs is not None and all(atom in facts for atom in needs):
                    continue
                fits = variable_fits.get(key)
                if fits is None:
                    fits = self.fits_of(schema)
                binding = _match(schema.pre[i][1], fact, {}, fits)
                if binding is None:
                    continue
                self.apply_joined(schema, rest, binding, fits)
        if self.shared is not None and self.missing:
            # the placeholder's facts are all found (the queue is empty): the members follow them
            self._spread()
            for atom in sorted(self.missing):
                name = next((arg for arg in atom[1:] if arg in self.kept_members), None)
                if name is not None:
                    pattern = self._pattern(atom)
                    if pattern is not None and self.holders.get(pattern, 0) & self._bit(name):
                        self._record(name, pattern)

    def _bit(self, name: str) -> int:
        bit = self.bit_of.get(name)
        if bit is None:
            bit = self.bit_of[name] = 1 << len(self.bit_of)
        return bit

    def _spread(self) -> None:
        """Carry the members' bits along the placeholder's steps to a fixpoint: a step passes on the
        bits its conditions on the placeholder all hold (every member's bit when it has none)."""
        holders, arrivals, spreading = self.holders, self.arrivals, self.spreading
        # a pattern waits in the queue once however many times its bits grow meanwhile: its steps
        # read its bits when they fire
        queued = set(spreading)
        everyone = 0
        for name in self.kept_members:
            everyone |= self._bit(name)
        for pattern, name in self.seeds:
            bit = self._bit(name)
            if not holders.get(pattern, 0) & bit:
                holders[pattern] = holders.get(pattern, 0) | bit
                arrivals[pattern].append((bit, None))
                if pattern not in queued:
                    queued.add(pattern)
                    spreading.append(pattern)
        self.seeds.clear()
        edges, work = self.edges, self.work

        def fire(index: int) -> None:
            needs, adds = edges[index][0], edges[index][1]
            if needs:
                bits = holders.get(needs[0], 0)
                for need in needs[1:]:
                    bits &= holders.get(need, 0)
            else:
                bits = everyone
            if not bits:
                return
            for pattern in adds:
                old = holders.get(pattern, 0)
                new = bits & ~old
                if new:
                    holders[pattern] = old | new
                    arrivals[pattern].append((new, index))
                    if pattern not in queued:
                        queued.add(pattern)
                        spreading.append(pattern)

        # steps found since the last spread, and those with no condition on the placeholder (new members)
        for index in range(self.edges_spread, len(edges)):
            fire(index)
        for index in range(self.edges_spread):
            if not edges[index][0]:
                fire(index)
        self.edges_spread = len(edges)
        while spreading:
            pattern = spreading.popleft()
            queued.discard(pattern)
            work.spend()
            for index in self.edges_from.get(pattern, ()):
                fire(index)

    def _record(self, name: str, pattern: GroundAtom) -> None:
        """The fact ``pattern`` stands for with member ``name``, and the facts the steps that first
        brought ``name`` there need, back to its initial ones, each with its step (what a relaxed
        plan walks back through)."""
        facts, edges, bit = self.facts, self.edges, self._bit(name)
        stack = [pattern]
        while stack:
            pattern = stack.pop()
            fact = tuple(name if arg == MEMBER else arg for arg in pattern)
            if fact in facts:
                continue
            index = next(step for bits, step in self.arrivals[pattern] if bits & bit)
            if index is None:
                facts[fact] = None
            else:
                needs, _, step, schema, binding = edges[index]
                own = {v: name if value == MEMBER else value for v, value in binding.items()}
                facts[fact] = _Achiever(tuple(name if arg == MEMBER else arg for arg in step), schema, own)
                stack.extend(needs)
            self.missing.discard(fact)

    def _edge(self, schema: _Schema, binding: Binding) -> None:
        """Record a step of the placeholder with the conditions on it that a member must reach first."""
        step = (schema.name,) + tuple(binding[v] for v in schema.parameters)
        if step in self.edge_steps:
            return
        self.edge_steps.add(step)
        needs = tuple(
            sorted(
                {
                    fact
                    for predicate, args in schema.pre
                    if MEMBER in (fact := (predicate, *(binding.get(a, a) for a in args)))
                }
            )
        )
        adds = tuple((predicate,) + tuple(binding.get(a, a) for a in args) for predicate, args, _ in schema.add)
        index = len(self.edges)
        self.edges.append((needs, adds, step, schema, binding))
        for fact in needs:
            self.edges_from[fact].append(index)

    def compatible(self, predicate: str, types: tuple[str | None, ...]) -> list[tuple[str, ...]]:
        """The signatures of processed ``predicate`` facts whose objects fit ``types`` (None: any)."""
        seen = self.signatures.get(predicate, ())
        cached = self.compatible_cache.get((predicate, types))
        if cached is not None and cached[0] == len(seen):
            return cached[1]
        fitting = [
            signature
            for signature in seen
            if all(t is None or t == "object" or self.domain.is_subtype(c, t) for c, t in zip(signature, types))
        ]
        self.compatible_cache[(predicate, types)] = (len(seen), fitting)
        return fitting

    def apply(self, schema: _Schema, binding: Binding, again: Set[str] | None = None) -> None:
        """Every step of ``schema`` that extends ``binding`` (whose values fit their types) adds its
        atoms; ``again``: the objects just added, when the application was made before them (then
        only the steps with one of them are new, unless an effect ranges over a type)."""
        if schema.bound_by_pre and len(binding) == len(schema.parameters):
            # the common case, kept short: the conditions bound every parameter, no effect ranges over a type
            if self.shared is not None and id(schema) in self.shared.variable:
                self._edge(schema, binding)
            facts, achiever = self.facts, None
            for predicate, args, _ in schema.add:
                fact = (predicate,) + tuple(binding.get(a, a) for a in args)
                if fact not in facts:
                    if achiever is None:
                        step = (schema.name,) + tuple(binding[v] for v in schema.parameters)
                        achiever = _Achiever(step, schema, binding)
                    facts[fact] = achiever
                    if predicate in self.counted:
                        self._count(fact)
                    self.queue.append(fact)
                    self.missing.discard(fact)
            return
        free = [(v, t) for v, t in zip(schema.parameters, schema.types) if v not in binding]
        if again is None and free and not schema.ranged:
            # The effects name only some of the bound parameters (a flight adds where the airplane is,
            # not where it came from): every binding that agrees on those adds the same atoms.
            key = (id(schema), *(value for variable, value in sorted(binding.items()) if variable in schema.in_effects))
            if key in self.effects_added:
                return
            self.effects_added.add(key)
        if again is None and (free or schema.ranged):
            self.ranging.append((schema, binding, frozenset(t for _, t in free) | schema.ranged))
        if again is not None and not schema.ranged:
            fills = _fill_fresh(binding, free, self.objects_of, self.work, again)
        else:
            fills = _fill(binding, free, self.objects_of, self.work)
        for full in fills:
            step = (schema.name,) + tuple(full[v] for v in schema.parameters)
            for predicate, args, quantified in schema.add:
                # a universally quantified effect adds its atom for every kept object of the variable's type
                for each in _fill(full, list(quantified), self.objects_of, self.work) if quantified else (full,):
                    fact = (predicate,) + tuple(each.get(a, a) for a in args)
                    if fact not in self.facts:
                        self.facts[fact] = _Achiever(step, schema, full)
                        if predicate in self.counted:
                            self._count(fact)
                        self.queue.append(fact)
                        self.missing.discard(fact)

    def apply_joined(
        self, schema: _Schema, pre: list[_Typed], binding: Binding, fits: Mapping[str, frozenset[str]]
    ) -> None:
        """:meth:`apply` ``schema`` for each extension of ``binding`` that matches processed facts of
        all of ``pre``, depth first, the condition with the fewest candidate facts joined first.
        ``apply`` adds facts but processes none, so the lists joined do not change under it."""
        if not pre:
            self.apply(schema, binding)
            return
        best, buckets = self.smallest(pre, binding)
        args = pre[best][1]
        rest = pre[:best] + pre[best + 1 :]
        spend = self.work.spend
        for bucket in buckets:
            for fact in bucket:
                spend()
                new = _match(args, fact, binding, fits)
                if new is None:
                    continue
                if rest:
                    self.apply_joined(schema, rest, new, fits)
                else:
                    self.apply(schema, new)

    def smallest(self, pre: list[_Typed], binding: Binding) -> tuple[int, list[Sequence[GroundAtom]]]:
        """The condition whose bound arguments leave the fewest processed facts, and those facts."""
        processed = self.processed
        best = 0
        best_buckets: list[Sequence[GroundAtom]] = []
        best_size: int | None = None
        buckets: list[Sequence[GroundAtom]]
        cache, seen = self.compatible_cache, self.signatures
        for j, (predicate, args, types) in enumerate(pre):
            cached = cache.get((predicate, types))
            if cached is not None and cached[0] == len(seen.get(predicate, ())):
                signatures = cached[1]  # compatible()'s answer, without the call
            else:
                signatures = self.compatible(predicate, types)
            if len(signatures) == 1:  # the common case (typed objects), without the lists of lists
                signature = signatures[0]
                bucket: Sequence[GroundAtom] = processed.get((predicate, signature), ())
                size = len(bucket)
                for position, arg in enumerate(args):
                    if not size:
                        break
                    value = binding.get(arg, arg) if arg[0] == "?" else arg
                    if value[0] != "?":
                        fewer: Sequence[GroundAtom] = processed.get((predicate, position, value, signature), ())
                        if len(fewer) < size:
                            bucket, size = fewer, len(fewer)
                buckets = [bucket]
            else:
                buckets = [processed.get((predicate, signature), []) for signature in signatures]
                size = sum(len(bucket) for bucket in buckets)
                for position, arg in enumerate(args):
                    value = binding.get(arg, arg) if arg[0] == "?" else arg
                    if value[0] != "?" and size:
                        narrower: list[Sequence[GroundAtom]] = [
                            processed.get((predicate, position, value, sig), []) for sig in signatures
                        ]
                        narrower_size = sum(len(bucket) for bucket in narrower)
                        if narrower_size < size:
                            buckets, size = narrower, narrower_size
            if best_size is None or size < best_size:
                best, best_buckets, best_size = j, buckets, size
                if size == 0 or len(pre) == 1:
                    break
        return best, best_buckets


def _match(args: Args, fact: GroundAtom, binding: Binding, fits: Mapping[str, frozenset[str]]) -> Binding | None:
    """``binding`` extended so that ``args`` match ``fact`` (a new value must fit its variable's type), or None."""
    if len(args) != len(fact) - 1:
        return None
    new = binding
    for arg, value in zip(args, fact[1:]):
        if arg[0] == "?":
            bound = new.get(arg)
            if bound is None:
                admitted = fits.get(arg)
                if admitted is not None and value not in admitted:
                    return None
                if new is binding:
                    new = dict(binding)
                new[arg] = value
            elif bound != value:
                return None
        elif arg != value:
            return None
    return new


def _fill(
    binding: Binding, free: list[tuple[str, str]], objects_of: Callable[[str], list[str]], work: Work
) -> Iterator[Binding]:
    if not free:
        yield binding
        return
    variable, type_name = free[0]
    for value in objects_of(type_name):
        work.spend()
        new = dict(binding)
        new[variable] = value
        yield from _fill(new, free[1:], objects_of, work)


def _fill_fresh(
    binding: Binding,
    free: list[tuple[str, str]],
    objects_of: Callable[[str], list[str]],
    work: Work,
    fresh: Set[str],
) -> Iterator[Binding]:
    """The bindings of :func:`_fill` with at least one value from ``fresh``: the ``i``-th free variable
    takes the first fresh value, those before it older ones."""
    for i, (_, fresh_type) in enumerate(free):
        firsts = [o for o in objects_of(fresh_type) if o in fresh]
        if not firsts:
            continue
        before = [[o for o in objects_of(t) if o not in fresh] for _, t in free[:i]]
        yield from _fill_parts(binding, free, [*before, firsts], objects_of, work)


def _fill_parts(
    binding: Binding,
    free: list[tuple[str, str]],
    values: list[list[str]],
    objects_of: Callable[[str], list[str]],
    work: Work,
) -> Iterator[Binding]:
    """Bindings of ``free`` taking the given ``values`` for the first variables, any object of its
    type for the rest."""
    if not free:
        yield binding
        return
    variable, type_name = free[0]
    for value in values[0] if values else objects_of(type_name):
        work.spend()
        new = dict(binding)
        new[variable] = value
        yield from _fill_parts(new, free[1:], values[1:], objects_of, work)


def _relaxed_plan(
    facts: Mapping[GroundAtom, _Achiever | None], goal: Sequence[GroundAtom]
) -> tuple[list[Step], set[str]]:
    plan: list[Step] = []
    objects: set[str] = set()
    done: set[GroundAtom] = set()
    stack = list(goal)
    seen_steps: set[Step] = set()
    while stack:
        fact = stack.pop()
        if fact in done:
            continue
        done.add(fact)
        objects.update(fact[1:])
        achiever = facts.get(fact)
        if achiever is None:
            continue
        step, schema, binding = achiever.step, achiever.schema, achiever.binding
        if step in seen_steps:
            continue
        seen_steps.add(step)
        plan.append(step)
        objects.update(a for a in step[1:] if a != "?")
        for predicate, args in schema.pre:
            stack.append((predicate,) + tuple(binding.get(a, a) for a in args))
    plan.reverse()
    return plan, objects
