"""Process supervision (relevance_plan/supervision/): the watchdog, interrupts, parallel runs, terminating every
run, what the planner inherits and its memory limit; real Fast Downward runs on tiny files."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import tempfile
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest
from support import (
    BIG_DOMAIN,
    COFFEE_DOMAIN,
    PROBLEMS,
    SMALL_GRIPPER_DOMAIN,
    TOOL,
    assert_session_gone,
    big_problem,
    process_gone,
    small_gripper_problem,
    write_file,
)

from relevance_plan.planning.planners.base import PlannerStatus
from relevance_plan.planning.planners.fast_downward import adapter as fast_downward
from relevance_plan.supervision import guard, process, spawn


@pytest.fixture
def big40(tmp_path: Path) -> tuple[Path, Path]:
    return write_file(tmp_path, "big.pddl", BIG_DOMAIN), write_file(tmp_path, "big40.pddl", big_problem(40))


@pytest.mark.planner
def test_watchdog_kills_whole_process_group(big40: tuple[Path, Path]) -> None:
    outcome = fast_downward.run_fast_downward(
        *big40, time_limit=1, process=fast_downward.DriverProcess(driver_limits=False, watchdog_grace=0.5)
    )
    assert outcome.killed_by_watchdog
    assert outcome.status is PlannerStatus.OUT_OF_TIME
    assert outcome.exit_code == -signal.SIGKILL
    assert outcome.wall_time > 1.4  # not before the limit and its grace; the kill itself is the behaviour
    assert_session_gone(outcome.process_group)


@pytest.mark.planner
def test_keyboard_interrupt_kills_process_group(big40: tuple[Path, Path], monkeypatch: pytest.MonkeyPatch) -> None:
    started: list[int] = []
    start_guarded = spawn.start_guarded

    def recording(*args, **kwargs):  # type: ignore[no-untyped-def]
        spawned = start_guarded(*args, **kwargs)
        started.append(spawned.pid)
        return spawned

    monkeypatch.setattr(spawn, "start_guarded", recording)
    # A shell's background job inherits SIGINT ignored; install Python's default.
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    interrupt = threading.Timer(0.7, os.kill, (os.getpid(), signal.SIGINT))
    interrupt.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            fast_downward.run_fast_downward(*big40, time_limit=30)
    finally:
        interrupt.cancel()
        signal.signal(signal.SIGINT, previous)
    assert len(started) == 1
    assert_session_gone(started[0])


@pytest.mark.planner
def test_parallel_runs_from_threads(tmp_path: Path) -> None:
    domain = write_file(tmp_path, "domain.pddl", SMALL_GRIPPER_DOMAIN)
    problems = {
        "to_b": write_file(tmp_path, "b.pddl", small_gripper_problem("roomb")),
        "to_c": write_file(tmp_path, "c.pddl", small_gripper_problem("roomc")),
        "stuck1": write_file(tmp_path, "s1.pddl", small_gripper_problem("roomb", free_gripper=False)),
        "stuck2": write_file(tmp_path, "s2.pddl", small_gripper_problem("roomc", free_gripper=False)),
    }
    with ThreadPoolExecutor(max_workers=4) as pool:
        futures = {
            name: pool.submit(fast_downward.run_fast_downward, domain, problem, time_limit=30)
            for name, problem in problems.items()
        }
        outcomes = {name: future.result() for name, future in futures.items()}
    assert str(outcomes["to_b"].plan.steps[-1]) == "(drop ball1 roomb left)"
    assert str(outcomes["to_c"].plan.steps[-1]) == "(drop ball1 roomc left)"
    assert outcomes["stuck1"].status is PlannerStatus.UNSOLVABLE
    assert outcomes["stuck2"].status is PlannerStatus.UNSOLVABLE
    assert len({outcome.process_group for outcome in outcomes.values()}) == 4


@pytest.mark.planner
def test_terminate_all_runs_stops_every_running_planner(big40: tuple[Path, Path]) -> None:
    """Batch Ctrl-C: every planner started from threads is killed, none survives."""
    import threading

    domain, problem = big40
    outcomes = []
    threads = [
        threading.Thread(
            target=lambda: outcomes.append(fast_downward.run_fast_downward(domain, problem, time_limit=60))
        )
        for _ in range(2)
    ]
    for thread in threads:
        thread.start()
    deadline = time.monotonic() + 20
    while time.monotonic() < deadline and len(process._ACTIVE_GROUPS) < 2:
        time.sleep(0.05)
    assert process.terminate_all_runs() == 2
    for thread in threads:
        thread.join(30)
    assert len(outcomes) == 2
    assert all(not o.solved for o in outcomes)
    assert not process._ACTIVE_GROUPS
    for outcome in outcomes:
        assert_session_gone(outcome.process_group)


def test_the_planner_inherits_no_descriptor_of_ours_and_runs_where_it_was_told(tmp_path: Path) -> None:
    # an inheritable descriptor the tool's own parent might have left open (a shell's fd 3, say)
    inherited = os.open(os.devnull, os.O_RDONLY)
    os.set_inheritable(inherited, True)
    probe = (
        "import os, sys\n"
        f"fd = {inherited}\n"
        "try:\n    os.fstat(fd)\n    print('open', fd)\nexcept OSError:\n    print('closed', fd)\n"
        "print('cwd', os.getcwd())\n"
        "print('stdin', os.read(0, 10))\n"
    )
    try:
        run = process.run_process_group(
            [sys.executable, "-c", probe], tmp_path, 30, what="a probe", program=sys.executable
        )
    finally:
        os.close(inherited)
    log = process.read_log(tmp_path)
    assert run.exit_code == 0, log
    assert f"closed {inherited}" in log
    assert f"cwd {tmp_path}" in log
    assert "stdin b''" in log  # /dev/null, not the tool's terminal


def test_the_memory_limit_holds_in_the_planner(tmp_path: Path) -> None:
    probe = "import resource; print('limit', resource.getrlimit(resource.RLIMIT_AS)[0] // 2**20)"
    run = process.run_process_group(
        [sys.executable, "-c", probe], tmp_path, 30, what="a probe", program=sys.executable, memory_limit_mb=900
    )
    assert run.exit_code == 0
    assert "limit 900" in process.read_log(tmp_path)


# A planner that puts a link to a folder (or file) of the user's where its working folder (or its log) was.
_SWAP_FOLDER = (
    "import os, shutil, sys\n"
    "here = os.getcwd()\nos.chdir('/')\nshutil.rmtree(here)\nos.symlink(sys.argv[1], here)\n"
    "print('(move counter_1 table_1)')\n"
)
_SWAP_LOG = "import os, sys\nos.unlink('planner.log')\nos.symlink(sys.argv[1] + '/mine.txt', 'planner.log')\n"


@pytest.mark.parametrize("script", [_SWAP_FOLDER, _SWAP_LOG], ids=["folder", "log"])
def test_a_planner_that_swaps_in_a_link_to_the_users_files_gets_nothing_written_there(tmp_path, script):
    users = tmp_path / "users"
    users.mkdir()
    (users / "mine.txt").write_text("keep\n")
    scratch = tmp_path / "tmp"
    scratch.mkdir()
    swap = write_file(tmp_path, "swap.py", script)
    template = f"cmd:{sys.executable} {swap} {users} {{domain}} {{problem}}"
    completed = subprocess.run(
        [*TOOL, "plan", str(COFFEE_DOMAIN), str(PROBLEMS / "coffee-simple.pddl"), "--method", "pure", "-q"]
        + ["--timeout", "60", "--planner", template],
        env=dict(os.environ, TMPDIR=str(scratch)),
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert [path.name for path in users.iterdir()] == ["mine.txt"]
    assert (users / "mine.txt").read_text() == "keep\n"
    assert "Traceback" not in completed.stderr and completed.returncode in (0, 40), completed.stderr
    assert list(scratch.iterdir()) == [], "a link or folder of the run left behind"


# A supervised program that forks a copy of itself (as a warm engine worker does): the copy leads a
# group of its own with one child of its own, and writes its pid to ``copy.pid``.
FORKING = """
import os, subprocess, sys, time
pid = os.fork()
if pid == 0:
    os.setpgid(0, 0)
    subprocess.Popen([sys.executable, "-c", "import time; time.sleep(300)"])
    with open("copy.pid.tmp", "w") as out:
        out.write(str(os.getpid()))
    os.rename("copy.pid.tmp", "copy.pid")
    time.sleep(300)
    os._exit(0)
