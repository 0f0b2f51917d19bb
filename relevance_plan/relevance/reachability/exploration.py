"""The cheap reachability check before any planner call: relaxed reachability on the kept objects.

``relaxed_reachability`` grounds the actions on the kept objects only (joins
over the positive preconditions of the task's join schemas, ``schemas.py``, as
Fast Downward's translator explores the delete relaxation) and runs them to a
fixpoint, ignoring deletes.  If the goal's atoms are not reached, no plan
exists on that object set.  When they are, it returns the objects of a relaxed
plan (``relaxed_plan.py``): what at least one way of reaching the goal uses.
:class:`Exploration` is the same exploration on an object set that may grow
(the repair's, in ``selection.repair``); it reads its processed facts through
a :class:`~.joins.JoinIndex`.

Many goal objects of one class that never meet in an action (packages,
passengers) share one exploration through a placeholder and then advance
together, one bit each (``members.py``); the answer and the kind of relaxed
plan are those of the object-by-object exploration.

The check over-approximates: negative and quantified conditions and effect
conditions are ignored, an action with a disjunctive condition becomes one
schema per way through it (or ignores the disjunction where a way requires
no atom), and a universally quantified effect adds
its atom for every kept object of the type, so "unreachable" is sound.  It gives up (and says so)
past a work budget (``budget.py``), or a few seconds, rather than cost more than the planner would.
"""

from __future__ import annotations

import itertools
import math
from collections import defaultdict, deque
from collections.abc import Callable, Iterator, Mapping, Set
from dataclasses import dataclass

from relevance_plan.pddl.formulas import GroundAtom
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.analysis.witnesses import WitnessNeed, match_witnesses
from relevance_plan.relevance.reachability.budget import OutOfBudget, Work
from relevance_plan.relevance.reachability.joins import JoinIndex
from relevance_plan.relevance.reachability.members import SharedMembers
from relevance_plan.relevance.reachability.relaxed_plan import Achiever, relaxed_plan
from relevance_plan.relevance.reachability.schemas import (
    MEMBER,
    Args,
    Binding,
    JoinSchema,
    RelaxedTask,
    SharedClass,
    Step,
    TypedCondition,
    relaxed_task,
    required_atoms,
)

DEFAULT_BUDGET = 400_000  # bindings tried before the check gives up


