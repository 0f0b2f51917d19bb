"""What the tool writes: never over one of its inputs, through non-regular targets, never over the
user's own files, with the existing mode kept, and nothing at all before the options are checked."""

from __future__ import annotations

import json
import os
import stat
import subprocess
import threading
from pathlib import Path

import pytest
from support import (
    COFFEE_MODEL,
    DOMAINS,
    PAYING_DOMAIN,
    PAYING_PROBLEM,
    TOOL,
    make_row,
    one_line_error,
    planner_script,
    run,
    write_file,
    write_store,
)

from relevance_plan.exitcodes import ExitCode


def snapshot(*paths):
    return {Path(p): (Path(p).read_bytes(), stat.S_IMODE(Path(p).stat().st_mode)) for p in paths}


# --------------------------------------------------------------------------- an output that is an input


@pytest.mark.parametrize(
    "command, option, target",
    [
        ("prune", "-o", "problem"),
        ("prune", "-o", "domain"),
        ("prune", "-o", "model"),
        ("plan", "--plan-file", "domain"),
        ("plan", "--plan-file", "problem"),
    ],
)
def test_an_output_that_is_an_input_is_refused(copied_coffee_files, tmp_path, command, option, target):
    domain, problem = copied_coffee_files
    model = tmp_path / "model.yaml"
    model.write_bytes(COFFEE_MODEL.read_bytes())
    paths = {"domain": domain, "problem": problem, "model": model}
    # Through another spelling of the same file: a symlink.
    alias = tmp_path / "alias"
    alias.symlink_to(paths[target])
    before = snapshot(domain, problem, model)
    code, _, stderr = run(command, domain, problem, "--model", model, option, alias)
    assert code == ExitCode.USAGE
    assert "same file as the input" in one_line_error(stderr)
    assert snapshot(domain, problem, model) == before


def test_the_model_found_next_to_the_domain_is_an_input_too(copied_coffee_files, tmp_path):
    domain, problem = copied_coffee_files
    model = tmp_path / "relevance.yaml"
    model.write_bytes(COFFEE_MODEL.read_bytes())
    before = snapshot(model)
    code, _, stderr = run("prune", domain, problem, "-o", model)
    assert code == ExitCode.USAGE and "same file" in one_line_error(stderr)
    assert snapshot(model) == before


def test_sweep_heatmap_cannot_replace_a_suite_file(tmp_path):
    suite = tmp_path / "suite"
    assert run("generate", "coffee", "--count", "1", "--out", suite)[0] == 0
    before = snapshot(*suite.iterdir())
    code, _, stderr = run("sweep", suite, "--heatmap", suite / "domain.pddl")
    assert code == ExitCode.USAGE and "same file" in one_line_error(stderr)
    assert snapshot(*suite.iterdir()) == before


# --------------------------------------------------------------------------- non-regular targets


def test_non_regular_targets_are_written_through(copied_coffee_files, tmp_path):
    domain, problem = copied_coffee_files
    # A character device stays a device.
    code, _, _ = run("prune", domain, problem, "-o", "/dev/null")
    assert code == 0 and stat.S_ISCHR(os.stat("/dev/null").st_mode)
    # A FIFO stays a FIFO and its reader gets the pruned problem.
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    received = []
    reader = threading.Thread(target=lambda: received.append(fifo.read_bytes()))
    reader.start()
    code, _, _ = run("prune", domain, problem, "-o", fifo)
    reader.join(10)
    assert code == 0 and stat.S_ISFIFO(fifo.lstat().st_mode) and b"(:objects" in received[0]
    # A symlink stays a link; its target gets the text.
    real = tmp_path / "real.pddl"
    real.write_text("old")
    link = tmp_path / "link.pddl"
    link.symlink_to(real)
    code, _, _ = run("prune", domain, problem, "-o", link)
    assert code == 0 and link.is_symlink() and "(:objects" in real.read_text()


def test_dash_writes_to_stdout(copied_coffee_files):
    domain, problem = copied_coffee_files
    code, stdout, stderr = run("prune", domain, problem, "-o", "-")
    assert code == 0 and stdout.startswith("(define") and "wrote standard output" in stderr
    code, _, stderr = run("prune", domain, problem, "-o", "-", "--json")
    assert code == ExitCode.USAGE and "--json" in one_line_error(stderr)


PURE_AND_RELEVANCE = (make_row("suite", "p01", "pure"), make_row("suite", "p01", "relevance"))


def test_dash_is_standard_output_wherever_a_file_goes_and_refused_for_folders_and_stores(tmp_path):
    store = write_store(
        tmp_path / "s.sqlite", [make_row("suite", "p01", "pure"), make_row("suite", "p01", "relevance")]
    )
    code, stdout, stderr = run("report", store, "--html", "-")
    assert code == 0 and stdout.startswith("<!DOCTYPE html>") and "| suite |" not in stdout and stderr == ""
    assert not (tmp_path / "-").exists()
    code, _, stderr = run("report", store, "--html", "-", "--csv")
    assert code == ExitCode.USAGE and "--html -" in one_line_error(stderr)
    for args in (
        ["report", store, "--plots", "-"],
        ["generate", "coffee", "--out", "-"],
        ["compare", tmp_path, "--store", "-"],
        ["sweep", tmp_path, "--heatmap", "-"],
        ["demo", "--workdir", "-"],
    ):
        code, _, stderr = run(*args)
        assert code == ExitCode.USAGE and "'-' (standard output)" in one_line_error(stderr), args
    assert sorted(path.name for path in tmp_path.iterdir()) == ["s.sqlite"]


