"""A planner fitted to one problem: its pass-through arguments, the compilations it needs, its kept files.

The attempt loop calls :func:`prepare_planner` once per problem, before any
work.  The planner gets its pass-through arguments (``--planner-args``);
then its features are compared with the problem's.  What it lacks and a
compilation of ``pddl.compile`` removes (each declares what it removes) is
compiled away (the compilations are chosen once, on the full problem, and
named in the result); what cannot be removed is refused, as the planner's
own ``check`` refuses it.

Each run of the :class:`PreparedPlanner` then compiles the problem it is
given (an attempt's pruned problem, or the full one, compiled once),
writes the compiled domain and problem with the formatter, runs the planner
on them and maps every plan back to the problem's own actions and
arguments, so that the loop validates it on the ORIGINAL problem.  With
``keep_work``, each run works in ``DIR/attempt-N``, which is left behind:
the planner's own files (Fast Downward's ``output.sas`` and ``sas_plan*``,
a command's plan file, the log) and the compiled files.
"""

from __future__ import annotations

import contextlib
import dataclasses
import itertools
import os
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass
from pathlib import Path

from relevance_plan import errors
from relevance_plan.io import load_problem, scratch_directory, write_text_atomic
from relevance_plan.pddl.compile import COMPILATIONS, Compilation
from relevance_plan.pddl.formatter import format_domain, format_problem
from relevance_plan.pddl.model import Domain, Problem
from relevance_plan.pddl.plans import Plan
from relevance_plan.planning.planners.auto import FallbackPlanner
from relevance_plan.planning.planners.base import Planner, RunOutcome
from relevance_plan.planning.planners.requirements import problem_features

# The features each compilation removes, as it declares them; and all that can be compiled away.
COMPILED_FEATURES: dict[str, frozenset[str]] = {name: step.removes for name, step in COMPILATIONS.items()}
COMPILABLE = frozenset().union(*COMPILED_FEATURES.values())

ATTEMPT_DIRECTORY = "attempt-{}"
COMPILED_DOMAIN = "compiled-domain.pddl"
COMPILED_PROBLEM = "compiled-problem.pddl"


@dataclass(frozen=True)
class CompiledTask:
    """A task after a chain of compilations, and the way back for its plans."""

    domain: Domain
    problem: Problem
    steps: tuple[Compilation, ...] = ()

    @property
    def names(self) -> tuple[str, ...]:
        return tuple(step.name for step in self.steps)

    def map_back(self, plan: Plan) -> Plan:
        for step in reversed(self.steps):
            plan = step.map_back(plan)
        return plan


def compile_for(takes: frozenset[str], domain: Domain, problem: Problem) -> CompiledTask:
    """Run, in their order, the compilations that remove a feature the task uses and ``takes`` lacks,
    and again while one is left (a compilation may uncover what an earlier one removes)."""
    steps: list[Compilation] = []
    for _ in range(len(COMPILATIONS)):
        ran = False
        for compiler in COMPILATIONS.values():
            if (problem_features(domain, problem) - takes) & compiler.removes:
                step = compiler(domain, problem)
                steps.append(step)
                domain, problem = step.domain, step.problem
                ran = True
        if not ran:
            break
    return CompiledTask(domain, problem, tuple(steps))


def replay(names: Iterable[str], domain: Domain, problem: Problem) -> CompiledTask:
    """The compilations called ``names``, in that order (those chosen for the full problem, on a pruned one)."""
    steps: list[Compilation] = []
    for name in names:
        step = COMPILATIONS[name](domain, problem)
        steps.append(step)
        domain, problem = step.domain, step.problem
    return CompiledTask(domain, problem, tuple(steps))


# --------------------------------------------------------------------------- pass-through arguments, kept files


def _has_field(planner: object, name: str) -> bool:
    return dataclasses.is_dataclass(planner) and name in {f.name for f in dataclasses.fields(planner)}


def with_planner_args(planner: Planner, arguments: Sequence[str]) -> Planner:
    """The planner with ``arguments`` appended to its command line (``--planner-args``)."""
    if not arguments:
        return planner
    if not _has_field(planner, "extra_arguments"):
        raise errors.UsageError(f"{planner.name} takes no --planner-args: it has no command line of its own")
    return dataclasses.replace(planner, extra_arguments=tuple(arguments))  # type: ignore[type-var]


def keeping_work(planner: Planner, directory: Path) -> Planner:
    """The planner, working in ``directory`` and leaving its files there."""
    if not _has_field(planner, "work_dir"):
        raise errors.UsageError(f"{planner.name} cannot keep its working files (--keep-work)")
    return dataclasses.replace(planner, work_dir=str(directory))  # type: ignore[type-var]


def check_keep_directory(directory: str | os.PathLike[str], inputs: Iterable[str | None] = ()) -> Path:
    """Refuse, before any work, a ``--keep-work`` directory that is an input, a file, or holds attempts;
    the directory made absolute (planners run in directories of their own, where a relative path
    names another place)."""
    path = Path(os.path.abspath(directory))
    for source in inputs:
        if source is not None and _same_path(path, Path(source)):
            raise errors.UsageError(f"--keep-work {path} is also the file {source}; choose another directory")
    if path.exists() and not path.is_dir():
        raise errors.InputFileError("--keep-work must name a directory, and this is a file", path=str(path))
    earlier = sorted(path.glob(ATTEMPT_DIRECTORY.format("*"))) if path.is_dir() else []
    if earlier:
        raise errors.InputFileError(
            f"--keep-work never overwrites: {earlier[0].name} is there from an earlier run; choose another directory",
            path=str(path),
        )
    return path


