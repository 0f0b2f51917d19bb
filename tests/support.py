"""Helpers shared by the test modules: paths, running the CLI, files, processes and store rows.

Fixtures live in ``conftest.py``; the coffee problems built in code in ``kitchen.py``; the
padded classic worlds in ``benchmarks/padded_worlds.py`` (``conftest.py`` puts ``benchmarks/``
on the path).  Nothing here imports the package at import time.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
DOMAINS = REPO / "domains"
PROBLEMS = REPO / "problems"
COFFEE_DOMAIN = DOMAINS / "coffee" / "domain.pddl"
COFFEE_MODEL = DOMAINS / "coffee" / "relevance.yaml"

# The tool as a separate process.
TOOL = [sys.executable, "-m", "relevance_plan"]


# --------------------------------------------------------------------------- the command line, in-process


def invoke(*args, input=None):
    """The click result of ``relevance-plan ARGS`` run in-process; a traceback fails the test."""
    from click.testing import CliRunner

    from relevance_plan.cli import main

    result = CliRunner().invoke(main, [str(a) for a in args], input=input)
    if result.exception is not None and not isinstance(result.exception, SystemExit):
        raise result.exception
    return result


def run(*args, input=None):
    """(exit code, stdout, stderr) of the command run in-process; a traceback fails the test."""
    result = invoke(*args, input=input)
    return result.exit_code, result.stdout, result.stderr


def one_line_error(stderr: str) -> str:
    lines = stderr.splitlines()
    assert len(lines) == 1, stderr
    assert lines[0].startswith("relevance-plan:") and "Traceback" not in stderr
    return lines[0]


# --------------------------------------------------------------------------- files


def write_file(directory: Path, name: str, data: str | bytes) -> Path:
    """``directory / name`` holding ``data`` (text or bytes)."""
    path = directory / name
    if isinstance(data, bytes):
        path.write_bytes(data)
    else:
        path.write_text(data)
    return path


def alias_bomb(levels: int = 9) -> bytes:
    """A YAML document whose aliases expand to 9**levels strings."""
    lines = ['a0: &a0 ["lol", "lol", "lol", "lol", "lol", "lol", "lol", "lol", "lol"]']
    for level in range(1, levels):
        lines.append(f"a{level}: &a{level} [" + ", ".join([f"*a{level - 1}"] * 9) + "]")
    return ("\n".join(lines) + "\n").encode()


# --------------------------------------------------------------------------- processes


def process_state(pid: int) -> str | None:
    """The state letter of ``pid`` in /proc (R, S, Z, ...), or None if it is gone."""
    try:
        return Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except OSError:
        return None


def running(pid: int) -> bool:
    """Alive and not a zombie waiting to be reaped by whoever adopted it (nor dead, X)."""
    return process_state(pid) not in (None, "Z", "X")


def process_gone(pid: int) -> bool:
    """Exited: no longer in /proc, or a zombie."""
    return not running(pid)


# --------------------------------------------------------------------------- results-store rows

TIMEOUT = 100.0


def make_row(
    suite,
    problem,
    method,
    status="solved",
    wall=1.0,
    relevance=0.0,
    first=None,
    kept=10,
    total=20,
    seed=0,
    config="c",
    exit_code=0,
    cost=None,
):
    """A complete results-store row, made by hand."""
    config_json = json.dumps({"method": method, "timeout": TIMEOUT, "config": config}, sort_keys=True)
    return {
        "problem_hash": f"hash-{suite}-{problem}",
        "method": method,
        "config_hash": f"{config}-{seed}",
        "planner_version": "1.0.0",
        "suite": suite,
        "problem": f"{problem}.pddl",
        "world": "coffee",
        "difficulty": "simple",
        "seed": seed,
        "status": status,
        "valid": int(status == "solved"),
        "exit_code": exit_code,
        "wall_time": wall,
        "relevance_time": relevance,
        "planner_time": max(wall - relevance, 0.0),
        "objects_total": total,
        "objects_kept": kept,
        "attempts": 1,
        "first_attempt_status": first or status,
        "plan_length": 10 if status == "solved" else None,
        "plan_cost": (10.0 if cost is None else cost) if status == "solved" else None,
        "timeout": TIMEOUT,
        "message": "",
        "config_json": config_json,
        "finished_at": "2026-11-22T00:00:00.000+00:00",
        "result_json": "{}",
    }


# --------------------------------------------------------------------------- other processes


def outputs_under_hash_seeds(script: str, seeds: tuple[str, ...] = ("1", "2"), *args: str) -> list[str]:
    """What ``python -c script args`` prints in a new process under each hash seed: sets and
    dicts of strings iterate in another order in each."""
    return [
        subprocess.run(
            [sys.executable, "-c", script, *args],
            env=dict(os.environ, PYTHONHASHSEED=seed),
            capture_output=True,
            text=True,
            check=True,
        ).stdout
        for seed in seeds
    ]


# --------------------------------------------------------------------------- a store written by several processes


def write_store_rounds(barrier, folder: str, rounds: int, writer: str, jobs: int) -> None:
    """In a child process: for each round, wait for the other writers, then create the round's store
    (the same new path for every writer) and add ``jobs`` rows of its own plus one row all share."""
    from relevance_plan.batch.store import ResultStore

    for number in range(rounds):
        barrier.wait(timeout=120)
        with ResultStore(Path(folder) / f"round-{number}.sqlite") as store:
            store.add(make_row("s", "shared", "pure"))
            for job in range(jobs):
                store.add(make_row("s", f"{writer}-{job}", "pure"))
