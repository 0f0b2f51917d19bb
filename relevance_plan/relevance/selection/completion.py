"""Completing a first selection for what the relaxed check passes over: the negative preconditions.

The reachability check (``exploration``, ``repair``) ignores conditions such
as ``(not (locked ?s))``: on it, a toolbox opens without its key.  Compiled
into complements (``(not-locked ?s)``, true of every unlocked storage and
added by ``unlock``: ``pddl.compile``), the same check sees the lock, and the
repair adds the key, the drawer it is in and the way there.  A knowledge
model asks for this with ``reachability_check: true`` (drafted models do); the
drafting check uses it to compare a draft with the goal scorer.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import replace

from relevance_plan.errors import UnsupportedFeatureError
from relevance_plan.pddl.compile import compile_negative_preconditions
from relevance_plan.pddl.writer import write_pruned_problem
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.reachability.exploration import relaxed_reachability
from relevance_plan.relevance.scoring.knowledge import KnowledgeModel
from relevance_plan.relevance.selection.closure import ConstraintClosure, Restored
from relevance_plan.relevance.selection.prune import Selection
from relevance_plan.relevance.selection.repair import repair_selection


def strict_task(task: PlanningTask) -> PlanningTask:
    """The task with negative preconditions compiled into complements (the task itself when it has
    none, or they cannot be compiled)."""
    try:
        compiled = compile_negative_preconditions(task.domain, task.problem)
    except UnsupportedFeatureError:
        return task
    if compiled.problem.init == task.problem.init and compiled.domain.predicates == task.domain.predicates:
        return task
    return PlanningTask(compiled.domain, compiled.problem, deadline=task.deadline)


def lacking(
    strict: PlanningTask, kept: frozenset[str], scores: Mapping[str, float], model: KnowledgeModel | None
) -> tuple[Restored, ...]:
    """What ``kept`` lacks on ``strict`` for the goal to be reachable ignoring deletes, each with the
    relaxed plan's step that needs it (nothing when the goal is reachable, or out of reach whatever is added)."""
    if relaxed_reachability(strict, kept).reachable:
        return ()
    repaired, reasons, check = repair_selection(strict, kept, scores, ConstraintClosure.of(strict, model))
    if not check.reachable:
        return ()
    return tuple(reason for reason in reasons if reason.name in repaired - kept)


def complete_selection(selection: Selection, model: KnowledgeModel | None) -> Selection:
    """``selection`` with what its goal needs once negative preconditions count (see the module docstring)."""
    task = selection.task
    strict = strict_task(task)
    if strict is task:
        return selection
    added = lacking(strict, selection.kept, selection.scores.element_scores, model)
    if not added:
        return selection
    kept = selection.kept | {reason.name for reason in added}
    task.check_time("checking the selection")
    return replace(
        selection,
        kept=kept,
        restored=selection.restored + added,
        text=write_pruned_problem(task.problem, kept),
        set_aside=selection.set_aside - kept,
    )
