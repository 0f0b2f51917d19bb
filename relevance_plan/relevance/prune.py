"""Score -> threshold -> closure -> pruned problem text, as one result value."""

from __future__ import annotations

from collections import Counter, defaultdict
from collections.abc import Sequence, Set
from dataclasses import dataclass, field
from typing import Any

from relevance_plan.pddl.model import Domain
from relevance_plan.pddl.writer import write_pruned_problem
from relevance_plan.relevance.analysis import (
    ConstraintRule,
    FactIndex,
    infer_constraint_rules,
    single_valued_predicates,
)
from relevance_plan.relevance.closure import Restored, close_over_constraints
from relevance_plan.relevance.knowledge import KnowledgeModel, check_threshold
from relevance_plan.relevance.repair import repair_selection
from relevance_plan.relevance.scorers import ScoreResult
from relevance_plan.relevance.soundness import KeptForSoundness
from relevance_plan.relevance.task import PlanningTask
from relevance_plan.relevance.types import static_predicates

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
class Selection:
    task: PlanningTask
    scores: ScoreResult
    thresholds: Thresholds
    selected: frozenset[str]  # passed the thresholds (plus goal objects)
    kept: frozenset[str]  # after closure
    restored: tuple[Restored, ...]  # in the order closure found them
    text: str = field(repr=False)  # the pruned problem in the user's own layout
    set_aside: frozenset[str] = frozenset()  # relevant alternatives left for a later attempt (see free_alternatives)
    unpruned: str = ""  # why every object is kept, when one is ("" when the selection prunes)

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
            "unpruned_reason": self.unpruned or None,
            "objects_total": len(problem.objects),
            "objects_kept": len(self.kept),
            "kept": [problem.display(n) for n in problem.objects if n in self.kept],
            "removed": [problem.display(n) for n in self.removed],
            "restored": [
                {"object": problem.display(r.name), "reason": r.reason, "rule": r.rule, "because_of": r.because_of}
                for r in self.restored
            ],
            "set_aside": [problem.display(n) for n in problem.objects if n in self.set_aside],
        }


def constraint_rules(domain: Domain, index: FactIndex, model: KnowledgeModel | None) -> tuple[ConstraintRule, ...]:
    rules = list(infer_constraint_rules(domain, index))
    if model is not None:
        for dependency in model.dependencies:
            rules.append(
                ConstraintRule(
                    dependency.predicate, dependency.when_kept, dependency.restore, "model", dependency.reason
                )
            )
    return tuple(rules)


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
    selected = set(task.pinned_objects)
    for name, score in scores.element_scores.items():
        if thresholds.admits(scores.class_score(name), score) and (not goal_filter or can_serve_goal(task, name)):
            selected.add(name)
    return frozenset(selected)


def free_alternatives(
    task: PlanningTask, scores: ScoreResult, selected: frozenset[str], restored: Sequence[Restored]
) -> frozenset[str]:
    """``selected`` without the objects that something stands on, when another selected
    object of the same model class stands free.

    Any cup serves coffee: a cup under a plate costs the planner the plate as
    well, and every extra item multiplies grounding.  Only classes of a
    knowledge model are treated as interchangeable (a PDDL type is not: all
    blocks of a tower are needed); goal objects always stay.
    """
    from relevance_plan.relevance.scorers.model import UNKNOWN_CLASS

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


