"""The lean stand-in for Fast Downward's driver: the same outcome as the driver, or the driver itself."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest
from support import SMALL_GRIPPER_DOMAIN, small_gripper_problem, write_file

from relevance_plan.planning.planners.base import PlannerStatus
from relevance_plan.planning.planners.fast_downward import adapter as fast_downward
from relevance_plan.planning.planners.fast_downward import command_line as fd_command
from relevance_plan.supervision import process

LEAN_MARK = "translate command line: "  # the lean driver's own line; the driver logs "INFO     Running translator."
DRIVER_MARK = "INFO     Running translator."


def _run(domain: Path, problem: Path, monkeypatch: pytest.MonkeyPatch, full: bool, **options):
    """The outcome and the whole log (kept in a work folder) of one run, by the lean or the full driver."""
    if full:
        monkeypatch.setenv(fd_command.FULL_DRIVER_ENV, "1")
    else:
        monkeypatch.delenv(fd_command.FULL_DRIVER_ENV, raising=False)
    work = domain.parent / f"work-{'full' if full else 'lean'}-{len(list(domain.parent.iterdir()))}"
    work.mkdir()
    outcome = fast_downward.run_fast_downward(domain, problem, time_limit=30, work_dir=str(work), **options)
    return outcome, (work / "planner.log").read_text()


@pytest.mark.planner
@pytest.mark.parametrize(
    ("problem_text", "config", "status", "code"),
    [
        (small_gripper_problem(), "lama-first", PlannerStatus.SOLVED, 0),
        (small_gripper_problem(), "astar(blind())", PlannerStatus.SOLVED, 0),
        (small_gripper_problem(free_gripper=False), "lama-first", PlannerStatus.UNSOLVABLE, 11),
        (small_gripper_problem().replace("(free left))", "(free left)"), "lama-first", PlannerStatus.INPUT_ERROR, 31),
        (small_gripper_problem(), "astar(no_such_heuristic())", PlannerStatus.PLANNER_CONFIG_ERROR, 33),
    ],
)
def test_the_lean_driver_ends_as_the_driver_does(tmp_path, monkeypatch, problem_text, config, status, code):
    domain = write_file(tmp_path, "domain.pddl", SMALL_GRIPPER_DOMAIN)
    problem = write_file(tmp_path, "p.pddl", problem_text)
    lean, lean_log = _run(domain, problem, monkeypatch, full=False, config=config)
    full, full_log = _run(domain, problem, monkeypatch, full=True, config=config)
    assert (lean.status, lean.exit_code) == (full.status, full.exit_code) == (status, code)
    assert [str(step) for step in lean.plan] == [str(step) for step in full.plan]
    assert LEAN_MARK in lean_log and DRIVER_MARK not in lean_log
    assert DRIVER_MARK in full_log


@pytest.mark.planner
@pytest.mark.parametrize("config", ["lama", "no-such-alias"])
def test_an_alias_only_the_driver_reads_goes_to_the_driver(tmp_path, monkeypatch, config):
    # seq-sat-lama-2011 (``lama``) needs the driver's --if-unit-cost; an unknown alias gets the driver's own error
    domain = write_file(tmp_path, "domain.pddl", SMALL_GRIPPER_DOMAIN)
    problem = write_file(tmp_path, "p.pddl", small_gripper_problem())
    outcome, log = _run(domain, problem, monkeypatch, full=False, config=config)
    if config == "lama":
        assert outcome.status is PlannerStatus.SOLVED and outcome.plan_cost == 3
        assert DRIVER_MARK in log
    else:
        assert outcome.exit_code == 36  # the driver's input error


@pytest.mark.planner
def test_driver_options_after_the_inputs_go_to_the_driver(tmp_path, monkeypatch):
    domain = write_file(tmp_path, "domain.pddl", SMALL_GRIPPER_DOMAIN)
    problem = write_file(tmp_path, "p.pddl", small_gripper_problem())
    extra = ("--translate-options", "--invariant-generation-max-candidates", "0")
    outcome, log = _run(domain, problem, monkeypatch, full=False, extra_arguments=extra)
    assert outcome.status is PlannerStatus.SOLVED
    assert DRIVER_MARK in log


@pytest.mark.planner
def test_the_intermediate_file_is_removed_unless_kept(tmp_path, monkeypatch):
    domain = write_file(tmp_path, "domain.pddl", SMALL_GRIPPER_DOMAIN)
    problem = write_file(tmp_path, "p.pddl", small_gripper_problem())
    outcome, log = _run(domain, problem, monkeypatch, full=False)  # a work folder: --keep-sas-file
    assert outcome.status is PlannerStatus.SOLVED and LEAN_MARK in log
    assert list(tmp_path.glob("work-*/output.sas"))
    workdir = tmp_path / "scratch"
    workdir.mkdir()
    command = fd_command.build_command(
        (sys.executable, str(fd_command.driver_location())), domain, problem, "lama-first", 30, None
    )
    run = process.run_process_group(
        fd_command.through_lean_driver(command), workdir, 60, what="Fast Downward", program=command[1]
    )
    assert run.exit_code == 0
    assert (workdir / "sas_plan").is_file() and not (workdir / "output.sas").exists()
