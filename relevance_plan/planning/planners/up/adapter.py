"""The ``up:NAME`` adapter: a one-shot planner installed for unified-planning, run in a child process.

The child (``up.child``) reads the PDDL files with unified-planning,
solves, and writes the plan and the engine's verdict (a
``PlanGenerationResultStatus`` name) into the run's directory; it runs under
``process.run_process_group`` so that its time limit holds and a hung
engine can be killed with whatever it started.

:data:`UP_STATUS` is the one table from unified-planning's statuses to ours,
keyed by name so that reading it does not import unified_planning; the
child's parent here and the ``relevance[...]`` meta-engine
(``integrations.up_engine``) both derive their mappings from it.
"""

from __future__ import annotations

import os
import shutil
import sys
from dataclasses import dataclass
from pathlib import Path

from relevance_plan import errors
from relevance_plan.pddl.model import Domain, Problem
from relevance_plan.pddl.plans import Plan
from relevance_plan.planning.planners import requirements as f
from relevance_plan.planning.planners.base import (
    READER_REFUSED,
    FinishedRun,
    PlannerStatus,
    RunOutcome,
    parse_ipc_plan,
    signal_reason,
)
from relevance_plan.planning.planners.requirements import refuse_unsupported
from relevance_plan.supervision.process import log_tail, read_log, run_process_group, watchdog_deadline, work_directory

KIND = "up"
PLANNERS_EXTRA_HINT = "pip install 'relevance-plan[planners]'"

# unified-planning's PlanGenerationResultStatus, by name -> our status.
UP_STATUS: dict[str, PlannerStatus] = {
    "SOLVED_SATISFICING": PlannerStatus.SOLVED,
    "SOLVED_OPTIMALLY": PlannerStatus.SOLVED,
    "UNSOLVABLE_PROVEN": PlannerStatus.UNSOLVABLE,
    "UNSOLVABLE_INCOMPLETELY": PlannerStatus.SEARCH_INCOMPLETE,
    "TIMEOUT": PlannerStatus.OUT_OF_TIME,
    "MEMOUT": PlannerStatus.OUT_OF_MEMORY,
    "INTERNAL_ERROR": PlannerStatus.PLANNER_CRASH,
    "UNSUPPORTED_PROBLEM": PlannerStatus.UNSUPPORTED,
}
SOLVED_OPTIMALLY = "SOLVED_OPTIMALLY"


def up_status_name(status: PlannerStatus) -> str:
    """The unified-planning status name for one of ours (the first in :data:`UP_STATUS`; else INTERNAL_ERROR)."""
    return next((name for name, ours in UP_STATUS.items() if ours is status), "INTERNAL_ERROR")


# What the child leaves in the run's directory, and its one exit code of its own.
PLAN_FILE = "plan.txt"
VERDICT_FILE = "verdict.txt"
CHILD_CANNOT_READ = 3  # unified-planning cannot read the PDDL files: an input error

