"""The planner registry: every planner the attempt loop can call, behind one contract.

A planner runs one domain/problem pair under a time and memory limit and
returns a :class:`~relevance_plan.planning.runner.RunOutcome` (solved with
plan and cost, unsolvable, out of time, out of memory, input error, crash —
with the exit code and the log tail).  ``PLANNERS`` maps a kind to its
adapter; a planner is named ``KIND`` or ``KIND:ARGUMENT``:

- ``fast-downward`` — Fast Downward from up-fast-downward (``--planner-config``
  chooses its alias or search);
- ``up:NAME`` — a one-shot planner installed for unified-planning
  (``up:pyperplan``, ``up:symk``, ``up:lpg``, ...), run in a child process so
  that its time limit holds and a hung engine can be killed;
- ``cmd:TEMPLATE`` — any external planner: a command template with
  ``{domain}``, ``{problem}`` and optionally ``{plan}``, split into an
  argument list (never a shell).

All of them run in their own session and temporary directory with the
watchdog of ``runner.run_process_group``.
"""

from __future__ import annotations

import hashlib
import os
import re
import shlex
import shutil
import sys
import tempfile
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Protocol

from relevance_plan import errors
from relevance_plan.errors import PlanFormatError
from relevance_plan.pddl.plans import Plan, read_plan
from relevance_plan.planning import runner
from relevance_plan.planning.runner import LOG_FILE, LOG_TAIL_LINES, PlannerStatus, RunOutcome

PLANNERS_EXTRA_HINT = "pip install 'relevance-plan[planners]'"


class Planner(Protocol):
    name: str

    def version(self) -> str: ...

    def run(
        self, domain_path: str, problem_path: str, *, time_limit: float | None, memory_limit_mb: int | None
    ) -> RunOutcome: ...


def _watchdog_deadline(time_limit: float | None) -> float | None:
    if time_limit is None:
        return None
    return time_limit + max(runner.DEFAULT_WATCHDOG_GRACE, 0.1 * time_limit)


def _log_tail(workdir: Path) -> str:
    try:
        text = (workdir / LOG_FILE).read_text(errors="replace")
    except OSError:
        return ""
    return "\n".join(text.splitlines()[-LOG_TAIL_LINES:])


# --------------------------------------------------------------------------- IPC plan files


def parse_ipc_plan(text: str) -> Plan | None:
    """The plan in the IPC format, or None when a line is neither a step nor a comment."""
    try:
        return read_plan(text)
    except PlanFormatError:
        return None


# --------------------------------------------------------------------------- fast-downward


@dataclass(frozen=True)
class FastDownwardPlanner:
    config: str = runner.DEFAULT_CONFIG
    name: str = "fast-downward"

    def version(self) -> str:
        """The up-fast-downward version; a driver override adds a digest of its file."""
        version = runner.fast_downward_version()
        override = os.environ.get(runner.FAST_DOWNWARD_ENV)
        if override:
            try:
                digest = hashlib.sha256(Path(override).expanduser().read_bytes()).hexdigest()
            except OSError:
                digest = "missing"
            version += f"+custom-{digest[:12]}"
        return version

    def run(self, domain_path, problem_path, *, time_limit, memory_limit_mb) -> RunOutcome:
        return runner.run_fast_downward(
            domain_path, problem_path, config=self.config, time_limit=time_limit, memory_limit_mb=memory_limit_mb
        )


# --------------------------------------------------------------------------- up:NAME

# Exit codes of ``relevance_plan.planning.up_child`` -> status.
UP_CHILD_STATUS = {
    0: PlannerStatus.SOLVED,
    10: PlannerStatus.UNSOLVABLE,
    12: PlannerStatus.SEARCH_INCOMPLETE,
    22: PlannerStatus.OUT_OF_MEMORY,
    23: PlannerStatus.OUT_OF_TIME,
    31: PlannerStatus.INPUT_ERROR,
    34: PlannerStatus.UNSUPPORTED,
}


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


