"""Bad input is one stderr line that names what is wrong, with its documented exit code:
sidecars, path arguments, non-ASCII names, models, byte-order marks and NUL bytes, options."""

from __future__ import annotations

import os

import pytest
from support import COFFEE_DOMAIN, COFFEE_MODEL, coffee_problem, one_line_error, run

from relevance_plan.exitcodes import ExitCode

# --------------------------------------------------------------------------- sidecars


@pytest.mark.parametrize(
    "sidecar",
    ['{"necessary": [1, 2], "relevant": []}', '{"necessary": "cup"}', "[1, 2]", "not json", "[" * 5000 + "]" * 5000],
)
def test_bad_sidecars_are_exit_31_in_plan_and_sweep(tmp_path, sidecar):
    suite = tmp_path / "suite"
    suite.mkdir()
    (suite / "domain.pddl").write_bytes(COFFEE_DOMAIN.read_bytes())
    (suite / "p.pddl").write_text(coffee_problem())
    (suite / "p.json").write_text(sidecar)
    code, _, stderr = run(
        "plan", suite / "domain.pddl", suite / "p.pddl", "--method", "oracle", "-q", "--plan-file", tmp_path / "plan"
    )
    assert code == ExitCode.INPUT_FILE and "p.json" in one_line_error(stderr)
    code, _, stderr = run("sweep", suite)
    assert code == ExitCode.INPUT_FILE and "p.json" in one_line_error(stderr)


# --------------------------------------------------------------------------- path arguments


def test_a_directory_or_missing_file_is_exit_31_in_one_line(copied_coffee_files, tmp_path):
    domain, problem = copied_coffee_files
    for args in (
        ["score", tmp_path, problem],
        ["plan", domain, tmp_path],
        ["prune", domain, problem, "-o", tmp_path],
        ["score", domain, problem, "--model", tmp_path],
        ["report", tmp_path],
        ["score", domain, tmp_path / "missing.pddl"],
        ["score", "/dev/zero", problem],
        ["prune", domain, problem, "-o", tmp_path / "no" / "such" / "dir.pddl"],
    ):
        code, _, stderr = run(*args)
        assert code == ExitCode.INPUT_FILE, args
        one_line_error(stderr)


@pytest.mark.skipif(os.geteuid() == 0, reason="root reads a mode-000 file")
def test_an_unreadable_file_is_exit_31_in_one_line(copied_coffee_files):
    domain, problem = copied_coffee_files
    problem.chmod(0)
    code, _, stderr = run("score", domain, problem)
    assert code == ExitCode.INPUT_FILE
    one_line_error(stderr)


# --------------------------------------------------------------------------- what the message names


def test_non_ascii_object_names_are_named_before_planning(copied_coffee_files, tmp_path):
    domain, problem = copied_coffee_files
    problem.write_text(problem.read_text().replace("paper_cup_1", "tasse_café_1"))
    assert run("score", domain, problem)[0] == 0  # our reader takes them
    code, _, stderr = run("plan", domain, problem, "-q", "--plan-file", tmp_path / "plan")
    assert code == ExitCode.UNSUPPORTED_PDDL
    line = one_line_error(stderr)
    assert "tasse_café_1" in line and "non-ASCII" in line and "Fast Downward" in line


def test_model_messages_name_the_class(copied_coffee_files, tmp_path):
    domain, problem = copied_coffee_files
    model = tmp_path / "model.yaml"
    text = COFFEE_MODEL.read_text()
    model.write_text(text)
    import yaml

    from relevance_plan.relevance.scoring.knowledge import parse_knowledge_model

    data = yaml.safe_load(text)
    task = next(iter(data["activities"]))
    class_name = next(iter(data["activities"][task]))
    data["activities"][task][class_name] = 7
    model.write_text(yaml.safe_dump(data))
    code, _, stderr = run("score", domain, problem, "--model", model)
    assert code == ExitCode.MODEL
    line = one_line_error(stderr)
    assert "{class}" not in line and f"P({class_name} | {task})" in line
    assert parse_knowledge_model  # imported for the schema's error path


def test_generate_errors_have_no_progress_line(tmp_path):
    code, _, stderr = run("generate", "coffee", "--count", "-1", "--out", tmp_path / "s")
    assert code == ExitCode.USAGE
    assert "done" not in one_line_error(stderr)


@pytest.mark.parametrize("prefix, expected", [(b"\xef\xbb\xbf", "byte-order mark"), (b"\x00", "NUL byte")])
def test_bom_and_nul_are_named(copied_coffee_files, tmp_path, prefix, expected):
    domain, problem = copied_coffee_files
    bad = tmp_path / "bad.pddl"
    bad.write_bytes(prefix + problem.read_bytes())
    code, _, stderr = run("score", domain, bad)
    assert code == ExitCode.PDDL_SYNTAX
    line = one_line_error(stderr)
    assert expected in line and "\x00" not in line and "\ufeff" not in line


def test_duplicate_parameter_is_named(copied_coffee_files, tmp_path):
    domain, problem = copied_coffee_files
    text = domain.read_text()
    at = text.index(":parameters (") + len(":parameters (")
    domain.write_text(text[:at] + "?zz - object ?zz - object " + text[at:])
    code, _, stderr = run("score", domain, problem)
    assert code == ExitCode.PDDL_SYNTAX and "'?zz' is declared twice" in one_line_error(stderr)


# --------------------------------------------------------------------------- options


def test_taus_errors_name_taus(tmp_path):
    suite = tmp_path / "suite"
    assert run("generate", "coffee", "--count", "1", "--out", suite)[0] == 0
    code, _, stderr = run("sweep", suite, "--taus", "0.1,7")
    assert code == ExitCode.USAGE
    line = one_line_error(stderr)
    assert "--taus" in line and "--tau-class" not in line


@pytest.mark.planner
def test_unknown_planner_alias_is_named(copied_coffee_files, tmp_path):
    domain, problem = copied_coffee_files
    code, _, stderr = run(
        "plan", domain, problem, "-q", "--planner-config", "no-such-alias", "--plan-file", tmp_path / "plan"
    )
    assert code == ExitCode.USAGE and "'no-such-alias'" in one_line_error(stderr)


def test_tiny_does_not_hide_a_bad_distractor_count(tmp_path):
    code, _, stderr = run("demo", "--tiny", "--distractors", "-3", "--workdir", tmp_path / "d")
    assert code == ExitCode.USAGE and "--distractors" in one_line_error(stderr)
