"""The exploration's shortcuts change no answer: schemas with nothing left to add are passed over,
and the repair's distances over a prebuilt object graph are plain breadth-first hops."""

from __future__ import annotations

import random
from collections import deque

import pytest

from relevance_plan.generators import WORLDS, Settings
from relevance_plan.pddl.parser import read_domain, read_problem
from relevance_plan.relevance.analysis.distances import object_distances
from relevance_plan.relevance.analysis.facts import fan_in
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.reachability import exploration, schemas
from relevance_plan.relevance.reachability.budget import Work
from relevance_plan.relevance.reachability.exploration import relaxed_reachability
from relevance_plan.relevance.selection import repair
from relevance_plan.relevance.setup import ScoringOptions, score_problem


def task_of(world: str, size: int, seed: int = 2) -> tuple[PlanningTask, dict]:
    problem = WORLDS[world].problem(seed, 1, Settings(size=size))
    sidecar = problem.sidecar
    domain = read_domain(WORLDS[world].domain_path.read_text())
    return PlanningTask(domain, read_problem(problem.pddl_text, domain)), sidecar


def trials(task: PlanningTask, sidecar: dict, seed: str) -> list[set[str]]:
    necessary = set(sidecar.get("necessary") or sidecar["goal_objects"])
    everything = set(task.problem.objects)
    rng = random.Random(seed)
    others = sorted(everything - necessary)
    found = [necessary, everything]
    for _ in range(4):
        found.append(necessary - {rng.choice(sorted(necessary))} | set(rng.sample(others, min(12, len(others)))))
        found.append(necessary | set(rng.sample(others, min(30, len(others)))))
    return found


@pytest.mark.parametrize(
    "world", ["miconic", "miconic-typed", "miconic-manygoals", "grid", "logistics", "gripper", "blocksworld", "ferry"]
)
def test_passing_over_saturated_schemas_changes_no_answer(monkeypatch, world):
    task, sidecar = task_of(world, 150)
    passed_over = []
    saturated = exploration.Exploration._saturated

    def counting(self, schema):
        answer = saturated(self, schema)
        passed_over.append(answer)
        return answer

    monkeypatch.setattr(exploration.Exploration, "_saturated", counting)
    for kept in trials(task, sidecar, world):
        with_cut = relaxed_reachability(task, kept)
        with monkeypatch.context() as patch:
            patch.setattr(exploration.Exploration, "_saturated", lambda self, schema: False)
            without = relaxed_reachability(PlanningTask(task.domain, task.problem), kept)
        assert with_cut.complete and without.complete
        assert with_cut.reachable == without.reachable, sorted(kept)
        assert set(with_cut.unreached) == set(without.unreached)
        # the first step found for each fact is the same, so the relaxed plan is too
        assert with_cut.plan == without.plan
    if world.startswith("miconic"):
        assert any(passed_over)  # the lift's moves: every floor is reached after the first one


def test_a_schema_is_saturated_only_when_every_atom_it_adds_is_reached():
    task, sidecar = task_of("miconic", 60)
    explored = exploration.Exploration(task, set(sidecar["necessary"]), Work(10**6))
    up = next(s for s in explored.schemas if s.name == "up")
    floors = explored.objects_of(dict(zip(up.parameters, up.types))["?f2"])
    reached = {f for f in floors if ("lift-at", f) in explored.facts}
    # before the run only the lift's floor is reached: not saturated
    assert len(reached) < len(floors) and not explored._saturated(up)
    explored.run()
    reached = {f for f in floors if ("lift-at", f) in explored.facts}
    assert explored._saturated(up) == (reached == set(floors))


def reference_hops(task: PlanningTask, sources, hub, max_fan) -> dict[str, int]:
    """Plain breadth-first search over the initial facts with the same two rules."""
    index = task.init_index
    fans = fan_in(index)
    distance = {s: 0 for s in sources}
    queue = deque(distance)
    while queue:
        name = queue.popleft()
        if hub is not None and distance[name] > 0 and len(index.by_object.get(name, ())) > hub:
            continue
        for atom in index.by_object.get(name, ()):
            if len(atom) < 3:
                continue
            if max_fan is not None and fans.get((atom[0], atom.index(name) - 1), 0.0) > max_fan:
                continue
            for other in atom[1:]:
                if other not in distance:
                    distance[other] = distance[name] + 1
                    queue.append(other)
    return distance


@pytest.mark.parametrize("world", ["grid", "logistics", "scenegraph", "ferry"])
def test_object_distances_are_breadth_first_hops(world):
    task, _ = task_of(world, 200)
    rng = random.Random(world)
    names = sorted(task.problem.objects)
    for _ in range(10):
        sources = rng.sample(names, rng.randint(1, 5))
        for hub, max_fan in [(None, None), (task.hub_degree, None), (3, repair.REPAIR_MAX_FAN)]:
            assert object_distances(task.init_index, sources, hub, max_fan) == reference_hops(
                task, sources, hub, max_fan
            )


def test_picking_up_while_holding_is_passed_over_once_the_arm_has_been_empty():
    task, _ = task_of("grid", 150)
    compiled = schemas.relaxed_task(task)
    dominated = {
        schema.name: compiled.dominated[id(schema)] for schema in compiled.schemas if id(schema) in compiled.dominated
    }
    assert dominated == {"pickup-and-lose": frozenset({("arm-empty",)})}


