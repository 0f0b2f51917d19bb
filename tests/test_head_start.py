"""The launcher's head start: Fast Downward on the full problem before the tool is imported."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import time

import pytest
from support import DOMAINS, TOOL, modules_after, write_file

from relevance_plan.planning.options import PlanOptions
from relevance_plan.planning.planners.fast_downward import head_start
from relevance_plan.planning.results import PlanStatus
from relevance_plan.planning.run import plan_task

GRIPPER = DOMAINS / "gripper" / "domain.pddl"
GRIPPER_PROBLEM = """(define (problem two-balls) (:domain gripper)
  (:objects rooma roomb ball1 ball2 left right)
  (:init (room rooma) (room roomb) (ball ball1) (ball ball2) (gripper left) (gripper right)
         (at-robby rooma) (at ball1 rooma) (at ball2 rooma) (free left) (free right))
  (:goal (and (at ball1 roomb) (at ball2 roomb))))
"""
HEAVY = ("click", "yaml", "unified_planning", "dask", "numpy", "matplotlib")
# What `plan` itself need not import: the heavy packages, and our modules for other commands.
NOT_FOR_PLAN = (
    "yaml", "unified_planning", "dask", "numpy", "matplotlib", "importlib.metadata",
    "relevance_plan.cli.batch", "relevance_plan.cli.watch",
)  # fmt: skip


@pytest.fixture
def gripper_problem(tmp_path):
    return write_file(tmp_path, "problem.pddl", GRIPPER_PROBLEM)


@pytest.mark.planner
def test_the_fast_path_imports_nothing_heavy(gripper_problem):
    # a fresh interpreter: what the launcher has imported when the driver is running
    modules = modules_after(
        "from relevance_plan.planning.planners.fast_downward import head_start",
        f"head_start.start_for_plan([{str(GRIPPER)!r}, {str(gripper_problem)!r}, '--method', 'pure'])",
        "assert head_start._PENDING, 'no head start'",
        then="head_start.discard_pending()\n",
    )
    assert not [m for m in modules if m.split(".")[0] in HEAVY]
    ours = {m for m in modules if m.startswith("relevance_plan")}
    assert not {
        m for m in ours if m.startswith(("relevance_plan.pddl", "relevance_plan.relevance", "relevance_plan.cli"))
    }
    assert not ours & {f"relevance_plan.planning.{name}" for name in ("options", "attempts", "run", "summary")}
    assert "dataclasses" not in modules  # its import (inspect, ast, ...) alone would delay the driver ~10 ms


@pytest.mark.planner
def test_plan_imports_only_what_it_uses_and_leaves_no_temporary_folder(gripper_problem, tmp_path):
    temporary = tmp_path / "tmp"
    temporary.mkdir()
    done = subprocess.run(
        [sys.executable, "-X", "importtime", *TOOL[1:], "plan", GRIPPER, gripper_problem, "--method", "pure", "-q"],
        capture_output=True,
        text=True,
        timeout=120,
        cwd=tmp_path,
        env={**os.environ, "TMPDIR": str(temporary)},
    )
    assert done.returncode == 0, done.stderr
    # -X importtime: one line on stderr per module imported, "import time: self | cumulative | name"
    modules = {line.rsplit("|", 1)[1].strip() for line in done.stderr.splitlines() if line.startswith("import time:")}
    assert "relevance_plan.planning.run" in modules  # the lines were read
    assert not [m for m in modules if m.startswith(NOT_FOR_PLAN)]
    # plan ends without the interpreter's teardown: its folders are gone all the same
    assert (tmp_path / "sas_plan").is_file() and not list(temporary.iterdir())


@pytest.mark.parametrize(
    ("extra", "wanted"),
    [
        (["--method", "pure"], True),
        (["--method=pure", "--timeout=30", "--memory-limit", "2000"], True),
        (["--race"], True),
        (["--no-race"], False),
        (["--method", "random", "--race"], False),
        (["--method", "pure", "--planner", "lpg"], False),
        (["--method", "pure", "--keep-work", "w"], False),
        (["--method", "pure", "--help"], False),
        (["--method", "pure", "--timeout", "soon"], False),
        (["--method", "pure", "--frobnicate"], False),
    ],
)
def test_what_the_launcher_reads_from_the_command_line(gripper_problem, extra, wanted):
    found = head_start._full_run_wanted([str(GRIPPER), str(gripper_problem), *extra])
    assert (found is not None) is wanted
    if "--timeout=30" in extra:
        assert found is not None and found[3] == 30.0 and found[4] == 2000


def test_the_launcher_s_option_table_is_plan_s():
    # the head start reads plan's command line without click: its table is generated from plan's options
    import click

    from relevance_plan.cli.app import plan
    from relevance_plan.limits import DEFAULT_TIMEOUT
    from relevance_plan.planning.planners.fast_downward import command_line

    options = [param for param in plan.params if isinstance(param, click.Option)]
    values = {name for param in options if not param.is_flag for name in (*param.opts, *param.secondary_opts)}
    flags = {name for param in options if param.is_flag for name in (*param.opts, *param.secondary_opts)}
    table = f"VALUE_OPTIONS = frozenset({sorted(values)})\nFLAGS = frozenset({sorted(flags)})"
    assert (head_start.VALUE_OPTIONS, head_start.FLAGS) == (values, flags), f"paste into head_start.py:\n{table}"
    defaults = {param.opts[0]: param.default for param in options}
    assert defaults["--method"] == head_start.DEFAULT_METHOD
    assert defaults["--planner"] == head_start.DEFAULT_PLANNER
    assert defaults["--planner-config"] == command_line.DEFAULT_CONFIG
    assert defaults["--timeout"] == DEFAULT_TIMEOUT


def test_a_temporal_domain_gets_no_head_start_under_auto(tmp_path):
    domain = DOMAINS / "coffee-temporal" / "domain.pddl"
    problem = write_file(tmp_path, "p.pddl", "(define (problem p) (:domain coffee-temporal))")
    assert head_start._full_run_wanted([str(domain), str(problem), "--method", "pure"]) is None
    # named explicitly, Fast Downward is what the user asked for
    assert head_start._full_run_wanted([str(domain), str(problem), "--method", "pure", "--planner", "fast-downward"])


@pytest.mark.planner
def test_the_full_problem_run_takes_the_head_start_over(gripper_problem):
    head_start.start_for_plan([str(GRIPPER), str(gripper_problem), "--method", "pure"])
    head = head_start._PENDING[-1]
    result = plan_task(GRIPPER, gripper_problem, PlanOptions(method="pure", timeout=60))
    assert result.status is PlanStatus.SOLVED and result.valid
    assert head.used and not os.path.exists(head.workdir)
    assert head_start.take() is None


@pytest.mark.planner
def test_a_head_start_that_does_not_match_is_stopped(gripper_problem):
    head_start.start_for_plan([str(GRIPPER), str(gripper_problem), "--method", "pure"])
    head = head_start._PENDING[-1]
    pgid = head.group.run.pgid
    result = plan_task(GRIPPER, gripper_problem, PlanOptions(method="pure", timeout=60, planner_config="ff-gbfs"))
    assert result.status is PlanStatus.SOLVED
    assert head.claimed and not head.used and not os.path.exists(head.workdir)
    assert not _running_in_group(pgid)


def _running_in_group(pgid: int) -> list[int]:
    """Processes of the group still running (an exited one may wait a moment to be reaped by init)."""
    from relevance_plan.supervision.guard import process_stats

    deadline = time.monotonic() + 3
    while True:
        running = [pid for pid, fields in process_stats() if int(fields[2]) == pgid and fields[0] not in (b"Z", b"X")]
        if not running or time.monotonic() > deadline:
            return running
        time.sleep(0.05)


@pytest.mark.planner
def test_plan_through_the_launcher_solves_and_leaves_nothing(gripper_problem, tmp_path):
    plan_file = tmp_path / "plan.txt"
    done = subprocess.run(
        [*TOOL, "plan", GRIPPER, gripper_problem, "--race", "--json", "--plan-file", plan_file],
        capture_output=True,
        text=True,
        timeout=120,
        cwd=tmp_path,
    )
    assert done.returncode == 0, done.stderr
    report = json.loads(done.stdout)
    assert report["status"] == "solved" and report["valid"] and plan_file.is_file()
    # a problem the tool cannot prune: the race's full run, started by the launcher, wins
    assert report["raced"] == "full"


@pytest.mark.planner
def test_a_bad_problem_still_gets_its_one_line_error(tmp_path):
    problem = write_file(tmp_path, "bad.pddl", "(define (problem p) (:domain gripper) (:objects a - nosuchtype))")
    done = subprocess.run(
        [*TOOL, "plan", GRIPPER, problem, "--method", "pure"], capture_output=True, text=True, timeout=60, cwd=tmp_path
    )
    assert done.returncode != 0 and "Traceback" not in done.stderr
    assert len(done.stderr.strip().splitlines()) == 1
