"""The generator's sidecar (``PROBLEM.json``): ground truth and provenance, read in one place.

Every front end that needs a sidecar (the oracle scorer's set-up, ``sweep``, the
batch rows, the scene-graph import's node map) goes through this module, so a
malformed sidecar gets the same error everywhere.

The generators write sidecars (``generators.generate``), but the reader cannot
sit beside them: the generators are a layer above ``relevance``, whose scoring
set-up reads the oracle's answer (``necessary_objects``) from the sidecar.  So
the reader is a module of its own just above ``io``, whose file reading it
uses, and below every layer that reads a sidecar.
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from relevance_plan.errors import InputFileError
from relevance_plan.io import read_text


@dataclass(frozen=True)
class Sidecar:
    path: str
    world: str | None = None
    difficulty: str | None = None
    relevant: frozenset[str] | None = None  # lower-cased object names; None when the sidecar has none
    necessary: frozenset[str] | None = None


def sidecar_path(problem_path: str | os.PathLike[str]) -> Path:
    return Path(problem_path).with_suffix(".json")


def read_sidecar(path: str | os.PathLike[str]) -> dict[str, Any]:
    """A sidecar file as a dict (its fields are checked by :func:`read_sidecar_for`)."""
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


def _names(data: dict[str, Any], key: str, path: str) -> frozenset[str] | None:
    if key not in data:
        return None
    value = data[key]
    if not isinstance(value, list) or not all(isinstance(name, str) for name in value):
        raise InputFileError(f"sidecar field '{key}' must be a list of object names", path=path)
    return frozenset(name.lower() for name in value)


def _text(data: dict[str, Any], key: str, path: str) -> str | None:
    value = data.get(key)
    if value is not None and not isinstance(value, str):
        raise InputFileError(f"sidecar field '{key}' must be a string", path=path)
    return value


def read_sidecar_for(problem_path: str | os.PathLike[str], required: bool = False) -> Sidecar | None:
    """The sidecar next to ``problem_path``; None when there is none and it is not ``required``."""
    path = sidecar_path(problem_path)
    if not path.is_file():
        if required:
            raise InputFileError("the generator's sidecar is missing", path=str(path))
        return None
    data = read_sidecar(path)
    where = str(path)
    return Sidecar(
        path=where,
        world=_text(data, "world", where),
        difficulty=_text(data, "difficulty", where),
        relevant=_names(data, "relevant", where),
        necessary=_names(data, "necessary", where),
    )


def necessary_objects(problem_path: str | os.PathLike[str]) -> frozenset[str] | None:
    """The sidecar's ``necessary`` set (the oracle's answer); None without a sidecar or the field."""
    sidecar = read_sidecar_for(problem_path)
    return sidecar.necessary if sidecar is not None else None
