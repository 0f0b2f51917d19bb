"""Functions longer than 80 lines: each named with its file, line and length; exit 1 if there is one.

    python .ci/function_lengths.py relevance_plan tests benchmarks

A function's length is its span in the source (``def`` to its last line,
decorators left out), read from the syntax tree of every ``.py`` file under
the folders given.  A function that needs more is two steps sharing state
that wants a name.  Called by ``.ci/run`` and by ``tests/test_layout.py``.
Standard library only.
"""

from __future__ import annotations

import ast
import sys
from pathlib import Path

LIMIT = 80


def long_functions(folders: list[Path], limit: int = LIMIT) -> list[str]:
    """``path:line name (N lines)`` for every function over ``limit`` lines, in file order."""
    found = []
    for folder in folders:
        for path in sorted(folder.rglob("*.py")):
            tree = ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
            for node in ast.walk(tree):
                if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                    length = node.end_lineno - node.lineno + 1
                    if length > limit:
                        found.append((str(path), node.lineno, f"{path}:{node.lineno} {node.name} ({length} lines)"))
    return [line for _, _, line in sorted(found)]


def main(argv: list[str]) -> int:
    if not argv:
        print("usage: function_lengths.py FOLDER...", file=sys.stderr)
        return 2
    found = long_functions([Path(folder) for folder in argv])
    for line in found:
        print(line)
    if found:
        print(f"{len(found)} function(s) over {LIMIT} lines", file=sys.stderr)
    return 1 if found else 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
