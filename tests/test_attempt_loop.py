"""Prune-then-plan: every method's plan validates on the original; relaxation recovers."""

import json
import re
import time

import pytest
from support import coffee_problem

from relevance_plan.errors import RelevancePlanError
from relevance_plan.generators.padded import BLOCKSWORLD_DOMAIN, GRIPPER_DOMAIN, blocksworld_problem, gripper_problem
from relevance_plan.io import load_task
from relevance_plan.pddl.plans import Plan
from relevance_plan.planning.options import PlanOptions
from relevance_plan.planning.results import PlanStatus
from relevance_plan.planning.run import plan_task
from relevance_plan.planning.validation import ValidationStatus, validate_with_up
from relevance_plan.relevance.selection.prune import Thresholds


def assert_valid_on_original(domain_path, problem_path, result):
    assert result.status is PlanStatus.SOLVED, result.message
    assert result.valid
    domain, problem = load_task(domain_path, problem_path)
    # a second, independent validator agrees
    assert validate_with_up(domain, problem, result.plan).status is ValidationStatus.VALID


@pytest.mark.planner
@pytest.mark.parametrize("method", ["relevance", "pure", "random"])
def test_every_method_gives_a_plan_valid_on_the_original(coffee_files, method):
    domain_path, problem_path = coffee_files
    result = plan_task(domain_path, problem_path, PlanOptions(method=method, timeout=60))
    assert_valid_on_original(domain_path, problem_path, result)
    if method == "relevance":
        assert result.objects_kept < result.objects_total
        assert "side_plate_1" in result.selection.removed
        # the plate stands on the plastic cup, which is set aside for the free paper cup
        assert result.selection.set_aside == {"plastic_cup_1"}
        assert "dinner_plate_1" in result.selection.removed
    if method == "pure":
        assert result.objects_kept == result.objects_total


@pytest.mark.planner
def test_oracle_uses_the_sidecar(coffee_files):
    domain_path, problem_path = coffee_files
    necessary = ["alice", "counter_1", "table_1", "paper_cup_1", "cold_brew_1", "creamer_1", "fridge_1", "stir_stick_1"]
    problem_path.with_suffix(".json").write_text(json.dumps({"necessary": necessary}))
    result = plan_task(domain_path, problem_path, PlanOptions(method="oracle", timeout=60))
    assert_valid_on_original(domain_path, problem_path, result)
    assert result.objects_kept == len(necessary)


@pytest.mark.planner
def test_relaxation_recovers_when_the_first_pruning_removed_a_needed_object(coffee_files):
    domain_path, problem_path = coffee_files
    strict = Thresholds(0.2, 0.85)  # keeps the cup and the coffee, drops whitener and stirrer
    result = plan_task(domain_path, problem_path, PlanOptions(thresholds=strict, timeout=60))
    assert_valid_on_original(domain_path, problem_path, result)
    assert len(result.attempts) >= 2
    assert result.first_attempt_status == "unsolvable"
    assert result.attempts[0].objects_kept < result.attempts[-1].objects_kept


@pytest.mark.planner
def test_a_goal_object_is_never_set_aside(tmp_path, coffee_domain_path):
    # the plate-covered plastic cup is named by the goal, so it stays with its plate
    problem = tmp_path / "coffee.pddl"
    problem.write_text(
        coffee_problem(extra_plates=2).replace(
            "(coffee-served alice)", "(and (coffee-served alice) (holding plastic_cup_1))"
        )
    )
    result = plan_task(coffee_domain_path, problem, PlanOptions(timeout=60))
    assert_valid_on_original(coffee_domain_path, problem, result)
    assert result.selection.set_aside == frozenset()
    assert {"plastic_cup_1", "dinner_plate_1"} <= result.selection.kept


@pytest.mark.planner
def test_widening_brings_back_a_set_aside_alternative_when_the_free_one_cannot_serve(tmp_path, coffee_domain_path):
    # the free paper cup is not empty, so only the plastic cup under the plate can take coffee
    problem = tmp_path / "coffee.pddl"
    problem.write_text(coffee_problem(extra_plates=2).replace("(empty paper_cup_1)", ""))
    result = plan_task(coffee_domain_path, problem, PlanOptions(timeout=60))
    assert_valid_on_original(coffee_domain_path, problem, result)
    assert result.selection.set_aside == {"plastic_cup_1"}
    assert result.first_attempt_status == "unsolvable" and len(result.attempts) >= 2
    assert any("plastic_cup_1" in step.args for step in result.plan)


