"""Deadlines that hold against huge inputs and planners that never answer; floods from a planner."""

from __future__ import annotations

import json
import shutil
from collections.abc import Callable
from pathlib import Path

from support import REPO

from hostile.inputs import PLAN_PURE, big_problem, files, planner, says, slow_model, suite, write
from hostile.scenario import MODEL, NO_VALID, OK, PLANNER, TIME, Result, Scenario, scenario_test


def _ratio_at_most(limit: float) -> Callable[[Result], str | None]:
    """The shell printed three clock readings around two runs: the first run may take ``limit`` x the second."""

    def check(result: Result) -> str | None:
        start, middle, end = (float(value) for value in result.stdout.split()[-3:])
        ratio = (middle - start) / max(end - middle, 1e-3)
        return None if ratio <= limit else f"the single line took {ratio:.1f} x as long as with newlines"

    return check


def _big_suite(work: Path) -> None:
    (work / "bigsuite").mkdir()
    shutil.copy(work / "D.pddl", work / "bigsuite" / "domain.pddl")
    write(work, "bigsuite/p01.pddl", big_problem(150_000))


def _forall_goal(objects: int) -> str:
    text = (REPO / "problems" / "coffee-simple.pddl").read_text()
    names = " ".join(f"q{i}" for i in range(objects))
    goal = "(forall (?x ?y ?z - plate) (or (not (clear ?x)) (clear ?x) (clear ?y) (clear ?z)))"
    return text.replace("(:objects", f"(:objects {names} - plate", 1).replace("(:goal (and", f"(:goal (and {goal}", 1)


PLAN = ("plan", "D.pddl", "P.pddl", "-q", "--plan-file", "out.plan")
BIG = files(big_dot_pddl=lambda: big_problem(150_000))

DEADLINES = [
    Scenario(
        "deadlines/huge-problem-reading",
        args=("plan", "D.pddl", "big.pddl", "-q", "--timeout", "2"),
        setup=BIG,
        codes=(TIME,),
        timeout=2,
        quick=True,
    ),
    Scenario(
        "deadlines/huge-problem-pure",
        args=("plan", "D.pddl", "big.pddl", "-q", "--timeout", "3", "--method", "pure"),
        setup=BIG,
        codes=(TIME,),
        timeout=3,
    ),
    Scenario(
        "deadlines/huge-problem-compare-job",
        args=("compare", "bigsuite", "--methods", "pure", "--timeout", "2", "--store", "s.sqlite", "-q"),
        setup=_big_suite,
        codes=(OK,),
        timeout=2,
        writes=("s.sqlite*",),
    ),
    Scenario(
        "deadlines/slow-model",
        args=PLAN + ("--model", "slow.yaml", "--timeout", "2"),
        setup=files(slow_dot_yaml=slow_model),
        codes=(TIME, MODEL),
        timeout=2,
    ),
    Scenario(
        "deadlines/planner-fast-downward-too-slow",
        args=("plan", "D.pddl", "mid.pddl", "-q", "--method", "pure", "--timeout", "3"),
        setup=files(mid_dot_pddl=lambda: big_problem(3000)),
        codes=(TIME,),
        timeout=3,
    ),
    Scenario(
        "deadlines/validation-of-a-huge-forall",
        args=("plan", "D.pddl", "forall.pddl", "-q", "--method", "pure", "--timeout", "4"),
        setup=files(forall_dot_pddl=lambda: _forall_goal(400)),
        codes=(TIME, OK),
        timeout=4,
    ),
    Scenario(
        "deadlines/watch-plan-event-never-answered",
        args=(
            "watch",
            "D.pddl",
            "P.pddl",
            "--events",
            "ev.jsonl",
            "--timeout",
            "2",
            "--planner",
            planner("never.py"),
        ),
        setup=files(ev_dot_jsonl='{"event": "plan"}\n'),
        timeout=2,
        check=says("out-of-time", where="stdout"),
    ),
    Scenario(
        "deadlines/compare-jobs-never-answered",
        args=(
            "compare",
            "suite",
            "--methods",
            "pure,relevance",
            "--timeout",
            "1",
            "--store",
            "s.sqlite",
            "-q",
            "--planner",
            planner("never.py"),
        ),
        setup=suite,
        budget=6,
        writes=("s.sqlite*",),
    ),
    Scenario(
        "deadlines/single-line-as-fast-as-lines",
        shell="date +%s.%N; $TOOL prune D.pddl line.pddl -o o1.pddl"
        " >/dev/null; date +%s.%N; $TOOL prune D.pddl lines.pddl -o o2.pddl > /dev/null; date +%s.%N",
        setup=files(line_dot_pddl=lambda: big_problem(22_000, True), lines_dot_pddl=lambda: big_problem(22_000)),
        writes=("o1.pddl", "o2.pddl"),
        check=_ratio_at_most(1.5),
    ),
    *(
        Scenario(
            f"deadlines/never-answers-{seconds}s",
            args=PLAN_PURE + ("--timeout", str(seconds), "--planner", planner("never.py")),
            codes=(TIME,),
            timeout=seconds,
            quick=seconds == 1,
        )
        for seconds in (1, 2, 3)
    ),
]


