#!/usr/bin/env python
"""The tool against a temporal engine alone, on IPC driverlog with time, unpadded and padded.

For each size N (N objects of each kind added to the IPC's ``driverlog-time-automatic``
instance-3 of the in-repository corpus: packages, trucks, drivers and
linked locations the goal does not need), it times, in this one run:

- ``engine``: the engine alone, as a fresh Python process would call it
  (``python -m relevance_plan.planning.planners.up.child``: import
  unified-planning, read, fit, solve) — the per-attempt child of the tool,
  which imports ConfigSpace only if the engine asks for it (about 1.2 s
  less than a plain script's ``import unified_planning.shortcuts``), so
  this baseline is the faster one;
- ``pure``: ``relevance-plan plan --method pure`` (a whole process);
- ``no-race``: ``relevance-plan plan --no-race`` (relevance, one core);
- ``race``: ``relevance-plan plan --race``.

Every plan the tool reports is validated on the original problem (the tool
does it; the script checks the JSON says so).  Prints one row per run with
the attempts (objects kept, time limit, status), then the ratios.

    python benchmarks/bench_budgets.py                       # up:aries; sizes 0, 60, 120: about 2 minutes
    python benchmarks/bench_budgets.py --planner up:tamer --extra 0 60
"""

from __future__ import annotations

import argparse
import json
import sys
import tempfile
from pathlib import Path

import corpus
from base import REPO, run_timed

from relevance_plan.generators.padded import padded_driverlog

FOLDER = corpus.corpus_root() / "potassco" / "ipc-2002" / "driverlog-time-automatic"
DOMAIN = FOLDER / "domain.pddl"
PROBLEM = FOLDER / "instances" / "instance-3.pddl"


def engine_alone(engine: str, problem: Path, folder: Path, timeout: float) -> tuple[float, str]:
    command = [sys.executable, "-m", "relevance_plan.planning.planners.up.child", engine, str(DOMAIN)]
    command += [str(problem), str(folder / "plan"), str(folder / "verdict"), f"{timeout:g}"]
    run = run_timed(command, cwd=REPO)
    verdict = (folder / "verdict").read_text().strip() if (folder / "verdict").exists() else "none"
    return run.seconds, verdict


def tool(problem: Path, planner: str, extra: list[str], folder: Path, timeout: float) -> tuple[float, dict]:
    command = [sys.executable, "-m", "relevance_plan", "plan", str(DOMAIN), str(problem), "--planner", planner]
    command += ["--timeout", f"{timeout:g}", "--json", "--plan-file", str(folder / "sas_plan"), *extra]
    run = run_timed(command, cwd=REPO)
    try:
        return run.seconds, json.loads(run.stdout)
    except ValueError:
        return run.seconds, {"status": "no-json", "attempt_log": []}


def describe(result: dict) -> str:
    steps = [
        f"{a['objects_kept']}:{a['status']}" + (f"<{a['time_limit']:.0f}s" if a["time_limit"] else "")
        for a in result.get("attempt_log", [])
    ]
    valid = "valid" if result.get("valid") else "NOT VALID"
    return f"{result['status']} ({valid}; raced: {result.get('raced')}) " + " ".join(steps)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0],
        epilog="Sizes 0, 60 and 120 with up:aries take about 2 minutes on 2 cores.",
    )
    parser.add_argument("--planner", default="up:aries")
    parser.add_argument("--extra", type=int, nargs="+", default=[0, 60, 120])
    parser.add_argument("--timeout", type=float, default=300.0)
    args = parser.parse_args(argv)
    engine = args.planner.removeprefix("up:")
    with tempfile.TemporaryDirectory(prefix="bench-budgets-") as scratch:
        folder = Path(scratch)
        for extra in args.extra:
            problem = folder / f"driverlog-{extra}.pddl"
            problem.write_text(padded_driverlog(PROBLEM.read_text(), extra))
            objects = 14 + 4 * extra
            alone, verdict = engine_alone(engine, problem, folder, args.timeout)
            print(f"+{extra:<4} ({objects} objects) engine alone {alone:7.2f} s  {verdict}", flush=True)
            times = {}
            for name, flags in (("pure", ["--method", "pure"]), ("no-race", ["--no-race"]), ("race", ["--race"])):
                seconds, result = tool(problem, args.planner, flags, folder, args.timeout)
                times[name] = seconds if result.get("status") == "solved" else float("inf")
                print(f"+{extra:<4} {name:15} {seconds:7.2f} s  {describe(result)}", flush=True)
            ratios = ", ".join(f"{name} {alone / t:.2f}x" for name, t in times.items())
            print(f"+{extra:<4} engine alone / tool: {ratios}", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
