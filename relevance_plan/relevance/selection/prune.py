"""Pruning: from scores to the objects an attempt keeps, in five stages, as one result value.

    select -> close -> set aside -> repair -> finish

* **select** (:func:`select_relevant`): the objects whose class and score pass
  the thresholds, the pinned ones always, and the ``extra`` objects a widening
  adds; with the goal filter, relevant objects no action toward the goal can
  use stay out;
* **close** (``closure.ConstraintClosure``): what the selected objects depend
  on comes back, each with its reason, and what a quantifier ranges over stays;
* **set aside**: alternatives the first attempt bets it can do without, left
  for a later one: blocked ones while a free one of their class is kept
  (:func:`without_blocked_alternatives`), and the spare candidates of a populous role,
  which the repair brings back as a relaxed plan needs them;
* **repair** (``repair.repair_selection``): a kept set on which the goal is
  unreachable even ignoring deletes gets what a relaxed plan needs;
* **finish**: the pruned problem's text, or the full problem when the
  selection keeps most of it.

Each stage takes the selection so far (``_Partial``, immutable) and returns the
next; :class:`PruneSettings` holds the knobs.  :func:`widen` grows a failed
selection, adding objects in the order of :func:`ranked_names`.
"""

from __future__ import annotations

from collections import Counter, defaultdict
from collections.abc import Sequence, Set
from dataclasses import dataclass, field, replace
from typing import Any

from relevance_plan.pddl.formatter import format_atom
from relevance_plan.pddl.formulas import GroundAtom
from relevance_plan.pddl.writer import write_pruned_problem
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.analysis.types import static_predicates
from relevance_plan.relevance.scoring.knowledge import KnowledgeModel, check_threshold
from relevance_plan.relevance.scoring.scorers import ScoreResult
from relevance_plan.relevance.scoring.scorers.knowledge_model import UNKNOWN_CLASS
from relevance_plan.relevance.selection.closure import ConstraintClosure, Restored
from relevance_plan.relevance.selection.neighbourhood import next_ring
from relevance_plan.relevance.selection.repair import repair_selection

DEFAULT_TAU = 0.2
FULL_ABOVE = 0.8  # a selection keeping more than this share of the objects plans on the full problem
GROWTH = 2.0  # each widening at least doubles the kept set
REPAIR_SCORERS = frozenset({"goal", "learned"})  # scorers whose selection the reachability check repairs by default


@dataclass(frozen=True)
class Thresholds:
    tau_class: float = DEFAULT_TAU
    tau_element: float = DEFAULT_TAU

    def __post_init__(self) -> None:
        check_threshold(self.tau_class, "--tau-class")
        check_threshold(self.tau_element, "--tau-element")

    def admits(self, class_score: float | None, element_score: float) -> bool:
        """The paper's test, in one place: the element's class passes tau_c (when classes are
        scored: ``class_score`` is None otherwise), then the element passes tau_e."""
        if class_score is not None and class_score <= self.tau_class:
            return False
        return element_score > self.tau_element

    def scaled(self, factor: float) -> Thresholds:
        return Thresholds(self.tau_class * factor, self.tau_element * factor)


@dataclass(frozen=True)
class PruneSettings:
    """How a selection is narrowed and checked; the defaults are thresholds and closure alone."""

    goal_filter: bool = False  # leave out relevant objects no action toward the goal can use
    prefer_free: bool = False  # set aside blocked alternatives while a free one of their class is kept
    # (with the repair) set aside the selected candidates of a populous role (ScoreResult.alternatives):
    # the repair brings back, best ranked first, those a relaxed plan needs (one airplane carries every package)
    economical: bool = False
    repair: bool | None = None  # None: for REPAIR_SCORERS at the default thresholds or lower
    # keeping more than this share of the objects means the full problem: pruning would save little and
    # risk a second attempt (None: FULL_ABOVE for REPAIR_SCORERS; 1 for the others, kept as chosen)
    full_above: float | None = None
    set_aside: frozenset[str] = frozenset()  # what earlier selections set aside: stays out unless given as extra

    def repairs(self, scorer: str, thresholds: Thresholds) -> bool:
        if self.repair is not None:
            return self.repair
        # A stricter selection than the defaults, asked for explicitly, is tried as given.
        return scorer in REPAIR_SCORERS and max(thresholds.tau_class, thresholds.tau_element) <= DEFAULT_TAU

    def full_share(self, scorer: str) -> float:
        if self.full_above is not None:
            return self.full_above
        return FULL_ABOVE if scorer in REPAIR_SCORERS else 1.0


