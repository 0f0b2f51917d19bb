"""Temporal and numeric planners in the registry: LPG-td, Aries, Tamer, ENHSP and the ``auto`` choice.

Every plan is validated by the builtin simulator on the original problem and cross-checked with
unified-planning's validator (time-triggered for timed plans, sequential for numeric ones).
"""

from __future__ import annotations

import importlib.util
import json
import shutil
from pathlib import Path

import pytest
from support import run, task_fixture, write_task

from relevance_plan.errors import UnsupportedFeatureError
from relevance_plan.io import load_task
from relevance_plan.pddl.plans import PlanStep, format_plan, read_plan
from relevance_plan.planning.options import PlanOptions
from relevance_plan.planning.planners import auto
from relevance_plan.planning.planners import requirements as f
from relevance_plan.planning.planners.base import PlannerStatus
from relevance_plan.planning.planners.lpg import classify, lpg_binary, read_lpg_plan
from relevance_plan.planning.planners.registry import make_planner
from relevance_plan.planning.results import PlanStatus
from relevance_plan.planning.run import plan_task
from relevance_plan.planning.validation import ValidationStatus, validate_builtin, validate_with_up
from relevance_plan.supervision.process import ProcessRun

JAVA_MISSING = "Java runtime not found: apt-get install default-jre-headless"

# Flat types, constant durations: every temporal planner here takes it as read (Tamer takes
# a type hierarchy and Aries functions only as the up child rewrites them: test_up_fit.py).
HAUL_DOMAIN = """
(define (domain haul)
  (:requirements :typing :durative-actions)
  (:types truck package place)
  (:predicates (truck-at ?t - truck ?p - place) (package-at ?o - package ?p - place)
               (in ?o - package ?t - truck) (road ?a ?b - place))
  (:durative-action drive
    :parameters (?t - truck ?a ?b - place)
    :duration (= ?duration 10)
    :condition (and (at start (truck-at ?t ?a)) (over all (road ?a ?b)))
    :effect (and (at start (not (truck-at ?t ?a))) (at end (truck-at ?t ?b))))
  (:durative-action load
    :parameters (?o - package ?t - truck ?p - place)
    :duration (= ?duration 2)
    :condition (and (at start (package-at ?o ?p)) (over all (truck-at ?t ?p)))
    :effect (and (at start (not (package-at ?o ?p))) (at end (in ?o ?t))))
  (:durative-action unload
    :parameters (?o - package ?t - truck ?p - place)
    :duration (= ?duration 2)
    :condition (and (at start (in ?o ?t)) (over all (truck-at ?t ?p)))
    :effect (and (at start (not (in ?o ?t))) (at end (package-at ?o ?p)))))
"""

# Two packages to move, and a second depot with packages and a truck nobody needs.
HAUL_PROBLEM = """
(define (problem haul-1) (:domain haul)
  (:objects truck1 truck2 - truck box1 box2 crate1 crate2 - package depot market farm yard - place)
  (:init (truck-at truck1 depot) (package-at box1 depot) (package-at box2 farm)
         (truck-at truck2 yard) (package-at crate1 yard) (package-at crate2 yard)
         (road depot market) (road market depot) (road market farm) (road farm market))
  (:goal (and (package-at box1 market) (package-at box2 market))))
"""

FUEL_DOMAIN = """
(define (domain fuel-haul)
  (:requirements :typing :numeric-fluents)
  (:types truck package place)
  (:predicates (truck-at ?t - truck ?p - place) (package-at ?o - package ?p - place)
               (in ?o - package ?t - truck) (road ?a ?b - place))
  (:functions (fuel ?t - truck) (distance ?a ?b - place) (carried ?t - truck) (capacity ?t - truck))
  (:action drive
    :parameters (?t - truck ?a ?b - place)
    :precondition (and (truck-at ?t ?a) (road ?a ?b) (>= (fuel ?t) (distance ?a ?b)))
    :effect (and (not (truck-at ?t ?a)) (truck-at ?t ?b) (decrease (fuel ?t) (distance ?a ?b))))
  (:action refuel
    :parameters (?t - truck ?p - place)
    :precondition (and (truck-at ?t ?p) (< (fuel ?t) 10))
    :effect (assign (fuel ?t) 20))
  (:action load
    :parameters (?o - package ?t - truck ?p - place)
    :precondition (and (package-at ?o ?p) (truck-at ?t ?p) (< (carried ?t) (capacity ?t)))
    :effect (and (not (package-at ?o ?p)) (in ?o ?t) (increase (carried ?t) 1)))
  (:action unload
    :parameters (?o - package ?t - truck ?p - place)
    :precondition (and (in ?o ?t) (truck-at ?t ?p))
    :effect (and (not (in ?o ?t)) (package-at ?o ?p) (decrease (carried ?t) 1))))
"""