@dataclass(frozen=True)
class Reachability:
    reachable: bool
    complete: bool  # False: the budget ran out, nothing is known
    unreached: tuple[GroundAtom, ...] = ()  # goal atoms the relaxation does not reach
    plan: tuple[Step, ...] = ()  # ground relaxed-plan steps (action, *args)
    plan_objects: frozenset[str] = frozenset()  # the relaxed plan's objects and the goal atoms' witnesses
    # goal atom -> the object it is met through, where it needs one of its own (``witnesses``)
    witnesses: tuple[tuple[GroundAtom, str], ...] = ()


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
        # the outcome may explore on, to the end, for the goal's witnesses: within the same budget
        return exploration.outcome()
    except OutOfBudget:
        return Reachability(False, False)


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
        self._prepare_facts(task, relaxed)
        self._prepare_joins()
        self._reach_start(relaxed)

    def _take_objects(self, task: PlanningTask, shared: SharedClass | None, kept: Set[str]) -> None:
        """The objects the exploration may use, and their types."""
        domain = self.domain
        self.shared = shared
        self.shared_members = SharedMembers(shared, kept)
        self.allowed = set(kept) - self.shared_members.kept | set(domain.constants)
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
        self.facts: dict[GroundAtom, Achiever | None] = {}  # the step that first reached each fact
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
        self.joins = JoinIndex(self.domain, self.types_of)
        # (schema, the values of the bound parameters its effects name) of applications with free parameters
        self.effects_added: set[tuple[object, ...]] = set()
        # applications that ranged over every kept object of some types: run again when those grow
        self.ranging: list[tuple[JoinSchema, Binding, frozenset[str]]] = []
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
        self._reach_initial(self.allowed | self.shared_members.kept, relaxed.nullary, static)
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
        sharing, init, timed = self.shared_members, self.init, self.timed
        allowed, members = self.allowed, sharing.members
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
                pattern = sharing.pattern(atom)
                if pattern is not None and fits(pattern[1:]) and atom in init:
                    found[pattern] = None
                    sharing.seeds.append((pattern, next(arg for arg in args if arg in members)))
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
        self.joins.index(indexed)
        # sorted: the same objects give the same relaxed plan whatever order they came in
        self.queue.extend(sorted(queued))

    def _count(self, fact: GroundAtom) -> None:
        type_of = self.types_of.get
        key = (fact[0], tuple([type_of(arg, "object") for arg in fact[1:]]))
        count = self.reached.get(key)
        if count is None:
            self.reached_signatures[fact[0]].append(key[1])
        self.reached[key] = (count or 0) + 1
        self.reached_total[fact[0]] = self.reached_total.get(fact[0], 0) + 1

    def _saturated(self, schema: JoinSchema) -> bool:
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
        sharing = self.shared_members
        new = {name for name in names if name not in self.allowed and name not in sharing.kept}
        if not new:
            return
        sharing.kept |= new & sharing.members
        self.allowed |= new - sharing.kept
        grown = set()
        for type_name, members in self.of_type.items():
            fitting = sorted(
                o for o in new - sharing.kept if self.domain.is_subtype(self.types_of.get(o, "object"), type_name)
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
        plan, objects = relaxed_plan(self.facts, [*self.goal, *self.witness_facts])
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
            seen = MEMBER if name in self.shared_members.kept else name
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
            if (name in self.allowed or name in self.shared_members.kept) and made_usable(need, name) is None
        )
        return unmatched

    def objects_of(self, type_name: str) -> list[str]:
        if type_name not in self.of_type:
            self.of_type[type_name] = sorted(
                o for o in self.allowed if self.domain.is_subtype(self.types_of.get(o, "object"), type_name)
            )
            self.fits[type_name] = frozenset(self.of_type[type_name])
        return self.of_type[type_name]

    def fits_of(self, schema: JoinSchema) -> dict[str, frozenset[str]]:
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
            self.joins.index((fact,))
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
            self.shared_members.follow(self.facts, self.missing, self.work)

    def apply(self, schema: JoinSchema, binding: Binding, again: Set[str] | None = None) -> None:
        """Every step of ``schema`` that extends ``binding`` (whose values fit their types) adds its
        atoms; ``again``: the objects just added, when the application was made before them (then
        only the steps with one of them are new, unless an effect ranges over a type)."""
        if schema.bound_by_pre and len(binding) == len(schema.parameters):
            # the common case, kept short: the conditions bound every parameter, no effect ranges over a type
            if self.shared is not None and id(schema) in self.shared.variable:
                self.shared_members.add_step(schema, binding)
            facts, achiever = self.facts, None
            for predicate, args, _ in schema.add:
                fact = (predicate,) + tuple(binding.get(a, a) for a in args)
                if fact not in facts:
                    if achiever is None:
                        step = (schema.name,) + tuple(binding[v] for v in schema.parameters)
                        achiever = Achiever(step, schema, binding)
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
                        self.facts[fact] = Achiever(step, schema, full)
                        if predicate in self.counted:
                            self._count(fact)
                        self.queue.append(fact)
                        self.missing.discard(fact)

    def apply_joined(
        self, schema: JoinSchema, pre: list[TypedCondition], binding: Binding, fits: Mapping[str, frozenset[str]]
    ) -> None:
        """:meth:`apply` ``schema`` for each extension of ``binding`` that matches processed facts of
        all of ``pre``, depth first, the condition with the fewest candidate facts joined first.
        ``apply`` adds facts but processes none, so the lists joined do not change under it."""
        if not pre:
            self.apply(schema, binding)
            return
        best, buckets = self.joins.smallest(pre, binding)
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
