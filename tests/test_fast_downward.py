"""The Fast Downward adapter: its command line, exit codes, plan files and limits; real runs on tiny files."""

from __future__ import annotations

import os
import runpy
import signal
from pathlib import Path

import pytest
from support import (
    BIG_DOMAIN,
    SMALL_GRIPPER_DOMAIN,
    assert_session_gone,
    big_problem,
    small_gripper_problem,
    write_file,
)

from relevance_plan import errors
from relevance_plan.planning.planners.base import PlannerStatus
from relevance_plan.planning.planners.fast_downward import adapter as fast_downward
from relevance_plan.planning.planners.fast_downward import command_line as fd_command
from relevance_plan.supervision import process


@pytest.fixture
def gripper(tmp_path: Path) -> tuple[Path, Path]:
    return write_file(tmp_path, "domain.pddl", SMALL_GRIPPER_DOMAIN), write_file(
        tmp_path, "p.pddl", small_gripper_problem()
    )


@pytest.fixture
def big40(tmp_path: Path) -> tuple[Path, Path]:
    return write_file(tmp_path, "big.pddl", BIG_DOMAIN), write_file(tmp_path, "big40.pddl", big_problem(40))


def test_planner_arguments() -> None:
    assert fast_downward.planner_arguments("lama-first") == ("--alias", "lama-first")
    assert fast_downward.planner_arguments("lama") == ("--alias", "seq-sat-lama-2011")
    assert fast_downward.planner_arguments("astar(lmcut())") == ("--search", "astar(lmcut())")
    assert fast_downward.planner_arguments("seq-opt-lmcut") == ("--alias", "seq-opt-lmcut")
    for name in ("lama-first", "lama", "ff-gbfs", "astar-lmcut", "astar-blind"):
        assert name in fast_downward.PLANNER_CONFIGS
    with pytest.raises(errors.UsageError):
        fast_downward.planner_arguments(" ")


def test_command_puts_driver_options_before_files_and_search_after(tmp_path: Path) -> None:
    domain, problem = tmp_path / "d.pddl", tmp_path / "p.pddl"
    command = fd_command.build_command(("py", "fd.py"), domain, problem, "ff-gbfs", 9.2, 100)
    assert command[:8] == [
        "py",
        "fd.py",
        "--plan-file",
        "sas_plan",
        "--overall-time-limit",
        "10s",
        "--overall-memory-limit",
        "100M",
    ]
    assert command[8:10] == [str(domain), str(problem)]
    assert command[10:] == list(fast_downward.PLANNER_CONFIGS["ff-gbfs"])
    command = fd_command.build_command(("py", "fd.py"), domain, problem, "lama", None, None)
    assert command[2:] == ["--plan-file", "sas_plan", "--alias", "seq-sat-lama-2011", str(domain), str(problem)]


@pytest.mark.planner  # reads Fast Downward's own exit-code table: needs the planner installed
def test_exit_code_table_matches_driver_returncodes() -> None:
    codes = runpy.run_path(str(fast_downward.find_fast_downward().parent / "driver" / "returncodes.py"))
    expected = {
        "SUCCESS": PlannerStatus.SOLVED,
        "TRANSLATE_UNSOLVABLE": PlannerStatus.UNSOLVABLE,
        "SEARCH_UNSOLVABLE": PlannerStatus.UNSOLVABLE,
        "SEARCH_UNSOLVED_INCOMPLETE": PlannerStatus.SEARCH_INCOMPLETE,
        "TRANSLATE_OUT_OF_MEMORY": PlannerStatus.OUT_OF_MEMORY,
        "SEARCH_OUT_OF_MEMORY": PlannerStatus.OUT_OF_MEMORY,
        "TRANSLATE_OUT_OF_TIME": PlannerStatus.OUT_OF_TIME,
        "SEARCH_OUT_OF_TIME": PlannerStatus.OUT_OF_TIME,
        "SEARCH_OUT_OF_MEMORY_AND_TIME": PlannerStatus.OUT_OF_TIME,
        "TRANSLATE_CRITICAL_ERROR": PlannerStatus.PLANNER_CRASH,
        "TRANSLATE_INPUT_ERROR": PlannerStatus.INPUT_ERROR,
        "SEARCH_CRITICAL_ERROR": PlannerStatus.PLANNER_CRASH,
        "SEARCH_INPUT_ERROR": PlannerStatus.PLANNER_CONFIG_ERROR,
        "SEARCH_UNSUPPORTED": PlannerStatus.UNSUPPORTED,
        "DRIVER_CRITICAL_ERROR": PlannerStatus.PLANNER_CRASH,
        "DRIVER_INPUT_ERROR": PlannerStatus.PLANNER_CONFIG_ERROR,
        "DRIVER_UNSUPPORTED": PlannerStatus.UNSUPPORTED,
    }
    for name, status in expected.items():
        assert fast_downward.EXIT_CODES[codes[name]][1] is status, name
    # Every code of the driver is in the table under the driver's own name; 2 without a plan
    # is argparse's usage error (with a plan the run is solved before the table is read).
    driver_codes = {value: name for name, value in codes.items() if name.isupper() and isinstance(value, int)}
    for code, name in driver_codes.items():
        if name != "SEARCH_PLAN_FOUND_AND_OUT_OF_TIME":
            assert fast_downward.EXIT_CODES[code][0] == name, code
    assert fast_downward.EXIT_CODES[2] == ("USAGE_ERROR", PlannerStatus.PLANNER_CONFIG_ERROR)


