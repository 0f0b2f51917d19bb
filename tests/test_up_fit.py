"""Fitting a problem read by unified-planning to an engine that refuses its kind as read (``up_fit``).

Aries takes no real-valued fluent, and unified-planning reads every PDDL
function as one; Tamer takes no type below another and no undefined numeric
value.  The rewritten problems must be ones the engines declare they take,
and their plans must be plans of the PDDL files as they are: every plan here
is checked by our own validator on the original files.
"""

from __future__ import annotations

import json
import warnings
from fractions import Fraction

import pytest
from support import run

pytest.importorskip("unified_planning")

from unified_planning.engines.results import ValidationResultStatus  # noqa: E402
from unified_planning.io import PDDLReader  # noqa: E402
from unified_planning.plans import ActionInstance, TimeTriggeredPlan  # noqa: E402
from unified_planning.shortcuts import OneshotPlanner, PlanValidator, get_environment  # noqa: E402

from relevance_plan.io import load_task  # noqa: E402
from relevance_plan.pddl.plans import read_plan  # noqa: E402
from relevance_plan.planning.options import PlanOptions  # noqa: E402
from relevance_plan.planning.planners import auto  # noqa: E402
from relevance_plan.planning.planners import requirements as f  # noqa: E402
from relevance_plan.planning.planners.up.child import _plan_lines  # noqa: E402
from relevance_plan.planning.planners.up.fitting import fit_problem  # noqa: E402
from relevance_plan.planning.results import PlanStatus  # noqa: E402
from relevance_plan.planning.run import plan_task  # noqa: E402
from relevance_plan.planning.validation import validate_builtin  # noqa: E402

# A robot carries parcels between places; rooms and a yard are places, parcels are things.
# The distance is a static function with whole values, undefined from a place to itself;
# the lamp is a thing that is no parcel, so only a guard on ?t keeps `pick` off it.
ERRAND_DOMAIN = """
(define (domain errand)
  (:requirements :typing :durative-actions :numeric-fluents)
  (:types place thing - object
          room yard - place
          parcel - thing)
  (:predicates (robot-at ?p - place) (at ?t - thing ?p - place) (holding ?t - thing) (free) (lit ?r - room))
  (:functions (distance ?a ?b - place))
  (:durative-action go
    :parameters (?a ?b - place)
    :duration (= ?duration (distance ?a ?b))
    :condition (at start (robot-at ?a))
    :effect (and (at start (not (robot-at ?a))) (at end (robot-at ?b))))
  (:durative-action pick
    :parameters (?t - parcel ?p - place)
    :duration (= ?duration 1)
    :condition (and (at start (free)) (at start (at ?t ?p)) (over all (robot-at ?p)))
    :effect (and (at start (not (free))) (at start (not (at ?t ?p))) (at end (holding ?t))))
  (:durative-action drop
    :parameters (?t - thing ?r - room)
    :duration (= ?duration 1)
    :condition (and (at start (holding ?t)) (over all (robot-at ?r)))
    :effect (and (at start (not (holding ?t))) (at end (at ?t ?r)) (at end (free)))))
"""

ERRAND_PROBLEM = """
(define (problem errand-1) (:domain errand)
  (:objects hall kitchen - room garden - yard box1 box2 - parcel lamp - thing)
  (:init (robot-at hall) (free) (at box1 garden) (at box2 hall) (at lamp garden)
         (= (distance hall kitchen) 3) (= (distance kitchen hall) 3)
         (= (distance hall garden) 5) (= (distance garden hall) 5)
         (= (distance kitchen garden) 4) (= (distance garden kitchen) 4))
  (:goal (and (at box1 kitchen))))
"""

# A plan of the original problem, and the same with the lamp (no parcel) for the box.
ERRAND_PLAN = """
0.0: (go hall garden) [5.0]
5.01: (pick box1 garden) [1.0]
6.02: (go garden kitchen) [4.0]
10.03: (drop box1 kitchen) [1.0]
"""
LAMP_PLAN = ERRAND_PLAN.replace("box1", "lamp")


