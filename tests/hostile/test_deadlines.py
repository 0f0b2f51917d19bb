"""Deadlines that hold against huge inputs and planners that never answer; floods from a planner."""

from __future__ import annotations

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

SCENARIOS = DEADLINES + FLOODS


test_deadlines_and_floods = scenario_test(SCENARIOS)