# What an engine takes, for the engines whose limits are known.  The engines'
# declared ProblemKinds are advisory (up-lpg's lacks negative conditions, yet
# LPG plans with them), so refusing by them would refuse problems an engine
# solves; an engine not listed here decides for itself (the child reports
# UNSUPPORTED_PROBLEM).
# unified-planning's PDDL reader takes no derived predicates, either types,
# preferences or constraints, and turns every function into a real-valued
# fluent; the engines' limits below were found by trying (docs/planners.md).
# The child rewrites what an engine refuses when it can (``up.fitting``): real
# fluents with whole values as integers, the type hierarchy flat; whether it
# can depends on the values, so a feature admitted for that may still end in
# UNSUPPORTED_PROBLEM from the child.
_UP_READ = frozenset(
    {f.STRIPS, f.TYPING, f.HIERARCHICAL_TYPING, f.NEGATIVE_PRECONDITIONS, f.DISJUNCTIVE_PRECONDITIONS, f.EQUALITY}
)
_TEMPORAL = frozenset({f.DURATIVE_ACTIONS, f.DURATION_INEQUALITIES, f.TIMED_INITIAL_LITERALS})
_QUANTIFIED = frozenset({f.EXISTENTIAL_PRECONDITIONS, f.UNIVERSAL_PRECONDITIONS, f.CONDITIONAL_EFFECTS})
ENGINE_FEATURES: dict[str, frozenset[str]] = {
    # "Pyperplan supports the following PDDL fragment: STRIPS without action costs" (its credits).
    "pyperplan": frozenset({f.STRIPS, f.TYPING, f.HIERARCHICAL_TYPING}),
    # Aries: temporal and action costs; integer fluents but no real-valued ones, so PDDL's numbers only
    # when the child can read them as integers (whole values); no quantifiers.
    "aries": _UP_READ | _TEMPORAL | {f.NUMERIC_FLUENTS, f.ACTION_COSTS},
    # Tamer: temporal and numeric; its type checker rejects a type below another declared type, which the
    # child flattens.
    "tamer": _UP_READ | _TEMPORAL | {f.NUMERIC_FLUENTS, f.ACTION_COSTS},
    # Kairos (up-kairos, registered by the child and the worker): temporal and numeric, proves unsolvability.
    "kairos": _UP_READ | _TEMPORAL | {f.NUMERIC_FLUENTS, f.ACTION_COSTS},
    # ENHSP: numeric planning with ADL; no durative actions.
    "enhsp": _UP_READ | _QUANTIFIED | {f.NUMERIC_FLUENTS, f.ACTION_COSTS},
}

# Engines whose search ends on a problem without a plan: complete searches over a finite grounded
# space (Fast Downward's, SymK's, pyperplan's).  Aries and Tamer's satisficing searches and ENHSP's
# search a temporal or numeric space that may be infinite: on a problem without a plan they search
# until their time runs out.  Kairos ends quickly on small numeric spaces but, on temporal ones, often
# not in time; a budget changes nothing where it does end.  An engine not listed counts as one that cannot.
PROVING_ENGINES = frozenset({"fast-downward", "fast-downward-opt", "symk", "symk-opt", "pyperplan", "pyperplan-opt"})

# Features an engine takes only when the child can rewrite the problem for it, which depends on
# values that features do not show (Aries: PDDL's numbers only when they are whole); ``auto`` does
# not choose an engine for them.
FITTED_ONLY: dict[str, frozenset[str]] = {"aries": frozenset({f.NUMERIC_FLUENTS})}

# Engines that start a Java virtual machine (``java`` from PATH).
JAVA_ENGINES = frozenset({"enhsp", "enhsp-any", "enhsp-opt"})
JAVA_HINT = "install a Java runtime (Debian: apt-get install default-jre-headless)"


def java_runtime() -> Path | None:
    """The ``java`` executable: on PATH, else under JAVA_HOME."""
    found = shutil.which("java")
    if found is not None:
        return Path(found)
    home = os.environ.get("JAVA_HOME")
    candidate = Path(home) / "bin" / "java" if home else None
    if candidate is not None and candidate.is_file() and os.access(candidate, os.X_OK):
        return candidate
    return None


def java_environment(engine: str) -> dict[str, str] | None:
    """The child's environment: PATH reaching ``java`` when the engine needs it (None: inherit)."""
    if engine not in JAVA_ENGINES:
        return None
    java = java_runtime()
    if java is None:
        raise errors.PlannerError(f"up:{engine} needs a Java runtime, and none was found: {JAVA_HINT}")
    if shutil.which("java") is not None:
        return None
    return {**os.environ, "PATH": os.pathsep.join([str(java.parent), os.environ.get("PATH", "")])}


# The top-level module of each one-shot planner in unified-planning's own table of engines: finding it
# installed imports nothing (unified-planning and every engine's module take seconds to import).
ENGINE_MODULES = {
    "fast-downward": "up_fast_downward",
    "fast-downward-opt": "up_fast_downward",
    "symk": "up_symk",
    "symk-opt": "up_symk",
    "pyperplan": "up_pyperplan",
    "pyperplan-opt": "up_pyperplan",
    "enhsp": "up_enhsp",
    "enhsp-opt": "up_enhsp",
    "enhsp-any": "up_enhsp",
    "tamer": "up_tamer",
    "lpg": "up_lpg",
    "lpg-anytime": "up_lpg",
    "aries": "up_aries",
    "kairos": "up_kairos",  # not in unified-planning's table: registered by ``child.register_engine``
}


