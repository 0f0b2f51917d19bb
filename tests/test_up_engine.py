"""The unified-planning meta-engine ``relevance[<planner>]``, end to end.

Problems are built in code with UP's shortcuts; every plan is validated on
the ORIGINAL problem with UP's own validator.  Fast Downward writes
``output.sas`` in the working directory, so each test runs in its own.
"""

from __future__ import annotations

import shutil
import subprocess
import sys
import textwrap
import warnings

import pytest
from support import REPO
from unified_planning.engines import PlanGenerationResultStatus as Status
from unified_planning.engines.results import ValidationResultStatus
from unified_planning.io import PDDLReader
from unified_planning.plans import ActionInstance, SequentialPlan
from unified_planning.shortcuts import (
    BoolType,
    Equals,
    Exists,
    Fluent,
    InstantaneousAction,
    IntType,
    MinimizeActionCosts,
    Not,
    Object,
    OneshotPlanner,
    PlanValidator,
    Problem,
    UserType,
    Variable,
    get_environment,
)

from relevance_plan.errors import UsageError
from relevance_plan.integrations.up_engine import lift_plan, register_relevance_engine, restrict_problem


@pytest.fixture(scope="module", autouse=True)
def registered():
    register_relevance_engine()
    get_environment().credits_stream = None  # no credit banners in the test output


@pytest.fixture(autouse=True)
def own_directory(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)


# --------------------------------------------------------------------------- problems


def gripper(extra: int = 10, rooms: int = 4, room_name: str = "Room {}") -> Problem:
    """Two balls to the second room; ``extra`` balls elsewhere that do not matter.

    Names with capitals and spaces check that the writer's renaming never leaks out.
    """
    Room, Ball, Gripper = UserType("Room"), UserType("Ball"), UserType("Gripper")
    at_robby = Fluent("at-robby", BoolType(), r=Room)
    at = Fluent("at", BoolType(), b=Ball, r=Room)
    free = Fluent("free", BoolType(), g=Gripper)
    carry = Fluent("carry", BoolType(), b=Ball, g=Gripper)
    move = InstantaneousAction("move", frm=Room, to=Room)
    frm, to = move.parameters
    move.add_precondition(at_robby(frm))
    move.add_effect(at_robby(to), True)
    move.add_effect(at_robby(frm), False)
    pick = InstantaneousAction("pick", b=Ball, r=Room, g=Gripper)
    b, r, g = pick.parameters
    pick.add_precondition(at(b, r))
    pick.add_precondition(at_robby(r))
    pick.add_precondition(free(g))
    pick.add_effect(carry(b, g), True)
    pick.add_effect(at(b, r), False)
    pick.add_effect(free(g), False)
    drop = InstantaneousAction("drop", b=Ball, r=Room, g=Gripper)
    b, r, g = drop.parameters
    drop.add_precondition(carry(b, g))
    drop.add_precondition(at_robby(r))
    drop.add_effect(at(b, r), True)
    drop.add_effect(free(g), True)
    drop.add_effect(carry(b, g), False)
    problem = Problem("gripper")
    for fluent in (at_robby, at, free, carry):
        problem.add_fluent(fluent, default_initial_value=False)
    problem.add_actions([move, pick, drop])
    room_objects = [Object(room_name.format(i), Room) for i in range(1, rooms + 1)]
    balls = [Object(f"Ball{i}", Ball) for i in range(1, extra + 3)]
    grippers = [Object("Left", Gripper), Object("right", Gripper)]
    problem.add_objects(room_objects + balls + grippers)
    problem.set_initial_value(at_robby(room_objects[0]), True)
    for hand in grippers:
        problem.set_initial_value(free(hand), True)
    for index, ball in enumerate(balls):
        problem.set_initial_value(at(ball, room_objects[index % rooms] if index >= 2 else room_objects[0]), True)
    problem.add_goal(at(balls[0], room_objects[1]))
    problem.add_goal(at(balls[1], room_objects[1]))
    return problem


