"""The unified-planning worker: one warm engine per run, its time limit held, dead with the tool."""

from __future__ import annotations

import contextlib
import os
import signal
import subprocess
import sys
import textwrap
import threading
import time

import pytest
from support import BIG_DOMAIN, SMALL_GRIPPER_DOMAIN, big_problem, process_gone, small_gripper_problem

from relevance_plan.generators.padded import GRIPPER_DOMAIN, gripper_problem
from relevance_plan.planning.options import PlanOptions
from relevance_plan.planning.planners.base import PlannerStatus
from relevance_plan.planning.planners.registry import make_planner
from relevance_plan.planning.planners.supply import warm_planners, warm_up
from relevance_plan.planning.planners.up.adapter import engine_module_installed
from relevance_plan.planning.planners.up.pool import COPY_NICE, EngineWorker, ForkedWorker, current_pool
from relevance_plan.planning.race import THREAD_NAME
from relevance_plan.planning.results import PlanStatus
from relevance_plan.planning.run import plan_task

needs_pyperplan = pytest.mark.skipif(not engine_module_installed("pyperplan"), reason="up-pyperplan not installed")


def runs_pyperplan(test):
    """A test that starts up:pyperplan's worker (skipped without the engine)."""
    return pytest.mark.planner(needs_pyperplan(test))


@contextlib.contextmanager
def warm_pool(planner, beside: bool = False):
    """A run's pool of workers (``beside``: the race's second pool), ``planner``'s warmed in it."""
    with warm_planners(None, beside=beside):
        warm_up(planner)
        yield


def _files(tmp_path, domain: str, problem: str):
    (tmp_path / "domain.pddl").write_text(domain)
    (tmp_path / "problem.pddl").write_text(problem)
    return str(tmp_path / "domain.pddl"), str(tmp_path / "problem.pddl")


@pytest.fixture
def gripper(tmp_path):
    """The small gripper problem's files and a planner run on them (in whatever pool is current)."""
    files = _files(tmp_path, SMALL_GRIPPER_DOMAIN, small_gripper_problem())
    planner = make_planner("up:pyperplan")
    return planner, lambda: planner.run(*files, time_limit=60, memory_limit_mb=None)


@runs_pyperplan
def test_the_attempts_of_a_run_are_served_by_one_worker(gripper):
    planner, solve = gripper
    with warm_pool(planner):
        first = solve()
        second = solve()
    assert first.status is second.status is PlannerStatus.SOLVED
    assert first.plan == second.plan and len(first.plan) == 3
    assert first.process_group == second.process_group  # the same worker answered both
    assert process_gone(first.process_group)  # killed when the run ended
    alone = solve()  # no run open: the one-shot child
    assert alone.status is PlannerStatus.SOLVED and alone.process_group != first.process_group


@runs_pyperplan
def test_an_attempt_that_overruns_kills_the_worker_and_the_next_gets_a_new_one(tmp_path):
    (tmp_path / "hard").mkdir()
    hard = _files(tmp_path / "hard", BIG_DOMAIN, big_problem(60))
    easy = _files(tmp_path, SMALL_GRIPPER_DOMAIN, small_gripper_problem())
    planner = make_planner("up:pyperplan")
    with warm_pool(planner):
        warm = planner.run(*easy, time_limit=60, memory_limit_mb=None)
        started = time.monotonic()
        overrun = planner.run(*hard, time_limit=1.0, memory_limit_mb=None)
        took = time.monotonic() - started
        after = planner.run(*easy, time_limit=60, memory_limit_mb=None)
    assert overrun.status is PlannerStatus.OUT_OF_TIME
    assert took < 30  # the limit held (one second and the worker's grace, on a slow machine)
    assert process_gone(overrun.process_group)
    assert after.status is PlannerStatus.SOLVED and after.process_group not in (warm.process_group, None)
    assert after.process_group != overrun.process_group


def _served_by(monkeypatch) -> list[tuple[str, EngineWorker]]:
    """(thread name, worker) of every request a worker is sent from now on."""
    served: list[tuple[str, EngineWorker]] = []
    solve = EngineWorker.solve

    def spy(self, *args, **kwargs):
        served.append((threading.current_thread().name, self))
        return solve(self, *args, **kwargs)

    monkeypatch.setattr(EngineWorker, "solve", spy)
    return served


@runs_pyperplan
def test_a_race_plans_the_full_problem_in_the_runs_warm_worker_and_the_pruned_attempts_in_another(
    tmp_path, monkeypatch
):
    # as planning without pruning does: no one-shot child paying unified-planning's import
    served = _served_by(monkeypatch)
    domain, problem = _files(tmp_path, GRIPPER_DOMAIN, gripper_problem(8))
    result = plan_task(domain, problem, PlanOptions(planner="up:pyperplan", race=True, timeout=120))
    assert result.status is PlanStatus.SOLVED and result.valid and result.pruned
    full_side = {worker for thread, worker in served if thread == THREAD_NAME}
    pruned_side = {worker for thread, worker in served if thread != THREAD_NAME}
    assert full_side and pruned_side
    assert not full_side & pruned_side  # one worker never serves both sides


@runs_pyperplan
def test_a_race_copies_the_runs_warm_worker_for_the_pruned_attempts(tmp_path, monkeypatch):
    # a second worker would import unified-planning again, on the core the full problem needs
    served = _served_by(monkeypatch)
    domain, problem = _files(tmp_path, GRIPPER_DOMAIN, gripper_problem(8))
    result = plan_task(domain, problem, PlanOptions(planner="up:pyperplan", race=True, timeout=120))
    assert result.status is PlanStatus.SOLVED and result.valid and result.pruned
    pruned_side = [worker for thread, worker in served if thread != THREAD_NAME]
    copies = [worker for worker in pruned_side if isinstance(worker, ForkedWorker)]
    assert copies and copies[0] is pruned_side[0]  # the first pruned attempt had a copy
    full_side = [worker for thread, worker in served if thread == THREAD_NAME]
    assert all(type(worker) is EngineWorker for worker in full_side)
    assert all(copy.parent is full_side[0] for copy in copies)
    groups = [attempt.outcome.process_group for attempt in result.attempts]
    assert all(group is None or process_gone(group) for group in groups)  # nothing left running