def engine_installed(engine: str) -> None:
    pytest.importorskip(f"up_{engine}", reason=f"up-{engine} is not installed: pip install 'relevance-plan[planners]'")


@pytest.fixture(scope="module", autouse=True)
def quiet_environment():
    get_environment().credits_stream = None


def write_errand(tmp_path, domain: str = ERRAND_DOMAIN, problem: str = ERRAND_PROBLEM):
    (tmp_path / "domain.pddl").write_text(domain)
    (tmp_path / "problem.pddl").write_text(problem)
    return tmp_path / "domain.pddl", tmp_path / "problem.pddl"


def read_up(domain_path, problem_path):
    return PDDLReader().parse_problem(str(domain_path), str(problem_path))


def fitted_for(engine: str, domain_path, problem_path):
    environment = get_environment()
    fitted = fit_problem(environment, engine, read_up(domain_path, problem_path))
    return fitted, environment.factory.engine(engine)


def valid_on_the_original(domain_path, problem_path, plan_text: str) -> bool:
    domain, problem = load_task(domain_path, problem_path)
    return validate_builtin(domain, problem, read_plan(plan_text)).valid


def up_validates(problem, plan_text: str) -> bool:
    """unified-planning's verdict on a timed plan of ``problem`` (actions and objects by name)."""
    steps = []
    for step in read_plan(plan_text):
        action = problem.action(step.action)
        instance = ActionInstance(action, [problem.object(name) for name in step.args])
        steps.append((Fraction(str(step.time)), instance, Fraction(str(step.duration))))
    plan = TimeTriggeredPlan(steps)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        with PlanValidator(problem_kind=problem.kind, plan_kind=plan.kind) as validator:
            return validator.validate(problem, plan).status is ValidationResultStatus.VALID


# --------------------------------------------------------------------------- whole numbers for Aries


def test_whole_values_become_integer_fluents_that_aries_takes(tmp_path):
    engine_installed("aries")
    files = write_errand(tmp_path)
    read = read_up(*files)
    fitted, aries = fitted_for("aries", *files)
    assert not aries.supports(read.kind) and "REAL_TYPE_DURATIONS" in read.kind.features
    assert aries.supports(fitted.problem.kind) and fitted.lacking == ()
    assert fitted.notes == ("turned 1 real-valued fluent into integer fluent (every value is whole) to run",)
    assert fitted.problem.fluent("distance").type.is_int_type()
    assert "INT_TYPE_DURATIONS" in fitted.problem.kind.features
    assert "REAL_TYPE_DURATIONS" not in fitted.problem.kind.features
    # Values, names and the hierarchy (Aries takes it) are as read.
    hall, kitchen = fitted.problem.object("hall"), fitted.problem.object("kitchen")
    assert fitted.problem.initial_value(fitted.problem.fluent("distance")(hall, kitchen)).constant_value() == 3
    assert [a.name for a in fitted.problem.actions] == [a.name for a in read.actions]
    assert fitted.problem.user_type("room").father is not None


@pytest.mark.parametrize(
    ("change", "into"),
    [
        ("(= (distance hall kitchen) 3)", "(= (distance hall kitchen) 2.5)"),  # an initial value
        ("(= ?duration 1)", "(= ?duration 1.5)"),  # a number beside the functions
    ],
)
def test_a_value_that_is_not_whole_is_left_alone(tmp_path, change, into):
    engine_installed("aries")
    domain, problem = ERRAND_DOMAIN.replace(change, into), ERRAND_PROBLEM.replace(change, into)
    fitted, aries = fitted_for("aries", *write_errand(tmp_path, domain, problem))
    assert fitted.problem.fluent("distance").type.is_real_type()
    assert not any("integer" in note for note in fitted.notes)
    assert not aries.supports(fitted.problem.kind) and "REAL_TYPE_DURATIONS" in fitted.lacking