def _same_path(a: Path, b: Path) -> bool:
    if a.exists() and b.exists():
        return os.path.samefile(a, b)
    return os.path.abspath(a) == os.path.abspath(b)


def attempt_directory(base: Path, number: int) -> Path:
    """``base/attempt-N``, new (an existing one is never reused)."""
    path = base / ATTEMPT_DIRECTORY.format(number)
    try:
        base.mkdir(parents=True, exist_ok=True)
        path.mkdir()
    except FileExistsError:
        raise errors.InputFileError("--keep-work never overwrites: this exists", path=str(path)) from None
    except OSError as error:
        raise errors.InputFileError(
            f"cannot create the --keep-work directory: {error.strerror}", path=str(path)
        ) from None
    return path


# --------------------------------------------------------------------------- the prepared planner


class PreparedPlanner:
    """A planner fitted to one problem; each :meth:`run` is one attempt."""

    def __init__(
        self,
        planner: Planner,
        domain: Domain | None = None,
        full: CompiledTask | None = None,
        problem_path: str = "",
        keep: Path | None = None,
    ):
        """``planner`` alone: it runs on the files as they are (input our reader refuses)."""
        self.planner = planner
        self.domain = domain
        self.full = full  # the full problem compiled (None: the planner takes it as it is)
        self.problem_path = problem_path
        self.keep = keep
        self._runs = itertools.count(1)

    @property
    def compilations(self) -> tuple[str, ...]:
        return self.full.names if self.full is not None else ()

    def run(
        self, domain_path: str, problem_path: str, *, time_limit: float | None, memory_limit_mb: int | None
    ) -> RunOutcome:
        """Run the planner on this pair (compiled first when needed); plans are the problem's own."""
        number = next(self._runs)
        workdir = attempt_directory(self.keep, number) if self.keep is not None else None
        planner = keeping_work(self.planner, workdir) if workdir is not None else self.planner
        if self.full is None:
            return planner.run(domain_path, problem_path, time_limit=time_limit, memory_limit_mb=memory_limit_mb)
        task = self._compiled(problem_path)
        folder = contextlib.nullcontext(str(workdir)) if workdir is not None else scratch_directory()
        with folder as directory:
            compiled_domain = write_text_atomic(Path(directory) / COMPILED_DOMAIN, format_domain(task.domain))
            compiled_problem = write_text_atomic(Path(directory) / COMPILED_PROBLEM, format_problem(task.problem))
            outcome = planner.run(
                str(compiled_domain), str(compiled_problem), time_limit=time_limit, memory_limit_mb=memory_limit_mb
            )
        return dataclasses.replace(
            outcome,
            plan=task.map_back(outcome.plan),
            plans=tuple(task.map_back(plan) for plan in outcome.plans),
        )

    def _compiled(self, problem_path: str) -> CompiledTask:
        assert self.full is not None and self.domain is not None
        if os.path.abspath(problem_path) == os.path.abspath(self.problem_path):
            return self.full
        return replay(self.full.names, self.domain, load_problem(problem_path, self.domain))


def prepare_planner(
    planner: Planner,
    domain: Domain,
    problem: Problem,
    problem_path: str,
    planner_args: Sequence[str] = (),
    keep_work: str | os.PathLike[str] | None = None,
    say: Callable[[str], None] | None = None,
) -> PreparedPlanner:
    """The planner fitted to this problem, or the refusal (``UnsupportedFeatureError``, ``UsageError``).

    Compiles only when every feature the planner lacks can be compiled away;
    otherwise the planner's own ``check`` refuses the problem as it is.
    ``say`` hears which compilations will run.
    """
    if isinstance(planner, FallbackPlanner) and (planner_args or keep_work is not None):
        planner = planner.first  # options for one planner's own command line: it runs alone
    planner = with_planner_args(planner, planner_args)
    keep = None
    if keep_work is not None:
        keep = check_keep_directory(keep_work, (domain.path, problem_path))
        keeping_work(planner, keep)  # refuses a planner that cannot keep its files, before any work
    takes = planner.features
    missing = frozenset() if takes is None else problem_features(domain, problem) - takes
    if not missing or missing - COMPILABLE or domain.temporal:
        planner.check(domain, problem)
        return PreparedPlanner(planner, domain, None, problem_path, keep)
    assert takes is not None
    try:
        full = compile_for(takes, domain, problem)
    except errors.UnsupportedFeatureError as error:
        raise errors.UnsupportedFeatureError(
            f"{planner.name} does not take {', '.join(sorted(missing))}, and compiling it away failed: {error.message}",
            path=error.path,
            line=error.line,
        ) from None
    planner.check(full.domain, full.problem)
    if say is not None:
        say(f"{planner.name}: compiling away {', '.join(full.names)} (plans are mapped back)")
    return PreparedPlanner(planner, domain, full, problem_path, keep)
