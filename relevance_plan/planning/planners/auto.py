"""The ``auto`` planner: the installed planner that takes what the problem uses.

The problem's features (``requirements.py``) name a family, and the family an
order of planners; the first one installed that takes every feature runs:

- classical (ADL, action costs, derived predicates): Fast Downward;
- temporal (durative actions, timed initial literals): ``lpg``, then
  ``up:aries``, then ``up:tamer``;
- numeric without time: ``up:enhsp`` (with a Java runtime), then ``lpg``,
  then ``up:tamer``;
- PDDL+ (processes, events: our reader refuses them, so they are planned
  unpruned): ``up:enhsp``.

When none installed takes the problem, the refusal is one line naming what
to install.  Whether a planner is installed is decided without importing
it (unified-planning takes seconds to import).  When the first gives up
without an answer (it crashed, its search ended incomplete, it could not
read the problem), the next installed one that takes the problem runs in
the time left (``FallbackPlanner``): LPG crashes on some IPC temporal
domains that Aries and Tamer solve.
"""

from __future__ import annotations

import dataclasses
import importlib.util
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass

from relevance_plan.errors import UnsupportedFeatureError
from relevance_plan.io import load_domain, load_problem
from relevance_plan.pddl.model import Domain, Problem
from relevance_plan.planning.planners import requirements as f
from relevance_plan.planning.planners.base import Planner, PlannerStatus, RunOutcome
from relevance_plan.planning.planners.fast_downward.adapter import FEATURES as FAST_DOWNWARD_FEATURES
from relevance_plan.planning.planners.fast_downward.adapter import FastDownwardPlanner, check_config
from relevance_plan.planning.planners.fast_downward.command_line import DEFAULT_CONFIG
from relevance_plan.planning.planners.lpg import FEATURES as LPG_FEATURES
from relevance_plan.planning.planners.lpg import INSTALL_HINT as LPG_HINT
from relevance_plan.planning.planners.lpg import LpgPlanner, lpg_binary
from relevance_plan.planning.planners.up.adapter import (
    ENGINE_FEATURES,
    FITTED_ONLY,
    JAVA_ENGINES,
    JAVA_HINT,
    UnifiedPlanningPlanner,
)
from relevance_plan.planning.planners.up.adapter import java_runtime as find_java

NAME = "auto"
PDDL_PLUS = "PDDL+"  # how the reader's refusals of processes, events and continuous effects name them


@dataclass(frozen=True)
class PlannerCandidate:
    name: str  # as --planner takes it
    takes: frozenset[str]
    installed: Callable[[], bool]
    install: Callable[[], str]  # what to install, when it is not installed
    make: Callable[[str], Planner]  # Fast Downward's configuration -> the planner


def has_module(name: str) -> bool:
    return importlib.util.find_spec(name) is not None


def _engine(engine: str, package: str) -> PlannerCandidate:
    needs_java = engine in JAVA_ENGINES

    def installed() -> bool:
        return has_module(package.replace("-", "_")) and (not needs_java or find_java() is not None)

    def install() -> str:
        missing = [] if has_module(package.replace("-", "_")) else [f"pip install {package}"]
        if needs_java and find_java() is None:
            missing.append(JAVA_HINT)
        return ", and ".join(missing)

    takes = ENGINE_FEATURES[engine] - FITTED_ONLY.get(engine, frozenset())  # only what it surely takes
    return PlannerCandidate(f"up:{engine}", takes, installed, install, lambda _: UnifiedPlanningPlanner(engine))


FAST_DOWNWARD = PlannerCandidate(
    "fast-downward", FAST_DOWNWARD_FEATURES, lambda: True, str, lambda config: FastDownwardPlanner(config)
)
LPG = PlannerCandidate("lpg", LPG_FEATURES, lambda: lpg_binary() is not None, lambda: LPG_HINT, lambda _: LpgPlanner())
ARIES = _engine("aries", "up-aries")
TAMER = _engine("tamer", "up-tamer")
ENHSP = _engine("enhsp", "up-enhsp")

# Each family's planners, in order of preference.
CLASSICAL_ORDER = (FAST_DOWNWARD,)
TEMPORAL_ORDER = (LPG, ARIES, TAMER)
NUMERIC_ORDER = (ENHSP, LPG, TAMER)
PDDL_PLUS_ORDER = (ENHSP,)
EVERY = (FAST_DOWNWARD, LPG, ENHSP, ARIES, TAMER)


@dataclass(frozen=True)
class Choice:
    planner: Planner
    reason: str  # why it was chosen, for the progress line and the JSON


def family(uses: frozenset[str]) -> tuple[str, Sequence[PlannerCandidate]]:
    """The problem's family, and its planners in order of preference."""
    if uses <= f.CLASSICAL:
        return "classical", CLASSICAL_ORDER
    if uses & f.TEMPORAL:
        return "temporal", TEMPORAL_ORDER
    if f.NUMERIC_FLUENTS in uses:
        return "numeric", NUMERIC_ORDER
    return "other", EVERY


