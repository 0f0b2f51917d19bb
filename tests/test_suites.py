"""Suite folders in the field's layouts: discovery pairs every problem with its domain,
and compare, sweep and report run over IPC, potassco and pddlgym folders."""

from __future__ import annotations

import json
import os
import subprocess
import threading
from pathlib import Path

import pytest
from support import REPO, TOOL, invoke, one_line_error

from relevance_plan.batch.jobs import build_jobs, run_job
from relevance_plan.batch.suites import find_suite_problems, suite_name
from relevance_plan.errors import InputFileError
from relevance_plan.exitcodes import ExitCode

GRIPPER = (REPO / "relevance_plan" / "data" / "domains" / "gripper" / "domain.pddl").read_text()


def gripper_problem(balls: int, name: str = "g") -> str:
    """Carry ``balls`` balls from rooma to roomb (a second of planning at most)."""
    names = [f"ball{i}" for i in range(1, balls + 1)]
    facts = ["(room rooma)", "(room roomb)", "(gripper left)", "(gripper right)", "(at-robby rooma)"]
    facts += ["(free left)", "(free right)"] + [f"(ball {b}) (at {b} rooma)" for b in names]
    goal = " ".join(f"(at {b} roomb)" for b in names)
    return (
        f"(define (problem {name}) (:domain gripper)\n"
        f"  (:objects rooma roomb left right {' '.join(names)})\n"
        f"  (:init {' '.join(facts)})\n  (:goal (and {goal})))\n"
    )


def write_layout(root: Path, files: dict[str, str]) -> None:
    """``files`` maps a relative path to 'domain' or to a problem's number of balls ('1', '2')."""
    for relative, kind in files.items():
        path = root / relative
        path.parent.mkdir(parents=True, exist_ok=True)
        # Named after its path: problems of different suites differ, so compare runs each.
        name = "p-" + "".join(c if c.isalnum() else "-" for c in str(root.name + "/" + relative))
        path.write_text(GRIPPER if kind == "domain" else gripper_problem(int(kind), name))


def layout(given: str, name: str, *pairs: tuple[str, str]) -> tuple:
    """(files, the folder given, expected suite name, expected (problem, domain) pairs relative to the root):
    the files are each pair's domain and problem (the n-th problem a gripper problem of n balls)."""
    files = {}
    for number, (problem, domain) in enumerate(pairs, 1):
        files[domain] = "domain"
        files[problem] = str(number)
    return files, given, name, list(pairs)


LAYOUTS = {
    "one-domain-per-suite": layout("s", "s", ("s/p01.pddl", "s/domain.pddl"), ("s/p02.pddl", "s/domain.pddl")),
    "problem-domain-suffix": layout("s", "s", ("s/p01.pddl", "s/p01-domain.pddl"), ("s/p02.pddl", "s/p02_domain.pddl")),
    "domain-problem-prefix": layout("s", "s", ("s/p01.pddl", "s/domain_p01.pddl"), ("s/p02.pddl", "s/domain-p02.pddl")),
    "numbered-domains": layout("s", "s", ("s/p01.pddl", "s/domain-01.pddl"), ("s/p02.pddl", "s/domain-02.pddl")),
    "d-and-p-by-content": layout("s", "s", ("s/p01.pddl", "s/d01.pddl"), ("s/p02.pddl", "s/d02.pddl")),
    "potassco-numbered": layout(
        "t",
        "t",
        ("t/instances/instance-1.pddl", "t/domains/domain-1.pddl"),
        ("t/instances/instance-2.pddl", "t/domains/domain-2.pddl"),
    ),
    "potassco-one-domain": layout(
        "t", "t", ("t/instances/instance-1.pddl", "t/domain.pddl"), ("t/instances/instance-2.pddl", "t/domain.pddl")
    ),
    "instances-folder-given": layout(
        "t/instances",
        "t",
        ("t/instances/instance-1.pddl", "t/domain.pddl"),
        ("t/instances/instance-2.pddl", "t/domain.pddl"),
    ),
    "domain-in-parent": layout(
        "w/easy", "easy", ("w/easy/p01.pddl", "w/domain.pddl"), ("w/easy/p02.pddl", "w/domain.pddl")
    ),
    "pddlgym": layout(
        "pddl/gripper",
        "gripper",
        ("pddl/gripper/problem1.pddl", "pddl/gripper.pddl"),
        ("pddl/gripper/problem2.pddl", "pddl/gripper.pddl"),
    ),
    "pddlgym-test-problems": layout(
        "pddl/gripper_test",
        "gripper_test",
        ("pddl/gripper_test/problem1.pddl", "pddl/gripper.pddl"),
        ("pddl/gripper_test/problem2.pddl", "pddl/gripper.pddl"),
    ),
}


