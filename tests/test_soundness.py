"""A plan of the pruned problem is a plan of the original: ADL quantifiers, conditional effects,
quantified effects on other facts, derived predicates.  Each world below is one where dropping an
object a quantifier ranges over changes the verdict; the last test shows that without the soundness
rule some of them break."""

from __future__ import annotations

from pathlib import Path

import pytest
from support import (
    ALARM,
    GUARDED,
    LIFT,
    NOISE,
    ROOMS,
    SCENE,
    UNTYPED_LIFT,
    WORLDS,
    alarm_problem,
    guarded_problem,
    lift_problem,
    noise_problem,
    rooms_problem,
    scene_problem,
)

from relevance_plan.io import load_task
from relevance_plan.pddl.parser import read_domain, read_problem
from relevance_plan.planning.options import PlanOptions
from relevance_plan.planning.validation import validate_plan
from relevance_plan.relevance.analysis.soundness import KeptObjects
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.setup import score_problem


def first_kept(domain_text: str, problem_text: str) -> tuple[PlanningTask, frozenset, tuple]:
    domain = read_domain(domain_text)
    task = PlanningTask(domain, read_problem(problem_text, domain))
    options = PlanOptions()
    selection = score_problem(task, options.scoring).first_selection()
    return task, selection.kept, selection.restored


def test_every_object_a_universal_goal_ranges_over_stays_with_its_reason():
    task, kept, restored = first_kept(LIFT, lift_problem(1))
    passengers = {name for name, kind in task.problem.objects.items() if kind == "passenger"}
    assert passengers <= kept
    _, kept_untyped, restored_untyped = first_kept(UNTYPED_LIFT, lift_problem(1, untyped=True))
    assert {f"p{i}" for i in range(12)} <= kept_untyped
    assert not any(name.startswith("j") for name in kept_untyped)  # the guard admits passengers only
    reasons = {item.name: item.describe() for item in restored_untyped if item.rule == "soundness"}
    assert reasons and all("the goal quantifies over every object with (passenger ...)" in r for r in reasons.values())


def test_quantifiers_in_preconditions_derived_predicates_and_effect_conditions_keep_their_range():
    # (exists (?a - alarm) (and (armed ?a) (covers ?a ?u))) in an effect's condition: every armed alarm
    task, kept, _ = first_kept(ALARM, alarm_problem(2))
    assert {n for n, k in task.problem.objects.items() if k == "alarm"} <= kept
    # (forall (?i - item) (not (in ?i ?x))) to seal a kept room ?x: the items in kept rooms
    task, kept, _ = first_kept(ROOMS, rooms_problem(2))
    assert {atom[1] for atom in task.problem.init if atom[0] == "in" and atom[2] in kept} <= kept
    # (seen ?c) derived from (exists (?g - guard) (watch ?g ?c)): the guards watching kept cells
    task, kept, _ = first_kept(GUARDED, guarded_problem(2))
    watching = {atom[1] for atom in task.problem.init if atom[0] == "watch" and atom[2] in kept}
    assert watching and watching <= kept


def _holders(task: PlanningTask, kept: frozenset[str]) -> tuple[set[str], set[str]]:
    """(the receptacles holding a kept item in the initial state, those holding none)."""
    every = {name for name, kind in task.problem.objects.items() if kind == "receptacle"}
    holding = {atom[2] for atom in task.problem.init if atom[0] == "inside" and atom[1] in kept}
    return holding, every - holding


def test_a_universal_over_a_negated_atom_keeps_only_the_objects_its_facts_link_to_kept_ones():
    for seed in range(3):
        task, kept, restored = first_kept(SCENE, scene_problem(seed))
        holding, others = _holders(task, kept)
        assert holding and holding <= kept  # each could make (forall (?r) (not (inside ?i ?r))) false
        assert not others & kept, seed  # empty, or holding pruned items only: can never
        reasons = {item.name: item.describe() for item in restored if item.rule == "soundness"}
        assert holding <= reasons.keys() and all("with (inside ...)" in reasons[name] for name in holding)


def test_an_effect_over_every_object_or_a_timed_fact_widens_what_the_negated_atom_keeps():
    # an effect that puts an item in every receptacle: any receptacle may come to hold it
    scatter = SCENE.replace(
        "  (:action put",
        "  (:action scatter :parameters (?a - agent ?i - item)\n    :precondition (holding ?a ?i)"
        "\n    :effect (forall (?r - receptacle) (inside ?i ?r)))\n  (:action put",
    )
    task, kept, _ = first_kept(scatter, scene_problem(1))
    assert {name for name, kind in task.problem.objects.items() if kind == "receptacle"} <= kept
    # a timed fact that puts the goal's item in a receptacle later names that receptacle too
    task, kept_plain, _ = first_kept(SCENE, scene_problem(1))
    _, others = _holders(task, kept_plain)
    item = task.problem.goal.args[1]
    dropped = sorted(others)[0]
    timed_domain = SCENE.replace("(:requirements :adl)", "(:requirements :adl :timed-initial-literals)")
    _, kept_timed, _ = first_kept(timed_domain, scene_problem(1, timed=f"(at 5 (inside {item} {dropped}))"))
    assert dropped in kept_timed


def test_an_effect_over_every_object_that_sets_a_kept_fact_keeps_the_objects_its_condition_admits():
    for seed in range(3):
        task, kept, restored = first_kept(NOISE, noise_problem(seed))
        assert {"s0", "s1", "s2"} <= kept  # each can wake the house once the agent steps near it
        assert "z0" not in kept  # near no cell: it can never set (woken)
    task, kept, restored = first_kept(NOISE, noise_problem(0))
    reasons = [item.describe() for item in restored if item.rule == "soundness"]
    assert reasons and all("action 'step'" in reason and "(woken)" in reason for reason in reasons)


def _prune_plan_validate(tmp_path: Path, world: str, seed: int) -> bool:
    from support import run

    from relevance_plan.planning.planners.fast_downward.adapter import run_fast_downward

    domain_text, make = WORLDS[world]
    domain_path, problem_path = tmp_path / f"{world}.pddl", tmp_path / f"{world}-{seed}.pddl"
    domain_path.write_text(domain_text)
    problem_path.write_text(make(seed))
    pruned = tmp_path / f"{world}-{seed}-pruned.pddl"
    code, _, stderr = run("prune", domain_path, problem_path, "-o", pruned, "--scorer", "goal")
    assert code == 0, stderr
    outcome = run_fast_downward(domain_path, pruned, time_limit=60)
    if not outcome.solved:
        return True  # no plan, nothing to be wrong about (the loop would widen)
    domain, original = load_task(domain_path, problem_path)
    return validate_plan(domain, original, outcome.plan).valid


@pytest.mark.planner
@pytest.mark.parametrize("world", sorted(WORLDS))
def test_a_plan_of_the_pruned_problem_is_valid_on_the_original(tmp_path, world):
    for seed in range(3):
        assert _prune_plan_validate(tmp_path, world, seed), (world, seed)


@pytest.mark.planner
def test_without_the_soundness_rule_pruning_breaks_plans(tmp_path, monkeypatch):
    """The worlds above are hard enough: switch the rule off and plans become invalid on the original."""
    monkeypatch.setattr(PlanningTask, "kept_for_soundness", property(lambda self: KeptObjects({}, {})))
    broken = [
        (world, seed)
        for world in sorted(WORLDS)
        for seed in range(3)
        if not _prune_plan_validate(tmp_path, world, seed)
    ]
    assert broken, "every plan was valid even without the rule: the worlds do not test it"
