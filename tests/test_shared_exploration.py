"""The relaxed check with one placeholder for many interchangeable goal objects (packages, passengers)
decides as the object-by-object exploration does, and its relaxed plans hold on the original problem."""

from __future__ import annotations

import random

import pytest

from relevance_plan.data import DOMAINS_DIR
from relevance_plan.generators import WORLDS, Settings
from relevance_plan.pddl.parser import read_domain, read_problem
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.reachability import exploration, schemas
from relevance_plan.relevance.reachability.budget import Work
from relevance_plan.relevance.reachability.exploration import relaxed_reachability
from relevance_plan.relevance.selection import repair
from relevance_plan.relevance.setup import ScoringOptions, score_problem

CASES = ("logistics-manygoals", "logistics-manygoals-typed", "miconic-manygoals", "miconic-manygoals-typed")


def task_of(world: str, seed: int, size: int) -> tuple[PlanningTask, dict]:
    problem = WORLDS[world].problem(seed, 1, Settings(size=size))
    domain = read_domain(WORLDS[world].domain_path.read_text())
    return PlanningTask(domain, read_problem(problem.pddl_text, domain)), problem.sidecar


def plain_check(monkeypatch, task: PlanningTask, kept: set[str]) -> exploration.Reachability:
    """The same check with sharing off (a new task object: the compiled schemas are cached per task)."""
    with monkeypatch.context() as patch:
        patch.setattr(schemas, "SHARED_FROM", 10**9)
        fresh = PlanningTask(task.domain, task.problem)
        return relaxed_reachability(fresh, kept)


def holds_relaxed(task: PlanningTask, check: exploration.Reachability) -> bool:
    """The relaxed plan's steps, applied in any order their conditions allow (deletes ignored), all
    apply, from the initial facts, and reach the goal's atoms."""
    by_name = {schema.name: schema for schema in schemas.relaxed_task(task).schemas}
    facts = set(task.typing.problem.init)
    waiting = list(check.plan)
    while waiting:
        ready = []
        for step in waiting:
            schema = by_name[step[0]]
            binding = dict(zip(schema.parameters, step[1:]))
            if all((p, *(binding.get(a, a) for a in args)) in facts for p, args in schema.pre):
                ready.append((step, schema, binding))
        if not ready:
            return False
        for step, schema, binding in ready:
            facts.update((p, *(binding.get(a, a) for a in args)) for p, args, _ in schema.add)
            waiting.remove(step)
    goal = [(p, *args) for p, args in schemas.required_atoms(task.problem.goal)]
    return all(atom in facts for atom in goal)


@pytest.mark.parametrize("world", CASES)
def test_the_shared_class_is_found_and_decides_as_the_plain_check(monkeypatch, world):
    task, sidecar = task_of(world, 4, 240)
    shared = schemas.relaxed_task(task).shared
    assert shared is not None and len(shared.members) >= schemas.SHARED_FROM
    necessary = set(sidecar["necessary"])
    rng = random.Random(world)
    others = sorted(set(task.problem.objects) - necessary)
    trials = [necessary, set(task.problem.objects)]
    # without one needed object, and with some unneeded ones: both answers occur
    for _ in range(6):
        trials.append(necessary - {rng.choice(sorted(necessary))} | set(rng.sample(others, 10)))
    answers = set()
    for kept in trials:
        shared_check = relaxed_reachability(task, kept)
        plain = plain_check(monkeypatch, task, kept)
        assert shared_check.complete and plain.complete
        assert shared_check.reachable == plain.reachable, sorted(kept)
        assert set(shared_check.unreached) == set(plain.unreached)
        answers.add(shared_check.reachable)
        if shared_check.reachable:
            assert holds_relaxed(task, shared_check)
            assert shared_check.plan_objects <= kept
    assert answers == {True, False}


def test_no_shared_class_where_goal_objects_meet():
    # blocksworld: a stacking action holds two blocks; the check stays object by object
    domain = read_domain((DOMAINS_DIR / "blocksworld" / "domain.pddl").read_text())
    blocks = [f"b{i}" for i in range(12)]
    text = (
        "(define (problem tower) (:domain blocksworld) (:objects "
        + " ".join(blocks)
        + ") (:init (handempty) "
        + " ".join(f"(ontable {b}) (clear {b})" for b in blocks)
        + ") (:goal (and "
        + " ".join(f"(on {a} {b})" for a, b in zip(blocks, blocks[1:]))
        + ")))"
    )
    task = PlanningTask(domain, read_problem(text, domain))
    assert schemas.relaxed_task(task).shared is None
    assert relaxed_reachability(task, set(blocks)).reachable


def test_many_goal_repair_keeps_the_oracles_vehicles_at_500_objects():
    task, sidecar = task_of("logistics-manygoals", 1, 500)
    selection = score_problem(task, ScoringOptions(), method="relevance").first_selection(narrow=True)
    classes = task.typing.problem.objects
    kept_airplanes = {n for n in selection.kept if classes[n] == "airplane"}
    assert len(kept_airplanes) == 1
    necessary_trucks = {n for n in sidecar["necessary"] if classes[n] == "truck"}
    kept_trucks = {n for n in selection.kept if classes[n] == "truck"}
    assert len(kept_trucks) <= len(necessary_trucks)
    assert relaxed_reachability(task, selection.kept).reachable


def test_a_second_airplane_is_passed_over_while_trucks_are_missing():
    # one airplane kept, every airport and package kept, no truck: the repair's candidates are the
    # trucks the relaxed plan lacks, not the airplanes parked at kept airports (the first flies there)
    task, _ = task_of("logistics-manygoals", 2, 200)
    classes = task.typing.problem.objects
    airports = {n for n, c in classes.items() if "airport" in c.split("+")}
    places = {n for n, c in classes.items() if c in ("location", "city")} | airports
    packages = {n for n, c in classes.items() if c == "package"}
    kept = places | packages | {"plane1"}
    explored = exploration.Exploration(task, kept, Work(10**7))
    explored.run()
    assert explored.missing  # the trucks are missing
    unreached = {arg for atom in explored.missing for arg in atom[1:]}
    toward = repair.RepairOrder(task, {})
    chosen = toward.nearest(kept, unreached, 10, explored.facts)
    assert chosen and all(classes[n] == "truck" for n in chosen), chosen
    # and with the check off every airplane parked at an airport counts as near as a truck
    parked = [n for n in classes if classes[n] == "airplane" and n != "plane1"]
    assert any(toward.stood_in_for(n, ["plane1"], explored.facts) for n in parked)