# --------------------------------------------------------------------------- discovery


@pytest.mark.parametrize("layout", LAYOUTS)
def test_every_layout_pairs_each_problem_with_its_domain(tmp_path, layout):
    files, given, name, expected = LAYOUTS[layout]
    write_layout(tmp_path, files)
    found = find_suite_problems(tmp_path / given)
    assert [(p.problem, p.domain, p.error) for p in found] == [
        (tmp_path / problem, tmp_path / domain, None) for problem, domain in expected
    ]
    assert suite_name(tmp_path / given) == name


def test_problems_come_in_natural_name_order(tmp_path):
    write_layout(tmp_path, {"s/domain.pddl": "domain"} | {f"s/problem{i}.pddl": "1" for i in (10, 2, 1)})
    assert [p.problem.name for p in find_suite_problems(tmp_path / "s")] == [
        "problem1.pddl",
        "problem2.pddl",
        "problem10.pddl",
    ]


@pytest.mark.parametrize(
    "files, given, message",
    [
        ({"pddl/blocks.pddl": "domain", "pddl/gripper.pddl": "domain"}, "pddl", "suite has no problem files"),
        ({"s/p01.pddl": "1", "s/p02.pddl": "1"}, "s", "no domain file for any problem here"),
        ({"s/domain.pddl": "domain"}, "s", "suite has no problem files"),
        ({}, "missing", "suite directory not found"),
    ],
    ids=["only-domains", "no-domain", "no-problems", "missing"],
)
def test_a_folder_without_a_usable_pair_is_refused_naming_it(tmp_path, files, given, message):
    write_layout(tmp_path, files)
    with pytest.raises(InputFileError) as raised:
        find_suite_problems(tmp_path / given)
    assert message in str(raised.value) and str(tmp_path / given) in str(raised.value)


def bad_entries(suite: Path) -> dict[str, str]:
    """Entries that cannot be run, next to good ones; their expected per-problem error."""
    (suite / "dangling.pddl").symlink_to(suite / "no-such-file.pddl")
    os.mkfifo(suite / "fifo.pddl")
    (suite / "folder.pddl").mkdir()
    return {
        "dangling.pddl": "problem file is a link to a file that does not exist",
        "fifo.pddl": "problem file is not a regular file (a FIFO)",
        "folder.pddl": "problem file is not a regular file (a directory)",
    }


def test_entries_that_cannot_run_are_reported_per_problem(tmp_path):
    write_layout(tmp_path, {"s/p01-domain.pddl": "domain", "s/p01.pddl": "1", "s/p02.pddl": "1"})
    write_layout(tmp_path, {"s/domain-03.pddl": "domain", "s/d03.pddl": "domain", "s/p03.pddl": "1"})
    expected = bad_entries(tmp_path / "s")
    expected |= {
        "p01.pddl": None,
        "p02.pddl": "no domain file found for this problem",
        "p03.pddl": "several domain files could go with this problem: d03.pddl, domain-03.pddl",
    }
    found = {p.problem.name: p.error for p in find_suite_problems(tmp_path / "s")}
    assert found == expected


def test_jobs_of_unrunnable_problems_record_the_reason_without_planning(tmp_path):
    write_layout(tmp_path, {"s/domain.pddl": "domain", "s/p01.pddl": "1"})
    reasons = bad_entries(tmp_path / "s")
    jobs = [job for job in build_jobs([tmp_path / "s"], "pure,relevance") if job.input_error]
    assert sorted({job.problem for job in jobs}) == sorted(reasons)
    rows = [run_job(job) for job in jobs]  # a FIFO is never opened: this returns at once
    assert {row["status"] for row in rows} == {"input-error"}
    assert all(reasons[row["problem"]] in row["message"] and row["problem"] in row["message"] for row in rows)
    assert len({job.key for job in jobs}) == len(jobs)
    # Keys do not depend on where the suite lives.
    moved = tmp_path / "elsewhere"
    moved.mkdir()
    (tmp_path / "s").rename(moved / "s")
    again = [job for job in build_jobs([moved / "s"], "pure,relevance") if job.input_error]
    assert [job.key for job in again] == [job.key for job in jobs]


