"""Racing the full problem beside the pruned attempts: the first decisive side wins, the other is stopped."""

from __future__ import annotations

import contextvars
import sys
import time

import pytest
from support import planner_script, process_gone

from relevance_plan.planning.options import PlanOptions
from relevance_plan.planning.race import Race, race_by_default, usable_cores
from relevance_plan.planning.results import AttemptStatus, PlanStatus
from relevance_plan.planning.run import plan_task
from relevance_plan.supervision.process import CancelScope, cancel_scope

# A planner that hangs (after noting its pid) on one kind of input and asks Fast Downward on the other.
SPLIT_PLANNER = """
    import os, sys, time
    from relevance_plan.planning.planners.fast_downward.adapter import run_fast_downward
    pruned = os.path.basename(sys.argv[2]).startswith("pruned-")
    if pruned == {hang_on_pruned}:
        with open({marker!r}, "a") as out:
            out.write(f"{{os.getpid()}}\\n")
        time.sleep(300)
    for step in run_fast_downward(sys.argv[1], sys.argv[2], time_limit=60).plan:
        print(step)
"""


def split_planner(tmp_path, hang_on_pruned: bool) -> tuple[str, object]:
    marker = tmp_path / "hanging.pids"
    body = SPLIT_PLANNER.format(hang_on_pruned=hang_on_pruned, marker=str(marker))
    return "cmd:" + planner_script(tmp_path, "split", body) + " {domain} {problem}", marker


def hung_pids(marker) -> list[int]:
    return [int(line) for line in marker.read_text().split()] if marker.exists() else []


@pytest.mark.planner
def test_the_full_problem_wins_when_the_pruned_attempt_hangs_and_the_hung_planner_is_stopped(tmp_path, coffee_files):
    domain, problem = coffee_files
    planner, marker = split_planner(tmp_path, hang_on_pruned=True)
    started = time.monotonic()
    result = plan_task(domain, problem, PlanOptions(planner=planner, timeout=120, race=True))
    elapsed = time.monotonic() - started
    assert result.status is PlanStatus.SOLVED and result.valid, result.message
    assert result.deciding_side == "full" and result.attempts[-1].full
    assert result.objects_kept == result.objects_total
    assert elapsed < 60  # not the pruned attempt's share of the 120 s, nor its 300 s sleep
    pids = hung_pids(marker)
    assert pids and all(process_gone(pid) for pid in pids)


@pytest.mark.planner
def test_the_pruned_problem_wins_when_the_full_problem_hangs_and_the_full_run_is_stopped(tmp_path, coffee_files):
    domain, problem = coffee_files
    planner, marker = split_planner(tmp_path, hang_on_pruned=False)
    result = plan_task(domain, problem, PlanOptions(planner=planner, timeout=120, race=True))
    assert result.status is PlanStatus.SOLVED and result.valid, result.message
    assert result.deciding_side == "pruned"
    assert result.objects_kept < result.objects_total
    # the full problem ran once, raced, and is listed last, stopped; every other attempt was pruned
    *pruned, beside = result.attempts
    assert all(attempt.selection is not None for attempt in pruned) and pruned[-1].status is AttemptStatus.SOLVED
    assert beside.full and beside.raced and beside.status is AttemptStatus.STOPPED
    logged = result.to_json()["attempt_log"][-1]
    assert logged["status"] == "stopped" and logged["side"] == "full" and logged["kept"] == "all"
    assert logged["planner_status"] == "stopped"  # we stopped it: not a crash of the planner's
    deadline = time.monotonic() + 10
    while not hung_pids(marker) and time.monotonic() < deadline:
        time.sleep(0.05)  # the stopped run may not have got as far as writing its pid
    assert all(process_gone(pid) for pid in hung_pids(marker))


