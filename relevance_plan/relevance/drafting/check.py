"""The drafting check: a drafted model must never prune worse than no model on the problems it was drafted from.

For each given problem, the draft's first selection (what ``plan`` would try
first with the model) is compared with the goal scorer's, and both are put to
the reachability check with the negative preconditions compiled into
complements (``pddl.compile``), so that a lock nothing can open counts: the
relaxation the planning loop uses passes over ``(not (locked ?s))``.  What a
selection lacks is what the repair (``repair.repair_selection``) adds to it.

A draft that lacks something gets a dependency when a static fact ties the
missing object to a kept one (the key that fits a kept toolbox), else a
higher prior for its class and kind; a draft that keeps more than
``DRAFT_RATIO`` times what the goal scorer needs gets lower priors for the
kinds the goal scorer did not need.  Each change is a note for the model's
comments; what still differs after ``MAX_ROUNDS`` is said, problem by problem.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence, Set
from dataclasses import dataclass

from relevance_plan.pddl.formulas import literals
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.analysis.types import static_predicates
from relevance_plan.relevance.drafting.draft import HIGH, LOW, Draft, Prior
from relevance_plan.relevance.drafting.evidence import ProblemEvidence
from relevance_plan.relevance.drafting.structure import DraftedDependency
from relevance_plan.relevance.scoring.knowledge import KnowledgeModel
from relevance_plan.relevance.scoring.scene import kind_of
from relevance_plan.relevance.selection.completion import lacking
from relevance_plan.relevance.setup import ScoringOptions, score_problem

DRAFT_RATIO = 1.2  # a draft may keep this many times what the goal scorer needs
MAX_ROUNDS = 8


@dataclass(frozen=True)
class ProblemCheck:
    """One given problem under the draft and under the goal scorer."""

    problem: str
    objects: int
    kept: int  # the draft's first selection
    goal_kept: int  # the goal scorer's first selection
    goal_lacks: tuple[str, ...]  # what the goal scorer's first selection lacks (its first attempt fails)
    lacks: tuple[str, ...] = ()  # what the draft's first selection lacks
    insufficiency: str = ""  # why the draft decided nothing ("" when it did)
    chosen: frozenset[str] = frozenset()  # what the draft's thresholds chose (not the goal's objects)
    kept_objects: frozenset[str] = frozenset()  # the draft's first selection

    @property
    def goal_needs(self) -> int:
        """What the goal scorer's first attempt needs: its selection and what that lacks."""
        return self.goal_kept + len(self.goal_lacks)

    @property
    def sufficient(self) -> bool:
        return not self.insufficiency and not self.lacks

    @property
    def matched(self) -> bool:
        return self.sufficient and self.kept <= DRAFT_RATIO * self.goal_needs

    def describe(self) -> str:
        if self.insufficiency:
            return f"{self.problem}: the draft decides nothing: {self.insufficiency}"
        goal = f"the goal scorer {self.goal_kept}" + (
            f" (its first attempt lacks {len(self.goal_lacks)}: {', '.join(self.goal_lacks[:4])})"
            if self.goal_lacks
            else ""
        )
        said = f"{self.problem}: kept {self.kept} of {self.objects} with the draft, {goal}"
        if self.lacks:
            return f"{said}; the draft lacks {', '.join(self.lacks[:4])}"
        return said + ("" if self.matched else f"; more than {DRAFT_RATIO:g}x what the goal scorer needs")


def check_problem(
    item: ProblemEvidence, model: KnowledgeModel, strict: PlanningTask, goal_lacks: tuple[str, ...]
) -> ProblemCheck:
    task = item.task
    total, goal_kept = len(task.problem.objects), len(item.selection.kept)
    scoring = score_problem(task, ScoringOptions(scorer="model"), knowledge_model=model)
    if not scoring.scores.sufficient:
        return ProblemCheck(item.name, total, 0, goal_kept, goal_lacks, insufficiency=scoring.scores.insufficiency)
    selection = scoring.first_selection()
    lacks = tuple(sorted(r.name for r in lacking(strict, selection.kept, scoring.scores.element_scores, model)))
    chosen = selection.selected - task.goal_objects
    return ProblemCheck(
        item.name, total, len(selection.kept), goal_kept, goal_lacks, lacks, chosen=chosen, kept_objects=selection.kept
    )