time.sleep(300)
"""


def test_a_forked_group_is_killed_alone_and_its_parent_goes_on(tmp_path):
    workdir = tmp_path / "run"
    workdir.mkdir()
    started = process.start_process_group(
        [sys.executable, "-c", FORKING], workdir, what="forking program", program=sys.executable
    )
    try:
        deadline = time.monotonic() + 30
        while not (workdir / "copy.pid").exists() and time.monotonic() < deadline:
            time.sleep(0.02)
        copy = process.ForkedGroup(int((workdir / "copy.pid").read_text()))
        members = [pid for pid, fields in guard.process_stats() if int(fields[2]) == copy.run.pgid]
        assert len(members) == 2 and not copy.exited()  # the copy and its child
        copy.stop()
        assert copy.exited() and all(process_gone(pid) for pid in members)
        assert not started.exited()  # the guard and the program that forked the copy run on
        copy.kill()  # again: its number is no longer its own (a zombie), and nothing else is touched
        assert not started.exited()
    finally:
        started.stop()
    assert process_gone(started.run.pgid)


def test_a_forked_group_that_is_gone_counts_as_exited():
    copy = process.ForkedGroup(2**22 + 1)  # above Linux's largest pid: never a process
    assert copy.exited()
    copy.stop()  # nothing to kill, and no error


# --------------------------------------------------------------------------- the planner's temporary files

LITTERING = """
    import os, sys, tempfile, time
    os.close(tempfile.mkstemp(prefix="engine-log-")[0])  # delete=False, as up_aries logs
    os.makedirs(os.path.join(tempfile.mkdtemp(), "copies"))  # as ENHSP's wrapper copies the files
    print(os.environ["TMPDIR"], flush=True)
    time.sleep(float(sys.argv[1]))
