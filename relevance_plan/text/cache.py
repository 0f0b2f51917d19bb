"""Phrase embeddings kept between runs, in the user's cache folder.

Embedding a model's vocabulary (about a hundred phrases for the kitchen
models' classes) is most of the text model's cost; a command run again with
the same model reads it back instead.  A file is keyed by the weights and the
phrases, so a changed model or other weights never read a stale one.  The
cache is a convenience: a folder that cannot be read or written is no cache,
never an error.
"""

from __future__ import annotations

import contextlib
import hashlib
import os
import tempfile
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from relevance_plan.text.encoder import FloatArray

# Set to a folder to keep the cache there, or to an empty string to keep none.
CACHE_ENV = "RELEVANCE_PLAN_TEXT_CACHE"


def cache_folder() -> Path | None:
    """``$RELEVANCE_PLAN_TEXT_CACHE``, else ``$XDG_CACHE_HOME`` or ``~/.cache``, then ``relevance-plan/text``."""
    chosen = os.environ.get(CACHE_ENV)
    if chosen is not None:
        return Path(chosen) if chosen else None
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base, "relevance-plan", "text")


def cache_key(fingerprint: str, phrases: Sequence[str]) -> str:
    digest = hashlib.sha256(fingerprint.encode())
    for phrase in phrases:
        digest.update(b"\0" + phrase.encode("utf-8", "surrogatepass"))
    return digest.hexdigest()[:40]


def read_cached(key: str, rows: int, width: int) -> FloatArray | None:
    """The stored embeddings under ``key`` if they are there and of the expected shape, else None."""
    import numpy as np

    folder = cache_folder()
    if folder is None:
        return None
    try:
        array = np.load(folder / f"{key}.npy", allow_pickle=False)
    except (OSError, ValueError, EOFError):
        return None
    if array.shape != (rows, width) or array.dtype != np.float32 or not np.isfinite(array).all():
        return None
    return np.asarray(array, dtype=np.float32)


def write_cached(key: str, array: FloatArray) -> None:
    """Store ``array`` under ``key``; written whole or not at all (a temporary file, then a rename)."""
    import numpy as np

    folder = cache_folder()
    if folder is None:
        return
    with contextlib.suppress(OSError):
        folder.mkdir(parents=True, exist_ok=True)
        handle, temporary = tempfile.mkstemp(dir=folder, suffix=".tmp")
        try:
            with os.fdopen(handle, "wb") as file:
                np.save(file, array, allow_pickle=False)
            os.replace(temporary, folder / f"{key}.npy")
        finally:
            with contextlib.suppress(FileNotFoundError):
                os.unlink(temporary)
