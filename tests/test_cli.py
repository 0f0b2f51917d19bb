"""The command line: outputs, JSON fields, and one-line errors with documented exit codes."""

import json
import subprocess
import sys

import pytest
from click.testing import CliRunner
from support import COFFEE_DOMAIN, COFFEE_MODEL, TOOL, coffee_problem, invoke, write_file

from relevance_plan.cli import main
from relevance_plan.exitcodes import ExitCode


@pytest.fixture
def runner():
    return CliRunner()


@pytest.fixture
def problem(tmp_path):
    path = tmp_path / "coffee.pddl"
    path.write_text(coffee_problem(extra_plates=4).replace("plastic_cup_1 paper_cup_1", "Plastic_Cup_1 paper_cup_1"))
    return path


def test_score_table_and_json(problem):
    result = invoke("score", COFFEE_DOMAIN, problem)
    assert result.exit_code == 0
    assert "R(C)" in result.output and "side_plate_1" in result.output
    # the cup under a plate is set aside for the free paper cup, as plan's first attempt does
    assert "aside" in result.output and "restored" in result.output
    data = json.loads(invoke("score", COFFEE_DOMAIN, problem, "--json").output)
    assert data["sufficient"] is True
    assert {"kept", "removed", "restored", "set_aside", "scores", "sufficient"} <= set(data)
    assert data["set_aside"] == ["Plastic_Cup_1"] and "paper_cup_1" in data["kept"]  # the user's spelling
    assert all(r["reason"] for r in data["restored"])


def test_score_inquiries(problem):
    data = json.loads(invoke("score", COFFEE_DOMAIN, problem, "--inquiries", "--json").output)
    inquiries = data["inquiries"]
    assert "cold_brew" in inquiries["necessary"]
    assert {"plastic_cup", "paper_cup"} <= set(inquiries["questions"])
    assert inquiries["no_relevance"] == len(data["scores"])
    assert inquiries["with_necessity"] < inquiries["relevance_only"] < inquiries["no_relevance"]


@pytest.mark.planner
def test_prune_writes_a_problem_that_planners_read(problem, tmp_path):
    out = tmp_path / "pruned.pddl"
    result = invoke("prune", COFFEE_DOMAIN, problem, "-o", out, "--json")
    assert result.exit_code == 0
    data = json.loads(result.output)
    # the cup under a plate is set aside for the free paper cup (plan's first attempt), in the user's spelling
    assert "side_plate_1" in data["removed"] and data["set_aside"] == ["Plastic_Cup_1"]
    text = out.read_text()
    assert "paper_cup_1 - cup" in text and "side_plate_1" not in text and "Plastic_Cup_1" not in text
    # unified-planning reads it
    from unified_planning.io import PDDLReader

    parsed = PDDLReader().parse_problem(str(COFFEE_DOMAIN), str(out))
    assert len(list(parsed.all_objects)) == len(data["kept"])
    # and Fast Downward solves it; the plan validates on the ORIGINAL problem
    from relevance_plan.io import load_task
    from relevance_plan.planning.planners.fast_downward.adapter import run_fast_downward
    from relevance_plan.planning.validation import validate_plan

    outcome = run_fast_downward(COFFEE_DOMAIN, out, time_limit=60)
    assert outcome.solved
    domain, original = load_task(COFFEE_DOMAIN, problem)
    assert validate_plan(domain, original, outcome.plan).valid


@pytest.mark.planner
def test_plan_json_fields_and_plan_file(problem, tmp_path):
    plan_file = tmp_path / "out.plan"
    result = invoke("plan", COFFEE_DOMAIN, problem, "--plan-file", plan_file, "--json")
    assert result.exit_code == 0, result.output
    data = json.loads(result.output)
    for key in (
        "status",
        "valid",
        "plan_length",
        "wall_time",
        "relevance_time",
        "planner_time",
        "objects_total",
        "objects_kept",
        "attempts",
        "first_attempt_status",
    ):
        assert key in data
    assert data["status"] == "solved" and data["valid"] is True
    lines = [l for l in plan_file.read_text().splitlines() if not l.startswith(";")]
    assert len(lines) == data["plan_length"]
    assert any("Plastic_Cup_1" in l or "paper_cup_1" in l for l in lines)


@pytest.mark.planner
def test_plan_summary_text(problem, tmp_path):
    result = invoke("plan", COFFEE_DOMAIN, problem, "--plan-file", tmp_path / "p", "--method", "pure", "-q")
    assert result.exit_code == 0
    assert "valid on the original problem" in result.output


def _bad_yaml(tmp_path):
    path = tmp_path / "bad.yaml"
    path.write_text("version: 1\ndomain: coffee\nobjectives: [\n")
    return path


def _bad_probability(tmp_path):
    text = COFFEE_MODEL.read_text().replace("coffee: 0.98", "coffee: 1.98", 1)
    path = tmp_path / "prob.yaml"
    path.write_text(text)
    return path


