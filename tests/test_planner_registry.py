"""The planner registry: every adapter kind inside the one validated attempt loop."""

from __future__ import annotations

import dataclasses
import time
from dataclasses import dataclass, field
from pathlib import Path

import pytest
from click.testing import CliRunner
from support import planner_script, running

from relevance_plan.cli import main
from relevance_plan.errors import PlannerError, UnsupportedFeatureError, UsageError
from relevance_plan.exitcodes import ExitCode
from relevance_plan.generators.padded import GRIPPER_DOMAIN, gripper_problem
from relevance_plan.pddl.plans import Plan
from relevance_plan.planning.options import PlanOptions
from relevance_plan.planning.planners import auto
from relevance_plan.planning.planners.auto import FallbackPlanner
from relevance_plan.planning.planners.base import PlannerStatus, RunOutcome, parse_ipc_plan
from relevance_plan.planning.planners.command import CommandPlanner
from relevance_plan.planning.planners.registry import make_planner, split_planner_names
from relevance_plan.planning.planners.up import adapter as up_engines
from relevance_plan.planning.results import PlanStatus
from relevance_plan.planning.run import plan_task


@pytest.fixture
def coffee_extra_plates():
    """``coffee_files`` (conftest.py) with three extra plates."""
    return 3


@pytest.fixture
def gripper_files(tmp_path):
    domain = tmp_path / "gripper.pddl"
    domain.write_text(GRIPPER_DOMAIN)
    problem = tmp_path / "gripper-p.pddl"
    problem.write_text(gripper_problem(extra=6, rooms=3))
    return domain, problem


# A planner that asks Fast Downward and prints its plan on stdout: a real plan from a foreign binary.
FD_ON_STDOUT = """
    import subprocess, sys, tempfile, os
    from relevance_plan.planning.planners.fast_downward.adapter import run_fast_downward
    outcome = run_fast_downward(sys.argv[1], sys.argv[2], time_limit=60)
    for step in outcome.plan:
        print(step)
    print("; a comment line")
"""


FD_TO_FILE = """
    import sys
    from relevance_plan.planning.planners.fast_downward.adapter import run_fast_downward
    outcome = run_fast_downward(sys.argv[1], sys.argv[2], time_limit=60)
    with open(sys.argv[3], "w") as out:
        out.write("; found by a planner writing to its plan file\\n")
        out.write("".join(str(step) + "\\n" for step in outcome.plan))
    print("planner chatter that is not a plan")
"""


# --------------------------------------------------------------------------- names


def test_planner_names_are_parsed_and_checked():
    assert make_planner("fast-downward").name == "fast-downward"
    assert make_planner("up:pyperplan").name == "up:pyperplan"
    assert make_planner("cmd:plan {domain} {problem}").name == "cmd:plan {domain} {problem}"
    for bad in ("nope", "fast-downward:x", "up:", "cmd:"):
        with pytest.raises(UsageError, match="unknown planner"):
            make_planner(bad)
    assert split_planner_names("fast-downward, up:pyperplan,cmd:p {domain},{problem}") == (
        "fast-downward",
        "up:pyperplan",
        "cmd:p {domain},{problem}",
    )


def test_command_templates_are_checked_before_running(tmp_path):
    with pytest.raises(UsageError, match=r"needs \{problem\}"):
        make_planner("cmd:true {domain}", check=True)
    with pytest.raises(UsageError, match="unknown placeholder"):
        make_planner("cmd:true {domain} {problem} {out}", check=True)
    with pytest.raises(PlannerError, match="not found: no-such-planner-binary"):
        make_planner("cmd:no-such-planner-binary {domain} {problem}", check=True)


def test_ipc_plans_are_parsed_and_garbage_is_refused():
    plan = parse_ipc_plan("(pick A b)\n; cost = 3 (unit cost)\n\n0: (drop a b) [1]\n")
    assert [str(step) for step in plan] == ["(pick a b)", "(drop a b)"] and plan.cost == 3
    assert parse_ipc_plan("Solution found!\n(pick a b)\n") is None


# --------------------------------------------------------------------------- planner-agnostic core

PLANNER_WORDS = (
    "fast-downward",
    "fast downward",
    "fast_downward",
    "downward",
    "lama",
    "pyperplan",
    "lpg",
    "symk",
    "up:",
    "cmd:",
    "sas_plan",
)