@pytest.mark.parametrize("world", ["grid", "grid-typed", "logistics", "scenegraph", "blocksworld"])
def test_passing_over_dominated_schemas_changes_no_answer(monkeypatch, world):
    from test_shared_exploration import holds_relaxed

    task, sidecar = task_of(world, 150)
    for kept in trials(task, sidecar, world):
        with_cut = relaxed_reachability(task, kept)
        with monkeypatch.context() as patch:
            patch.setattr(schemas, "_dominated", lambda *args: {})
            without = relaxed_reachability(PlanningTask(task.domain, task.problem), kept)
        assert with_cut.complete and without.complete
        assert with_cut.reachable == without.reachable, sorted(kept)
        assert set(with_cut.unreached) == set(without.unreached)
        if with_cut.reachable:
            assert holds_relaxed(task, with_cut)  # the steps that stand in are real steps


def test_the_repair_grows_a_corridor_from_the_robot_not_discs_around_the_keys(monkeypatch):
    """Before any step is found the robot's place is where reaching starts; the repair adds one
    shortest way of cells from there toward the goal's key, which keeps fewer objects than ranking
    every cell between them."""
    task, _ = task_of("grid", 2000, seed=1)
    toward = repair.RepairOrder(task, {})
    (robot,) = [atom[1] for atom in task.init_index.by_predicate["at-robot"]]
    assert robot in toward.agents

    def first_kept() -> frozenset[str]:
        fresh = PlanningTask(task.domain, task.problem)
        return score_problem(fresh, ScoringOptions(), method="relevance").first_selection(narrow=True).kept

    with_corridor = first_kept()
    monkeypatch.setattr(repair.RepairOrder, "_path", lambda self, targets, sources, current: [])
    without = first_kept()
    assert len(with_corridor) < len(without)


def test_the_repairs_selection_is_the_same_in_every_process():
    """A problem's facts are a set, iterated in the hash seed's order; the exploration (which takes
    the static facts in the file's order, unsorted), the corridor and the ranking must not follow it.
    Many-goal logistics failed it when the facts came in the index's order before that followed the
    file."""
    from support import outputs_under_hash_seeds

    script = (
        "from relevance_plan.data import DOMAINS_DIR\n"
        "from relevance_plan.generators import WORLDS, Settings\n"
        "from relevance_plan.pddl.parser import read_domain, read_problem\n"
        "from relevance_plan.relevance.analysis.task import PlanningTask\n"
        "from relevance_plan.relevance.setup import ScoringOptions, score_problem\n"
        "for world, domain in (('grid', 'grid'), ('scenegraph', 'scenegraph'), ('logistics-manygoals', 'logistics')):\n"
        "    problem = WORLDS[world].problem(3, 1, Settings(size=500))\n"
        "    d = read_domain((DOMAINS_DIR / domain / 'domain.pddl').read_text())\n"
        "    task = PlanningTask(d, read_problem(problem.pddl_text, d))\n"
        "    kept = score_problem(task, ScoringOptions(), method='relevance').first_selection(narrow=True).kept\n"
        "    print(world, sorted(kept))\n"
    )
    outputs = outputs_under_hash_seeds(script, ("1", "2", "3"))
    assert outputs[0] and outputs[0] == outputs[1] == outputs[2]


TWO_WAY = """(define (domain two-way)
  (:requirements :typing :disjunctive-preconditions :negative-preconditions)
  (:types robot spot)
  (:predicates (at ?r - robot ?s - spot) (link ?a ?b - spot) (blocked ?s - spot))
  (:action move :parameters (?r - robot ?a ?b - spot)
    :precondition (and (at ?r ?a) (or (link ?a ?b) (link ?b ?a)))
    :effect (and (not (at ?r ?a)) (at ?r ?b))))
"""


def _two_way(domain_text: str) -> PlanningTask:
    # links one way only, s0 -> s1 -> ... -> s5; the robot starts at the far end and must go back
    links = " ".join(f"(link s{i} s{i + 1})" for i in range(5))
    spots = " ".join(f"s{i}" for i in range(6))
    problem = (
        f"(define (problem back) (:domain two-way) (:objects bot - robot {spots} - spot)"
        f" (:init (at bot s5) {links}) (:goal (at bot s0)))"
    )
    domain = read_domain(domain_text)
    return PlanningTask(domain, read_problem(problem, domain))


def test_a_disjunctive_condition_is_checked_one_way_through_it_at_a_time():
    task = _two_way(TWO_WAY)
    assert not relaxed_reachability(task, {"bot", "s0", "s5"}).reachable  # no link between them
    every = set(task.problem.objects)
    check = relaxed_reachability(task, every)
    assert check.reachable and check.plan_objects >= every - {"bot"}  # back along each link, by its second way
    # a way that requires no atom (a negated one) leaves the disjunction unchecked: still an over-approximation
    loose = TWO_WAY.replace("(or (link ?a ?b) (link ?b ?a))", "(or (link ?a ?b) (not (blocked ?b)))")
    assert relaxed_reachability(_two_way(loose), {"bot", "s0", "s5"}).reachable