def blocksworld(in_the_way: int = 2, towers: int = 3) -> Problem:
    """Goal a on b on c; ``in_the_way`` blocks stacked on a; towers of 4 extra blocks."""
    Block = UserType("block")
    on = Fluent("on", BoolType(), x=Block, y=Block)
    ontable = Fluent("ontable", BoolType(), x=Block)
    clear = Fluent("clear", BoolType(), x=Block)
    handempty = Fluent("handempty", BoolType())
    holding = Fluent("holding", BoolType(), x=Block)
    pick_up = InstantaneousAction("pick-up", x=Block)
    x = pick_up.parameter("x")
    pick_up.add_precondition(clear(x))
    pick_up.add_precondition(ontable(x))
    pick_up.add_precondition(handempty())
    for fluent in (ontable(x), clear(x), handempty()):
        pick_up.add_effect(fluent, False)
    pick_up.add_effect(holding(x), True)
    put_down = InstantaneousAction("put-down", x=Block)
    x = put_down.parameter("x")
    put_down.add_precondition(holding(x))
    put_down.add_effect(holding(x), False)
    for fluent in (clear(x), handempty(), ontable(x)):
        put_down.add_effect(fluent, True)
    stack = InstantaneousAction("stack", x=Block, y=Block)
    x, y = stack.parameters
    stack.add_precondition(holding(x))
    stack.add_precondition(clear(y))
    stack.add_effect(holding(x), False)
    stack.add_effect(clear(y), False)
    for fluent in (clear(x), handempty(), on(x, y)):
        stack.add_effect(fluent, True)
    unstack = InstantaneousAction("unstack", x=Block, y=Block)
    x, y = unstack.parameters
    unstack.add_precondition(on(x, y))
    unstack.add_precondition(clear(x))
    unstack.add_precondition(handempty())
    unstack.add_effect(holding(x), True)
    unstack.add_effect(clear(y), True)
    for fluent in (clear(x), handempty(), on(x, y)):
        unstack.add_effect(fluent, False)
    problem = Problem("blocks")
    for fluent in (on, ontable, clear, handempty, holding):
        problem.add_fluent(fluent, default_initial_value=False)
    problem.add_actions([pick_up, put_down, stack, unstack])
    a, b, c = (Object(name, Block) for name in "abc")
    blockers = [Object(f"x{i}", Block) for i in range(1, in_the_way + 1)]
    extras = [Object(f"t{i}", Block) for i in range(1, 4 * towers + 1)]
    problem.add_objects([a, b, c] + blockers + extras)
    problem.set_initial_value(handempty(), True)
    for block in (b, c):
        problem.set_initial_value(ontable(block), True)
        problem.set_initial_value(clear(block), True)
    for tower in [[a] + blockers] + [extras[i : i + 4] for i in range(0, len(extras), 4)]:
        problem.set_initial_value(ontable(tower[0]), True)
        for lower, upper in zip(tower, tower[1:]):
            problem.set_initial_value(on(upper, lower), True)
        problem.set_initial_value(clear(tower[-1]), True)
    problem.add_goal(on(a, b))
    problem.add_goal(on(b, c))
    return problem


# --------------------------------------------------------------------------- helpers


def solve(problem: Problem, engine: str = "relevance[fast-downward]", timeout: float = 30, **params):
    with OneshotPlanner(name=engine, params=params) as planner:
        return planner.solve(problem, timeout=timeout)


def assert_valid_on_original(problem: Problem, plan) -> None:
    with PlanValidator(name="sequential_plan_validator") as validator:
        assert validator.validate(problem, plan).status is ValidationResultStatus.VALID
    for step in plan.actions:
        assert step.action is problem.action(step.action.name)
        for argument in step.actual_parameters:
            assert argument.object() == problem.object(argument.object().name)


def log_text(result) -> str:
    return "\n".join(message.message for message in result.log_messages)


# --------------------------------------------------------------------------- registration and kinds


def test_registration_is_idempotent_and_names_every_oneshot_planner():
    factory = get_environment().factory
    register_relevance_engine()
    register_relevance_engine(get_environment())
    assert "relevance[fast-downward]" in factory.engines
    assert factory.preference_list.count("relevance[fast-downward]") == 1
    assert not any(name.startswith("relevance[oversubscription") for name in factory.engines)


def test_supported_kind_is_what_reader_and_inner_planner_share():
    engine = get_environment().factory.engine("relevance[fast-downward]")
    problem = gripper(extra=1)
    assert engine.supports(problem.kind)
    counter = Fluent("counter", IntType())
    numeric = problem.clone()
    numeric.add_fluent(counter, default_initial_value=0)
    tick = InstantaneousAction("tick")
    tick.add_increase_effect(counter, 1)
    numeric.add_action(tick)
    assert not engine.supports(numeric.kind)
    kind = engine.supported_kind()
    assert kind.has_negative_conditions() and kind.has_conditional_effects() and kind.has_equalities()
    assert not kind.has_int_fluents()


