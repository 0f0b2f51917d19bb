"""Issue 11, item by item: nothing a user owns is changed, no process outlives
the tool, and every bad input is one line with its documented exit code."""

from __future__ import annotations

import os
import signal
import stat
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest
from click.testing import CliRunner
from kitchen import coffee_problem

from relevance_plan.cli import main
from relevance_plan.exitcodes import ExitCode

REPO = Path(__file__).resolve().parent.parent
COFFEE_DOMAIN = REPO / "domains" / "coffee" / "domain.pddl"
TOOL = [sys.executable, "-m", "relevance_plan"]


def run(*args, input=None):
    """(exit code, stdout, stderr) of the command run in-process; a traceback fails the test."""
    result = CliRunner().invoke(main, [str(a) for a in args], input=input)
    if result.exception is not None and not isinstance(result.exception, SystemExit):
        raise result.exception
    return result.exit_code, result.stdout, result.stderr


def one_line_error(stderr: str) -> str:
    lines = stderr.splitlines()
    assert len(lines) == 1, stderr
    assert lines[0].startswith("relevance-plan:") and "Traceback" not in stderr
    return lines[0]


@pytest.fixture
def files(tmp_path):
    domain = tmp_path / "domain.pddl"
    domain.write_bytes(COFFEE_DOMAIN.read_bytes())
    problem = tmp_path / "problem.pddl"
    problem.write_text(coffee_problem(extra_plates=2))
    return domain, problem


def snapshot(*paths):
    return {Path(p): (Path(p).read_bytes(), stat.S_IMODE(Path(p).stat().st_mode)) for p in paths}


# --------------------------------------------------------------------------- 1. output is an input


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
def test_1_an_output_that_is_an_input_is_refused(files, tmp_path, command, option, target):
    domain, problem = files
    model = tmp_path / "model.yaml"
    model.write_bytes((REPO / "domains" / "coffee" / "relevance.yaml").read_bytes())
    paths = {"domain": domain, "problem": problem, "model": model}
    # Through another spelling of the same file: a symlink.
    alias = tmp_path / "alias"
    alias.symlink_to(paths[target])
    before = snapshot(domain, problem, model)
    code, _, stderr = run(command, domain, problem, "--model", model, option, alias)
    assert code == ExitCode.USAGE
    assert "same file as the input" in one_line_error(stderr)
    assert snapshot(domain, problem, model) == before


def test_1_the_model_found_next_to_the_domain_is_an_input_too(files, tmp_path):
    domain, problem = files
    model = tmp_path / "relevance.yaml"
    model.write_bytes((REPO / "domains" / "coffee" / "relevance.yaml").read_bytes())
    before = snapshot(model)
    code, _, stderr = run("prune", domain, problem, "-o", model)
    assert code == ExitCode.USAGE and "same file" in one_line_error(stderr)
    assert snapshot(model) == before


def test_1_sweep_heatmap_cannot_replace_a_suite_file(tmp_path):
    suite = tmp_path / "suite"
    assert run("generate", "coffee", "--count", "1", "--out", suite)[0] == 0
    before = snapshot(*suite.iterdir())
    code, _, stderr = run("sweep", suite, "--heatmap", suite / "domain.pddl")
    assert code == ExitCode.USAGE and "same file" in one_line_error(stderr)
    assert snapshot(*suite.iterdir()) == before


# --------------------------------------------------------------------------- 2. non-regular targets


def test_2_non_regular_targets_are_written_through(files, tmp_path):
    domain, problem = files
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


def test_2_dash_writes_to_stdout(files):
    domain, problem = files
    code, stdout, stderr = run("prune", domain, problem, "-o", "-")
    assert code == 0 and stdout.startswith("(define") and "wrote standard output" in stderr
    code, _, stderr = run("prune", domain, problem, "-o", "-", "--json")
    assert code == ExitCode.USAGE and "--json" in one_line_error(stderr)


# --------------------------------------------------------------------------- 3. generate --out


def test_3_generate_keeps_the_users_files(tmp_path):
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


# --------------------------------------------------------------------------- 4. report is read-only


@pytest.mark.parametrize("content", [b"", b"not a database\n", b"SQLite format 3\x00" + bytes(200)])
def test_4_report_leaves_a_non_store_byte_identical(tmp_path, content):
    store = tmp_path / "store.sqlite"
    store.write_bytes(content)
    code, _, stderr = run("report", store)
    assert code == ExitCode.STORE
    one_line_error(stderr)
    assert store.read_bytes() == content
    assert sorted(p.name for p in tmp_path.iterdir()) == ["store.sqlite"]