@runs_pyperplan
def test_a_copy_serves_its_own_requests_and_is_killed_alone(gripper):
    planner, solve = gripper
    with warm_pool(planner):
        parent = current_pool().start("pyperplan", None)
        with warm_pool(planner, beside=True):
            copy = current_pool().start("pyperplan", None)
            assert isinstance(copy, ForkedWorker) and copy.parent is parent
            copied = solve()
            assert copied.status is PlannerStatus.SOLVED and len(copied.plan) == 3
            assert copied.process_group != parent._group.run.pgid  # a group of its own
            assert not process_gone(copied.process_group)
            # a guess: lower in priority than the worker planning the full problem
            lower = os.getpriority(os.PRIO_PROCESS, copied.process_group)
            assert lower - os.getpriority(os.PRIO_PROCESS, parent._group.run.pgid) == COPY_NICE
        assert process_gone(copied.process_group)  # killed when its pool closed
        assert parent.alive
        own = solve()
        assert own.status is PlannerStatus.SOLVED and own.process_group == parent._group.run.pgid
    assert process_gone(own.process_group)


@runs_pyperplan
def test_a_worker_that_has_served_a_request_is_not_copied(gripper):
    # an engine may leave threads behind after a request, and a fork copies none of them
    planner, solve = gripper
    with warm_pool(planner):
        assert solve().status is PlannerStatus.SOLVED
        with warm_pool(planner, beside=True):
            worker = current_pool().start("pyperplan", None)
            assert type(worker) is EngineWorker
            assert solve().status is PlannerStatus.SOLVED


@runs_pyperplan
def test_a_race_with_nothing_to_prune_plans_once_in_the_warm_worker(tmp_path, monkeypatch):
    served = _served_by(monkeypatch)
    every_object_needed = small_gripper_problem().replace("rooma roomb roomc - room", "rooma roomb - room")
    domain, problem = _files(tmp_path, SMALL_GRIPPER_DOMAIN, every_object_needed)
    result = plan_task(domain, problem, PlanOptions(planner="up:pyperplan", race=True, timeout=120))
    assert result.status is PlanStatus.SOLVED and not result.pruned
    assert [thread for thread, _ in served] == [THREAD_NAME]


WORKER_OWNER = """
    import sys, time
    from relevance_plan.planning.planners.registry import make_planner
    from relevance_plan.planning.planners.supply import warm_planners
    from relevance_plan.planning.planners.up.pool import current_pool
    with warm_planners(None):
        worker = current_pool().start("pyperplan", None)
        worker.wait_ready(time.monotonic() + 120)
        print(worker._group.run.pgid, flush=True)
        time.sleep(300)
"""


@runs_pyperplan
def test_the_worker_dies_when_the_tool_is_killed():
    owner = subprocess.Popen(
        [sys.executable, "-c", textwrap.dedent(WORKER_OWNER)],
        stdout=subprocess.PIPE,
        text=True,
        env={**os.environ, "PYTHONPATH": os.pathsep.join(sys.path)},
    )
    try:
        group = int(owner.stdout.readline())
        assert not process_gone(group)
        owner.send_signal(signal.SIGKILL)
        owner.wait()
        deadline = time.monotonic() + 30
        while not process_gone(group) and time.monotonic() < deadline:
            time.sleep(0.05)
        assert process_gone(group)
    finally:
        owner.kill()
        owner.wait()


DEFERRED_CHECK = """
import sys
from relevance_plan.planning.planners.up.deferred import defer_configspace
assert defer_configspace()
import unified_planning.io, unified_planning.shortcuts as shortcuts
shortcuts.get_environment().credits_stream = None
engine = shortcuts.get_environment().factory.engine("pyperplan")
assert "scipy.stats" not in sys.modules, "ConfigSpace was imported with unified-planning"
space = engine.get_configuration_space()  # built on first use, by the real package
import ConfigSpace, ConfigSpace.util
assert isinstance(space, ConfigSpace.ConfigurationSpace), type(space)
assert "scipy.stats" in sys.modules
print("deferred")
"""


@needs_pyperplan
def test_the_engine_processes_import_configspace_only_when_an_engine_asks_for_it():
    completed = subprocess.run(
        [sys.executable, "-c", DEFERRED_CHECK], capture_output=True, text=True, timeout=120, check=False
    )
    assert completed.returncode == 0, completed.stderr
    assert completed.stdout.strip() == "deferred"


@needs_pyperplan
def test_waiting_for_a_starting_worker_leaves_its_lock_free_for_the_other_side():
    # the race's full side waits for the worker while the pruned side gives up its copy: that
    # must not queue behind the wait (it held the lock through every 0.05 s look, 0.1-0.2 s in all)
    worker = EngineWorker("pyperplan", None, None)
    try:
        waiting = threading.Thread(target=worker.wait_ready, args=(time.monotonic() + 60,))
        waiting.start()
        free = taken = 0
        while waiting.is_alive() and free + taken < 200:
            if worker._lock.acquire(blocking=False):
                worker._lock.release()
                free += 1
            else:
                taken += 1
            time.sleep(0.002)
        waiting.join(60)
        assert free + taken >= 20  # the worker took a while to start: the wait was sampled
        assert free > 3 * taken
    finally:
        worker.close()
