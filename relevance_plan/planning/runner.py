"""Run the Fast Downward planner shipped inside ``up_fast_downward``.

Each run gets a fresh temporary working directory (Fast Downward writes
``output.sas`` and ``sas_plan`` into its cwd) and its own session, so the
whole process tree (driver, translator, search) can be killed at once.
The session is led by a small guard (``guard.py``) that kills it if this
process dies.  The driver's own limits are CPU time and address space per
component; a wall-clock watchdog backs them up.  The module is thread-safe:
many runs may go at once from a thread pool.
"""

from __future__ import annotations

import enum
import functools
import importlib.util
import math
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time
from dataclasses import dataclass
from pathlib import Path

from relevance_plan import errors
from relevance_plan.errors import PlanFormatError
from relevance_plan.pddl.plans import Plan, read_plan

FAST_DOWNWARD_ENV = "RELEVANCE_PLAN_FAST_DOWNWARD"
DEFAULT_CONFIG = "lama-first"

# Named configurations -> driver arguments.  Options the driver itself parses
# (``--alias``) must precede the input files, while component options
# (``--evaluator``, ``--search``) must follow them: ``--search`` before the
# files would be read as the driver's "run search component" flag.
# ``_split_driver_options`` puts each part in its place.
PLANNER_CONFIGS: dict[str, tuple[str, ...]] = {
    "lama-first": ("--alias", "lama-first"),
    # Anytime: writes sas_plan.1, sas_plan.2, ... with decreasing cost.
    "lama": ("--alias", "seq-sat-lama-2011"),
    "ff-gbfs": ("--evaluator", "h=ff()", "--search", "lazy_greedy([h],preferred=[h])"),
    "astar-lmcut": ("--search", "astar(lmcut())"),
    "astar-blind": ("--search", "astar(blind())"),
}

# Driver options that take one value and belong before the input files.
_DRIVER_OPTIONS = frozenset({"--alias", "--portfolio"})

PLAN_FILE = "sas_plan"
LOG_FILE = "planner.log"
LOG_TAIL_LINES = 40
DEFAULT_WATCHDOG_GRACE = 5.0
_GUARD = Path(__file__).with_name("guard.py")


class PlannerStatus(enum.Enum):
    SOLVED = "solved"
    UNSOLVABLE = "unsolvable"
    SEARCH_INCOMPLETE = "search_incomplete"
    OUT_OF_TIME = "out_of_time"
    OUT_OF_MEMORY = "out_of_memory"
    INPUT_ERROR = "input_error"
    UNSUPPORTED = "unsupported"
    PLANNER_CRASH = "planner_crash"


