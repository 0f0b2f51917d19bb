"""Every file the library reads or writes goes through these helpers."""

from __future__ import annotations

import contextlib
import os
import tempfile
from pathlib import Path

from relevance_plan.errors import InputFileError
from relevance_plan.pddl.reader import Domain, Problem, read_domain, read_problem


def read_bytes(path: str | os.PathLike, what: str = "file") -> bytes:
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
        raise InputFileError(f"not a UTF-8 text file ({error.reason})", path=str(path)) from None


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
    """A generator sidecar (PROBLEM.json): ground truth and provenance."""
    import json

    try:
        data = json.loads(read_text(path, "sidecar"))
    except ValueError as error:
        raise InputFileError(f"sidecar is not valid JSON: {error}", path=str(path)) from None
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


def write_bytes_atomic(path: str | os.PathLike, data: bytes) -> Path:
    """Write through a temporary file in the same directory and rename it into place."""
    path = Path(path)
    directory = path.parent if str(path.parent) else Path(".")
    if not directory.is_dir():
        raise InputFileError("output directory does not exist", path=str(directory))
    try:
        handle, temporary = tempfile.mkstemp(prefix="." + path.name + ".", suffix=".tmp", dir=directory)
    except OSError as error:
        raise InputFileError(f"cannot write here: {error.strerror}", path=str(directory)) from None
    try:
        with os.fdopen(handle, "wb") as stream:
            stream.write(data)
        # mkstemp creates 0600; give the file the mode an ordinary open() would.
        os.chmod(temporary, 0o666 & ~_UMASK)
        os.replace(temporary, path)
    except OSError as error:
        try:
            os.unlink(temporary)
        except OSError:
            pass
        raise InputFileError(f"cannot write file: {error.strerror}", path=str(path)) from None
    return path
