"""Fast Downward started on the user's own files before the rest of the tool is imported.

``relevance-plan plan`` plans the full problem anyway when it races it
beside the pruned attempts (or when the method is ``pure``).  Importing the
pipeline, reading and scoring take a few tenths of a second, which on a
problem that cannot be pruned is pure overhead.  The launcher
(``cli/launch.py``) therefore reads the command line with the standard
library only and, when the full problem will be planned by Fast Downward
with a configuration it can tell from the arguments, starts the driver at
once under the guard (:func:`start_for_plan`).  The attempt loop offers that
run to its first full-problem call (:func:`offered`); Fast Downward's adapter
takes it over (:func:`claim`) when the command it would have started is the
same, and otherwise the run is stopped and its folder removed.  Nothing is
decided here: every argument is checked again by the CLI, and a head start
that does not match is simply not used.

Standard library only (besides ``fd_command`` and ``process``), and no
dataclasses (their import costs ~10 ms): this runs before anything else is
imported, and whatever it imports delays the driver.
"""

from __future__ import annotations

import contextlib
import contextvars
import re
import shlex
import shutil
import sys
import tempfile
import threading
from collections.abc import Iterator, Sequence
from pathlib import Path

from relevance_plan.planning import fd_command
from relevance_plan.planning.process import StartedGroup, start_process_group
from relevance_plan.planning.race import usable_cores

# What identifies a driver run: (domain, problem, configuration, memory limit MB, extra arguments).
RunKey = tuple[str, str, str, "int | None", tuple[str, ...]]

# ``plan``'s options that take a value, and its flags (cli/app.py); anything else: no head start.
_VALUE_OPTIONS = frozenset(
    {
        "--method", "--scorer", "--model", "--objective", "--task", "--human", "--tau-class", "--tau-element",
        "--seed", "--planner", "--planner-config", "--planner-args", "--timeout", "--memory-limit",
        "--validator", "--plan-file", "--keep-work",
    }
)  # fmt: skip
_FLAGS = frozenset({"--no-widen", "--no-relax", "--race", "--no-race", "--json", "--quiet", "-q"})
_DEFAULT_TIMEOUT = 120.0
# Domains whose features may make ``auto`` choose another planner than Fast Downward.
_NOT_CLASSICAL = re.compile(r":durative-action|:process\b|:event\b|:numeric-fluents|:fluents|:time\b|preference")
_ONLY_TOTAL_COST = re.compile(r"\(:functions\s*\(total-cost\)\s*(-\s*number\s*)?\)")


class HeadStart:
    """A driver run started early on the user's files, in its own scratch folder."""

    def __init__(self, key: RunKey, group: StartedGroup, workdir: Path, time_limit: float):
        self.key = key
        self.group = group
        self.workdir = workdir
        self.time_limit = time_limit
        self.claimed = False  # taken over or discarded: nobody else may have it
        self.used = False  # taken over by the full-problem run
        self._lock = threading.Lock()

    def take_over(self, key: RunKey) -> bool:
        """Whether the caller, about to start the run ``key``, takes this one instead (once)."""
        with self._lock:
            if self.claimed or key != self.key:
                return False
            self.claimed = self.used = True
            return True

    @contextlib.contextmanager
    def folder(self) -> Iterator[Path]:
        """The run's folder, removed after the block (the caller took the run over)."""
        try:
            yield self.workdir
        finally:
            shutil.rmtree(self.workdir, ignore_errors=True)

    def discard(self) -> None:
        """Stop the run and remove its folder, unless somebody took it over."""
        with self._lock:
            if self.claimed:
                return
            self.claimed = True
        try:
            self.group.stop()
        finally:
            shutil.rmtree(self.workdir, ignore_errors=True)


_PENDING: list[HeadStart] = []
_OFFER: contextvars.ContextVar[HeadStart | None] = contextvars.ContextVar("relevance_plan_head_start", default=None)


def take() -> HeadStart | None:
    """The head start the launcher made for this process, handed out once."""
    try:
        return _PENDING.pop()
    except IndexError:
        return None


