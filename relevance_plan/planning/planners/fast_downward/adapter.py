"""The Fast Downward adapter: the planner shipped inside ``up_fast_downward``.

What is Fast Downward's own lives here: where its driver is, the named
configurations and how they become driver arguments, its exit codes (the
driver's ``returncodes.py``) and what they mean for us, the plan files it
writes (``sas_plan``, or ``sas_plan.1``, ``sas_plan.2``, ... with falling
cost for anytime configurations such as ``lama``: the last complete one is
the best), the logs it prints, and the PDDL it takes.  Each run gets a fresh
temporary working directory (the driver writes ``output.sas`` and the plans
into its cwd) and is supervised by ``process.run_process_group``.  The
driver's own limits are CPU time and address space per component; the
watchdog backs them up with wall-clock time.
"""

from __future__ import annotations

import ast
import functools
import os
import re
import signal
import sys
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from relevance_plan import errors
from relevance_plan.errors import PlanFormatError
from relevance_plan.limits import DEFAULT_TIMEOUT
from relevance_plan.pddl.model import Domain, Problem
from relevance_plan.pddl.plans import Plan, read_plan
from relevance_plan.planning.planners.base import PlannerStatus, RunOutcome, signal_reason
from relevance_plan.planning.planners.fast_downward import head_start
from relevance_plan.planning.planners.fast_downward.command_line import (
    DEFAULT_CONFIG,
    FAST_DOWNWARD_ENV,
    PLAN_FILE,
    PLANNER_CONFIGS,
    build_command,
    find_fast_downward,
    planner_arguments,
    through_lean_driver,
)
from relevance_plan.planning.planners.requirements import (
    CLASSICAL,
    EITHER_OBJECT_TYPES,
    EITHER_TYPES,
    refuse_unsupported,
)
from relevance_plan.supervision.process import (
    ProcessRun,
    log_tail,
    read_log,
    run_process_group,
    watchdog_deadline,
    work_directory,
)

NAME = "fast-downward"
WHOSE = "Fast Downward"
# What its translator reads: classical planning with ADL, action costs and derived predicates, an
# ``(either ...)`` type only among a predicate's parameters ("Type value is expected to be a single
# word" anywhere else).
FEATURES = CLASSICAL - {EITHER_TYPES, EITHER_OBJECT_TYPES}

# Driver exit code -> (its name in the driver's ``returncodes.py``, our status).
# Checked against the copy in up-fast-downward by the tests.  A negative code
# -N means a process was killed by signal N: either the driver itself (seen
# by os.wait4) or a component whose signal the driver passed on via
# ``sys.exit(-N)``.  Codes not listed here, and codes 0-3 without a plan
# file, are PLANNER_CRASH.
EXIT_CODES: dict[int, tuple[str, PlannerStatus]] = {
    0: ("SUCCESS", PlannerStatus.SOLVED),
    1: ("SEARCH_PLAN_FOUND_AND_OUT_OF_MEMORY", PlannerStatus.SOLVED),
    # The driver's 2 is SEARCH_PLAN_FOUND_AND_OUT_OF_TIME, but a run with a
    # plan is SOLVED before this table is consulted; without one, 2 is
    # argparse's usage error (an unknown driver option in --planner-config).
    2: ("USAGE_ERROR", PlannerStatus.PLANNER_CONFIG_ERROR),
    3: ("SEARCH_PLAN_FOUND_AND_OUT_OF_MEMORY_AND_TIME", PlannerStatus.SOLVED),
    10: ("TRANSLATE_UNSOLVABLE", PlannerStatus.UNSOLVABLE),
    11: ("SEARCH_UNSOLVABLE", PlannerStatus.UNSOLVABLE),  # also a statically unreachable goal
    12: ("SEARCH_UNSOLVED_INCOMPLETE", PlannerStatus.SEARCH_INCOMPLETE),
    # No plan below a cost bound proves nothing about the task itself.
    13: ("SEARCH_UNSOLVABLE_WITHIN_BOUND", PlannerStatus.SEARCH_INCOMPLETE),
    20: ("TRANSLATE_OUT_OF_MEMORY", PlannerStatus.OUT_OF_MEMORY),
    21: ("TRANSLATE_OUT_OF_TIME", PlannerStatus.OUT_OF_TIME),
    22: ("SEARCH_OUT_OF_MEMORY", PlannerStatus.OUT_OF_MEMORY),
    23: ("SEARCH_OUT_OF_TIME", PlannerStatus.OUT_OF_TIME),
    24: ("SEARCH_OUT_OF_MEMORY_AND_TIME", PlannerStatus.OUT_OF_TIME),
    # Translator exit 1 (any uncaught exception, incl. "Could not read file")
    # becomes 30; see _refine_status for the log-based split.
    30: ("TRANSLATE_CRITICAL_ERROR", PlannerStatus.PLANNER_CRASH),
    31: ("TRANSLATE_INPUT_ERROR", PlannerStatus.INPUT_ERROR),  # PDDL syntax, undefined names
    32: ("SEARCH_CRITICAL_ERROR", PlannerStatus.PLANNER_CRASH),
    33: ("SEARCH_INPUT_ERROR", PlannerStatus.PLANNER_CONFIG_ERROR),
    34: ("SEARCH_UNSUPPORTED", PlannerStatus.UNSUPPORTED),
    35: ("DRIVER_CRITICAL_ERROR", PlannerStatus.PLANNER_CRASH),
    36: ("DRIVER_INPUT_ERROR", PlannerStatus.PLANNER_CONFIG_ERROR),
    37: ("DRIVER_UNSUPPORTED", PlannerStatus.UNSUPPORTED),
    # The translator's CPU limit can be 0 s after the driver's own start-up
    # (it rounds the remainder down), so SIGXCPU arrives before the
    # translator installs its handler.
    -signal.SIGXCPU: ("SIGXCPU", PlannerStatus.OUT_OF_TIME),
}

