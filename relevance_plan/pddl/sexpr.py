"""S-expression reading with source positions.

Every node remembers where it starts and ends in the text and on which line,
so errors can name the line and the writer can cut a user's file precisely
instead of re-printing it.
"""

from __future__ import annotations

import bisect
import re
from dataclasses import dataclass

from relevance_plan.errors import PDDLParseError

_TOKEN = re.compile(r";[^\n]*|\(|\)|[^\s();]+")

# Lists nested deeper than this are refused, naming the line: the formula
# walkers (ours and the planner's) recurse once or twice per level, and real
# PDDL stays far below it.
MAX_NESTING = 128


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
        self._starts = [0] + [m.end() for m in re.finditer("\n", text)]

    def line_of(self, offset: int) -> int:
        return bisect.bisect_right(self._starts, offset)


def parse_sexpr(text: str, path: str | None = None) -> Node:
    """Parse ``text`` holding exactly one top-level list (a PDDL domain or problem)."""
    lines = LineIndex(text)
    if "\0" in text:
        raise PDDLParseError("NUL byte in the file (a binary file?)", path=path, line=lines.line_of(text.index("\0")))
    stack: list[Node] = []
    root: Node | None = None
    for match in _TOKEN.finditer(text):
        token = match.group()
        if token[0] == ";":
            continue
        start = match.start()
        if token == "(":
            if root is not None and not stack:
                raise PDDLParseError(
                    "unexpected text after the end of the definition", path=path, line=lines.line_of(start)
                )
            if len(stack) >= MAX_NESTING:
                raise PDDLParseError(
                    f"lists nested more than {MAX_NESTING} levels deep", path=path, line=lines.line_of(start)
                )
            stack.append(Node([], start, -1, lines.line_of(start)))
        elif token == ")":
            if not stack:
                raise PDDLParseError("unbalanced ')'", path=path, line=lines.line_of(start))
            node = stack.pop()
            node.end = match.end()
            if stack:
                stack[-1].items.append(node)
            else:
                root = node
        else:
            if not stack:
                if token.startswith("\ufeff") and start == 0:
                    raise PDDLParseError(
                        "the file starts with a byte-order mark (BOM), which planners reject; save it as UTF-8"
                        " without BOM",
                        path=path,
                        line=1,
                    )
                raise PDDLParseError(
                    f"unexpected token '{token}' outside any parenthesis", path=path, line=lines.line_of(start)
                )
            stack[-1].items.append(Symbol(token, start, match.end(), lines.line_of(start)))
    if stack:
        raise PDDLParseError("missing ')': a list is never closed", path=path, line=stack[-1].line)
    if root is None:
        raise PDDLParseError("empty file: no PDDL definition found", path=path, line=1)
    return root