# --------------------------------------------------------------------------- compare, sweep and report


@pytest.mark.planner
def test_compare_runs_ipc_potassco_and_pddlgym_folders_and_records_bad_entries(tmp_path):
    for layout in ("problem-domain-suffix", "potassco-numbered", "pddlgym"):
        write_layout(tmp_path / layout, LAYOUTS[layout][0])
    suites = [tmp_path / "problem-domain-suffix" / "s", tmp_path / "potassco-numbered" / "t"]
    suites.append(tmp_path / "pddlgym" / "pddl" / "gripper")
    reasons = bad_entries(suites[0])
    store = tmp_path / "results.sqlite"
    # A separate process with a deadline: a FIFO that were opened would block forever.
    command = [*TOOL, "compare", *map(str, suites), "--methods", "pure,relevance", "--store", str(store), "-q"]
    finished = subprocess.run(command, cwd=REPO, capture_output=True, text=True, timeout=300)
    assert finished.returncode == 0, finished.stderr
    assert "18 jobs: 0 already stored, 18 run (6 input-error, 12 solved)" in finished.stdout
    result = invoke("report", store, "--json")
    rows = json.loads(result.stdout)
    assert {(r["suite"], r["status"]) for r in rows if r["problem"] not in reasons} == {
        ("s", "solved"),
        ("t", "solved"),
        ("gripper", "solved"),
    }
    assert {r["problem"] for r in rows if r["status"] == "input-error"} == set(reasons)


def test_sweep_without_sidecars_reports_kept_counts_and_timing(tmp_path):
    write_layout(tmp_path, LAYOUTS["pddlgym"][0])
    result = invoke("sweep", tmp_path / "pddl" / "gripper", "--taus", "0.2,0.4", "--scorer", "goal")
    assert result.exit_code == 0, result.output
    assert "no ground truth" in result.stdout
    assert "objects kept (after closure) of 5.5 on average" in result.stdout
    assert "s per problem to read and score" in result.stdout
    assert "precision" not in result.stdout
    data = json.loads(invoke("sweep", tmp_path / "pddl" / "gripper", "--taus", "0.2", "--json").stdout)
    assert data["with_truth"] == 0 and data["relevant"] == [] and data["problems"] == 2
    assert data["kept"][0]["objects_kept"] > 0 and data["objects_total"] == pytest.approx(5.5)


def test_sweep_names_a_problem_that_cannot_run(tmp_path):
    write_layout(tmp_path, {"s/domain.pddl": "domain", "s/p01.pddl": "1"})
    os.mkfifo(tmp_path / "s" / "p02.pddl")
    result = invoke("sweep", tmp_path / "s")
    assert result.exit_code == ExitCode.INPUT_FILE
    line = one_line_error(result.stderr)
    assert "p02.pddl" in line and "FIFO" in line


@pytest.mark.parametrize(
    "name",
    ["domain.pddl", pytest.param("p01.json", marks=pytest.mark.planner)],
    ids=["domain", "oracle-sidecar"],
)
def test_a_fifo_where_a_job_reads_is_never_opened(tmp_path, name):
    write_layout(tmp_path, {"s/domain.pddl": "domain", "s/p01.pddl": "1"})
    (tmp_path / "s" / name).unlink(missing_ok=True)
    os.mkfifo(tmp_path / "s" / name)
    rows = []
    worker = threading.Thread(
        target=lambda: rows.extend(run_job(job) for job in build_jobs([tmp_path / "s"], "pure,oracle")), daemon=True
    )
    worker.start()
    worker.join(timeout=60)
    assert not worker.is_alive(), "a FIFO was opened"
    if name == "domain.pddl":
        assert {row["status"] for row in rows} == {"input-error"}
        assert all("its domain file domain.pddl is not a regular file (a FIFO)" in row["message"] for row in rows)