@pytest.mark.planner
def test_no_widen_reports_the_failed_pruning(coffee_files):
    domain_path, problem_path = coffee_files
    result = plan_task(
        domain_path, problem_path, PlanOptions(thresholds=Thresholds(0.2, 0.85), widen=False, timeout=60)
    )
    assert result.status is PlanStatus.NO_VALID_PLAN
    assert len(result.attempts) == 1 and not result.plan.steps


@pytest.mark.planner
def test_unsolvable_original_is_reported_as_unsolvable(tmp_path, coffee_domain_path):
    problem = tmp_path / "no-cup.pddl"
    text = coffee_problem(plate_on_cup=False).replace("plastic_cup_1 paper_cup_1 - cup", "")
    text = "\n".join(line for line in text.splitlines() if "_cup_1" not in line)
    problem.write_text(text)
    result = plan_task(coffee_domain_path, problem, PlanOptions(timeout=60))
    assert result.status is PlanStatus.UNSOLVABLE
    assert result.attempts[-1].objects_kept == result.objects_total  # proven on the full problem


@pytest.mark.planner
def test_insufficient_cues_is_its_own_outcome(coffee_files):
    domain_path, problem_path = coffee_files
    result = plan_task(domain_path, problem_path, PlanOptions(objective="drink-at-break", timeout=60))
    assert result.status is PlanStatus.INSUFFICIENT_CUES
    assert "give --activity or --human" in result.message
    resolved = plan_task(domain_path, problem_path, PlanOptions(objective="drink-at-break", human="alice", timeout=60))
    assert resolved.status is PlanStatus.SOLVED


@pytest.mark.planner
@pytest.mark.parametrize(
    "domain_text, problem_text, expected_kept_at_most",
    [
        (BLOCKSWORLD_DOMAIN, blocksworld_problem(40, seed=2, in_the_way=2), 6),
        (GRIPPER_DOMAIN, gripper_problem(40), 16),
    ],
)
def test_goal_scorer_plans_on_classic_domains_without_a_model(
    tmp_path, domain_text, problem_text, expected_kept_at_most
):
    domain_path, problem_path = tmp_path / "domain.pddl", tmp_path / "problem.pddl"
    domain_path.write_text(domain_text)
    problem_path.write_text(problem_text)
    result = plan_task(domain_path, problem_path, PlanOptions(timeout=60))
    assert_valid_on_original(domain_path, problem_path, result)
    assert result.selection.scores.scorer == "goal"
    assert result.objects_kept <= expected_kept_at_most


@pytest.mark.planner
def test_out_of_time_is_reported(tmp_path):
    domain_path, problem_path = tmp_path / "domain.pddl", tmp_path / "problem.pddl"
    domain_path.write_text(BLOCKSWORLD_DOMAIN)
    problem_path.write_text(blocksworld_problem(150, seed=1))
    started = time.perf_counter()
    result = plan_task(domain_path, problem_path, PlanOptions(method="pure", timeout=2))
    assert result.status is PlanStatus.OUT_OF_TIME
    assert time.perf_counter() - started < 15  # the deadline is the behaviour: 2 s, bounded generously


@pytest.mark.planner
def test_out_of_memory_is_reported(tmp_path):
    domain_path, problem_path = tmp_path / "domain.pddl", tmp_path / "problem.pddl"
    domain_path.write_text(BLOCKSWORLD_DOMAIN)
    problem_path.write_text(blocksworld_problem(120, seed=1))
    result = plan_task(domain_path, problem_path, PlanOptions(method="pure", timeout=60, memory_limit_mb=60))
    assert result.status is PlanStatus.OUT_OF_MEMORY


@pytest.mark.planner
def test_bad_planner_configuration_is_a_usage_error_before_planning(coffee_files):
    from relevance_plan.errors import UsageError

    domain_path, problem_path = coffee_files
    with pytest.raises(UsageError, match="no-such-alias"):
        plan_task(domain_path, problem_path, PlanOptions(method="pure", planner_config="no-such-alias", timeout=30))


