"""The ``lpg`` adapter: the LPG-td 1.4 binary that the ``up-lpg`` wheel ships, run directly.

LPG-td reads temporal and numeric PDDL 2.1 itself (unified-planning's
``lpg`` engine declares no temporal problem kind, so it is not asked).
What is LPG's own lives here:

- the PDDL it takes, found by trying: ADL conditions, universal
  quantifiers, derived predicates, action costs, numeric fluents, durative
  actions and timed initial literals; not conditional or universal effects
  (it exits 1 after parsing), not duration inequalities nor ``scale-up``
  and ``scale-down`` (it says "not supported");
- its command line: ``-o DOMAIN -f PROBLEM -n 1 -out plan`` writes
  ``plan_1.SOL``; a fixed ``-seed`` makes runs repeatable (its default seed
  is random);
- its plan file: IPC timed lines in upper case, a stray ``)`` after the
  duration (``0.0003: (LOAD P T D) [2.0000])``), ``;`` comments; for a
  domain without durative actions (the comment "Actions having STRIPS
  duration") the time stamps are levels of a parallel plan, read here as
  the sequence they list, unless timed initial literals make time matter;
- its endings: exit 0 with a plan file: solved; exit 0 without one: its
  local search gave up (or it named a construct it does not support); exit 1
  with "can not be reached": the goal is unreachable from the initial state;
  exit 1 with "too many ... increase MAX_...": the problem outgrew one of its
  fixed-size tables (a few hundred objects do it), which we count as out of
  memory.

The domain and problem are linked into the run's directory under short
names, so its fixed-size path buffers never see a long path.
"""

from __future__ import annotations

import importlib.util
import math
import os
import re
import tempfile
from dataclasses import dataclass, replace
from pathlib import Path

from relevance_plan import errors
from relevance_plan.pddl.model import Domain, Problem
from relevance_plan.pddl.plans import Plan
from relevance_plan.planning.planners import requirements as f
from relevance_plan.planning.planners.base import PlannerStatus, RunOutcome, parse_ipc_plan, signal_reason
from relevance_plan.supervision.process import ProcessRun, log_tail, read_log, run_process_group, watchdog_deadline

NAME = "lpg"
WHOSE = "LPG-td"
PACKAGE = "up-lpg"
INSTALL_HINT = "pip install 'relevance-plan[planners]' (or pip install up-lpg)"
SEED = "1"
PLAN_STEM = "plan"
PLAN_FILE = PLAN_STEM + "_1.SOL"

FEATURES = frozenset(
    {
        f.STRIPS,
        f.TYPING,
        f.HIERARCHICAL_TYPING,
        f.EITHER_TYPES,
        f.EITHER_PREDICATE_TYPES,
        f.NEGATIVE_PRECONDITIONS,
        f.DISJUNCTIVE_PRECONDITIONS,
        f.EQUALITY,
        f.EXISTENTIAL_PRECONDITIONS,
        f.UNIVERSAL_PRECONDITIONS,
        f.ACTION_COSTS,
        f.NUMERIC_FLUENTS,
        f.DURATIVE_ACTIONS,
        f.DERIVED_PREDICATES,
        f.TIMED_INITIAL_LITERALS,
    }
)

_STRAY_PAREN_RE = re.compile(r"\]\s*\)\s*$")
_SEQUENTIAL_MARK = "Actions having STRIPS duration"
_TIMED_LITERALS_MARK = re.compile(r"Timed Initial Literals:\s*YES", re.IGNORECASE)
_UNREACHABLE_MARK = "can not be reached"
_UNSUPPORTED_RE = re.compile(r"(not supported|doesn't support)[^\n]*", re.IGNORECASE)
_TABLE_FULL_RE = re.compile(r"too many [^\n]*increase MAX_\w+[^\n]*", re.IGNORECASE)


def lpg_binary() -> Path | None:
    """The LPG-td executable inside the installed ``up_lpg`` package (found without importing it)."""
    spec = importlib.util.find_spec("up_lpg")
    if spec is None or not spec.submodule_search_locations:
        return None
    for folder in spec.submodule_search_locations:
        candidate = Path(folder) / "lpg"
        if candidate.is_file() and os.access(candidate, os.X_OK):
            return candidate
    return None


def read_lpg_plan(text: str, log: str) -> Plan | None:
    """LPG's plan file as a plan (None when a line is neither a step nor a comment)."""
    lines = [_STRAY_PAREN_RE.sub("]", line) for line in text.splitlines()]
    plan = parse_ipc_plan("\n".join(lines))
    if plan is None or _SEQUENTIAL_MARK not in text or _TIMED_LITERALS_MARK.search(log):
        return plan
    ordered = sorted(plan.steps, key=lambda step: step.time or 0.0)  # stable: the file's order within a level
    return Plan(tuple(replace(step, time=None, duration=None) for step in ordered), plan.cost)