# Driver exit code -> status.  Codes follow Fast Downward's
# ``driver/returncodes.py`` (checked against the copy in up-fast-downward
# 1.0.0).  A negative code -N means a process was killed by signal N: either
# the driver itself (seen by os.wait4) or a component whose signal the driver
# passed on via ``sys.exit(-N)`` (exit status 256-N, normalised back to -N).
# Codes not listed here, and codes 0-3 without a plan file, are PLANNER_CRASH.
EXIT_CODE_STATUS: dict[int, PlannerStatus] = {
    0: PlannerStatus.SOLVED,  # SUCCESS
    1: PlannerStatus.SOLVED,  # SEARCH_PLAN_FOUND_AND_OUT_OF_MEMORY
    # FD's 2 is SEARCH_PLAN_FOUND_AND_OUT_OF_TIME, but a run with a plan is
    # SOLVED before this table is consulted; without one, 2 is argparse's
    # usage error (unknown driver flag).
    2: PlannerStatus.INPUT_ERROR,
    3: PlannerStatus.SOLVED,  # SEARCH_PLAN_FOUND_AND_OUT_OF_MEMORY_AND_TIME
    10: PlannerStatus.UNSOLVABLE,  # TRANSLATE_UNSOLVABLE
    11: PlannerStatus.UNSOLVABLE,  # SEARCH_UNSOLVABLE (also a statically unreachable goal)
    12: PlannerStatus.SEARCH_INCOMPLETE,  # SEARCH_UNSOLVED_INCOMPLETE
    # No plan below a cost bound proves nothing about the task itself.
    13: PlannerStatus.SEARCH_INCOMPLETE,  # SEARCH_UNSOLVABLE_WITHIN_BOUND
    20: PlannerStatus.OUT_OF_MEMORY,  # TRANSLATE_OUT_OF_MEMORY
    21: PlannerStatus.OUT_OF_TIME,  # TRANSLATE_OUT_OF_TIME
    22: PlannerStatus.OUT_OF_MEMORY,  # SEARCH_OUT_OF_MEMORY
    23: PlannerStatus.OUT_OF_TIME,  # SEARCH_OUT_OF_TIME
    24: PlannerStatus.OUT_OF_TIME,  # SEARCH_OUT_OF_MEMORY_AND_TIME
    # Translator exit 1 (any uncaught exception, incl. "Could not read file")
    # becomes 30; see _refine_status for the log-based split.
    30: PlannerStatus.PLANNER_CRASH,  # TRANSLATE_CRITICAL_ERROR
    31: PlannerStatus.INPUT_ERROR,  # TRANSLATE_INPUT_ERROR (PDDL syntax / undefined names)
    32: PlannerStatus.PLANNER_CRASH,  # SEARCH_CRITICAL_ERROR
    33: PlannerStatus.INPUT_ERROR,  # SEARCH_INPUT_ERROR (bad search string)
    34: PlannerStatus.UNSUPPORTED,  # SEARCH_UNSUPPORTED
    35: PlannerStatus.PLANNER_CRASH,  # DRIVER_CRITICAL_ERROR
    36: PlannerStatus.INPUT_ERROR,  # DRIVER_INPUT_ERROR (unknown alias, bad option value)
    37: PlannerStatus.UNSUPPORTED,  # DRIVER_UNSUPPORTED
    # The translator's CPU limit can be 0 s after the driver's own start-up
    # (it rounds the remainder down), so SIGXCPU arrives before the
    # translator installs its handler.
    -signal.SIGXCPU: PlannerStatus.OUT_OF_TIME,
}

_TRANSLATE_CRITICAL_ERROR = 30

# "Done! [0.390s CPU, 0.384s wall-clock]" ends a successful translator run.
_TRANSLATE_DONE_RE = re.compile(r"^Done! \[[\d.]+s CPU, ([\d.]+)s wall-clock\]", re.MULTILINE)
# "[t=0.0027s, 10544 KB] Total time: 0.0027s" ends the search component's log;
# "Search time:" (search proper, without input reading) is the fallback.
_SEARCH_TOTAL_RE = re.compile(r"\] Total time: ([\d.]+)s$", re.MULTILINE)
_SEARCH_ONLY_RE = re.compile(r"\] Search time: ([\d.]+)s$", re.MULTILINE)
_PLAN_COST_RE = re.compile(r"^;\s*cost\s*=\s*(\d+)", re.MULTILINE)
_ANYTIME_PLAN_RE = re.compile(re.escape(PLAN_FILE) + r"\.(\d+)")


@dataclass(frozen=True)
class RunOutcome:
    """One planner run.

    ``plan`` holds the steps as Fast Downward writes them, lowercase and
    without parentheses ("pick cup1 counter").  ``exit_code`` is the driver's,
    with -N for death by signal N.  ``cpu_time`` and ``peak_memory_mb`` come
    from os.wait4 and so cover the guard, the driver and the components they reaped; a
    component killed by the watchdog is not counted.  ``translate_time`` and
    ``search_time`` are the components' own reports, None if they did not
    finish.  ``process_group`` is the run's (now dead) process group id.
    """

    status: PlannerStatus
    exit_code: int | None
    plan: Plan
    plan_cost: float | None
    wall_time: float
    cpu_time: float = 0.0
    peak_memory_mb: float = 0.0
    translate_time: float | None = None
    search_time: float | None = None
    config: str = ""
    log_tail: str = ""
    killed_by_watchdog: bool = False
    process_group: int | None = None
    planner: str = "fast-downward"
    raw_status: str = ""  # the planner's own word for the outcome (an engine's status name), for logs
    optimal: bool = False  # the planner proved the plan optimal

    @property
    def solved(self) -> bool:
        return self.status is PlannerStatus.SOLVED