def test_an_effect_giving_a_value_that_is_not_whole_is_left_alone(tmp_path):
    engine_installed("aries")
    domain = ERRAND_DOMAIN.replace(
        "(:functions (distance ?a ?b - place))", "(:functions (distance ?a ?b - place) (tired))"
    )
    domain = domain.replace("(at end (holding ?t))))", "(at end (holding ?t)) (at end (increase (tired) 0.5))))")
    problem = ERRAND_PROBLEM.replace("(free)", "(free) (= (tired) 0)")
    fitted, _ = fitted_for("aries", *write_errand(tmp_path, domain, problem))
    assert fitted.problem.fluent("tired").type.is_real_type()
    assert fitted.problem.fluent("distance").type.is_real_type()  # all or none


def test_action_costs_read_as_integers_for_aries_and_dropped_for_tamer(tmp_path):
    engine_installed("aries")
    engine_installed("tamer")
    domain = ERRAND_DOMAIN.replace("(distance ?a ?b - place))", "(distance ?a ?b - place) (total-cost))")
    domain = domain.replace(
        "(at end (robot-at ?b))))", "(at end (robot-at ?b)) (at end (increase (total-cost) (distance ?a ?b)))))"
    )
    problem = ERRAND_PROBLEM.replace("(free)", "(free) (= (total-cost) 0)")
    problem = problem.replace("(at box1 kitchen))))", "(at box1 kitchen))) (:metric minimize (total-cost)))")
    files = write_errand(tmp_path, domain, problem)
    for_aries, aries = fitted_for("aries", *files)
    (metric,) = for_aries.problem.quality_metrics
    assert metric.costs[for_aries.problem.action("go")].type.is_int_type() and aries.supports(for_aries.problem.kind)
    # Tamer ranks by no metric: the costs are not worth rewriting, the distance's undefined values still are.
    for_tamer, tamer = fitted_for("tamer", *files)
    assert for_tamer.notes == (
        "flattened the type hierarchy (3 types) to run",
        "guarded the undefined values of 1 numeric fluent (distance) to run",
        "solving without the metric, which it does not take",
    )
    assert not for_tamer.problem.quality_metrics and tamer.supports(for_tamer.problem.kind)
    assert read_up(*files).quality_metrics  # the problem as read keeps its metric


# --------------------------------------------------------------------------- flat types for Tamer


def test_flat_types_and_defined_values_give_a_problem_tamer_takes(tmp_path):
    engine_installed("tamer")
    files = write_errand(tmp_path)
    read = read_up(*files)
    fitted, tamer = fitted_for("tamer", *files)
    assert {"HIERARCHICAL_TYPING", "UNDEFINED_INITIAL_NUMERIC"} <= set(read.kind.features)
    assert tamer.supports(fitted.problem.kind) and fitted.lacking == ()
    assert fitted.notes == (
        "flattened the type hierarchy (3 types) to run",
        "guarded the undefined values of 1 numeric fluent (distance) to run",
    )
    flat = fitted.problem
    assert all(t.father is None for t in flat.user_types)
    assert {o.name: o.type.name for o in flat.all_objects} == {
        "hall": "place",
        "kitchen": "place",
        "garden": "place",
        "box1": "thing",
        "box2": "thing",
        "lamp": "thing",
    }
    assert [a.name for a in flat.actions] == [a.name for a in read.actions]
    is_parcel = flat.fluent("is_parcel")
    assert flat.initial_value(is_parcel(flat.object("box1"))).is_true()
    assert flat.initial_value(is_parcel(flat.object("lamp"))).is_false()
    pick_starts = [str(c) for i, cs in flat.action("pick").conditions.items() if i.lower.is_from_start() for c in cs]
    assert "is_parcel(t)" in pick_starts  # the parameter's own type, checked when the action starts
    assert "defined_distance(a, b)" in [str(c) for cs in flat.action("go").conditions.values() for c in cs]
    assert read.user_type("room").father is not None  # the problem as read is not changed