@dataclass(frozen=True)
class Selection:
    task: PlanningTask
    scores: ScoreResult
    thresholds: Thresholds
    selected: frozenset[str]  # passed the thresholds (plus goal objects)
    kept: frozenset[str]  # after closure
    restored: tuple[Restored, ...]  # in the order closure found them
    text: str = field(repr=False)  # the pruned problem in the user's own layout
    set_aside: frozenset[str] = frozenset()  # alternatives left for a later attempt (without_blocked_alternatives)
    unpruned_reason: str = ""  # why every object is kept, when one is ("" when the selection prunes)
    # goal atom -> the kept object it is met through, where it needs one of its own (``witnesses``)
    witnesses: tuple[tuple[GroundAtom, str], ...] = ()

    @property
    def removed(self) -> tuple[str, ...]:
        return tuple(name for name in self.task.problem.objects if name not in self.kept)

    @property
    def sufficient(self) -> bool:
        return self.scores.sufficient

    def describe(self) -> dict[str, Any]:
        """What was kept, removed and restored (with reasons), in the user's spelling, for JSON output."""
        problem = self.task.problem
        return {
            "pruned": bool(self.removed),
            "unpruned_reason": self.unpruned_reason or None,
            "objects_total": len(problem.objects),
            "objects_kept": len(self.kept),
            "kept": [problem.display(n) for n in problem.objects if n in self.kept],
            "removed": [problem.display(n) for n in self.removed],
            "restored": [
                {
                    "object": problem.display(r.name),
                    "reason": r.describe(problem.spelling),
                    "rule": r.rule,
                    "because_of": problem.display(r.because_of) if r.because_of else "",
                }
                for r in self.restored
            ],
            "set_aside": [problem.display(n) for n in problem.objects if n in self.set_aside],
            "witnesses": [
                {"goal": format_atom(goal, problem.spelling), "object": problem.display(name)}
                for goal, name in self.witnesses
            ],
        }


@dataclass(frozen=True)
class _Partial:
    """The selection so far, as one pruning stage hands it to the next."""

    selected: frozenset[str]  # passed the thresholds, and the extra objects
    set_aside: frozenset[str]
    kept: frozenset[str] = frozenset()  # the selected ones closed, and what the repair added
    restored: tuple[Restored, ...] = ()  # why each kept object that was not selected is kept
    witnesses: tuple[tuple[GroundAtom, str], ...] = ()  # the repair's last check's


def prune_with_scores(
    task: PlanningTask,
    scores: ScoreResult,
    thresholds: Thresholds = Thresholds(),
    knowledge_model: KnowledgeModel | None = None,
    extra: Set[str] = frozenset(),
    settings: PruneSettings = PruneSettings(),
) -> Selection:
    """The selection ``settings`` ask for: select -> close -> set aside -> repair -> finish (see the
    module's docstring).  ``extra`` objects are kept whatever their scores; ``knowledge_model``
    adds the dependencies it declares to closure's rules."""
    extra = frozenset(extra) & task.problem.objects.keys()
    draft = _select(task, scores, thresholds, settings, extra)
    task.check_time("choosing the objects")
    closure = ConstraintClosure.of(task, knowledge_model)
    draft = _close(draft, closure)
    task.check_time("closing the selection over constraints")
    if settings.prefer_free:
        draft = _set_aside_blocked(task, scores, draft, closure)
    repair = settings.repairs(scores.scorer, thresholds)
    if repair and settings.economical:
        draft = _set_aside_spare(task, scores, draft, closure, extra)
    full_above = settings.full_share(scores.scorer)
    if repair and task.witness_shortfall:
        # no selection can do what the whole problem cannot: the planner decides on the full problem
        proof = task.proved_unsolvable
        why = f"{proof}: the problem has no plan" if proof else f"{task.witness_shortfall}: the full problem"
        return full_problem(task, scores, thresholds, draft.selected, draft.restored, why)
    if repair and len(draft.kept) <= full_above * len(task.problem.objects):
        draft = _repair(task, scores, draft, closure)
    return _finish(task, scores, thresholds, draft, full_above)


def _select(
    task: PlanningTask, scores: ScoreResult, thresholds: Thresholds, settings: PruneSettings, extra: frozenset[str]
) -> _Partial:
    """The relevant objects and the extra ones, without what earlier selections set aside."""
    set_aside = settings.set_aside - extra
    selected = (select_relevant(task, scores, thresholds, settings.goal_filter) - set_aside) | extra
    return _Partial(selected & task.problem.objects.keys(), set_aside)


