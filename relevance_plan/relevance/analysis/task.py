"""The planning task every stage reads: a domain and a problem, with the analyses they share.

``PlanningTask`` sits at the bottom of ``relevance``: the scorers, the closure,
the relaxed exploration, its repair and the pruning all take one, and each
analysis (the initial facts' index, inferred types, the goal's roles,
distances, what soundness keeps) is computed once, on first use.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from functools import cached_property

from relevance_plan.pddl.formulas import Atom, conjuncts, is_variable
from relevance_plan.pddl.model import Domain, Problem, goal_objects, pinned_objects
from relevance_plan.pddl.sexpr import check_deadline
from relevance_plan.relevance.analysis.distances import object_distances
from relevance_plan.relevance.analysis.facts import FactIndex, index_init, object_profiles
from relevance_plan.relevance.analysis.goal_regression import GoalAnalysis, analyse_goal
from relevance_plan.relevance.analysis.invariants import count_keeping_for
from relevance_plan.relevance.analysis.network import Network, find_network
from relevance_plan.relevance.analysis.soundness import KeptObjects, objects_to_keep, soundness_requirements
from relevance_plan.relevance.analysis.types import InferredTypes, infer_types
from relevance_plan.relevance.analysis.witnesses import WitnessNeed, exists_needs, shortfall_reason, witness_needs


@dataclass(frozen=True, eq=False)
class PlanningTask:
    """A domain and problem with the analyses several stages share, computed once."""

    domain: Domain
    problem: Problem
    # time.monotonic() by which scoring and pruning end (``plan``'s --timeout): past it, the
    # analyses stop with OutOfTimeError instead of running on until the CLI's last alarm
    deadline: float | None = field(default=None, kw_only=True)
    # shown, after each reachability repair on this task, its input, its result and what it read
    # (``repair.RepairReads``): how the live session keeps a result while nothing it read changes
    repair_observer: Callable[..., None] | None = field(default=None, kw_only=True)

    def check_time(self, what: str) -> None:
        """OutOfTimeError naming ``what`` when the task's deadline has passed."""
        check_deadline(self.deadline, what, self.problem.path)

    @cached_property
    def init_index(self) -> FactIndex:
        return index_init(self.problem, self.deadline, count_keeping_for(self.domain, self.problem.timed_literals))

    @cached_property
    def typing(self) -> InferredTypes:
        """The domain and problem with types inferred where the domain declares none."""
        typing = infer_types(self.domain, self.problem, self.init_index.by_predicate)
        self.check_time("inferring the objects' classes")
        return typing

    @cached_property
    def goal_analysis(self) -> GoalAnalysis:
        return analyse_goal(self.typing.domain, self.typing.problem, self.init_index, self.deadline)

    @cached_property
    def goal_distance(self) -> dict[str, int]:
        """Hops from the goal's objects through initial facts (unreached objects are absent)."""
        return object_distances(self.init_index, self.goal_objects, self.hub_degree)

    @cached_property
    def hub_degree(self) -> int:
        """Objects in more initial facts than this (a shape every key has, a floor above all others) link
        everything to everything: distances do not pass through them."""
        return hub_degree(len(self.problem.objects))

    @cached_property
    def object_profiles(self) -> dict[str, tuple[object, ...]]:
        """Each object's class and initial facts, its own name blanked out: equal for interchangeable objects."""
        facts = object_profiles(self.init_index, self.problem.numeric_init)
        return {name: (self.object_type(name), *facts.get(name, ())) for name in self.problem.objects}

    def object_type(self, name: str) -> str:
        """The declared type of an object, or its inferred class in an untyped domain."""
        return self.typing.problem.objects[name]

    @cached_property
    def network(self) -> Network:
        """The static links joining many objects of one class (``network``): closure does not follow them."""
        typing = self.typing
        classes = {**typing.domain.constants, **typing.problem.objects}
        return find_network(typing.domain, classes, self.init_index)

    @cached_property
    def goal_objects(self) -> frozenset[str]:
        return goal_objects(self.problem, self.domain)

    @cached_property
    def pinned_objects(self) -> frozenset[str]:
        """Objects named in the goal, the trajectory constraints or the metric: never pruned."""
        return pinned_objects(self.problem, self.domain)

    @cached_property
    def witness_needs(self) -> tuple[WitnessNeed, ...]:
        """The goal atoms that each need an object of their own to be met through (``witnesses``)."""
        typing = self.typing
        problem = typing.problem
        # the goal's top-level atoms, as the relaxed check reads them (``witness_needs`` keeps each once)
        goal = [(p.predicate, *p.args) for p in conjuncts(problem.goal) if isinstance(p, Atom)]
        ground = [atom for atom in goal if not any(is_variable(arg) for arg in atom[1:])]
        needs = witness_needs(typing.domain, problem, self.init_index, problem.objects, self.hub_degree, ground)
        self.check_time("finding the goal's witnesses")
        return needs

    @cached_property
    def exists_needs(self) -> tuple[WitnessNeed, ...]:
        """The goal's top-level existentials, each with the objects that can be its variable (``witnesses``)."""
        typing = self.typing
        problem = typing.problem
        return exists_needs(typing.domain, self.init_index, problem.objects, self.hub_degree, problem.goal)

    @cached_property
    def witness_shortfall(self) -> str:
        """Why even the whole problem has too few witnesses for its goal ("" when it has enough)."""
        return shortfall_reason(self.witness_needs)

    @cached_property
    def proved_unsolvable(self) -> str:
        """Why the problem has no plan, when a goal predicate's witnesses are proved short
        (``witness_proof``); "" when not (a verdict the tool gives without a planner, so it is given
        only when proved).  The proof runs only when the judgement of ``witness_shortfall`` finds a
        shortfall: a proved one is always among them (the proof counts the same distinct goal atoms,
        one predicate at a time, with at least the same candidates)."""
        typing = self.typing
        if typing.inferred:
            return ""  # inferred classes guide choices; a proof stands on the types the domain declares
        if not self.witness_shortfall:
            return ""  # enough witnesses: nothing to prove (and the proof's modules stay unloaded)
        from relevance_plan.relevance.analysis.witness_proof import unsolvable_by_witnesses

        proof = unsolvable_by_witnesses(typing.domain, typing.problem, self.init_index)
        self.check_time("proving the goal's witnesses short")
        return proof

    @cached_property
    def kept_for_soundness(self) -> KeptObjects:
        """Objects a quantifier ranges over where pruning them could change a verdict (``soundness``)."""
        return objects_to_keep(self.domain, self.problem, soundness_requirements(self.domain, self.problem))


def hub_degree(objects: int) -> int:
    """:attr:`PlanningTask.hub_degree` for a problem of ``objects`` objects."""
    return max(16, int(2 * objects**0.5))
