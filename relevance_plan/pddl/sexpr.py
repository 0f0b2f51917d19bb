"""S-expression reading with source positions.

Every node remembers where it starts and ends in the text and on which line,
so errors can name the line and the writer can cut a user's file precisely
instead of re-printing it.  Lines end at LF, CRLF or a lone CR (old Mac
files), and so do comments.

Reading is one pass over the text, the same speed whether the file has one
line or a million.  A reader given a ``deadline`` (``time.monotonic()``
seconds) checks it every few thousand tokens and stops with
:class:`~relevance_plan.errors.OutOfTimeError`.
"""

from __future__ import annotations

import bisect
import contextlib
import gc
import itertools
import re
import threading
import time
from collections.abc import Iterator, Sequence
from dataclasses import dataclass

from relevance_plan.errors import OutOfTimeError, PDDLParseError

# Group 1: '(', group 2: ')', no group: a comment or a symbol.  A '?' starts a new
# symbol, since names cannot hold one: some IPC files write '(aircraft?a)'.
_TOKEN = re.compile(r"(\()|(\))|;[^\n\r]*|\??[^\s();?]+|\?")
_LINE_BREAK = re.compile(r"\r\n?|\n")

# Lists nested deeper than this are refused, naming the line: the formula
# walkers (ours and the planner's) recurse once or twice per level, and real
# PDDL stays far below it.
MAX_NESTING = 128
# The deadline is checked once per this many tokens (a power of two: a mask test).
DEADLINE_STRIDE = 1 << 14


@dataclass(slots=True)
class Symbol:
    text: str
    start: int
    end: int
    line: int


@dataclass(slots=True)
class Node:
    items: list[Node | Symbol]
    start: int
    end: int
    line: int


Item = Node | Symbol


class LineIndex:
    """Maps a character offset to a 1-based line number."""

    def __init__(self, text: str):
        self._starts = [0] + [m.end() for m in _LINE_BREAK.finditer(text)]

    def line_of(self, offset: int) -> int:
        return bisect.bisect_right(self._starts, offset)


def check_deadline(deadline: float | None, what: str, path: str | None = None, line: int | None = None) -> None:
    """``OutOfTimeError`` naming ``what`` when ``deadline`` (``time.monotonic()`` seconds) has passed."""
    if deadline is not None and time.monotonic() > deadline:
        raise OutOfTimeError(f"out of time while {what} (the --timeout ran out)", path=path, line=line)


_PAUSES = 0
_PAUSES_LOCK = threading.Lock()


@contextlib.contextmanager
def collection_paused() -> Iterator[None]:
    """Pause the cyclic garbage collector while a big file becomes millions of small objects, or
    while a run (reading, scoring, pruning, planning) works on them.

    Its passes over the growing heap would otherwise take a quarter to a
    third of the pruning time, and more than half of the reading: each pass
    walks every fact again.  Nothing read here forms a cycle, and a whole run
    leaves a handful of small ones (17 objects after pruning a 5,000-object
    problem), reclaimed once the collector resumes, when the last pause, of
    any thread, is over.
    """
    global _PAUSES
    with _PAUSES_LOCK:
        _PAUSES += 1
        if _PAUSES == 1:
            resume = gc.isenabled()
            gc.disable()
            collection_paused.resume = resume  # type: ignore[attr-defined]
    try:
        yield
    finally:
        with _PAUSES_LOCK:
            _PAUSES -= 1
            if _PAUSES == 0 and collection_paused.resume:  # type: ignore[attr-defined]
                gc.enable()


def parse_sexpr(
    text: str, path: str | None = None, deadline: float | None = None, skip: Sequence[tuple[int, int]] = ()
) -> Node:
    """Parse ``text`` holding exactly one top-level list (a PDDL domain or problem).

    ``skip``: the offsets of parts read elsewhere (a big :init's plain atoms, see the parser), in
    order, passed over; each must start and end between tokens and not inside a CRLF.  Lines after
    a part still count its line breaks.
    """
    if "\0" in text:
        raise PDDLParseError(
            "NUL byte in the file (a binary file?)", path=path, line=LineIndex(text).line_of(text.index("\0"))
        )
    with collection_paused():
        root = _read_lists(text, path, deadline, skip)
    if root is None:
        if text.strip():
            raise PDDLParseError("no PDDL definition found: the file holds only comments", path=path, line=1)
        raise PDDLParseError("empty file: no PDDL definition found", path=path, line=1)
    return root


