"""No process outlives the tool: a signal or kill -9 during plan, compare or generate stops every
planner process, removes the planner's scratch directory and leaves no half-written output."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
from support import COFFEE_DOMAIN, PROBLEMS, TOOL, one_line_error, run, running, write_file

from relevance_plan.exitcodes import ExitCode


def _session_processes(sid: int) -> list[int]:
    found = []
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                if os.getsid(int(entry)) == sid:
                    found.append(int(entry))
            except OSError:
                pass
    return found


def _guards(marker: str) -> list[int]:
    """The planner guards whose command line mentions ``marker`` (other runs may share /tmp)."""
    guards = []
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                command = Path(f"/proc/{entry}/cmdline").read_bytes()
            except OSError:
                continue
            if b"import guard" in command and marker.encode() in command:
                guards.append(int(entry))
    return guards


def _planner_processes(marker: str) -> list[int]:
    """Every process of the planner sessions of ``_guards(marker)``."""
    return [pid for guard in _guards(marker) for pid in _session_processes(guard)]


def _planner_workdirs(marker: str) -> list[Path]:
    return [Path(os.readlink(f"/proc/{guard}/cwd")) for guard in _guards(marker)]


@pytest.fixture(scope="module")
def long_problem(tmp_path_factory):
    """A problem pure planning needs several seconds for."""
    suite = tmp_path_factory.mktemp("long") / "suite"
    assert (
        run("generate", "coffee", "--difficulty", "hard", "--count", "1", "--distractors", "100", "--out", suite)[0]
        == 0
    )
    return suite / "domain.pddl", suite / "coffee-hard-001.pddl"


def _start_plan(long_problem, tmp_path):
    """The running tool and its planner's scratch directory."""
    domain, problem = long_problem
    marker = str(problem.parent)
    process = subprocess.Popen(
        TOOL + ["plan", str(domain), str(problem), "--method", "pure", "-q", "--plan-file", str(tmp_path / "plan")],
        start_new_session=True,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
    )
    deadline = time.monotonic() + 20
    while not _guards(marker) and time.monotonic() < deadline:
        time.sleep(0.1)
    time.sleep(1.0)  # the translator is running now
    assert process.poll() is None
    assert len(_planner_processes(marker)) >= 3, "guard, driver and a component"
    (workdir,) = _planner_workdirs(marker)
    assert workdir.name.startswith("relevance-plan-fd-") and workdir.is_dir()
    return process, workdir


def _interrupt(process: subprocess.Popen, signum: int, planners: list[int], workdir: Path, wait: float) -> None:
    """Send ``signum`` to the tool: it ends interrupted, in one line, its planners and working folder gone."""
    os.kill(process.pid, signum)
    _, stderr = process.communicate(timeout=wait)
    assert process.returncode == ExitCode.INTERRUPTED
    assert "interrupted" in one_line_error(stderr.decode())
    time.sleep(0.2)
    # Killed processes may stay zombies until init reaps them; none may still run.
    assert [p for p in _session_processes(process.pid) + planners if running(p)] == []
    assert not workdir.exists()


@pytest.mark.planner
@pytest.mark.parametrize("signum", [signal.SIGTERM, signal.SIGHUP, signal.SIGINT])
def test_a_signal_during_plan_stops_every_process_and_cleans_up(long_problem, tmp_path, signum):
    process, workdir = _start_plan(long_problem, tmp_path)
    planners = _planner_processes(str(long_problem[1].parent))
    assert planners
    _interrupt(process, signum, planners, workdir, wait=20)
    assert not (tmp_path / "plan").exists()


@pytest.mark.planner
def test_sighup_during_compare_stops_the_batch_and_its_planners(long_problem, tmp_path):
    suite = long_problem[1].parent
    store = tmp_path / "results.sqlite"
    process = subprocess.Popen(
        TOOL + ["compare", str(suite), "--methods", "pure", "--store", str(store), "-q"],
        start_new_session=True,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
    )
    marker = str(suite)
    deadline = time.monotonic() + 20
    while not _guards(marker) and time.monotonic() < deadline:
        time.sleep(0.1)
    time.sleep(0.5)
    planners = _planner_processes(marker)
    (workdir,) = _planner_workdirs(marker)
    assert planners
    _interrupt(process, signal.SIGHUP, planners, workdir, wait=40)