def _distances(places: list[str], roads: dict[tuple[str, str], int]) -> str:
    # Every value defined: unified-planning's validators refuse a partial function.
    return " ".join(f"(= (distance {a} {b}) {roads.get((a, b), 0 if a == b else 99)})" for a in places for b in places)


FUEL_PROBLEM = f"""
(define (problem fuel-haul-1) (:domain fuel-haul)
  (:objects truck1 - truck box1 box2 crate1 - package depot market farm - place)
  (:init (truck-at truck1 depot) (package-at box1 depot) (package-at box2 farm) (package-at crate1 depot)
         (road depot market) (road market depot) (road market farm) (road farm market)
         {
    _distances(
        ["depot", "market", "farm"],
        {("depot", "market"): 8, ("market", "depot"): 8, ("market", "farm"): 6, ("farm", "market"): 6},
    )
}
         (= (fuel truck1) 9) (= (carried truck1) 0) (= (capacity truck1) 1))
  (:goal (and (package-at box1 market) (package-at box2 market))))
"""


def installed(planner: str) -> bool:
    if planner == "lpg":
        return lpg_binary() is not None
    engine = planner.removeprefix("up:")
    return importlib.util.find_spec(f"up_{engine}") is not None


def needs(planner: str) -> None:
    """Skip when the planner (or the Java runtime ENHSP needs) is not installed."""
    if not installed(planner):
        pytest.skip(f"{planner} is not installed: pip install 'relevance-plan[planners]'")
    if planner == "up:enhsp" and shutil.which("java") is None:
        pytest.skip(JAVA_MISSING)


haul_files = task_fixture("haul", HAUL_DOMAIN, HAUL_PROBLEM)


fuel_files = task_fixture("fuel-haul", FUEL_DOMAIN, FUEL_PROBLEM)


def planned(files: tuple[Path, Path], planner: str, widen: bool = True):
    """``plan_task`` with ``planner`` (skipped when not installed), its plan cross-checked."""
    needs(planner)
    result = plan_task(*files, PlanOptions(planner=planner, timeout=60, widen=widen))
    cross_checked(*files, result)
    return result


def cross_checked(domain_path: Path, problem_path: Path, result) -> None:
    """The reported plan is valid on the original for the builtin simulator and for unified-planning."""
    assert result.status is PlanStatus.SOLVED, result.message
    assert result.valid and result.validation.validator.startswith("builtin")
    domain, problem = load_task(domain_path, problem_path)
    assert validate_builtin(domain, problem, result.plan).valid
    up = validate_with_up(domain, problem, result.plan)
    assert up.status is ValidationStatus.VALID, up.message


# --------------------------------------------------------------------------- each planner, each family


@pytest.mark.planner
@pytest.mark.parametrize("planner", ["lpg", "up:aries", "up:tamer"])
def test_temporal_planners_give_timed_plans_valid_on_the_original(haul_files, planner):
    # one attempt, with all the time: a planner that proves nothing gets a short first budget, and whether
    # that is enough (LPG's start under load) would decide whether the pruned problem is the one solved
    result = planned(haul_files, planner, widen=False)
    assert result.plan.timed and all(step.duration is not None for step in result.plan)
    assert result.pruned and result.objects_kept < result.objects_total  # the yard and what is in it went
    assert result.planner == planner


@pytest.mark.planner
@pytest.mark.parametrize("planner", ["up:enhsp", "lpg", "up:tamer"])
def test_numeric_planners_give_plans_valid_on_the_original(fuel_files, planner):
    result = planned(fuel_files, planner)
    assert not result.plan.timed  # LPG's parallel levels are read as the sequence they list
    assert any(step.action == "refuel" for step in result.plan)  # the fuel is counted


