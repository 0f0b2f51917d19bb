"""The repair: what a selection that fails the relaxed check lacks, found by growing it.

``repair_selection`` is the step ``prune_with_scores`` runs after closure:
when the kept set fails the check (``exploration.relaxed_reachability``), it
adds the best-ranked missing objects in doubling batches until the goal is
relaxed-reachable, then keeps only the added objects some relaxed plan uses
(a truck, an airplane, the cells of a path), each with the plan step that
needs it as its reason.  :class:`RepairOrder` says which objects come next;
``_economize`` drops the added objects of one class that others can stand in
for; ``_sharpen`` asks the sharper temporal and numeric check
(``timed_relaxation``) on top.
"""

from __future__ import annotations

import heapq
import itertools
import math
import time
from collections.abc import Callable, Collection, Iterator, Mapping, Sequence, Set
from dataclasses import dataclass

from relevance_plan.pddl.formulas import GroundAtom
from relevance_plan.relevance.analysis.distances import (
    GrowingDistances,
    NearestBetween,
    graph_distances,
    shared_graph,
    walk_bounds,
    walk_levels,
)
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.analysis.witnesses import WitnessNeed, match_witnesses
from relevance_plan.relevance.reachability.budget import OutOfBudget, Work
from relevance_plan.relevance.reachability.exploration import (
    DEFAULT_BUDGET,
    Exploration,
    Reachability,
    relaxed_reachability,
)
from relevance_plan.relevance.reachability.schemas import MEMBER, Step, relaxed_task
from relevance_plan.relevance.selection.closure import Restored

BUDGET_PER_OBJECT = 5_000  # the budget grows with the problem, as the planner's own grounding does
REPAIR_SECONDS = 5.0  # and the repair's checks together stop after this long,
REPAIR_SHARE = 0.2  # or after this share of a longer --timeout (the full problem races beside it)
BINDINGS_PER_SECOND = 1_000_000  # past the budget per object, time decides: a check tries about 300,000 a second
REPAIR_MAX_FAN = 4.0  # repair candidates are ranked by hops that do not pass from a class-like value to its members
DOMINANCE_TRIES = 8  # kept objects of its class a repair candidate is compared with
PAIRWISE_UP_TO = 64  # added objects of one class compared each with all others after the repair
# goal objects no reached fact names, up to which a round walks toward each in turn when the way to
# the nearest adds nothing (a few items and receptacles; past it, a package per city: the ranking)
WAYS_EACH_UP_TO = 8

# closure over constraints: (names, a subset of them already closed) -> (closed set, what it put back and why)
CloseFn = Callable[[Set[str], Set[str]], tuple[frozenset[str], tuple[Restored, ...]]]
Repaired = tuple[frozenset[str], tuple[Restored, ...], Reachability]  # (kept, what was put back and why, last check)


@dataclass(frozen=True)
class _Repair:
    """What every step of one repair reads: the task, the kept set it grows, closure and the bounds."""

    task: PlanningTask
    kept: frozenset[str]
    scores: Mapping[str, float]
    close: CloseFn
    budget: int  # bindings each check may try
    deadline: float  # time.monotonic() by which the checks stop
    give_up_above: int  # kept objects past which the search stops and returns what it has

    def work(self) -> Work:
        return Work(self.budget, self.deadline)


