"""A plan of the pruned problem is a plan of the original: ADL quantifiers, conditional effects,
quantified effects on other facts, derived predicates.  Each world below is one where dropping an
object a quantifier ranges over changes the verdict; the last test shows that without the soundness
rule some of them break."""

from __future__ import annotations

import random
from pathlib import Path

import pytest

from relevance_plan.io import load_task
from relevance_plan.pddl.parser import read_domain, read_problem
from relevance_plan.planning.loop import PlanOptions
from relevance_plan.planning.validate import validate_plan
from relevance_plan.relevance.scorers import PlanningTask
from relevance_plan.relevance.setup import score_problem
from relevance_plan.relevance.soundness import KeptObjects

LIFT = """(define (domain lift-adl)
  (:requirements :adl)
  (:types passenger floor)
  (:predicates (origin ?p - passenger ?f - floor) (destin ?p - passenger ?f - floor)
               (boarded ?p - passenger) (served ?p - passenger) (lift-at ?f - floor))
  (:action move :parameters (?f1 ?f2 - floor)
    :precondition (lift-at ?f1)
    :effect (and (not (lift-at ?f1)) (lift-at ?f2)))
  (:action stop :parameters (?f - floor)
    :precondition (lift-at ?f)
    :effect (and (forall (?p - passenger) (when (and (boarded ?p) (destin ?p ?f))
                                                (and (not (boarded ?p)) (served ?p))))
                 (forall (?p - passenger) (when (and (origin ?p ?f) (not (served ?p))) (boarded ?p))))))
"""

UNTYPED_LIFT = LIFT.replace("(:types passenger floor)", "").replace(" - passenger", "").replace(" - floor", "")
UNTYPED_LIFT = UNTYPED_LIFT.replace("(lift-at ?f))", "(lift-at ?f) (passenger ?p) (floor ?f) (junk ?j))", 1)
UNTYPED_LIFT = UNTYPED_LIFT.replace(
    "(forall (?p) (when (and (boarded ?p)", "(forall (?p) (when (and (passenger ?p) (boarded ?p)"
)

ROOMS = """(define (domain rooms)
  (:requirements :adl)
  (:types robot room item)
  (:predicates (at ?r - robot ?x - room) (in ?i - item ?x - room) (door ?a - room ?b - room)
               (sealed ?x - room))
  (:action go :parameters (?r - robot ?a - room ?b - room)
    :precondition (and (at ?r ?a) (door ?a ?b))
    :effect (and (not (at ?r ?a)) (at ?r ?b)))
  (:action seal :parameters (?r - robot ?x - room)
    :precondition (and (at ?r ?x) (forall (?i - item) (not (in ?i ?x))))
    :effect (sealed ?x))
  (:action carry :parameters (?r - robot ?i - item ?a - room ?b - room)
    :precondition (and (at ?r ?a) (in ?i ?a) (door ?a ?b))
    :effect (and (not (in ?i ?a)) (in ?i ?b) (not (at ?r ?a)) (at ?r ?b))))
"""

GUARDED = """(define (domain guarded)
  (:requirements :adl :derived-predicates)
  (:types agent cell guard)
  (:predicates (at ?a - agent ?c - cell) (adj ?c ?d - cell) (watch ?g - guard ?c - cell) (seen ?c - cell))
  (:derived (seen ?c - cell) (exists (?g - guard) (watch ?g ?c)))
  (:action step :parameters (?a - agent ?c ?d - cell)
    :precondition (and (at ?a ?c) (adj ?c ?d) (not (seen ?d)))
    :effect (and (not (at ?a ?c)) (at ?a ?d))))
"""

ALARM = """(define (domain alarm)
  (:requirements :adl)
  (:types thief spot alarm)
  (:predicates (at ?t - thief ?s - spot) (link ?s ?u - spot) (armed ?a - alarm) (covers ?a - alarm ?s - spot)
               (caught ?t - thief) (took ?t - thief))
  (:action go :parameters (?t - thief ?s ?u - spot)
    :precondition (and (at ?t ?s) (link ?s ?u))
    :effect (and (not (at ?t ?s)) (at ?t ?u)
                 (when (exists (?a - alarm) (and (armed ?a) (covers ?a ?u))) (caught ?t))))
  (:action grab :parameters (?t - thief ?s - spot)
    :precondition (and (at ?t ?s) (not (caught ?t)))
    :effect (took ?t)))
"""