def classify(run: ProcessRun, plan: Plan | None, log: str) -> PlannerStatus:
    """LPG's ending in our words."""
    if run.watchdog_fired and plan is None:
        return PlannerStatus.OUT_OF_TIME
    if run.exit_code == 0 and plan is not None:
        return PlannerStatus.SOLVED
    if _UNSUPPORTED_RE.search(log):
        return PlannerStatus.UNSUPPORTED
    if run.exit_code == 0:
        return PlannerStatus.SEARCH_INCOMPLETE  # its local search gave up
    if run.exit_code == 1 and _UNREACHABLE_MARK in log:
        return PlannerStatus.UNSOLVABLE
    if _TABLE_FULL_RE.search(log) or "memory" in log.lower():
        return PlannerStatus.OUT_OF_MEMORY
    return PlannerStatus.PLANNER_CRASH


def exit_reason(run: ProcessRun, status: PlannerStatus, log: str) -> str:
    """How LPG ended, saying that the exit code is its own."""
    if run.watchdog_fired:
        return f"{WHOSE} killed by the watchdog at its wall-clock limit"
    if run.exit_code < 0:
        return f"{WHOSE} exit code {run.exit_code}: {signal_reason(run.exit_code)}"
    unsupported = _UNSUPPORTED_RE.search(log)
    if status is PlannerStatus.UNSUPPORTED and unsupported:
        return f"{WHOSE} exit code {run.exit_code}: {unsupported.group(0).strip()}"
    if status is PlannerStatus.UNSOLVABLE:
        return f"{WHOSE} exit code 1: the goal can not be reached"
    table_full = _TABLE_FULL_RE.search(log)
    if table_full:
        return f"{WHOSE} exit code {run.exit_code}: {table_full.group(0).strip()}"
    if status is PlannerStatus.SEARCH_INCOMPLETE:
        return f"{WHOSE} exit code 0 without a plan: its search gave up"
    return f"{WHOSE} exit code {run.exit_code}"


@dataclass(frozen=True)
class LpgPlanner:
    name: str = NAME

    @property
    def features(self) -> frozenset[str]:
        return FEATURES

    @property
    def proves_unsolvable(self) -> bool:
        """A local search: on a problem without a plan it restarts until its time runs out."""
        return False

    def executable(self) -> Path:
        found = lpg_binary()
        if found is None:
            raise errors.UsageError(f"the LPG-td planner is not installed: {INSTALL_HINT}")
        return found

    def check_installed(self) -> None:
        self.executable()

    def check(self, domain: Domain, problem: Problem) -> None:
        f.refuse_unsupported(self.name, self.features, domain, problem)

    def version(self) -> str:
        import importlib.metadata  # slow to import; only batch keys need it

        try:
            return f"LPG-td 1.4 ({PACKAGE} {importlib.metadata.version(PACKAGE)})"
        except importlib.metadata.PackageNotFoundError:
            return "LPG-td 1.4"

    def run(
        self, domain_path: str, problem_path: str, *, time_limit: float | None, memory_limit_mb: int | None
    ) -> RunOutcome:
        binary = self.executable()
        with tempfile.TemporaryDirectory(prefix="relevance-plan-lpg-") as tmp:
            workdir = Path(tmp)
            (workdir / "domain.pddl").symlink_to(Path(domain_path).absolute())
            (workdir / "problem.pddl").symlink_to(Path(problem_path).absolute())
            command = [str(binary), "-o", "domain.pddl", "-f", "problem.pddl", "-n", "1", "-out", PLAN_STEM]
            command += ["-seed", SEED]
            if time_limit is not None:
                command += ["-cputime", str(max(1, math.ceil(time_limit)))]
            run = run_process_group(
                command,
                workdir,
                watchdog_deadline(time_limit),
                what=WHOSE,
                program=binary,
                memory_limit_mb=memory_limit_mb,
            )
            log = read_log(workdir)
            plan_path = workdir / PLAN_FILE
            text = plan_path.read_text(errors="replace") if plan_path.is_file() else None
        plan = None if text is None or run.exit_code != 0 else read_lpg_plan(text, log)
        tail = log_tail(log)
        status = classify(run, plan, log)
        return RunOutcome.of_process(
            run,
            status,
            plan,
            plan_cost=None,
            planner=self.name,
            log_tail=tail,
            reason=exit_reason(run, status, log),
        )
