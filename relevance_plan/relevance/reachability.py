"""A cheap sufficiency check before any planner call: relaxed reachability on the kept objects.

``relaxed_reachability`` grounds the actions on the kept objects only (joins
over the positive preconditions, as Fast Downward's translator explores the
delete relaxation) and runs them to a fixpoint, ignoring deletes.  If the
goal's atoms are not reached, no plan exists on that object set.  When they
are, it returns the objects of a relaxed plan: what at least one way of
reaching the goal uses.

``repair_selection`` is the step ``prune_with_scores`` runs after closure:
when the kept set fails the check, it adds the best-ranked missing objects in
doubling batches until the goal is relaxed-reachable, then keeps only the
added objects some relaxed plan uses (a truck, an airplane, the cells of a
path), each with the plan step that needs it as its reason.

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

import itertools
import math
import time
import weakref
from collections import defaultdict, deque
from collections.abc import Callable, Collection, Iterable, Iterator, Mapping, Sequence, Set
from dataclasses import dataclass, field, replace

from relevance_plan.pddl.formulas import Atom, Formula, GroundAtom, Or, conjuncts, effect_literals
from relevance_plan.pddl.model import Domain
from relevance_plan.relevance.analysis import ObjectGraph, fan_in, graph_distances
from relevance_plan.relevance.closure import Restored
from relevance_plan.relevance.task import PlanningTask
from relevance_plan.relevance.types import static_predicates

DEFAULT_BUDGET = 400_000  # bindings tried before the check gives up
DISJUNCTIVE_WAYS = 16  # ways through an action's disjunctive conditions the check splits it into
BUDGET_PER_OBJECT = 5_000  # the budget grows with the problem, as the planner's own grounding does
REPAIR_SECONDS = 5.0  # and the repair's checks together stop after this long
REPAIR_MAX_FAN = 4.0  # repair candidates are ranked by hops that do not pass from a class-like value to its members
DOMINANCE_TRIES = 8  # kept objects of its class a repair candidate is compared with
PAIRWISE_UP_TO = 64  # added objects of one class compared each with all others after the repair
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
    plan_objects: frozenset[str] = frozenset()


def _required_atoms(formula: Formula) -> Iterator[Condition]:
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
class _Compiled:
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


def _compiled(task: PlanningTask) -> _Compiled:
    cached = _COMPILED.get(task)
    if cached is None:
        problem = task.typing.problem
        timed = frozenset(
            literal.atom for literal in problem.timed_literals if literal.atom is not None and not literal.negated
        )
        static = static_predicates(task.typing.domain) - {
            literal.atom[0] for literal in problem.timed_literals if literal.atom
        }
        by_predicate = task.init_index.by_predicate
        nullary = frozenset(
            atom
            for predicate, parameters in task.typing.domain.predicates.items()
            if not parameters
            for atom in by_predicate.get(predicate, ())
            if atom in problem.init
        ) | frozenset(atom for atom in timed if len(atom) == 1)
        timed_by_object: dict[str, list[GroundAtom]] = defaultdict(list)
        for atom in sorted(timed):
            for name in dict.fromkeys(atom[1:]):
                timed_by_object[name].append(atom)
        schemas = _compiled_schemas(task)
        shared = None if problem.timed_literals else _shared_class(task, schemas)
        dominated = _dominated(task.typing.domain, schemas, shared.variable if shared else {})
        cached = _Compiled(
            schemas,
            frozenset(static),
            timed,
            {name: tuple(atoms) for name, atoms in timed_by_object.items()},
            nullary,
            shared,
            dominated,
        )
        _COMPILED[task] = cached
    return cached


_COMPILED: weakref.WeakKeyDictionary[PlanningTask, _Compiled] = weakref.WeakKeyDictionary()


def _compiled_schemas(task: PlanningTask) -> list[_Schema]:
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
    typed = dict(domain.constants)
    typed.update(problem.objects)
    members: dict[str, list[str]] = {}

    def implied(predicate: str, type_name: str) -> bool:
        if type_name not in members:
            members[type_name] = [o for o, t in typed.items() if domain.is_subtype(t, type_name)]
        held = holders[predicate]
        return all(o in held for o in members[type_name])

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
    goal = [(p, *args) for p, args in _required_atoms(problem.goal)]
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


class _OutOfBudget(Exception):
    pass


@dataclass
class _Work:
    """Bindings tried by one check, against its budget and its deadline (``time.monotonic()``)."""

    limit: int
    deadline: float = math.inf
    done: int = 0

    def spend(self) -> None:
        self.done += 1
        # the clock is read once every 4,096 bindings: cheap, and still within milliseconds
        if self.done > self.limit or (not self.done & 4095 and time.monotonic() > self.deadline):
            raise _OutOfBudget


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
        exploration = _Exploration(task, kept, _Work(budget, deadline))
        exploration.run()
    except _OutOfBudget:
        return Reachability(False, False)
    return exploration.outcome()


class _Exploration:
    """The delete-relaxed exploration of :func:`relaxed_reachability`, on an object set that may grow.

    :meth:`add` brings in more objects and :meth:`run` carries on from where
    it stopped, so growing a selection one object at a time costs about one
    exploration of the final set.
    """

    def __init__(self, task: PlanningTask, kept: Set[str], work: _Work):
        domain, problem = task.typing.domain, task.typing.problem
        compiled = _compiled(task)
        self.domain = domain
        self.work = work
        self.shared = compiled.shared
        self.dominated = compiled.dominated
        self.members = self.shared.members if self.shared else frozenset()  # of the shared class, kept or not
        # with a shared class, its kept members are not objects of the exploration: MEMBER stands for them
        self.kept_members: set[str] = set(kept) & self.members
        self.allowed = set(kept) - self.kept_members | set(domain.constants)
        self.types_of = dict(domain.constants)
        self.types_of.update(problem.objects)
        if self.shared is not None:
            self.allowed.add(MEMBER)
            self.types_of[MEMBER] = self.shared.name
        # the placeholder's steps, each with its conditions on the placeholder (shared class only)
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
        self.goal = [(p, *args) for p, args in _required_atoms(problem.goal) if not any(a[0] == "?" for a in args)]
        self.facts: dict[GroundAtom, _Achiever | None] = {}  # the step that first reached each fact
        self.queue: deque[GroundAtom] = deque()
        self.by_object = task.init_index.by_object
        self.init = problem.init
        # the index also holds numeric terms, (distance a b), which are not facts
        self.numeric_terms = bool(problem.numeric_init)
        # timed initial literals that make a fact true count as reached: a plan may wait for them
        self.timed = compiled.timed
        self.timed_by_object = compiled.timed_by_object
        self.of_type: dict[str, list[str]] = {}
        self.fits: dict[str, frozenset[str]] = {}
        self.schemas = compiled.schemas
        # predicate -> (schema, the condition it matches, the schema's other conditions with their types)
        self.triggers: dict[str, list[tuple[_Schema, int, list[_Typed]]]] = defaultdict(list)
        self.conditions: dict[int, list[_Typed]] = {}
        for schema in self.schemas:
            type_of = dict(zip(schema.parameters, schema.types))
            typed = [
                (predicate, args, tuple(type_of.get(a) if a[0] == "?" else None for a in args))
                for predicate, args in schema.pre
            ]
            self.conditions[id(schema)] = typed
            for i, (predicate, _) in enumerate(schema.pre):
                self.triggers[predicate].append((schema, i, typed[:i] + typed[i + 1 :]))
        self.variable_fits: dict[int, dict[str, frozenset[str]]] = {}
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
        self.missing = set(self.goal)
        # How many reached facts of each (predicate, signature) a saturable schema adds, to pass over
        # the schemas that have nothing left to add (every floor reached: no more joins of ``up``).
        # The placeholder's steps are never passed over: each member follows them.
        shared_steps = self.shared.variable if self.shared else {}
        self.saturable = {id(s): s for s in self.schemas if s.saturable and id(s) not in shared_steps}
        self.counted = {predicate for s in self.saturable.values() for predicate, _, _ in s.add}
        self.reached: dict[tuple[str, tuple[str, ...]], int] = {}
        self.reached_signatures: dict[str, list[tuple[str, ...]]] = defaultdict(list)
        self.reached_total: dict[str, int] = {}
        self.saturated: set[int] = set()
        self.saturation_needs: dict[int, list[tuple[str, tuple[str, ...], int]]] = {}  # until objects are added
        # The initial static facts (a map, the floors above each other) are indexed at once and trigger
        # nothing: every dynamic fact is processed after them, and its joins find them.  Only the
        # schemas whose conditions are all static need a join of their own.
        static = compiled.static
        self._reach_initial(self.allowed | self.kept_members, compiled.nullary, static)
        for schema in self.schemas:
            if not schema.pre:
                self.apply(schema, {})
            elif all(predicate in static for predicate, _ in schema.pre):
                for binding in self.join(self.conditions[id(schema)], {}, self.fits_of(schema)):
                    self.apply(schema, binding)

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
        key = (fact[0], tuple(self.types_of.get(arg, "object") for arg in fact[1:]))
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
        plan, objects = _relaxed_plan(self.facts, self.goal)
        return Reachability(True, True, (), tuple(plan), frozenset(objects) - set(self.domain.constants))

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

    def run(self) -> None:
        saturable, dominated, facts = self.saturable, self.dominated, self.facts
        while self.queue and self.missing:
            fact = self.queue.popleft()
            self._index((fact,))
            for schema, i, rest in self.triggers.get(fact[0], ()):
                if id(schema) in saturable and self._saturated(schema):
                    continue
                needs = dominated.get(id(schema))
                if needs is not None and all(atom in facts for atom in needs):
                    continue
                fits = self.fits_of(schema)
                binding = _match(schema.pre[i][1], fact, {}, fits)
                if binding is None:
                    continue
                # apply() adds facts but never processes them: the join's lists do not change under it
                for found in self.join(rest, binding, fits):
                    self.apply(schema, found)
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

    def join(self, pre: list[_Typed], binding: Binding, fits: Mapping[str, frozenset[str]]) -> Iterator[Binding]:
        if not pre:
            yield binding
            return
        best, buckets = self.smallest(pre, binding)
        args = pre[best][1]
        rest = pre[:best] + pre[best + 1 :]
        for bucket in buckets:
            for fact in bucket:
                self.work.spend()
                new = _match(args, fact, binding, fits)
                if new is not None:
                    yield from self.join(rest, new, fits)

    def smallest(self, pre: list[_Typed], binding: Binding) -> tuple[int, list[list[GroundAtom]]]:
        """The condition whose bound arguments leave the fewest processed facts, and those facts."""
        processed = self.processed
        best = 0
        best_buckets: list[list[GroundAtom]] = []
        best_size: int | None = None
        for j, (predicate, args, types) in enumerate(pre):
            signatures = self.compatible(predicate, types)
            buckets = [processed.get((predicate, signature), []) for signature in signatures]
            size = sum(len(bucket) for bucket in buckets)
            for position, arg in enumerate(args):
                value = binding.get(arg, arg) if arg[0] == "?" else arg
                if value[0] != "?" and size:
                    narrower = [processed.get((predicate, position, value, signature), []) for signature in signatures]
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
    binding: Binding, free: list[tuple[str, str]], objects_of: Callable[[str], list[str]], work: _Work
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
    work: _Work,
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
    work: _Work,
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


# closure over constraints: (names, a subset of them already closed) -> (closed set, what it put back and why)
CloseFn = Callable[[Set[str], Set[str]], tuple[frozenset[str], tuple[Restored, ...]]]


def repair_selection(
    task: PlanningTask,
    kept: frozenset[str],
    scores: Mapping[str, float],
    close: CloseFn,
    budget: int | None = None,
    give_up_above: int | None = None,
) -> tuple[frozenset[str], tuple[Restored, ...], Reachability]:
    """Add what the relaxed goal needs to ``kept``; returns (kept, what was put back and why, the last check).

    Candidates are tried best first: one member of every class the kept set
    lacks, then by score, then by hops from the kept objects in the initial
    state; ``close`` is closure over constraints (it returns the closed set
    and its own reasons).  ``budget`` bounds each check (default: grows with
    the problem); past ``give_up_above`` kept objects the search stops and
    returns what it has.
    """
    total = len(task.problem.objects)
    if budget is None:
        budget = max(DEFAULT_BUDGET, BUDGET_PER_OBJECT * total)
    if give_up_above is None:
        give_up_above = total
    deadline = min(time.monotonic() + REPAIR_SECONDS, math.inf if task.deadline is None else task.deadline)
    try:
        exploration = _Exploration(task, kept, _Work(budget, deadline))
        exploration.run()
    except _OutOfBudget:
        task.check_time("checking the selection")  # the --timeout, not the repair's own bound
        return kept, (), Reachability(False, False)
    check = exploration.outcome()
    if check.reachable:
        return _sharpen(task, kept, kept, (), check, scores, close, give_up_above)
    # One member of every class the kept set lacks first (no airplane at all), together; then, round by
    # round, the objects between what is reached and the goal atoms still unreached: one at a time at
    # first (one airplane may carry every package), then a quarter of what was added, or as many as
    # the last round's rate of goal atoms says are needed.  The exploration carries on from where it
    # stopped, so the whole growth costs about one exploration of the final set.
    toward = _Toward(task, scores)
    take = toward.missing_classes(kept)
    current = kept
    added: list[str] = []
    estimate = 0  # objects still needed, judged by what the last round's objects reached
    try:
        while exploration.missing:
            if not take:
                batch = max(1, (len(current) - len(kept)) // 4, min(estimate, 2 * (len(current) - len(kept))))
                unreached = {arg for atom in exploration.missing for arg in atom[1:]}
                take = toward.nearest(current, unreached, batch, exploration.facts)
                if not take:
                    break
            grown, _ = close(current | frozenset(take), current)
            added += take + sorted(grown - current - set(take))
            if len(grown) > give_up_above:
                current = grown
                break  # it would keep most of the problem anyway: checking costs more than it saves
            before = len(exploration.missing)
            exploration.add(grown - current)
            current = grown
            exploration.run()
            brought = before - len(exploration.missing)
            toward.learn(take, brought > 0)
            # one truck brought its city's packages home: about as many more as cities still waiting
            estimate = -(-len(take) * len(exploration.missing) // brought) if brought > 0 else 0
            take = []
        check = exploration.outcome()
    except _OutOfBudget:
        task.check_time("checking the selection")
        check = Reachability(False, False)
    rank = {name: i for i, name in enumerate(added)}
    if not check.reachable:
        # Nothing short of the whole problem reaches the goal (or the check gave up): let the planner decide.
        unchecked = frozenset(current) - kept
        return frozenset(current), tuple(Restored(n, "", "reachability", ("goal",)) for n in sorted(unchecked)), check
    classes = task.typing.problem.objects
    used = {name for name in check.plan_objects if name in task.problem.objects and name not in kept}
    reached = exploration.facts
    used, check = _economize(
        task,
        kept,
        used,
        classes,
        rank,
        check,
        close,
        budget,
        deadline,
        lambda members: toward.interchangeable(members, reached),
        lambda name, others: toward.stood_in_for(name, others, reached),
    )
    step_of: dict[str, Step] = {}
    for step in check.plan:
        for arg in step[1:]:
            step_of.setdefault(arg, step)
    reasons = [
        Restored(name, "", "reachability", step_of.get(name, ("goal",)))
        for name in sorted(used, key=lambda n: (rank.get(n, len(rank)), n))
    ]
    closed, closure_reasons = close(kept | frozenset(used), kept)
    reasons.extend(r for r in closure_reasons if r.name not in used and r.name not in kept)
    return _sharpen(task, kept, closed, tuple(reasons), check, scores, close, give_up_above)


def _sharpen(
    task: PlanningTask,
    kept: frozenset[str],
    closed: frozenset[str],
    reasons: tuple[Restored, ...],
    check: Reachability,
    scores: Mapping[str, float],
    close: CloseFn,
    give_up_above: int,
) -> tuple[frozenset[str], tuple[Restored, ...], Reachability]:
    """On a temporal or numeric problem, a selection the delete relaxation admits but the sharper
    relaxation of ``timed_relaxation`` refutes (fuel no kept action can give, a durative action's end
    out of reach) has no plan: add the best-ranked objects, a doubling batch at a time, until it is
    admitted (or the planner decides, past ``give_up_above``)."""
    from relevance_plan.relevance.timed_relaxation import applies, timed_relaxed_reachability

    if not applies(task) or timed_relaxed_reachability(task, closed) is not False:
        return closed, reasons, check
    distance = task.goal_distance
    far = len(task.problem.objects) + 1
    ranked = _lacking_classes_first(
        sorted(
            (name for name in task.problem.objects if name not in closed),
            key=lambda name: (-scores.get(name, 0.0), distance.get(name, far), name),
        ),
        closed,
        task.typing.problem.objects,
    )
    current, added, batch = closed, list(reasons), 1
    while ranked and len(current) <= give_up_above:
        take, ranked = ranked[:batch], ranked[batch:]
        grown, more = close(current | frozenset(take), current)
        added += [Restored(name, "", "reachability", ("goal",)) for name in take]
        added += [r for r in more if r.name not in current and r.name not in take]
        current = grown
        ranked = [name for name in ranked if name not in current]
        task.check_time("checking the selection")
        if timed_relaxed_reachability(task, current) is not False:
            break
        batch = max(1, len(current) - len(kept))
    return current, tuple(added), check


def _lacking_classes_first(ranked: Sequence[str], selected: Set[str], classes: Mapping[str, str]) -> list[str]:
    """``ranked`` with the best candidate of each class ``selected`` has no member of moved to the front.

    The sharper check says only that the selection fails, not what it lacks: as the repair does,
    one member of every missing class comes first, so sixty agents tied at score 0 do not all come
    before the one tap the agents need to fill up."""
    present = {classes.get(name, "object") for name in selected}
    first: dict[str, str] = {}
    for name in ranked:
        first.setdefault(classes.get(name, "object"), name)
    front = [name for cls, name in first.items() if cls not in present]
    chosen = set(front)
    return front + [name for name in ranked if name not in chosen]


class _Toward:
    """The order in which the repair adds objects (see :func:`repair_selection`)."""

    def __init__(self, task: PlanningTask, scores: Mapping[str, float]):
        self.task = task
        self.scores = scores
        self.hub = hub_degree(task)
        # the initial facts' links, walked once or twice a round
        self.graph = ObjectGraph(task.init_index, REPAIR_MAX_FAN, fan_in(task.init_index))
        self.toward_unreached: tuple[frozenset[str], dict[str, int]] = (frozenset(), {})
        self.classes = task.typing.problem.objects
        self.timed = bool(task.typing.problem.timed_literals)
        self.static = _compiled(task).static
        # where the one agent is (the robot's place: the objects of a changing predicate's only
        # initial fact): what it reaches grows from there before any step is found
        self.agents = {
            arg
            for predicate in task.init_index.singletons
            if predicate not in self.static
            for atom in task.init_index.by_predicate[predicate]
            for arg in atom[1:]
        }
        # class -> rounds in a row its objects brought no goal atom nearer: a second airplane adds
        # nothing to a relaxed plan that has one, a truck in another city does
        self.fruitless: dict[str, int] = {}

    def learn(self, taken: Sequence[str], progress: bool) -> None:
        for cls in {self.classes.get(name, "object") for name in taken}:
            self.fruitless[cls] = 0 if progress else self.fruitless.get(cls, 0) + 1

    def missing_classes(self, kept: Set[str]) -> list[str]:
        """The best-ranked member (score, then hops from ``kept``) of every class ``kept`` has none of."""
        present = {self.classes[name] for name in kept if name in self.classes}
        distance = graph_distances(self.task.init_index, self.graph, kept, self.hub)
        best: dict[str, tuple[float, int, str]] = {}
        far = len(self.classes) + 1
        for name, cls in self.classes.items():
            if cls in present or name in kept:
                continue
            key = (-self.scores.get(name, 0.0), distance.get(name, far), name)
            if cls not in best or key < best[cls]:
                best[cls] = key
        return sorted(key[2] for key in best.values())

    def nearest(
        self, current: Set[str], unreached: Set[str], count: int, reached: Mapping[GroundAtom, object]
    ) -> list[str]:
        """While a goal object is named by no reached fact, the objects of one shortest way toward it
        (:meth:`_path`).  Otherwise the ``count`` objects outside ``current`` on the shortest ways
        in the initial state between the objects of facts a step reached (and the agent's place)
        and ``unreached`` (objects of goal atoms not reached yet): fewest hops from the one plus
        to the other, then nearest to ``unreached``, classes that helped before those that did
        not, then best scored.  Passed over, as they add
        nothing: an object a kept one of its class can stand in for (an airplane at an airport
        another kept airplane flies to), and one whose every link is to objects not kept while a
        kept one has its properties (an airplane parked at an airport not kept); when nothing else
        is left, the latter, then any."""
        index = self.task.init_index
        if self.toward_unreached[0] != unreached:  # the same goal atoms stay unreached for many rounds
            self.toward_unreached = (frozenset(unreached), graph_distances(index, self.graph, unreached, self.hub))
        distance = self.toward_unreached[1]
        far = len(self.classes) + 1
        sources = {arg for fact, achiever in reached.items() if achiever is not None for arg in fact[1:]}
        sources.update(self.agents)
        sources.discard(MEMBER)
        path = self._path(unreached - sources, sources - unreached, current)
        if path:
            return path
        between = graph_distances(index, self.graph, sources, self.hub) if sources else {}
        fruitless, classes = self.fruitless, self.classes
        ranked = sorted(
            (name for name in classes if name not in current),
            key=lambda name: (
                distance.get(name, far) + between.get(name, far if sources else 0),
                distance.get(name, far),
                fruitless.get(classes[name], 0),
                -self.scores.get(name, 0.0),
                name,
            ),
        )
        kept_of: dict[str, list[str]] = {}
        chosen: list[str] = []
        detached: list[str] = []
        for name in ranked:
            if len(chosen) == count:
                break
            cls = classes[name]
            if cls not in kept_of:
                kept_of[cls] = sorted(n for n in current if classes.get(n) == cls)[:DOMINANCE_TRIES]
            if self.stood_in_for(name, kept_of[cls], reached):
                continue
            if self._detached(name, kept_of[cls], reached, current):
                detached.append(name)
            else:
                chosen.append(name)
        return chosen or detached[:count] or ranked[:count]

    def _path(self, targets: Set[str], sources: Set[str], current: Set[str]) -> list[str]:
        """The objects outside ``current`` on one shortest way in the initial state from the source
        nearest to ``targets`` (goal objects no reached fact names yet) down to one of them: a
        corridor of cells from where the robot can go to the goal's place, not every cell of the
        rectangle between them."""
        if not targets or not sources:
            return []
        distance = graph_distances(self.task.init_index, self.graph, targets, self.hub)
        start = min((name for name in sources if name in distance), key=lambda n: (distance[n], n), default=None)
        walk: list[str] = []
        name = start
        while name is not None and distance[name] > 0:
            lower = distance[name] - 1
            # the first by name: the facts' order, and so the neighbours', changes from run to run
            name = min((o for o in self.graph.neighbours(name) if distance.get(o) == lower), default=None)
            if name is not None and name not in current and name in self.classes:
                walk.append(name)
        return walk

    def _detached(self, name: str, others: Sequence[str], reached: Mapping[GroundAtom, object], kept: Set[str]) -> bool:
        """Whether ``name``'s links to other objects are all where it is now (facts that change) and
        name objects not ``kept``, and one of ``others`` has reached its facts about itself alone:
        alone, it adds nothing."""
        atoms = self.task.init_index.by_object.get(name, ())
        classes = self.classes
        linked = [atom for atom in atoms if len(atom) > 2]
        if not linked or any(
            atom[0] in self.static or all(a == name or a in kept or a not in classes for a in atom[1:])
            for atom in linked
        ):
            return False  # a static link (a road, a door) is part of a way that may be needed
        return self.stood_in_for(name, others, reached, [atom for atom in atoms if len(atom) <= 2])

    def interchangeable(self, members: Sequence[str], reached: Mapping[GroundAtom, object]) -> bool:
        """Whether one of ``members`` (of one class) can stand in for another (``reached``: what the
        exploration of them all reached)."""
        return any(
            self.stood_in_for(name, [o for o in members if o != name][:DOMINANCE_TRIES], reached) for name in members
        )

    def stood_in_for(
        self,
        name: str,
        others: Sequence[str],
        reached: Mapping[GroundAtom, object],
        atoms: Collection[GroundAtom] | None = None,
    ) -> bool:
        """Whether one of ``others`` (kept, of ``name``'s class) has reached every initial fact of
        ``name`` (or every one of ``atoms``) with ``name`` renamed to it: then whatever ``name`` could
        do in the relaxation, it can do too (an airplane parked at an airport another kept airplane
        can fly to)."""
        if self.timed:
            return False  # a timed fact of ``name`` is not among the initial ones
        facts = self.task.init_index.by_object.get(name, ()) if atoms is None else atoms
        return any(
            all(tuple(other if arg == name else arg for arg in atom) in reached for atom in facts) for other in others
        )


def _economize(
    task: PlanningTask,
    kept: frozenset[str],
    used: set[str],
    classes: Mapping[str, str],
    rank: Mapping[str, int],
    check: Reachability,
    close: CloseFn,
    budget: int,
    deadline: float,
    interchangeable: Callable[[Sequence[str]], bool],
    stood_in_for: Callable[[str, Sequence[str]], bool],
) -> tuple[set[str], Reachability]:
    """Fewer added objects of one class where fewer do: a relaxed plan takes the first airplane it
    meets for each package, when one airplane carries them all.  Class by class (most members
    first), keep the member the current relaxed plan uses most, alone, if the goal stays
    relaxed-reachable, else drop the less used half while it does; what the last relaxed plan no
    longer uses goes too.  A few checks, each on the small kept set.  In a class none of whose
    members can stand in for most others (a truck in each city), only those another member can
    stand in for go (a second truck in one city, added in the same round as the first)."""
    by_class: dict[str, list[str]] = {}
    for name in used:
        by_class.setdefault(classes.get(name, "object"), []).append(name)
    for cls in sorted((c for c in by_class if len(by_class[c]) > 1), key=lambda c: (-len(by_class[c]), c)):
        if not interchangeable(sorted(by_class[cls])):
            members = _by_use(by_class[cls], check, rank)
            if len(members) <= PAIRWISE_UP_TO:
                dropped: list[str] = []
                for name in reversed(members):  # the least used first
                    if stood_in_for(name, [m for m in members if m != name and m not in dropped]):
                        dropped.append(name)
                if dropped:
                    trial_used, trial = _without(task, kept, used, dropped, close, budget, deadline)
                    if trial is not None and len(trial_used) < len(used):
                        used, check = trial_used, trial
            continue
        while True:
            members = _by_use([m for m in by_class[cls] if m in used], check, rank)
            if len(members) < 2:
                break
            trial_used, trial = _without(task, kept, used, members[1:], close, budget, deadline)
            if trial is None and len(members) > 3:
                trial_used, trial = _without(task, kept, used, members[len(members) // 2 :], close, budget, deadline)
            if trial is None or len(trial_used) >= len(used):
                break  # no smaller set reaches the goal (closure may bring the dropped ones back)
            used, check = trial_used, trial
    return used, check


def _by_use(members: list[str], check: Reachability, rank: Mapping[str, int]) -> list[str]:
    uses: dict[str, int] = {}
    for step in check.plan:
        for arg in step[1:]:
            uses[arg] = uses.get(arg, 0) + 1
    return sorted(members, key=lambda n: (-uses.get(n, 0), rank.get(n, len(rank)), n))


def _without(
    task: PlanningTask,
    kept: frozenset[str],
    used: set[str],
    dropped: list[str],
    close: CloseFn,
    budget: int,
    deadline: float,
) -> tuple[set[str], Reachability | None]:
    """``used`` without ``dropped`` (and without what its relaxed plan then leaves unused), if the goal
    stays relaxed-reachable."""
    trial = used - set(dropped)
    closed, _ = close(kept | frozenset(trial), kept)
    attempt = relaxed_reachability(task, closed, budget, deadline)
    if not attempt.reachable:
        return used, None
    # what the relaxed plan uses, closure's additions included (they stay only through their cause)
    needed = {n for n in attempt.plan_objects if n in closed and n not in kept}
    return needed or trial, attempt


def hub_degree(task: PlanningTask) -> int:
    """Objects in more initial facts than this (a shape every key has, a floor above all others) link
    everything to everything: distances do not pass through them."""
    return max(16, int(2 * len(task.problem.objects) ** 0.5))