RAISED = "raised by the check"


def adjust(draft: Draft, item: ProblemEvidence, check: ProblemCheck) -> tuple[Draft, list[str]]:
    """The draft changed toward matching ``check``'s problem, and notes saying how (none: it cannot)."""
    if check.insufficiency:
        return draft, []
    if check.lacks:
        return _supply(draft, item, check)
    if not check.matched:
        return _narrow(draft, item, check)
    return draft, []


def _supply(draft: Draft, item: ProblemEvidence, check: ProblemCheck) -> tuple[Draft, list[str]]:
    """A dependency for each missing object a static fact ties to a kept one; else a higher prior."""
    notes = []
    task = item.task
    used = _precondition_predicates(task)
    drafted = {(d.predicate, d.when_kept, d.restore) for d in draft.dependencies}
    for name in check.lacks:
        link = _static_link(task, name, used, check.kept_objects, draft.structure.portable)
        if link is not None and link not in drafted:
            predicate, when_kept, restore = link
            drafted.add(link)
            draft = draft.with_dependency(
                DraftedDependency(
                    predicate,
                    when_kept,
                    restore,
                    f"the {item.class_of(name)} it needs ({predicate})",
                    f"the check: {item.name} lacked {name} without it",
                )
            )
            notes.append(f"{item.name} lacked {name}: added a dependency on ({predicate} ...)")
            continue
        class_name, kind = item.class_of(name), kind_of(name)
        why = f"{RAISED}: {item.name} lacked {name}"
        prior = draft.priors.get((item.objective, class_name))
        if prior is not None and not prior.why.startswith(RAISED):
            draft = draft.with_prior(item.objective, class_name, Prior(HIGH, why))
            notes.append(f"{item.name} lacked {name}: raised P({class_name} | {item.objective})")
        kind_prior = draft.kinds.get((class_name, kind))
        if kind_prior is None or not kind_prior.why.startswith(RAISED):
            draft = draft.with_kind(class_name, kind, Prior(HIGH, why))
            notes.append(f"{item.name} lacked {name}: raised P({kind} | {class_name})")
    return draft, notes


def _narrow(draft: Draft, item: ProblemEvidence, check: ProblemCheck) -> tuple[Draft, list[str]]:
    """Lower the kinds the draft chose and the goal scorer did not need (never one the check raised)."""
    notes = []
    needed = item.selection.kept
    for name in sorted(check.chosen - needed):
        class_name, kind = item.class_of(name), kind_of(name)
        prior = draft.kinds.get((class_name, kind), Prior(HIGH, ""))
        if prior.why.startswith(RAISED) or prior.value <= LOW:
            continue
        draft = draft.with_kind(class_name, kind, Prior(LOW, f"lowered by the check: {item.name} needs no {kind}"))
        notes.append(f"{item.name} kept {name} the goal scorer did not need: lowered P({kind} | {class_name})")
    return draft, notes


def _precondition_predicates(task: PlanningTask) -> set[str]:
    return {atom.predicate for action in task.domain.actions for atom, _ in literals(action.precondition)}


def _static_link(
    task: PlanningTask, name: str, used: set[str], kept: Set[str], portable: Set[str]
) -> tuple[str, int, int] | None:
    """(predicate, position of the kept object, position of ``name``) of a static initial fact an
    action's precondition reads that ties ``name``, a thing the robot carries (of a ``portable``
    type), to a kept object."""
    static = static_predicates(task.domain)
    if not any(t in portable for t in task.domain.ancestors(task.problem.objects[name])):
        return None  # what is not carried (a door, a room) comes back through the reachability check
    for atom in sorted(task.init_index.by_object.get(name, ())):
        if atom[0] in static and atom[0] in used and len(atom) == 3 and atom[1] != atom[2]:
            restore = atom.index(name) - 1
            if atom[2 - restore] in kept:
                return atom[0], 1 - restore, restore
    return None


def check_all(
    evidence: Sequence[ProblemEvidence],
    model: KnowledgeModel,
    strict: Mapping[str, PlanningTask],
    goal_lacks: Mapping[str, tuple[str, ...]],
) -> list[ProblemCheck]:
    return [check_problem(item, model, strict[item.name], goal_lacks[item.name]) for item in evidence]
