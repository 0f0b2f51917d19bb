"""Never refuse what a planner can solve: input that cannot be pruned is planned (or passed through) whole.

Also: ``--validator none`` is the only way to report a plan that no validator checked, and a
planner that needs Java says so in one line when it is missing.
"""

from __future__ import annotations

import json
import shutil
import stat
import sys
import textwrap
from pathlib import Path

import pytest
from support import one_line_error, run, task_fixture

from relevance_plan.errors import PlannerError, UnsupportedFeatureError
from relevance_plan.exitcodes import ExitCode
from relevance_plan.planning.options import PlanOptions
from relevance_plan.planning.planners import auto
from relevance_plan.planning.planners.up import adapter as up_engines
from relevance_plan.planning.results import PlanStatus
from relevance_plan.planning.run import plan_task

JAVA_MISSING = "Java runtime not found: apt-get install default-jre-headless"

# PDDL+: a process our reader refuses; ENHSP (through unified-planning) plans it.
TANK_DOMAIN = """
(define (domain tank)
  (:requirements :typing :numeric-fluents :negative-preconditions)
  (:types tank)
  (:predicates (filling ?t - tank) (full ?t - tank))
  (:functions (level ?t - tank))
  (:action open-valve :parameters (?t - tank) :precondition (not (filling ?t)) :effect (filling ?t))
  (:action close-valve :parameters (?t - tank)
    :precondition (and (filling ?t) (>= (level ?t) 10))
    :effect (and (not (filling ?t)) (full ?t)))
  (:process fill :parameters (?t - tank) :precondition (filling ?t)
    :effect (increase (level ?t) (* #t 2))))
"""
TANK_PROBLEM = """
(define (problem tank-1) (:domain tank) (:objects t1 t2 - tank)
  (:init (= (level t1) 0) (= (level t2) 0)) (:goal (full t1)))
"""

MOVE_DOMAIN = """
(define (domain move) (:requirements :strips :typing)
  (:types place)
  (:predicates (at ?p - place) (road ?a ?b - place))
  (:action move :parameters (?a ?b - place) :precondition (and (at ?a) (road ?a ?b))
    :effect (and (not (at ?a)) (at ?b))))
"""
MOVE_PROBLEM = """
(define (problem move-1) (:domain move) (:objects a b c d e - place)
  (:init (at a) (road a b) (road c d) (road d e)) (:goal (at b)))
"""


def script(tmp_path: Path, name: str, body: str) -> str:
    """An executable Python script standing in for an external planner."""
    path = tmp_path / name
    path.write_text(f"#!{sys.executable}\n" + textwrap.dedent(body))
    path.chmod(path.stat().st_mode | stat.S_IXUSR)
    return str(path)


def stub(tmp_path: Path, *steps: str) -> str:
    """``cmd:`` a planner that prints ``steps`` as its plan, whatever the problem."""
    lines = "".join(f"print({step!r})\n" for step in ("; a stub planner", *steps))
    return "cmd:" + script(tmp_path, "stub-planner", lines) + " {domain} {problem}"


tank_files = task_fixture("tank", TANK_DOMAIN, TANK_PROBLEM)


move_files = task_fixture("move", MOVE_DOMAIN, MOVE_PROBLEM)


# --------------------------------------------------------------------------- plan: input the reader refuses


@pytest.mark.planner
def test_plan_runs_a_pddl_plus_problem_whole_and_says_it_could_not_validate(tmp_path, tank_files):
    planner = stub(tmp_path, "0.0: (open-valve t1)", "5.0: (close-valve t1)")
    code, stdout, stderr = run("plan", *tank_files, "--planner", planner, "--json", "--plan-file", tmp_path / "p")
    assert code == ExitCode.VALIDATOR, stderr
    data = json.loads(stdout)
    assert data["status"] == "validator-unavailable" and not data["valid"] and data["plan_file"] is None
    assert data["pruned"] is False and "':process' (PDDL+) is not supported" in data["unpruned_reason"]
    assert data["attempts"] == 1 and data["attempt_log"][0]["planner_status"] == "solved"
    assert "NO VALIDATOR COULD RUN" in data["message"] and "our reader refuses the input" in data["message"]
    assert not (tmp_path / "p").exists()  # an unvalidated plan is never written as a result

    code, stdout, stderr = run("plan", *tank_files, "--planner", planner, "--plan-file", tmp_path / "p")
    assert code == ExitCode.VALIDATOR
    assert "... pruned: no (our reader refuses the input:" in stderr and "tank.pddl:" in stderr
    assert stderr.rstrip().splitlines()[-1].startswith("relevance-plan: validator-unavailable:")