def repair_selection(
    task: PlanningTask,
    kept: frozenset[str],
    scores: Mapping[str, float],
    close: CloseFn,
    budget: int | None = None,
    give_up_above: int | None = None,
) -> Repaired:
    """Add what the relaxed goal needs to ``kept``; returns (kept, what was put back and why, the last check).

    Candidates are tried best first: one member of every class the kept set
    lacks, then by score, then by hops from the kept objects in the initial
    state; ``close`` is closure over constraints (it returns the closed set
    and its own reasons).  ``budget`` bounds each check (default: grows with
    the problem, and with the time the checks may take); past ``give_up_above`` kept objects the search stops and
    returns what it has.
    """
    total = len(task.problem.objects)
    now = time.monotonic()
    seconds = REPAIR_SECONDS if task.deadline is None else max(REPAIR_SECONDS, REPAIR_SHARE * (task.deadline - now))
    bindings = max(DEFAULT_BUDGET, BUDGET_PER_OBJECT * total, int(BINDINGS_PER_SECOND * seconds))
    repair = _Repair(
        task,
        kept,
        scores,
        close,
        bindings if budget is None else budget,
        min(now + seconds, math.inf if task.deadline is None else task.deadline),
        total if give_up_above is None else give_up_above,
    )
    reads = RepairReads(set(kept), set())
    try:
        exploration = Exploration(task, kept, repair.work())
        exploration.run()
        check = exploration.outcome()  # may explore on for the goal's witnesses, within the budget
    except OutOfBudget:
        task.check_time("checking the selection")  # the --timeout, not the repair's own bound
        return _observed(task, kept, (kept, (), Reachability(False, False)), RepairReads(None, set()))
    if check.reachable:
        return _observed(task, kept, _sharpen(repair, kept, (), check), reads)
    order = RepairOrder(task, scores, reads)
    current, added, check = _grow(repair, exploration, order)
    if reads.objects is not None:
        reads.objects |= current  # the explorations read their facts
    if not check.reachable:
        # Nothing short of the whole problem reaches the goal (or the check gave up): let the planner decide.
        reasons = tuple(Restored(n, "", "reachability", ("goal",)) for n in sorted(current - kept))
        return _observed(task, kept, (current, reasons, check), reads)
    grown = _Grown({name: i for i, name in enumerate(added)}, order, exploration.facts)
    used = {name for name in check.plan_objects if name in task.problem.objects and name not in kept}
    used, check = _economize(repair, grown, used, check)
    closed, reasons = _restore_used(repair, used, grown.rank, check)
    return _observed(task, kept, _sharpen(repair, closed, reasons, check), reads)


@dataclass
class RepairReads:
    """What one repair read beyond the links between objects: the objects whose facts or rank a
    choice read (``None``: it ranked every object, even those no link reaches), and the classes whose
    every member a choice compared.  A caller that keeps the repair's result (the live session) keeps
    it while none of these, the links a ranking followed and the scores stay as they were."""

    objects: set[str] | None
    classes: set[str]
    ranked: bool = False  # whether a choice ranked objects by the links between them


def _observed(task: PlanningTask, kept: frozenset[str], repaired: Repaired, reads: RepairReads) -> Repaired:
    """``repaired``, shown first to the task's ``repair_observer`` (when it has one) with what the repair read."""
    if task.repair_observer is not None:
        from relevance_plan.relevance.reachability.timed_relaxation import applies

        if applies(task) or not repaired[2].complete:
            # the sharper check ranks every object; a check that gave up stopped where time ran out
            reads = RepairReads(None, reads.classes)
        task.repair_observer(kept, repaired, reads)
    return repaired