@pytest.mark.parametrize("module", ["options", "attempts", "run", "summary", "results", "methods"])
def test_the_attempt_loop_names_no_planner(module):
    import importlib

    text = Path(importlib.import_module(f"relevance_plan.planning.{module}").__file__).read_text().lower()
    assert [word for word in PLANNER_WORDS if word in text] == []


DURATIVE_DOMAIN = """
(define (domain timed) (:requirements :durative-actions :typing)
  (:types thing)
  (:predicates (ready ?t - thing) (done ?t - thing))
  (:durative-action work :parameters (?t - thing) :duration (= ?duration 2)
    :condition (at start (ready ?t))
    :effect (at end (done ?t))))
"""

DURATIVE_PROBLEM = "(define (problem p) (:domain timed) (:objects a - thing) (:init (ready a)) (:goal (done a)))"


def _task(tmp_path, domain_text, problem_text):
    from relevance_plan.io import load_task

    domain_path, problem_path = tmp_path / "domain.pddl", tmp_path / "problem.pddl"
    domain_path.write_text(domain_text)
    problem_path.write_text(problem_text)
    return load_task(domain_path, problem_path)


def test_check_refuses_what_the_planner_does_not_take_in_one_line(tmp_path, coffee_files):
    from relevance_plan.io import load_task

    domain, problem = load_task(*coffee_files)
    with pytest.raises(UnsupportedFeatureError) as refused:
        make_planner("up:pyperplan").check(domain, problem)
    message = str(refused.value)
    assert "negative-preconditions" in message and "up:pyperplan" in message and "\n" not in message
    make_planner("fast-downward").check(domain, problem)  # Fast Downward takes them
    make_planner("cmd:any-planner {domain} {problem}").check(domain, problem)  # unknown: the planner decides
    domain, problem = _task(tmp_path, DURATIVE_DOMAIN, DURATIVE_PROBLEM)
    with pytest.raises(UnsupportedFeatureError, match="Fast Downward does not take durative-actions") as refused:
        make_planner("fast-downward").check(domain, problem)
    assert "\n" not in str(refused.value) and str(tmp_path / "domain.pddl") in str(refused.value)


def test_check_still_refuses_names_fast_downward_cannot_read(tmp_path):
    domain, problem = _task(tmp_path, GRIPPER_DOMAIN, gripper_problem(extra=1).replace("left", "gauche_é"))
    with pytest.raises(UnsupportedFeatureError, match="non-ASCII name, which Fast Downward does not accept"):
        make_planner("fast-downward").check(domain, problem)
    make_planner("up:pyperplan").check(domain, problem)


FEATURE_CASES = [
    ("(:action a :parameters (?x) :precondition (p ?x) :effect (q ?x))", {"strips"}),
    (
        "(:action a :parameters (?x - t) :precondition (not (p ?x)) :effect (q ?x))",
        {"typing", "negative-preconditions"},
    ),
    (
        "(:action a :parameters (?x) :precondition (or (p ?x) (= ?x ?x)) :effect (q ?x))",
        {"disjunctive-preconditions", "equality"},
    ),
    (
        "(:action a :parameters () :precondition (exists (?x) (p ?x)) :effect (forall (?y) (when (p ?y) (q ?y))))",
        {"existential-preconditions", "conditional-effects"},
    ),
    # for all x: not (p x)
    (
        "(:action a :parameters () :precondition (not (exists (?x) (p ?x))) :effect (q c))",
        {"universal-preconditions", "negative-preconditions"},
    ),
    (
        "(:action a :parameters (?x) :precondition (p ?x) :effect (and (q ?x) (increase (total-cost) 1)))",
        {"action-costs"},
    ),
    ("(:action a :parameters (?x) :precondition (> (f ?x) 0) :effect (decrease (f ?x) 1))", {"numeric-fluents"}),
    (
        "(:derived (r ?x) (p ?x)) (:action a :parameters (?x) :precondition (r ?x) :effect (q ?x))",
        {"derived-predicates"},
    ),
]