@pytest.mark.planner
def test_plan_picks_a_temporal_planner_by_itself_and_says_which(haul_files):
    if not (installed("lpg") or installed("up:aries")):
        pytest.skip("no temporal planner installed: pip install 'relevance-plan[planners]'")
    code, stdout, stderr = run("plan", *haul_files, "--json", "--plan-file", haul_files[0].parent / "plan.txt")
    assert code == 0, stderr
    data = json.loads(stdout)
    assert data["planner"] == ("lpg" if installed("lpg") else "up:aries")
    assert data["planner_choice"].startswith("a temporal problem (durative-actions")
    assert data["status"] == "solved" and data["valid"] and data["pruned"]
    written = read_plan((haul_files[0].parent / "plan.txt").read_text())
    assert written.timed and [s.ground for s in written] == [s.ground for s in read_plan("\n".join(data["plan"]))]
    domain, problem = load_task(*haul_files)
    assert validate_builtin(domain, problem, written).valid  # the file holds the plan that was validated


# --------------------------------------------------------------------------- the auto choice, without planning


@pytest.fixture
def everything_installed(monkeypatch):
    monkeypatch.setattr(auto, "has_module", lambda name: True)
    monkeypatch.setattr(auto, "lpg_binary", lambda: Path("/opt/lpg"))
    monkeypatch.setattr(auto, "find_java", lambda: Path("/usr/bin/java"))


def test_auto_chooses_by_the_family_of_the_problem(everything_installed):
    classical = frozenset({f.STRIPS, f.TYPING, f.ACTION_COSTS, f.DERIVED_PREDICATES, f.CONDITIONAL_EFFECTS})
    assert auto.choose(classical, "lama-first").planner.name == "fast-downward"
    temporal = frozenset({f.STRIPS, f.DURATIVE_ACTIONS, f.NUMERIC_FLUENTS})
    assert auto.choose(temporal, "lama-first").planner.name == "lpg"
    assert auto.choose(temporal | {f.DURATION_INEQUALITIES}, "").planner.name == "up:tamer"  # LPG: not supported
    assert auto.choose(frozenset({f.STRIPS, f.HIERARCHICAL_TYPING, f.DURATION_INEQUALITIES}), "").planner.name == (
        "up:aries"
    )
    numeric = frozenset({f.STRIPS, f.NUMERIC_FLUENTS})
    assert auto.choose(numeric, "").planner.name == "up:enhsp"
    assert auto.choose(numeric | {f.DERIVED_PREDICATES}, "").planner.name == "lpg"
    choice = auto.choose(temporal, "")
    assert choice.reason.startswith("a temporal problem (durative-actions, numeric-fluents)")


def test_auto_without_java_plans_numeric_problems_with_lpg(everything_installed, monkeypatch):
    monkeypatch.setattr(auto, "find_java", lambda: None)
    assert auto.choose(frozenset({f.STRIPS, f.NUMERIC_FLUENTS}), "").planner.name == "lpg"


def test_auto_names_what_to_install_in_one_line(monkeypatch):
    monkeypatch.setattr(auto, "has_module", lambda name: False)
    monkeypatch.setattr(auto, "lpg_binary", lambda: None)
    with pytest.raises(UnsupportedFeatureError) as refused:
        auto.choose(frozenset({f.STRIPS, f.DURATIVE_ACTIONS}), "", "domain.pddl")
    message = str(refused.value)
    assert "\n" not in message and message.startswith("domain.pddl: no installed planner takes")
    assert "durative-actions" in message and "pip install" in message and "up-lpg" in message
    with pytest.raises(UnsupportedFeatureError, match="no planner this tool knows .* --planner cmd:"):
        auto.choose(frozenset({f.STRIPS, f.PREFERENCES}), "")


def test_auto_is_the_default_and_stays_fast_downward_on_classical_problems(coffee_files):
    from relevance_plan.planning.planners.registry import DEFAULT_PLANNER
    from relevance_plan.planning.planners.supply import planner_for

    assert DEFAULT_PLANNER == "auto" and PlanOptions().planner == "auto"
    domain, problem = load_task(*coffee_files)
    chosen, why = planner_for(make_planner("auto"), domain, problem)
    assert chosen.name == "fast-downward" and why == "a classical problem"
    assert make_planner("auto").version().startswith("auto: ")


# --------------------------------------------------------------------------- what each problem uses


def _features(tmp_path, domain_text: str, problem_text: str) -> frozenset[str]:
    (tmp_path / "d.pddl").write_text(domain_text)
    (tmp_path / "p.pddl").write_text(problem_text)
    return f.problem_features(*load_task(tmp_path / "d.pddl", tmp_path / "p.pddl"))