@pytest.mark.planner
def test_planners_die_with_the_tool_on_kill_9(long_problem, tmp_path):
    process, workdir = _start_plan(long_problem, tmp_path)
    planners = _planner_processes(str(long_problem[1].parent))
    assert planners
    os.kill(process.pid, signal.SIGKILL)
    process.wait(timeout=10)
    deadline = time.monotonic() + 2.0
    while [p for p in planners if running(p)] and time.monotonic() < deadline:
        time.sleep(0.05)
    assert [p for p in planners if running(p)] == [], "planners outlived the tool"
    while workdir.exists() and time.monotonic() < deadline + 2.0:
        time.sleep(0.05)
    assert not workdir.exists(), "the planner's scratch directory is removed too"


@pytest.mark.planner
def test_a_guard_killed_from_outside_ends_plan_at_once_as_a_planner_error(long_problem, tmp_path):
    process, workdir = _start_plan(long_problem, tmp_path)
    (guard,) = _guards(str(long_problem[1].parent))
    planners = _session_processes(guard)
    assert len(planners) >= 3, "guard, driver and a component"
    os.kill(guard, signal.SIGKILL)
    _, stderr = process.communicate(timeout=30)
    assert process.returncode == ExitCode.PLANNER
    assert "the planner's guard was killed (by SIGKILL)" in one_line_error(stderr.decode())
    assert [p for p in planners if running(p)] == [], "the driver or a component outlived its guard"
    assert not workdir.exists()
    assert not (tmp_path / "plan").exists()


def test_a_killed_guard_of_a_pruned_attempt_does_not_wait_for_the_race(tmp_path):
    """The full problem, planned beside the pruned attempt, would only end at the time limit."""
    sleeper = write_file(tmp_path, "sleeper.py", "import time\ntime.sleep(1000)\n")
    process = subprocess.Popen(
        [
            *TOOL,
            "plan",
            str(COFFEE_DOMAIN),
            str(PROBLEMS / "coffee-simple.pddl"),
            "--race",
            "--timeout",
            "300",
            "-q",
            "--planner",
            f"cmd:{sys.executable} {sleeper} {{domain}} {{problem}}",
        ],
        start_new_session=True,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
    )
    try:
        pruned: list[int] = []
        deadline = time.monotonic() + 30
        while not pruned and time.monotonic() < deadline:
            pruned = sorted(set(_guards(str(sleeper))) & set(_guards("pruned-")))
            time.sleep(0.05)
        assert pruned, "the pruned attempt never started"
        planners = _planner_processes(str(sleeper))
        os.kill(pruned[0], signal.SIGKILL)
        _, stderr = process.communicate(timeout=60)  # the time limit is 300 s
    finally:
        if process.poll() is None:
            os.killpg(process.pid, signal.SIGKILL)
            process.wait()
    assert process.returncode == ExitCode.PLANNER
    assert "guard was killed (by SIGKILL)" in one_line_error(stderr.decode())
    assert [p for p in planners if running(p)] == [], "a planner outlived the run"


def test_sigterm_during_generate_leaves_no_staging(tmp_path):
    process = subprocess.Popen(
        TOOL + ["generate", "coffee", "--count", "3000", "--distractors", "500", "--out", str(tmp_path / "suite")],
        start_new_session=True,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
    )
    deadline = time.monotonic() + 20
    while not list(tmp_path.iterdir()) and time.monotonic() < deadline:
        time.sleep(0.05)
    time.sleep(0.5)
    os.kill(process.pid, signal.SIGTERM)
    _, stderr = process.communicate(timeout=20)
    assert process.returncode == ExitCode.INTERRUPTED
    one_line_error(stderr.decode())
    assert list(tmp_path.iterdir()) == []