@pytest.mark.parametrize("body, expected", FEATURE_CASES)
def test_problem_features_come_from_what_the_files_use(tmp_path, body, expected):
    from relevance_plan.planning.planners.requirements import problem_features

    types = "(:types t)" if " - t" in body else ""
    domain_text = (
        f"(define (domain d) (:requirements :adl :typing :action-costs :numeric-fluents :derived-predicates) {types}"
        " (:constants c) (:predicates (p ?x) (q ?x) (r ?x)) (:functions (total-cost) (f ?x)) " + body + ")"
    )
    domain, problem = _task(tmp_path, domain_text, "(define (problem p) (:domain d) (:init) (:goal (q c)))")
    assert problem_features(domain, problem) == frozenset({"strips"} | expected)


def test_problem_features_of_durative_and_timed_problems(tmp_path):
    from relevance_plan.planning.planners.requirements import problem_features

    timed = DURATIVE_PROBLEM.replace("(:init (ready a))", "(:init (at 5 (ready a)))")
    domain, problem = _task(tmp_path, DURATIVE_DOMAIN.replace(":typing", ":typing :timed-initial-literals"), timed)
    assert problem_features(domain, problem) == {"strips", "typing", "durative-actions", "timed-initial-literals"}


def test_either_types_are_told_apart_by_where_they_are_and_auto_chooses_a_planner_that_reads_them():
    from relevance_plan.planning.planners import auto
    from relevance_plan.planning.planners import requirements as f

    assert auto.choose(frozenset({f.STRIPS, f.TYPING, f.EITHER_PREDICATE_TYPES}), "").planner.name == "fast-downward"
    with pytest.raises(UnsupportedFeatureError, match="no planner this tool knows takes .*either-object-types"):
        auto.choose(frozenset({f.STRIPS, f.TYPING, f.EITHER_OBJECT_TYPES}), "")  # LPG's reader refuses it too
    either = frozenset({f.STRIPS, f.TYPING, f.EITHER_TYPES})
    if not auto.LPG.installed():
        with pytest.raises(UnsupportedFeatureError, match="either-types"):
            auto.choose(either, "")
        return
    chosen = auto.choose(either, "")
    assert chosen.planner.name == "lpg" and "fast-downward does not take either-types" in chosen.reason


# --------------------------------------------------------------------------- each adapter's exit codes


def test_one_unified_planning_table_keyed_by_status_names():
    from unified_planning.engines.results import PlanGenerationResultStatus

    names = {status.name for status in PlanGenerationResultStatus}
    assert set(up_engines.UP_STATUS) <= names
    # every verdict an engine can end a one-shot run with is in the table
    assert names - set(up_engines.UP_STATUS) == {"INTERMEDIATE"}
    assert up_engines.up_status_name(PlannerStatus.SOLVED) == "SOLVED_SATISFICING"
    assert up_engines.up_status_name(PlannerStatus.INPUT_ERROR) == "INTERNAL_ERROR"
    for name, status in up_engines.UP_STATUS.items():
        if name != "SOLVED_OPTIMALLY":
            assert up_engines.up_status_name(status) == name


def test_the_unified_planning_child_is_classified_by_its_verdict():
    classify = up_engines.classify
    assert classify(0, "SOLVED_SATISFICING", True, False, "") is PlannerStatus.SOLVED
    assert classify(0, "SOLVED_SATISFICING", False, False, "") is PlannerStatus.PLANNER_CRASH  # no plan written
    assert classify(0, "TIMEOUT", False, False, "") is PlannerStatus.OUT_OF_TIME
    assert classify(0, "UNSUPPORTED_PROBLEM", False, False, "") is PlannerStatus.UNSUPPORTED
    assert classify(up_engines.CHILD_CANNOT_READ, None, False, False, "") is PlannerStatus.INPUT_ERROR
    assert classify(-9, None, False, True, "") is PlannerStatus.OUT_OF_TIME  # the watchdog
    assert classify(1, None, False, False, "Traceback ... MemoryError") is PlannerStatus.OUT_OF_MEMORY
    assert classify(1, None, False, False, "Traceback") is PlannerStatus.PLANNER_CRASH
    assert up_engines.exit_reason("up:x", 0, "MEMOUT", False) == "up:x: unified-planning status MEMOUT"
    assert up_engines.exit_reason("up:x", -9, None, False) == "up:x child process exit code -9: killed by SIGKILL"