@dataclass(frozen=True)
class UnifiedPlanningPlanner:
    engine: str

    @property
    def name(self) -> str:
        return f"up:{self.engine}"

    def check(self) -> None:
        if self.engine not in installed_up_engines():
            raise errors.UsageError(
                f"unified-planning engine '{self.engine}' is not installed (installed: "
                f"{', '.join(installed_up_engines()) or 'none'}); {PLANNERS_EXTRA_HINT} adds pyperplan, symk and lpg"
            )

    def version(self) -> str:
        import importlib.metadata  # slow to import; only batch keys need it

        parts = [f"unified-planning {importlib.metadata.version('unified-planning')}"]
        try:
            parts.append(f"up-{self.engine} {importlib.metadata.version('up-' + self.engine)}")
        except importlib.metadata.PackageNotFoundError:
            pass
        return "; ".join(parts)

    def run(self, domain_path, problem_path, *, time_limit, memory_limit_mb) -> RunOutcome:
        with tempfile.TemporaryDirectory(prefix="relevance-plan-up-") as tmp:
            workdir = Path(tmp)
            plan_path = workdir / "plan.txt"
            command = [
                sys.executable,
                "-m",
                "relevance_plan.planning.up_child",
                self.engine,
                str(Path(domain_path).absolute()),
                str(Path(problem_path).absolute()),
                str(plan_path),
                "none" if time_limit is None else f"{time_limit:.3f}",
            ]
            run = runner.run_process_group(
                command,
                workdir,
                _watchdog_deadline(time_limit),
                what=self.name,
                program=sys.executable,
                memory_limit_mb=memory_limit_mb,
            )
            parsed = parse_ipc_plan(plan_path.read_text(errors="replace")) if plan_path.is_file() else None
            log = _log_tail(workdir)
        status = UP_CHILD_STATUS.get(run.exit_code, PlannerStatus.PLANNER_CRASH)
        if run.watchdog_fired and parsed is None:
            status = PlannerStatus.OUT_OF_TIME
        elif status is PlannerStatus.SOLVED and parsed is None:
            status = PlannerStatus.PLANNER_CRASH
        elif status is PlannerStatus.PLANNER_CRASH and "MemoryError" in log:
            status = PlannerStatus.OUT_OF_MEMORY
        return RunOutcome(
            status=status,
            exit_code=run.exit_code,
            plan=parsed if parsed is not None and status is PlannerStatus.SOLVED else Plan(),
            plan_cost=parsed.cost if parsed is not None else None,
            wall_time=run.wall_time,
            cpu_time=run.cpu_time,
            peak_memory_mb=run.peak_memory_mb,
            config=self.engine,
            log_tail=log,
            killed_by_watchdog=run.watchdog_fired,
            process_group=run.process_group,
            planner=self.name,
            raw_status=status.name,
        )


# --------------------------------------------------------------------------- cmd:TEMPLATE

_PLACEHOLDER_RE = re.compile(r"\{(\w*)\}")
_PLACEHOLDERS = frozenset({"domain", "problem", "plan"})


