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

Everything this module imports at its top delays the driver, so that is
``os``, ``sys``, ``limits``, ``methods``, ``command_line`` and ``spawn`` (no ``re``, ``typing``,
``pathlib``, ``subprocess``, ``contextlib`` or ``threading``): the
command line and the domain are read with string methods, and what waits
for the run (``process``) is imported once the tool needs it.
"""

from __future__ import annotations

import _thread
import contextvars
import os
import sys

from relevance_plan.limits import DEFAULT_TIMEOUT, MAX_TIMEOUT
from relevance_plan.planning.methods import Method
from relevance_plan.planning.planners.fast_downward import command_line
from relevance_plan.supervision import spawn

TYPE_CHECKING = False  # typing's own flag would import typing
if TYPE_CHECKING:
    from collections.abc import Sequence
    from pathlib import Path

    from relevance_plan.supervision.process import StartedGroup

    # What identifies a driver run: (domain, problem, configuration, memory limit MB, extra arguments).
    RunKey = tuple[str, str, str, int | None, tuple[str, ...]]

# ``plan``'s options as the launcher reads them, generated from ``plan``'s click parameters (cli/app.py):
# those that take a value, its flags, and the defaults the head start depends on.  click cannot be
# imported here (it delays the driver), so the table is written out; tests/test_head_start.py derives
# it from ``plan`` again and prints the table to paste here when the two differ.  Anything else on the
# command line: no head start.
VALUE_OPTIONS = frozenset(
    {
        "--activity", "--human", "--keep-work", "--memory-limit", "--method", "--model", "--objective",
        "--plan-file", "--planner", "--planner-args", "--planner-config", "--scorer", "--seed", "--task",
        "--tau-class", "--tau-element", "--timeout", "--validator",
    }
)  # fmt: skip
FLAGS = frozenset(
    {"--json", "--no-race", "--no-relax", "--no-widen", "--place-kinds", "--quiet", "--race", "--verbose", "-q"}
)
DEFAULT_METHOD = Method.RELEVANCE
DEFAULT_PLANNER = "auto"
# --timeout's and --planner-config's defaults are shared: relevance_plan.limits, command_line.DEFAULT_CONFIG.

# Words of a domain that may make ``auto`` choose another planner than Fast Downward.
_NOT_CLASSICAL = frozenset({":durative-action", ":process", ":event", ":numeric-fluents", ":fluents", ":time"})
# The one function Fast Downward takes: (:functions (total-cost)), perhaps typed ``- number``.
_ONLY_TOTAL_COST = (
    ["(", ":functions", "(", "total-cost", ")", ")"],
    ["(", ":functions", "(", "total-cost", ")", "-", "number", ")"],
)


class HeadStart:
    """A driver run started early on the user's files, in its own scratch folder."""

    def __init__(self, key: RunKey, spawned: spawn.Spawned, workdir: str, time_limit: float):
        self.key = key
        self.spawned = spawned
        self.workdir = workdir
        self.time_limit = time_limit
        self.claimed = False  # taken over or discarded: nobody else may have it
        self.used = False  # taken over by the full-problem run
        self._group: StartedGroup | None = None
        self._lock = _thread.allocate_lock()

    @property
    def group(self) -> StartedGroup:
        """The run as ``process`` waits for and stops it (imported only now)."""
        if self._group is None:
            from pathlib import Path

            from relevance_plan.supervision.process import StartedGroup

            self._group = StartedGroup.adopt(self.spawned, Path(self.workdir))
        return self._group

    def take_over(self, key: RunKey) -> bool:
        """Whether the caller, about to start the run ``key``, takes this one instead (once)."""
        with self._lock:
            if self.claimed or key != self.key:
                return False
            self.claimed = self.used = True
            return True

    def folder(self) -> _Folder:
        """The run's folder, as a context: removed after the block (the caller took the run over)."""
        return _Folder(self.workdir)

    def discard(self) -> None:
        """Stop the run and remove its folder, unless somebody took it over."""
        with self._lock:
            if self.claimed:
                return
            self.claimed = True
        try:
            self.group.stop()
        finally:
            _remove(self.workdir)


class _Folder:
    def __init__(self, path: str):
        self.path = path

    def __enter__(self) -> Path:
        from pathlib import Path

        return Path(self.path)

    def __exit__(self, *exception: object) -> None:
        _remove(self.path)


def _remove(folder: str) -> None:
    import shutil

    shutil.rmtree(folder, ignore_errors=True)


_PENDING: list[HeadStart] = []
_OFFER: contextvars.ContextVar[HeadStart | None] = contextvars.ContextVar("relevance_plan_head_start", default=None)