"""


@pytest.mark.parametrize("sleep, stopped", [(0.0, False), (30.0, True)])
def test_what_a_planner_leaves_in_the_temporary_folder_goes_with_its_run(tmp_path, monkeypatch, sleep, stopped):
    """The planner's $TMPDIR is a folder of its run's own: it ends empty whether the planner exits, or
    is killed by the watchdog before it could clean up."""
    from support import planner_script

    from relevance_plan.planning.planners.command import CommandPlanner

    temporary = tmp_path / "tmp"
    temporary.mkdir()
    monkeypatch.setenv("TMPDIR", str(temporary))
    monkeypatch.setattr(tempfile, "tempdir", str(temporary))  # the tool's own folders go there too
    script = planner_script(tmp_path, "littering.py", LITTERING)
    planner = CommandPlanner(f"{script} {sleep} {{domain}} {{problem}}")
    domain = write_file(tmp_path, "d.pddl", SMALL_GRIPPER_DOMAIN)
    outcome = planner.run(str(domain), str(domain), time_limit=1.0, memory_limit_mb=None)
    assert outcome.killed_by_watchdog is stopped
    planners = outcome.log_tail.splitlines()[0]
    assert planners != str(temporary) and not os.path.exists(planners)  # the run's own, gone with it
    assert list(temporary.iterdir()) == []