def _close(draft: _Partial, closure: ConstraintClosure) -> _Partial:
    kept, restored = closure(draft.selected)
    return replace(draft, kept=kept, restored=restored)


def _set_aside_blocked(
    task: PlanningTask, scores: ScoreResult, draft: _Partial, closure: ConstraintClosure
) -> _Partial:
    """Without the blocked alternatives (``without_blocked_alternatives``), closed again."""
    narrowed = without_blocked_alternatives(task, scores, draft.selected, draft.restored)
    if narrowed == draft.selected:
        return draft
    return _close(replace(draft, selected=narrowed, set_aside=draft.set_aside | (draft.selected - narrowed)), closure)


def _set_aside_spare(
    task: PlanningTask, scores: ScoreResult, draft: _Partial, closure: ConstraintClosure, extra: frozenset[str]
) -> _Partial:
    """Without the spare alternatives (``_spare_alternatives``; never the extra ones), closed again."""
    spare = _spare_alternatives(task, scores, draft.selected - extra)
    if not spare:
        return draft
    return _close(replace(draft, selected=draft.selected - spare, set_aside=draft.set_aside | spare), closure)


def _repair(task: PlanningTask, scores: ScoreResult, draft: _Partial, closure: ConstraintClosure) -> _Partial:
    """With what a relaxed plan needs; what the repair brought back is no longer set aside."""
    kept, repaired, check = repair_selection(task, draft.kept, scores.element_scores, closure)
    restored, set_aside = draft.restored + repaired, draft.set_aside - kept
    return replace(draft, kept=kept, restored=restored, set_aside=set_aside, witnesses=check.witnesses)


def _finish(
    task: PlanningTask, scores: ScoreResult, thresholds: Thresholds, draft: _Partial, full_above: float
) -> Selection:
    """The pruned problem, or the full one when the draft keeps more than ``full_above`` of the objects."""
    total = len(task.problem.objects)
    if len(draft.kept) > full_above * total:
        why = f"the selection kept {len(draft.kept)} of {total} objects (more than {full_above:.0%}): the full problem"
        return full_problem(task, scores, thresholds, draft.selected, draft.restored, why)
    task.check_time("checking the selection")
    kept, text = draft.kept, write_pruned_problem(task.problem, draft.kept)
    why = _why_nothing_pruned(task, kept, draft.restored)
    return Selection(
        task, scores, thresholds, draft.selected, kept, draft.restored, text, draft.set_aside, why, draft.witnesses
    )


def can_serve_goal(task: PlanningTask, name: str) -> bool:
    """Whether the object can fill a role toward the goal (see ``analysis.analyse_goal``)."""
    roles = task.goal_analysis.role_depth
    domain = task.typing.domain
    return name in task.goal_objects or any(t in roles for t in domain.ancestors(task.object_type(name)))


def select_relevant(
    task: PlanningTask, scores: ScoreResult, thresholds: Thresholds, goal_filter: bool = False
) -> frozenset[str]:
    """Elements whose class passes tau_c (when classes are scored) and whose score passes tau_e.

    With ``goal_filter``, relevant objects no action toward the goal can use
    (a napkin the domain can only carry around) are left out too: relevant to
    the human, useless to the planner.  Closure still puts back what the kept
    objects need (their places, what stands on them).
    """
    passing = scores.passing.get(thresholds)
    if passing is None:
        passing = scores.passing[thresholds] = frozenset(
            name for name, score in scores.element_scores.items() if thresholds.admits(scores.class_score(name), score)
        )
    selected = set(task.pinned_objects)
    selected.update(name for name in passing if not goal_filter or can_serve_goal(task, name))
    return frozenset(selected)


def without_blocked_alternatives(
    task: PlanningTask, scores: ScoreResult, selected: frozenset[str], restored: Sequence[Restored]
) -> frozenset[str]:
    """``selected`` without the objects that something stands on, when another selected
    object of the same model class stands free.

    Any cup serves coffee: a cup under a plate costs the planner the plate as
    well, and every extra item multiplies grounding.  Only classes of a
    knowledge model are treated as interchangeable (a PDDL type is not: all
    blocks of a tower are needed); goal objects always stay.
    """
    if scores.scorer != "model":
        return selected
    encumbered = {item.because_of for item in restored if item.rule == "blocker"}
    members_by_class: dict[str, set[str]] = defaultdict(set)
    for name in selected - task.goal_objects:
        class_name = scores.element_class.get(name)
        if class_name is not None and class_name != UNKNOWN_CLASS:
            members_by_class[class_name].add(name)
    set_aside = set()
    for members in members_by_class.values():
        if members - encumbered:
            set_aside |= members & encumbered
    return selected - set_aside


