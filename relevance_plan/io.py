"""Reading and writing files: every file the library reads or writes goes through these helpers.

Reading checks first that the path names something readable (never a
device, which would be read until memory runs out); writing goes through a
temporary file renamed into place, or through this process's own
descriptor when the name is one (``/dev/stdout``, ``/proc/self/fd/1``).
Finding a suite's problems is ``batch.suites``'; the CLI's checks of the
files a command names, and its standard output, are ``cli.files``'.
"""

from __future__ import annotations

import contextlib
import json
import os
import re
import stat
import sys
import tempfile
from pathlib import Path
from typing import Any

from relevance_plan.errors import InputFileError
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


def parse_json(text: str) -> Any:
    """The value of the JSON ``text`` (a learned model, a store row's columns); ``ValueError`` for text
    that is not JSON, or nests deeper than the interpreter's recursion limit (the parser recurses
    once per level, and stops there)."""
    try:
        return json.loads(text)
    except RecursionError:
        raise ValueError(f"nested more than {sys.getrecursionlimit()} levels deep") from None


def load_domain(path: str | os.PathLike, deadline: float | None = None) -> Domain:
    """The domain in ``path``; ``deadline`` (``time.monotonic()`` seconds): past it, ``OutOfTimeError``."""
    return read_domain(read_text(path, "domain file"), str(path), deadline)


def load_problem(path: str | os.PathLike, domain: Domain, deadline: float | None = None) -> Problem:
    """The problem in ``path`` for ``domain``; ``deadline`` as for :func:`load_domain`."""
    return read_problem(read_text(path, "problem file"), domain, str(path), deadline)


Source = str | os.PathLike  # a file's path, or (a str starting with '(' or ';') the PDDL text itself


def is_pddl_text(source: object) -> bool:
    """A string that holds a PDDL definition rather than naming a file."""
    return isinstance(source, str) and source.lstrip().startswith(("(", ";"))


def load_sources(domain: Domain | Source, problem: Problem | Source) -> tuple[Domain, Problem]:
    """The domain and the problem from paths, PDDL text, or values already read."""
    if not isinstance(domain, Domain):
        domain = read_domain(str(domain), "<domain text>") if is_pddl_text(domain) else load_domain(domain)
    if not isinstance(problem, Problem):
        text = is_pddl_text(problem)
        problem = read_problem(str(problem), domain, "<problem text>") if text else load_problem(problem, domain)
    return domain, problem


def load_task(
    domain_path: str | os.PathLike, problem_path: str | os.PathLike, deadline: float | None = None
) -> tuple[Domain, Problem]:
    domain = load_domain(domain_path, deadline)
    return domain, load_problem(problem_path, domain, deadline)


def write_text_atomic(path: str | os.PathLike, text: str) -> Path:
    """Write through a temporary file and rename, so no half-written file is ever seen."""
    return write_bytes_atomic(path, text.encode("utf-8"))


@contextlib.contextmanager
def scratch_directory(prefix: str = "relevance-plan-"):
    """A private temporary directory for pruned problems, removed afterwards."""
    with tempfile.TemporaryDirectory(prefix=prefix) as directory:
        yield Path(directory)


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


STDOUT = "-"  # the file name that means standard output
# An open descriptor of a process, as /proc shows it once the links are followed.
_PROC_DESCRIPTOR = re.compile(r"/proc/(\d+)(?:/task/\d+)?/fd/(\d+)")
_MAX_LINKS = 40  # as the kernel's own limit on a chain of symbolic links


def check_file_name(path: str | os.PathLike) -> None:
    """``InputFileError`` for a name no file can have (the OS refuses it with ValueError, not OSError)."""
    if "\0" in os.fspath(path):
        raise InputFileError("a file name cannot contain a NUL byte", path=os.fspath(path))


def _an(what: str) -> str:
    return ("an " if what[:1] in "aeiou" else "a ") + what