def test_a_planner_that_cannot_start_is_a_clear_error(coffee_files, monkeypatch, tmp_path):
    from relevance_plan.errors import PlannerError
    from relevance_plan.planning.planners.fast_downward import adapter as fast_downward

    monkeypatch.setenv("RELEVANCE_PLAN_FAST_DOWNWARD", str(tmp_path / "absent" / "fast-downward.py"))
    fast_downward.find_fast_downward.cache_clear() if hasattr(fast_downward.find_fast_downward, "cache_clear") else None
    domain_path, problem_path = coffee_files
    with pytest.raises(PlannerError):
        plan_task(domain_path, problem_path, PlanOptions(method="pure", timeout=30))


@pytest.mark.planner
def test_an_anytime_configuration_gives_its_best_plan_to_the_validator(tmp_path):
    domain_path, problem_path = tmp_path / "domain.pddl", tmp_path / "problem.pddl"
    domain_path.write_text(GRIPPER_DOMAIN)
    problem_path.write_text(gripper_problem(3, rooms=3))
    result = plan_task(domain_path, problem_path, PlanOptions(method="pure", planner_config="lama", timeout=60))
    assert_valid_on_original(domain_path, problem_path, result)
    assert result.plan_cost == len(result.plan)  # the last (best) of the numbered plans, complete


# --------------------------------------------------------------------------- one spelling per status


def _status_strings(data, found):
    """Every string held under a key that names a status, anywhere in ``data``."""
    if isinstance(data, dict):
        for key, value in data.items():
            if key.endswith("status") and isinstance(value, str):
                found.append(value)
            _status_strings(value, found)
    elif isinstance(data, list):
        for value in data:
            _status_strings(value, found)
    return found


def _spelling(value: str) -> str:
    return value.lower().replace("_", "-").replace(" ", "-")


def test_every_status_enum_spells_its_values_one_way():
    from relevance_plan.exitcodes import PLAN_STATUS_EXIT
    from relevance_plan.planning.planners.base import PlannerStatus
    from relevance_plan.planning.results import AttemptStatus
    from relevance_plan.planning.validation import ValidationStatus

    values = [status.value for enum in (PlanStatus, AttemptStatus, PlannerStatus, ValidationStatus) for status in enum]
    assert all(value == _spelling(value) for value in values), values
    # the planner's statuses reach an attempt's status unchanged
    assert {status.value for status in PlannerStatus} <= {status.value for status in AttemptStatus}
    # the tool's exit table covers every verdict of `plan`
    assert set(PLAN_STATUS_EXIT) == {status.value for status in PlanStatus}


@pytest.mark.planner
def test_plan_json_spells_every_status_one_way(tmp_path, coffee_domain_path):
    """Several outcomes of `plan --json`; every status string in them is an enum value, spelled one way."""
    from support import invoke

    from relevance_plan.planning.planners.base import PlannerStatus
    from relevance_plan.planning.results import AttemptStatus
    from relevance_plan.planning.validation import ValidationStatus

    coffee = tmp_path / "coffee.pddl"
    coffee.write_text(coffee_problem(extra_plates=2))
    no_cup = tmp_path / "no-cup.pddl"
    text = coffee_problem(plate_on_cup=False).replace("plastic_cup_1 paper_cup_1 - cup", "")
    no_cup.write_text("\n".join(line for line in text.splitlines() if "_cup_1" not in line))
    blocks_domain, blocks = tmp_path / "blocks-domain.pddl", tmp_path / "blocks.pddl"
    blocks_domain.write_text(BLOCKSWORLD_DOMAIN)
    blocks.write_text(blocksworld_problem(150, seed=1))
    # no race: which side decides first is the machine's load, and the first attempt must be the one that fails
    strict = ("--tau-class", "0.2", "--tau-element", "0.85", "--timeout", "60", "--no-race")
    runs = {
        "solved after a failed first attempt": (coffee_domain_path, coffee, *strict),
        "unsolvable": (coffee_domain_path, no_cup, "--timeout", "60"),
        "out of time": (blocks_domain, blocks, "--method", "pure", "--timeout", "2"),
    }
    outputs = {}
    for name, (domain, problem, *options) in runs.items():
        result = invoke("plan", domain, problem, "--json", "--plan-file", tmp_path / "plan", *options)
        outputs[name] = json.loads(result.output)
    assert outputs["solved after a failed first attempt"]["status"] == "solved"
    assert outputs["solved after a failed first attempt"]["first_attempt_status"] == "unsolvable"
    assert outputs["unsolvable"]["status"] == "unsolvable"
    assert outputs["out of time"]["status"] == "out-of-time"

    known = {s.value for enum in (PlanStatus, AttemptStatus, PlannerStatus, ValidationStatus) for s in enum}
    found = [value for data in outputs.values() for value in _status_strings(data, [])]
    assert {"solved", "unsolvable", "out-of-time"} <= set(found)
    assert set(found) <= known, set(found) - known
    spellings: dict[str, set] = {}
    for value in found:
        spellings.setdefault(_spelling(value), set()).add(value)
    assert all(len(values) == 1 for values in spellings.values()), spellings
    # a message quoting the planner's exit code says whose it is, never a bare "(exit code N)"
    message = outputs["out of time"]["message"]
    assert message.startswith("planner: out-of-time (") and "Fast Downward" in message, message
    assert re.search(r"\(exit code -?\d+\)", message) is None


