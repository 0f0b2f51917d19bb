"""The shipped worlds copied out of the package, so that a regular install can follow the README.

``relevance-plan examples DIR`` writes ``DIR/domains/<world>/`` (domain and
knowledge model), ``DIR/problems/`` (the paper-sized scenes and their
sidecars) and ``DIR/examples/`` (the live-session demonstration: its scene,
events and script): the same relative paths as a clone's root.
"""

from __future__ import annotations

import os
import shutil
import tempfile
from pathlib import Path

from relevance_plan.data import DATA_DIR, DOMAINS_DIR, EXAMPLES_DIR, PROBLEMS_DIR
from relevance_plan.errors import InputFileError, UsageError
from relevance_plan.io import write_bytes_atomic


def example_files() -> list[Path]:
    """The package's world files, relative to the data folder, in a stable order."""
    found = [
        *DOMAINS_DIR.glob("*/*.pddl"),
        *DOMAINS_DIR.glob("*/*.yaml"),
        *PROBLEMS_DIR.glob("*.*"),
        *EXAMPLES_DIR.glob("*.py"),
        *EXAMPLES_DIR.glob("*/*.*"),
    ]
    shipped = (".pddl", ".yaml", ".json", ".jsonl", ".py")
    return sorted(path.relative_to(DATA_DIR) for path in found if path.suffix in shipped)


def write_examples(target: str | os.PathLike[str]) -> list[Path]:
    """Copy the shipped worlds into ``target``; returns the files written.

    Nothing of the user's is replaced: a file that already exists at one of
    the paths refuses the whole copy before anything is written.  A new
    folder appears complete or not at all (built beside it, then renamed).
    """
    if not str(target).strip():
        raise UsageError("the examples folder is an empty path; give a folder name")
    target = Path(target)
    files = example_files()
    if not target.parent.is_dir():
        raise InputFileError(f"{target.parent} is not a folder: cannot create {target}")
    if target.exists() and not target.is_dir():
        raise UsageError(f"{target} exists and is not a folder")
    clashes = [relative for relative in files if (target / relative).exists() or (target / relative).is_symlink()]
    if clashes:
        raise UsageError(f"{target / clashes[0]} exists: choose an empty or new folder (nothing was written)")
    if not target.exists():
        staging = Path(tempfile.mkdtemp(prefix=".relevance-plan-examples-", dir=target.parent))
        try:
            for relative in files:
                (staging / relative).parent.mkdir(parents=True, exist_ok=True)
                shutil.copyfile(DATA_DIR / relative, staging / relative)
            os.rename(staging, target)
        except BaseException:
            shutil.rmtree(staging, ignore_errors=True)
            raise
        return [target / relative for relative in files]
    for relative in files:
        (target / relative).parent.mkdir(parents=True, exist_ok=True)
        write_bytes_atomic(target / relative, (DATA_DIR / relative).read_bytes())
    return [target / relative for relative in files]
