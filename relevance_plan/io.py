"""Every file the library reads or writes goes through these helpers."""

from __future__ import annotations

import contextlib
import os
import re
import stat
import sys
import tempfile
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
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


@dataclass(frozen=True)
class SuiteProblem:
    """One problem file of a suite and the domain file it goes with.

    ``error`` says why the problem cannot be run (no domain file found, not a
    regular file, a link to nothing); ``domain`` is None when none was found.
    """

    problem: Path
    domain: Path | None
    error: str | None = None


PROBLEM_FOLDERS = ("instances", "problems")  # where the potassco/IPC layouts keep problems
_DOMAIN_NAME = re.compile(r"^domain(?:$|[-_.\d])|[-_.]domain$", re.IGNORECASE)
_DEFINES = re.compile(rb"\(\s*define\s*\(\s*(domain|problem)\b", re.IGNORECASE)
_TRAILING_NUMBER = re.compile(r"(\d+)$")
_SNIFF_BYTES = 4096


def _natural_key(path: Path) -> list:
    """'p2' before 'p10': numbers in a name compare as numbers."""
    return [int(part) if part.isdigit() else part for part in re.split(r"(\d+)", path.name)]


def _not_regular(path: Path) -> str | None:
    """What ``path`` is when it is not a readable regular file (completes "... is"), else None."""
    try:
        info = path.stat()
    except FileNotFoundError:
        return "a link to a file that does not exist" if path.is_symlink() else "missing"
    except OSError as error:
        return f"unreadable ({error.strerror})"
    if stat.S_ISREG(info.st_mode):
        return None
    kind = "a directory" if stat.S_ISDIR(info.st_mode) else "a FIFO" if stat.S_ISFIFO(info.st_mode) else "a device"
    return f"not a regular file ({kind})"


def _is_domain_file(path: Path) -> bool:
    """A domain by its name (domain.pddl, p01-domain.pddl, domain_p01.pddl, ...) or by its first definition."""
    if _DOMAIN_NAME.search(path.stem):
        return True
    if _not_regular(path) is not None:
        return False  # never opened: reading a FIFO would block
    try:
        with open(path, "rb") as stream:
            head = stream.read(_SNIFF_BYTES)
    except OSError:
        return False
    text = b"\n".join(line.split(b";", 1)[0] for line in head.splitlines())
    found = _DEFINES.search(text)
    return found is not None and found.group(1).lower() == b"domain"


def _number(stem: str) -> int | None:
    found = _TRAILING_NUMBER.search(stem)
    return int(found.group(1)) if found else None


def _domain_for(problem: Path, domains: Sequence[Path]) -> list[Path]:
    """The candidate domains of ``problem``, best rule first: one path, none, or several (ambiguous).

    In order: a domain named after the problem (``p01-domain``, ``p01_domain``,
    ``domain_p01``, ``domain-p01``); a numbered domain with the problem's
    number (``domain-01``, ``domains/domain-1``, ``d01`` for ``p01``); the
    folder's ``domain.pddl``; the parent folder's ``domain.pddl``; pddlgym's
    ``NAME.pddl`` beside the folder ``NAME/`` (or ``NAME_test/``).
    """
    stem = problem.stem.lower()
    by_name = {d.stem.lower(): d for d in domains}
    for name in (f"{stem}-domain", f"{stem}_domain", f"domain_{stem}", f"domain-{stem}"):
        if name in by_name:
            return [by_name[name]]
    number = _number(stem)
    numbered = [d for d in domains if number is not None and _number(d.stem) == number]
    if numbered:
        return numbered
    folder = problem.parent
    names = [folder.name] + [folder.name[: -len(end)] for end in ("_test", "_train") if folder.name.endswith(end)]
    candidates = [folder / "domain.pddl", folder.parent / "domain.pddl"]
    candidates += [folder.parent / f"{name}.pddl" for name in names]
    for candidate in candidates:
        if candidate.exists() or candidate.is_symlink():
            return [candidate]
    return []


def _pddl_entries(directory: Path) -> list[Path]:
    try:
        return sorted((p for p in directory.iterdir() if p.suffix.lower() == ".pddl"), key=_natural_key)
    except OSError as error:
        raise InputFileError(f"cannot list the suite directory: {error.strerror}", path=str(directory)) from None


def _split(entries: list[Path]) -> tuple[list[Path], list[Path]]:
    domains = [p for p in entries if _is_domain_file(p)]
    return domains, [p for p in entries if p not in domains]


def _pair(problem: Path, domains: Sequence[Path]) -> SuiteProblem:
    what = _not_regular(problem)
    if what is not None:
        return SuiteProblem(problem, None, f"problem file is {what}")
    found = _domain_for(problem, domains)
    if not found:
        return SuiteProblem(problem, None, "no domain file found for this problem")
    if len(found) > 1:
        names = ", ".join(d.name for d in found)
        return SuiteProblem(problem, None, f"several domain files could go with this problem: {names}")
    what = _not_regular(found[0])
    if what is not None:
        return SuiteProblem(problem, found[0], f"its domain file {found[0].name} is {what}")
    return SuiteProblem(problem, found[0])