def test_relevance_options_are_checked_when_the_engine_is_made():
    with pytest.raises(UsageError, match="unknown scorer 'oracle'"):
        OneshotPlanner(name="relevance[fast-downward]", params={"scorer": "oracle"})
    with pytest.raises(UsageError, match="tau-class"):
        OneshotPlanner(name="relevance[fast-downward]", params={"tau_class": 1.5})


# --------------------------------------------------------------------------- compile and map back, no planner


def test_restricted_problem_maps_back_to_the_original():
    problem = gripper(extra=3)
    explicit_before = len(problem.explicit_initial_values)
    removed = {"Ball3", "Ball4", "Ball5", "Room 4"}
    restricted = restrict_problem(problem, removed)
    assert {o.name for o in restricted.all_objects} == {o.name for o in problem.all_objects} - removed
    assert all(arg.object().name not in removed for fluent in restricted.explicit_initial_values for arg in fluent.args)
    assert len(problem.explicit_initial_values) == explicit_before  # the original is untouched
    pick, move, drop = restricted.action("pick"), restricted.action("move"), restricted.action("drop")
    obj = restricted.object
    steps = [
        ActionInstance(pick, (obj("Ball1"), obj("Room 1"), obj("Left"))),
        ActionInstance(pick, (obj("Ball2"), obj("Room 1"), obj("right"))),
        ActionInstance(move, (obj("Room 1"), obj("Room 2"))),
        ActionInstance(drop, (obj("Ball1"), obj("Room 2"), obj("Left"))),
        ActionInstance(drop, (obj("Ball2"), obj("Room 2"), obj("right"))),
    ]
    lifted = lift_plan(SequentialPlan(steps), problem)
    assert_valid_on_original(problem, lifted)
    other = Problem("other")
    teleport = InstantaneousAction("teleport")
    other.add_action(teleport)
    assert lift_plan(SequentialPlan([ActionInstance(teleport)]), problem) is None


# --------------------------------------------------------------------------- end to end with Fast Downward


@pytest.mark.planner
def test_gripper_extra_balls_are_pruned_and_the_plan_is_the_originals():
    problem = gripper(extra=10)
    explicit_before = len(problem.explicit_initial_values)
    result = solve(problem)
    assert result.status is Status.SOLVED_SATISFICING
    assert result.engine_name == "relevance[Fast Downward]"
    assert_valid_on_original(problem, result.plan)
    names = {arg.object().name for step in result.plan.actions for arg in step.actual_parameters}
    assert {"Ball1", "Ball2", "Room 1", "Room 2"} <= names  # the user's names, not the writer's
    metrics = result.metrics
    assert metrics["objects_total"] == "18"
    assert int(metrics["objects_kept"]) < 18 and metrics["attempts"] == "1"
    assert metrics["scorer"] == "goal"
    # The goal filter of `plan` applies here too (one attempt loop): the two balls the goal
    # does not name but that share a room with it are left out, as `plan` leaves them out.
    assert "kept 6 of 18 objects" in log_text(result)
    assert len(problem.explicit_initial_values) == explicit_before


@pytest.mark.planner
def test_blocks_in_the_way_are_kept_by_closure():
    problem = blocksworld(in_the_way=2, towers=3)
    result = solve(problem)
    assert result.status is Status.SOLVED_SATISFICING
    assert_valid_on_original(problem, result.plan)
    # a, b, c and the two blocks on a; the 12 tower blocks are removed.
    assert result.metrics["objects_kept_first_attempt"] == "5"
    assert result.metrics["objects_total"] == "17"
    moved = {step.actual_parameters[0].object().name for step in result.plan.actions}
    assert {"x1", "x2"} <= moved


@pytest.mark.planner
def test_relaxation_recovers_when_the_first_pruning_removes_something_needed():
    problem = gripper(extra=10)
    result = solve(problem, tau_class=0.95, tau_element=0.95)
    assert result.status is Status.SOLVED_SATISFICING
    assert_valid_on_original(problem, result.plan)
    metrics = result.metrics
    assert int(metrics["attempts"]) >= 2
    assert int(metrics["objects_kept_first_attempt"]) < int(metrics["objects_kept"]) < 18
    assert "attempt 1: 4 of 18 objects" in log_text(result) and "UNSOLVABLE_PROVEN" in log_text(result)