def flood(name: str, script: str, codes: tuple, plan_file: bool = False, rss: int = 300) -> Scenario:
    args = PLAN_PURE + ("--timeout", "20", "--planner", planner(script, plan_file))
    return Scenario(f"floods/{name}", args=args, codes=codes, budget=15, max_rss_mb=rss)


FLOODS = [
    flood("150-mb-on-stdout", "flood_stdout.py", (PLANNER,)),
    flood("20-mb-single-line-on-stdout", "long_line.py", (PLANNER,)),
    flood("two-million-comment-lines", "comment_lines.py", (NO_VALID,)),
    flood("200-mb-plan-file", "huge_plan_file.py", (PLANNER,), plan_file=True),
    flood("plan-line-of-120000-spaces", "spaces.py", (NO_VALID,)),
    flood("plan-file-is-a-fifo", "fifo_plan.py", (PLANNER,), plan_file=True),
    flood("plan-file-links-to-dev-zero", "zero_plan.py", (PLANNER,), plan_file=True),
    flood("binary-on-stdout", "garbage.py", (PLANNER,)),
    flood("planner-segfaults", "crash.py", (PLANNER,)),
    Scenario(
        "floods/prune-a-10-mb-problem",
        args=("prune", "D.pddl", "big.pddl", "-o", "out.pddl"),
        setup=BIG,
        writes=("out.pddl",),
        max_rss_mb=1500,
        budget=80,
    ),
]


def _counts(total: int | None, kept: str) -> Callable[[Result], str | None]:
    """``plan --json`` names the problem's objects (``total``; None: not yet read) and what was kept:
    "selection" (fewer than all), "none" (no selection yet, null) or "any" (null or a count); no side
    is named a race's winner."""

    def check(result: Result) -> str | None:
        try:
            data = json.loads(result.stdout)
        except ValueError:
            return f"not JSON: {result.stdout[-200:]!r}"
        found = (data["objects_total"], data["objects_kept"], data["deciding_side"])
        if total is not None and data["objects_total"] != total:
            return f"objects_total, objects_kept, deciding_side: {found}, expected {total} in all"
        if total is None and data["objects_total"] not in (None, 150_019):
            return f"objects_total {data['objects_total']!r}: neither unknown nor the problem's"
        kept_ok = {
            "selection": isinstance(data["objects_kept"], int) and 0 < data["objects_kept"] < (total or 0),
            "none": data["objects_kept"] is None,
            "any": data["objects_kept"] is None or data["objects_kept"] > 0,
        }[kept]
        return None if kept_ok and data["deciding_side"] is None else f"counts and winner: {found}"

    return check


def _summary_says(*needles: str, never: tuple = ()) -> Callable[[Result], str | None]:
    def check(result: Result) -> str | None:
        missing = [needle for needle in needles if needle not in result.stdout]
        present = [word for word in never if word in result.stdout]
        return f"summary lacks {missing} or has {present}: {result.stdout[-400:]!r}" if missing or present else None

    return check


def _json_line(args: tuple) -> str:
    """A shell line running ``plan ARGS --json`` that must end out of time (exit 20), saying nothing else."""
    quoted = " ".join(f"'{arg}'" for arg in args)
    return f"$TOOL {quoted} --json 2> err; test $? = {TIME} && test ! -s err"


NEVER = ("--planner", planner("never.py"))
RACED = ("plan", "D.pddl", "P.pddl", "--race", "--plan-file", "out.plan")
# what a run stopped at its --timeout (or lost by every side) says: the counts it had, no winner
COUNTS = [
    Scenario(
        "deadlines/json-counts-while-a-planner-runs",
        shell=_json_line(RACED + ("--timeout", "5") + NEVER),
        writes=("err",),
        timeout=5,
        check=_counts(19, "selection"),
        quick=True,
    ),
    Scenario(
        "deadlines/summary-counts-while-a-planner-runs",
        args=RACED + ("-q", "--timeout", "5") + NEVER,
        codes=(TIME,),
        timeout=5,
        check=_summary_says("kept of 19", "race:        no side won", never=("0 kept of 0", " won;", "won\n")),
    ),
    Scenario(
        "deadlines/json-counts-without-pruning",
        shell=_json_line(PLAN_PURE + ("--timeout", "5") + NEVER),
        writes=("err",),
        timeout=5,
        check=_counts(19, "any"),
    ),
    Scenario(
        "deadlines/json-counts-while-reading-a-huge-problem",
        shell=_json_line(("plan", "D.pddl", "big.pddl", "--timeout", "2")),
        setup=BIG,
        writes=("err",),
        timeout=2,
        check=_counts(None, "any"),  # read in time on a fast machine: then the counts are the real ones
    ),
    Scenario(
        "deadlines/summary-while-reading-a-huge-problem",
        args=("plan", "D.pddl", "big.pddl", "-q", "--timeout", "2"),
        setup=BIG,
        codes=(TIME,),
        timeout=2,
        check=_summary_says("objects:", never=("0 kept of 0",)),
    ),
    Scenario(
        "deadlines/race-lost-by-both-sides-is-no-win",
        args=RACED + ("-q", "--timeout", "20", "--planner", planner("crash.py")),
        codes=(PLANNER,),
        check=_summary_says("no side won (pruned side: planner-crash, full problem: planner-crash)"),
    ),
]

SCENARIOS = DEADLINES + FLOODS + COUNTS


test_deadlines_and_floods = scenario_test(SCENARIOS)