@pytest.mark.parametrize(
    "args, code, needle",
    [
        (lambda t, p: ["score", COFFEE_DOMAIN, t / "missing.pddl"], ExitCode.INPUT_FILE, "missing.pddl"),
        (lambda t, p: ["score", t / "nodomain.pddl", p], ExitCode.INPUT_FILE, "nodomain.pddl"),
        (
            lambda t, p: [
                "score",
                COFFEE_DOMAIN,
                write_file(t, "broken.pddl", p.read_text().replace("(hand-empty)", "(hand-empty")),
            ],
            ExitCode.PDDL_SYNTAX,
            "broken.pddl",
        ),
        (
            lambda t, p: [
                "score",
                COFFEE_DOMAIN,
                write_file(t, "other.pddl", p.read_text().replace("(:domain coffee)", "(:domain cereal)")),
            ],
            ExitCode.DOMAIN_MISMATCH,
            "other.pddl:2",
        ),
        (lambda t, p: ["score", COFFEE_DOMAIN, p, "--model", _bad_yaml(t)], ExitCode.MODEL, "bad.yaml:"),
        (lambda t, p: ["score", COFFEE_DOMAIN, p, "--model", _bad_probability(t)], ExitCode.MODEL, "outside [0, 1]"),
        (lambda t, p: ["score", COFFEE_DOMAIN, p, "--tau-class", "1.5"], ExitCode.USAGE, "--tau-class"),
        (lambda t, p: ["score", COFFEE_DOMAIN, p, "--human", "nobody"], ExitCode.MODEL, "unknown human 'nobody'"),
        (
            lambda t, p: ["plan", COFFEE_DOMAIN, p, "--timeout", "-3", "--plan-file", t / "x.plan"],
            ExitCode.USAGE,
            "--timeout",
        ),
        (
            lambda t, p: ["plan", COFFEE_DOMAIN, p, "--memory-limit", "2", "--plan-file", t / "x.plan"],
            ExitCode.USAGE,
            "--memory-limit",
        ),
        (
            lambda t, p: ["prune", COFFEE_DOMAIN, p, "-o", t / "x.pddl", "--objective", "drink-at-break"],
            ExitCode.INSUFFICIENT_CUES,
            "objective ambiguous",
        ),
        (lambda t, p: ["prune", COFFEE_DOMAIN, p, "-o", t / "nodir" / "x.pddl"], ExitCode.INPUT_FILE, "nodir"),
    ],
)
def test_bad_input_gives_one_line_and_exit_code(runner, problem, tmp_path, args, code, needle):
    before = set(tmp_path.iterdir())
    result = runner.invoke(main, [str(a) for a in args(tmp_path, problem)])
    assert result.exit_code == int(code), result.output
    assert needle in result.output
    error_lines = [l for l in result.output.splitlines() if l.startswith("relevance-plan:")]
    assert len(error_lines) >= 1 and "Traceback" not in result.output
    created = set(tmp_path.iterdir()) - before
    assert all(p.suffix in (".pddl", ".yaml") and p.name not in ("x.pddl", "x.plan") for p in created)


def test_an_objective_the_model_lacks_without_the_text_extra_is_one_line_naming_it(runner, problem, monkeypatch):
    monkeypatch.setitem(sys.modules, "numpy", None)  # what an import finds when numpy is not installed
    result = runner.invoke(main, ["score", str(COFFEE_DOMAIN), str(problem), "--objective", "a light lunch"])
    assert result.exit_code == ExitCode.USAGE
    (line,) = [l for l in result.output.splitlines() if l.startswith("relevance-plan:")]
    assert "unknown objective 'a light lunch'" in line and "'text' extra" in line and "Traceback" not in result.output


def test_insufficient_cues_exit_code_from_plan(runner, problem, tmp_path):
    result = runner.invoke(
        main,
        ["plan", str(COFFEE_DOMAIN), str(problem), "--objective", "drink-at-break", "--plan-file", str(tmp_path / "p")],
    )
    assert result.exit_code == ExitCode.INSUFFICIENT_CUES
    assert not (tmp_path / "p").exists()


def test_no_traceback_from_the_real_command(tmp_path, problem):
    completed = subprocess.run(
        TOOL + ["score", str(COFFEE_DOMAIN), str(tmp_path / "nope.pddl")],
        capture_output=True,
        text=True,
    )
    assert completed.returncode == ExitCode.INPUT_FILE
    assert completed.stderr.strip().count("\n") == 0 and "Traceback" not in completed.stderr


def test_exit_code_table_is_printed():
    result = invoke("exit-codes")
    for code in ExitCode:
        assert f"{int(code):>4}  {code.name}" in result.output


@pytest.mark.planner
def test_plan_bad_planner_config_and_malformed_problem(runner, problem, tmp_path):
    result = runner.invoke(
        main,
        [
            "plan",
            str(COFFEE_DOMAIN),
            str(problem),
            "--planner-config",
            "no-such-alias",
            "--method",
            "pure",
            "--plan-file",
            str(tmp_path / "p"),
        ],
    )
    assert result.exit_code == ExitCode.USAGE
    broken = write_file(tmp_path, "broken.pddl", problem.read_text().replace("(:init", "(:init (at)"))
    result = runner.invoke(main, ["plan", str(COFFEE_DOMAIN), str(broken), "--plan-file", str(tmp_path / "p")])
    assert result.exit_code == ExitCode.DOMAIN_MISMATCH and "broken.pddl:" in result.output
    assert not (tmp_path / "p").exists()