@pytest.mark.planner
def test_validator_none_reports_the_plan_not_validated_and_succeeds(tmp_path, tank_files):
    planner = stub(tmp_path, "0.0: (open-valve t1)", "5.0: (close-valve t1)")
    code, stdout, stderr = run(
        "plan", *tank_files, "--planner", planner, "--validator", "none", "--plan-file", tmp_path / "p"
    )
    assert code == 0, stderr
    assert "objects:     all (pruned: no, our reader refuses the input:" in stdout
    assert "plan:        2 steps, NOT validated (--validator none)" in stdout
    assert (tmp_path / "p").read_text() == "0.000: (open-valve t1)\n5.000: (close-valve t1)\n"
    result = plan_task(*tank_files, PlanOptions(planner=planner, validators=("none",), timeout=30))
    assert result.status is PlanStatus.SOLVED and not result.valid
    assert result.to_json()["validation"] == "not-validated" and result.to_json()["validator"] == "none"


def test_validator_none_cannot_be_combined_with_a_validator(move_files):
    code, _, stderr = run("plan", *move_files, "--validator", "none", "--validator", "builtin", "--plan-file", "-")
    assert code == ExitCode.USAGE
    assert "--validator none means no validation" in one_line_error(stderr)


@pytest.mark.planner
def test_a_plan_no_validator_can_check_is_exit_41_never_solved(tmp_path, move_files):
    domain, problem = move_files
    constrained = MOVE_PROBLEM.replace("(:goal (at b))", "(:goal (at b)) (:constraints (always (not (at c))))")
    problem.write_text(constrained)
    planner = stub(tmp_path, "(move a b)")
    code, stdout, stderr = run("plan", domain, problem, "--planner", planner, "--json", "--plan-file", tmp_path / "p")
    assert code == ExitCode.VALIDATOR, stderr
    data = json.loads(stdout)
    assert data["status"] == "validator-unavailable" and "trajectory constraints" in data["message"]
    code, stdout, _ = run(
        "plan", domain, problem, "--planner", planner, "--validator", "none", "--json", "--plan-file", tmp_path / "p"
    )
    assert code == 0 and json.loads(stdout)["validation"] == "not-validated"


# --------------------------------------------------------------------------- plan: the analysis refuses


@pytest.mark.planner
def test_plan_plans_the_full_problem_when_the_analysis_refuses(tmp_path, move_files, monkeypatch):
    import relevance_plan.planning.run as run

    def refuse(*args, **kwargs):
        raise UnsupportedFeatureError("a construct the analysis does not know")

    monkeypatch.setattr(run, "score_problem", refuse)
    messages = []
    result = plan_task(
        *move_files,
        PlanOptions(planner=stub(tmp_path, "(move a b)"), timeout=30),
        progress=lambda event: messages.append(event.message),
    )
    assert result.status is PlanStatus.SOLVED and result.valid, result.message
    assert not result.pruned and result.objects_kept == result.objects_total == 5
    reason = "the relevance analysis does not take this input: a construct the analysis does not know"
    assert result.to_json()["unpruned_reason"] == reason
    assert f"pruned: no ({reason}); planning the full problem" in messages


# --------------------------------------------------------------------------- prune --pass-through


def test_prune_refuses_unprunable_input_in_one_line_unless_asked_to_pass_it_through(tmp_path, tank_files):
    out = tmp_path / "small.pddl"
    code, _, stderr = run("prune", *tank_files, "-o", out)
    assert code == ExitCode.UNSUPPORTED_PDDL
    assert "':process' (PDDL+) is not supported" in one_line_error(stderr) and not out.exists()

    code, stdout, stderr = run("prune", *tank_files, "-o", out, "--pass-through")
    assert code == 0, stderr
    assert out.read_bytes() == tank_files[1].read_bytes()
    assert stdout.startswith("pruned: no (cannot be pruned:") and f"wrote the problem unchanged to {out}" in stdout

    code, stdout, _ = run("prune", *tank_files, "-o", out, "--pass-through", "--json")
    data = json.loads(stdout)
    assert code == 0 and data["pruned"] is False and "PDDL+" in data["unpruned_reason"]

    code, stdout, stderr = run("prune", *tank_files, "-o", "-", "--pass-through")
    assert code == 0 and stdout == TANK_PROBLEM and stderr.startswith("pruned: no")


