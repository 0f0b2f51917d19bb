"""Suites: the folders of problems ``compare``, ``sweep`` and ``learn`` run, each problem with its domain file.

:func:`find_suite_problems` reads the layouts suites come in (``generate``'s,
the IPC's, potassco's, pddlgym's) and pairs every problem with its domain;
:func:`suite_name` is a suite's name in the results store.
"""

from __future__ import annotations

import os
import re
import stat
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from relevance_plan.errors import InputFileError


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