# --------------------------------------------------------------------------- 5. read-only output


def test_5_a_read_only_plan_file_is_refused_before_planning(files, tmp_path):
    domain, problem = files
    plan_file = tmp_path / "plan.txt"
    plan_file.write_text("my old plan")
    plan_file.chmod(0o444)
    started = time.monotonic()
    code, _, stderr = run("plan", domain, problem, "-q", "--plan-file", plan_file)
    assert code == ExitCode.INPUT_FILE
    assert "read-only" in one_line_error(stderr)
    assert time.monotonic() - started < 2.0, "found before planning"
    assert plan_file.read_text() == "my old plan" and stat.S_IMODE(plan_file.stat().st_mode) == 0o444


def test_5_an_existing_output_keeps_its_mode(files, tmp_path):
    domain, problem = files
    out = tmp_path / "out.pddl"
    out.write_text("old")
    out.chmod(0o640)
    if os.geteuid() == 0:
        os.chown(out, 1234, 5678)
    assert run("prune", domain, problem, "-o", out)[0] == 0
    assert stat.S_IMODE(out.stat().st_mode) == 0o640 and "(:objects" in out.read_text()
    if os.geteuid() == 0:
        assert (out.stat().st_uid, out.stat().st_gid) == (1234, 5678)


# --------------------------------------------------------------------------- 6. signals and processes


def _session_processes(sid: int) -> list[int]:
    found = []
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                if os.getsid(int(entry)) == sid:
                    found.append(int(entry))
            except OSError:
                pass
    return found


def _guards(marker: str) -> list[int]:
    """The planner guards whose command line mentions ``marker`` (other runs may share /tmp)."""
    guards = []
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                command = Path(f"/proc/{entry}/cmdline").read_bytes()
            except OSError:
                continue
            if b"guard.py" in command and marker.encode() in command:
                guards.append(int(entry))
    return guards


def _planner_processes(marker: str) -> list[int]:
    """Every process of the planner sessions of ``_guards(marker)``."""
    return [pid for guard in _guards(marker) for pid in _session_processes(guard)]


def _planner_workdirs(marker: str) -> list[Path]:
    return [Path(os.readlink(f"/proc/{guard}/cwd")) for guard in _guards(marker)]


@pytest.fixture(scope="module")
def long_problem(tmp_path_factory):
    """A problem pure planning needs several seconds for."""
    suite = tmp_path_factory.mktemp("long") / "suite"
    assert (
        run("generate", "coffee", "--difficulty", "hard", "--count", "1", "--distractors", "100", "--out", suite)[0]
        == 0
    )
    return suite / "domain.pddl", suite / "coffee-hard-001.pddl"


def _start_plan(long_problem, tmp_path):
    """The running tool and its planner's scratch directory."""
    domain, problem = long_problem
    marker = str(problem.parent)
    process = subprocess.Popen(
        TOOL + ["plan", str(domain), str(problem), "--method", "pure", "-q", "--plan-file", str(tmp_path / "plan")],
        start_new_session=True,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
    )
    deadline = time.monotonic() + 20
    while not _guards(marker) and time.monotonic() < deadline:
        time.sleep(0.1)
    time.sleep(1.0)  # the translator is running now
    assert process.poll() is None
    assert len(_planner_processes(marker)) >= 3, "guard, driver and a component"
    (workdir,) = _planner_workdirs(marker)
    assert workdir.name.startswith("relevance-plan-fd-") and workdir.is_dir()
    return process, workdir


@pytest.mark.parametrize("signum", [signal.SIGTERM, signal.SIGHUP, signal.SIGINT])
def test_6_a_signal_during_plan_stops_every_process_and_cleans_up(long_problem, tmp_path, signum):
    process, workdir = _start_plan(long_problem, tmp_path)
    planners = _planner_processes(str(long_problem[1].parent))
    assert planners
    os.kill(process.pid, signum)
    _, stderr = process.communicate(timeout=20)
    assert process.returncode == ExitCode.INTERRUPTED
    assert "interrupted" in one_line_error(stderr.decode())
    time.sleep(0.2)
    # Killed processes may stay zombies until init reaps them; none may still run.
    assert [p for p in _session_processes(process.pid) + planners if _alive(p)] == []
    assert not workdir.exists()
    assert not (tmp_path / "plan").exists()