@dataclass(frozen=True)
class CommandPlanner:
    template: str

    @property
    def name(self) -> str:
        return f"cmd:{self.template}"

    @property
    def arguments(self) -> list[str]:
        try:
            arguments = shlex.split(self.template)
        except ValueError as error:
            raise errors.UsageError(f"planner command template cannot be split: {error}") from None
        if not arguments:
            raise errors.UsageError("planner command template is empty")
        return arguments

    def check(self) -> None:
        found = set(_PLACEHOLDER_RE.findall(self.template))
        unknown = found - _PLACEHOLDERS
        if unknown:
            raise errors.UsageError(
                f"planner command template has unknown placeholder(s) "
                f"{', '.join('{' + u + '}' for u in sorted(unknown))} "
                "(use {domain}, {problem} and optionally {plan})"
            )
        missing = {"domain", "problem"} - found
        if missing:
            raise errors.UsageError(
                f"planner command template needs {' and '.join('{' + m + '}' for m in sorted(missing))}"
            )
        self.executable()

    def executable(self) -> str:
        program = self.arguments[0]
        found = shutil.which(program)
        if found is None:
            raise errors.PlannerError(f"planner executable not found: {program}")
        return found

    def version(self) -> str:
        try:
            digest = hashlib.sha256(Path(self.executable()).read_bytes()).hexdigest()[:12]
        except OSError:
            digest = "unreadable"
        return f"cmd sha256:{digest}"

    def run(self, domain_path, problem_path, *, time_limit, memory_limit_mb) -> RunOutcome:
        with tempfile.TemporaryDirectory(prefix="relevance-plan-cmd-") as tmp:
            workdir = Path(tmp)
            plan_path = workdir / "plan.txt"
            values = {
                "domain": str(Path(domain_path).absolute()),
                "problem": str(Path(problem_path).absolute()),
                "plan": str(plan_path),
            }
            command = [_PLACEHOLDER_RE.sub(lambda m: values[m.group(1)], part) for part in self.arguments]
            command[0] = self.executable()
            run = runner.run_process_group(
                command,
                workdir,
                _watchdog_deadline(time_limit),
                what=self.name,
                program=command[0],
                memory_limit_mb=memory_limit_mb,
            )
            uses_plan_file = "{plan}" in self.template
            if uses_plan_file:
                text = plan_path.read_text(errors="replace") if plan_path.is_file() else None
            else:
                text = (workdir / LOG_FILE).read_text(errors="replace")
            log = _log_tail(workdir)
        parsed = None if text is None else parse_ipc_plan(text)
        if run.watchdog_fired:
            status = PlannerStatus.OUT_OF_TIME
        elif run.exit_code != 0:
            status = PlannerStatus.OUT_OF_MEMORY if "MemoryError" in log else PlannerStatus.PLANNER_CRASH
        elif parsed is None:
            status = PlannerStatus.PLANNER_CRASH  # exit 0 but its output is not a plan
        elif not parsed.steps and not uses_plan_file:
            status = PlannerStatus.SEARCH_INCOMPLETE  # said nothing: no plan found
        else:
            status = PlannerStatus.SOLVED
        return RunOutcome(
            status=status,
            exit_code=run.exit_code,
            plan=parsed if parsed is not None and status is PlannerStatus.SOLVED else Plan(),
            plan_cost=parsed.cost if parsed is not None else None,
            wall_time=run.wall_time,
            cpu_time=run.cpu_time,
            peak_memory_mb=run.peak_memory_mb,
            config=self.template,
            log_tail=log,
            killed_by_watchdog=run.watchdog_fired,
            process_group=run.process_group,
            planner=self.name,
            raw_status=status.name,
        )


# --------------------------------------------------------------------------- registry

PLANNERS: dict[str, Callable[[str, str], Planner]] = {
    "fast-downward": lambda argument, config: FastDownwardPlanner(config),
    "up": lambda argument, config: UnifiedPlanningPlanner(argument),
    "cmd": lambda argument, config: CommandPlanner(argument),
}


def make_planner(name: str, config: str = runner.DEFAULT_CONFIG, check: bool = False) -> Planner:
    """The planner called ``name`` (``fast-downward``, ``up:NAME`` or ``cmd:TEMPLATE``).

    With ``check``, also verify that it can run (engine installed, executable
    found, template complete) — a front end does this once, before any work.
    """
    kind, _, argument = name.partition(":")
    if kind not in PLANNERS or (kind == "fast-downward") == bool(argument):
        raise errors.UsageError(f"unknown planner '{name}' (choose from: fast-downward, up:NAME, cmd:TEMPLATE)")
    planner = PLANNERS[kind](argument, config)
    if check and hasattr(planner, "check"):
        planner.check()
    return planner


def split_planner_names(text: str) -> tuple[str, ...]:
    """``fast-downward,up:pyperplan`` -> names; a ``cmd:`` template may contain commas, so it must come last."""
    names: list[str] = []
    rest = text.strip()
    while rest:
        if rest.startswith("cmd:"):
            names.append(rest)
            break
        head, _, rest = rest.partition(",")
        if head.strip():
            names.append(head.strip())
        rest = rest.strip()
    if not names:
        raise errors.UsageError("no planner given")
    return tuple(dict.fromkeys(names))
