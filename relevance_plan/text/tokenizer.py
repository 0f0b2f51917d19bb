"""BERT's uncased WordPiece tokenizer, in plain Python.

Two passes, as the text model was trained with:

1. words: drop control characters, turn any white space into a space, set
   CJK ideographs apart, lower-case, strip accents (``café`` -> ``cafe``), and
   split every punctuation mark into a word of its own (``I'd`` -> ``i ' d``);
2. word pieces: each word is cut greedily into the longest pieces found in the
   vocabulary, pieces after the first marked ``##`` (``creamer`` ->
   ``cream ##er``); a word that cannot be cut, or is very long, is ``[UNK]``.

A sentence is ``[CLS]`` + its pieces + ``[SEP]``, cut to ``max_length`` ids.
"""

from __future__ import annotations

import unicodedata
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from types import MappingProxyType

from relevance_plan.errors import InputFileError

UNKNOWN = "[UNK]"
START = "[CLS]"
END = "[SEP]"
PADDING = "[PAD]"
CONTINUATION = "##"
# A word longer than this is one unknown piece, as in the model's training.
MAX_WORD_CHARACTERS = 100
# The sentence-embedding model reads at most this many ids per text.
MAX_IDS = 256

# Blocks of CJK ideographs: each ideograph is a word of its own.
_CJK_BLOCKS = (
    (0x4E00, 0x9FFF),
    (0x3400, 0x4DBF),
    (0x20000, 0x2A6DF),
    (0x2A700, 0x2B73F),
    (0x2B740, 0x2B81F),
    (0x2B820, 0x2CEAF),
    (0xF900, 0xFAFF),
    (0x2F800, 0x2FA1F),
)


def _is_space(character: str) -> bool:
    return character in " \t\n\r" or unicodedata.category(character) == "Zs"


def _is_control(character: str) -> bool:
    # Tab, newline and return are white space, not control.
    return character not in "\t\n\r" and unicodedata.category(character).startswith("C")


def _is_punctuation(character: str) -> bool:
    # Every ASCII symbol that is neither a letter, a digit nor a space counts (``$``, ``^``, ``~`` ...),
    # though Unicode files some of them under symbols rather than punctuation.
    code = ord(character)
    if 33 <= code <= 47 or 58 <= code <= 64 or 91 <= code <= 96 or 123 <= code <= 126:
        return True
    return unicodedata.category(character).startswith("P")


def _is_cjk(character: str) -> bool:
    code = ord(character)
    return any(first <= code <= last for first, last in _CJK_BLOCKS)


def split_words(text: str) -> list[str]:
    """The first pass: lower-cased, accent-free words and punctuation marks."""
    spaced = []
    for character in unicodedata.normalize("NFC", text):
        if character in ("\x00", "\ufffd") or _is_control(character):
            continue
        if _is_space(character):
            spaced.append(" ")
        elif _is_cjk(character):
            spaced.append(f" {character} ")
        else:
            spaced.append(character)
    words: list[str] = []
    for token in "".join(spaced).split():
        decomposed = unicodedata.normalize("NFD", token.lower())
        plain = "".join(c for c in decomposed if unicodedata.category(c) != "Mn")
        current = ""
        for character in plain:
            if _is_punctuation(character):
                if current:
                    words.append(current)
                    current = ""
                words.append(character)
            else:
                current += character
        if current:
            words.append(current)
    return words


@dataclass(frozen=True)
class WordPieceTokenizer:
    """Text to the ids the encoder reads; ``pieces`` maps each vocabulary entry to its id."""

    pieces: Mapping[str, int]
    max_ids: int = MAX_IDS
    source: str = field(default="<vocabulary>", compare=False)  # the file, for errors

    def __post_init__(self) -> None:
        missing = [token for token in (UNKNOWN, START, END, PADDING) if token not in self.pieces]
        if missing:
            raise InputFileError(f"not a WordPiece vocabulary: it lacks {', '.join(missing)}", path=self.source)
        if self.max_ids < 2:
            raise InputFileError("max_ids must leave room for [CLS] and [SEP]", path=self.source)

    @classmethod
    def from_lines(cls, lines: Sequence[str], source: str = "<vocabulary>") -> WordPieceTokenizer:
        """One vocabulary entry a line; its id is its line number from 0 (the format of ``vocab.txt``)."""
        pieces: dict[str, int] = {}
        for index, line in enumerate(lines):
            pieces.setdefault(line.rstrip("\r\n"), index)
        return cls(MappingProxyType(pieces), source=source)

    @property
    def padding_id(self) -> int:
        return self.pieces[PADDING]

    def word_pieces(self, word: str) -> list[str]:
        """``word`` cut greedily into the longest vocabulary pieces; ``[UNK]`` when it cannot be."""
        if len(word) > MAX_WORD_CHARACTERS:
            return [UNKNOWN]
        found = []
        start = 0
        while start < len(word):
            end = len(word)
            while end > start:
                piece = word[start:end] if start == 0 else CONTINUATION + word[start:end]
                if piece in self.pieces:
                    break
                end -= 1
            else:
                return [UNKNOWN]
            found.append(piece)
            start = end
        return found

    def tokens(self, text: str) -> list[str]:
        """The pieces of ``text``, without ``[CLS]`` and ``[SEP]`` and not cut to length."""
        return [piece for word in split_words(text) for piece in self.word_pieces(word)]

    def encode(self, text: str) -> tuple[int, ...]:
        """``[CLS]`` + the pieces' ids + ``[SEP]``, at most ``max_ids`` in all."""
        pieces = self.tokens(text)[: self.max_ids - 2]
        return (self.pieces[START], *(self.pieces[piece] for piece in pieces), self.pieces[END])