_TRANSLATE_CRITICAL_ERROR = 30
_TRANSLATE_INPUT_ERROR = 31
# The translator's complaints about PDDL it does not take (legal PDDL, which the tool's reader took):
# its input error then means unsupported, not malformed.
_TRANSLATOR_REFUSES = re.compile(
    r"Type value is expected to be a single word|Fractional numbers are not supported|Unsupported assignment operator"
)

# What the user got wrong when the driver rejects --planner-config.
_CONFIG_ERRORS = {
    2: "an unknown driver option",
    33: "a bad search string",
    36: "an unknown alias or a bad option value",
}

# "Done! [0.390s CPU, 0.384s wall-clock]" ends a successful translator run.
_TRANSLATE_DONE_RE = re.compile(r"^Done! \[[\d.]+s CPU, ([\d.]+)s wall-clock\]", re.MULTILINE)
# "[t=0.0027s, 10544 KB] Total time: 0.0027s" ends the search component's log;
# "Search time:" (search proper, without input reading) is the fallback.
_SEARCH_TOTAL_RE = re.compile(r"\] Total time: ([\d.]+)s$", re.MULTILINE)
_SEARCH_ONLY_RE = re.compile(r"\] Search time: ([\d.]+)s$", re.MULTILINE)
_PLAN_COST_RE = re.compile(r"^;\s*cost\s*=\s*(\d+)", re.MULTILINE)
_ANYTIME_PLAN_RE = re.compile(re.escape(PLAN_FILE) + r"\.(\d+)")

# How a component dies when its address-space limit is too small for it to
# even start: the loader cannot map libc (exit 127), Python raises MemoryError
# during start-up, or fails to flush at exit (exit 120).
# "lost sys.stderr": Python had no memory left to print its error (the translator under a tight limit)
_OUT_OF_MEMORY_MARKERS = (
    "MemoryError",
    "failed to map segment",
    "Cannot allocate memory",
    "std::bad_alloc",
    "lost sys.stderr",
)
_PYTHON_FINALIZE_FAILED = 120


# --------------------------------------------------------------------------- the driver


@functools.lru_cache(maxsize=1)
def fast_downward_version() -> str:
    """Version of the installed up-fast-downward package (for result keys)."""
    import importlib.metadata  # slow to import; only batch keys need it

    try:
        return importlib.metadata.version("up-fast-downward")
    except importlib.metadata.PackageNotFoundError as error:
        raise errors.PlannerError("up-fast-downward is not installed") from error


