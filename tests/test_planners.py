"""The planner registry: every adapter kind inside the one validated attempt loop."""

from __future__ import annotations

import stat
import sys
import textwrap
import time
from pathlib import Path

import pytest
from click.testing import CliRunner
from padded_worlds import GRIPPER_DOMAIN, gripper_problem
from support import running

from relevance_plan.cli import main
from relevance_plan.errors import PlannerError, UsageError
from relevance_plan.exitcodes import ExitCode
from relevance_plan.planning.loop import PlanOptions, PlanStatus, plan_task
from relevance_plan.planning.planners import (
    CommandPlanner,
    make_planner,
    parse_ipc_plan,
    split_planner_names,
)
from relevance_plan.planning.runner import PlannerStatus


@pytest.fixture
def coffee_extra_plates():
    """``coffee_files`` (conftest.py) with three extra plates."""
    return 3


@pytest.fixture
def gripper_files(tmp_path):
    domain = tmp_path / "gripper.pddl"
    domain.write_text(GRIPPER_DOMAIN)
    problem = tmp_path / "gripper-p.pddl"
    problem.write_text(gripper_problem(extra=6, rooms=3))
    return domain, problem


def script(tmp_path: Path, name: str, body: str) -> str:
    """An executable Python script standing in for an external planner."""
    path = tmp_path / name
    path.write_text(f"#!{sys.executable}\n" + textwrap.dedent(body))
    path.chmod(path.stat().st_mode | stat.S_IXUSR)
    return str(path)


# A planner that asks Fast Downward and prints its plan on stdout: a real plan from a foreign binary.
FD_ON_STDOUT = """
    import subprocess, sys, tempfile, os
    from relevance_plan.planning.runner import run_fast_downward
    outcome = run_fast_downward(sys.argv[1], sys.argv[2], time_limit=60)
    for step in outcome.plan:
        print(step)
    print("; a comment line")
"""


FD_TO_FILE = """
    import sys
    from relevance_plan.planning.runner import run_fast_downward
    outcome = run_fast_downward(sys.argv[1], sys.argv[2], time_limit=60)
    with open(sys.argv[3], "w") as out:
        out.write("; found by a planner writing to its plan file\\n")
        out.write("".join(str(step) + "\\n" for step in outcome.plan))
    print("planner chatter that is not a plan")
"""


# --------------------------------------------------------------------------- names


def test_planner_names_are_parsed_and_checked():
    assert make_planner("fast-downward").name == "fast-downward"
    assert make_planner("up:pyperplan").name == "up:pyperplan"
    assert make_planner("cmd:plan {domain} {problem}").name == "cmd:plan {domain} {problem}"
    for bad in ("nope", "fast-downward:x", "up:", "cmd:"):
        with pytest.raises(UsageError, match="unknown planner"):
            make_planner(bad)
    assert split_planner_names("fast-downward, up:pyperplan,cmd:p {domain},{problem}") == (
        "fast-downward",
        "up:pyperplan",
        "cmd:p {domain},{problem}",
    )


def test_command_templates_are_checked_before_running(tmp_path):
    with pytest.raises(UsageError, match=r"needs \{problem\}"):
        make_planner("cmd:true {domain}", check=True)
    with pytest.raises(UsageError, match="unknown placeholder"):
        make_planner("cmd:true {domain} {problem} {out}", check=True)
    with pytest.raises(PlannerError, match="not found: no-such-planner-binary"):
        make_planner("cmd:no-such-planner-binary {domain} {problem}", check=True)


def test_ipc_plans_are_parsed_and_garbage_is_refused():
    plan = parse_ipc_plan("(pick A b)\n; cost = 3 (unit cost)\n\n0: (drop a b) [1]\n")
    assert [str(step) for step in plan] == ["(pick a b)", "(drop a b)"] and plan.cost == 3
    assert parse_ipc_plan("Solution found!\n(pick a b)\n") is None


# --------------------------------------------------------------------------- cmd: inside the loop


@pytest.mark.planner
def test_external_command_plan_is_validated_on_the_original(tmp_path, coffee_files):
    domain, problem = coffee_files
    planner = "cmd:" + script(tmp_path, "fd-stdout", FD_ON_STDOUT) + " {domain} {problem}"
    result = plan_task(domain, problem, PlanOptions(planner=planner, timeout=60))
    assert result.status is PlanStatus.SOLVED, result.message
    assert result.valid and result.planner == planner
    assert result.objects_kept < result.objects_total


@pytest.mark.planner
def test_external_command_on_a_classic_problem_with_a_plan_file(tmp_path, gripper_files):
    domain, problem = gripper_files
    planner = "cmd:" + script(tmp_path, "fd-file", FD_TO_FILE) + " {domain} {problem} {plan}"
    result = plan_task(domain, problem, PlanOptions(planner=planner, timeout=60))
    assert result.status is PlanStatus.SOLVED, result.message
    assert result.valid and result.objects_kept < result.objects_total