def engine_module_installed(engine: str) -> bool:
    """Whether ``engine`` is one of unified-planning's own one-shot planners with its package installed."""
    import importlib.util

    module = ENGINE_MODULES.get(engine)
    return module is not None and importlib.util.find_spec(module) is not None


def installed_up_engines() -> tuple[str, ...]:
    """One-shot planners the unified-planning factory knows (imports unified_planning: slow)."""
    import unified_planning.environment as environment

    factory = environment.get_environment().factory
    names = []
    for name in factory.engines:
        if "[" in name:
            continue  # a meta-engine (ours among them) is not a planner of its own
        try:
            if factory.engine(name).is_oneshot_planner():
                names.append(name)
        except Exception:  # an engine whose class cannot be loaded is not usable
            continue
    return tuple(sorted(names))


def classify(exit_code: int, verdict: str | None, has_plan: bool, watchdog_fired: bool, log: str) -> PlannerStatus:
    """The child's ending in our words."""
    if watchdog_fired and not has_plan:
        return PlannerStatus.OUT_OF_TIME
    if verdict is not None:
        status = UP_STATUS.get(verdict, PlannerStatus.PLANNER_CRASH)
    elif exit_code == CHILD_CANNOT_READ:
        status = PlannerStatus.INPUT_ERROR
    else:
        status = PlannerStatus.PLANNER_CRASH
    if status is PlannerStatus.SOLVED and not has_plan:
        return PlannerStatus.PLANNER_CRASH
    if status is PlannerStatus.PLANNER_CRASH and "MemoryError" in log:
        return PlannerStatus.OUT_OF_MEMORY
    return status


def exit_reason(name: str, exit_code: int, verdict: str | None, watchdog_fired: bool) -> str:
    """How the child ended, saying whose words they are."""
    if watchdog_fired:
        return f"{name} killed by the watchdog at its wall-clock limit"
    if verdict is not None:
        return f"{name}: unified-planning status {verdict}"
    if exit_code == CHILD_CANNOT_READ:
        return f"{name}: unified-planning cannot read the problem"
    if exit_code < 0:
        return f"{name} child process exit code {exit_code}: {signal_reason(exit_code)}"
    return f"{name} child process exit code {exit_code}: ended without a verdict"


def _read_verdict(workdir: Path) -> str | None:
    try:
        text = (workdir / VERDICT_FILE).read_text().strip()
    except OSError:
        return None
    return text or None