def descriptor_of(path: str | os.PathLike) -> int | None:
    """The descriptor of this process that ``path`` names, or None for an ordinary path.

    ``/dev/stdout``, ``/dev/fd/3``, ``/proc/self/fd/1`` and any chain of
    links to them name a descriptor this process already has open: writing
    there must go through that descriptor (appending where the shell's
    ``>>`` put it), never replace what the link resolves to.
    """
    if str(path) == STDOUT:
        return None
    current = os.path.abspath(os.fspath(path))
    for _ in range(_MAX_LINKS):
        parent = os.path.realpath(os.path.dirname(current))
        current = os.path.join(parent, os.path.basename(current))
        found = _PROC_DESCRIPTOR.fullmatch(current)
        if found is not None and int(found.group(1)) == os.getpid():
            return int(found.group(2))
        try:
            target = os.readlink(current)
        except (OSError, ValueError):
            return None
        current = os.path.join(parent, target)
    return None


def check_input_file(path: str | os.PathLike, what: str = "file") -> None:
    """Fail with one line (``InputFileError``) unless ``path`` is a readable file.

    Done before any work, so a bad path is reported the same way for every command.
    """
    check_file_name(path)
    path = Path(path)
    try:
        info = path.stat()
    except FileNotFoundError:
        raise InputFileError(f"{what} not found", path=str(path)) from None
    except OSError as error:
        raise InputFileError(f"cannot read {what}: {error.strerror}", path=str(path)) from None
    if stat.S_ISDIR(info.st_mode):
        raise InputFileError(f"expected {_an(what)}, found a directory", path=str(path))
    if stat.S_ISCHR(info.st_mode) or stat.S_ISBLK(info.st_mode):
        # /dev/zero would be read until memory runs out; a pipe (/dev/stdin) is fine.
        raise InputFileError(f"expected {_an(what)}, found a device", path=str(path))
    if not os.access(path, os.R_OK):
        raise InputFileError(f"cannot read {what}: permission denied", path=str(path))


def check_writable_descriptor(descriptor: int, what: str, shown: str) -> None:
    """``InputFileError`` unless this process's ``descriptor`` (named ``shown``) is open for writing."""
    import fcntl

    try:
        mode = fcntl.fcntl(descriptor, fcntl.F_GETFL) & os.O_ACCMODE
    except OSError:
        raise InputFileError(f"{what} names descriptor {descriptor}, which is not open", path=shown) from None
    if mode not in (os.O_WRONLY, os.O_RDWR):
        raise InputFileError(f"{what} names descriptor {descriptor}, which is not open for writing", path=shown)


def _write_descriptor(descriptor: int, data: bytes, shown: str) -> None:
    """Write through one of our own descriptors, at its current offset (``>>`` appends)."""
    for stream in (sys.stdout, sys.stderr):
        with contextlib.suppress(Exception):
            if stream.fileno() == descriptor:
                stream.flush()  # what click printed before must come first
    view = memoryview(data)
    try:
        while view:
            view = view[os.write(descriptor, view) :]
    except BrokenPipeError:
        raise
    except OSError as error:
        raise InputFileError(f"cannot write file: {error.strerror}", path=shown) from None


def write_bytes_atomic(path: str | os.PathLike, data: bytes) -> Path:
    """Write through a temporary file in the same directory and rename it into place.

    A symlink is followed (the link stays, its target gets the new text);
    a name of one of this process's open descriptors (``/dev/stdout``, a link
    to ``/proc/self/fd/1``) is written through that descriptor; a device,
    FIFO or other non-regular file is written to directly, never replaced;
    an existing file keeps its permissions, and a file without write
    permission is refused rather than replaced.  A name ending in ``/`` is
    refused: it names a directory, never the file without the slash.
    """
    check_file_name(path)
    descriptor = descriptor_of(path)
    if descriptor is not None:
        check_writable_descriptor(descriptor, "output file", str(path))
        _write_descriptor(descriptor, data, str(path))
        return Path(path)
    if os.fspath(path).endswith(("/", os.sep)):
        raise InputFileError("cannot write file: the name ends with '/', so it names a directory", path=str(path))
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
