"""The ``cmd:TEMPLATE`` adapter: any external planner, from a command template.

The template holds ``{domain}``, ``{problem}`` and optionally ``{plan}``; it
is split into an argument list (never run by a shell); ``--planner-args``
come after the template's arguments.  With ``{plan}`` the planner writes its
plan to that file, else the plan is read from its output.
Nothing is known about the planner: it takes whatever PDDL it takes, and
any exit code but 0 is a crash.
"""

from __future__ import annotations

import re
import shlex
import shutil
from dataclasses import dataclass
from pathlib import Path

from relevance_plan import errors
from relevance_plan.pddl.model import Domain, Problem
from relevance_plan.pddl.plans import Plan
from relevance_plan.planning.planners.base import PlannerStatus, RunOutcome, parse_ipc_plan, signal_reason
from relevance_plan.planning.planners.requirements import refuse_unsupported
from relevance_plan.supervision.process import (
    ProcessRun,
    log_tail,
    read_log,
    read_plan_file,
    run_process_group,
    watchdog_deadline,
    work_directory,
)

KIND = "cmd"
PLAN_FILE = "plan.txt"
_PLACEHOLDER_RE = re.compile(r"\{(\w*)\}")
_PLACEHOLDERS = frozenset({"domain", "problem", "plan"})


def classify(run: ProcessRun, plan: Plan | None, uses_plan_file: bool, log: str) -> PlannerStatus:
    """The command's ending in our words."""
    if run.watchdog_fired:
        return PlannerStatus.OUT_OF_TIME
    if run.exit_code != 0:
        return PlannerStatus.OUT_OF_MEMORY if "MemoryError" in log else PlannerStatus.PLANNER_CRASH
    if plan is None:
        return PlannerStatus.PLANNER_CRASH  # exit 0 but its output is not a plan
    if not plan.steps and not uses_plan_file:
        return PlannerStatus.SEARCH_INCOMPLETE  # said nothing: no plan found
    return PlannerStatus.SOLVED


def exit_reason(program: str, run: ProcessRun, plan: Plan | None) -> str:
    """How the command ended, saying that the exit code is its own."""
    if run.watchdog_fired:
        return f"{program} killed by the watchdog at its wall-clock limit"
    if run.exit_code < 0:
        return f"{program} exit code {run.exit_code}: {signal_reason(run.exit_code)}"
    if run.exit_code == 0 and plan is None:
        return f"{program} exit code 0, but its output is not an IPC plan"
    return f"{program} exit code {run.exit_code}"


@dataclass(frozen=True)
class CommandPlanner:
    template: str
    extra_arguments: tuple[str, ...] = ()  # --planner-args, after the template's arguments
    work_dir: str | None = None  # --keep-work: run here and leave the plan file and the log

    @property
    def name(self) -> str:
        return f"{KIND}:{self.template}"

    @property
    def features(self) -> None:
        """Unknown: the planner decides."""
        return None

    @property
    def proves_unsolvable(self) -> bool:
        """Unknown: counted as no."""
        return False

    @property
    def arguments(self) -> list[str]:
        try:
            arguments = shlex.split(self.template)
        except ValueError as error:
            raise errors.UsageError(f"planner command template cannot be split: {error}") from None
        if not arguments:
            raise errors.UsageError("planner command template is empty")
        return arguments

    def check_installed(self) -> None:
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

    def check(self, domain: Domain, problem: Problem) -> None:
        refuse_unsupported(self.name, self.features, domain, problem)

    def executable(self) -> str:
        program = self.arguments[0]
        found = shutil.which(program)
        if found is None:
            raise errors.PlannerError(f"planner executable not found: {program}")
        return found

    def version(self) -> str:
        import hashlib  # only batch keys need it

        try:
            digest = hashlib.sha256(Path(self.executable()).read_bytes()).hexdigest()[:12]
        except OSError:
            digest = "unreadable"
        return f"cmd sha256:{digest}"

    def run(
        self, domain_path: str, problem_path: str, *, time_limit: float | None, memory_limit_mb: int | None
    ) -> RunOutcome:
        uses_plan_file = "{plan}" in self.template
        with work_directory(self.work_dir, prefix="relevance-plan-cmd-") as workdir:
            plan_path = workdir / PLAN_FILE
            values = {
                "domain": str(Path(domain_path).absolute()),
                "problem": str(Path(problem_path).absolute()),
                "plan": str(plan_path),
            }
            command = [_PLACEHOLDER_RE.sub(lambda m: values[m.group(1)], part) for part in self.arguments]
            command += self.extra_arguments
            command[0] = self.executable()
            run = run_process_group(
                command,
                workdir,
                watchdog_deadline(time_limit),
                what=self.name,
                program=command[0],
                memory_limit_mb=memory_limit_mb,
            )
            log = read_log(workdir)
            refused = ""
            try:
                text = read_plan_file(plan_path) if uses_plan_file else log
            except errors.PlanFormatError as error:
                text, refused = None, error.message
        parsed = None if text is None else parse_ipc_plan(text)
        tail = log_tail(log)
        status = classify(run, parsed, uses_plan_file, tail)
        return RunOutcome.of_process(
            run,
            status,
            parsed,
            planner=self.name,
            config=self.template,
            log_tail=tail,
            reason=refused or exit_reason(Path(command[0]).name, run, parsed),
        )
