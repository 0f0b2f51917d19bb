"""Domain-independent relevance from the goal and the action schemas.

Used when no knowledge model applies.  Goal objects score 1.  Objects whose
type can fill a role that reaching the goal needs (a cup to serve, a gripper
to carry) score 0.6 per role step away from the goal: 0.6 for a role of the
goal's own achiever, 0.36 for what that role needs, and so on.  Objects that
share a relevant initial fact with a goal object score 0.3.  Objects that can
only get in the way score 0 and are left to closure.

Types are the declared ones, or in an untyped domain the classes inferred from
static unary predicates (``relevance.analysis.types``).

When a role has many candidates (more than ``POPULOUS``: fifty trucks, a
hundred rooms), one or a few of them will do, and the likely ones are those
near the goal's objects in the initial state: a candidate's role score halves
with every hop beyond the first (``DISTANCE_DECAY``), and candidates the
initial state does not connect to the goal at all count as ``FAR`` hops.  The
first attempt then keeps, of the nearby candidates, those a relaxed plan
needs (``ScoreResult.alternatives``; ``prune.prune_with_scores``); the
reachability check and widening bring the others back in this order when
needed.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Callable, Collection, Iterable, Mapping, Set

from relevance_plan.pddl.formatter import format_atom
from relevance_plan.pddl.formulas import GroundAtom
from relevance_plan.pddl.model import UNSPELLED, Domain, Spelling
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.scoring.scorers.base import ScoreRequest, ScoreResult

ROLE_DECAY = 0.6
NEIGHBOUR_SCORE = 0.3
POPULOUS = 8
DISTANCE_DECAY = 0.5
FAR = 8


def score_by_goal(task: PlanningTask, request: ScoreRequest) -> ScoreResult:
    domain, problem = task.typing.domain, task.typing.problem
    analysis = task.goal_analysis
    goal_objects = task.goal_objects
    neighbours = goal_neighbours(
        task.init_index.by_object, goal_objects, analysis.relevant_predicates, problem.spelling
    )
    candidates = role_candidates(domain, analysis.role_depth, problem.objects.values())
    scores: dict[str, float] = {}
    explanations: dict[str, str] = {}
    alternatives: set[str] = set()
    for name, type_name in problem.objects.items():
        score, why, populous = goal_score(
            domain,
            analysis.role_depth,
            candidates,
            lambda: task.goal_distance,
            name,
            type_name,
            goal_objects,
            neighbours,
        )
        scores[name], explanations[name] = score, why
        if populous:
            alternatives.add(name)
    return ScoreResult(
        "goal",
        scores,
        element_class={name: problem.objects[name] for name in scores},
        explanations=explanations,
        alternatives=frozenset(alternatives),
    )


def goal_neighbours(
    by_object: Mapping[str, Collection[GroundAtom]],
    goal_objects: Set[str],
    relevant_predicates: Set[str],
    spelling: Spelling = UNSPELLED,
) -> dict[str, str]:
    """Object -> the first relevant fact it shares with a goal object, written in ``spelling``."""
    neighbours: dict[str, str] = {}
    # sorted: the same fact explains a neighbour whatever order the sets were built in
    for name in sorted(goal_objects):
        for atom in sorted(by_object.get(name, ())):
            if atom[0] in relevant_predicates:
                for other in atom[1:]:
                    if other != name:
                        if other not in neighbours:
                            neighbours[other] = format_atom(atom, spelling)
    return neighbours


def role_candidates(domain: Domain, role_depth: Mapping[str, int], types: Iterable[str]) -> dict[str, int]:
    """Role type -> how many objects (of these types) can fill it."""
    candidates: dict[str, int] = {}
    for type_name, count in Counter(types).items():
        for ancestor in domain.ancestors(type_name):
            if ancestor in role_depth:
                candidates[ancestor] = candidates.get(ancestor, 0) + count
    return candidates


def goal_score(
    domain: Domain,
    role_depth: Mapping[str, int],
    candidates: Mapping[str, int],
    distances: Callable[[], Mapping[str, int]],
    name: str,
    type_name: str,
    goal_objects: Set[str],
    neighbours: Mapping[str, str],
) -> tuple[float, str, bool]:
    """One object's score, its explanation, and whether it is one of a populous role's candidates
    (``distances``: hops from the goal's objects, asked for only for those)."""
    if name in goal_objects:
        return 1.0, "named in the goal", False
    best, why, populous = 0.0, "no role in reaching the goal", False
    for ancestor in domain.ancestors(type_name):
        depth = role_depth.get(ancestor)
        if depth is None:
            continue
        value = ROLE_DECAY ** max(depth, 1)
        role = f"can serve as {domain.spelling.type(ancestor)} (role {depth} step(s) from the goal)"
        many = candidates.get(ancestor, 0) > POPULOUS
        if many:
            distance = distances()
            hops = distance.get(name, FAR)
            value *= DISTANCE_DECAY ** max(hops - 1, 0)
            role += f", one of {candidates[ancestor]}, " + (
                f"{hops} hop(s) from the goal's objects" if name in distance else "not linked to the goal's objects"
            )
        if value > best:
            best, why, populous = value, role, many
    if name in neighbours and NEIGHBOUR_SCORE > best:
        best, why, populous = NEIGHBOUR_SCORE, f"shares {neighbours[name]} with a goal object", False
    return best, why, populous