def test_6_sighup_during_compare_stops_the_batch_and_its_planners(long_problem, tmp_path):
    suite = long_problem[1].parent
    store = tmp_path / "results.sqlite"
    process = subprocess.Popen(
        TOOL + ["compare", str(suite), "--methods", "pure", "--store", str(store), "-q"],
        start_new_session=True,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
    )
    marker = str(suite)
    deadline = time.monotonic() + 20
    while not _guards(marker) and time.monotonic() < deadline:
        time.sleep(0.1)
    time.sleep(0.5)
    planners = _planner_processes(marker)
    (workdir,) = _planner_workdirs(marker)
    assert planners
    os.kill(process.pid, signal.SIGHUP)
    _, stderr = process.communicate(timeout=40)
    assert process.returncode == ExitCode.INTERRUPTED
    assert "interrupted" in one_line_error(stderr.decode())
    time.sleep(0.2)
    assert [p for p in _session_processes(process.pid) + planners if _alive(p)] == []
    assert not workdir.exists()


def test_6_planners_die_with_the_tool_on_kill_9(long_problem, tmp_path):
    process, workdir = _start_plan(long_problem, tmp_path)
    planners = _planner_processes(str(long_problem[1].parent))
    assert planners
    os.kill(process.pid, signal.SIGKILL)
    process.wait(timeout=10)
    deadline = time.monotonic() + 2.0
    while [p for p in planners if _alive(p)] and time.monotonic() < deadline:
        time.sleep(0.05)
    assert [p for p in planners if _alive(p)] == [], "planners outlived the tool"
    while workdir.exists() and time.monotonic() < deadline + 2.0:
        time.sleep(0.05)
    assert not workdir.exists(), "the planner's scratch directory is removed too"


def _alive(pid: int) -> bool:
    try:
        state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except OSError:
        return False
    return state != "Z"


def test_6_sigterm_during_generate_leaves_no_staging(tmp_path):
    process = subprocess.Popen(
        TOOL + ["generate", "coffee", "--count", "3000", "--distractors", "500", "--out", str(tmp_path / "suite")],
        start_new_session=True,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
    )
    deadline = time.monotonic() + 20
    while not list(tmp_path.iterdir()) and time.monotonic() < deadline:
        time.sleep(0.05)
    time.sleep(0.5)
    os.kill(process.pid, signal.SIGTERM)
    _, stderr = process.communicate(timeout=20)
    assert process.returncode == ExitCode.INTERRUPTED
    one_line_error(stderr.decode())
    assert list(tmp_path.iterdir()) == []


# --------------------------------------------------------------------------- 7. --timeout is the whole run


def test_7_timeout_covers_reading_and_scoring(tmp_path):
    suite = tmp_path / "suite"
    assert run("generate", "coffee", "--count", "1", "--distractors", "20000", "--out", suite)[0] == 0
    started = time.monotonic()
    code, _, stderr = run(
        "plan",
        suite / "domain.pddl",
        suite / "coffee-simple-001.pddl",
        "-q",
        "--timeout",
        "0.05",
        "--plan-file",
        tmp_path / "plan",
    )
    assert code == ExitCode.OUT_OF_TIME
    line = one_line_error(stderr)
    assert "out of time while" in line and "--timeout" in line
    assert time.monotonic() - started < 20


# --------------------------------------------------------------------------- 8. deep nesting


def _nested_goal(depth: int) -> str:
    text = coffee_problem()
    start = text.index("(:goal") + len("(:goal")
    end = text.rindex(")", 0, text.rindex(")"))
    return text[:start] + " " + "(and " * depth + text[start:end].strip() + ")" * depth + text[end:]


def test_8_deep_nesting_is_exit_32_naming_file_and_line(files, tmp_path):
    domain, _ = files
    deep = tmp_path / "deep.pddl"
    deep.write_text(_nested_goal(500))
    for command in ("score", "plan"):
        code, _, stderr = run(command, domain, deep, "-q" if command == "plan" else "--json")
        assert code == ExitCode.PDDL_SYNTAX
        assert f"{deep}:" in one_line_error(stderr) and "nested" in stderr
    fine = tmp_path / "fine.pddl"
    fine.write_text(_nested_goal(100))
    assert run("plan", domain, fine, "-q", "--plan-file", tmp_path / "plan")[0] == 0