def test_a_failed_first_attempt_costs_no_more_than_its_share(coffee_files):
    # every pruned attempt fails: each may use only its share of the time left, the full problem the rest
    from relevance_plan.planning.attempts import AttemptLoop, run_attempts
    from relevance_plan.planning.planners.base import PlannerStatus, RunOutcome
    from relevance_plan.relevance.analysis.task import PlanningTask
    from relevance_plan.relevance.setup import ScoringOptions, score_problem

    domain_path, problem_path = coffee_files
    task = PlanningTask(*load_task(domain_path, problem_path))
    selection = score_problem(task, ScoringOptions(), domain_path=domain_path).first_selection()
    assert len(selection.kept) < len(task.problem.objects)
    calls = []

    def call_planner(objects, limit):
        calls.append((objects is None, limit))
        status = PlannerStatus.OUT_OF_TIME if objects is None else PlannerStatus.UNSOLVABLE
        return RunOutcome(status=status, exit_code=12, plan=Plan(()), plan_cost=None, wall_time=0.01, planner="fake")

    options = PlanOptions(timeout=60, first_share=0.25)
    attempts, _ = run_attempts(AttemptLoop(task, call_planner, options, time.perf_counter()), selection)
    assert len(attempts) >= 2 and calls[-1][0]  # widened until the full problem was planned
    assert not calls[0][0] and calls[0][1] <= 60 * 0.25 + 0.01
    for full, limit in calls:
        if not full:
            assert limit <= 60 * 0.25 + 0.01
    assert calls[-1][1] > 60 * (1 - 0.25) - 1  # what is left for the full problem


@pytest.mark.planner
def test_a_run_pauses_the_garbage_collector_and_resumes_it(coffee_files):
    """The collector's passes over a big problem's facts cost a third of the pruning: a run pauses
    it (its facts form no cycle) and gives it back, enabled, however the run ends."""
    import gc

    domain_path, problem_path = coffee_files
    seen = []
    assert gc.isenabled()
    result = plan_task(
        domain_path, problem_path, PlanOptions(timeout=60), progress=lambda _: seen.append(gc.isenabled())
    )
    assert result.status is PlanStatus.SOLVED
    assert seen and not any(seen)
    assert gc.isenabled()
    with pytest.raises(RelevancePlanError):
        plan_task(domain_path, problem_path.with_name("missing.pddl"), PlanOptions(timeout=60))
    assert gc.isenabled()


def _negative_literals_problem(blocks: int) -> str:
    """Blocks x1..xN on the table, each also stated not held (a negative literal, true anyway under the
    closed world); the goal names three of them."""
    names = [f"x{i}" for i in range(1, blocks + 1)]
    init = ["(handempty)", *(f"(ontable {n}) (clear {n}) (not (holding {n}))" for n in names)]
    return (
        f"(define (problem negative-literals) (:domain blocksworld)\n  (:objects {' '.join(names)})\n"
        "  (:init\n    " + "\n    ".join(init) + ")\n  (:goal (and (on x1 x2) (on x2 x3))))\n"
    )


