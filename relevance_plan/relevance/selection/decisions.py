"""Every pruning decision, named by the step that made it.

A selection (``prune.Selection``) says what was kept; this says, for each
object, which step kept or dropped it and why: the goal names it; it passed
the thresholds; closure, a dependency of the knowledge model, the
reachability check or soundness put it back; or it stayed below the
thresholds, the goal filter left it out (relevant, but no action toward the
goal can use it), or it was set aside for a later attempt.  ``score`` prints
these, ``score --why NAME`` follows one object's chain back to what the goal
needs.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from relevance_plan.relevance.scoring.scorers.knowledge_model import GOAL_EXPLANATION
from relevance_plan.relevance.selection.closure import Restored
from relevance_plan.relevance.selection.prune import Selection, can_serve_goal

# The steps, as ``score`` names them.
GOAL = "goal"
THRESHOLDS = "thresholds"
CLASS_THRESHOLD = "class threshold"
GOAL_FILTER = "goal filter"
SET_ASIDE = "set aside"
CLOSURE = "closure"
DEPENDENCY = "dependency"
REACHABILITY_CHECK = "reachability check"
SOUNDNESS = "soundness"
FULL_PROBLEM = "full problem"
NO_CUES = "insufficient cues"

# The step that put an object back, by the closure rule that did.
_RESTORING_STEP = {
    "blocker": CLOSURE,
    "anchor": CLOSURE,
    "singleton": CLOSURE,
    "model": DEPENDENCY,
    "reachability": REACHABILITY_CHECK,
    "soundness": SOUNDNESS,
}


@dataclass(frozen=True)
class Decision:
    """Why one object is kept or not: the step, its reason, and the score shown for it."""

    name: str
    kept: bool
    step: str
    reason: str
    score: float
    restored: Restored | None = None  # the closure entry, for objects put back

    @property
    def status(self) -> str:
        """``score``'s kept column: yes, restored, aside or no."""
        if self.kept:
            return "restored" if self.restored is not None or self.step == FULL_PROBLEM else "yes"
        return "aside" if self.step == SET_ASIDE else "no"

    def as_json(self) -> dict[str, Any]:
        return {"kept": self.kept, "step": self.step, "reason": self.reason}


def decide(selection: Selection) -> dict[str, Decision]:
    """Each object's decision, in the problem's order."""
    restored = _restored_by(selection)
    return {name: _decision(selection, name, restored) for name in selection.task.problem.objects}


def _restored_by(selection: Selection) -> Mapping[str, Restored]:
    found: dict[str, Restored] = {}
    for item in selection.restored:
        found.setdefault(item.name, item)
    return found


def _decision(selection: Selection, name: str, restored: Mapping[str, Restored]) -> Decision:
    task, scores = selection.task, selection.scores
    value = scores.element_scores.get(name, 0.0)
    explanation = scores.explanations.get(name, "")
    if name in task.pinned_objects:
        return Decision(name, True, GOAL, GOAL_EXPLANATION, 1.0)
    if not scores.sufficient:
        return Decision(name, name in selection.kept, NO_CUES, scores.insufficiency, value)
    if name in selection.selected and name in selection.kept:
        return Decision(name, True, THRESHOLDS, explanation, value)
    if name in restored and name in selection.kept:
        item = restored[name]
        reason = item.describe(task.problem.spelling)
        return Decision(name, True, _RESTORING_STEP.get(item.rule, CLOSURE), reason, value, item)
    if name in selection.kept:
        return Decision(name, True, FULL_PROBLEM, selection.unpruned_reason or "the full problem is planned", value)
    return _dropped(selection, name, value, explanation)


def _dropped(selection: Selection, name: str, value: float, explanation: str) -> Decision:
    task, scores, thresholds = selection.task, selection.scores, selection.thresholds
    if name in selection.set_aside:
        why = (
            "blocked (a fact naming it must be undone before it can be used) and a free object of its class is kept"
            if scores.scorer == "model"
            else "one of many candidates for its role, and a relaxed plan needs others"
        )
        return Decision(name, False, SET_ASIDE, f"{why} (a later attempt brings it back if needed)", value)
    class_score = scores.class_score(name)
    if class_score is not None and class_score <= thresholds.tau_class:
        class_name = scores.element_class.get(name, "?")
        return Decision(
            name,
            False,
            CLASS_THRESHOLD,
            f"R({class_name})={class_score:.2f} is not above tau_c {thresholds.tau_class:g}",
            value,
        )
    if thresholds.admits(class_score, value) and not can_serve_goal(task, name):
        return Decision(
            name,
            False,
            GOAL_FILTER,
            f"relevant (R(e)={value:.2f}), but no action toward the goal can use {_a(task.object_type(name))}",
            value,
        )
    because = f" ({explanation})" if explanation else ""
    return Decision(
        name, False, THRESHOLDS, f"R(e)={value:.2f} is not above tau_e {thresholds.tau_element:g}{because}", value
    )


def _a(noun: str) -> str:
    return ("an " if noun[:1] in "aeiou" else "a ") + noun


@dataclass(frozen=True)
class ClassKept:
    """A scored class in ``score``'s class table: kept when one of its objects is kept, by whatever
    step, so the class table says what the element table says."""

    kept: int  # its objects kept
    objects: int  # its objects

    @property
    def any_kept(self) -> bool:
        return self.kept > 0

    def as_json(self) -> dict[str, Any]:
        return {"kept": self.any_kept, "objects_kept": self.kept, "objects": self.objects}


def classes_kept(selection: Selection, decisions: Mapping[str, Decision] | None = None) -> dict[str, ClassKept]:
    """Each class the scorer scored, with how many of its objects the decisions keep."""
    decided = decide(selection) if decisions is None else decisions
    element_class = selection.scores.element_class
    counts = {class_name: [0, 0] for class_name in selection.scores.class_scores}
    for name, decision in decided.items():
        count = counts.get(element_class.get(name, ""))
        if count is not None:
            count[0] += decision.kept
            count[1] += 1
    return {class_name: ClassKept(kept, objects) for class_name, (kept, objects) in counts.items()}


def kept_summary(selection: Selection) -> str:
    """``kept 9 of 54 objects (4 relevant, 2 by closure, 1 by the reachability check)``."""
    counts = Counter(d.step for d in decide(selection).values() if d.kept)
    parts = [f"{counts[step]} {label}" for step, label in _SUMMARY_LABELS if counts[step]]
    total = len(selection.task.problem.objects)
    return f"kept {len(selection.kept)} of {total} objects" + (f" ({', '.join(parts)})" if parts else "")


_SUMMARY_LABELS = (
    (GOAL, "named in the goal"),
    (THRESHOLDS, "relevant"),
    (CLOSURE, "by closure"),
    (DEPENDENCY, "by a dependency"),
    (REACHABILITY_CHECK, "by the reachability check"),
    (SOUNDNESS, "for soundness"),
    (FULL_PROBLEM, "as the full problem"),
    (NO_CUES, "undecided"),
)


def why(selection: Selection, name: str) -> list[Decision]:
    """``name``'s decision, then the decisions of the objects that brought it back, in turn, up to
    one the goal or the thresholds chose (what closure followed to reach it)."""
    decisions = decide(selection)
    chain = [decisions[name]]
    seen = {name}
    while chain[-1].restored is not None and chain[-1].restored.because_of not in ("", *seen):
        cause = chain[-1].restored.because_of
        seen.add(cause)
        chain.append(decisions[cause])
    return chain