def choose(uses: frozenset[str], config: str, where: str | None = None) -> Choice:
    """The first installed planner of the family that takes ``uses``; else the refusal naming what to install."""
    kind, order = family(uses)
    fitting = list(dict.fromkeys(c for c in (*order, *EVERY) if uses <= c.takes))
    shown = ", ".join(sorted(uses - {f.STRIPS, f.TYPING})) or "strips"
    beyond = ", ".join(sorted(uses - f.CLASSICAL))
    installed = [candidate for candidate in fitting if candidate.installed()]
    if installed:
        reason = f"a {kind} problem" + (f" ({beyond})" if beyond else "")
        lacking = sorted(uses - order[0].takes)
        if installed[0] is not order[0] and lacking:  # the family's own planner cannot: say why not
            reason += f"; {order[0].name} does not take {', '.join(lacking)}"
        # the family's other planners stand by (Fast Downward alone is the classical family's)
        first = installed[0].make(config)
        then = tuple(c.make(config) for c in installed[1:] if c in order) if kind in FALLBACK_FAMILIES else ()
        if not then:
            return Choice(first, reason)
        return Choice(FallbackPlanner(first, then), f"{reason}; then {', '.join(p.name for p in then)}")
    if fitting:
        raise UnsupportedFeatureError(
            f"no installed planner takes what this problem uses ({shown}): {fitting[0].install()}", path=where
        )
    raise UnsupportedFeatureError(
        f"no planner this tool knows takes what this problem uses ({shown});"
        " give your own with --planner cmd:'PLANNER {domain} {problem}'",
        path=where,
    )


def choose_unread(refused: UnsupportedFeatureError, config: str) -> Choice:
    """For input our reader refuses: ENHSP for PDDL+; anything else only a planner the user names can take."""
    if PDDL_PLUS in refused.message:
        for candidate in PDDL_PLUS_ORDER:
            if candidate.installed():
                return Choice(candidate.make(config), "a PDDL+ problem")
        raise UnsupportedFeatureError(
            f"{refused.message}, and no installed planner takes it: {PDDL_PLUS_ORDER[0].install()}",
            path=refused.path,
            line=refused.line,
        )
    raise UnsupportedFeatureError(
        f"{refused.message}; no planner this tool knows takes it: give your own with"
        " --planner cmd:'PLANNER {domain} {problem}'",
        path=refused.path,
        line=refused.line,
    )


# A run that ended without an answer another planner might give (not a proof, not the time running out).
GAVE_UP = frozenset({PlannerStatus.PLANNER_CRASH, PlannerStatus.SEARCH_INCOMPLETE, PlannerStatus.INPUT_ERROR})
FALLBACK_FROM = 1.0  # seconds left below which the next planner is not started
FALLBACK_FAMILIES = ("temporal", "numeric")


@dataclass(frozen=True)
class FallbackPlanner:
    """``first``; when it gives up without an answer, each of ``then`` in turn, in the time left.
    It is ``first`` to the user (name, features, check): the others take what it takes."""

    first: Planner
    then: tuple[Planner, ...]

    @property
    def name(self) -> str:
        return self.first.name

    @property
    def features(self) -> frozenset[str] | None:
        return self.first.features

    @property
    def proves_unsolvable(self) -> bool:
        return self.first.proves_unsolvable

    def check_installed(self) -> None:
        self.first.check_installed()

    def check(self, domain: Domain, problem: Problem) -> None:
        self.first.check(domain, problem)

    def version(self) -> str:
        return self.first.version()

    def run(
        self, domain_path: str, problem_path: str, *, time_limit: float | None, memory_limit_mb: int | None
    ) -> RunOutcome:
        started = time.monotonic()
        outcome = self.first.run(domain_path, problem_path, time_limit=time_limit, memory_limit_mb=memory_limit_mb)
        for planner in self.then:
            left = None if time_limit is None else time_limit - (time.monotonic() - started)
            if outcome.status not in GAVE_UP or (left is not None and left < FALLBACK_FROM):
                break
            earlier = outcome
            outcome = planner.run(domain_path, problem_path, time_limit=left, memory_limit_mb=memory_limit_mb)
            outcome = dataclasses.replace(
                outcome,
                wall_time=earlier.wall_time + outcome.wall_time,
                reason=f"{earlier.planner} gave up ({earlier.reason}); {outcome.planner}: {outcome.reason}",
            )
        return outcome


@dataclass(frozen=True)
class AutoPlanner:
    config: str = DEFAULT_CONFIG  # Fast Downward's, when it is the one chosen
    name: str = NAME

    @property
    def features(self) -> frozenset[str]:
        """What the installed planners take between them."""
        return frozenset().union(*(c.takes for c in EVERY if c.installed()))

    @property
    def proves_unsolvable(self) -> bool:
        """The chosen planner's (``supply.planner_for`` chooses before any attempt); unknown before: no."""
        return False

    def check_installed(self) -> None:
        """Fast Downward is always there and its configuration is checked now (a typo is found before
        any work); what else is needed depends on the problem (see ``check``)."""
        check_config(self.config)

    def check(self, domain: Domain, problem: Problem) -> None:
        self.choose(domain, problem).planner.check(domain, problem)

    def choose(self, domain: Domain, problem: Problem) -> Choice:
        uses = f.problem_features(domain, problem)
        path = domain.path if f.domain_features(domain) == uses else problem.path
        return choose(uses, self.config, path)

    def choose_unread(self, refused: UnsupportedFeatureError) -> Choice:
        return choose_unread(refused, self.config)

    def version(self) -> str:
        installed = [c.make(self.config) for c in EVERY if c.installed()]
        return "auto: " + "; ".join(planner.version() for planner in installed)

    def run(
        self, domain_path: str, problem_path: str, *, time_limit: float | None, memory_limit_mb: int | None
    ) -> RunOutcome:
        """Choose from the files, then run the chosen planner (front ends that read the problem choose first)."""
        try:
            domain = load_domain(domain_path)
            problem = load_problem(problem_path, domain)
        except UnsupportedFeatureError as refused:
            choice = self.choose_unread(refused)
        else:
            choice = self.choose(domain, problem)
        return choice.planner.run(domain_path, problem_path, time_limit=time_limit, memory_limit_mb=memory_limit_mb)
