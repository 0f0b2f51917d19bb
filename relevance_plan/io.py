"""Every file the library reads or writes goes through these helpers."""

from __future__ import annotations

import contextlib
import os
import stat
import sys
import tempfile
from collections.abc import Iterable
from pathlib import Path

from relevance_plan.errors import InputFileError, UsageError
from relevance_plan.pddl.model import Domain, Problem
from relevance_plan.pddl.parser import read_domain, read_problem


def read_bytes(path: str | os.PathLike, what: str = "file") -> bytes:
    check_input_file(path, what)
    path = Path(path)
    try:
        return path.read_bytes()
    except FileNotFoundError:
        raise InputFileError(f"{what} not found", path=str(path)) from None
    except IsADirectoryError:
        raise InputFileError(f"expected a {what}, found a directory", path=str(path)) from None
    except OSError as error:
        raise InputFileError(f"cannot read {what}: {error.strerror}", path=str(path)) from None


def read_text(path: str | os.PathLike, what: str = "file") -> str:
    data = read_bytes(path, what)
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as error:
        line = data.count(b"\n", 0, error.start) + 1
        raise InputFileError(f"not a UTF-8 text file ({error.reason})", path=str(path), line=line) from None


def load_domain(path: str | os.PathLike) -> Domain:
    return read_domain(read_text(path, "domain file"), str(path))


def load_problem(path: str | os.PathLike, domain: Domain) -> Problem:
    return read_problem(read_text(path, "problem file"), domain, str(path))


def load_task(domain_path: str | os.PathLike, problem_path: str | os.PathLike) -> tuple[Domain, Problem]:
    domain = load_domain(domain_path)
    return domain, load_problem(problem_path, domain)


def write_text_atomic(path: str | os.PathLike, text: str) -> Path:
    """Write through a temporary file and rename, so no half-written file is ever seen."""
    return write_bytes_atomic(path, text.encode("utf-8"))


@contextlib.contextmanager
def scratch_directory(prefix: str = "relevance-plan-"):
    """A private temporary directory for pruned problems, removed afterwards."""
    with tempfile.TemporaryDirectory(prefix=prefix) as directory:
        yield Path(directory)


def read_sidecar(path: str | os.PathLike) -> dict:
    """A generator sidecar (PROBLEM.json) as a dict; ``relevance.sidecar`` checks its fields."""
    import json

    try:
        data = json.loads(read_text(path, "sidecar"))
    except ValueError as error:
        raise InputFileError(f"sidecar is not valid JSON: {str(error).splitlines()[0]}", path=str(path)) from None
    except RecursionError:
        raise InputFileError("sidecar is not valid JSON: nested too deeply", path=str(path)) from None
    if not isinstance(data, dict):
        raise InputFileError("sidecar must hold a JSON object", path=str(path))
    return data


def find_suite_problems(directory: str | os.PathLike) -> tuple[Path, list[Path]]:
    """The suite's domain file and its problem files, sorted by name."""
    directory = Path(directory)
    if not directory.is_dir():
        raise InputFileError("suite directory not found", path=str(directory))
    domain = directory / "domain.pddl"
    if not domain.is_file():
        raise InputFileError("suite has no domain.pddl", path=str(directory))
    problems = sorted(p for p in directory.glob("*.pddl") if p.name != "domain.pddl")
    if not problems:
        raise InputFileError("suite has no problem files", path=str(directory))
    return domain, problems


def _read_umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


# Read once at import: os.umask is process-wide and briefly changing it while
# worker threads create files would be a race.
_UMASK = _read_umask()


def new_directory_mode() -> int:
    """The mode ``mkdir`` gives a new directory under this process's umask."""
    return 0o777 & ~_UMASK


STDOUT = "-"


def _same_file(a: Path, b: Path) -> bool:
    try:
        return os.path.samefile(a, b)
    except (OSError, ValueError):
        return False


def _check_name(path: str | os.PathLike) -> None:
    # The OS refuses such names with ValueError, not OSError.
    if "\0" in os.fspath(path):
        raise InputFileError("a file name cannot contain a NUL byte", path=os.fspath(path))


def check_input_file(path: str | os.PathLike, what: str = "file") -> None:
    """Fail with one line (``InputFileError``) unless ``path`` is a readable file.

    Done before any work, so a bad path is reported the same way for every command.
    """
    _check_name(path)
    path = Path(path)
    try:
        info = path.stat()
    except FileNotFoundError:
        raise InputFileError(f"{what} not found", path=str(path)) from None
    except OSError as error:
        raise InputFileError(f"cannot read {what}: {error.strerror}", path=str(path)) from None
    if stat.S_ISDIR(info.st_mode):
        raise InputFileError(f"expected a {what}, found a directory", path=str(path))
    if stat.S_ISCHR(info.st_mode) or stat.S_ISBLK(info.st_mode):
        # /dev/zero would be read until memory runs out; a pipe (/dev/stdin) is fine.
        raise InputFileError(f"expected a {what}, found a device", path=str(path))
    if not os.access(path, os.R_OK):
        raise InputFileError(f"cannot read {what}: permission denied", path=str(path))