def test_durations_typings_and_either_types_are_features(tmp_path):
    haul = _features(tmp_path, HAUL_DOMAIN, HAUL_PROBLEM)
    assert haul == {f.STRIPS, f.TYPING, f.DURATIVE_ACTIONS}
    ranged = HAUL_DOMAIN.replace("(= ?duration 10)", "(and (>= ?duration 5) (<= ?duration 10))")
    assert f.DURATION_INEQUALITIES in _features(tmp_path, ranged, HAUL_PROBLEM)
    timed_by_function = HAUL_DOMAIN.replace("(:predicates", "(:functions (speed)) (:predicates").replace(
        "(= ?duration 10)", "(= ?duration (* 2 (speed)))"
    )
    assert f.NUMERIC_FLUENTS in _features(tmp_path, timed_by_function, HAUL_PROBLEM)
    typed = HAUL_DOMAIN.replace(
        "(:types truck package place)", "(:types vehicle place package - object truck - vehicle)"
    )
    assert f.HIERARCHICAL_TYPING in _features(tmp_path, typed, HAUL_PROBLEM)
    # (either ...) by where it stands: readers take it in some places only
    either = HAUL_DOMAIN.replace("(truck-at ?t - truck", "(truck-at ?t - (either truck package)")
    assert f.EITHER_PREDICATE_TYPES in _features(tmp_path, either, HAUL_PROBLEM)
    assert f.EITHER_TYPES not in _features(tmp_path, either, HAUL_PROBLEM)
    either = HAUL_DOMAIN.replace(":parameters (?t - truck ?a", ":parameters (?t - (either truck package) ?a")
    assert f.EITHER_TYPES in _features(tmp_path, either, HAUL_PROBLEM)
    either = HAUL_PROBLEM.replace("truck1 truck2 - truck", "truck1 - (either truck package) truck2 - truck")
    assert f.EITHER_OBJECT_TYPES in _features(tmp_path, HAUL_DOMAIN, either)


def test_declared_features_refuse_before_any_work(tmp_path):
    ranged = HAUL_DOMAIN.replace("(= ?duration 10)", "(and (>= ?duration 5) (<= ?duration 10))")
    (tmp_path / "d.pddl").write_text(ranged)
    (tmp_path / "p.pddl").write_text(HAUL_PROBLEM)
    domain, problem = load_task(tmp_path / "d.pddl", tmp_path / "p.pddl")
    with pytest.raises(UnsupportedFeatureError, match="lpg does not take duration-inequalities"):
        make_planner("lpg").check(domain, problem)
    make_planner("up:aries").check(domain, problem)
    with pytest.raises(UnsupportedFeatureError, match="up:enhsp does not take duration-inequalities, durative-actions"):
        make_planner("up:enhsp").check(domain, problem)


# --------------------------------------------------------------------------- LPG's own conventions


LPG_TEMPORAL_PLAN = """
; Version LPG-td-1.4
; MakeSpan 14.00

0.0003:   (LOAD BOX1 TRUCK1 DEPOT) [2.0000])
2.0007:   (DRIVE TRUCK1 DEPOT MARKET) [10.0000])
"""

LPG_PARALLEL_PLAN = """
; Version LPG-td-1.4
; Actions having STRIPS duration
; MetricValue 2.00

0:   (LOAD BOX1 TRUCK1 DEPOT) [1]
1:   (UNLOAD BOX1 TRUCK1 MARKET) [1]
1:   (REFUEL TRUCK1 MARKET) [1]
"""


def test_lpg_plan_files_are_read_in_its_own_conventions():
    timed = read_lpg_plan(LPG_TEMPORAL_PLAN, "")
    assert timed.steps[0] == PlanStep("load", ("box1", "truck1", "depot"), 0.0003, 2.0)
    assert timed.steps[1].time == 2.0007 and timed.steps[1].duration == 10.0
    parallel = read_lpg_plan(LPG_PARALLEL_PLAN, "Problem with Timed Initial Literals: NO")
    assert not parallel.timed and [s.action for s in parallel] == ["load", "unload", "refuel"]
    # with timed initial literals the time stamps matter: kept
    assert read_lpg_plan(LPG_PARALLEL_PLAN, "Problem with Timed Initial Literals: YES").timed
    assert read_lpg_plan("this is no plan\n", "") is None
    assert read_plan(format_plan(timed)) == timed  # LPG's fractions of a millisecond survive writing


