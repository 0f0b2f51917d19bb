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

The check over-approximates: negative, disjunctive and quantified conditions
and effect conditions are ignored, and a universally quantified effect adds
its atom for every kept object of the type, so "unreachable" is sound.  It gives up (and says so)
past a work budget, or a few seconds, rather than cost more than the planner would.
"""

from __future__ import annotations

import math
import time
from collections import defaultdict, deque
from collections.abc import Callable, Iterator, Mapping, Sequence, Set
from dataclasses import dataclass
from typing import TYPE_CHECKING

from relevance_plan.pddl.formulas import Atom, Formula, GroundAtom, conjuncts, effect_literals
from relevance_plan.pddl.model import Domain, Problem
from relevance_plan.relevance.analysis import object_distances
from relevance_plan.relevance.closure import Restored

if TYPE_CHECKING:  # the scorers' package imports this module's users
    from relevance_plan.relevance.scorers.base import PlanningTask

DEFAULT_BUDGET = 400_000  # bindings tried before the check gives up
BUDGET_PER_OBJECT = 5_000  # the budget grows with the problem, as the planner's own grounding does
REPAIR_SECONDS = 5.0  # and the repair's checks together stop after this long
REPAIR_MAX_FAN = 4.0  # repair candidates are ranked by hops that do not pass from a class-like value to its members

Args = tuple[str, ...]  # a condition's or an effect's arguments: variables (``?x``) and names
Condition = tuple[str, Args]  # (predicate, args)
Binding = dict[str, str]  # variable -> object
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


@dataclass(frozen=True)
class _Schema:
    name: str
    parameters: tuple[str, ...]  # variables
    types: tuple[str, ...]
    pre: tuple[Condition, ...]
    add: tuple[tuple[str, Args, tuple[tuple[str, str], ...]], ...]  # (predicate, args, quantified (variable, type)s)


def _schemas(domain: Domain) -> list[_Schema]:
    """The relaxed actions (derived rules included) as join schemas; effect conditions are ignored."""
    result = []
    for action in domain.relaxed_actions:
        pre = tuple(_required_atoms(action.precondition))
        add = tuple(
            (item.atom.predicate, item.atom.args, tuple((v, t) for v, t in item.quantified if v in item.atom.args))
            for item in effect_literals(action.effect)
            if item.is_add
        )
        variables = tuple(v for v, _ in action.parameters)
        result.append(_Schema(action.name, variables, tuple(t for _, t in action.parameters), pre, add))
    return result


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
    typing = task.typing
    exploration = _Exploration(typing.domain, typing.problem, kept, _Work(budget, deadline))
    try:
        exploration.run()
    except _OutOfBudget:
        return Reachability(False, False)
    goal, facts = exploration.goal, exploration.facts
    unreached = tuple(atom for atom in goal if atom not in facts)
    if unreached:
        return Reachability(False, True, unreached)
    plan, objects = _relaxed_plan(facts, goal)
    return Reachability(True, True, (), tuple(plan), frozenset(objects) - set(typing.domain.constants))


class _Exploration:
    """The delete-relaxed exploration of :func:`relaxed_reachability` on one object set."""

    def __init__(self, domain: Domain, problem: Problem, kept: Set[str], work: _Work):
        self.domain = domain
        self.work = work
        self.allowed = set(kept) | set(domain.constants)
        self.types_of = dict(domain.constants)
        self.types_of.update(problem.objects)
        self.goal = [(p, *args) for p, args in _required_atoms(problem.goal) if not any(a[0] == "?" for a in args)]
        self.facts: dict[GroundAtom, _Achiever | None] = {}  # the step that first reached each fact
        self.queue: deque[GroundAtom] = deque()
        # sorted: the same objects give the same relaxed plan whatever order the set was built in;
        # timed initial literals that make a fact true count as reached: a plan may wait for them
        timed = {literal.atom for literal in problem.timed_literals if literal.atom is not None and not literal.negated}
        for atom in sorted(atom for atom in problem.init | timed if all(arg in self.allowed for arg in atom[1:])):
            self.facts[atom] = None
            self.queue.append(atom)
        self.of_type: dict[str, list[str]] = {}
        self.fits: dict[str, frozenset[str]] = {}
        self.schemas = _schemas(domain)
        self.triggers: dict[str, list[tuple[_Schema, int]]] = defaultdict(list)
        for schema in self.schemas:
            for i, (predicate, _) in enumerate(schema.pre):
                self.triggers[predicate].append((schema, i))
        # (predicate, position, value) -> facts; (predicate,) -> facts
        self.processed: dict[tuple[str | int, ...], list[GroundAtom]] = defaultdict(list)
        self.missing = set(self.goal) - set(self.facts)

    def objects_of(self, type_name: str) -> list[str]:
        if type_name not in self.of_type:
            self.of_type[type_name] = sorted(
                o for o in self.allowed if self.domain.is_subtype(self.types_of.get(o, "object"), type_name)
            )
            self.fits[type_name] = frozenset(self.of_type[type_name])
        return self.of_type[type_name]

    def run(self) -> None:
        for schema in self.schemas:
            if not schema.pre:
                self.apply(schema, {})
        while self.queue and self.missing:
            fact = self.queue.popleft()
            self.processed[(fact[0],)].append(fact)
            for position, value in enumerate(fact[1:]):
                self.processed[(fact[0], position, value)].append(fact)
            for schema, i in self.triggers.get(fact[0], ()):
                binding = _match(schema.pre[i][1], fact, {})
                if binding is None:
                    continue
                for found in list(self.join(list(schema.pre[:i] + schema.pre[i + 1 :]), binding)):
                    self.apply(schema, found)

    def apply(self, schema: _Schema, binding: Binding) -> None:
        for variable, type_name in zip(schema.parameters, schema.types):
            if type_name == "object":
                continue
            if type_name not in self.fits:
                self.objects_of(type_name)
            if variable in binding and binding[variable] not in self.fits[type_name]:
                return
        free = [(v, t) for v, t in zip(schema.parameters, schema.types) if v not in binding]
        for full in _fill(binding, free, self.objects_of, self.work):
            step = (schema.name,) + tuple(full[v] for v in schema.parameters)
            for predicate, args, quantified in schema.add:
                # a universally quantified effect adds its atom for every kept object of the variable's type
                for each in _fill(full, list(quantified), self.objects_of, self.work):
                    fact = (predicate,) + tuple(each.get(a, a) for a in args)
                    if fact not in self.facts:
                        self.facts[fact] = _Achiever(step, schema, full)
                        self.queue.append(fact)
                        self.missing.discard(fact)

    def join(self, pre: list[Condition], binding: Binding) -> Iterator[Binding]:
        if not pre:
            yield binding
            return
        best, best_key = self.smallest(pre, binding)
        predicate, args = pre[best]
        rest = pre[:best] + pre[best + 1 :]
        for fact in self.processed.get(best_key, ()):
            self.work.spend()
            new = _match(args, fact, binding)
            if new is not None:
                yield from self.join(rest, new)

    def smallest(self, pre: list[Condition], binding: Binding) -> tuple[int, tuple[str | int, ...]]:
        """The condition whose bound arguments leave the fewest processed facts, and that index key."""
        best: int = 0
        best_key: tuple[str | int, ...] = (pre[0][0],)
        best_size: int | None = None
        for j, (predicate, args) in enumerate(pre):
            key: tuple[str | int, ...] = (predicate,)
            size = len(self.processed.get(key, ()))
            for position, arg in enumerate(args):
                value = binding.get(arg, arg) if arg[0] == "?" else arg
                if value[0] != "?":
                    candidate = (predicate, position, value)
                    candidate_size = len(self.processed.get(candidate, ()))
                    if candidate_size < size:
                        key, size = candidate, candidate_size
            if best_size is None or size < best_size:
                best, best_key, best_size = j, key, size
                if size == 0:
                    break
        return best, best_key


def _match(args: Args, fact: GroundAtom, binding: Binding) -> Binding | None:
    if len(args) != len(fact) - 1:
        return None
    new = binding
    for arg, value in zip(args, fact[1:]):
        if arg.startswith("?"):
            bound = new.get(arg)
            if bound is None:
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


CloseFn = Callable[[Set[str]], tuple[frozenset[str], tuple[Restored, ...]]]


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
    deadline = time.monotonic() + REPAIR_SECONDS
    check = relaxed_reachability(task, kept, budget, deadline)
    if check.reachable or not check.complete:
        return kept, (), check
    distance = object_distances(task.init_index, kept, hub_degree(task), max_fan=REPAIR_MAX_FAN)
    far = total + 1
    pool = sorted(
        (name for name in task.problem.objects if name not in kept),
        key=lambda name: (-scores.get(name, 0.0), distance.get(name, far), name),
    )
    # A class with no member kept cannot fill any role (no airplane at all): its best-ranked member goes first.
    classes = task.typing.problem.objects
    present = {classes[name] for name in kept if name in classes}
    representatives: dict[str, str] = {}
    for name in pool:
        representatives.setdefault(classes[name], name)
    first = [name for cls, name in representatives.items() if cls not in present]
    pool = first + [name for name in pool if name not in set(first)]
    rank = {name: i for i, name in enumerate(pool)}
    current = kept
    # The missing classes' representatives alone first (one airplane may carry every package),
    # then doubling batches by rank.
    batch = len(first) or max(4, len(kept))
    while pool and not check.reachable:
        take, pool = pool[:batch], pool[batch:]
        current, _ = close(current | frozenset(take))
        if len(current) > give_up_above:
            break  # it would keep most of the problem anyway: checking costs more than it saves
        check = relaxed_reachability(task, current, budget, deadline)
        if not check.complete:
            break
        batch = max(4, len(kept), 2 * batch)
    if not check.reachable:
        # Nothing short of the whole problem reaches the goal (or the check gave up): let the planner decide.
        added = frozenset(current) - kept
        return frozenset(current), tuple(Restored(n, "", "reachability", ("goal",)) for n in sorted(added)), check
    used = {name for name in check.plan_objects if name in task.problem.objects and name not in kept}
    used, check = _economize(task, kept, used, classes, rank, check, close, budget, deadline)
    step_of: dict[str, Step] = {}
    for step in check.plan:
        for arg in step[1:]:
            step_of.setdefault(arg, step)
    reasons = [
        Restored(name, "", "reachability", step_of.get(name, ("goal",)))
        for name in sorted(used, key=lambda n: (rank.get(n, len(rank)), n))
    ]
    closed, closure_reasons = close(kept | frozenset(used))
    reasons.extend(r for r in closure_reasons if r.name not in used and r.name not in kept)
    return closed, tuple(reasons), check


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
) -> tuple[set[str], Reachability]:
    """Fewer added objects of one class where fewer do: a relaxed plan takes the first airplane it
    meets for each package, when one airplane carries them all.  Class by class (most members
    first), keep the member the current relaxed plan uses most, alone, if the goal stays
    relaxed-reachable, else drop the less used half while it does; what the last relaxed plan no
    longer uses goes too.  A few checks, each on the small kept set."""
    by_class: dict[str, list[str]] = {}
    for name in used:
        by_class.setdefault(classes.get(name, "object"), []).append(name)
    for cls in sorted((c for c in by_class if len(by_class[c]) > 1), key=lambda c: (-len(by_class[c]), c)):
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
    closed, _ = close(kept | frozenset(trial))
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
