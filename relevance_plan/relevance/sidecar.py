"""The generator's sidecar (``PROBLEM.json``), checked against its schema once.

Every reader of sidecars (``plan --method oracle``, ``sweep``, ``compare``)
goes through ``read_sidecar_fields``, so a bad sidecar gives the same one
line and exit code (31, a bad input file) everywhere.
"""

from __future__ import annotations

import json
import os
from dataclasses import dataclass
from pathlib import Path

from relevance_plan.errors import InputFileError
from relevance_plan.io import read_text

_NAME_LISTS = ("relevant", "necessary")
_NAMES = ("world", "difficulty")


@dataclass(frozen=True)
class SidecarFields:
    """The fields this tool uses; None where the sidecar does not have one."""

    relevant: frozenset | None
    necessary: frozenset | None
    world: str | None
    difficulty: str | None


def read_sidecar_fields(path: str | os.PathLike) -> SidecarFields:
    """Read and check a sidecar; ``InputFileError`` naming the file and the field otherwise.

    ``relevant`` and ``necessary`` must be lists of object names (lower-cased
    here, as PDDL names are), ``world`` and ``difficulty`` strings; other
    fields are the generator's provenance and are not checked.
    """
    path = Path(path)
    try:
        data = json.loads(read_text(path, "sidecar"))
    except (ValueError, RecursionError) as error:
        detail = str(error).splitlines()[0] if isinstance(error, ValueError) else "nested too deeply"
        raise InputFileError(f"sidecar is not valid JSON: {detail}", path=str(path)) from None
    if not isinstance(data, dict):
        raise InputFileError("sidecar must hold a JSON object", path=str(path))
    values = {}
    for key in _NAME_LISTS:
        value = data.get(key)
        if value is not None and (not isinstance(value, list) or not all(isinstance(v, str) for v in value)):
            raise InputFileError(f"sidecar field '{key}' must be a list of object names", path=str(path))
        values[key] = frozenset(v.lower() for v in value) if value is not None else None
    for key in _NAMES:
        value = data.get(key)
        if value is not None and not isinstance(value, str):
            raise InputFileError(f"sidecar field '{key}' must be a string", path=str(path))
        values[key] = value
    return SidecarFields(**values)