@functools.cache
def _locate_driver(override: str | None) -> Path:
    if override:
        path = Path(override).expanduser()
        if not path.is_file():
            raise errors.PlannerError(f"Fast Downward driver not found at {path} (from ${FAST_DOWNWARD_ENV})")
        return path.resolve()
    # find_spec locates the package without importing it (its __init__
    # pulls in unified_planning, which is slow).
    spec = importlib.util.find_spec("up_fast_downward")
    if spec is None or not spec.submodule_search_locations:
        raise errors.PlannerError(f"up-fast-downward is not installed; install it or set ${FAST_DOWNWARD_ENV}")
    for location in spec.submodule_search_locations:
        path = Path(location) / "downward" / "fast-downward.py"
        if path.is_file():
            return path.resolve()
    raise errors.PlannerError(
        f"up-fast-downward has no downward/fast-downward.py; reinstall it or set ${FAST_DOWNWARD_ENV}"
    )


def find_fast_downward() -> Path:
    """Path of ``fast-downward.py``; ``$RELEVANCE_PLAN_FAST_DOWNWARD`` overrides it."""
    # Cached per override value, so changing the variable takes effect.
    return _locate_driver(os.environ.get(FAST_DOWNWARD_ENV) or None)


@functools.lru_cache(maxsize=1)
def fast_downward_version() -> str:
    """Version of the installed up-fast-downward package (for result keys)."""
    import importlib.metadata  # slow to import; only batch keys need it

    try:
        return importlib.metadata.version("up-fast-downward")
    except importlib.metadata.PackageNotFoundError as error:
        raise errors.PlannerError("up-fast-downward is not installed") from error


def check_planner_names(domain, problem) -> None:
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
                f"{kind} '{name}' has a non-ASCII name, which Fast Downward does not accept", path=domain.path
            )
    for name in problem.objects:
        if not name.isascii():
            raise errors.UnsupportedFeatureError(
                f"object '{problem.display(name)}' has a non-ASCII name, which Fast Downward does not accept",
                path=problem.path,
                line=_object_line(problem, name),
            )


def _object_line(problem, name: str) -> int | None:
    for symbols, _ in problem.object_groups:
        for symbol in symbols:
            if symbol.text.lower() == name:
                return symbol.line
    return None


def planner_arguments(config: str) -> tuple[str, ...]:
    """Driver arguments for a named config, a raw search string or an alias.

    Unknown aliases are left to the driver, which rejects them (exit 36).
    """
    if config in PLANNER_CONFIGS:
        return PLANNER_CONFIGS[config]
    if not config.strip():
        raise errors.UsageError("empty planner configuration")
    if "(" in config:
        return ("--search", config)
    return ("--alias", config)


def _split_driver_options(arguments: tuple[str, ...]) -> tuple[list[str], list[str]]:
    """(options before the input files, component options after them)."""
    before: list[str] = []
    index = 0
    while index + 1 < len(arguments) and arguments[index] in _DRIVER_OPTIONS:
        before.extend(arguments[index : index + 2])
        index += 2
    return before, list(arguments[index:])


def _build_command(
    python: str,
    driver: Path,
    domain: Path,
    problem: Path,
    config: str,
    time_limit: float | None,
    memory_limit_mb: int | None,
) -> list[str]:
    limits: list[str] = []
    if time_limit is not None:
        limits += ["--overall-time-limit", f"{math.ceil(time_limit)}s"]
    if memory_limit_mb is not None:
        limits += ["--overall-memory-limit", f"{memory_limit_mb}M"]
    before, after = _split_driver_options(planner_arguments(config))
    return [python, str(driver), "--plan-file", PLAN_FILE, *limits, *before, str(domain), str(problem), *after]


# Process groups of the planners running now, so a batch's Ctrl-C can stop them all.
_ACTIVE_GROUPS: set[int] = set()
_ACTIVE_LOCK = threading.Lock()


def terminate_all_runs() -> int:
    """Kill every planner process group this process started and still waits for.

    Each group's driver stays unreaped until its waiting thread returns, so
    a group id here cannot belong to an unrelated process.  Returns how many.
    """
    with _ACTIVE_LOCK:
        groups = list(_ACTIVE_GROUPS)
    for pgid in groups:
        _kill_group(pgid)
    return len(groups)