def prune_with_scores(
    task: PlanningTask,
    scores: ScoreResult,
    thresholds: Thresholds = Thresholds(),
    model: KnowledgeModel | None = None,
    extra: Set[str] = frozenset(),
    goal_filter: bool = False,
    prefer_free: bool = False,
    *,
    repair: bool | None = None,
    full_above: float | None = None,
    economical: bool = False,
    held_aside: Set[str] = frozenset(),
) -> Selection:
    """Threshold the scores, add ``extra`` objects, close over constraints, check, write the text.

    With ``prefer_free``, blocked alternatives are set aside (``free_alternatives``)
    and closure runs again on what is left.  With ``repair`` (default: for the
    goal scorer at the default thresholds or lower), a kept set on which the goal is unreachable even ignoring
    deletes gets what a relaxed plan needs (``repair.repair_selection``).
    A selection that keeps more than ``full_above`` of the objects (default:
    ``FULL_ABOVE`` for the scorers repaired by default, never for the others,
    whose first selection is kept as chosen) becomes the full problem: pruning
    it would save little and risk a second attempt.  With ``economical`` (and
    ``repair``), the selected alternatives of a populous role
    (``ScoreResult.alternatives``: fifty airplanes near the goal's objects)
    are set aside and the repair brings back, best ranked first, only those
    a relaxed plan needs: one airplane carries every package.  ``held_aside``
    (a widening's: what earlier selections set aside) stays out unless in ``extra``.
    """
    extra = frozenset(extra) & task.problem.objects.keys()
    held = frozenset(held_aside) - extra
    selected = (select_relevant(task, scores, thresholds, goal_filter) - held) | extra
    task.check_time("choosing the objects")
    rules = constraint_rules(task.domain, task.init_index, model)
    singletons = single_valued_predicates(task.domain, task.init_index)

    sound = task.kept_for_soundness

    def over_constraints(names: Set[str], already: Set[str]) -> tuple[frozenset[str], tuple[Restored, ...]]:
        candidates = task.problem.objects.keys()
        return close_over_constraints(names, rules, task.init_index, candidates, singletons, already)

    def close(names: Set[str], already: Set[str] = frozenset()) -> tuple[frozenset[str], tuple[Restored, ...]]:
        # what a quantifier ranges over stays, so that a plan of the pruned problem is one of the original
        missing = sorted(sound.always.keys() - set(names))
        closed, found = over_constraints(set(names) | set(missing), already)
        reasons = [soundness_reason(name, sound.always[name]) for name in missing]
        added = closed - already  # ``already`` was closed by this function: its links were followed
        while sound.linked:
            linked = sound.admitted(closed, added)
            if not linked:
                break
            reasons += (soundness_reason(name, requirement) for name, requirement in sorted(linked.items()))
            grown, more = over_constraints(closed | linked.keys(), closed)
            found += more
            added, closed = grown - closed, grown
        return closed, tuple(reasons) + found

    kept, restored = close(selected)
    task.check_time("closing the selection over constraints")
    set_aside: frozenset[str] = held
    if prefer_free:
        narrowed = free_alternatives(task, scores, selected, restored)
        if narrowed != selected:
            set_aside |= selected - narrowed
            selected = narrowed
            kept, restored = close(selected)
    if repair is None:
        # A stricter selection than the defaults, asked for explicitly, is tried as given.
        repair = scores.scorer in REPAIR_SCORERS and max(thresholds.tau_class, thresholds.tau_element) <= DEFAULT_TAU
    if full_above is None:
        full_above = FULL_ABOVE if scores.scorer in REPAIR_SCORERS else 1.0
    total = len(task.problem.objects)
    if repair and economical:
        spare = _spare_alternatives(task, scores, selected - frozenset(extra))
        if spare:
            set_aside |= spare
            selected = selected - spare
            kept, restored = close(selected)
    if repair and len(kept) <= full_above * total:
        kept, repaired, _ = repair_selection(task, kept, scores.element_scores, close)
        restored = tuple(restored) + repaired
        set_aside -= kept
    if len(kept) > full_above * total:
        why = f"the selection kept {len(kept)} of {total} objects (more than {full_above:.0%}): the full problem"
        return full_problem(task, scores, thresholds, selected, restored, why)
    task.check_time("checking the selection")
    return Selection(
        task=task,
        scores=scores,
        thresholds=thresholds,
        selected=selected,
        kept=kept,
        restored=restored,
        text=write_pruned_problem(task.problem, kept),
        set_aside=set_aside,
        unpruned=_why_nothing_pruned(task, kept, restored),
    )


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


def soundness_reason(name: str, requirement: KeptForSoundness) -> Restored:
    admitted = f" with ({requirement.guard} ...)" if requirement.guard else ""
    note = f"{requirement.where} quantifies over every {requirement.type_name}{admitted}: {requirement.formula}"
    return Restored(name, "", "soundness", (), note)