@pytest.mark.planner
def test_without_a_race_the_json_says_so_and_with_one_it_names_the_winner(coffee_files):
    domain, problem = coffee_files
    plain = plan_task(domain, problem, PlanOptions(timeout=60, race=False))
    raced = plan_task(domain, problem, PlanOptions(timeout=60, race=True))
    assert plain.to_json()["raced"] is None
    assert raced.to_json()["raced"] in ("full", "pruned")
    # the field's new name, and the old one kept for a release: the same value
    assert plain.to_json()["deciding_side"] is None
    assert raced.to_json()["deciding_side"] == raced.to_json()["raced"] == raced.deciding_side
    assert plain.status is raced.status is PlanStatus.SOLVED


def test_a_cancelled_scope_stops_runs_started_later_at_once(tmp_path):
    from relevance_plan.supervision.process import run_process_group

    scope = CancelScope()
    scope.cancel()
    started = time.monotonic()
    with cancel_scope(scope):
        run = run_process_group(
            [sys.executable, "-c", "import time; time.sleep(60)"], tmp_path, 120, what="sleeper", program="sleeper"
        )
    assert time.monotonic() - started < 20 and run.exit_code != 0


def test_a_race_that_decides_cancels_the_loser_and_stop_waits_for_its_thread():
    loser = CancelScope()
    race = Race(lambda: 42, lambda result: result == 42, loser).start()
    assert race.wait() == 42 and race.won
    assert loser.cancelled
    undecided = Race(lambda: 1, lambda result: result == 42, CancelScope()).start()
    assert undecided.wait() == 1 and not undecided.won
    undecided.stop()


def test_a_race_works_in_a_copy_of_its_starters_context():
    # the run's warm planners are found through a context variable: the race's thread must see them
    run = contextvars.ContextVar("run", default="none")
    token = run.set("this run")
    try:
        race = Race(run.get, lambda result: True, CancelScope()).start()
        assert race.wait() == "this run"
        race.stop()
    finally:
        run.reset(token)


def test_a_race_hands_its_error_to_the_caller():
    def fails():
        raise RuntimeError("broken planner")

    loser = CancelScope()
    race = Race(fails, lambda result: True, loser).start()
    with pytest.raises(RuntimeError, match="broken planner"):
        race.wait()
    race.stop()  # the thread has cancelled the other side by the time it ends
    # an error is decisive: the other side learns it now, not at its own time limit
    assert race.won and loser.cancelled


def test_racing_is_the_default_only_for_relevance_with_a_second_core():
    assert race_by_default("pure") is False
    assert race_by_default("relevance") is (usable_cores() >= 2)


# Fails at once on a pruned problem; on the full problem, never answers (the watchdog stops it).
FAILS_PRUNED_HANGS_FULL = """
    import os, sys, time
    if os.path.basename(sys.argv[2]).startswith("pruned-"):
        sys.exit(1)
    time.sleep(300)
"""


@pytest.mark.planner
def test_a_race_neither_side_wins_is_no_win_and_names_how_each_side_ended(tmp_path, coffee_files):
    domain, problem = coffee_files
    planner = "cmd:" + planner_script(tmp_path, "fails", FAILS_PRUNED_HANGS_FULL) + " {domain} {problem}"
    result = plan_task(domain, problem, PlanOptions(planner=planner, timeout=3, race=True))
    assert result.status is PlanStatus.OUT_OF_TIME, result.message
    assert result.race and result.deciding_side == ""  # out of time: nobody won
    data = result.to_json()
    assert data["deciding_side"] is None and data["raced"] is None
    assert data["race"] == {"pruned": "planner-crash", "full": "out-of-time"}
    assert {entry["side"] for entry in data["attempt_log"]} == {"pruned", "full"}
    assert data["objects_total"] == result.objects_total > 0


@pytest.mark.planner
def test_a_race_won_by_a_failure_is_no_win(tmp_path, coffee_files):
    domain, problem = coffee_files
    planner = "cmd:" + planner_script(tmp_path, "fails", "import sys\nsys.exit(1)\n") + " {domain} {problem}"
    result = plan_task(domain, problem, PlanOptions(planner=planner, timeout=30, race=True))
    assert result.status is PlanStatus.PLANNER_ERROR, result.message
    assert result.deciding_side == ""
    assert result.to_json()["race"] == {"pruned": "planner-crash", "full": "planner-crash"}