@pytest.mark.planner
@pytest.mark.parametrize("flat", [False, True], ids=["list-reading", "flat-reading"])
def test_negative_initial_literals_of_pruned_objects_are_cut_and_plan_solves_at_once(tmp_path, monkeypatch, flat):
    from support import DOMAINS, run

    from relevance_plan.pddl import parser

    # a big :init is read with string methods, the negative literals being entries between its stretches
    monkeypatch.setattr(parser, "FLAT_INIT_FROM", 1 if flat else 10**9)
    domain = DOMAINS / "blocksworld" / "domain.pddl"
    problem = tmp_path / "negative.pddl"
    problem.write_text(_negative_literals_problem(40))
    pruned = tmp_path / "pruned.pddl"
    code, _, stderr = run("prune", domain, problem, "-o", pruned)
    assert code == 0, stderr
    _, kept = load_task(domain, pruned)
    assert 3 <= len(kept.objects) < 40
    held = set(re.findall(r"\(not \(holding (\w+)\)\)", pruned.read_text()))
    assert held == set(kept.objects), "a negative literal about a pruned object stayed (or a kept one's went)"
    code, stdout, stderr = run("plan", domain, problem, "--no-race", "--json", "-q", "--plan-file", tmp_path / "plan")
    result = json.loads(stdout)
    assert code == 0 and result["status"] == "solved", stderr
    assert result["pruned"] and result["attempts"] == 1, result["attempt_log"]


class _Stop(Exception):
    """Stands for the CLI's last alarm: raised from the run's own report of a step."""


def _stopping_at(prefix: str):
    def progress(event) -> None:
        if event.message.startswith(prefix):
            raise _Stop(event.message)

    return progress


@pytest.mark.parametrize(
    "step, method, kept",
    [
        ("scoring", "relevance", None),  # the problem is read, no selection yet
        ("kept", "relevance", "selection"),  # the selection is made, no attempt started
        ("attempt 1", "relevance", "selection"),  # the first attempt under way
        ("attempt 1", "pure", "all"),
    ],
)
def test_a_run_stopped_anywhere_reports_the_counts_it_had_established(coffee_files, step, method, kept):
    from relevance_plan.planning.results import RunRecord

    record = RunRecord(method, _stopping_at(step))
    with pytest.raises(_Stop):
        plan_task(*coffee_files, PlanOptions(method=method, timeout=60, race=False), record=record)
    result = record.stopped(f"stopped {record.where()}")
    assert result.status is PlanStatus.OUT_OF_TIME
    assert result.objects_total == len(load_task(*coffee_files)[1].objects)
    if kept is None:
        assert result.objects_kept is None
    elif kept == "selection":
        assert result.selection is not None and result.objects_kept == len(result.selection.kept) < result.objects_total
    else:
        assert result.objects_kept == result.objects_total
    data = result.to_json()
    assert data["objects_total"] == result.objects_total and data["objects_kept"] == result.objects_kept
    if step == "attempt 1":  # the attempt under way is listed, cut short
        assert [a["status"] for a in data["attempt_log"]] == ["out-of-time"]
        assert data["attempt_log"][0]["objects_kept"] == result.objects_kept
    else:
        assert data["attempt_log"] == []


def test_a_run_stopped_while_reading_says_it_counted_nothing(coffee_files):
    from relevance_plan.planning.results import RunRecord

    record = RunRecord("relevance")
    result = record.stopped(f"stopped {record.where()}")
    assert result.objects_total is None and result.objects_kept is None
    assert result.message == "stopped while reading the domain and problem"
    assert result.to_json()["objects_total"] is None


def test_plan_task_takes_progress_or_a_record_not_both(coffee_files):
    from relevance_plan.planning.results import RunRecord

    with pytest.raises(RelevancePlanError, match="not both"):
        plan_task(*coffee_files, PlanOptions(), progress=print, record=RunRecord("relevance"))


def test_a_run_on_input_our_reader_refuses_stopped_counts_nothing():
    from relevance_plan.planning.results import RunRecord

    record = RunRecord("relevance")
    record.unread("our reader refuses the input: PDDL+")
    record.attempting(1, None, 10.0)
    result = record.stopped("stopped")
    assert result.objects_total is None and result.objects_kept is None  # not 0 of 0: never counted
    assert result.unpruned_reason == "our reader refuses the input: PDDL+"
    assert [a.status.value for a in result.attempts] == ["out-of-time"]
