"""The members of a shared class following the placeholder's steps, one bit each.

When many goal objects of one class never meet in an action (packages, passengers:
``schemas.SharedClass``), the exploration runs once with :data:`~.schemas.MEMBER` standing for
every kept member.  Each step it finds for the placeholder is recorded here with the conditions
on the placeholder a member must reach first; then the members' bits are carried along those
steps to a fixpoint, all members at once, and each member's own facts are written with the step
that first brought it there: the answer and the relaxed plan of the object-by-object exploration.
"""

from __future__ import annotations

from collections import defaultdict, deque
from collections.abc import Set

from relevance_plan.pddl.formulas import GroundAtom
from relevance_plan.relevance.reachability.budget import Work
from relevance_plan.relevance.reachability.relaxed_plan import Achiever
from relevance_plan.relevance.reachability.schemas import MEMBER, Binding, JoinSchema, SharedClass, Step


class SharedMembers:
    """The shared class's members (none without one): which are kept, which of the placeholder's
    facts each has reached, and the placeholder's steps."""

    def __init__(self, shared: SharedClass | None, kept: Set[str]):
        self.shared = shared
        self.members = shared.members if shared else frozenset()  # of the shared class, kept or not
        # with a shared class, its kept members are not objects of the exploration: MEMBER stands for them
        self.kept: set[str] = set(kept) & self.members
        # the placeholder's steps, each with its conditions on the placeholder
        self.edges: list[tuple[tuple[GroundAtom, ...], tuple[GroundAtom, ...], Step, JoinSchema, Binding]] = []
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

    def pattern(self, atom: GroundAtom) -> GroundAtom | None:
        """``atom`` with its member of the shared class as MEMBER (None: that member is not kept)."""
        args = []
        for arg in atom[1:]:
            if arg in self.members:
                if arg not in self.kept:
                    return None
                arg = MEMBER
            args.append(arg)
        return (atom[0], *args)

    def bit(self, name: str) -> int:
        bit = self.bit_of.get(name)
        if bit is None:
            bit = self.bit_of[name] = 1 << len(self.bit_of)
        return bit

    def add_step(self, schema: JoinSchema, binding: Binding) -> None:
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

    def follow(self, facts: dict[GroundAtom, Achiever | None], missing: set[GroundAtom], work: Work) -> None:
        """Once the placeholder's facts are all found: its steps carry the members' bits
        (:meth:`_spread`), and each ``missing`` fact of a kept member that member has reached is
        written into ``facts``, with the steps that brought it there."""
        self._spread(work)
        for atom in sorted(missing):
            name = next((arg for arg in atom[1:] if arg in self.kept), None)
            if name is not None:
                pattern = self.pattern(atom)
                if pattern is not None and self.holders.get(pattern, 0) & self.bit(name):
                    self._record(name, pattern, facts, missing)

    def _spread(self, work: Work) -> None:
        """Carry the members' bits along the placeholder's steps to a fixpoint: a step passes on the
        bits its conditions on the placeholder all hold (every member's bit when it has none)."""
        holders, arrivals, spreading = self.holders, self.arrivals, self.spreading
        # a pattern waits in the queue once however many times its bits grow meanwhile: its steps
        # read its bits when they fire
        queued = set(spreading)
        everyone = 0
        for name in self.kept:
            everyone |= self.bit(name)
        for pattern, name in self.seeds:
            bit = self.bit(name)
            if not holders.get(pattern, 0) & bit:
                holders[pattern] = holders.get(pattern, 0) | bit
                arrivals[pattern].append((bit, None))
                if pattern not in queued:
                    queued.add(pattern)
                    spreading.append(pattern)
        self.seeds.clear()
        edges = self.edges

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

    def _record(
        self, name: str, pattern: GroundAtom, facts: dict[GroundAtom, Achiever | None], missing: set[GroundAtom]
    ) -> None:
        """The fact ``pattern`` stands for with member ``name``, and the facts the steps that first
        brought ``name`` there need, back to its initial ones, each with its step (what a relaxed
        plan walks back through)."""
        edges, bit = self.edges, self.bit(name)
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
                facts[fact] = Achiever(tuple(name if arg == MEMBER else arg for arg in step), schema, own)
                stack.extend(needs)
            missing.discard(fact)