def test_8_compare_records_a_deep_problem_as_an_input_error_and_carries_on(tmp_path):
    suite = tmp_path / "suite"
    suite.mkdir()
    (suite / "domain.pddl").write_bytes(COFFEE_DOMAIN.read_bytes())
    (suite / "a.pddl").write_text(_nested_goal(500))
    (suite / "b.pddl").write_text(coffee_problem())
    store = tmp_path / "results.sqlite"
    code, stdout, _ = run("compare", suite, "--methods", "relevance", "--store", store, "-q")
    assert code == 0 and "1 input-error" in stdout and "1 solved" in stdout


# --------------------------------------------------------------------------- 9. YAML alias bomb


def test_9_yaml_alias_bomb_is_exit_35_at_once(files, tmp_path):
    domain, problem = files
    bomb = tmp_path / "bomb.yaml"
    lines = ['a0: &a0 ["lol", "lol", "lol", "lol", "lol", "lol", "lol", "lol", "lol"]']
    for level in range(1, 9):
        lines.append(f"a{level}: &a{level} [" + ", ".join([f"*a{level - 1}"] * 9) + "]")
    bomb.write_text("\n".join(lines) + "\n")
    started = time.monotonic()
    code, _, stderr = run("score", domain, problem, "--model", bomb)
    assert code == ExitCode.MODEL and "aliases" in one_line_error(stderr)
    assert time.monotonic() - started < 1.0


# --------------------------------------------------------------------------- 10. absurd limits


@pytest.mark.parametrize(
    "option, value",
    [
        ("--timeout", "inf"),
        ("--timeout", "nan"),
        ("--timeout", "1e12"),
        ("--timeout", "-1"),
        ("--memory-limit", "10000000000000"),
        ("--memory-limit", "-5"),
    ],
)
def test_10_absurd_limits_are_exit_30(files, tmp_path, option, value):
    domain, problem = files
    code, _, stderr = run("plan", domain, problem, "-q", option, value, "--plan-file", tmp_path / "plan")
    assert code == ExitCode.USAGE
    one_line_error(stderr)
    store = tmp_path / "results.sqlite"
    suite = tmp_path / "suite"
    suite.mkdir()
    (suite / "domain.pddl").write_bytes(domain.read_bytes())
    (suite / "p.pddl").write_bytes(problem.read_bytes())
    code, _, stderr = run("compare", suite, "--store", store, option, value, "-q")
    assert code == ExitCode.USAGE
    one_line_error(stderr)
    assert not store.exists()


# --------------------------------------------------------------------------- 11. sidecar schema


@pytest.mark.parametrize(
    "sidecar",
    ['{"necessary": [1, 2], "relevant": []}', '{"necessary": "cup"}', "[1, 2]", "not json", "[" * 5000 + "]" * 5000],
)
def test_11_bad_sidecars_are_exit_31_in_plan_and_sweep(tmp_path, sidecar):
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


# --------------------------------------------------------------------------- 12. path arguments


def test_12_a_directory_or_missing_file_is_exit_31_in_one_line(files, tmp_path):
    domain, problem = files
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
def test_12_an_unreadable_file_is_exit_31_in_one_line(files):
    domain, problem = files
    problem.chmod(0)
    code, _, stderr = run("score", domain, problem)
    assert code == ExitCode.INPUT_FILE
    one_line_error(stderr)


# --------------------------------------------------------------------------- 13. memory


def test_13_too_little_memory_for_the_planner_is_out_of_memory(files, tmp_path):
    domain, problem = files
    for limit in ("16", "20"):
        code, _, stderr = run("plan", domain, problem, "-q", "--memory-limit", limit, "--plan-file", tmp_path / "p")
        assert code == ExitCode.OUT_OF_MEMORY, stderr
        one_line_error(stderr)


def test_13_the_loaders_messages_are_out_of_memory():
    from relevance_plan.planning.runner import PlannerStatus, _classify

    log = "error while loading shared libraries: libc.so.6: failed to map segment from shared object"
    assert _classify(127, False, False, log, 0.0, 10.0, memory_limited=True) is PlannerStatus.OUT_OF_MEMORY
    assert _classify(120, False, False, "", 0.0, 10.0, memory_limited=True) is PlannerStatus.OUT_OF_MEMORY
    assert _classify(120, False, False, "", 0.0, 10.0, memory_limited=False) is PlannerStatus.PLANNER_CRASH


# --------------------------------------------------------------------------- 14. non-ASCII names


