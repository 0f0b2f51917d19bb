"""Every file the library reads or writes goes through these helpers."""

from __future__ import annotations

import os
import tempfile
from pathlib import Path

from .errors import InputFileError
from .pddl import Domain, Problem, read_domain, read_problem


def read_text(path: str | os.PathLike, what: str = "file") -> str:
    path = Path(path)
    try:
        return path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise InputFileError(f"{what} not found", path=str(path)) from None
    except IsADirectoryError:
        raise InputFileError(f"expected a {what}, found a directory", path=str(path)) from None
    except UnicodeDecodeError as error:
        raise InputFileError(f"not a UTF-8 text file ({error.reason})", path=str(path)) from None
    except OSError as error:
        raise InputFileError(f"cannot read {what}: {error.strerror}", path=str(path)) from None


def load_domain(path: str | os.PathLike) -> Domain:
    return read_domain(read_text(path, "domain file"), str(path))


def load_problem(path: str | os.PathLike, domain: Domain) -> Problem:
    return read_problem(read_text(path, "problem file"), domain, str(path))


def load_task(domain_path: str | os.PathLike, problem_path: str | os.PathLike) -> tuple[Domain, Problem]:
    domain = load_domain(domain_path)
    return domain, load_problem(problem_path, domain)


def write_text_atomic(path: str | os.PathLike, text: str) -> Path:
    """Write through a temporary file and rename, so no half-written file is ever seen."""
    path = Path(path)
    directory = path.parent if str(path.parent) else Path(".")
    if not directory.is_dir():
        raise InputFileError("output directory does not exist", path=str(directory))
    try:
        handle, temporary = tempfile.mkstemp(prefix="." + path.name + ".", suffix=".tmp", dir=directory)
    except OSError as error:
        raise InputFileError(f"cannot write here: {error.strerror}", path=str(directory)) from None
    try:
        with os.fdopen(handle, "w", encoding="utf-8") as stream:
            stream.write(text)
        os.replace(temporary, path)
    except OSError as error:
        try:
            os.unlink(temporary)
        except OSError:
            pass
        raise InputFileError(f"cannot write file: {error.strerror}", path=str(path)) from None
    return path
