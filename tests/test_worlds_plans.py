"""Plans exist for every newer world, on the full problem and on its sidecar's sufficient set, and each
plan is valid on the ORIGINAL problem by the builtin simulator.

Classical worlds are planned with Fast Downward; temporal and numeric ones with the LPG-td binary
that the up-lpg wheel ships (it reads PDDL 2.1 itself).  LPG writes ``t: (ACTION ARGS) [D:d; C:c]``
lines in upper case; ``lpg_plan`` rewrites them as IPC timed steps for ``read_plan``.
"""

from __future__ import annotations

import os
import re
import subprocess
from pathlib import Path

import pytest

from relevance_plan.data import DOMAINS_DIR
from relevance_plan.generators import WORLDS, Settings
from relevance_plan.pddl.parser import read_domain, read_problem
from relevance_plan.pddl.plans import Plan, PlanStep, read_plan
from relevance_plan.pddl.writer import write_pruned_problem
from relevance_plan.planning.validation import simulate

pytestmark = pytest.mark.planner

LPG_STEP = re.compile(r"^\s*(\d+(?:\.\d+)?):\s*(\([^()]*\))\s*\[(?:D:)?(\d+(?:\.\d+)?)")


def lpg_binary() -> Path:
    up_lpg = pytest.importorskip("up_lpg", reason="the LPG tests need the up-lpg wheel (the 'test' extra)")
    return Path(os.path.dirname(up_lpg.__file__)) / "lpg"


def lpg_plan(domain: Path, problem: Path, workdir: Path, timeout: float = 600) -> Plan | None:
    """LPG-td's first plan (seed 1), or None when it finds none."""
    workdir.mkdir(parents=True, exist_ok=True)
    command = [str(lpg_binary()), "-o", str(domain), "-f", str(problem), "-n", "1", "-out", "plan", "-seed", "1"]
    subprocess.run(command, cwd=workdir, capture_output=True, timeout=timeout, check=False)
    found = workdir / "plan_1.SOL"
    if not found.is_file():
        return None
    steps = [LPG_STEP.match(line) for line in found.read_text().splitlines()]
    return read_plan("".join(f"{m[1]}: {m[2].lower()} [{m[3]}]\n" for m in steps if m))


def fast_downward_plan(domain: Path, problem: Path) -> Plan | None:
    from relevance_plan.planning.planners.fast_downward.adapter import run_fast_downward

    outcome = run_fast_downward(domain, problem, time_limit=120)
    return outcome.plan if outcome.solved else None


def in_time_order(plan: Plan) -> Plan:
    """A plan of instantaneous actions as the sequence LPG means: its steps in time order (steps
    sharing a time stamp are one parallel step of non-interfering actions)."""
    return Plan(tuple(PlanStep(s.action, s.args) for s in sorted(plan.steps, key=lambda s: s.time or 0.0)))


def check_world(tmp_path: Path, folder: str, text: str, necessary: list[str], full: bool = True) -> None:
    domain_path = DOMAINS_DIR / folder / "domain.pddl"
    domain = read_domain(domain_path.read_text())
    original = read_problem(text, domain)
    files = {"necessary": write_pruned_problem(original, set(necessary))}
    if full:
        files["full"] = text
    for label, problem_text in files.items():
        problem_path = tmp_path / f"{label}.pddl"
        problem_path.write_text(problem_text)
        if domain.temporal or domain.numeric:
            plan = lpg_plan(domain_path, problem_path, tmp_path / f"lpg-{label}")
        else:
            plan = fast_downward_plan(domain_path, problem_path)
        assert plan is not None and len(plan) > 0, f"no plan for the {label} problem"
        if not domain.temporal and plan.timed:
            plan = in_time_order(plan)
        outcome = simulate(domain, original, plan)
        assert outcome.valid, f"{label}: {outcome.message}"


@pytest.mark.parametrize(
    "world,difficulty,distractors",
    [
        ("coffee-temporal", "simple", 4),
        ("coffee-temporal", "hard", 0),
        ("cereal-temporal", "simple", 4),
        ("coffee-numeric", "simple", 4),
        ("coffee-numeric", "hard", 0),
    ],
)
def test_kitchen_variants_full_with_few_distractors(tmp_path, world, difficulty, distractors):
    problem = WORLDS[world].problem(3, 1, Settings(difficulty, distractors=distractors))
    check_world(tmp_path, world, problem.pddl_text, problem.sidecar["necessary"])


@pytest.mark.parametrize("world", ["coffee-temporal", "cereal-temporal", "coffee-numeric"])
@pytest.mark.parametrize("difficulty", ["simple", "hard"])
def test_kitchen_variants_necessary_set_with_the_papers_distractors(tmp_path, world, difficulty):
    problem = WORLDS[world].problem(5, 2, Settings(difficulty))
    check_world(tmp_path, world, problem.pddl_text, problem.sidecar["necessary"], full=False)


@pytest.mark.parametrize(
    "world,size",
    [
        ("driverlog-temporal", 60),
        ("zenotravel-numeric", 60),
        ("scenegraph", 200),
        ("logistics-manygoals", 60),
        ("logistics-manygoals-typed", 60),
        ("miconic-manygoals", 120),
    ],
)
def test_sized_worlds_full_and_necessary(tmp_path, world, size):
    problem = WORLDS[world].problem(3, 1, Settings(size=size))
    check_world(tmp_path, WORLDS[world].domain, problem.pddl_text, problem.sidecar["necessary"])


@pytest.mark.slow
@pytest.mark.parametrize(
    "world,size",
    [("scenegraph", 500), ("driverlog-temporal", 100), ("zenotravel-numeric", 100), ("miconic-manygoals", 1000)],
)
def test_sized_worlds_at_benchmark_sizes(tmp_path, world, size):
    problem = WORLDS[world].problem(1, 1, Settings(size=size))
    check_world(tmp_path, WORLDS[world].domain, problem.pddl_text, problem.sidecar["necessary"])


@pytest.mark.slow
def test_coffee_temporal_hard_full_size(tmp_path):
    problem = WORLDS["coffee-temporal"].problem(1, 1, Settings("hard"))
    check_world(tmp_path, "coffee-temporal", problem.pddl_text, problem.sidecar["necessary"])
