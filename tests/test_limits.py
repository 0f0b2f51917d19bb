"""Limits: --timeout covers the whole run, too little memory is out of memory, deep nesting and
YAML alias bombs are refused at once, and absurd limit values are usage errors."""

from __future__ import annotations

import re
import subprocess
import sys
import time

import pytest
from support import COFFEE_DOMAIN, PROBLEMS, alias_bomb, coffee_problem, nested_goal, one_line_error, run

from relevance_plan.exitcodes import ExitCode

# --------------------------------------------------------------------------- time


def test_timeout_covers_reading_and_scoring(tmp_path):
    suite = tmp_path / "suite"
    assert run("generate", "coffee", "--count", "1", "--distractors", "20000", "--out", suite)[0] == 0
    started = time.monotonic()
    code, _, stderr = run(
        "plan",
        suite / "domain.pddl",
        suite / "coffee-simple-001.pddl",
        "-q",
        "--timeout",
        "0.05",
        "--plan-file",
        tmp_path / "plan",
    )
    assert code == ExitCode.OUT_OF_TIME
    line = one_line_error(stderr)
    # the deadline may stop a step (which says so) or the CLI's alarm may stop the run: one wording
    assert re.search(r"out of time (while|after) ", line) and "--timeout" in line, line
    assert time.monotonic() - started < 20  # the deadline is the behaviour: 0.05 s, bounded generously


# --------------------------------------------------------------------------- memory


@pytest.mark.planner
def test_too_little_memory_for_the_planner_is_out_of_memory(copied_coffee_files, tmp_path):
    domain, problem = copied_coffee_files
    for limit in ("16", "20"):
        code, _, stderr = run("plan", domain, problem, "-q", "--memory-limit", limit, "--plan-file", tmp_path / "p")
        assert code == ExitCode.OUT_OF_MEMORY, stderr
        one_line_error(stderr)


@pytest.mark.planner
def test_a_planner_that_dies_under_the_memory_limit_ran_out_of_memory_whatever_it_says(copied_coffee_files, tmp_path):
    """With its address space capped, a failed allocation can surface as any error (Fast Downward's
    translator has died of it with "SystemError: error return without exception set", exit 30)."""
    from support import planner_script

    domain, problem = copied_coffee_files
    for last_words, code in (("SystemError: error return without exception set", 30), ("Segmentation fault", -11)):
        body = f"import os, signal, sys\nprint({last_words!r}, flush=True)\n"
        body += "os.kill(os.getpid(), signal.SIGSEGV)\n" if code < 0 else f"sys.exit({code})\n"
        script = planner_script(tmp_path, "dying.py", body)
        plan = ["plan", domain, problem, "-q", "--no-race", "--method", "pure", "--plan-file", tmp_path / "p"]
        plan += ["--planner", f"cmd:{script} {{domain}} {{problem}}"]
        exit_code, _, stderr = run(*plan, "--memory-limit", "256")
        assert exit_code == ExitCode.OUT_OF_MEMORY and "--memory-limit" in one_line_error(stderr), stderr
        exit_code, _, stderr = run(*plan)  # no limit of the tool's: a crash is a crash
        assert exit_code == ExitCode.PLANNER, stderr


def test_memory_running_out_again_on_the_way_out_is_still_one_line(monkeypatch, copied_coffee_files, capfd):
    from relevance_plan.cli import exits
    from relevance_plan.pddl import parser

    def no_memory(*args, **kwargs):
        raise MemoryError

    leaving = []

    def drop_stdout_once_out_of_memory():
        leaving.append(True)
        if len(leaving) == 1:  # the command's own handler said the line; memory runs out again after
            raise MemoryError

    monkeypatch.setattr(parser, "_read_problem", no_memory)
    monkeypatch.setattr(exits, "_drop_stdout", drop_stdout_once_out_of_memory)
    monkeypatch.setattr(exits, "_said_out_of_memory", False)
    code, _, _ = run("score", *copied_coffee_files)
    assert code == ExitCode.OUT_OF_MEMORY
    assert "out of memory" in one_line_error(capfd.readouterr().err)  # said straight to the descriptor
    assert len(leaving) == 2  # the outer handler ran too, and kept quiet