@functools.cache
def _driver_aliases(driver: Path) -> frozenset[str] | None:
    """The aliases and portfolios the driver knows, read from its ``driver/aliases.py`` and
    ``driver/portfolios/`` without running it (None: not there, or not in the usual shape)."""
    package = driver.parent / "driver"
    try:
        tree = ast.parse((package / "aliases.py").read_text(encoding="utf-8"))
    except (OSError, SyntaxError, ValueError):
        return None
    names = set()
    for node in ast.walk(tree):
        for target in node.targets if isinstance(node, ast.Assign) else ():
            # ALIASES["name"] = [...]
            if (
                isinstance(target, ast.Subscript)
                and isinstance(target.value, ast.Name)
                and target.value.id == "ALIASES"
                and isinstance(target.slice, ast.Constant)
                and isinstance(target.slice.value, str)
            ):
                names.add(target.slice.value)
    portfolios = package / "portfolios"
    if portfolios.is_dir():
        # the driver names a portfolio after its file, underscores as hyphens
        names.update(path.stem.replace("_", "-") for path in portfolios.glob("*.py"))
    return frozenset(names) or None


def driver_aliases() -> frozenset[str] | None:
    """The aliases the installed driver accepts; None when they cannot be read (the driver decides)."""
    try:
        driver = find_fast_downward()
    except errors.PlannerError:
        return None
    return _driver_aliases(driver)


def check_config(config: str) -> None:
    """Refuse, before any planning, an alias the driver does not know (a search string is the driver's)."""
    arguments = planner_arguments(config)
    if config in PLANNER_CONFIGS or arguments[0] != "--alias":
        return
    known = driver_aliases()
    if known is None or config in known:
        return
    import difflib  # only for this message

    close = difflib.get_close_matches(config, [*PLANNER_CONFIGS, *sorted(known)], n=1)
    hint = f" (did you mean '{close[0]}'?)" if close else ""
    raise errors.UsageError(
        f"unknown --planner-config '{config}'{hint}: not one of {', '.join(PLANNER_CONFIGS)}, nor an alias of"
        f" the {WHOSE} driver (see its --show-aliases); a search string has parentheses"
    )


# --------------------------------------------------------------------------- what it leaves behind


def _plan_paths(workdir: Path) -> list[Path]:
    """Plan files, best last: sas_plan, or sas_plan.1, .2, ... for anytime configs."""
    numbered: list[tuple[int, Path]] = []
    for path in workdir.iterdir():
        match = _ANYTIME_PLAN_RE.fullmatch(path.name)
        if match:
            numbered.append((int(match.group(1)), path))
    if numbered:
        return [path for _, path in sorted(numbered)]
    single = workdir / PLAN_FILE
    return [single] if single.is_file() else []


def read_plans(workdir: Path) -> tuple[tuple[Plan, ...], bool]:
    """Every complete plan file (a cost line ends it) in the order written, best last, and whether
    they were numbered (an anytime configuration's ``sas_plan.N``)."""
    paths = _plan_paths(workdir)
    plans = []
    for path in paths:
        text = path.read_text(errors="replace")
        if _PLAN_COST_RE.search(text) is None:
            continue  # cut off mid-write by a kill; an earlier plan may be whole
        try:
            plans.append(read_plan(text))
        except PlanFormatError:
            continue
    return tuple(plans), any(path.name != PLAN_FILE for path in paths)


def _last_float(pattern: re.Pattern[str], text: str) -> float | None:
    matches = pattern.findall(text)
    return float(matches[-1]) if matches else None


def _search_time(log: str) -> float | None:
    total = _last_float(_SEARCH_TOTAL_RE, log)
    return total if total is not None else _last_float(_SEARCH_ONLY_RE, log)


# "translate exit code: 31": the driver's line after a component failed; the component's complaint precedes it.
_COMPONENT_FAILED_RE = re.compile(r"^(?:translate|search) exit code: [1-9]\d*$", re.MULTILINE)
_CONTEXT_PREFIXES = ("Got:", "Syntax:", "\t->", "INFO", "Parsing")