@pytest.mark.planner
def test_learn_to_stdout_writes_the_model_alone(tmp_path):
    from relevance_plan.generators.classic import generate_classic_problem

    problem = tmp_path / "train.pddl"
    problem.write_text(generate_classic_problem("ferry-typed", 0, 0, size=10).pddl_text)
    code, stdout, stderr = run("learn", DOMAINS / "ferry-typed" / "domain.pddl", problem, "-o", "-", "-q")
    assert code == 0, stderr
    assert json.loads(stdout)["format"] == "relevance-plan-learned-model"
    assert "model written to standard output" in stderr


def test_an_output_another_output_of_the_run_writes_is_refused(tmp_path):
    pytest.importorskip("matplotlib")
    store = write_store(
        tmp_path / "s.sqlite", [make_row("suite", "p01", "pure"), make_row("suite", "p01", "relevance")]
    )
    plots = tmp_path / "plots"
    plots.mkdir()
    (tmp_path / "link.html").symlink_to(plots / "relevance-vs-pure.png")
    for page in (plots / "cactus.png", plots / "cactus-suite.png", tmp_path / "link.html"):
        code, _, stderr = run("report", store, "--plots", plots, "--html", page)
        assert code == ExitCode.USAGE and "would replace the plot" in one_line_error(stderr), page
        assert list(plots.iterdir()) == []


def test_json_output_is_strict_json(tmp_path):
    """A metric past the largest float is no number JSON has: null, never Infinity."""
    domain = write_file(tmp_path, "d.pddl", PAYING_DOMAIN)
    problem = write_file(tmp_path, "p.pddl", PAYING_PROBLEM)
    plan = write_file(tmp_path, "plan", "(spend a)\n(spend b)\n")
    code, stdout, _ = run("validate", domain, problem, plan, "--json")

    def refuse(constant: str) -> None:
        raise AssertionError(f"not JSON: {constant}")

    assert code == 0 and json.loads(stdout, parse_constant=refuse)["metric"] is None
    assert run("validate", domain, problem, plan)[1].startswith("valid: plan of 2 steps, metric inf")


# --------------------------------------------------------------------------- the user's files


def test_generate_keeps_the_users_files(tmp_path):
    suite = tmp_path / "suite"
    assert run("generate", "coffee", "--count", "3", "--seed", "1", "--out", suite)[0] == 0
    mine = {"notes.txt": b"my notes", "results.sqlite": b"SQLite format 3\x00...", "mine.pddl": b"(define)"}
    for name, data in mine.items():
        (suite / name).write_bytes(data)
    assert run("generate", "coffee", "--count", "2", "--seed", "2", "--out", suite)[0] == 0
    assert {name: (suite / name).read_bytes() for name in mine} == mine
    assert not (suite / "coffee-simple-003.pddl").exists(), "the generator's own old file is gone"
    assert (suite / "coffee-simple-002.pddl").exists()
    # A file of the user's with a name the generator would write: refused, unless --force.
    (suite / "coffee-simple-003.pddl").write_text("hand-written")
    code, _, stderr = run("generate", "coffee", "--count", "3", "--out", suite)
    assert code == ExitCode.USAGE and "--force" in one_line_error(stderr)
    assert (suite / "coffee-simple-003.pddl").read_text() == "hand-written"
    foreign = tmp_path / "foreign"
    foreign.mkdir()
    (foreign / "notes.txt").write_text("mine")
    code, _, stderr = run("generate", "coffee", "--count", "1", "--out", foreign)
    assert code == ExitCode.USAGE and "--force" in one_line_error(stderr)
    assert run("generate", "coffee", "--count", "1", "--out", foreign, "--force")[0] == 0
    assert (foreign / "notes.txt").read_text() == "mine"


@pytest.mark.parametrize("content", [b"", b"not a database\n", b"SQLite format 3\x00" + bytes(200)])
def test_report_leaves_a_non_store_byte_identical(tmp_path, content):
    store = tmp_path / "store.sqlite"
    store.write_bytes(content)
    code, _, stderr = run("report", store)
    assert code == ExitCode.STORE
    one_line_error(stderr)
    assert store.read_bytes() == content
    assert sorted(p.name for p in tmp_path.iterdir()) == ["store.sqlite"]


# --------------------------------------------------------------------------- modes


