"""A knowledge model drafted from a domain's own structure and a few of its problems, for a person to review.

    structure.py  scene roles and dependencies, from the action schemas
    evidence.py   the problems: objectives, classes and kinds, what the goal scorer keeps
    draft.py      classes, objectives, priors, each with where it came from
    check.py      the draft against the goal scorer on each problem, and the adjustments
    writer.py     the commented YAML

:func:`draft_model` runs them: the drafted model is written, read back (it
loads as any model does), checked on every given problem and adjusted until
it prunes no worse than no model there, or the check says where it could not.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

from relevance_plan.errors import UsageError
from relevance_plan.pddl.model import Domain
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.drafting.check import (
    DRAFT_RATIO,
    MAX_ROUNDS,
    ProblemCheck,
    adjust,
    check_all,
)
from relevance_plan.relevance.drafting.draft import Draft, first_draft
from relevance_plan.relevance.drafting.evidence import ProblemEvidence, read_evidence
from relevance_plan.relevance.drafting.structure import find_dependencies, find_structure
from relevance_plan.relevance.drafting.writer import draft_text
from relevance_plan.relevance.scoring.knowledge import KnowledgeModel, parse_knowledge_model
from relevance_plan.relevance.selection.completion import lacking, strict_task


@dataclass(frozen=True)
class DraftedModel:
    """The drafted model's text and value, the check of every given problem, and what the check changed."""

    text: str
    model: KnowledgeModel
    checks: tuple[ProblemCheck, ...]
    adjustments: tuple[str, ...]

    @property
    def matched(self) -> bool:
        return all(check.matched for check in self.checks)

    @property
    def unmatched(self) -> tuple[ProblemCheck, ...]:
        return tuple(check for check in self.checks if not check.matched)


def draft_model(domain: Domain, tasks: Sequence[PlanningTask], path: str = "<drafted model>") -> DraftedModel:
    """A knowledge model for ``domain`` drafted from its schemas and ``tasks`` (its problems), checked on them."""
    if not tasks:
        raise UsageError("drafting a knowledge model needs at least one problem of the domain")
    structure = find_structure(domain)
    evidence = read_evidence(tasks)
    draft = first_draft(domain, structure, evidence, find_dependencies(domain, structure))
    strict = {item.name: strict_task(item.task) for item in evidence}
    goal_lacks = {
        item.name: tuple(
            sorted(
                r.name
                for r in lacking(strict[item.name], item.selection.kept, item.selection.scores.element_scores, None)
            )
        )
        for item in evidence
    }
    run = _CheckInputs(evidence, strict, goal_lacks, path)
    notes: list[str] = []
    for _ in range(MAX_ROUNDS):
        checks = run.check(draft)
        changed = draft
        for item, check in zip(evidence, checks):
            changed, said = adjust(changed, item, check)
            notes += said
        if changed == draft:
            break
        draft = changed
    else:
        checks = run.check(draft)
    draft, checks, said = _leave_out_dependencies(run, draft, checks)
    return _finished(draft, run.names, notes + said, checks, path)


@dataclass(frozen=True)
class _CheckInputs:
    """What every round of the check reads: the problems, their strict versions, what the goal scorer lacks."""

    evidence: Sequence[ProblemEvidence]
    strict: Mapping[str, PlanningTask]
    goal_lacks: Mapping[str, tuple[str, ...]]
    path: str

    @property
    def names(self) -> list[str]:
        return [item.name for item in self.evidence]

    def check(self, draft: Draft) -> list[ProblemCheck]:
        model = parse_knowledge_model(draft_text(draft, self.names), self.path)
        return check_all(self.evidence, model, self.strict, self.goal_lacks)


def _leave_out_dependencies(
    run: _CheckInputs, draft: Draft, checks: list[ProblemCheck]
) -> tuple[Draft, list[ProblemCheck], list[str]]:
    """Without each dependency in turn: left out when every problem stays sufficient with fewer objects
    kept (a lock with two keys: the reachability check takes the one a plan uses, a dependency both)."""
    notes = []
    for dependency in draft.dependencies:
        why = "with it the draft keeps more, and without it lacks nothing"
        trial = draft.without_dependency(dependency, why)
        tried = run.check(trial)
        fewer = sum(c.kept for c in tried) < sum(c.kept for c in checks)
        if (
            fewer
            and all(c.sufficient for c in tried)
            and sum(c.matched for c in tried) >= sum(c.matched for c in checks)
        ):
            draft, checks = trial, tried
            notes.append(f"left out the dependency on ({dependency.predicate} ...): {why}")
    return draft, checks, notes


def _finished(draft: Draft, names: list[str], notes: list[str], checks: list[ProblemCheck], path: str) -> DraftedModel:
    """The final text: the check's changes and, for each problem it could not match, why."""
    said = [f"The check: {note}." for note in notes]
    said += [f"Not matched: {check.describe()}." for check in checks if not check.matched]
    text = draft_text(draft, names, said)
    return DraftedModel(text, parse_knowledge_model(text, path), tuple(checks), tuple(notes))


__all__ = ["DRAFT_RATIO", "DraftedModel", "ProblemCheck", "draft_model"]