def _up_to_complaint(log: str) -> str:
    """The log up to the failed component's own complaint (the translator's "Expected ..."), so its
    last line says what went wrong rather than the driver's closing lines."""
    failed = _COMPONENT_FAILED_RE.search(log)
    if failed is None:
        return log
    lines = log[: failed.start()].rstrip("\n").split("\n")
    for index in range(len(lines) - 1, max(len(lines) - 12, -1), -1):
        if lines[index].strip() and not lines[index].startswith(_CONTEXT_PREFIXES):
            return "\n".join(lines[: index + 1])
    return log


# --------------------------------------------------------------------------- exit codes -> status


def exit_reason(exit_code: int, killed_by_watchdog: bool = False) -> str:
    """What the driver's exit code means, saying that it is Fast Downward's."""
    if killed_by_watchdog:
        return f"{WHOSE} killed by the watchdog at its wall-clock limit"
    if exit_code in EXIT_CODES and exit_code >= 0:
        meaning = EXIT_CODES[exit_code][0].lower().replace("_", " ")
        if exit_code in _CONFIG_ERRORS:
            meaning += f", {_CONFIG_ERRORS[exit_code]}"
        return f"{WHOSE} exit code {exit_code}: {meaning}"
    if exit_code < 0:
        return f"{WHOSE} exit code {exit_code}: {signal_reason(exit_code)}"
    return f"{WHOSE} exit code {exit_code}: not one of the driver's codes"


def _refine_status(
    status: PlannerStatus,
    exit_code: int,
    log: str,
    cpu_time: float,
    driver_time_limit: float | None,
    memory_limited: bool = False,
) -> PlannerStatus:
    """Split exit codes the driver uses for several causes, by the log."""
    if exit_code == _TRANSLATE_INPUT_ERROR and _TRANSLATOR_REFUSES.search(log):
        return PlannerStatus.UNSUPPORTED
    if exit_code == _TRANSLATE_CRITICAL_ERROR:
        if "Could not read file" in log:
            return PlannerStatus.INPUT_ERROR
        if "MemoryError" in log:  # limit so low that Python could not start
            return PlannerStatus.OUT_OF_MEMORY
    if (
        memory_limited
        and status is PlannerStatus.PLANNER_CRASH
        and (exit_code == _PYTHON_FINALIZE_FAILED or any(marker in log for marker in _OUT_OF_MEMORY_MARKERS))
    ):
        return PlannerStatus.OUT_OF_MEMORY
    # A component that ignores SIGXCPU gets SIGKILL at the hard CPU limit.
    if exit_code == -signal.SIGKILL and driver_time_limit is not None and cpu_time >= driver_time_limit - 1.0:
        return PlannerStatus.OUT_OF_TIME
    return status


def classify(
    exit_code: int,
    has_plan: bool,
    killed_by_watchdog: bool,
    log: str,
    cpu_time: float,
    driver_time_limit: float | None,
    memory_limited: bool = False,
) -> PlannerStatus:
    """Fast Downward's ending in our words."""
    if has_plan:
        # A plan file with its cost line is complete, even if the run was then
        # stopped (anytime configs end by hitting a limit).
        return PlannerStatus.SOLVED
    if killed_by_watchdog:
        return PlannerStatus.OUT_OF_TIME
    _, status = EXIT_CODES.get(exit_code, ("", PlannerStatus.PLANNER_CRASH))
    if status is PlannerStatus.SOLVED:
        return PlannerStatus.PLANNER_CRASH  # "success" but no plan file
    return _refine_status(status, exit_code, log, cpu_time, driver_time_limit, memory_limited)


# --------------------------------------------------------------------------- one run


DRIVER_CPU_SLACK = 2.0  # seconds of CPU the driver may use beyond the attempt's wall-clock limit


@dataclass(frozen=True)
class DriverProcess:
    """How the driver's process is started and watched: the tool's defaults; tests change them."""

    python: str = sys.executable  # the interpreter the driver runs under
    driver_limits: bool = True  # False: the limits are the watchdog's alone, none goes to the driver
    watchdog_grace: float | None = None  # beyond the time limit before the group is killed (None: the default)