def test_classify_splits_translator_critical_error_by_log() -> None:
    def classify(code: int, log: str = "", has_plan: bool = False) -> PlannerStatus:
        return fast_downward.classify(code, has_plan, False, log, 0.1, None)

    assert classify(30, "Error: Could not read file: x.pddl") is PlannerStatus.INPUT_ERROR
    assert classify(30, "MemoryError") is PlannerStatus.OUT_OF_MEMORY
    assert classify(30, "Traceback ... AssertionError") is PlannerStatus.PLANNER_CRASH
    assert classify(0) is PlannerStatus.PLANNER_CRASH  # success without a plan file
    assert classify(23, has_plan=True) is PlannerStatus.SOLVED  # anytime run hit its limit
    assert classify(-signal.SIGSEGV) is PlannerStatus.PLANNER_CRASH
    assert classify(99) is PlannerStatus.PLANNER_CRASH


def test_read_plans_skips_an_anytime_plan_cut_off_mid_write(tmp_path: Path) -> None:
    write_file(tmp_path, "sas_plan.2", "(A X)\n(B Y)\n; cost = 2 (unit cost)\n")
    write_file(tmp_path, "sas_plan.10", "(c z)\n; cost = 1 (unit cost)\n")
    write_file(tmp_path, "sas_plan.11", "(d z)\n")  # cut off by a kill mid-write
    plans, numbered = fast_downward.read_plans(tmp_path)
    assert numbered and [[str(step) for step in plan] for plan in plans] == [["(a x)", "(b y)"], ["(c z)"]]
    assert plans[-1].cost == 1
    empty = tmp_path / "empty"
    empty.mkdir()
    assert fast_downward.read_plans(empty) == ((), False)


