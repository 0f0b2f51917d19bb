"""The Fast Downward adapter (fast_downward.py) and the process supervisor (process.py): real runs, tiny files."""

from __future__ import annotations

import os
import runpy
import signal
import subprocess
import sys
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest
from support import write_file

from relevance_plan import errors
from relevance_plan.planning.planners.base import PlannerStatus
from relevance_plan.planning.planners.fast_downward import adapter as fast_downward
from relevance_plan.planning.planners.fast_downward import command as fd_command
from relevance_plan.supervision import process, spawn

GRIPPER_DOMAIN = """
(define (domain gripper)
  (:requirements :strips :typing)
  (:types room ball gripper)
  (:predicates (at-robby ?r - room) (at ?b - ball ?r - room)
               (free ?g - gripper) (carry ?b - ball ?g - gripper))
  (:action move :parameters (?from ?to - room)
    :precondition (at-robby ?from)
    :effect (and (at-robby ?to) (not (at-robby ?from))))
  (:action pick :parameters (?b - ball ?r - room ?g - gripper)
    :precondition (and (at ?b ?r) (at-robby ?r) (free ?g))
    :effect (and (carry ?b ?g) (not (at ?b ?r)) (not (free ?g))))
  (:action drop :parameters (?b - ball ?r - room ?g - gripper)
    :precondition (and (carry ?b ?g) (at-robby ?r))
    :effect (and (at ?b ?r) (free ?g) (not (carry ?b ?g)))))
"""


def gripper_problem(target: str = "roomb", free_gripper: bool = True) -> str:
    free = "(free left)" if free_gripper else ""
    return f"""
(define (problem g) (:domain gripper)
  (:objects rooma roomb roomc - room ball1 - ball left - gripper)
  (:init (at-robby rooma) (at ball1 rooma) {free})
  (:goal (at ball1 {target})))
"""


# n objects give n^3 ground actions: n=30 needs ~125 MB, n=40 ~5.5 s of
# translation (measured), while the search itself is trivial.
BIG_DOMAIN = """
(define (domain big)
  (:requirements :strips)
  (:predicates (p ?x) (q ?x ?y ?z) (done))
  (:action a :parameters (?x ?y ?z)
    :precondition (and (p ?x) (p ?y) (p ?z))
    :effect (q ?x ?y ?z))
  (:action fin :parameters (?x)
    :precondition (q ?x ?x ?x)
    :effect (done)))
"""


def big_problem(n: int) -> str:
    objects = " ".join(f"o{i}" for i in range(n))
    init = " ".join(f"(p o{i})" for i in range(n))
    return f"(define (problem big{n}) (:domain big) (:objects {objects}) (:init {init}) (:goal (done)))"


@pytest.fixture
def gripper(tmp_path: Path) -> tuple[Path, Path]:
    return write_file(tmp_path, "domain.pddl", GRIPPER_DOMAIN), write_file(tmp_path, "p.pddl", gripper_problem())


@pytest.fixture
def big40(tmp_path: Path) -> tuple[Path, Path]:
    return write_file(tmp_path, "big.pddl", BIG_DOMAIN), write_file(tmp_path, "big40.pddl", big_problem(40))


def live_session_members(session: int) -> list[int]:
    """Pids of processes in this session that are not zombies (from /proc)."""
    members = []
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        try:
            stat = (entry / "stat").read_text()
        except OSError:
            continue
        # Fields after "(comm)": state ppid pgrp session ...
        fields = stat[stat.rindex(")") + 2 :].split()
        if int(fields[3]) == session and fields[0] != "Z":
            members.append(int(entry.name))
    return members


def assert_session_gone(session: int) -> None:
    # SIGKILL is delivered at once, but exiting (freeing memory) takes a moment.
    deadline = time.monotonic() + 3.0
    while live_session_members(session) and time.monotonic() < deadline:
        time.sleep(0.05)
    assert live_session_members(session) == []


# --- without running the planner ---------------------------------------------


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
    command = fd_command.build_command("py", Path("fd.py"), domain, problem, "ff-gbfs", 9.2, 100)
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
    command = fd_command.build_command("py", Path("fd.py"), domain, problem, "lama", None, None)
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