def test_memory_running_out_as_a_system_error_is_out_of_memory(monkeypatch, copied_coffee_files, capfd):
    """Under ``ulimit -v`` a C function may fail an allocation without saying so; the interpreter then
    raises SystemError, not MemoryError.  Any other SystemError is not the tool's to explain."""
    from relevance_plan.cli import exits
    from relevance_plan.pddl import parser

    def silent_failure(*args, **kwargs):
        raise SystemError("<function score at 0x7f> returned NULL without setting an exception")

    monkeypatch.setattr(parser, "_read_problem", silent_failure)
    monkeypatch.setattr(exits, "_said_out_of_memory", False)
    code, _, _ = run("score", *copied_coffee_files)
    assert code == ExitCode.OUT_OF_MEMORY
    assert "out of memory" in one_line_error(capfd.readouterr().err)

    def bug(*args, **kwargs):
        raise SystemError("a bug")

    monkeypatch.setattr(parser, "_read_problem", bug)
    with pytest.raises(SystemError, match="a bug"):
        run("score", *copied_coffee_files)


def test_the_loaders_messages_are_out_of_memory():
    from relevance_plan.planning.planners.base import PlannerStatus
    from relevance_plan.planning.planners.fast_downward.adapter import classify as _classify

    log = "error while loading shared libraries: libc.so.6: failed to map segment from shared object"
    assert _classify(127, False, False, log, 0.0, 10.0, memory_limited=True) is PlannerStatus.OUT_OF_MEMORY
    assert _classify(120, False, False, "", 0.0, 10.0, memory_limited=True) is PlannerStatus.OUT_OF_MEMORY
    assert _classify(120, False, False, "", 0.0, 10.0, memory_limited=False) is PlannerStatus.PLANNER_CRASH
    # the translator out of memory before it could even print why (seen at a 16-20 MB limit)
    assert _classify(30, False, False, "lost sys.stderr", 0.0, 10.0, memory_limited=True) is PlannerStatus.OUT_OF_MEMORY
    assert (
        _classify(30, False, False, "lost sys.stderr", 0.0, 10.0, memory_limited=False) is PlannerStatus.PLANNER_CRASH
    )


# --------------------------------------------------------------------------- deep nesting


@pytest.mark.planner
def test_deep_nesting_is_exit_32_naming_file_and_line(copied_coffee_files, tmp_path):
    domain, _ = copied_coffee_files
    deep = tmp_path / "deep.pddl"
    deep.write_text(nested_goal(500))
    for command in ("score", "plan"):
        code, _, stderr = run(command, domain, deep, "-q" if command == "plan" else "--json")
        assert code == ExitCode.PDDL_SYNTAX
        assert f"{deep}:" in one_line_error(stderr) and "nested" in stderr
    fine = tmp_path / "fine.pddl"
    fine.write_text(nested_goal(100))
    assert run("plan", domain, fine, "-q", "--plan-file", tmp_path / "plan")[0] == 0


@pytest.mark.planner
def test_compare_records_a_deep_problem_as_an_input_error_and_carries_on(tmp_path):
    suite = tmp_path / "suite"
    suite.mkdir()
    (suite / "domain.pddl").write_bytes(COFFEE_DOMAIN.read_bytes())
    (suite / "a.pddl").write_text(nested_goal(500))
    (suite / "b.pddl").write_text(coffee_problem())
    store = tmp_path / "results.sqlite"
    code, stdout, _ = run("compare", suite, "--methods", "relevance", "--store", store, "-q")
    assert code == 0 and "1 input-error" in stdout and "1 solved" in stdout


# --------------------------------------------------------------------------- YAML alias bomb


def test_yaml_alias_bomb_is_exit_35_at_once(copied_coffee_files, tmp_path):
    domain, problem = copied_coffee_files
    bomb = tmp_path / "bomb.yaml"
    bomb.write_bytes(alias_bomb())
    started = time.monotonic()
    code, _, stderr = run("score", domain, problem, "--model", bomb)
    assert code == ExitCode.MODEL and "aliases" in one_line_error(stderr)
    assert time.monotonic() - started < 30  # unrefused, the bomb's expansion would not end at all


# --------------------------------------------------------------------------- absurd limits


