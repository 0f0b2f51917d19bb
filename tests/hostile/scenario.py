"""What a hostile scenario is, what its run gives back, and how a test module turns scenarios into tests."""

from __future__ import annotations

import re
import subprocess
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path

import pytest

from relevance_plan.exitcodes import ExitCode

OK, TIME, INPUT, USAGE = 0, int(ExitCode.OUT_OF_TIME), int(ExitCode.INPUT_FILE), int(ExitCode.USAGE)
PDDL, UNSUPPORTED, MISMATCH = int(ExitCode.PDDL_SYNTAX), int(ExitCode.UNSUPPORTED_PDDL), int(ExitCode.DOMAIN_MISMATCH)
MODEL, STORE, PLANNER = int(ExitCode.MODEL), int(ExitCode.STORE), int(ExitCode.PLANNER)
INTERRUPTED, PIPE = int(ExitCode.INTERRUPTED), 141
NO_VALID, INSUFFICIENT = int(ExitCode.NO_VALID_PLAN), int(ExitCode.INSUFFICIENT_CUES)
SCHEDULER = int(ExitCode.SCHEDULER)


@dataclass(frozen=True)
class Result:
    code: int
    stdout: str
    stderr: str
    elapsed: float
    peak_mb: float
    work: Path


Check = Callable[[Result], str | None]  # what is wrong with a run, or None


@dataclass(frozen=True)
class Scenario:
    """One hostile run.  ``args``: the tool's arguments; or ``shell``: a bash line using ``$TOOL``.

    Paths are relative to the workspace (the tool's cwd), which ``setup``
    fills after the common files (D.pddl, P.pddl, the planners/ folder).
    """

    name: str
    args: tuple = ()
    shell: str | None = None
    setup: Callable[[Path], None] | None = None
    codes: tuple = (OK,)
    stdin: bytes | None = None
    timeout: float | None = None  # the --timeout whose deadline must hold (within 1 s)
    budget: float | None = None  # or: seconds the run may take at most (beyond start-up)
    writes: tuple = ()  # glob patterns of workspace files the run may create or change
    check: Check | None = None
    during: Callable[[subprocess.Popen, Path], None] | None = None
    env: tuple = ()  # (name, value) pairs added to the environment
    max_rss_mb: int = 900
    quick: bool = False  # in the default test run; the others are marked slow
    needs: Callable[[], str | None] | None = None  # a reason to skip, or None


# The commands that start a planner (or may: watch plans on a "plan" event).
_PLANNING = re.compile(r"(^|\$TOOL )(plan|compare|demo|watch)\b")


def starts_a_planner(scenario: Scenario) -> bool:
    command = scenario.shell or " ".join(str(arg) for arg in scenario.args[:1])
    return bool(_PLANNING.search(command))


def params(scenarios: Sequence[Scenario]) -> list:
    """The scenarios as pytest parameters named after them: the quick ones run by default, the others
    are marked ``slow``; those whose command starts a planner are marked ``planner``."""
    names = [scenario.name for scenario in scenarios]
    assert len(names) == len(set(names)), "scenario names must be unique"
    found = []
    for scenario in scenarios:
        marks = [] if scenario.quick else [pytest.mark.slow]
        if starts_a_planner(scenario):
            marks.append(pytest.mark.planner)
        found.append(pytest.param(scenario, id=scenario.name.split("/", 1)[1], marks=marks))
    return found


def scenario_test(scenarios: Sequence[Scenario]):
    """A module's test of its scenarios, one case each (``test_outputs = scenario_test(SCENARIOS)``): the
    ``hostile`` fixture runs and judges each."""

    @pytest.mark.parametrize("scenario", params(scenarios))
    def test(scenario: Scenario, hostile) -> None:
        hostile(scenario)

    return test