def test_14_non_ascii_object_names_are_named_before_planning(files, tmp_path):
    domain, problem = files
    problem.write_text(problem.read_text().replace("paper_cup_1", "tasse_café_1"))
    assert run("score", domain, problem)[0] == 0  # our reader takes them
    code, _, stderr = run("plan", domain, problem, "-q", "--plan-file", tmp_path / "plan")
    assert code == ExitCode.UNSUPPORTED_PDDL
    line = one_line_error(stderr)
    assert "tasse_café_1" in line and "non-ASCII" in line and "Fast Downward" in line


# --------------------------------------------------------------------------- 15. validate before writing


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
def test_15_demo_checks_options_before_writing(tmp_path, args):
    workdir = tmp_path / "demo"
    code, _, stderr = run("demo", "--workdir", workdir, *args)
    assert code == ExitCode.USAGE
    one_line_error(stderr)
    assert not workdir.exists()


def test_15_an_unreachable_scheduler_leaves_no_store(files, tmp_path):
    pytest.importorskip("dask.distributed")
    domain, problem = files
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


# --------------------------------------------------------------------------- 16. messages


def test_16_model_messages_name_the_class(files, tmp_path):
    domain, problem = files
    model = tmp_path / "model.yaml"
    text = (REPO / "domains" / "coffee" / "relevance.yaml").read_text()
    model.write_text(text)
    import yaml

    from relevance_plan.relevance.knowledge import parse_model

    data = yaml.safe_load(text)
    task = next(iter(data["tasks"]))
    class_name = next(iter(data["tasks"][task]))
    data["tasks"][task][class_name] = 7
    model.write_text(yaml.safe_dump(data))
    code, _, stderr = run("score", domain, problem, "--model", model)
    assert code == ExitCode.MODEL
    line = one_line_error(stderr)
    assert "{class}" not in line and f"P({class_name} | {task})" in line
    assert parse_model  # imported for the schema's error path


def test_16_generate_errors_have_no_progress_line(tmp_path):
    code, _, stderr = run("generate", "coffee", "--count", "-1", "--out", tmp_path / "s")
    assert code == ExitCode.USAGE
    assert "done" not in one_line_error(stderr)


@pytest.mark.parametrize("prefix, expected", [(b"\xef\xbb\xbf", "byte-order mark"), (b"\x00", "NUL byte")])
def test_16_bom_and_nul_are_named(files, tmp_path, prefix, expected):
    domain, problem = files
    bad = tmp_path / "bad.pddl"
    bad.write_bytes(prefix + problem.read_bytes())
    code, _, stderr = run("score", domain, bad)
    assert code == ExitCode.PDDL_SYNTAX
    line = one_line_error(stderr)
    assert expected in line and "\x00" not in line and "\ufeff" not in line


def test_16_duplicate_parameter_is_named(files, tmp_path):
    domain, problem = files
    text = domain.read_text()
    at = text.index(":parameters (") + len(":parameters (")
    domain.write_text(text[:at] + "?zz - object ?zz - object " + text[at:])
    code, _, stderr = run("score", domain, problem)
    assert code == ExitCode.PDDL_SYNTAX and "'?zz' is declared twice" in one_line_error(stderr)


def test_16_taus_errors_name_taus(tmp_path):
    suite = tmp_path / "suite"
    assert run("generate", "coffee", "--count", "1", "--out", suite)[0] == 0
    code, _, stderr = run("sweep", suite, "--taus", "0.1,7")
    assert code == ExitCode.USAGE
    line = one_line_error(stderr)
    assert "--taus" in line and "--tau-class" not in line


def test_16_unknown_planner_alias_is_named(files, tmp_path):
    domain, problem = files
    code, _, stderr = run(
        "plan", domain, problem, "-q", "--planner-config", "no-such-alias", "--plan-file", tmp_path / "plan"
    )
    assert code == ExitCode.USAGE and "'no-such-alias'" in one_line_error(stderr)


def test_16_suite_folders_follow_the_umask(tmp_path):
    old = os.umask(0o022)
    try:
        suite = tmp_path / "suite"
        code = subprocess.run(
            TOOL + ["generate", "coffee", "--count", "1", "--out", str(suite)], capture_output=True
        ).returncode
    finally:
        os.umask(old)
    assert code == 0 and stat.S_IMODE(suite.stat().st_mode) == 0o755


def test_16_tiny_does_not_hide_a_bad_distractor_count(tmp_path):
    code, _, stderr = run("demo", "--tiny", "--distractors", "-3", "--workdir", tmp_path / "d")
    assert code == ExitCode.USAGE and "--distractors" in one_line_error(stderr)