def test_an_external_command_is_classified_by_its_exit_and_output():
    from relevance_plan.pddl.plans import Plan, PlanStep
    from relevance_plan.planning.planners.command import classify, exit_reason
    from relevance_plan.supervision.process import ProcessRun

    def run(code, fired=False):
        return ProcessRun(0, code, 0.0, 0.0, fired, 1.0, 1)

    plan = Plan((PlanStep("a"),))
    assert classify(run(0), plan, False, "") is PlannerStatus.SOLVED
    assert classify(run(0), Plan(), False, "") is PlannerStatus.SEARCH_INCOMPLETE  # said nothing
    assert classify(run(0), Plan(), True, "") is PlannerStatus.SOLVED  # an empty plan file: the goal holds
    assert classify(run(0), None, False, "") is PlannerStatus.PLANNER_CRASH  # output is not a plan
    assert classify(run(3), plan, False, "") is PlannerStatus.PLANNER_CRASH
    assert classify(run(1), None, False, "MemoryError") is PlannerStatus.OUT_OF_MEMORY
    assert classify(run(-9, fired=True), None, False, "") is PlannerStatus.OUT_OF_TIME
    assert exit_reason("ff", run(3), None) == "ff exit code 3"
    assert exit_reason("ff", run(-11), None) == "ff exit code -11: killed by SIGSEGV"


# --------------------------------------------------------------------------- cmd: inside the loop


@pytest.mark.planner
@pytest.mark.parametrize(
    "files, body, arguments",
    [
        ("coffee_files", FD_ON_STDOUT, "{domain} {problem}"),  # the plan on standard output
        ("gripper_files", FD_TO_FILE, "{domain} {problem} {plan}"),  # a classic problem, the plan in a file
    ],
)
def test_an_external_command_s_plan_is_validated_on_the_original(tmp_path, request, files, body, arguments):
    domain, problem = request.getfixturevalue(files)
    planner = f"cmd:{planner_script(tmp_path, 'external', body)} {arguments}"
    result = plan_task(domain, problem, PlanOptions(planner=planner, timeout=60))
    assert result.status is PlanStatus.SOLVED, result.message
    assert result.valid and result.planner == planner
    assert result.objects_kept < result.objects_total


@pytest.mark.planner
@pytest.mark.parametrize(
    "body, planner_status, plan_status",
    [
        ("print('I found it, trust me')\n", PlannerStatus.PLANNER_CRASH, PlanStatus.PLANNER_ERROR),
        ("import sys\nprint('segfault-ish')\nsys.exit(3)\n", PlannerStatus.PLANNER_CRASH, PlanStatus.PLANNER_ERROR),
        ("print('(serve alice nothing)')\n", PlannerStatus.SOLVED, PlanStatus.NO_VALID_PLAN),
    ],
)
def test_misbehaving_commands_get_the_right_outcome_and_the_loop_carries_on(
    tmp_path, coffee_files, body, planner_status, plan_status
):
    domain, problem = coffee_files
    planner = "cmd:" + planner_script(tmp_path, "bad", body) + " {domain} {problem}"
    result = plan_task(domain, problem, PlanOptions(planner=planner, timeout=30))
    assert result.status is plan_status
    statuses = [a.outcome.status for a in result.attempts]
    assert set(statuses) == {planner_status}
    # the loop went on to the full problem rather than stopping at the pruned one
    assert len(result.attempts) >= 2 and result.attempts[-1].full
    if plan_status is PlanStatus.NO_VALID_PLAN:
        assert all(a.validation is not None and not a.validation.valid for a in result.attempts)


@pytest.mark.planner
def test_a_hanging_command_is_killed_with_its_children(tmp_path, coffee_files):
    domain, problem = coffee_files
    marker = tmp_path / "child.pid"
    body = f"""
    import subprocess, time
    child = subprocess.Popen(["sleep", "300"])
    open({str(marker)!r}, "w").write(str(child.pid))
    time.sleep(300)
    """
    planner = CommandPlanner(planner_script(tmp_path, "hang", body) + " {domain} {problem}")
    outcome = planner.run(str(domain), str(problem), time_limit=2.0, memory_limit_mb=None)
    assert outcome.status is PlannerStatus.OUT_OF_TIME and outcome.killed_by_watchdog, outcome
    assert outcome.wall_time < 30
    assert marker.is_file(), outcome.log_tail
    child = int(marker.read_text())
    deadline = time.monotonic() + 5
    while running(child) and time.monotonic() < deadline:
        time.sleep(0.05)
    assert not running(child)  # the planner's own child died with its group