def take() -> HeadStart | None:
    """The head start the launcher made for this process, handed out once."""
    try:
        return _PENDING.pop()
    except IndexError:
        return None


class offered:  # noqa: N801 - used as a context manager, like contextlib's
    """Within the block, Fast Downward's adapter may :func:`claim` ``head``; after it, an unclaimed
    head start is stopped (the full problem was planned otherwise)."""

    def __init__(self, head: HeadStart | None):
        self.head = head

    def __enter__(self) -> None:
        self._token = _OFFER.set(self.head)

    def __exit__(self, *exception: object) -> None:
        _OFFER.reset(self._token)
        if self.head is not None:
            self.head.discard()


def claim(key: RunKey) -> HeadStart | None:
    """The head start offered to this call if it is the run ``key``, now the caller's to finish."""
    head = _OFFER.get()
    return head if head is not None and head.take_over(key) else None


def discard_pending() -> None:
    """Stop a head start nobody took (the command ended, or failed, before planning)."""
    head = take()
    if head is not None:
        head.discard()


def run_key(
    domain: str | Path, problem: str | Path, config: str, memory_limit_mb: int | None, extra: Sequence[str]
) -> RunKey:
    # abspath on both sides: the adapter's paths and the launcher's are spelled alike
    return (os.path.abspath(domain), os.path.abspath(problem), config, memory_limit_mb, tuple(extra))


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
    driver = command_line.driver_location()
    command = command_line.build_command((sys.executable, str(driver)), domain, problem, config, timeout, memory, extra)
    workdir = spawn.scratch_folder("fd")
    if workdir is None:
        return
    try:
        spawned = spawn.start_guarded(
            command_line.through_lean_driver(command), workdir, what="Fast Downward", program=driver
        )
    except BaseException:
        _remove(workdir)
        raise
    _PENDING.append(HeadStart(run_key(domain, problem, config, memory, extra), spawned, workdir, timeout))


def _full_run_wanted(
    arguments: Sequence[str],
) -> tuple[str, str, str, float, int | None, tuple[str, ...]] | None:
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
        if name in VALUE_OPTIONS:
            if not equals:
                if not items:
                    return None
                value = items.pop(0)
            values[name] = value
        elif item in FLAGS:
            flags.add(item)
        elif item.startswith("-") and item != "-":
            return None  # --help, a typo: the CLI answers
        else:
            positional.append(item)
    if len(positional) != 2 or "--keep-work" in values:
        return None
    method = values.get("--method", DEFAULT_METHOD)
    races = "--race" in flags or ("--no-race" not in flags and spawn.usable_cores() >= 2)
    if not (method == Method.PURE or (method == Method.RELEVANCE and races)):
        return None
    planner = values.get("--planner", DEFAULT_PLANNER)
    if planner not in ("auto", "fast-downward"):
        return None
    domain, problem = (os.path.abspath(path) for path in positional)
    if not (os.path.isfile(domain) and os.path.isfile(problem)):
        return None
    if planner == "auto" and not _plainly_classical(domain):
        return None
    try:
        timeout = float(values.get("--timeout", DEFAULT_TIMEOUT))
        memory = int(values["--memory-limit"]) if "--memory-limit" in values else None
        extra = _split_like_a_shell(values.get("--planner-args", ""))
    except ValueError:
        return None
    if not 0 < timeout <= MAX_TIMEOUT or (memory is not None and memory <= 0):
        return None
    return domain, problem, values.get("--planner-config", command_line.DEFAULT_CONFIG), timeout, memory, extra


def _split_like_a_shell(text: str) -> tuple[str, ...]:
    if not text:
        return ()
    import shlex  # imports re: only for the rare --planner-args

    return tuple(shlex.split(text))


def _plainly_classical(domain: str) -> bool:
    """The domain file shows nothing that could make ``auto`` choose a temporal or numeric planner."""
    try:
        with open(domain, encoding="utf-8", errors="replace") as stream:
            lines = stream.read().lower().splitlines()
    except OSError:
        return False
    text = "\n".join(line.partition(";")[0] for line in lines)
    if "preference" in text:
        return False
    words = text.replace("(", " ( ").replace(")", " ) ").split()
    if _NOT_CLASSICAL.intersection(words):
        return False
    if ":functions" not in words:
        return True
    return any(_contains(words, form) for form in _ONLY_TOTAL_COST)


def _contains(words: list[str], run: list[str]) -> bool:
    """Whether ``run`` occurs in ``words`` as consecutive items."""
    first, size = run[0], len(run)
    return any(words[index : index + size] == run for index, word in enumerate(words) if word == first)