@dataclass(frozen=True)
class UnifiedPlanningPlanner:
    """An engine has no command line, so it takes no ``--planner-args``; ``--keep-work`` keeps
    the child's plan, verdict and log."""

    engine: str
    work_dir: str | None = None

    @property
    def name(self) -> str:
        return f"{KIND}:{self.engine}"

    @property
    def features(self) -> frozenset[str] | None:
        return ENGINE_FEATURES.get(self.engine)

    @property
    def proves_unsolvable(self) -> bool:
        return self.engine in PROVING_ENGINES

    def check_installed(self) -> None:
        if not engine_module_installed(self.engine) and self.engine not in installed_up_engines():
            raise errors.UsageError(
                f"unified-planning engine '{self.engine}' is not installed (installed: "
                f"{', '.join(installed_up_engines()) or 'none'}); {PLANNERS_EXTRA_HINT} adds"
                " pyperplan, symk, lpg, aries, tamer and enhsp"
            )
        java_environment(self.engine)

    def check(self, domain: Domain, problem: Problem) -> None:
        refuse_unsupported(self.name, self.features, domain, problem)

    def version(self) -> str:
        import importlib.metadata  # slow to import; only batch keys need it

        parts = [f"unified-planning {importlib.metadata.version('unified-planning')}"]
        try:
            parts.append(f"up-{self.engine} {importlib.metadata.version('up-' + self.engine)}")
        except importlib.metadata.PackageNotFoundError:
            pass
        return "; ".join(parts)

    def warm_up(self) -> None:
        """Start this engine's worker now, when the run has a pool (``up.pool``), so that it imports
        unified-planning and the engine while the tool reads and scores."""
        from relevance_plan.planning.planners.up.pool import current_pool

        pool = current_pool()
        if pool is not None and self.work_dir is None:
            pool.start(self.engine, java_environment(self.engine))

    def await_warm(self, until: float | None) -> bool:
        """Wait (until ``until``, monotonic) for the worker :meth:`warm_up` started; whether it is ready."""
        from relevance_plan.planning.planners.up.pool import current_pool

        pool = current_pool()
        return pool is not None and self.work_dir is None and pool.wait_ready(self.engine, until)

    def run(
        self, domain_path: str, problem_path: str, *, time_limit: float | None, memory_limit_mb: int | None
    ) -> RunOutcome:
        environment = java_environment(self.engine)
        if self.work_dir is None:
            outcome = self._run_in_worker(domain_path, problem_path, time_limit, memory_limit_mb, environment)
            if outcome is not None:
                return outcome
        with work_directory(self.work_dir, prefix="relevance-plan-up-") as workdir:
            plan_path = workdir / PLAN_FILE
            command = [
                sys.executable,
                "-m",
                "relevance_plan.planning.planners.up.child",
                self.engine,
                str(Path(domain_path).absolute()),
                str(Path(problem_path).absolute()),
                str(plan_path),
                str(workdir / VERDICT_FILE),
                "none" if time_limit is None else f"{time_limit:.3f}",
            ]
            run = run_process_group(
                command,
                workdir,
                watchdog_deadline(time_limit),
                what=self.name,
                program=sys.executable,
                env=environment,
                memory_limit_mb=memory_limit_mb,
            )
            return self._outcome(run, workdir, log_tail(read_log(workdir)))

    def _outcome(self, run: FinishedRun, workdir: Path, log: str) -> RunOutcome:
        """The child's (or the worker's) answer in our words, from the plan and verdict it left in ``workdir``."""
        plan_path = workdir / PLAN_FILE
        parsed = parse_ipc_plan(plan_path.read_text(errors="replace")) if plan_path.is_file() else None
        verdict = _read_verdict(workdir)
        status = classify(run.exit_code, verdict, parsed is not None, run.watchdog_fired, log)
        return RunOutcome.of_process(
            run,
            status,
            parsed,
            planner=self.name,
            config=self.engine,
            log_tail=log,
            raw_status=verdict or (READER_REFUSED if run.exit_code == CHILD_CANNOT_READ else ""),
            reason=exit_reason(self.name, run.exit_code, verdict, run.watchdog_fired),
            optimal=verdict == SOLVED_OPTIMALLY and status is PlannerStatus.SOLVED,
        )

    def _run_in_worker(
        self,
        domain_path: str,
        problem_path: str,
        time_limit: float | None,
        memory_limit_mb: int | None,
        environment: dict[str, str] | None,
    ) -> RunOutcome | None:
        """The attempt as a request to the run's warm worker; None when there is none (the child runs)."""
        from relevance_plan.planning.planners.up.pool import WORKER_GRACE, current_pool

        pool = current_pool()
        if pool is None or pool.memory_limit_mb != memory_limit_mb:
            return None
        worker = pool.start(self.engine, environment)
        if worker is None:
            return None
        with work_directory(None, prefix="relevance-plan-up-") as workdir:
            answer = worker.solve(
                str(Path(domain_path).absolute()),
                str(Path(problem_path).absolute()),
                str(workdir / PLAN_FILE),
                str(workdir / VERDICT_FILE),
                time_limit,
                watchdog_deadline(time_limit, WORKER_GRACE),
            )
            if answer is None:
                pool.retire(self.engine)
                return None
            if answer.starting:
                return RunOutcome(
                    status=PlannerStatus.OUT_OF_TIME,
                    exit_code=None,
                    plan=Plan(),
                    plan_cost=None,
                    wall_time=answer.wall_time,
                    planner=self.name,
                    process_group=answer.process_group,
                    reason=f"{self.name}: the engine was still starting at the attempt's time limit",
                )
            outcome = self._outcome(answer, workdir, answer.log)
        if answer.code is None:
            # killed at its limit, by the race, or died: a new one starts now, for the next attempt
            pool.retire(self.engine)
            pool.start(self.engine, environment)
        return outcome