SCENE = """(define (domain scene)
  (:requirements :adl)
  (:types agent place receptacle item)
  (:predicates (at ?a - agent ?p - place) (link ?p ?q - place) (item-at ?i - item ?p - place)
               (rec-at ?r - receptacle ?p - place) (inside ?i - item ?r - receptacle)
               (opened ?r - receptacle) (holding ?a - agent ?i - item) (free ?a - agent))
  (:action go :parameters (?a - agent ?p ?q - place)
    :precondition (and (at ?a ?p) (link ?p ?q))
    :effect (and (not (at ?a ?p)) (at ?a ?q)))
  (:action open :parameters (?a - agent ?r - receptacle ?p - place)
    :precondition (and (at ?a ?p) (rec-at ?r ?p))
    :effect (opened ?r))
  (:action pick-loose :parameters (?a - agent ?i - item ?p - place)
    :precondition (and (at ?a ?p) (item-at ?i ?p) (free ?a) (forall (?r - receptacle) (not (inside ?i ?r))))
    :effect (and (holding ?a ?i) (not (free ?a)) (not (item-at ?i ?p))))
  (:action pick-from :parameters (?a - agent ?i - item ?r - receptacle ?p - place)
    :precondition (and (at ?a ?p) (rec-at ?r ?p) (inside ?i ?r) (opened ?r) (free ?a))
    :effect (and (holding ?a ?i) (not (free ?a)) (not (inside ?i ?r)) (not (item-at ?i ?p))))
  (:action put :parameters (?a - agent ?i - item ?r - receptacle ?p - place)
    :precondition (and (at ?a ?p) (rec-at ?r ?p) (holding ?a ?i))
    :effect (and (inside ?i ?r) (item-at ?i ?p) (free ?a) (not (holding ?a ?i)))))
"""

NOISE = """(define (domain noise)
  (:requirements :adl)
  (:types agent cell sleeper)
  (:predicates (at ?a - agent ?c - cell) (adj ?c ?d - cell) (near ?s - sleeper ?c - cell) (woken))
  (:action step :parameters (?a - agent ?c ?d - cell)
    :precondition (and (at ?a ?c) (adj ?c ?d))
    :effect (and (not (at ?a ?c)) (at ?a ?d) (forall (?s - sleeper) (when (near ?s ?d) (woken))))))
"""


def lift_problem(seed: int, untyped: bool = False) -> str:
    rng = random.Random(seed)
    passengers, floors = 12, 24
    init = ["(lift-at f0)"]
    for i in range(passengers):
        a, b = rng.sample(range(floors), 2)
        init += [f"(origin p{i} f{a})", f"(destin p{i} f{b})"]
        if rng.random() < 0.5:
            init.append(f"(served p{i})")
    if untyped:
        init += [f"(passenger p{i})" for i in range(passengers)] + [f"(floor f{i})" for i in range(floors)]
        init += [f"(junk j{i})" for i in range(30)]
        objects = " ".join([f"p{i}" for i in range(passengers)] + [f"f{i}" for i in range(floors)])
        objects += " " + " ".join(f"j{i}" for i in range(30))
        goal = "(forall (?p) (imply (passenger ?p) (served ?p)))"
    else:
        objects = " ".join(f"p{i}" for i in range(passengers)) + " - passenger "
        objects += " ".join(f"f{i}" for i in range(floors)) + " - floor"
        goal = "(forall (?p - passenger) (served ?p))"
    header = f"(define (problem lift-{seed}) (:domain lift-adl)"
    return f"{header} (:objects {objects}) (:init {' '.join(init)}) (:goal {goal}))"


def rooms_problem(seed: int) -> str:
    rng = random.Random(seed)
    rooms = [f"r{i}" for i in range(8)]
    doors = [f"(door r{i} r{i + 1}) (door r{i + 1} r{i})" for i in range(7)]
    items = [f"(in i{k} r{rng.randrange(8)})" for k in range(6)]
    objects = f"bot - robot {' '.join(rooms)} - room {' '.join(f'i{k}' for k in range(6))} - item"
    return (
        f"(define (problem rooms-{seed}) (:domain rooms) (:objects {objects})"
        f" (:init (at bot r0) {' '.join(doors)} {' '.join(items)}) (:goal (sealed r{rng.randrange(2, 8)})))"
    )