def run_fast_downward(
    domain_path: str | os.PathLike[str],
    problem_path: str | os.PathLike[str],
    *,
    config: str = DEFAULT_CONFIG,
    time_limit: float | None = DEFAULT_TIMEOUT,
    memory_limit_mb: int | None = None,
    extra_arguments: Sequence[str] = (),
    work_dir: str | None = None,
    process: DriverProcess = DriverProcess(),
) -> RunOutcome:
    """Run Fast Downward on one task and classify the result.

    ``time_limit`` (seconds), plus a grace period (``process.watchdog_deadline``),
    goes to a wall-clock watchdog that kills the whole process group, and plus
    ``DRIVER_CPU_SLACK`` to the driver as a CPU limit; ``process`` changes how the driver is run and
    watched (its interpreter, the limits left to the watchdog alone: for tests).
    ``extra_arguments`` end the command line; ``work_dir`` is the directory
    the driver works in and leaves its files in (default: a temporary one).
    An anytime configuration's plans are all in the outcome's ``plans``.
    """
    domain, problem = _check_run(domain_path, problem_path, time_limit, memory_limit_mb)
    python, driver_limits, watchdog_grace = process.python, process.driver_limits, process.watchdog_grace
    driver = find_fast_downward()
    # The driver counts its own start and the translator against its limit, and gives the search only
    # what is left: held to a short limit exactly, it stops a search that has barely begun.  The wall
    # clock is the watchdog's (at ``time_limit``); the driver's CPU limit sits above it, a backstop.
    driver_time_limit = time_limit + DRIVER_CPU_SLACK if driver_limits and time_limit is not None else None
    command = build_command(
        (python, str(driver)),
        domain,
        problem,
        config,
        driver_time_limit,
        memory_limit_mb if driver_limits else None,
        extra_arguments,
        keep_sas_file=work_dir is not None,
    )
    early = None
    if work_dir is None and python == sys.executable and driver_limits:
        early = head_start.claim(head_start.run_key(domain, problem, config, memory_limit_mb, extra_arguments))
    with early.folder() if early is not None else work_directory(work_dir, prefix="relevance-plan-fd-") as workdir:
        if early is not None:
            # started by the launcher with the whole --timeout, before the tool was imported
            driver_time_limit = early.time_limit
            run = early.group.finish(watchdog_deadline(early.time_limit, watchdog_grace))
        else:
            deadline = watchdog_deadline(time_limit, watchdog_grace)
            run = run_process_group(through_lean_driver(command), workdir, deadline, what=WHOSE, program=driver)
        plans, numbered = read_plans(workdir)
        ended = _Ended(run, read_log(workdir), plans, numbered, driver_time_limit)
    return ended.outcome(config, memory_limited=driver_limits and memory_limit_mb is not None)


def _check_run(
    domain_path: str | os.PathLike[str],
    problem_path: str | os.PathLike[str],
    time_limit: float | None,
    memory_limit_mb: int | None,
) -> tuple[Path, Path]:
    """The domain and problem as absolute paths; ``InputFileError`` or ``UsageError`` before any run."""
    domain = Path(domain_path).absolute()
    problem = Path(problem_path).absolute()
    for path in (domain, problem):
        if not path.is_file():
            raise errors.InputFileError("no such file", path=str(path))
    if time_limit is not None and time_limit <= 0:
        raise errors.UsageError(f"time limit must be positive, got {time_limit}")
    if memory_limit_mb is not None and memory_limit_mb <= 0:
        raise errors.UsageError(f"memory limit must be positive, got {memory_limit_mb}")
    return domain, problem