def test_a_read_only_plan_file_is_refused_before_planning(copied_coffee_files, tmp_path):
    domain, problem = copied_coffee_files
    plan_file = tmp_path / "plan.txt"
    plan_file.write_text("my old plan")
    plan_file.chmod(0o444)
    marker = tmp_path / "planned"
    planner = planner_script(tmp_path, "planner.py", f"open({str(marker)!r}, 'w').close()\n")
    code, _, stderr = run(
        "plan", domain, problem, "-q", "--plan-file", plan_file, "--planner", f"cmd:{planner} {{domain}}"
    )
    assert code == ExitCode.INPUT_FILE
    assert "read-only" in one_line_error(stderr)
    assert not marker.exists(), "found before planning"
    assert plan_file.read_text() == "my old plan" and stat.S_IMODE(plan_file.stat().st_mode) == 0o444


def test_an_existing_output_keeps_its_mode(copied_coffee_files, tmp_path):
    domain, problem = copied_coffee_files
    out = tmp_path / "out.pddl"
    out.write_text("old")
    out.chmod(0o640)
    if os.geteuid() == 0:
        os.chown(out, 1234, 5678)
    assert run("prune", domain, problem, "-o", out)[0] == 0
    assert stat.S_IMODE(out.stat().st_mode) == 0o640 and "(:objects" in out.read_text()
    if os.geteuid() == 0:
        assert (out.stat().st_uid, out.stat().st_gid) == (1234, 5678)


def test_suite_folders_follow_the_umask(tmp_path):
    old = os.umask(0o022)
    try:
        suite = tmp_path / "suite"
        code = subprocess.run(
            TOOL + ["generate", "coffee", "--count", "1", "--out", str(suite)], capture_output=True
        ).returncode
    finally:
        os.umask(old)
    assert code == 0 and stat.S_IMODE(suite.stat().st_mode) == 0o755


# --------------------------------------------------------------------------- nothing written before the checks


@pytest.mark.parametrize(
    "args",
    [
        ["--jobs", "0"],
        ["--timeout", "-1"],
        ["--count", "0"],
        ["--distractors", "-3"],
        ["--tiny", "--distractors", "-3"],
    ],
)
def test_demo_checks_options_before_writing(tmp_path, args):
    workdir = tmp_path / "demo"
    code, _, stderr = run("demo", "--workdir", workdir, *args)
    assert code == ExitCode.USAGE
    one_line_error(stderr)
    assert not workdir.exists()


def test_an_unreachable_scheduler_leaves_no_store(copied_coffee_files, tmp_path):
    pytest.importorskip("dask.distributed")
    domain, problem = copied_coffee_files
    suite = tmp_path / "suite"
    suite.mkdir()
    (suite / "domain.pddl").write_bytes(domain.read_bytes())
    (suite / "p.pddl").write_bytes(problem.read_bytes())
    store = tmp_path / "results.sqlite"
    code, _, stderr = run(
        "compare", suite, "--store", store, "--scheduler", "tcp://127.0.0.1:1", "--scheduler-timeout", "1", "-q"
    )
    assert code == ExitCode.SCHEDULER
    one_line_error(stderr)
    assert not store.exists()


def _stdout_outputs_and_flags() -> list[tuple[str, str, str]]:
    """(command, an output option that '-' may name, a flag that prints on standard output), for every
    command that has both."""
    import click

    from relevance_plan.cli import main
    from relevance_plan.cli.arguments.paths import NOT_STDOUT, OUTPUT_FILES, STDOUT_FLAGS

    context = click.Context(main)
    found = []
    for name in main.list_commands(context):
        params = main.get_command(context, name).params
        outputs = [p for p in params if p.name in OUTPUT_FILES and p.name not in NOT_STDOUT]
        flags = [p for p in params if p.name in STDOUT_FLAGS]
        found += [(name, min(o.opts, key=len), max(f.opts, key=len)) for o in outputs for f in flags]
    return found


@pytest.mark.parametrize("command, output, flag", _stdout_outputs_and_flags())
def test_an_output_on_standard_output_and_a_flag_printing_there_are_refused_in_every_command(
    command, output, flag, tmp_path
):
    problem = write_file(tmp_path, "p.pddl", (DOMAINS.parent / "problems" / "coffee-simple.pddl").read_text())
    store = write_store(tmp_path / "s.sqlite", list(PURE_AND_RELEVANCE))
    inputs = {"report": [store]}.get(command, [DOMAINS / "coffee" / "domain.pddl", problem])
    value = ["markdown"] if flag == "--format" else []
    for target in ("-", "/dev/stdout"):
        before = sorted(tmp_path.rglob("*"))
        code, stdout, stderr = run(command, *inputs, output, target, flag, *value)
        assert code == ExitCode.USAGE, f"{command} {output} {target} {flag}: {stderr}"
        assert f"'{output} {target}'" in one_line_error(stderr) and stdout == ""
        assert sorted(tmp_path.rglob("*")) == before


def test_every_command_with_an_output_on_standard_output_and_json_is_walked():
    walked = {command for command, _, flag in _stdout_outputs_and_flags() if flag == "--json"}
    assert walked >= {"prune", "plan", "draft-model", "report"}