def suite_name(directory: str | os.PathLike) -> str:
    """A suite's name in the store: its folder's name (the parent's for an ``instances/`` folder)."""
    directory = Path(directory)
    return directory.parent.name if directory.name in PROBLEM_FOLDERS and directory.parent.name else directory.name


def find_suite_problems(directory: str | os.PathLike) -> list[SuiteProblem]:
    """Every problem of a suite folder with its domain file, problems in natural name order.

    Layouts: one ``domain.pddl`` beside the problems (``generate``'s and the
    IPC's); a domain per problem (``p01-domain.pddl``, ``domain_p01.pddl``,
    ``domain-p01.pddl``, ``d01.pddl``, potassco's ``domains/domain-1.pddl``
    with ``instances/instance-1.pddl``); ``domain.pddl`` in the parent folder;
    pddlgym's ``NAME.pddl`` with the problems in ``NAME/`` or ``NAME_test/``.
    A problem without a domain, or that is not a regular file, comes back
    with its ``error`` (a batch records it per job).  ``InputFileError`` when
    the folder is missing, has no problem files, or no problem has a domain.
    """
    directory = Path(directory)
    if not directory.is_dir():
        raise InputFileError("suite directory not found", path=str(directory))
    folder = directory
    domains, problems = _split(_pddl_entries(directory))
    if not problems:
        # potassco's layout: domain.pddl (or domains/) beside instances/
        folder = next((directory / name for name in PROBLEM_FOLDERS if (directory / name).is_dir()), directory)
        if folder != directory:
            more, problems = _split(_pddl_entries(folder))
            domains += more
    if folder.name in PROBLEM_FOLDERS and (folder.parent / "domains").is_dir():
        domains += _pddl_entries(folder.parent / "domains")
    if not problems:
        raise InputFileError("suite has no problem files", path=str(directory))
    found = [_pair(problem, domains) for problem in problems]
    if all(entry.domain is None for entry in found):
        raise InputFileError(
            "no domain file for any problem here (looked for domain.pddl, PROBLEM-domain.pddl, "
            "domain_PROBLEM.pddl, domain-NN.pddl, ../domain.pddl and pddlgym's ../FOLDER.pddl)",
            path=str(directory),
        )
    return found


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
# An open descriptor of a process, as /proc shows it once the links are followed.
_PROC_DESCRIPTOR = re.compile(r"/proc/(\d+)(?:/task/\d+)?/fd/(\d+)")
_MAX_LINKS = 40  # as the kernel's own limit on a chain of symbolic links


def _same_file(a: Path, b: Path) -> bool:
    try:
        return os.path.samefile(a, b)
    except (OSError, ValueError):
        return False


def _check_name(path: str | os.PathLike) -> None:
    # The OS refuses such names with ValueError, not OSError.
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


def names_stdout(path: str | os.PathLike) -> bool:
    """Whether writing to ``path`` writes to standard output (``-``, ``/dev/stdout``, a link to it)."""
    return str(path) == STDOUT or descriptor_of(path) == 1


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
        raise InputFileError(f"expected {_an(what)}, found a directory", path=str(path))
    if stat.S_ISCHR(info.st_mode) or stat.S_ISBLK(info.st_mode):
        # /dev/zero would be read until memory runs out; a pipe (/dev/stdin) is fine.
        raise InputFileError(f"expected {_an(what)}, found a device", path=str(path))
    if not os.access(path, os.R_OK):
        raise InputFileError(f"cannot read {what}: permission denied", path=str(path))


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
    _check_name(path)
    try:
        _check_output_file(Path(path), what, inputs)
    except OSError as error:  # a name too long, a loop of symlinks, ...
        raise InputFileError(f"cannot write {what}: {error.strerror}", path=str(path)) from None
    descriptor = descriptor_of(path)
    if descriptor is not None:
        _check_descriptor(descriptor, what, str(path))
    elif os.fspath(path).endswith(("/", os.sep)):
        raise InputFileError(f"{what} name ends with '/', so it names a directory; give a file name", path=str(path))


def _check_descriptor(descriptor: int, what: str, shown: str) -> None:
    import fcntl

    try:
        mode = fcntl.fcntl(descriptor, fcntl.F_GETFL) & os.O_ACCMODE
    except OSError:
        raise InputFileError(f"{what} names descriptor {descriptor}, which is not open", path=shown) from None
    if mode not in (os.O_WRONLY, os.O_RDWR):
        raise InputFileError(f"{what} names descriptor {descriptor}, which is not open for writing", path=shown)


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


def write_output(path: str | os.PathLike, text: str) -> str:
    """Write a user-facing output: ``-`` is standard output, anything else
    goes through ``write_bytes_atomic``.  Returns where it went."""
    if str(path) == STDOUT:
        sys.stdout.write(text)
        sys.stdout.flush()
        return "standard output"
    written = write_bytes_atomic(path, text.encode("utf-8"))
    return "standard output" if descriptor_of(path) == 1 else str(written)


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
    _check_name(path)
    descriptor = descriptor_of(path)
    if descriptor is not None:
        _check_descriptor(descriptor, "output file", str(path))
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