@pytest.mark.planner
def test_unsolvable_is_proven_only_on_the_whole_problem():
    problem = gripper(extra=6)
    problem.add_goal(problem.fluent("at")(problem.object("Ball1"), problem.object("Room 3")))  # two rooms at once
    result = solve(problem)
    assert result.status is Status.UNSOLVABLE_PROVEN
    assert result.plan is None
    assert int(result.metrics["attempts"]) >= 2
    assert result.metrics["objects_kept"] == result.metrics["objects_total"]
    assert "the whole problem" in log_text(result)


@pytest.mark.planner
def test_no_time_left_is_a_timeout_not_a_verdict():
    result = solve(gripper(extra=2), timeout=1e-9)
    assert result.status is Status.TIMEOUT
    assert result.metrics["attempts"] == "0"


@pytest.mark.planner
def test_adl_features_and_action_costs_survive_the_round_trip():
    """Subtypes, equality, negation, existential conditions, conditional forall effects, costs."""
    Loc, Thing = UserType("Loc"), UserType("Thing")
    Box, Key = UserType("Box", Thing), UserType("Key", Thing)
    at = Fluent("at", BoolType(), t=Thing, l=Loc)
    robot = Fluent("robot", BoolType(), l=Loc)
    locked = Fluent("locked", BoolType(), b=Box)
    holding = Fluent("holding", BoolType(), t=Thing)
    move = InstantaneousAction("move", a=Loc, b=Loc)
    a, b = move.parameters
    move.add_precondition(robot(a))
    move.add_precondition(Not(Equals(a, b)))
    move.add_effect(robot(b), True)
    move.add_effect(robot(a), False)
    thing = Variable("t", Thing)
    move.add_effect(at(thing, b), True, condition=holding(thing), forall=[thing])
    move.add_effect(at(thing, a), False, condition=holding(thing), forall=[thing])
    pick = InstantaneousAction("pick", t=Thing, l=Loc)
    t, place = pick.parameters
    pick.add_precondition(at(t, place))
    pick.add_precondition(robot(place))
    pick.add_effect(holding(t), True)
    unlock = InstantaneousAction("unlock", bx=Box, l=Loc)
    box, place = unlock.parameters
    key = Variable("k", Key)
    unlock.add_precondition(Exists(holding(key), key))
    unlock.add_precondition(at(box, place))
    unlock.add_precondition(robot(place))
    unlock.add_effect(locked(box), False)
    problem = Problem("Features Test")
    for fluent in (at, robot, locked, holding):
        problem.add_fluent(fluent, default_initial_value=False)
    problem.add_actions([move, pick, unlock])
    places = [Object(f"L{i}", Loc) for i in range(5)]
    boxes = [Object(f"box{i}", Box) for i in range(6)]
    keys = [Object(f"key{i}", Key) for i in range(4)]
    problem.add_objects(places + boxes + keys)
    problem.set_initial_value(robot(places[0]), True)
    for i, item in enumerate(boxes):
        problem.set_initial_value(at(item, places[i % 5]), True)
        problem.set_initial_value(locked(item), True)
    for i, item in enumerate(keys):
        problem.set_initial_value(at(item, places[(i + 2) % 5]), True)
    problem.add_goal(Not(locked(boxes[1])))
    problem.add_goal(at(boxes[0], places[3]))
    problem.add_quality_metric(MinimizeActionCosts({move: 2, pick: 1, unlock: 1}))
    result = solve(problem)
    assert result.status is Status.SOLVED_SATISFICING
    assert_valid_on_original(problem, result.plan)
    assert int(result.metrics["objects_kept"]) < 15
    assert not [m for m in result.log_messages if m.level.name == "WARNING"]