def test_read_plan_takes_last_complete_anytime_plan(tmp_path: Path) -> None:
    write_file(tmp_path, "sas_plan.2", "(A X)\n(B Y)\n; cost = 2 (unit cost)\n")
    write_file(tmp_path, "sas_plan.10", "(c z)\n; cost = 1 (unit cost)\n")
    write_file(tmp_path, "sas_plan.11", "(d z)\n")  # cut off by a kill mid-write
    found = fast_downward.read_best_plan(tmp_path)
    assert [str(step) for step in found] == ["(c z)"] and found.cost == 1
    (tmp_path / "sas_plan.10").unlink()
    found = fast_downward.read_best_plan(tmp_path)
    assert [str(step) for step in found] == ["(a x)", "(b y)"] and found.cost == 2
    empty = tmp_path / "empty"
    empty.mkdir()
    assert fast_downward.read_best_plan(empty) is None


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
        fast_downward.run_fast_downward(*gripper, python=str(tmp_path / "no-python"))


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
    domain = write_file(tmp_path, "domain.pddl", GRIPPER_DOMAIN)
    problem = write_file(tmp_path, "p.pddl", gripper_problem(free_gripper=False))
    outcome = fast_downward.run_fast_downward(domain, problem, time_limit=30)
    assert outcome.status is PlannerStatus.UNSOLVABLE
    assert outcome.exit_code == 11 and not outcome.plan.steps and outcome.plan_cost is None


@pytest.mark.planner
def test_syntax_error_is_input_error(tmp_path: Path) -> None:
    domain = write_file(tmp_path, "domain.pddl", GRIPPER_DOMAIN)
    problem = write_file(tmp_path, "p.pddl", gripper_problem().replace("(free left))", "(free left)"))
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
    # Unlimited, translating big40 takes ~5.5 s.  With 1 s the translator's CPU
    # limit rounds down to 0 s (SIGXCPU, exit -24); with 2 s it exits 21.
    # A long grace: this is about the driver's own limit, which the watchdog must not pre-empt on a busy machine.
    outcome = fast_downward.run_fast_downward(*big40, time_limit=time_limit, watchdog_grace=5.0)
    assert outcome.status is PlannerStatus.OUT_OF_TIME
    assert outcome.exit_code in (21, -signal.SIGXCPU)
    assert outcome.cpu_time < time_limit + 1.0
    assert outcome.wall_time < 4.0  # generous: other test runs may share the cores
    assert not outcome.killed_by_watchdog
    assert_session_gone(outcome.process_group)


@pytest.mark.planner
def test_out_of_memory(tmp_path: Path) -> None:
    domain = write_file(tmp_path, "big.pddl", BIG_DOMAIN)
    problem = write_file(tmp_path, "big30.pddl", big_problem(30))  # needs ~125 MB
    outcome = fast_downward.run_fast_downward(domain, problem, time_limit=20, memory_limit_mb=80)
    assert outcome.status is PlannerStatus.OUT_OF_MEMORY, outcome.log_tail
    assert outcome.exit_code == 20


@pytest.mark.planner
def test_watchdog_kills_whole_process_group(big40: tuple[Path, Path]) -> None:
    outcome = fast_downward.run_fast_downward(*big40, time_limit=1, driver_limits=False, watchdog_grace=0.5)
    assert outcome.killed_by_watchdog
    assert outcome.status is PlannerStatus.OUT_OF_TIME
    assert outcome.exit_code == -signal.SIGKILL
    assert 1.4 < outcome.wall_time < 4.0
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
    domain = write_file(tmp_path, "domain.pddl", GRIPPER_DOMAIN)
    problems = {
        "to_b": write_file(tmp_path, "b.pddl", gripper_problem("roomb")),
        "to_c": write_file(tmp_path, "c.pddl", gripper_problem("roomc")),
        "stuck1": write_file(tmp_path, "s1.pddl", gripper_problem("roomb", free_gripper=False)),
        "stuck2": write_file(tmp_path, "s2.pddl", gripper_problem("roomc", free_gripper=False)),
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
    from support import COFFEE_DOMAIN, PROBLEMS, TOOL

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
