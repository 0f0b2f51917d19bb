"""The files a command names: checked before any work, and its output written to them or to standard output.

``-`` (and ``/dev/stdout``, or a link to it) is standard output.  An output
that is also an input, a read-only file, a missing folder or a descriptor
not open for writing is refused before anything runs; an input read more
than once (the planner reads the domain again) must be a regular file.
"""

from __future__ import annotations

import os
import stat
import sys
from collections.abc import Iterable
from pathlib import Path

from relevance_plan.errors import InputFileError, UsageError
from relevance_plan.io import (
    STDOUT,
    check_file_name,
    check_writable_descriptor,
    descriptor_of,
    write_bytes_atomic,
)


def _same_file(a: Path, b: Path) -> bool:
    try:
        return os.path.samefile(a, b)
    except (OSError, ValueError):
        return False


def names_stdout(path: str | os.PathLike) -> bool:
    """Whether writing to ``path`` writes to standard output (``-``, ``/dev/stdout``, a link to it)."""
    return str(path) == STDOUT or descriptor_of(path) == 1


def check_regular_file(path: str | os.PathLike, what: str, why: str) -> None:
    """``InputFileError`` unless ``path`` is a regular file (not a pipe such as ``<(...)`` or /dev/stdin).

    For inputs read more than once (a planner reads the domain again): a pipe
    gives its text only once.  ``why`` names who reads it again ("plan gives it to the planner").
    """
    try:
        regular = stat.S_ISREG(os.stat(path).st_mode)
    except OSError:
        return  # check_input_file reports it
    if descriptor_of(path) is not None:
        # /dev/stdin opened by another process is that process's own standard input.
        raise InputFileError(
            f"{what} names a descriptor of this process: {why}, which cannot open it; give the file's own name",
            path=str(path),
        )
    if not regular:
        raise InputFileError(
            f"{what} is a pipe, not a regular file: {why}, which reads it again; save it to a file first",
            path=str(path),
        )


def check_output_file(
    path: str | os.PathLike, what: str = "output file", inputs: Iterable[str | os.PathLike | None] = ()
) -> None:
    """Fail before any work if ``path`` cannot be written or would overwrite an input.

    ``-`` (standard output) is always fine, and so is a name of one of this
    process's open descriptors (``/dev/stdout``) that is open for writing.
    A file without any write permission bit is refused even for root: the
    user protected it.  A name ending in ``/`` names a directory.
    """
    if str(path) == STDOUT:
        return
    check_file_name(path)
    try:
        _check_output_file(Path(path), what, inputs)
    except OSError as error:  # a name too long, a loop of symlinks, ...
        raise InputFileError(f"cannot write {what}: {error.strerror}", path=str(path)) from None
    descriptor = descriptor_of(path)
    if descriptor is not None:
        check_writable_descriptor(descriptor, what, str(path))
    elif os.fspath(path).endswith(("/", os.sep)):
        raise InputFileError(f"{what} name ends with '/', so it names a directory; give a file name", path=str(path))


def _check_output_file(path: Path, what: str, inputs) -> None:
    for source in inputs:
        if source is not None and str(source) != STDOUT and _same_file(path, Path(source)):
            raise UsageError(f"{what} {path} is the same file as the input {source}; choose another name")
    if descriptor_of(path) is not None:
        return
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


def _output_identity(path: Path) -> tuple:
    """What two names of one output file share: the file (device, inode) once it exists, else its path
    with every link followed."""
    try:
        info = path.stat()
    except (OSError, ValueError):
        return ("path", os.path.realpath(path))
    return ("file", info.st_dev, info.st_ino)


def check_distinct_outputs(outputs: Iterable[tuple[str, str | os.PathLike]]) -> None:
    """``UsageError`` when two outputs of one run, (what, path) pairs, are the same file: the one
    written later would replace the other."""
    seen: dict[tuple, tuple[str, str | os.PathLike]] = {}
    for what, path in outputs:
        key = _output_identity(Path(path))
        if key in seen:
            first, where = seen[key]
            raise UsageError(f"the {what} {path} would replace the {first} {where} of this run; choose another name")
        seen[key] = (what, path)


def write_output(path: str | os.PathLike, text: str) -> str:
    """Write a user-facing output: ``-`` is standard output, anything else
    goes through ``write_bytes_atomic``.  Returns where it went."""
    if str(path) == STDOUT:
        sys.stdout.write(text)
        sys.stdout.flush()
        return "standard output"
    written = write_bytes_atomic(path, text.encode("utf-8"))
    return "standard output" if descriptor_of(path) == 1 else str(written)
