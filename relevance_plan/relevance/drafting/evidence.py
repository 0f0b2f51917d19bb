"""What the given problems say: their objectives, their objects' classes and kinds, and what the goal scorer keeps.

The goal scorer regresses each problem's goal through the action schemas
(``goal_regression.analyse_goal``) to the types that can play a role in reaching it;
its first selection (``prune``'s) is what a problem needs according to that
analysis.  Drafting reads both, per problem: the goal's objects, the members
of each class the selection chose or the reachability check added, the role
depth of each type.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path

from relevance_plan.pddl.formulas import predicates_in, scoped_literals
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.scoring.scene import kind_of
from relevance_plan.relevance.selection.prune import Selection
from relevance_plan.relevance.setup import ScoringOptions, score_problem


@dataclass(frozen=True)
class ProblemEvidence:
    """One given problem, read for drafting."""

    name: str  # the problem file's name
    task: PlanningTask
    goal_predicates: tuple[str, ...]
    selection: Selection  # the goal scorer's first selection

    @property
    def objective(self) -> str:
        """The drafted objective the problem belongs to, named after its goal's predicates."""
        return "goal-" + "-and-".join(self.goal_predicates)

    @property
    def chosen(self) -> frozenset[str]:
        """Objects the goal scorer selected for their roles, or its reachability check added (not the goal's)."""
        added = {r.name for r in self.selection.restored if r.rule == "reachability"}
        return (self.selection.selected | added) - self.task.goal_objects

    def class_of(self, name: str) -> str:
        return class_key(self.task, name)


def class_key(task: PlanningTask, name: str) -> str:
    """The class an object is drafted into: its declared type, or (an untyped domain) its inferred class."""
    declared = task.problem.objects[name]
    return declared if declared != "object" else task.object_type(name)


def read_evidence(tasks: Sequence[PlanningTask]) -> list[ProblemEvidence]:
    """Each problem with its objective (named after its goal's predicates) and the goal scorer's first selection."""
    found = []
    for task in tasks:
        predicates = tuple(sorted(predicates_in(task.problem.goal)))
        scoring = score_problem(task, ScoringOptions(scorer="goal"), knowledge_model=None)
        name = Path(task.problem.path).name if task.problem.path else task.problem.name
        found.append(ProblemEvidence(name, task, predicates, scoring.first_selection()))
    return found


def describe_goal(task: PlanningTask) -> list[str]:
    """The goal's atoms in plain words, objects by their kinds: ``torque wrench at workbench``."""
    parts = []
    for atom, positive, _ in scoped_literals(task.problem.goal):
        words = [kind_of(arg).replace("_", " ") if not arg.startswith("?") else "any" for arg in atom.args]
        predicate = atom.predicate.replace("-", " ").replace("_", " ")
        said = f"{words[0]} {predicate} {words[1]}" if len(words) == 2 else " ".join([*words, predicate])
        parts.append(said if positive else f"not {said}")
    return list(dict.fromkeys(parts))


def members_by_class(evidence: Sequence[ProblemEvidence]) -> Mapping[str, dict[str, set[str]]]:
    """Class -> kind -> the (problem-qualified) objects of that kind, over every problem."""
    found: dict[str, dict[str, set[str]]] = {}
    for item in evidence:
        for name in item.task.problem.objects:
            found.setdefault(item.class_of(name), {}).setdefault(kind_of(name), set()).add(f"{item.name}:{name}")
    return found