@pytest.mark.planner
def test_costs_from_a_static_fluent_are_pruned_and_validated():
    """Costs from a static numeric fluent: forced past the kind check, our reader reads them, so the
    relevance stage prunes, and the plan validates on the original."""
    problem = gripper(extra=3)
    distance = Fluent("distance", IntType(), a=problem.user_type("Room"), b=problem.user_type("Room"))
    problem.add_fluent(distance, default_initial_value=1)
    move = problem.action("move")
    costs = {move: distance(*move.parameters), problem.action("pick"): 1, problem.action("drop"): 1}
    problem.add_quality_metric(MinimizeActionCosts(costs))
    engine = get_environment().factory.engine("relevance[fast-downward]")
    assert not engine.supports(problem.kind)
    with OneshotPlanner(name="relevance[fast-downward]") as planner:
        planner.skip_checks = True
        result = planner.solve(problem, timeout=30)
    assert result.status is Status.SOLVED_SATISFICING
    assert_valid_on_original(problem, result.plan)
    assert result.metrics["scorer"] == "goal"
    assert int(result.metrics["objects_kept"]) < int(result.metrics["objects_total"])
    assert "relevance stage skipped" not in log_text(result)


@pytest.mark.planner
def test_knowledge_model_is_used_when_the_domain_is_named():
    problem = PDDLReader().parse_problem(
        str(REPO / "domains" / "coffee" / "domain.pddl"), str(REPO / "problems" / "coffee-simple.pddl")
    )
    result = solve(problem, domain="coffee")
    assert result.status is Status.SOLVED_SATISFICING
    assert result.metrics["scorer"] == "model"
    assert int(result.metrics["objects_kept"]) < int(result.metrics["objects_total"])
    assert_valid_on_original(problem, result.plan)


# --------------------------------------------------------------------------- other inner planners


@pytest.mark.planner
def test_pyperplan_as_inner_planner():
    pytest.importorskip("up_pyperplan")
    problem = gripper(extra=10, room_name="room{}")  # up-pyperplan splits plan steps on spaces
    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", message="Pyperplan does not support timeout")
        result = solve(problem, engine="relevance[pyperplan]")
    assert result.status is Status.SOLVED_SATISFICING
    assert result.engine_name.startswith("relevance[")
    assert_valid_on_original(problem, result.plan)
    assert result.metrics["objects_kept"] == "6"  # as `plan` keeps: the goal filter applies here too


@pytest.mark.planner
def test_enhsp_as_inner_planner():
    pytest.importorskip("up_enhsp")
    if shutil.which("java") is None:
        pytest.skip("ENHSP needs a Java runtime")
    problem = gripper(extra=10)
    result = solve(problem, engine="relevance[enhsp]")
    assert result.status is Status.SOLVED_SATISFICING
    assert_valid_on_original(problem, result.plan)
    assert result.metrics["objects_kept"] == "6"  # as `plan` keeps: the goal filter applies here too


# --------------------------------------------------------------------------- up.ini


def test_up_ini_example_registers_the_meta_engine(tmp_path):
    shutil.copy(REPO / "docs" / "up.ini.example", tmp_path / "up.ini")
    script = tmp_path / "scripts" / "check.py"
    script.parent.mkdir()
    script.write_text(
        textwrap.dedent(
            """
            from unified_planning.shortcuts import get_environment
            print(sorted(e for e in get_environment().factory.engines if e.startswith("relevance[")))
            """
        )
    )
    # UP looks for up.ini beside the script being run and in its parents.
    done = subprocess.run(
        [sys.executable, str(script)], cwd=tmp_path, capture_output=True, text=True, timeout=60, check=True
    )
    assert "'relevance[fast-downward]'" in done.stdout


def test_the_engine_derives_its_status_mappings_from_the_one_table():
    from relevance_plan.integrations.up_engine import up_status, up_verdict
    from relevance_plan.planning.planners.base import PlannerStatus
    from relevance_plan.planning.results import PlanStatus

    assert up_status(PlannerStatus.SOLVED) is Status.SOLVED_SATISFICING
    assert up_status(PlannerStatus.SEARCH_INCOMPLETE) is Status.UNSOLVABLE_INCOMPLETELY
    assert up_status(PlannerStatus.PLANNER_CRASH) is Status.INTERNAL_ERROR
    assert up_status(PlannerStatus.INPUT_ERROR) is Status.INTERNAL_ERROR
    expected = {
        PlanStatus.UNSOLVABLE: Status.UNSOLVABLE_PROVEN,
        PlanStatus.OUT_OF_TIME: Status.TIMEOUT,
        PlanStatus.OUT_OF_MEMORY: Status.MEMOUT,
        PlanStatus.UNSUPPORTED: Status.UNSUPPORTED_PROBLEM,
    }
    for verdict in PlanStatus:
        if verdict is not PlanStatus.SOLVED:
            assert up_verdict(verdict) is expected.get(verdict, Status.INTERNAL_ERROR), verdict