def _kill_group(pgid: int) -> None:
    try:
        os.killpg(pgid, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        # Group already gone (PermissionError: macOS reports a group of zombies so).
        pass


def _exit_code(wait_status: int) -> int:
    if os.WIFSIGNALED(wait_status):
        return -os.WTERMSIG(wait_status)
    code = os.WEXITSTATUS(wait_status)
    # The driver passes a component's death by signal N on as sys.exit(-N).
    return code - 256 if code > 128 else code


def _wait_for_group(pgid: int, deadline: float | None) -> tuple[int, float, float, bool]:
    """Wait for the driver; kill its whole group; reap it.

    Returns (wait status, cpu seconds, peak memory MB, watchdog fired).  The
    driver stays an unreaped zombie until the group is killed, so its pid
    (= the group id) cannot be reused by an unrelated process meanwhile.
    """
    fired = threading.Event()

    def watchdog() -> None:
        fired.set()
        _kill_group(pgid)

    timer: threading.Timer | None = None
    if deadline is not None:
        timer = threading.Timer(deadline, watchdog)
        timer.daemon = True
        timer.start()
    try:
        if hasattr(os, "waitid"):
            os.waitid(os.P_PID, pgid, os.WEXITED | os.WNOWAIT)
        else:  # macOS: no waitid; reap first and accept a tiny pid-reuse window
            _, status, usage = os.wait4(pgid, 0)
    finally:
        # Runs on KeyboardInterrupt too: the planner lives in its own session,
        # so the terminal's Ctrl-C never reached it.
        if timer is not None:
            timer.cancel()
            timer.join()  # a kill in flight must land before the pid is freed
        # Killing only the driver would leave a running translator orphaned.
        _kill_group(pgid)
        if hasattr(os, "waitid"):
            _await_group_death(pgid)
            _, status, usage = os.wait4(pgid, 0)
    cpu = usage.ru_utime + usage.ru_stime
    return status, cpu, usage.ru_maxrss / 1024.0, fired.is_set()


def _await_group_death(pgid: int, timeout: float = 2.0) -> None:
    """Wait until no member of the killed group still runs (Linux, via /proc).

    SIGKILL lands at once, but a process takes a moment to exit; the unreaped
    leader keeps the group id reserved meanwhile.  Without this, a caller
    could see the planner's children still running after the run returned.
    """
    if not os.path.isdir("/proc"):
        return
    deadline = time.monotonic() + timeout
    while _group_runs(pgid) and time.monotonic() < deadline:
        time.sleep(0.01)


def _group_runs(pgid: int) -> bool:
    for entry in os.scandir("/proc"):
        if not entry.name.isdigit():
            continue
        try:
            with open(f"/proc/{entry.name}/stat", "rb") as stream:
                fields = stream.read().rsplit(b")", 1)[1].split()
        except (OSError, IndexError):
            continue
        # fields: state, ppid, pgrp, ...; a zombie has exited already.
        if int(fields[2]) == pgid and fields[0] != b"Z":
            return True
    return False


def _plan_paths(workdir: Path) -> list[Path]:
    """Plan files, best last: sas_plan, or sas_plan.1, .2, ... for anytime configs."""
    numbered = []
    for path in workdir.iterdir():
        match = _ANYTIME_PLAN_RE.fullmatch(path.name)
        if match:
            numbered.append((int(match.group(1)), path))
    if numbered:
        return [path for _, path in sorted(numbered)]
    single = workdir / PLAN_FILE
    return [single] if single.is_file() else []


def _read_plan(workdir: Path) -> Plan | None:
    """The last complete plan file (a cost line ends it), or None if there is none."""
    for path in reversed(_plan_paths(workdir)):
        text = path.read_text(errors="replace")
        if _PLAN_COST_RE.search(text) is None:
            continue  # cut off mid-write by a kill; an earlier plan may be whole
        try:
            return read_plan(text)
        except PlanFormatError:
            continue
    return None


def _last_float(pattern: re.Pattern[str], text: str) -> float | None:
    matches = pattern.findall(text)
    return float(matches[-1]) if matches else None


def _search_time(log: str) -> float | None:
    total = _last_float(_SEARCH_TOTAL_RE, log)
    return total if total is not None else _last_float(_SEARCH_ONLY_RE, log)


# How a component dies when its address-space limit is too small for it to
# even start: the loader cannot map libc (exit 127), Python raises MemoryError
# during start-up, or fails to flush at exit (exit 120).
_OUT_OF_MEMORY_MARKERS = ("MemoryError", "failed to map segment", "Cannot allocate memory", "std::bad_alloc")
_PYTHON_FINALIZE_FAILED = 120


def _refine_status(
    status: PlannerStatus,
    exit_code: int,
    log: str,
    cpu_time: float,
    driver_time_limit: float | None,
    memory_limited: bool = False,
) -> PlannerStatus:
    """Split exit codes the driver uses for several causes, by the log."""
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


def _classify(
    exit_code: int,
    has_plan: bool,
    killed_by_watchdog: bool,
    log: str,
    cpu_time: float,
    driver_time_limit: float | None,
    memory_limited: bool = False,
) -> PlannerStatus:
    if has_plan:
        # A plan file with its cost line is complete, even if the run was then
        # stopped (anytime configs end by hitting a limit).
        return PlannerStatus.SOLVED
    if killed_by_watchdog:
        return PlannerStatus.OUT_OF_TIME
    status = EXIT_CODE_STATUS.get(exit_code, PlannerStatus.PLANNER_CRASH)
    if status is PlannerStatus.SOLVED:
        return PlannerStatus.PLANNER_CRASH  # "success" but no plan file
    return _refine_status(status, exit_code, log, cpu_time, driver_time_limit, memory_limited)


@dataclass(frozen=True)
class ProcessRun:
    wait_status: int
    exit_code: int
    cpu_time: float
    peak_memory_mb: float
    watchdog_fired: bool
    wall_time: float
    process_group: int


def _limit_memory(megabytes: int) -> None:
    import resource

    limit = megabytes * 1024 * 1024
    resource.setrlimit(resource.RLIMIT_AS, (limit, limit))


def run_process_group(
    command: list[str],
    workdir: Path,
    deadline: float | None,
    *,
    what: str,
    program: Path | str,
    env: dict | None = None,
    memory_limit_mb: int | None = None,
) -> ProcessRun:
    """Run ``command`` in ``workdir`` as the leader of its own session, output to ``workdir/planner.log``.

    A watchdog kills the whole group ``deadline`` seconds after the start;
    the group is killed and reaped in every case (Ctrl-C included).  Every
    planner adapter runs its processes through here.
    """
    # The guard starts the command, so a missing program must be caught here.
    executable = command[0] if os.sep in command[0] else shutil.which(command[0])
    if executable is None or not os.access(executable, os.X_OK) or os.path.isdir(executable):
        raise errors.PlannerError(f"cannot start {what}: {command[0]} is not an executable program", path=str(program))
    started = time.monotonic()
    # The guard kills the group when this process dies (its pipe's write end
    # closes, even on kill -9); os.pipe() fds are close-on-exec, so no other
    # child holds the write end.
    guard_read, guard_write = os.pipe()
    try:
        # A file, not a pipe: nobody has to drain it while we wait.
        with open(workdir / LOG_FILE, "wb") as log_file:
            try:
                process = subprocess.Popen(
                    # -I -S: the guard needs the standard library only; skipping site saves start-up
                    [sys.executable, "-I", "-S", str(_GUARD), str(guard_read), *command],
                    cwd=workdir,
                    stdin=subprocess.DEVNULL,
                    stdout=log_file,
                    stderr=subprocess.STDOUT,
                    start_new_session=True,
                    close_fds=True,
                    pass_fds=(guard_read,),
                    env=env,
                    preexec_fn=None if memory_limit_mb is None else functools.partial(_limit_memory, memory_limit_mb),
                )
            except OSError as error:
                raise errors.PlannerError(
                    f"cannot start {what}: {error.strerror or error}", path=str(program)
                ) from None
            finally:
                os.close(guard_read)
        # start_new_session: the guard leads its own group, pgid == pid.
        pgid = process.pid
        with _ACTIVE_LOCK:
            _ACTIVE_GROUPS.add(pgid)
        try:
            wait_status, cpu_time, peak_mb, fired = _wait_for_group(pgid, deadline)
        finally:
            with _ACTIVE_LOCK:
                _ACTIVE_GROUPS.discard(pgid)
    finally:
        os.close(guard_write)
    exit_code = _exit_code(wait_status)
    # We reaped it ourselves (for the rusage); tell Popen so it never waits.
    process.returncode = exit_code
    return ProcessRun(wait_status, exit_code, cpu_time, peak_mb, fired, time.monotonic() - started, pgid)


def run_fast_downward(
    domain_path: str | os.PathLike[str],
    problem_path: str | os.PathLike[str],
    *,
    config: str = DEFAULT_CONFIG,
    time_limit: float | None = 120.0,
    memory_limit_mb: int | None = None,
    python: str = sys.executable,
    driver_limits: bool = True,
    watchdog_grace: float | None = None,
) -> RunOutcome:
    """Run Fast Downward on one task and classify the result.

    ``time_limit`` (seconds) goes to the driver as a CPU limit and, plus a
    grace period (default max(5 s, 10 %)), to a wall-clock watchdog that
    kills the whole process group.  ``driver_limits=False`` withholds the
    limits from the driver so that only the watchdog applies (for tests).
    """
    domain = Path(domain_path).absolute()
    problem = Path(problem_path).absolute()
    for path in (domain, problem):
        if not path.is_file():
            raise errors.InputFileError("no such file", path=str(path))
    if time_limit is not None and time_limit <= 0:
        raise errors.UsageError(f"time limit must be positive, got {time_limit}")
    if memory_limit_mb is not None and memory_limit_mb <= 0:
        raise errors.UsageError(f"memory limit must be positive, got {memory_limit_mb}")
    driver = find_fast_downward()
    command = _build_command(
        python,
        driver,
        domain,
        problem,
        config,
        time_limit if driver_limits else None,
        memory_limit_mb if driver_limits else None,
    )
    deadline = None
    if time_limit is not None:
        grace = watchdog_grace if watchdog_grace is not None else max(DEFAULT_WATCHDOG_GRACE, 0.1 * time_limit)
        deadline = time_limit + grace

    with tempfile.TemporaryDirectory(prefix="relevance-plan-fd-") as tmp:
        workdir = Path(tmp)
        run = run_process_group(command, workdir, deadline, what="Fast Downward", program=driver)
        log = (workdir / LOG_FILE).read_text(errors="replace")
        plan = _read_plan(workdir)
    killed_by_watchdog = run.watchdog_fired and os.WIFSIGNALED(run.wait_status)
    status = _classify(
        run.exit_code,
        plan is not None,
        killed_by_watchdog,
        log,
        run.cpu_time,
        time_limit if driver_limits else None,
        memory_limited=driver_limits and memory_limit_mb is not None,
    )
    return RunOutcome(
        status=status,
        exit_code=run.exit_code,
        plan=plan if plan is not None else Plan(),
        plan_cost=plan.cost if plan is not None else None,
        wall_time=run.wall_time,
        cpu_time=run.cpu_time,
        peak_memory_mb=run.peak_memory_mb,
        translate_time=_last_float(_TRANSLATE_DONE_RE, log),
        search_time=_search_time(log),
        config=config,
        log_tail="\n".join(log.splitlines()[-LOG_TAIL_LINES:]),
        killed_by_watchdog=killed_by_watchdog,
        process_group=run.process_group,
        raw_status=status.name,
    )


def run_val(domain_path: str, problem_path: str, plan_text: str, timeout: float = 60.0) -> tuple[bool | None, str]:
    """Run VAL's ``Validate`` on a plan; (True/False, message), or (None, why) if it could not run."""
    validate = shutil.which("Validate")
    if validate is None:
        return None, "VAL's Validate is not on PATH"
    with tempfile.TemporaryDirectory(prefix="relevance-plan-val-") as tmp:
        plan_path = Path(tmp) / "plan"
        plan_path.write_text(plan_text)
        try:
            completed = subprocess.run(
                [validate, str(domain_path), str(problem_path), str(plan_path)],
                cwd=tmp,
                capture_output=True,
                text=True,
                timeout=timeout,
                stdin=subprocess.DEVNULL,
            )
        except (OSError, subprocess.TimeoutExpired) as error:
            return None, f"Validate could not run: {error}"
    output = completed.stdout + completed.stderr
    if "Plan valid" in output:
        return True, "Plan valid (VAL)"
    if "Plan failed" in output or "Goal not satisfied" in output or "Plan invalid" in output:
        lines = [line for line in output.splitlines() if line.strip()]
        return False, lines[-1] if lines else "invalid (VAL)"
    return None, f"Validate gave no verdict (exit {completed.returncode})"