def _read_lists(text: str, path: str | None, deadline: float | None, skip: Sequence[tuple[int, int]]) -> Node | None:
    # Offsets where each line after the first starts; the sentinel is never reached.  Inside a
    # skipped part no token asks for its line: its line breaks count, where they are does not.
    read = [0, *itertools.chain.from_iterable(skip), len(text)]  # the parts read: from, to, from, ...
    starts: list[int] = []
    for index in range(0, len(read), 2):
        starts.extend(m.end() for m in _LINE_BREAK.finditer(text, read[index], read[index + 1]))
        if index + 2 < len(read):
            gap_start, gap_end = read[index + 1], read[index + 2]
            breaks = text.count("\n", gap_start, gap_end) + text.count("\r", gap_start, gap_end)
            starts.extend([gap_end] * (breaks - text.count("\r\n", gap_start, gap_end)))
    starts.append(len(text) + 1)
    line, next_line = 1, starts[0]
    stack: list[Node] = []
    root: Node | None = None
    tokens = itertools.chain.from_iterable(
        _TOKEN.finditer(text, read[index], read[index + 1]) for index in range(0, len(read), 2)
    )
    for count, match in enumerate(tokens):
        start = match.start()
        if start >= next_line:
            line = bisect.bisect_right(starts, start) + 1
            next_line = starts[line - 1]
        if not count & (DEADLINE_STRIDE - 1):
            check_deadline(deadline, "reading the file", path, line)
        kind = match.lastindex
        if kind == 1:
            if root is not None:
                raise PDDLParseError("unexpected text after the end of the definition", path=path, line=line)
            if len(stack) >= MAX_NESTING:
                raise PDDLParseError(f"lists nested more than {MAX_NESTING} levels deep", path=path, line=line)
            stack.append(Node([], start, -1, line))
        elif kind == 2:
            if not stack:
                raise PDDLParseError("unbalanced ')'", path=path, line=line)
            node = stack.pop()
            node.end = start + 1
            if stack:
                stack[-1].items.append(node)
            else:
                root = node
        else:
            token = match.group()
            if token[0] == ";":
                continue
            if not stack:
                _outside(token, start, path, line)
            stack[-1].items.append(Symbol(token, start, match.end(), line))
    if stack:
        raise _unclosed(text, path, stack[0].line)
    return root


def _unclosed(text: str, path: str | None, outermost: int) -> PDDLParseError:
    """The error for a list never closed: where it opens, where the file ends, and, when the
    indentation tells, the list whose ')' is probably missing (a list that starts at the
    indentation of one still open, as the next action does when an action lacks its ')')."""
    lines = LineIndex(text)
    end = lines.line_of(max(len(text) - 1, 0))
    suspect = _suspect_list(text, lines)
    if suspect is None or suspect[0] == outermost:
        return PDDLParseError(
            f"missing ')': the list opened on line {outermost} is never closed (the file ends on line {end})",
            path=path,
            line=outermost,
        )
    opened, starts = suspect
    return PDDLParseError(
        f"missing ')': the list opened on line {opened} is probably never closed (line {starts} starts a list at"
        f" its indentation inside it), so the list opened on line {outermost} is still open where the file ends"
        f" on line {end}",
        path=path,
        line=opened,
    )


def _suspect_list(text: str, lines: LineIndex) -> tuple[int, int] | None:
    """(line of a list still open, line of the first list that starts at its indentation or left of it
    while it is open), read on a second pass over the text; None when the indentation tells nothing."""
    stack: list[tuple[int, int, bool]] = []  # (line, column, first on its line)
    for match in _TOKEN.finditer(text):
        kind = match.lastindex
        if kind == 2:
            if stack:
                stack.pop()
            continue
        if kind != 1:
            continue
        start = match.start()
        line = lines.line_of(start)
        line_start = text.rfind("\n", 0, start) + 1
        first = not text[line_start:start].strip()
        column = start - line_start
        if first and len(stack) > 1 and stack[-1][2] and stack[-1][1] >= column:
            return stack[-1][0], line
        stack.append((line, column, first))
    return None


def _outside(token: str, start: int, path: str | None, line: int) -> None:
    if token.startswith("\ufeff") and start == 0:
        raise PDDLParseError(
            "the file starts with a byte-order mark (BOM), which planners reject; save it as UTF-8 without BOM",
            path=path,
            line=1,
        )
    raise PDDLParseError(f"unexpected token '{token}' outside any parenthesis", path=path, line=line)