@pytest.mark.parametrize(
    "option, value",
    [
        ("--timeout", "inf"),
        ("--timeout", "nan"),
        ("--timeout", "1e12"),
        ("--timeout", "-1"),
        ("--memory-limit", "10000000000000"),
        ("--memory-limit", "-5"),
    ],
)
def test_absurd_limits_are_exit_30(copied_coffee_files, tmp_path, option, value):
    domain, problem = copied_coffee_files
    code, _, stderr = run("plan", domain, problem, "-q", option, value, "--plan-file", tmp_path / "plan")
    assert code == ExitCode.USAGE
    one_line_error(stderr)
    store = tmp_path / "results.sqlite"
    suite = tmp_path / "suite"
    suite.mkdir()
    (suite / "domain.pddl").write_bytes(domain.read_bytes())
    (suite / "p.pddl").write_bytes(problem.read_bytes())
    code, _, stderr = run("compare", suite, "--store", store, option, value, "-q")
    assert code == ExitCode.USAGE
    one_line_error(stderr)
    assert not store.exists()


def test_the_backstop_past_the_timeout_reports_like_any_result(monkeypatch, copied_coffee_files, tmp_path):
    """When a step overruns --timeout by more than the slack, the alarm stops it and the run still
    ends with an out-of-time result: one line, or with --json one JSON object."""
    import json

    import relevance_plan.cli.app as app

    def overrunning(*args, **kwargs):
        time.sleep(30)

    monkeypatch.setattr(app, "plan_task", overrunning)
    domain, problem = copied_coffee_files
    started = time.monotonic()
    code, stdout, stderr = run("plan", domain, problem, "--json", "--timeout", "0.1", "--plan-file", tmp_path / "p")
    assert code == ExitCode.OUT_OF_TIME, stderr
    data = json.loads(stdout)
    assert data["status"] == "out-of-time" and "--timeout ran out" in data["message"]
    code, _, stderr = run("plan", domain, problem, "-q", "--timeout", "0.1", "--plan-file", tmp_path / "p")
    assert code == ExitCode.OUT_OF_TIME
    assert "--timeout ran out" in one_line_error(stderr)
    assert time.monotonic() - started < 10  # the deadline is the behaviour: 0.1 s against a 30 s stall
    assert not (tmp_path / "p").exists()


# --------------------------------------------------------------------------- the analyses' own deadline


def test_a_task_past_its_deadline_stops_every_analysis_naming_the_step(copied_coffee_files):
    """The reading is fast enough now that a big problem's scoring starts before --timeout runs out:
    the task carries the deadline, and the index, the regression, the scene, the scorers and the
    pruning each stop at it rather than run on until the CLI's last alarm."""
    from relevance_plan.errors import OutOfTimeError
    from relevance_plan.io import load_task
    from relevance_plan.relevance.analysis.facts import index_init
    from relevance_plan.relevance.analysis.goal_regression import analyse_goal
    from relevance_plan.relevance.analysis.task import PlanningTask
    from relevance_plan.relevance.scoring.scene import build_scene
    from relevance_plan.relevance.setup import ScoringOptions, score_problem

    domain, problem = load_task(*copied_coffee_files)
    past = time.monotonic() - 1
    for step, call in [
        ("indexing the initial facts", lambda: index_init(problem, past)),
        ("regressing the goal", lambda: analyse_goal(domain, problem, None, past)),
        ("describing the scene", lambda: build_scene(domain, problem.objects, problem.init, deadline=past)),
        (
            "scoring the objects",
            lambda: score_problem(PlanningTask(domain, problem, deadline=past), ScoringOptions()),
        ),
    ]:
        with pytest.raises(OutOfTimeError, match=step):
            call()
    scoring = score_problem(PlanningTask(domain, problem, deadline=time.monotonic() + 60), ScoringOptions())
    assert scoring.first_selection().kept  # in time: the same analyses run to the end
    late = score_problem(PlanningTask(domain, problem), ScoringOptions())
    object.__setattr__(late.task, "deadline", past)  # the deadline passes between scoring and pruning
    with pytest.raises(OutOfTimeError, match="out of time while"):
        late.first_selection()


