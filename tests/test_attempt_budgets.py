"""Budgets for pruned attempts of a planner that cannot prove a pruned problem unsolvable."""

from __future__ import annotations

import time

import pytest
from support import planner_script

from relevance_plan.io import load_task
from relevance_plan.pddl.plans import Plan
from relevance_plan.planning.attempts import MIN_BUDGET, AttemptLoop, Budgets, run_attempts
from relevance_plan.planning.options import PlanOptions
from relevance_plan.planning.planners.base import PlannerStatus, RunOutcome
from relevance_plan.planning.planners.registry import make_planner
from relevance_plan.planning.results import AttemptStatus, PlanStatus
from relevance_plan.planning.run import plan_task
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.selection.prune import Thresholds
from relevance_plan.relevance.setup import ScoringOptions, score_problem

# Stands in for a planner that cannot prove unsolvability: on a pruned problem it searches "forever";
# on the full problem it asks Fast Downward and prints the plan.
FOREVER_ON_PRUNED = """
    import os, sys, time
    from relevance_plan.planning.planners.fast_downward.adapter import run_fast_downward
    if os.path.basename(sys.argv[2]).startswith("pruned-"):
        time.sleep(600)
    for step in run_fast_downward(sys.argv[1], sys.argv[2], time_limit=60).plan:
        print(step)
"""

# What a fake planner answers when its time ran out.
OUT_OF_TIME = RunOutcome(
    status=PlannerStatus.OUT_OF_TIME, exit_code=-9, plan=Plan(()), plan_cost=None, wall_time=0.01, planner="fake"
)

# Keeps little: each widening leaves more objects out than it brings back, so several attempts are pruned.
STRICT = Thresholds(0.2, 0.85)


def test_which_planners_prove_a_problem_unsolvable():
    assert make_planner("fast-downward").proves_unsolvable
    assert make_planner("up:symk").proves_unsolvable
    for name in ("lpg", "up:aries", "up:tamer", "up:enhsp", "up:kairos", "cmd:planner {domain} {problem}", "auto"):
        assert not make_planner(name).proves_unsolvable, name


def test_budgets_start_from_a_multiple_of_the_pruning_time_and_double():
    assert Budgets.after(0.01).first == MIN_BUDGET
    assert Budgets.after(2.0).first > 2.0
    budgets = Budgets(1.5)
    assert [budgets.limit(n) for n in range(4)] == [1.5, 3.0, 6.0, 12.0]


def _selection(coffee_files, thresholds=STRICT):
    domain_path, problem_path = coffee_files
    task = PlanningTask(*load_task(domain_path, problem_path))
    scoring = score_problem(task, ScoringOptions(thresholds=thresholds), domain_path=domain_path)
    return task, scoring.first_selection()


@pytest.mark.parametrize("timeout", [60.0, None])
def test_pruned_attempts_get_growing_budgets_and_the_full_problem_the_rest(coffee_files, timeout):
    task, selection = _selection(coffee_files)
    calls: list[tuple[bool, float | None]] = []

    def call_planner(objects, limit):
        calls.append((objects is None, limit))
        return OUT_OF_TIME

    options = PlanOptions(timeout=timeout, thresholds=STRICT)
    attempts, _ = run_attempts(AttemptLoop(task, call_planner, options, time.perf_counter()), selection, Budgets(1))
    pruned = [limit for full, limit in calls if not full]
    assert len(pruned) >= 2 and calls[-1][0], calls  # widened to the full problem
    assert pruned == [2.0**n for n in range(len(pruned))]
    assert calls[-1][1] is None if timeout is None else calls[-1][1] > timeout - 5  # the rest
    assert [a.time_limit for a in attempts] == [limit for _, limit in calls]


def test_without_budgets_a_pruned_attempt_gets_its_share(coffee_files):
    task, selection = _selection(coffee_files)
    limits = []

    def call_planner(objects, limit):
        limits.append(limit)
        return OUT_OF_TIME

    options = PlanOptions(timeout=60, thresholds=STRICT)
    run_attempts(AttemptLoop(task, call_planner, options, time.perf_counter()), selection)
    assert limits[0] > 20  # half of the time left: a planner that proves unsolvability ends early by itself


@pytest.mark.planner
@pytest.mark.parametrize("race", [False, True])
def test_a_planner_that_never_proves_reaches_the_full_problem_quickly(tmp_path, coffee_files, race):
    domain, problem = coffee_files
    planner = "cmd:" + planner_script(tmp_path, "forever", FOREVER_ON_PRUNED) + " {domain} {problem}"
    started = time.monotonic()
    result = plan_task(domain, problem, PlanOptions(planner=planner, timeout=600, thresholds=STRICT, race=race))
    elapsed = time.monotonic() - started
    assert result.status is PlanStatus.SOLVED and result.valid, result.message
    assert elapsed < 200  # the deadline is the behaviour: without budgets the first attempt alone takes 300 s
    pruned = [a for a in result.attempts if a.selection is not None]
    assert pruned and all(a.time_limit is not None and a.time_limit < 100 for a in pruned)
    limits = [a.time_limit for a in pruned]
    assert limits == sorted(limits) and len(set(limits)) == len(limits)  # each widening's budget is larger
    if race:
        assert result.deciding_side == "full"
        assert pruned[-1].status is AttemptStatus.STOPPED
        logged = result.to_json()["attempt_log"]
        assert logged[-1]["side"] == "full" and logged[-1]["status"] == "solved"
        assert any(entry["status"] == "stopped" and entry["side"] == "pruned" for entry in logged)
        assert all(entry["planner_status"] == "stopped" for entry in logged if entry["status"] == "stopped")
    else:
        assert all(a.status is AttemptStatus.OUT_OF_TIME for a in pruned)
        assert result.attempts[-1].full and result.objects_kept == result.objects_total