def test_lpg_is_classified_by_its_exit_code_and_words():
    def run(code, fired=False):
        return ProcessRun(0, code, 0.0, 0.0, fired, 1.0, 1)

    plan = read_plan("(a)")
    assert classify(run(0), plan, "") is PlannerStatus.SOLVED
    assert classify(run(0), None, "search limit exceeded.") is PlannerStatus.SEARCH_INCOMPLETE
    assert classify(run(1), None, "Goals of the planning problem can not be reached.") is PlannerStatus.UNSOLVABLE
    unsupported = "Duration inequalities are not supported by this version"
    assert classify(run(1), None, unsupported) is PlannerStatus.UNSUPPORTED
    assert classify(run(0), None, "This version of LPG doesn't support SCALE_UP") is PlannerStatus.UNSUPPORTED
    assert classify(run(-9, fired=True), None, "") is PlannerStatus.OUT_OF_TIME
    table = "too many relevant facts! increase MAX_RELEVANT_FACTS (currently 15000)"
    assert classify(run(1), None, table) is PlannerStatus.OUT_OF_MEMORY
    assert classify(run(1), None, "Parsing domain file") is PlannerStatus.PLANNER_CRASH


@pytest.mark.planner
def test_lpg_says_what_it_does_not_support(tmp_path):
    needs("lpg")
    (tmp_path / "d.pddl").write_text(
        "(define (domain g) (:requirements :typing :numeric-fluents) (:types thing) (:predicates (p ?x - thing))"
        " (:functions (e ?x - thing))"
        " (:action grow :parameters (?x - thing) :precondition (p ?x) :effect (scale-up (e ?x) 2)))"
    )
    (tmp_path / "p.pddl").write_text(
        "(define (problem g1) (:domain g) (:objects a - thing) (:init (p a) (= (e a) 1)) (:goal (> (e a) 3)))"
    )
    outcome = make_planner("lpg").run(tmp_path / "d.pddl", tmp_path / "p.pddl", time_limit=30, memory_limit_mb=None)
    assert outcome.status is PlannerStatus.UNSUPPORTED
    assert "SCALE_UP" in outcome.reason and outcome.reason.startswith("LPG-td exit code 0")


# --------------------------------------------------------------------------- timed plans, PDDL 2.1 semantics

TANK_DOMAIN = """
(define (domain tank) (:requirements :typing :durative-actions :numeric-fluents)
  (:types tank)
  (:predicates (open ?t - tank) (marked ?t - tank))
  (:functions (level ?t - tank) (rate))
  (:durative-action pour :parameters (?t - tank) :duration (= ?duration 2)
    :condition (at start (open ?t)) :effect (and (at end (increase (level ?t) 3)) (at end (marked ?t))))
  (:durative-action drain :parameters (?t - tank) :duration (= ?duration 2)
    :condition (at start (open ?t)) :effect (and (at end (decrease (level ?t) 1)) (at end (marked ?t))))
  (:durative-action set-rate :parameters (?t - tank) :duration (= ?duration 2)
    :condition (at start (open ?t)) :effect (at end (assign (rate) 7)))
  (:durative-action fill :parameters (?t - tank) :duration (= ?duration 2)
    :condition (at start (open ?t)) :effect (at end (increase (level ?t) (rate)))))
"""
TANK_PROBLEM = """
(define (problem tank-1) (:domain tank) (:objects a - tank)
  (:init (open a) (= (level a) 0) (= (rate) 1)) (:goal (and (marked a) (>= (level a) 2))))
"""


def test_simultaneous_happenings_follow_pddl21_mutex(tmp_path):
    """As VAL checks it: increases and decreases of one value commute and add up, two happenings may
    add one fact; an assignment with a read of the same value at one instant is a conflict."""
    (tmp_path / "d.pddl").write_text(TANK_DOMAIN)
    (tmp_path / "p.pddl").write_text(TANK_PROBLEM)
    domain, problem = load_task(tmp_path / "d.pddl", tmp_path / "p.pddl")
    together = validate_builtin(domain, problem, read_plan("0.0: (pour a) [2]\n0.0: (drain a) [2]\n"))
    assert together.valid, together.message  # level 0 + 3 - 1 = 2
    too_little = validate_builtin(domain, problem, read_plan("0.0: (drain a) [2]\n0.0: (drain a) [2]\n"))
    assert not too_little.valid and "goal" in too_little.message  # both decreases applied: -2
    clash = validate_builtin(domain, problem, read_plan("0.0: (set-rate a) [2]\n0.0: (fill a) [2]\n"))
    assert not clash.valid and "interfere" in clash.message