def scene_problem(seed: int, timed: str = "") -> str:
    """Items in receptacles and loose; the goal holds an item that sits in a receptacle, which a
    pruned problem without that receptacle would let the agent pick up loose."""
    rng = random.Random(seed)
    places = [f"p{i}" for i in range(10)]
    links = [f"(link p{i} p{i + 1}) (link p{i + 1} p{i})" for i in range(9)]
    where = {f"r{k}": rng.randrange(10) for k in range(12)}
    init = ["(at bot p0)", "(free bot)", *links, *(f"(rec-at {r} p{p})" for r, p in where.items())]
    for k in range(8):
        if k % 2 == 0:  # in a box in a cabinet: inside both
            box, cabinet = rng.sample(sorted(where), 2)
            init += [f"(inside i{k} {box})", f"(inside i{k} {cabinet})", f"(item-at i{k} p{where[box]})"]
        else:
            init.append(f"(item-at i{k} p{rng.randrange(10)})")
    objects = f"bot - agent {' '.join(places)} - place {' '.join(where)} - receptacle"
    objects += " " + " ".join(f"i{k}" for k in range(8)) + " - item"
    return (
        f"(define (problem scene-{seed}) (:domain scene) (:objects {objects})"
        f" (:init {' '.join(init)} {timed}) (:goal (holding bot i{2 * rng.randrange(4)})))"
    )


def noise_problem(seed: int) -> str:
    """A short way past sleepers and a long way round; the goal wakes no one.  The sleepers are
    named nowhere but in the quantified effect's condition; z0 sleeps near no cell."""
    rng = random.Random(seed)
    cells = [f"c{i}" for i in range(10)] + [f"d{i}" for i in range(1, 12)]
    way = ["c0", *(f"d{i}" for i in range(1, 12)), "c9"]
    links = [(f"c{i}", f"c{i + 1}") for i in range(9)] + list(zip(way, way[1:]))
    adj = " ".join(f"(adj {a} {b}) (adj {b} {a})" for a, b in links)
    near = " ".join(f"(near s{k} c{rng.randrange(2, 8)})" for k in range(3))
    objects = f"a - agent {' '.join(cells)} - cell s0 s1 s2 z0 - sleeper"
    return (
        f"(define (problem noise-{seed}) (:domain noise) (:objects {objects})"
        f" (:init (at a c0) {adj} {near}) (:goal (and (at a c9) (not (woken)))))"
    )


def guarded_problem(seed: int) -> str:
    rng = random.Random(seed)
    cells = [f"c{i}" for i in range(20)]
    adj = [f"(adj c{i} c{j})" for i in range(20) for j in (i + 1, i + 5) if j < 20]
    adj += [f"(adj c{j} c{i})" for i in range(20) for j in (i + 1, i + 5) if j < 20]
    guards = [f"(watch g{k} c{rng.randrange(1, 19)})" for k in range(6)]
    objects = f"a - agent {' '.join(cells)} - cell {' '.join(f'g{k}' for k in range(6))} - guard"
    return (
        f"(define (problem guarded-{seed}) (:domain guarded) (:objects {objects})"
        f" (:init (at a c0) {' '.join(adj)} {' '.join(guards)}) (:goal (at a c19)))"
    )


def alarm_problem(seed: int) -> str:
    rng = random.Random(seed)
    spots = [f"s{i}" for i in range(10)]
    links = [f"(link s{i} s{i + 1})" for i in range(9)] + ["(link s0 s9)"]
    alarms = [f"(armed a{k}) (covers a{k} s{rng.randrange(1, 9)})" for k in range(5)]
    objects = f"t - thief {' '.join(spots)} - spot {' '.join(f'a{k}' for k in range(5))} - alarm"
    return (
        f"(define (problem alarm-{seed}) (:domain alarm) (:objects {objects})"
        f" (:init (at t s0) {' '.join(links)} {' '.join(alarms)}) (:goal (and (took t) (at t s9))))"
    )


WORLDS = {
    "lift": (LIFT, lift_problem),
    "untyped-lift": (UNTYPED_LIFT, lambda seed: lift_problem(seed, untyped=True)),
    "rooms": (ROOMS, rooms_problem),
    "guarded": (GUARDED, guarded_problem),
    "alarm": (ALARM, alarm_problem),
    "scene": (SCENE, scene_problem),
    "noise": (NOISE, noise_problem),
}


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
    reasons = {item.name: item.reason for item in restored_untyped if item.rule == "soundness"}
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
        reasons = {item.name: item.reason for item in restored if item.rule == "soundness"}
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
    reasons = [item.reason for item in restored if item.rule == "soundness"]
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
    from relevance_plan.relevance.scorers import base

    monkeypatch.setattr(base.PlanningTask, "kept_for_soundness", property(lambda self: KeptObjects({}, {})))
    broken = [
        (world, seed)
        for world in sorted(WORLDS)
        for seed in range(3)
        if not _prune_plan_validate(tmp_path, world, seed)
    ]
    assert broken, "every plan was valid even without the rule: the worlds do not test it"