@pytest.mark.planner
@pytest.mark.parametrize(
    "body, planner_status, plan_status",
    [
        ("print('I found it, trust me')\n", PlannerStatus.PLANNER_CRASH, PlanStatus.PLANNER_ERROR),
        ("import sys\nprint('segfault-ish')\nsys.exit(3)\n", PlannerStatus.PLANNER_CRASH, PlanStatus.PLANNER_ERROR),
        ("print('(serve alice nothing)')\n", PlannerStatus.SOLVED, PlanStatus.NO_VALID_PLAN),
    ],
)
def test_misbehaving_commands_get_the_right_outcome_and_the_loop_carries_on(
    tmp_path, coffee_files, body, planner_status, plan_status
):
    domain, problem = coffee_files
    planner = "cmd:" + script(tmp_path, "bad", body) + " {domain} {problem}"
    result = plan_task(domain, problem, PlanOptions(planner=planner, timeout=30))
    assert result.status is plan_status
    statuses = [a.outcome.status for a in result.attempts]
    assert set(statuses) == {planner_status}
    # the loop went on to the full problem rather than stopping at the pruned one
    assert len(result.attempts) >= 2 and result.attempts[-1].full
    if plan_status is PlanStatus.NO_VALID_PLAN:
        assert all(a.validation is not None and not a.validation.valid for a in result.attempts)


@pytest.mark.planner
def test_a_hanging_command_is_killed_with_its_children(tmp_path, coffee_files):
    domain, problem = coffee_files
    marker = tmp_path / "child.pid"
    body = f"""
    import subprocess, time
    child = subprocess.Popen(["sleep", "300"])
    open({str(marker)!r}, "w").write(str(child.pid))
    time.sleep(300)
    """
    planner = CommandPlanner(script(tmp_path, "hang", body) + " {domain} {problem}")
    outcome = planner.run(str(domain), str(problem), time_limit=2.0, memory_limit_mb=None)
    assert outcome.status is PlannerStatus.OUT_OF_TIME and outcome.killed_by_watchdog, outcome
    assert outcome.wall_time < 30
    assert marker.is_file(), outcome.log_tail
    child = int(marker.read_text())
    deadline = time.monotonic() + 5
    while running(child) and time.monotonic() < deadline:
        time.sleep(0.05)
    assert not running(child)  # the planner's own child died with its group


def test_plan_command_takes_a_planner_and_refuses_a_bad_one(tmp_path, coffee_files):
    domain, problem = coffee_files
    runner = CliRunner()
    bad = runner.invoke(main, ["plan", str(domain), str(problem), "--planner", "cmd:true {domain}"])
    assert bad.exit_code == ExitCode.USAGE
    assert bad.output.count("\n") == 1 and "needs {problem}" in bad.output
    missing = runner.invoke(main, ["plan", str(domain), str(problem), "--planner", "cmd:nope-bin {domain} {problem}"])
    assert missing.exit_code == ExitCode.PLANNER and "not found: nope-bin" in missing.output
    unknown = runner.invoke(main, ["plan", str(domain), str(problem), "--planner", "ff"])
    assert unknown.exit_code == ExitCode.USAGE and "unknown planner 'ff'" in unknown.output


# --------------------------------------------------------------------------- up:NAME


@pytest.mark.planner
@pytest.mark.parametrize("files", ["coffee_files", "gripper_files"])
def test_unified_planning_engine_in_a_child_process(request, files):
    pytest.importorskip("up_lpg")
    domain, problem = request.getfixturevalue(files)
    result = plan_task(domain, problem, PlanOptions(planner="up:lpg", timeout=120))
    assert result.status is PlanStatus.SOLVED, result.message
    assert result.valid and result.planner == "up:lpg"


@pytest.mark.planner
def test_pyperplan_solves_a_classic_problem_and_refuses_features_it_lacks(gripper_files, coffee_files):
    pytest.importorskip("up_pyperplan")
    domain, problem = gripper_files
    result = plan_task(domain, problem, PlanOptions(planner="up:pyperplan", timeout=120))
    assert result.status is PlanStatus.SOLVED, result.message
    assert result.valid
    # the coffee domain has negative preconditions, which pyperplan cannot take: one attempt, a clear verdict
    domain, problem = coffee_files
    refused = plan_task(domain, problem, PlanOptions(planner="up:pyperplan", timeout=120))
    assert refused.status is PlanStatus.UNSUPPORTED and len(refused.attempts) == 1


def test_an_engine_that_is_not_installed_names_the_extra():
    with pytest.raises(UsageError, match=r"relevance-plan\[planners\]"):
        make_planner("up:no-such-engine", check=True)


# --------------------------------------------------------------------------- compare --planners


@pytest.mark.planner
def test_compare_with_two_planners_resumes_and_reports_per_planner(tmp_path):
    pytest.importorskip("up_lpg")
    from relevance_plan.generators.generate import generate_suite

    suite = tmp_path / "coffee-simple"
    generate_suite("coffee", "simple", 1, 5, suite, distractors=3)
    store = tmp_path / "results.sqlite"
    arguments = [
        "compare",
        str(suite),
        "--methods",
        "pure,relevance",
        "--planners",
        "fast-downward,up:lpg",
        "--timeout",
        "120",
        "--store",
        str(store),
        "--quiet",
    ]
    runner = CliRunner()
    first = runner.invoke(main, arguments)
    assert first.exit_code == 0, first.output
    assert "4 jobs: 0 already stored, 4 run (4 solved)" in first.output
    again = runner.invoke(main, arguments)
    assert again.exit_code == 0 and "4 jobs: 4 already stored, 0 run" in again.output
    report = runner.invoke(main, ["report", str(store)])
    assert "coffee-simple [fast-downward]" in report.output and "coffee-simple [up:lpg]" in report.output
    bad = runner.invoke(main, ["compare", str(suite), "--planners", "fast-downward,nope", "--store", str(store)])
    assert bad.exit_code == ExitCode.USAGE and "unknown planner 'nope'" in bad.output