def _spare_alternatives(task: PlanningTask, scores: ScoreResult, selected: frozenset[str]) -> frozenset[str]:
    """The selected alternatives the first selection may leave to the repair: not pinned, not
    kept for soundness, and not of a class whose members a static fact links to each other (the
    cells of a grid, the rooms of a map: a plan may need a way round that no relaxed plan takes)."""
    if not scores.alternatives:
        return frozenset()
    classes = task.typing.problem.objects
    static = static_predicates(task.typing.domain)
    linked: set[str] = set()
    for predicate in static:
        for atom in task.init_index.by_predicate.get(predicate, ()):
            seen = [classes.get(arg) for arg in atom[1:]]
            linked.update(c for i, c in enumerate(seen) if c is not None and c in seen[i + 1 :])
    keep = task.pinned_objects | task.kept_for_soundness.always.keys()
    return frozenset(
        name for name in scores.alternatives & selected if name not in keep and classes.get(name) not in linked
    )


def _why_nothing_pruned(task: PlanningTask, kept: Set[str], restored: Sequence[Restored]) -> str:
    if len(kept) < len(task.problem.objects):
        return ""
    rules = sorted({item.rule for item in restored})
    if "soundness" in rules:
        return "every object is kept: a quantifier ranges over them (see the soundness reasons)"
    return "every object is relevant or needed by a relevant one" + (f" ({', '.join(rules)})" if rules else "")


def full_problem(
    task: PlanningTask,
    scores: ScoreResult,
    thresholds: Thresholds,
    selected: Set[str] = frozenset(),
    restored: Sequence[Restored] = (),
    why: str = "",
) -> Selection:
    """The result that keeps every object (``why`` says why): the attempt loop plans on the user's own file."""
    kept, text = frozenset(task.problem.objects), task.problem.text
    return Selection(task, scores, thresholds, frozenset(selected), kept, tuple(restored), text, unpruned_reason=why)


@dataclass(frozen=True)
class Widening:
    """How one widening step grows a selection after a failed attempt."""

    factor: float  # the thresholds are multiplied by it
    goal_filter: bool = False
    growth: float = GROWTH  # the kept set grows at least this many times (and by four objects)
    full_above: float = FULL_ABOVE  # past this share of the objects, the full problem
    step: int = 0  # how many widenings came before this one (rings alternate by it: ``neighbourhood``)


def widen(
    result: Selection,
    widening: Widening,
    extra: Set[str] = frozenset(),
    knowledge_model: KnowledgeModel | None = None,
) -> tuple[Selection, frozenset[str]]:
    """One widening step after a failed attempt; returns the new selection and the extra set.

    The thresholds shrink by ``widening.factor`` and the best-ranked removed
    objects (``ranked_names``) are put back until the kept set has at least
    ``growth`` times as many objects, so all failed attempts together cost
    about as much as the last one.  When that would keep more than
    ``full_above`` of the objects, the result is the full problem.  The
    alternatives set aside stay aside, and come back late.

    In a network (``PlanningTask.network``), a selection the repair made grows by rings instead
    (:func:`_widen_by_rings`): tens of objects next to the kept ones, not twice as many.
    """
    task, kept = result.task, result.kept
    if task.network and result.removed:
        by_rings = _widen_by_rings(result, widening, extra, knowledge_model)
        if by_rings is not None:
            return by_rings
    total = len(task.problem.objects)
    target = max(len(kept) + 4, int(widening.growth * len(kept) + 0.999))
    thresholds = result.thresholds.scaled(widening.factor)
    if target > widening.full_above * total:
        why = f"widening would keep more than {widening.full_above:.0%} of the objects: the full problem"
        return full_problem(task, result.scores, thresholds, result.selected, (), why), frozenset(task.problem.objects)
    settings = PruneSettings(
        goal_filter=widening.goal_filter, full_above=widening.full_above, set_aside=result.set_aside
    )
    extra, widened = frozenset(extra), result
    while len(widened.kept) < min(target, total):
        # closure or the thresholds may not account for every addition: add more by rank until the target
        ranked = ranked_names(task, result.scores, widened.kept, result.set_aside)
        extra |= frozenset(ranked[: target - len(widened.kept)])
        widened = prune_with_scores(task, result.scores, thresholds, knowledge_model, extra, settings)
    return widened, extra