def _grow(
    repair: _Repair, exploration: Exploration, order: RepairOrder
) -> tuple[frozenset[str], list[str], Reachability]:
    """Grow the kept set until the exploration reaches the goal; returns (the grown set, the objects
    added in the order they came, the last check).

    The best witness of each goal atom that needs one of its own first (``witnesses``), and one
    member of every class the kept set lacks (no airplane at all), together; then, round by
    round, the objects between what is reached and the goal atoms still unreached: one at a time at
    first (one airplane may carry every package), then a quarter of what was added, or as many as
    the last round's rate of goal atoms says are needed; once the goal is reached, the next witness
    of each goal atom still without one of its own.  The exploration carries on from where it
    stopped, so the whole growth costs about one exploration of the final set."""
    kept = repair.kept
    take = order.first_witnesses(kept)
    take += [name for name in order.missing_classes(kept | set(take)) if name not in take]
    current = kept
    added: list[str] = []
    estimate = 0  # objects still needed, judged by what the last round's objects reached
    try:
        while True:
            if not take:
                take = _next_round(exploration, order, current, kept, estimate)
                if not take:
                    break
            grown, _ = repair.close(current | frozenset(take), current)
            added += take + sorted(grown - current - set(take))
            if len(grown) > repair.give_up_above:
                current = grown
                break  # it would keep most of the problem anyway: checking costs more than it saves
            before = len(exploration.missing)
            exploration.add(grown - current)
            current = grown
            exploration.run()
            brought = before - len(exploration.missing)
            order.learn(take, brought > 0)
            # one truck brought its city's packages home: about as many more as cities still waiting
            estimate = -(-len(take) * len(exploration.missing) // brought) if brought > 0 else 0
            take = []
        check = exploration.outcome()
    except OutOfBudget:
        repair.task.check_time("checking the selection")
        check = Reachability(False, False)
    return frozenset(current), added, check


def _next_round(
    exploration: Exploration, order: RepairOrder, current: frozenset[str], kept: frozenset[str], estimate: int
) -> list[str]:
    """What the next round of :func:`_grow` adds (nothing: the goal is reached, or nothing helps)."""
    batch = max(1, (len(current) - len(kept)) // 4, min(estimate, 2 * (len(current) - len(kept))))
    if not exploration.missing:
        # a goal atom without a witness of its own: its next candidate, and the way to the kept ones it cannot reach
        take = order.next_witnesses(exploration.shortfall(), current)
        if exploration.stranded:
            take += order.nearest(current, exploration.stranded, batch, exploration.facts)
        return list(dict.fromkeys(take))
    unreached = {arg for atom in exploration.missing for arg in atom[1:]}
    return order.nearest(current, unreached, batch, exploration.facts)


def _restore_used(
    repair: _Repair, used: Set[str], rank: Mapping[str, int], check: Reachability
) -> tuple[frozenset[str], tuple[Restored, ...]]:
    """The kept set with the objects the relaxed plan uses, closed, and why each came back: the
    first plan step that names it (closure's own reasons for what closure adds)."""
    kept = repair.kept
    step_of: dict[str, Step] = {}
    for step in check.plan:
        for arg in step[1:]:
            step_of.setdefault(arg, step)
    reasons = [
        Restored(name, "", "reachability", step_of.get(name, ("goal",)))
        for name in sorted(used, key=lambda n: (rank.get(n, len(rank)), n))
    ]
    closed, closure_reasons = repair.close(kept | frozenset(used), kept)
    reasons.extend(r for r in closure_reasons if r.name not in used and r.name not in kept)
    return closed, tuple(reasons)


def _sharpen(repair: _Repair, closed: frozenset[str], reasons: tuple[Restored, ...], check: Reachability) -> Repaired:
    """On a temporal or numeric problem, a selection the delete relaxation admits but the sharper
    relaxation of ``timed_relaxation`` refutes (fuel no kept action can give, a durative action's end
    out of reach) has no plan: add the best-ranked objects, a doubling batch at a time, until it is
    admitted (or the planner decides, past ``give_up_above``)."""
    from relevance_plan.relevance.reachability.timed_relaxation import applies, timed_relaxed_reachability

    task, scores = repair.task, repair.scores
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
    while ranked and len(current) <= repair.give_up_above:
        take, ranked = ranked[:batch], ranked[batch:]
        grown, more = repair.close(current | frozenset(take), current)
        added += [Restored(name, "", "reachability", ("goal",)) for name in take]
        added += [r for r in more if r.name not in current and r.name not in take]
        current = grown
        ranked = [name for name in ranked if name not in current]
        task.check_time("checking the selection")
        if timed_relaxed_reachability(task, current) is not False:
            break
        batch = max(1, len(current) - len(repair.kept))
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


class _Sorted:
    """The names of ``keys`` (tuples that end with the name) in the keys' order, each taken off a heap
    when an iteration first reaches it: a round of the repair reads the first few of thousands."""

    def __init__(self, keys: list[tuple[int, int, int, float, str]]):
        heapq.heapify(keys)
        self._heap = keys
        self._taken: list[str] = []

    def __len__(self) -> int:
        return len(self._taken) + len(self._heap)

    def __iter__(self) -> Iterator[str]:
        position = 0
        while True:
            if position < len(self._taken):
                yield self._taken[position]
                position += 1
            elif self._heap:
                self._taken.append(heapq.heappop(self._heap)[-1])
            else:
                return


class RepairOrder:
    """The order in which the repair adds objects (see :func:`repair_selection`)."""

    def __init__(self, task: PlanningTask, scores: Mapping[str, float], reads: RepairReads | None = None):
        self.task = task
        self.scores = scores
        # what the choices read (see RepairReads); each choice adds to it
        self.reads = RepairReads(set(), set()) if reads is None else reads
        self.reads.ranked = True
        self.hub = task.hub_degree
        # the initial facts' links, walked once or twice a round
        self.graph = shared_graph(task.init_index, REPAIR_MAX_FAN)
        self.toward_unreached: tuple[frozenset[str], dict[str, int]] = (frozenset(), {})
        self.bounds: tuple[frozenset[str], dict[str, int]] = (frozenset(), {})  # walk_bounds of toward_unreached
        # goal objects -> hops toward them: the same ones stay unnamed by reached facts for many rounds
        self.toward_goal_objects: dict[frozenset[str], dict[str, int]] = {}
        # hops from what the exploration reached, which only grows: each round walks from what is new
        self.from_reached = GrowingDistances(task.init_index, self.graph, self.hub)
        self.classes = task.typing.problem.objects
        self.timed = bool(task.typing.problem.timed_literals)
        self.static = relaxed_task(task).static
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

    def first_witnesses(self, kept: Set[str]) -> list[str]:
        """For each goal atom that needs a witness of its own and has no kept candidate to spare,
        its best-ranked candidate not taken by another (``witnesses.match_witnesses`` over all)."""
        needs = self.task.witness_needs
        wanted = [
            need.candidates[0]
            for need in self.task.exists_needs
            if need.candidates and not any(name in kept for name in need.candidates)
        ]
        if not needs:
            return wanted
        chosen, _ = match_witnesses(needs, lambda need, name: True)
        spare = set(kept)
        for need in needs:
            own = next((name for name in need.candidates if name in spare), None)
            if own is not None:
                spare.discard(own)
            elif need.goal in chosen and chosen[need.goal] not in kept:
                wanted.append(chosen[need.goal])
        return list(dict.fromkeys(wanted))

    def next_witnesses(self, shortfall: Sequence[WitnessNeed], current: Set[str]) -> list[str]:
        """The best-ranked candidate outside ``current`` of each goal atom left without a witness."""
        taken: list[str] = []
        for need in shortfall:
            name = next((n for n in need.candidates if n not in current and n not in taken), None)
            if name is not None:
                taken.append(name)
        return taken

    def missing_classes(self, kept: Set[str]) -> list[str]:
        """The best-ranked member (score, then hops from ``kept``) of every class ``kept`` has none of."""
        present = {self.classes[name] for name in kept if name in self.classes}
        missing = set(self.classes.values()) - present
        self.reads.classes.update(missing)
        best: dict[str, tuple[float, list[str]]] = {}  # class -> its best score, and the members with it
        for name, cls in self.classes.items():
            if cls in missing:
                score = self.scores.get(name, 0.0)
                top = best.get(cls)
                if top is None or score > top[0]:
                    best[cls] = (score, [name])
                elif score == top[0]:
                    top[1].append(name)
        chosen = [names[0] for _, names in best.values() if len(names) == 1]
        tied = {cls: set(names) for cls, (_, names) in best.items() if len(names) > 1}
        return sorted(chosen + self._nearest_members(kept, tied))

    def _nearest_members(self, kept: Set[str], tied: Mapping[str, Set[str]]) -> list[str]:
        """For each class, the member of ``tied[class]`` fewest hops from ``kept`` (then by name;
        none reached: the first by name), walking only until every class has one."""
        waiting = dict(tied)
        found: list[str] = []
        if waiting:
            for level in walk_levels(self.task.init_index, self.graph, kept, self.hub):
                reached: dict[str, list[str]] = {}
                for name in level:
                    cls = self.classes.get(name)
                    if cls in waiting and name in waiting[cls]:
                        reached.setdefault(cls, []).append(name)
                for cls, names in reached.items():
                    found.append(min(names))
                    del waiting[cls]
                if not waiting:
                    break
        return found + [min(names) for names in waiting.values()]

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
        sources = {arg for fact, achiever in reached.items() if achiever is not None for arg in fact[1:]}
        sources.update(self.agents)
        sources.discard(MEMBER)
        path = self._path(unreached - sources, sources - unreached, current)
        if path:
            return path
        kept_of: dict[str, list[str]] = {}
        chosen: list[str] = []
        detached: list[str] = []
        for name, linked in self._ranking(distance, sources, current):
            if len(chosen) == count:
                break
            self._read(name, linked)
            cls = self.classes[name]
            if cls not in kept_of:
                kept_of[cls] = sorted(n for n in current if self.classes.get(n) == cls)[:DOMINANCE_TRIES]
            if self.stood_in_for(name, kept_of[cls], reached):
                continue
            if self._detached(name, kept_of[cls], reached, current):
                detached.append(name)
            else:
                chosen.append(name)
        else:
            self.reads.objects = None  # every object was ranked: one more would be too
        if chosen or detached:
            return chosen or detached[:count]
        return [name for name, _ in itertools.islice(self._ranking(distance, sources, current), count)]

    def _ranking(self, distance: Mapping[str, int], sources: Set[str], current: Set[str]) -> Iterator[tuple[str, bool]]:
        """The objects outside ``current`` in the order :meth:`nearest` ranks them, each with whether
        a link reaches it (``distance``: hops toward the unreached objects).  Those both walks
        reach come from a search that walks from ``sources`` only as far as the round reads
        (``analysis.NearestBetween``); the rest, when a round reads that far, from ranking all."""
        fruitless, classes, score = self.fruitless, self.classes, self.scores.get
        far = len(classes) + 1
        shown = 0
        if sources:
            unreached = self.toward_unreached[0]
            # the bounds toward more goal objects hold for fewer too (hops to fewer are never fewer)
            if not unreached <= self.bounds[0]:
                index = self.task.init_index
                self.bounds = (unreached, walk_bounds(index, self.graph, unreached, distance, self.hub))
            search = NearestBetween(self.task.init_index, self.graph, sources, distance, self.bounds[1], self.hub, far)
            for group in search.groups():
                members = [(toward, name) for toward, name in group if name in classes and name not in current]
                members.sort(key=lambda m: (m[0], fruitless.get(classes[m[1]], 0), -score(m[1], 0.0), m[1]))
                for _, name in members:
                    shown += 1
                    yield name, True
        between = self.from_reached(sources) if sources else {}

        def rank(name: str) -> tuple[int, int, int, float, str]:
            return (
                distance.get(name, far) + between.get(name, far if sources else 0),
                distance.get(name, far),
                fruitless.get(classes[name], 0),
                -score(name, 0.0),
                name,
            )

        # The objects the distances reach rank first; the others, ranked alike after them, only
        # when those run out (most of a building's items: no link leads from their receptacle to them).
        linked = [name for name in distance.keys() | between.keys() if name in classes and name not in current]
        to, back, off = distance.get, between.get, far if sources else 0
        ranked = _Sorted(  # by rank(name), its parts looked up here: thousands of objects, a dozen rounds
            [(to(n, far) + back(n, off), to(n, far), fruitless.get(classes[n], 0), -score(n, 0.0), n) for n in linked]
        )
        rest = len(classes) - sum(1 for name in current if name in classes) - len(ranked)
        # the first ``shown`` are those the search gave, in the same order
        for position, name in enumerate(self._ranked(ranked, current, rank, rest)):
            if position >= shown:
                yield name, position < len(ranked)

    def _ranked(
        self, linked: _Sorted, current: Set[str], rank: Callable[[str], tuple[int, int, int, float, str]], rest: int
    ) -> Iterator[str]:
        """``linked`` (ranked), then the ``rest`` of the objects outside ``current``, ranked, made only when reached."""
        yield from linked
        if rest:
            seen = set(linked)
            yield from sorted((n for n in self.classes if n not in current and n not in seen), key=rank)

    def _read(self, name: str, linked: bool) -> None:
        """Note that a choice read ``name`` (past the objects a link reaches: it read every object)."""
        if not linked:
            self.reads.objects = None
        elif self.reads.objects is not None:
            self.reads.objects.add(name)

    def _path(self, targets: Set[str], sources: Set[str], current: Set[str]) -> list[str]:
        """The objects outside ``current`` on one shortest way in the initial state from the source
        nearest to ``targets`` (goal objects no reached fact names yet) down to one of them: a
        corridor of cells from where the robot can go to the goal's place, not every cell of the
        rectangle between them.  A step whose link is a fact with more objects (a door between
        two places) brings those objects too: without the door, the corridor leads nowhere."""
        if not targets or not sources:
            return []
        walk = self._walk_toward(frozenset(targets), sources, current)
        if walk or len(targets) == 1 or len(targets) > WAYS_EACH_UP_TO:
            return walk
        # the way to the nearest is kept already (a sofa next to where the robot can go): the way to another
        for target in sorted(targets):
            walk = self._walk_toward(frozenset([target]), sources, current)
            if walk:
                return walk
        return []

    def _walk_toward(self, targets: frozenset[str], sources: Set[str], current: Set[str]) -> list[str]:
        """:meth:`_path` toward ``targets``."""
        distance = self.toward_goal_objects.get(targets)
        if distance is None:
            distance = graph_distances(self.task.init_index, self.graph, targets, self.hub)
            self.toward_goal_objects[targets] = distance
        neighbours = self.graph.neighbours
        start = min((name for name in sources if name in distance), key=lambda n: (distance[n], n), default=None)
        walk: list[str] = []
        name = start
        while name is not None and distance[name] > 0:
            lower = distance[name] - 1
            # the first by name (the facts' order, and so the neighbours', changes from run to run),
            # linked both ways: a place leads to its room, but the room leads to none of its places
            step = min(
                (o for o in neighbours(name) if distance.get(o) == lower and name in neighbours(o)), default=None
            )
            if step is not None:
                walk += [o for o in self._link(name, step) if o not in current and o in self.classes]
                if step not in current and step in self.classes:
                    walk.append(step)
            name = step
        return list(dict.fromkeys(walk))

    def _link(self, name: str, step: str) -> tuple[str, ...]:
        """The other objects of the fact that links ``name`` to ``step`` with the fewest of them (the
        door of ``(door-between door here there)``; none for ``(connected here there)``)."""
        links = [
            tuple(sorted({o for o in atom[1:] if o != name and o != step}))
            for atom in self.task.init_index.by_object.get(name, ())
            if step in atom[1:] and self.graph.follows(atom, name)
        ]
        return min(links, key=lambda others: (len(others), others), default=())

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


@dataclass(frozen=True)
class _Grown:
    """What growing the kept set leaves for economizing it."""

    rank: Mapping[str, int]  # each added object's place in the order it came
    order: RepairOrder  # the order that chose them, to tell which member stands in for which
    reached: Mapping[GroundAtom, object]  # the facts the exploration reached


def _economize(repair: _Repair, grown: _Grown, used: set[str], check: Reachability) -> tuple[set[str], Reachability]:
    """Fewer added objects of one class where fewer do: a relaxed plan takes the first airplane it
    meets for each package, when one airplane carries them all.  Class by class (most members
    first), keep the member the current relaxed plan uses most, alone, if the goal stays
    relaxed-reachable, else drop the less used half while it does; what the last relaxed plan no
    longer uses goes too.  A few checks, each on the small kept set.  In a class none of whose
    members can stand in for most others (a truck in each city), only those another member can
    stand in for go (a second truck in one city, added in the same round as the first)."""
    classes = repair.task.typing.problem.objects
    by_class: dict[str, list[str]] = {}
    for name in used:
        by_class.setdefault(classes.get(name, "object"), []).append(name)
    for cls in sorted((c for c in by_class if len(by_class[c]) > 1), key=lambda c: (-len(by_class[c]), c)):
        if grown.order.interchangeable(sorted(by_class[cls]), grown.reached):
            used, check = _fewest_of_class(repair, grown, by_class[cls], used, check)
        else:
            used, check = _without_stood_in_for(repair, grown, by_class[cls], used, check)
    return used, check


def _fewest_of_class(
    repair: _Repair, grown: _Grown, members: list[str], used: set[str], check: Reachability
) -> tuple[set[str], Reachability]:
    """``used`` with the most used of ``members`` alone if the goal stays relaxed-reachable, else
    without the less used half while it does."""
    while True:
        ordered = _by_use([m for m in members if m in used], check, grown.rank)
        if len(ordered) < 2:
            break
        trial_used, trial = _without(repair, used, ordered[1:])
        if trial is None and len(ordered) > 3:
            trial_used, trial = _without(repair, used, ordered[len(ordered) // 2 :])
        if trial is None or len(trial_used) >= len(used):
            break  # no smaller set reaches the goal (closure may bring the dropped ones back)
        used, check = trial_used, trial
    return used, check


def _without_stood_in_for(
    repair: _Repair, grown: _Grown, members: list[str], used: set[str], check: Reachability
) -> tuple[set[str], Reachability]:
    """``used`` without the ``members`` another member can stand in for (the least used first), if
    the goal stays relaxed-reachable; past ``PAIRWISE_UP_TO`` members they are not compared."""
    ordered = _by_use(members, check, grown.rank)
    if len(ordered) > PAIRWISE_UP_TO:
        return used, check
    dropped: list[str] = []
    for name in reversed(ordered):  # the least used first
        if grown.order.stood_in_for(name, [m for m in ordered if m != name and m not in dropped], grown.reached):
            dropped.append(name)
    if dropped:
        trial_used, trial = _without(repair, used, dropped)
        if trial is not None and len(trial_used) < len(used):
            return trial_used, trial
    return used, check


def _by_use(members: list[str], check: Reachability, rank: Mapping[str, int]) -> list[str]:
    uses: dict[str, int] = {}
    for step in check.plan:
        for arg in step[1:]:
            uses[arg] = uses.get(arg, 0) + 1
    return sorted(members, key=lambda n: (-uses.get(n, 0), rank.get(n, len(rank)), n))


def _without(repair: _Repair, used: set[str], dropped: list[str]) -> tuple[set[str], Reachability | None]:
    """``used`` without ``dropped`` (and without what its relaxed plan then leaves unused), if the goal
    stays relaxed-reachable."""
    kept = repair.kept
    trial = used - set(dropped)
    closed, _ = repair.close(kept | frozenset(trial), kept)
    attempt = relaxed_reachability(repair.task, closed, repair.budget, repair.deadline)
    if not attempt.reachable:
        return used, None
    # what the relaxed plan uses, closure's additions included (they stay only through their cause)
    needed = {n for n in attempt.plan_objects if n in closed and n not in kept}
    return needed or trial, attempt