@contextlib.contextmanager
def offered(head: HeadStart | None) -> Iterator[None]:
    """Within the block, Fast Downward's adapter may :func:`claim` ``head``; after it, an unclaimed
    head start is stopped (the full problem was planned otherwise)."""
    token = _OFFER.set(head)
    try:
        yield
    finally:
        _OFFER.reset(token)
        if head is not None:
            head.discard()


def claim(key: RunKey) -> HeadStart | None:
    """The head start offered to this call if it is the run ``key``, now the caller's to finish."""
    head = _OFFER.get()
    return head if head is not None and head.take_over(key) else None


def discard_pending() -> None:
    """Stop a head start nobody took (the command ended, or failed, before planning)."""
    head = take()
    if head is not None:
        head.discard()


def run_key(domain: Path, problem: Path, config: str, memory_limit_mb: int | None, extra: Sequence[str]) -> RunKey:
    return (str(domain), str(problem), config, memory_limit_mb, tuple(extra))


def start_for_plan(arguments: Sequence[str]) -> None:
    """Start Fast Downward on the full problem if ``plan ARGUMENTS`` will plan it with Fast Downward.

    Quietly does nothing when it cannot tell (an option it does not know, a
    value it cannot read, another planner, a file it cannot read): the
    command then runs as it would have.
    """
    wanted = _full_run_wanted(arguments)
    if wanted is None:
        return
    domain, problem, config, timeout, memory, extra = wanted
    command = fd_command.build_command(
        sys.executable, fd_command.find_fast_downward(), domain, problem, config, timeout, memory, extra
    )
    workdir = Path(tempfile.mkdtemp(prefix="relevance-plan-fd-"))
    try:
        group = start_process_group(command, workdir, what="Fast Downward", program=command[1])
    except BaseException:
        shutil.rmtree(workdir, ignore_errors=True)
        raise
    _PENDING.append(HeadStart(run_key(domain, problem, config, memory, extra), group, workdir, timeout))


def _full_run_wanted(
    arguments: Sequence[str],
) -> tuple[Path, Path, str, float, int | None, tuple[str, ...]] | None:
    """(domain, problem, config, time limit, memory limit, extra arguments) of the full-problem run
    ``plan`` will start with Fast Downward, or None when it will not (or this cannot tell)."""
    values: dict[str, str] = {}
    flags: set[str] = set()
    positional: list[str] = []
    items = list(arguments)
    while items:
        item = items.pop(0)
        name, equals, value = item.partition("=")
        if item == "--":
            positional += items
            break
        if name in _VALUE_OPTIONS:
            if not equals:
                if not items:
                    return None
                value = items.pop(0)
            values[name] = value
        elif item in _FLAGS:
            flags.add(item)
        elif item.startswith("-") and item != "-":
            return None  # --help, a typo: the CLI answers
        else:
            positional.append(item)
    if len(positional) != 2 or "--keep-work" in values:
        return None
    method = values.get("--method", "relevance")
    races = "--race" in flags or ("--no-race" not in flags and usable_cores() >= 2)
    if not (method == "pure" or (method == "relevance" and races)):
        return None
    if values.get("--planner", "auto") not in ("auto", "fast-downward"):
        return None
    domain, problem = (Path(p).absolute() for p in positional)
    if not (domain.is_file() and problem.is_file()):
        return None
    if values.get("--planner", "auto") == "auto" and not _plainly_classical(domain):
        return None
    try:
        timeout = float(values.get("--timeout", _DEFAULT_TIMEOUT))
        memory = int(values["--memory-limit"]) if "--memory-limit" in values else None
        extra = tuple(shlex.split(values.get("--planner-args", "")))
    except ValueError:
        return None
    if not 0 < timeout <= 1e6 or (memory is not None and memory <= 0):
        return None
    return domain, problem, values.get("--planner-config", fd_command.DEFAULT_CONFIG), timeout, memory, extra


def _plainly_classical(domain: Path) -> bool:
    """The domain file shows nothing that could make ``auto`` choose a temporal or numeric planner."""
    try:
        text = domain.read_text(encoding="utf-8", errors="replace").lower()
    except OSError:
        return False
    text = re.sub(r";[^\n]*", "", text)
    if _NOT_CLASSICAL.search(text):
        return False
    return ":functions" not in text or bool(_ONLY_TOTAL_COST.search(text))