def check_output_file(
    path: str | os.PathLike, what: str = "output file", inputs: Iterable[str | os.PathLike | None] = ()
) -> None:
    """Fail before any work if ``path`` cannot be written or would overwrite an input.

    ``-`` (standard output) is always fine.  A file without any write
    permission bit is refused even for root: the user protected it.
    """
    if str(path) == STDOUT:
        return
    _check_name(path)
    try:
        _check_output_file(Path(path), what, inputs)
    except OSError as error:  # a name too long, a loop of symlinks, ...
        raise InputFileError(f"cannot write {what}: {error.strerror}", path=str(path)) from None


def _check_output_file(path: Path, what: str, inputs) -> None:
    for source in inputs:
        if source is not None and str(source) != STDOUT and _same_file(path, Path(source)):
            raise UsageError(f"{what} {path} is the same file as the input {source}; choose another name")
    target = Path(os.path.realpath(path))
    if target.is_dir():
        raise InputFileError(f"{what} is a directory", path=str(path))
    if target.exists():
        info = target.stat()
        if stat.S_ISREG(info.st_mode):
            if not info.st_mode & 0o222 or not os.access(target, os.W_OK):
                raise InputFileError(f"{what} is read-only", path=str(path))
            # A regular file is replaced by rename: its directory must be writable too.
            if not os.access(target.parent, os.W_OK):
                raise InputFileError(f"cannot write {what}: its directory is not writable", path=str(path))
        elif not os.access(target, os.W_OK):
            raise InputFileError(f"cannot write {what}: permission denied", path=str(path))
        return
    directory = target.parent
    if not directory.is_dir():
        raise InputFileError(f"directory of the {what} does not exist", path=str(path))
    if not os.access(directory, os.W_OK):
        raise InputFileError(f"cannot write {what}: its directory is not writable", path=str(path))


def write_output(path: str | os.PathLike, text: str) -> str:
    """Write a user-facing output: ``-`` is standard output, anything else
    goes through ``write_bytes_atomic``.  Returns where it went."""
    if str(path) == STDOUT:
        sys.stdout.write(text)
        sys.stdout.flush()
        return "standard output"
    return str(write_bytes_atomic(path, text.encode("utf-8")))


def write_bytes_atomic(path: str | os.PathLike, data: bytes) -> Path:
    """Write through a temporary file in the same directory and rename it into place.

    A symlink is followed (the link stays, its target gets the new text);
    a device, FIFO or other non-regular file is written to directly, never
    replaced; an existing file keeps its permissions, and a file without
    write permission is refused rather than replaced.
    """
    path = Path(path)
    try:
        target = Path(os.path.realpath(path)) if path.is_symlink() else path
        info = target.stat()
    except FileNotFoundError:
        target, info = path, None
    except OSError as error:
        raise InputFileError(f"cannot write file: {error.strerror}", path=str(path)) from None
    if info is not None and stat.S_ISDIR(info.st_mode):
        raise InputFileError("cannot write file: it is a directory", path=str(path))
    if info is not None and not stat.S_ISREG(info.st_mode):
        try:
            with open(target, "wb") as stream:
                stream.write(data)
        except OSError as error:
            raise InputFileError(f"cannot write file: {error.strerror}", path=str(path)) from None
        return path
    if info is not None and not info.st_mode & 0o222:
        raise InputFileError("cannot write file: it is read-only", path=str(path))
    directory = target.parent if str(target.parent) else Path(".")
    if not directory.is_dir():
        raise InputFileError("output directory does not exist", path=str(directory))
    try:
        handle, temporary = tempfile.mkstemp(prefix="." + target.name + ".", suffix=".tmp", dir=directory)
    except OSError as error:
        raise InputFileError(f"cannot write here: {error.strerror}", path=str(directory)) from None
    try:
        with os.fdopen(handle, "wb") as stream:
            stream.write(data)
        # mkstemp creates 0600; give the file the mode it had, or the one an ordinary open() would.
        mode = stat.S_IMODE(info.st_mode) if info is not None else 0o666 & ~_UMASK
        if info is not None and (info.st_uid, info.st_gid) != (os.getuid(), os.getgid()):
            with contextlib.suppress(OSError):  # only root may give a file away; keep the owner if we can
                os.chown(temporary, info.st_uid, info.st_gid)
        os.chmod(temporary, mode)
        os.replace(temporary, target)
    except BaseException as error:
        try:
            os.unlink(temporary)
        except OSError:
            pass
        if isinstance(error, OSError):
            raise InputFileError(f"cannot write file: {error.strerror}", path=str(path)) from None
        raise
    return path