def test_driver_override_and_missing_driver(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    fake = write_file(tmp_path, "fd.py", "")
    monkeypatch.setenv(fast_downward.FAST_DOWNWARD_ENV, str(fake))
    assert fast_downward.find_fast_downward() == fake.resolve()
    monkeypatch.setenv(fast_downward.FAST_DOWNWARD_ENV, str(tmp_path / "nowhere.py"))
    with pytest.raises(errors.PlannerError):
        fast_downward.find_fast_downward()
    monkeypatch.delenv(fast_downward.FAST_DOWNWARD_ENV)
    assert fast_downward.find_fast_downward().name == "fast-downward.py"
    assert fast_downward.fast_downward_version()


def test_missing_file_raises_before_starting(gripper: tuple[Path, Path], tmp_path: Path) -> None:
    domain, _ = gripper
    with pytest.raises(errors.InputFileError):
        fast_downward.run_fast_downward(domain, tmp_path / "missing.pddl")
    with pytest.raises(errors.InputFileError):
        fast_downward.run_fast_downward(tmp_path / "missing.pddl", domain)


def test_unstartable_interpreter(gripper: tuple[Path, Path], tmp_path: Path) -> None:
    with pytest.raises(errors.PlannerError):
        fast_downward.run_fast_downward(
            *gripper, process=fast_downward.DriverProcess(python=str(tmp_path / "no-python"))
        )


def test_bad_limits(gripper: tuple[Path, Path]) -> None:
    with pytest.raises(errors.UsageError):
        fast_downward.run_fast_downward(*gripper, time_limit=0)
    with pytest.raises(errors.UsageError):
        fast_downward.run_fast_downward(*gripper, memory_limit_mb=-1)


# --- real planner runs -----------------------------------------------------------


@pytest.mark.planner
def test_solved(gripper: tuple[Path, Path]) -> None:
    cwd = os.getcwd()
    outcome = fast_downward.run_fast_downward(*gripper, time_limit=30)
    assert os.getcwd() == cwd
    assert outcome.status is PlannerStatus.SOLVED and outcome.solved
    assert outcome.exit_code == 0
    assert [str(step) for step in outcome.plan] == [
        "(pick ball1 rooma left)",
        "(move rooma roomb)",
        "(drop ball1 roomb left)",
    ]
    assert outcome.plan_cost == 3
    assert outcome.wall_time > 0 and outcome.cpu_time > 0 and outcome.peak_memory_mb > 0
    assert outcome.translate_time is not None and outcome.translate_time > 0
    assert outcome.search_time is not None and outcome.search_time >= 0
    assert outcome.config == "lama-first" and not outcome.killed_by_watchdog
    assert "search exit code: 0" in outcome.log_tail
    assert len(outcome.log_tail.splitlines()) <= process.LOG_TAIL_LINES


@pytest.mark.planner
@pytest.mark.parametrize("config", ["lama", "ff-gbfs", "astar-lmcut", "astar-blind", "astar(blind())"])
def test_other_configs(gripper: tuple[Path, Path], config: str) -> None:
    outcome = fast_downward.run_fast_downward(*gripper, config=config, time_limit=30)
    assert outcome.status is PlannerStatus.SOLVED, outcome.log_tail
    assert len(outcome.plan) == 3 and outcome.plan_cost == 3


@pytest.mark.planner
def test_unsolvable(tmp_path: Path) -> None:
    domain = write_file(tmp_path, "domain.pddl", SMALL_GRIPPER_DOMAIN)
    problem = write_file(tmp_path, "p.pddl", small_gripper_problem(free_gripper=False))
    outcome = fast_downward.run_fast_downward(domain, problem, time_limit=30)
    assert outcome.status is PlannerStatus.UNSOLVABLE
    assert outcome.exit_code == 11 and not outcome.plan.steps and outcome.plan_cost is None


@pytest.mark.planner
def test_syntax_error_is_input_error(tmp_path: Path) -> None:
    domain = write_file(tmp_path, "domain.pddl", SMALL_GRIPPER_DOMAIN)
    problem = write_file(tmp_path, "p.pddl", small_gripper_problem().replace("(free left))", "(free left)"))
    outcome = fast_downward.run_fast_downward(domain, problem, time_limit=30)
    assert outcome.status is PlannerStatus.INPUT_ERROR
    assert outcome.exit_code == 31


@pytest.mark.planner
@pytest.mark.parametrize("config, code", [("no-such-alias", 36), ("astar(no_such_heuristic())", 33)])
def test_bad_config_is_a_config_error(gripper: tuple[Path, Path], config: str, code: int) -> None:
    outcome = fast_downward.run_fast_downward(*gripper, config=config, time_limit=30)
    assert outcome.status is PlannerStatus.PLANNER_CONFIG_ERROR
    assert outcome.exit_code == code
    assert outcome.reason.startswith(f"Fast Downward exit code {code}: ")


@pytest.mark.planner
@pytest.mark.parametrize("time_limit", [1, 2])
def test_out_of_time(big40: tuple[Path, Path], time_limit: int) -> None:
    # Unlimited, translating big40 takes ~5.5 s.  The driver's CPU limit is the time limit plus
    # DRIVER_CPU_SLACK: the translator runs out of it (exit 21, or SIGXCPU).
    # A long grace: this is about the driver's own limit, which the watchdog must not pre-empt on a busy machine.
    outcome = fast_downward.run_fast_downward(
        *big40, time_limit=time_limit, process=fast_downward.DriverProcess(watchdog_grace=5.0)
    )
    assert outcome.status is PlannerStatus.OUT_OF_TIME
    assert outcome.exit_code in (21, -signal.SIGXCPU)
    assert outcome.cpu_time < time_limit + fast_downward.DRIVER_CPU_SLACK + 1.0
    assert not outcome.killed_by_watchdog  # the driver's own limit ended it
    assert_session_gone(outcome.process_group)


@pytest.mark.planner
def test_a_one_second_limit_leaves_the_search_its_time(gripper: tuple[Path, Path]) -> None:
    # the driver counts its own start and the translator against its limit: held to 1 s of CPU,
    # it gave the search nothing left (exit 23 at once), so a short attempt could never succeed
    outcome = fast_downward.run_fast_downward(*gripper, time_limit=1)
    assert outcome.status is PlannerStatus.SOLVED, outcome.reason


@pytest.mark.planner
def test_out_of_memory(tmp_path: Path) -> None:
    domain = write_file(tmp_path, "big.pddl", BIG_DOMAIN)
    problem = write_file(tmp_path, "big30.pddl", big_problem(30))  # needs ~125 MB
    outcome = fast_downward.run_fast_downward(domain, problem, time_limit=20, memory_limit_mb=80)
    assert outcome.status is PlannerStatus.OUT_OF_MEMORY, outcome.log_tail
    assert outcome.exit_code == 20


# --------------------------------------------------------------------------- (either ...) types

EITHER_DOMAIN = """(define (domain gadgets)
  (:requirements :strips :typing)
  (:types item gadget place)
  (:predicates (at ?x - (either item gadget) ?p - place) (held ?x - (either item gadget)) (free))
  (:action pick :parameters (?x - {parameter} ?p - place)
    :precondition (and (at ?x ?p) (free))
    :effect (and (held ?x) (not (at ?x ?p)) (not (free)))))
"""
EITHER_PROBLEM = """(define (problem g1) (:domain gadgets)
  (:objects box - {object} phone - gadget room - place)
  (:init (at box room) (at phone room) (free))
  (:goal (held phone)))
"""
EITHER_CASES = {
    "parameter": dict(parameter="(either item gadget)", object="item"),
    "object": dict(parameter="object", object="(either item gadget)"),
}


def _either_files(tmp_path: Path, where: str) -> tuple[Path, Path]:
    case = EITHER_CASES.get(where, dict(parameter="object", object="item"))
    return (
        write_file(tmp_path, "domain.pddl", EITHER_DOMAIN.format(**case)),
        write_file(tmp_path, "p.pddl", EITHER_PROBLEM.format(**case)),
    )


def test_the_translators_refusal_of_legal_pddl_is_unsupported_not_malformed() -> None:
    def classify(log: str) -> PlannerStatus:
        return fast_downward.classify(31, False, False, log, 0.1, None)

    assert classify("Type value is expected to be a single word.\n") is PlannerStatus.UNSUPPORTED
    assert classify("Fractional numbers are not supported.\n") is PlannerStatus.UNSUPPORTED
    assert classify("Expected ')' but found end of file\n") is PlannerStatus.INPUT_ERROR


@pytest.mark.parametrize("where", EITHER_CASES)
def test_fast_downward_refuses_an_either_type_it_cannot_read_before_planning(tmp_path: Path, where: str) -> None:
    from relevance_plan.io import load_task

    domain, problem = load_task(*_either_files(tmp_path, where))
    feature = "either-types" if where == "parameter" else "either-object-types"
    with pytest.raises(errors.UnsupportedFeatureError, match=f"Fast Downward does not take {feature}") as refused:
        fast_downward.FastDownwardPlanner().check(domain, problem)
    assert refused.value.path == str(tmp_path / ("domain.pddl" if where == "parameter" else "p.pddl"))


@pytest.mark.planner
@pytest.mark.parametrize("where", EITHER_CASES)
def test_the_translator_given_an_either_type_says_unsupported(tmp_path: Path, where: str) -> None:
    outcome = fast_downward.run_fast_downward(*_either_files(tmp_path, where), time_limit=30)
    assert outcome.exit_code == 31 and outcome.status is PlannerStatus.UNSUPPORTED, outcome.log_tail


@pytest.mark.planner
def test_an_either_type_among_a_predicates_parameters_is_fast_downwards_to_plan(tmp_path: Path) -> None:
    from relevance_plan.io import load_task

    files = _either_files(tmp_path, "predicates only")
    fast_downward.FastDownwardPlanner().check(*load_task(*files))  # it takes them
    assert fast_downward.run_fast_downward(*files, time_limit=30).status is PlannerStatus.SOLVED