def test_plan_command_takes_a_planner_and_refuses_a_bad_one(tmp_path, coffee_files):
    domain, problem = coffee_files
    runner = CliRunner()
    bad = runner.invoke(main, ["plan", str(domain), str(problem), "--planner", "cmd:true {domain}"])
    assert bad.exit_code == ExitCode.USAGE
    assert bad.output.count("\n") == 1 and "needs {problem}" in bad.output
    missing = runner.invoke(main, ["plan", str(domain), str(problem), "--planner", "cmd:nope-bin {domain} {problem}"])
    assert missing.exit_code == ExitCode.PLANNER and "not found: nope-bin" in missing.output
    unknown = runner.invoke(main, ["plan", str(domain), str(problem), "--planner", "ff"])
    assert unknown.exit_code == ExitCode.USAGE and "unknown planner 'ff'" in unknown.output


# --------------------------------------------------------------------------- up:NAME


@pytest.mark.planner
@pytest.mark.parametrize("files", ["coffee_files", "gripper_files"])
def test_unified_planning_engine_in_a_child_process(request, files):
    pytest.importorskip("up_lpg")
    domain, problem = request.getfixturevalue(files)
    result = plan_task(domain, problem, PlanOptions(planner="up:lpg", timeout=120))
    assert result.status is PlanStatus.SOLVED, result.message
    assert result.valid and result.planner == "up:lpg"


@pytest.mark.planner
def test_pyperplan_solves_a_classic_problem_and_refuses_features_it_lacks(gripper_files, tmp_path):
    pytest.importorskip("up_pyperplan")
    domain, problem = gripper_files
    result = plan_task(domain, problem, PlanOptions(planner="up:pyperplan", timeout=120))
    assert result.status is PlanStatus.SOLVED, result.message
    assert result.valid and result.compilations == ()
    # durative actions, which pyperplan cannot take and nothing compiles away: refused before any attempt
    # (negative preconditions are compiled away: see test_planner_options.py)
    (tmp_path / "timed").mkdir()
    domain, problem = tmp_path / "timed" / "domain.pddl", tmp_path / "timed" / "problem.pddl"
    domain.write_text(DURATIVE_DOMAIN)
    problem.write_text(DURATIVE_PROBLEM)
    with pytest.raises(UnsupportedFeatureError, match="up:pyperplan does not take durative-actions") as refused:
        plan_task(domain, problem, PlanOptions(planner="up:pyperplan", timeout=120))
    assert "\n" not in str(refused.value) and str(domain) in str(refused.value)


@pytest.mark.planner
def test_an_engine_that_refuses_in_its_child_is_unsupported_after_one_attempt(coffee_files, monkeypatch):
    """An engine whose features are unknown decides itself; its refusal ends the loop with a clear verdict."""
    pytest.importorskip("up_pyperplan")
    monkeypatch.delitem(up_engines.ENGINE_FEATURES, "pyperplan")
    domain, problem = coffee_files
    refused = plan_task(domain, problem, PlanOptions(planner="up:pyperplan", timeout=120))
    assert refused.status is PlanStatus.UNSUPPORTED and len(refused.attempts) == 1
    assert refused.attempts[0].outcome.reason == "up:pyperplan: unified-planning status UNSUPPORTED_PROBLEM"
    assert "(up:pyperplan: unified-planning status UNSUPPORTED_PROBLEM)" in refused.message


def test_an_engine_that_is_not_installed_names_the_extra():
    with pytest.raises(UsageError, match=r"relevance-plan\[planners\]"):
        make_planner("up:no-such-engine", check=True)


# --------------------------------------------------------------------------- compare --planners