def test_prune_passes_through_what_the_analysis_refuses(tmp_path, move_files, monkeypatch):
    import relevance_plan.cli.app as app

    def refuse(*args, **kwargs):
        raise UnsupportedFeatureError("a construct the analysis does not know")

    monkeypatch.setattr(app, "score_problem", refuse)
    out = tmp_path / "small.pddl"
    code, _, stderr = run("prune", *move_files, "-o", out)
    assert code == ExitCode.UNSUPPORTED_PDDL and "does not know" in one_line_error(stderr)
    code, stdout, _ = run("prune", *move_files, "-o", out, "--pass-through")
    assert code == 0 and out.read_text() == MOVE_PROBLEM and "does not know" in stdout


def test_prune_reports_pruned_when_it_prunes(tmp_path, move_files):
    code, stdout, _ = run("prune", *move_files, "-o", tmp_path / "small.pddl", "--pass-through", "--json")
    data = json.loads(stdout)
    assert code == 0 and data["pruned"] is True and data["unpruned_reason"] is None


# --------------------------------------------------------------------------- PDDL+ and the default planner


@pytest.mark.planner
def test_auto_plans_pddl_plus_with_enhsp_unpruned(tank_files):
    pytest.importorskip("up_enhsp")
    if shutil.which("java") is None:
        pytest.skip(JAVA_MISSING)
    result = plan_task(*tank_files, PlanOptions(validators=("none",), timeout=60))
    assert result.status is PlanStatus.SOLVED, result.message
    assert result.planner == "up:enhsp" and result.planner_choice == "a PDDL+ problem"
    assert [step.action for step in result.plan] == ["open-valve", "close-valve"]
    assert result.plan.timed  # ENHSP's plan of a PDDL+ problem says when each action happens


def test_auto_without_java_refuses_pddl_plus_naming_the_runtime(tank_files, monkeypatch):
    monkeypatch.setattr(auto, "find_java", lambda: None)
    code, _, stderr = run("plan", *tank_files, "--plan-file", "-")
    assert code == ExitCode.UNSUPPORTED_PDDL
    line = one_line_error(stderr)
    assert "PDDL+" in line and "default-jre-headless" in line and "tank.pddl:" in line


# --------------------------------------------------------------------------- ENHSP needs Java


@pytest.fixture
def no_java(tmp_path, monkeypatch):
    """PATH and JAVA_HOME that reach no ``java`` (Python is found by its full path)."""
    empty = tmp_path / "no-java-bin"
    empty.mkdir()
    monkeypatch.setenv("PATH", str(empty))
    monkeypatch.delenv("JAVA_HOME", raising=False)


def test_enhsp_without_java_is_one_line_and_the_planner_exit_code(move_files, no_java):
    pytest.importorskip("up_enhsp")
    code, _, stderr = run("plan", *move_files, "--planner", "up:enhsp", "--plan-file", "-")
    assert code == ExitCode.PLANNER
    line = one_line_error(stderr)
    assert "up:enhsp needs a Java runtime" in line and "apt-get install default-jre-headless" in line
    with pytest.raises(PlannerError, match="needs a Java runtime"):
        up_engines.UnifiedPlanningPlanner("enhsp").run(*move_files, time_limit=10, memory_limit_mb=None)


def test_java_under_java_home_is_put_on_the_planner_s_path(tmp_path, no_java, monkeypatch):
    home = tmp_path / "jdk"
    (home / "bin").mkdir(parents=True)
    java = home / "bin" / "java"
    java.write_text("#!/bin/sh\n")
    java.chmod(0o755)
    monkeypatch.setenv("JAVA_HOME", str(home))
    assert up_engines.java_runtime() == java
    environment = up_engines.java_environment("enhsp")
    assert environment is not None and environment["PATH"].split(":")[0] == str(home / "bin")
    assert up_engines.java_environment("tamer") is None  # only the Java engines need it