@pytest.mark.planner
@pytest.mark.parametrize("step", ["scoring", "pruning and closure", "widening"])
def test_a_deadline_passing_inside_a_step_ends_the_run_as_out_of_time(monkeypatch, copied_coffee_files, step):
    from relevance_plan.errors import OutOfTimeError
    from relevance_plan.planning import attempts, run
    from relevance_plan.planning.options import PlanOptions
    from relevance_plan.planning.results import PlanStatus
    from relevance_plan.planning.run import plan_task
    from relevance_plan.relevance.selection.prune import Thresholds
    from relevance_plan.relevance.setup import Scoring

    def out_of_time(*args, **kwargs):
        raise OutOfTimeError("out of time while doing it (the --timeout ran out)")

    if step == "scoring":
        monkeypatch.setattr(run, "score_problem", out_of_time)
    elif step == "pruning and closure":
        monkeypatch.setattr(Scoring, "first_selection", out_of_time)
    else:
        monkeypatch.setattr(attempts, "widen", out_of_time)
    strict = Thresholds(0.2, 0.85)  # drops the whitener and the stirrer: the first attempt fails
    options = PlanOptions(timeout=60, race=False, thresholds=strict) if step == "widening" else PlanOptions(timeout=60)
    result = plan_task(*copied_coffee_files, options)
    if step == "widening":  # the widening runs out after the failed first attempt: the run stops there
        assert result.first_attempt_status == "unsolvable" and len(result.attempts) == 1
        assert result.status is not PlanStatus.SOLVED
    else:
        assert result.status is PlanStatus.OUT_OF_TIME and f"out of time while {step}" in result.message


def test_a_short_run_gets_a_short_grace():
    from relevance_plan.supervision.process import DEFAULT_WATCHDOG_GRACE, watchdog_deadline

    assert watchdog_deadline(None) is None
    assert watchdog_deadline(0.3) == pytest.approx(0.375)  # the last 0.3 s of a --timeout: done by 0.375 s
    assert watchdog_deadline(10.0) == pytest.approx(10.0 + DEFAULT_WATCHDOG_GRACE)
    assert watchdog_deadline(10.0, 2.0) == pytest.approx(12.0)


# --------------------------------------------------------------------------- open files

# The tool under a limit of 16 open files, with a descriptor its parent left open above that limit
# (as a shell's `ulimit -n 16` leaves one of its own parent's): then exec'd, as the shell would.
_UNDER_16_OPEN_FILES = (
    "import os, resource, sys\n"
    "os.dup2(0, 20)\nos.set_inheritable(20, True)\n"
    "resource.setrlimit(resource.RLIMIT_NOFILE, (16, 16))\n"
    "os.execv(sys.executable, [sys.executable, '-m', 'relevance_plan', *sys.argv[1:]])\n"
)


def _plan_under_16_open_files(tmp_path, *arguments: str) -> subprocess.CompletedProcess:
    problem = PROBLEMS / "coffee-simple.pddl"
    command = [sys.executable, "-c", _UNDER_16_OPEN_FILES, "plan", str(COFFEE_DOMAIN), str(problem), "-q"]
    command += ["--timeout", "60", "--plan-file", str(tmp_path / "plan"), *arguments]
    return subprocess.run(command, stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=120)


@pytest.mark.planner
@pytest.mark.parametrize("method", ["pure", "relevance"])
def test_plan_starts_fast_downward_under_a_limit_of_16_open_files(tmp_path, method):
    done = _plan_under_16_open_files(tmp_path, "--method", method)
    assert done.returncode == 0, done.stderr
    assert (tmp_path / "plan").read_text().strip()


def test_the_planner_does_not_inherit_a_descriptor_left_open_above_the_limit(tmp_path):
    probe = tmp_path / "probe.py"
    probe.write_text(
        "import os\ntry:\n    os.fstat(20)\n    print('fd 20 open')\nexcept OSError:\n    print('fd 20 closed')\n"
    )
    done = _plan_under_16_open_files(
        tmp_path, "--method", "pure", "--planner", f"cmd:{sys.executable} {probe} {{domain}} {{problem}}"
    )
    assert done.returncode == ExitCode.PLANNER  # its output is no plan
    assert "fd 20 closed" in one_line_error(done.stderr)