@dataclass(frozen=True)
class _Ended:
    """What a driver run left: how its process ended, its log, its complete plans (best last) and
    whether they were numbered (anytime), and the CPU limit the driver had (None: none)."""

    run: ProcessRun
    log: str
    plans: tuple[Plan, ...]
    numbered: bool
    driver_time_limit: float | None

    def outcome(self, config: str, memory_limited: bool) -> RunOutcome:
        """The run in our words: status, plan, times and Fast Downward's own reason."""
        run, log = self.run, self.log
        plan = self.plans[-1] if self.plans else None
        killed = run.killed_by_watchdog
        status = classify(
            run.exit_code, plan is not None, killed, log, run.cpu_time, self.driver_time_limit, memory_limited
        )
        return RunOutcome(
            status=status,
            exit_code=run.exit_code,
            plan=plan if plan is not None else Plan(),
            plan_cost=plan.cost if plan is not None else None,
            wall_time=run.wall_time,
            planner=NAME,
            cpu_time=run.cpu_time,
            peak_memory_mb=run.peak_memory_mb,
            translate_time=_last_float(_TRANSLATE_DONE_RE, log),
            search_time=_search_time(log),
            config=config,
            log_tail=log_tail(_up_to_complaint(log)),
            killed_by_watchdog=killed,
            process_group=run.process_group,
            raw_status=EXIT_CODES.get(run.exit_code, ("", status))[0],
            reason=exit_reason(run.exit_code, killed),
            plans=self.plans if self.numbered else (),
        )


# --------------------------------------------------------------------------- the adapter


def check_names(domain: Domain, problem: Problem) -> None:
    """Refuse, before any planning, a name Fast Downward cannot read.

    Its translator accepts only ASCII outside comments; our reader, like
    PDDL tools that read Unicode, accepts more, so ``score`` and ``prune``
    work while ``plan`` would fail deep inside the planner.
    """
    names = [("domain", domain.name), ("problem", problem.name)]
    names += [("type", name) for name in domain.types]
    names += [("constant", name) for name in domain.constants]
    names += [("predicate", name) for name in domain.predicates]
    names += [("action", action.name) for action in domain.actions]
    for kind, name in names:
        if not name.isascii():
            raise errors.UnsupportedFeatureError(
                f"{kind} '{name}' has a non-ASCII name, which {WHOSE} does not accept", path=domain.path
            )
    for name in problem.objects:
        if not name.isascii():
            raise errors.UnsupportedFeatureError(
                f"object '{problem.display(name)}' has a non-ASCII name, which {WHOSE} does not accept",
                path=problem.path,
                line=problem.object_line(name),
            )


@dataclass(frozen=True)
class FastDownwardPlanner:
    config: str = DEFAULT_CONFIG
    name: str = NAME
    extra_arguments: tuple[str, ...] = ()  # --planner-args, after the inputs
    work_dir: str | None = None  # --keep-work: run here and leave the files

    @property
    def features(self) -> frozenset[str]:
        """Classical planning with ADL, action costs and derived predicates; no numbers, time or
        preferences, no ``(either ...)`` type outside a predicate's parameters (``FEATURES``)."""
        return FEATURES

    @property
    def proves_unsolvable(self) -> bool:
        """Its translator and a complete search end on a problem without a plan (exit code 11 or 12)."""
        return True

    def check_installed(self) -> None:
        """The configuration: an alias must be one the driver knows.  up-fast-downward is a dependency
        of the tool, and a missing or overridden driver is reported when the first run looks for it."""
        check_config(self.config)

    def check(self, domain: Domain, problem: Problem) -> None:
        check_config(self.config)
        check_names(domain, problem)
        refuse_unsupported(WHOSE, self.features, domain, problem)

    def version(self) -> str:
        """The up-fast-downward version; a driver override adds a digest of its file."""
        version = fast_downward_version()
        override = os.environ.get(FAST_DOWNWARD_ENV)
        if override:
            import hashlib  # only batch keys need it

            try:
                digest = hashlib.sha256(Path(override).expanduser().read_bytes()).hexdigest()
            except OSError:
                digest = "missing"
            version += f"+custom-{digest[:12]}"
        return version

    def run(
        self, domain_path: str, problem_path: str, *, time_limit: float | None, memory_limit_mb: int | None
    ) -> RunOutcome:
        return run_fast_downward(
            domain_path,
            problem_path,
            config=self.config,
            time_limit=time_limit,
            memory_limit_mb=memory_limit_mb,
            extra_arguments=self.extra_arguments,
            work_dir=self.work_dir,
        )