def _widen_by_rings(
    result: Selection, widening: Widening, extra: Set[str], knowledge_model: KnowledgeModel | None
) -> tuple[Selection, frozenset[str]] | None:
    """The selection with the next ring of its network (``neighbourhood.next_ring``) kept too, closed
    and repaired again; None when no ring is left to add."""
    task = result.task
    closure = ConstraintClosure.of(task, knowledge_model)
    around = alternative_route(result, knowledge_model) - result.kept if widening.step == 0 else frozenset()
    if not around:
        around = next_ring(task, closure, result.kept, widening.step)
    if not around:
        return None
    total = len(task.problem.objects)
    grown = frozenset(extra) | result.kept | around
    if len(grown) > widening.full_above * total:
        why = f"widening would keep more than {widening.full_above:.0%} of the objects: the full problem"
        return full_problem(task, result.scores, result.thresholds, result.selected, (), why), frozenset(
            task.problem.objects
        )
    settings = PruneSettings(repair=True, full_above=widening.full_above, set_aside=result.set_aside)
    widened = prune_with_scores(task, result.scores, result.thresholds, knowledge_model, grown, settings)
    return widened, grown


def alternative_route(result: Selection, knowledge_model: KnowledgeModel | None) -> frozenset[str]:
    """The network members and other objects of a selection made as the first one is, on the problem
    without the members ``result`` kept beyond its selected objects and their anchors: another way to
    the goal, that avoids the one which failed (empty when the goal is out of reach without it)."""
    task = result.task
    network = task.network
    by_object = task.init_index.by_object
    anchored = {arg for name in result.selected for fact in by_object.get(name, ()) for arg in fact[1:]}
    avoided = (result.kept & network.members) - result.selected - anchored
    if not avoided:
        return frozenset()
    problem = task.problem
    objects = {name: kind for name, kind in problem.objects.items() if name not in avoided}
    init = frozenset(fact for fact in problem.init if not avoided.intersection(fact[1:]))
    reduced = replace(
        problem,
        objects=objects,
        init=init,
        init_order={fact: order for fact, order in problem.init_order.items() if fact in init},
        numeric_init={fact: value for fact, value in problem.numeric_init.items() if fact in init},
        object_groups=(),
        init_spans=(),
    )
    other_task = PlanningTask(task.domain, reduced, deadline=task.deadline)
    other = prune_with_scores(other_task, result.scores, result.thresholds, knowledge_model)
    if not other.removed:  # no way without what was avoided: the whole rest was kept
        return frozenset()
    return other.kept


def ranked_names(
    task: PlanningTask, scores: ScoreResult, kept: Set[str] = frozenset(), set_aside: Set[str] = frozenset()
) -> list[str]:
    """Objects outside ``kept``, in the order widening adds them back: one of each set of
    interchangeable objects (``PlanningTask.object_profiles``) before a second of any, the
    alternatives ``set_aside`` after the others, then by score and by hops from the goal's objects.

    A copy rarely does what its twin, kept or tried, could not: among fifty copies of a truck and
    one market that sells, the market comes second, not fifty-first.  Set-aside alternatives come
    late because the selection already holds a free member of their role, so a failed attempt
    more likely lacks an object of another role.  Before them all, the next witness of each goal
    atom that needs one of its own (:func:`next_witnesses`)."""
    values = scores.element_scores
    distance = task.goal_distance
    far = len(task.problem.objects) + 1

    def rank(name: str) -> tuple[bool, float, int, str]:
        return name in set_aside, -values.get(name, 0.0), distance.get(name, far), name

    candidates = sorted((name for name in task.problem.objects if name not in kept), key=rank)
    profiles = task.object_profiles
    seen = Counter(profiles[name] for name in kept if name in profiles)
    earlier: dict[str, int] = {}
    for name in candidates:
        earlier[name] = seen[profiles[name]]
        seen[profiles[name]] += 1
    first = next_witnesses(task, kept)
    ranked = sorted((name for name in candidates if name not in first), key=lambda name: (earlier[name], *rank(name)))
    return first + ranked


def next_witnesses(task: PlanningTask, kept: Set[str]) -> list[str]:
    """The best-ranked candidate outside ``kept`` of each goal atom that needs a witness of its own
    (``witnesses``): widening tries another vase before it takes back whole rooms."""
    needs = task.witness_needs + task.exists_needs
    chosen = (next((n for n in need.candidates if n not in kept), None) for need in needs)
    return list(dict.fromkeys(name for name in chosen if name is not None))


__all__ = [
    "DEFAULT_TAU",
    "PruneSettings",
    "Selection",
    "Restored",
    "Thresholds",
    "Widening",
    "full_problem",
    "next_witnesses",
    "ranked_names",
    "prune_with_scores",
    "widen",
    "select_relevant",
]