def test_a_parameter_of_type_object_makes_one_flat_type(tmp_path):
    engine_installed("tamer")
    # Naming `object` makes unified-planning put every type below it: one hierarchy, one flat type.
    domain = ERRAND_DOMAIN.replace("(lit ?r - room))", "(lit ?r - room) (seen ?o - object))")
    domain = domain.replace("(at end (free)))))", "(at end (free)) (at end (seen ?t)))))")
    fitted, tamer = fitted_for("tamer", *write_errand(tmp_path, domain))
    assert [t.name for t in fitted.problem.user_types] == ["object"] and tamer.supports(fitted.problem.kind)
    assert fitted.notes[0] == "flattened the type hierarchy (5 types) to run"


def test_timed_initial_literals_are_flattened_with_the_rest(tmp_path):
    engine_installed("tamer")
    problem = ERRAND_PROBLEM.replace("(free)", "(free) (at 20 (lit kitchen))")
    fitted, tamer = fitted_for("tamer", *write_errand(tmp_path, problem=problem))
    ((timing, (effect,)),) = fitted.problem.timed_effects.items()
    assert float(timing.delay) == 20 and str(effect.fluent) == "lit(kitchen)"
    assert effect.fluent.arg(0).object().type.name == "place" and tamer.supports(fitted.problem.kind)


def test_the_guards_keep_the_plans_of_the_original(tmp_path):
    engine_installed("tamer")
    files = write_errand(tmp_path)
    fitted, _ = fitted_for("tamer", *files)
    assert valid_on_the_original(*files, ERRAND_PLAN) and up_validates(fitted.problem, ERRAND_PLAN)
    # The lamp is a thing like a parcel in the flat problem, but no parcel: `pick` must still refuse it.
    (tmp_path / "lamp").mkdir()
    files = write_errand(tmp_path / "lamp", problem=ERRAND_PROBLEM.replace("(at box1 kitchen)", "(at lamp kitchen)"))
    fitted, _ = fitted_for("tamer", *files)
    assert not valid_on_the_original(*files, LAMP_PLAN) and not up_validates(fitted.problem, LAMP_PLAN)


def test_quantified_variables_are_guarded_too(tmp_path):
    engine_installed("tamer")
    # Every parcel, not every thing, must be in the kitchen; a forall effect lights every room.
    domain = ERRAND_DOMAIN.replace(
        "(at end (at ?t ?r)) (at end (free))",
        "(at end (at ?t ?r)) (at end (free)) (forall (?x - room) (at end (lit ?x)))",
    )
    problem = ERRAND_PROBLEM.replace("(at box1 kitchen)", "(forall (?p - parcel) (at ?p kitchen))")
    files = write_errand(tmp_path, domain, problem)
    fitted, _ = fitted_for("tamer", *files)
    flat = fitted.problem
    assert all(t.father is None for t in flat.user_types)
    (goal,) = flat.goals
    assert goal.is_forall() and "is_parcel(p)" in str(goal)
    (lights,) = [e for es in flat.action("drop").effects.values() for e in es if e.is_forall()]
    assert "is_room(x)" in str(lights.condition)
    both = (
        ERRAND_PLAN.strip()
        + "\n11.04: (go kitchen hall) [3.0]\n14.05: (pick box2 hall) [1.0]\n15.06: (go hall kitchen) [3.0]"
        + "\n18.07: (drop box2 kitchen) [1.0]\n"
    )
    # The lamp stays in the garden: only the guard keeps it out of the goal.
    assert valid_on_the_original(*files, both) and up_validates(flat, both)
    assert not valid_on_the_original(*files, ERRAND_PLAN) and not up_validates(flat, ERRAND_PLAN)