@pytest.mark.planner
def test_compare_with_two_planners_resumes_and_reports_per_planner(tmp_path):
    pytest.importorskip("up_lpg")
    from relevance_plan.generators import WORLDS, Settings

    suite = tmp_path / "coffee-simple"
    WORLDS["coffee"].suite(1, 5, suite, Settings("simple", distractors=3))
    store = tmp_path / "results.sqlite"
    arguments = [
        "compare",
        str(suite),
        "--methods",
        "pure,relevance",
        "--planners",
        "fast-downward,up:lpg",
        "--timeout",
        "120",
        "--store",
        str(store),
        "--quiet",
    ]
    runner = CliRunner()
    first = runner.invoke(main, arguments)
    assert first.exit_code == 0, first.output
    assert "4 jobs: 0 already stored, 4 run (4 solved)" in first.output
    again = runner.invoke(main, arguments)
    assert again.exit_code == 0 and "4 jobs: 4 already stored, 0 run" in again.output
    report = runner.invoke(main, ["report", str(store)])
    assert "coffee-simple [fast-downward]" in report.output and "coffee-simple [up:lpg]" in report.output
    bad = runner.invoke(main, ["compare", str(suite), "--planners", "fast-downward,nope", "--store", str(store)])
    assert bad.exit_code == ExitCode.USAGE and "unknown planner 'nope'" in bad.output


@dataclass(frozen=True)
class _Scripted:
    """A planner that ends as told, after ``seconds``, and records the time limit it was given."""

    name: str
    status: PlannerStatus
    seconds: float = 0.0
    limits: list = field(default_factory=list)
    features: frozenset | None = None

    def check_installed(self) -> None: ...

    def check(self, domain, problem) -> None: ...

    def version(self) -> str:
        return self.name

    def run(self, domain_path, problem_path, *, time_limit, memory_limit_mb) -> RunOutcome:
        self.limits.append(time_limit)
        time.sleep(self.seconds)
        return RunOutcome(
            status=self.status,
            exit_code=0,
            plan=Plan(()),
            plan_cost=None,
            wall_time=self.seconds,
            planner=self.name,
            reason=f"{self.name} said so",
        )


def test_auto_runs_the_next_planner_when_the_first_gives_up_without_an_answer():
    crashing, solving = _Scripted("lpg", PlannerStatus.PLANNER_CRASH, 0.2), _Scripted("up:aries", PlannerStatus.SOLVED)
    outcome = FallbackPlanner(crashing, (solving,)).run("d", "p", time_limit=10.0, memory_limit_mb=None)
    assert outcome.status is PlannerStatus.SOLVED and outcome.planner == "up:aries"
    assert "lpg gave up (lpg said so)" in outcome.reason
    assert 9.0 < solving.limits[0] < 9.9  # the time the first one left
    # a proof, or too little time left, ends it: the next planner never starts
    proof = _Scripted("lpg", PlannerStatus.UNSOLVABLE)
    late = _Scripted("lpg", PlannerStatus.SEARCH_INCOMPLETE, 0.2)
    for first, limit in ((proof, 10.0), (late, 1.1)):
        unused = _Scripted("up:aries", PlannerStatus.SOLVED)
        outcome = FallbackPlanner(first, (unused,)).run("d", "p", time_limit=limit, memory_limit_mb=None)
        assert outcome.status is first.status and not unused.limits


def test_auto_chains_the_installed_planners_of_a_family_and_one_alone_runs_as_itself(monkeypatch):
    uses = frozenset({"strips", "durative-actions"})
    lpg, aries = (dataclasses.replace(c, installed=lambda: True) for c in (auto.LPG, auto.ARIES))
    monkeypatch.setattr(auto, "TEMPORAL_ORDER", (lpg, aries))
    monkeypatch.setattr(auto, "EVERY", (auto.FAST_DOWNWARD, lpg, aries))
    choice = auto.choose(uses, "lama-first")
    assert isinstance(choice.planner, FallbackPlanner) and choice.planner.name == "lpg"
    assert [p.name for p in choice.planner.then] == ["up:aries"] and "then up:aries" in choice.reason
    alone = dataclasses.replace(aries, installed=lambda: False)
    monkeypatch.setattr(auto, "TEMPORAL_ORDER", (lpg, alone))
    monkeypatch.setattr(auto, "EVERY", (auto.FAST_DOWNWARD, lpg, alone))
    assert not isinstance(auto.choose(uses, "lama-first").planner, FallbackPlanner)