def full_problem(
    task: PlanningTask,
    scores: ScoreResult,
    thresholds: Thresholds,
    selected: Set[str] = frozenset(),
    restored: Sequence[Restored] = (),
    why: str = "",
) -> Selection:
    """The result that keeps every object (``why`` says why): the attempt loop plans on the user's own file."""
    return Selection(
        task=task,
        scores=scores,
        thresholds=thresholds,
        selected=frozenset(selected),
        kept=frozenset(task.problem.objects),
        restored=tuple(restored),
        text=task.problem.text,
        unpruned=why,
    )


def widen(
    result: Selection,
    factor: float,
    extra: Set[str] = frozenset(),
    model: KnowledgeModel | None = None,
    goal_filter: bool = False,
    *,
    growth: float = GROWTH,
    full_above: float = FULL_ABOVE,
) -> tuple[Selection, frozenset[str]]:
    """One widening step after a failed attempt; returns the new result and the extra set.

    The thresholds shrink by ``factor`` and the best-ranked removed objects
    (``ranked_names``) are put back until the kept
    set has at least ``growth`` times as many objects, so all failed attempts
    together cost about as much as the last one.  When that would keep more
    than ``full_above`` of the objects, the result is the full problem.
    """
    task = result.task
    total = len(task.problem.objects)
    target = max(len(result.kept) + 4, int(growth * len(result.kept) + 0.999))
    if target > full_above * total:
        everything = frozenset(task.problem.objects)
        why = f"widening would keep more than {full_above:.0%} of the objects: the full problem"
        return full_problem(task, result.scores, result.thresholds.scaled(factor), result.selected, (), why), everything
    held = result.set_aside  # alternatives set aside stay aside, and come back late
    ranked = widening_order(result, held)
    extra = frozenset(extra) | frozenset(ranked[: target - len(result.kept)])
    thresholds = result.thresholds.scaled(factor)
    widened = prune_with_scores(
        task, result.scores, thresholds, model, extra, goal_filter, full_above=full_above, held_aside=held
    )
    while len(widened.kept) < target and len(widened.kept) < total:
        # closure or the thresholds cannot account for every addition: add more by rank
        missing = widening_order(widened, held)
        extra = extra | frozenset(missing[: target - len(widened.kept)])
        widened = prune_with_scores(
            task, result.scores, thresholds, model, extra, goal_filter, full_above=full_above, held_aside=held
        )
    return widened, extra


def ranked_names(
    task: PlanningTask, scores: ScoreResult, kept: Set[str] = frozenset(), aside: Set[str] = frozenset()
) -> list[str]:
    """Objects outside ``kept``, in the order widening adds them back: one of each set of
    interchangeable objects (``PlanningTask.object_profiles``) before a second of any, the
    alternatives set ``aside`` after the others, then by score and by hops from the goal's objects.

    A copy rarely does what its twin, kept or tried, could not: among fifty copies of a truck and
    one market that sells, the market comes second, not fifty-first.  Set-aside alternatives come
    late because the selection already holds a free member of their role, so a failed attempt
    more likely lacks an object of another role."""
    values = scores.element_scores
    distance = task.goal_distance
    far = len(task.problem.objects) + 1

    def rank(name: str) -> tuple[bool, float, int, str]:
        return name in aside, -values.get(name, 0.0), distance.get(name, far), name

    candidates = sorted((name for name in task.problem.objects if name not in kept), key=rank)
    profiles = task.object_profiles
    seen = Counter(profiles[name] for name in kept if name in profiles)
    earlier: dict[str, int] = {}
    for name in candidates:
        earlier[name] = seen[profiles[name]]
        seen[profiles[name]] += 1
    return sorted(candidates, key=lambda name: (earlier[name], *rank(name)))


def widening_order(result: Selection, aside: Set[str] = frozenset()) -> Sequence[str]:
    """Pruned objects in the order widening adds them back (``ranked_names``)."""
    return ranked_names(result.task, result.scores, result.kept, aside)


__all__ = [
    "DEFAULT_TAU",
    "Selection",
    "Restored",
    "Thresholds",
    "constraint_rules",
    "full_problem",
    "ranked_names",
    "prune_with_scores",
    "widening_order",
    "widen",
    "select_relevant",
]