def test_the_added_predicates_take_names_the_problem_does_not_use(tmp_path):
    engine_installed("tamer")
    # The domain already has is_parcel and defined_distance, and a type named like the next choice.
    domain = ERRAND_DOMAIN.replace("(lit ?r - room))", "(lit ?r - room) (is_parcel ?t - thing) (defined_distance))")
    domain = domain.replace("parcel - thing)", "parcel is_parcel_2 - thing)")
    problem = ERRAND_PROBLEM.replace("(free)", "(free) (is_parcel lamp) (defined_distance)")
    files = write_errand(tmp_path, domain, problem)
    read = read_up(*files)
    fitted, tamer = fitted_for("tamer", *files)
    flat = fitted.problem
    names = [fluent.name for fluent in flat.fluents]
    added = set(names) - {fluent.name for fluent in read.fluents}
    assert len(names) == len(set(names))
    assert added == {"is_parcel_3", "is_room", "defined_distance_2"}
    assert not any(read.has_name(name) for name in added)
    # The problem's own predicates keep their values.
    assert flat.initial_value(flat.fluent("is_parcel")(flat.object("lamp"))).is_true()
    assert flat.initial_value(flat.fluent("is_parcel_3")(flat.object("lamp"))).is_false()
    assert tamer.supports(flat.kind)


def test_an_undefined_value_an_effect_may_set_is_not_guarded(tmp_path):
    engine_installed("tamer")
    # `go` measures the distance: it is no longer static, so no static guard can stand for it.
    domain = ERRAND_DOMAIN.replace(
        "(at end (robot-at ?b))))", "(at end (robot-at ?b)) (at end (assign (distance ?b ?a) (distance ?a ?b)))))"
    )
    fitted, _ = fitted_for("tamer", *write_errand(tmp_path, domain))
    assert not any("undefined" in note for note in fitted.notes)
    assert "UNDEFINED_INITIAL_NUMERIC" in fitted.lacking
    assert any("flattened" in note for note in fitted.notes)  # what could be done still is


def test_auto_does_not_count_on_a_rewrite_that_depends_on_values():
    temporal_numeric = frozenset({f.STRIPS, f.DURATIVE_ACTIONS, f.NUMERIC_FLUENTS, f.DURATION_INEQUALITIES})
    assert "up:aries" not in [c.name for c in auto.TEMPORAL_ORDER if temporal_numeric <= c.takes]
    assert f.HIERARCHICAL_TYPING in auto.TAMER.takes


# --------------------------------------------------------------------------- values never set

# A counter the problem never sets, which `bump` increases: the tool's validator (and VAL) count it
# from 0, so bump, bump, finish is a plan; `check` reads it before any bump, which nothing can.
COUNTER_DOMAIN = """(define (domain counting)
  (:requirements :typing :numeric-fluents)
  (:types box)
  (:predicates (done) (ready ?b - box))
  (:functions (counter) (reading))
  (:action bump :parameters (?b - box) :precondition (ready ?b) :effect (and (increase (counter) 1)))
  (:action finish :parameters (?b - box) :precondition (>= (counter) 2) :effect (and (done)))
  (:action check :parameters (?b - box) :precondition (>= (reading) 0) :effect (and (done))))
"""
COUNTER_PROBLEM = "(define (problem count-1) (:domain counting) (:objects b - box) (:init (ready b)) (:goal (done)))"


def test_a_value_never_set_that_effects_increase_starts_from_zero_for_every_engine(tmp_path):
    files = write_errand(tmp_path, COUNTER_DOMAIN, COUNTER_PROBLEM)
    for engine in ("enhsp", "tamer", "aries"):
        fitted, _ = fitted_for(engine, *files)
        problem = fitted.problem
        assert problem.initial_value(problem.fluent("counter")()).constant_value() == 0, engine
        assert "counted counter from 0 where the problem leaves it unset" in fitted.notes
    enhsp, _ = fitted_for("enhsp", *files)  # takes undefined values: one only read stays undefined
    assert enhsp.problem.initial_value(enhsp.problem.fluent("reading")()) is None