CHARGE_DOMAIN = """
(define (domain charge) (:requirements :typing :durative-actions :numeric-fluents)
  (:types bot)
  (:predicates (ran ?b - bot) (full ?b - bot))
  (:functions (energy ?b - bot))
  (:durative-action run :parameters (?b - bot) :duration (= ?duration 1)
    :condition (at start (>= (energy ?b) 5)) :effect (and (at end (decrease (energy ?b) 5)) (at end (ran ?b))))
  (:durative-action charge :parameters (?b - bot) :duration (= ?duration (/ (- 10 (energy ?b)) 2))
    :condition (at start (< (energy ?b) 10)) :effect (and (at end (assign (energy ?b) 10)) (at end (full ?b)))))
"""
CHARGE_PROBLEM = """
(define (problem charge-1) (:domain charge) (:objects b - bot)
  (:init (= (energy b) 8)) (:goal (and (ran b) (full b))))
"""


def test_a_given_duration_is_checked_in_the_values_the_step_starts_with(tmp_path):
    """A recharge lasts as long as the energy when it starts says (as in the IPC's rovers with
    time), not the initial energy: energy 8, a run takes 5, so the charge after it lasts 3.5."""
    (tmp_path / "d.pddl").write_text(CHARGE_DOMAIN)
    (tmp_path / "p.pddl").write_text(CHARGE_PROBLEM)
    domain, problem = load_task(tmp_path / "d.pddl", tmp_path / "p.pddl")
    right = validate_builtin(domain, problem, read_plan("0.0: (run b) [1]\n1.01: (charge b) [3.5]\n"))
    assert right.valid, right.message
    initial = validate_builtin(domain, problem, read_plan("0.0: (run b) [1]\n1.01: (charge b) [1]\n"))
    assert not initial.valid and "duration 1 violates its constraint" in initial.message
    before = validate_builtin(domain, problem, read_plan("0.0: (charge b) [1]\n1.01: (run b) [1]\n"))
    assert before.valid, before.message  # charged first, from 8: one time unit


@pytest.mark.planner
def test_broken_timed_plans_are_invalid_for_both_validators(haul_files):
    domain, problem = load_task(*haul_files)
    good = read_plan(
        "0.0: (load box1 truck1 depot) [2]\n2.01: (drive truck1 depot market) [10]\n"
        "12.02: (unload box1 truck1 market) [2]\n14.03: (drive truck1 market farm) [10]\n"
        "24.04: (load box2 truck1 farm) [2]\n26.05: (drive truck1 farm market) [10]\n"
        "36.06: (unload box2 truck1 market) [2]\n"
    )
    assert validate_builtin(domain, problem, good).valid
    assert validate_with_up(domain, problem, good).valid
    early = read_plan(_text(good).replace("2.010: (drive", "1.000: (drive"))  # leaves while loading
    first_gone = read_plan("\n".join(_text(good).splitlines()[1:]))
    for broken in (early, first_gone):
        assert validate_builtin(domain, problem, broken).status is ValidationStatus.INVALID
        assert validate_with_up(domain, problem, broken).status is ValidationStatus.INVALID


def _text(plan) -> str:
    return format_plan(plan)


@pytest.mark.planner
@pytest.mark.parametrize("planner", ["up:tamer", "auto"])
def test_a_number_the_planners_reader_refuses_is_unsupported_not_malformed(tmp_path, planner):
    """Our reader takes a timed literal at 1e308; unified-planning's grammar has no exponent: the
    planner does not take that input (33), which is not malformed PDDL (32)."""
    pytest.importorskip("up_tamer")
    domain = HAUL_DOMAIN.replace(":durative-actions", ":durative-actions :timed-initial-literals")
    problem = HAUL_PROBLEM.replace("(:init", "(:init (at 1e308 (road depot farm))", 1)
    domain, problem = write_task(tmp_path, "haul", domain, problem)
    code, _, stderr = run("plan", domain, problem, "--planner", planner, "-q", "--timeout", "60",
                          "--plan-file", tmp_path / "plan")  # fmt: skip
    assert code == 33, stderr
    assert "its reader refuses the problem, which the tool's reader takes" in stderr
