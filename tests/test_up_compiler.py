"""unified-planning idioms: the documented snippets, the anytime meta-engine, no credits banner.

There is deliberately no ``Compiler(name="relevance")`` (pruning is no
compilation kind; docs/unified-planning.md says why): the compiler's shape is
shown with ``relevance_plan.prune`` and ``restrict_problem``/``lift_plan``,
and that snippet runs here with the others.
"""

from __future__ import annotations

import re
import subprocess
import sys
import textwrap

import pytest
from support import REPO
from unified_planning.engines import PlanGenerationResultStatus as Status
from unified_planning.engines.mixins.anytime_planner import AnytimeGuarantee
from unified_planning.engines.results import ValidationResultStatus
from unified_planning.exceptions import UPUsageError
from unified_planning.shortcuts import (
    AnytimePlanner,
    BoolType,
    Fluent,
    InstantaneousAction,
    MinimizeActionCosts,
    Object,
    PlanValidator,
    Problem,
    UserType,
    get_environment,
)

from relevance_plan.integrations.up_engine import register_relevance_engine

DOCUMENT = REPO / "docs" / "unified-planning.md"


@pytest.fixture(scope="module", autouse=True)
def registered():
    register_relevance_engine()


@pytest.fixture(autouse=True)
def own_directory(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # Fast Downward writes output.sas in the working directory


def run_python(code: str, cwd) -> subprocess.CompletedProcess:
    """``code`` in a fresh interpreter (a fresh unified-planning environment, banners on by default)."""
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300, cwd=cwd)


@pytest.mark.planner
def test_the_documented_python_runs_as_written_and_prints_no_credits(tmp_path):
    blocks = re.findall(r"```python\n(.*?)```", DOCUMENT.read_text(), flags=re.DOTALL)
    assert len(blocks) >= 4 and "problem = Problem(" in blocks[0]  # the snippet builds the problem it uses
    done = run_python("\n".join(blocks), tmp_path)
    assert done.returncode == 0, done.stderr
    assert "SOLVED_SATISFICING 3 of 24" in done.stdout  # two rooms and the parcel that matter
    assert "objects removed; ValidationResultStatus.VALID" in done.stdout
    assert "Credits" not in done.stdout + done.stderr


@pytest.mark.planner
def test_no_banner_when_registered_through_the_factory_as_up_ini_does(tmp_path):
    code = textwrap.dedent(
        """
        from unified_planning.shortcuts import OneshotPlanner, get_environment
        get_environment().factory.add_meta_engine(
            "relevance", "relevance_plan.integrations.up_engine", "RelevanceMetaEngine"
        )
        with OneshotPlanner(name="relevance[fast-downward]") as planner:
            print("made", planner.name)
        """
    )
    done = run_python(code, tmp_path)
    assert done.returncode == 0, done.stderr
    assert "made relevance[" in done.stdout and "Credits" not in done.stdout


def test_registering_silences_the_environments_credits():
    assert get_environment().credits_stream is None


# --------------------------------------------------------------------------- anytime


def test_the_engine_is_anytime_exactly_when_its_inner_planner_is():
    factory = get_environment().factory
    assert factory.engine("relevance[fast-downward]").is_anytime_planner()
    assert not factory.engine("relevance[pyperplan]").is_anytime_planner()
    engine = factory.engine("relevance[fast-downward]")
    assert engine.ensures(AnytimeGuarantee.INCREASING_QUALITY)
    assert not engine.ensures(AnytimeGuarantee.OPTIMAL_PLANS)
    with AnytimePlanner(name="relevance[pyperplan]") as planner:  # by name, the factory does not ask
        with pytest.raises(UPUsageError, match="not an anytime planner"):
            next(iter(planner.get_solutions(roads())))


def roads(extra_places: int = 6) -> Problem:
    """One expensive flight or four cheap drives to the goal; places on a side road do not matter."""
    Place = UserType("Place")
    at = Fluent("at", BoolType(), p=Place)
    road = Fluent("road", BoolType(), a=Place, b=Place)
    highway = Fluent("highway", BoolType(), a=Place, b=Place)
    drive = InstantaneousAction("drive", a=Place, b=Place)
    fly = InstantaneousAction("fly", a=Place, b=Place)
    for action, link in ((drive, road), (fly, highway)):
        a, b = action.parameters
        action.add_precondition(at(a))
        action.add_precondition(link(a, b))
        action.add_effect(at(a), False)
        action.add_effect(at(b), True)
    problem = Problem("roads")
    for fluent in (at, road, highway):
        problem.add_fluent(fluent, default_initial_value=False)
    problem.add_actions([drive, fly])
    main = [Object(name, Place) for name in "abcde"]
    side = [Object(f"side{i}", Place) for i in range(extra_places)]
    problem.add_objects(main + side)
    problem.set_initial_value(at(main[0]), True)
    problem.set_initial_value(highway(main[0], main[4]), True)
    for here, there in zip(main + side, main[1:] + side[1:]):
        problem.set_initial_value(road(here, there), True)
    problem.add_goal(at(main[4]))
    problem.add_quality_metric(MinimizeActionCosts({drive: 1, fly: 20}))
    return problem


@pytest.mark.planner
def test_the_anytime_engine_yields_better_plans_each_valid_on_the_original():
    problem = roads()
    with AnytimePlanner(name="relevance[fast-downward]") as planner:
        results = list(planner.get_solutions(problem, timeout=30))
    *intermediate, final = results
    assert [result.status for result in intermediate] == [Status.INTERMEDIATE] * len(intermediate)
    costs = [sum(20 if step.action.name == "fly" else 1 for step in r.plan.actions) for r in intermediate]
    assert costs == sorted(costs, reverse=True) and len(set(costs)) == len(costs) and costs[-1] == 4
    assert final.status in (Status.SOLVED_SATISFICING, Status.SOLVED_OPTIMALLY)
    assert final.plan == intermediate[-1].plan
    assert int(final.metrics["objects_kept"]) < int(final.metrics["objects_total"])
    with PlanValidator(problem_kind=problem.kind) as validator:
        for result in results:
            assert validator.validate(problem, result.plan).status is ValidationResultStatus.VALID
            assert all(step.action is problem.action(step.action.name) for step in result.plan.actions)