@pytest.mark.planner
@pytest.mark.parametrize("engine", ["enhsp", "tamer"])
def test_plan_and_validate_agree_on_a_value_never_set(tmp_path, engine):
    """The planner route and the validator share one convention: the plan they find, validate takes."""
    engine_installed(engine)
    domain, problem = write_errand(tmp_path, COUNTER_DOMAIN, COUNTER_PROBLEM)
    plan = tmp_path / "plan.txt"
    code, stdout, stderr = run("plan", domain, problem, "--planner", f"up:{engine}", "--no-race", "--json",
                               "--plan-file", plan)  # fmt: skip
    assert code == 0, stderr
    assert json.loads(stdout)["status"] == "solved" and "bump" in plan.read_text()
    assert run("validate", domain, problem, plan)[0] == 0
    # a value only read is undefined for both: no plan from the planner, none accepted by validate
    reading = COUNTER_DOMAIN.replace("(increase (counter) 1)", "(increase (counter) 0)").replace(
        "(>= (counter) 2)", "(>= (reading) 1)"
    )
    domain.write_text(reading)
    code, stdout, _ = run("plan", domain, problem, "--planner", f"up:{engine}", "--no-race", "--json", "-q",
                          "--plan-file", plan)  # fmt: skip
    assert code != 0 and json.loads(stdout)["status"] in ("unsolvable", "unsupported", "no-valid-plan")
    plan.write_text("(check b)\n")
    assert run("validate", domain, problem, plan)[0] == 13


# --------------------------------------------------------------------------- solving


@pytest.mark.planner
def test_a_flattened_problems_plan_is_valid_on_the_original(tmp_path):
    engine_installed("tamer")
    files = write_errand(tmp_path)
    fitted, _ = fitted_for("tamer", *files)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # Tamer takes no timeout and says so
        with OneshotPlanner(name="tamer") as planner:
            result = planner.solve(fitted.problem, timeout=60)
    assert result.plan is not None, result.status
    written = "\n".join(_plan_lines(result.plan))
    assert valid_on_the_original(*files, written)


@pytest.mark.planner
def test_plan_with_aries_solves_a_temporal_problem_with_a_static_distance(tmp_path):
    engine_installed("aries")
    domain, problem = write_errand(tmp_path)
    code, stdout, stderr = run(
        "plan",
        domain,
        problem,
        "--planner",
        "up:aries",
        "--timeout",
        "60",
        "--no-race",
        "--json",
        "--plan-file",
        tmp_path / "plan.txt",
    )
    assert code == 0, stderr
    data = json.loads(stdout)
    assert data["status"] == "solved" and data["valid"] and data["planner"] == "up:aries"
    assert valid_on_the_original(domain, problem, (tmp_path / "plan.txt").read_text())


@pytest.mark.planner
def test_tamer_plans_the_hierarchy_it_refused(tmp_path):
    engine_installed("tamer")
    files = write_errand(tmp_path)
    result = plan_task(*files, PlanOptions(planner="up:tamer", method="pure", timeout=60, race=False))
    assert result.status is PlanStatus.SOLVED, result.message
    assert result.valid and result.validation.validator.startswith("builtin")


@pytest.mark.planner
def test_aries_refuses_what_cannot_be_read_as_integers_in_one_attempt(tmp_path):
    engine_installed("aries")
    files = write_errand(
        tmp_path, problem=ERRAND_PROBLEM.replace("(distance hall kitchen) 3", "(distance hall kitchen) 2.5")
    )
    result = plan_task(*files, PlanOptions(planner="up:aries", timeout=60, race=False))
    assert result.status is PlanStatus.UNSUPPORTED, result.message
    assert len(result.attempts) == 1  # an engine that refuses the kind would refuse the full problem too
