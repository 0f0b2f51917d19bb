"""Write a pruned problem by cutting the user's own file.

The output is the original text minus the pruned objects' declarations and
every initial fact that mentions them.  Names, comments, requirements, the
goal and the metric stay exactly as the user wrote them, so any planner can
read the result and its plan applies unchanged to the original problem.
Cost is linear in the file size: no re-formatting, no grounding.
"""

from __future__ import annotations

from collections.abc import Set

from relevance_plan.pddl.reader import Problem


def write_pruned_problem(problem: Problem, kept: Set[str]) -> str:
    """Return PDDL text of ``problem`` restricted to the objects in ``kept``."""
    cuts: list[tuple[int, int]] = []
    for names, type_symbol in problem.object_groups:
        removed = [symbol for symbol in names if symbol.text.lower() not in kept]
        if not removed:
            continue
        if len(removed) == len(names):
            end = type_symbol.end if type_symbol is not None else names[-1].end
            cuts.append((names[0].start, end))
        else:
            cuts.extend((symbol.start, symbol.end) for symbol in removed)
    for (start, end), mentioned in problem.init_spans:
        if mentioned and not mentioned <= kept:
            cuts.append((start, end))
    return _apply_cuts(problem.text, cuts)


def _apply_cuts(text: str, cuts: list[tuple[int, int]]) -> str:
    """Remove the spans, the blanks after each, and any line they leave empty."""
    if not cuts:
        return text
    length = len(text)
    by_line: dict[int, list[tuple[int, int]]] = {}
    for start, end in cuts:
        by_line.setdefault(text.rfind("\n", 0, start) + 1, []).append((start, end))
    merged: list[tuple[int, int]] = []
    for line_start, spans in by_line.items():
        spans.sort()
        line_end = text.find("\n", spans[-1][1])
        if line_end < 0:
            line_end = length
        position = line_start
        rest = []
        for start, end in spans:
            rest.append(text[position:start])
            position = max(position, end)
        rest.append(text[position:line_end])
        if not "".join(rest).strip():
            merged.append((line_start, min(line_end + 1, length)))
            continue
        for start, end in spans:
            if not text[end:line_end].strip():
                # Last thing on its line: take the blanks before it instead.
                while start > line_start and text[start - 1] in " \t":
                    start -= 1
            else:
                while end < line_end and text[end] in " \t":
                    end += 1
            merged.append((start, end))
    merged.sort()
    pieces: list[str] = []
    position = 0
    for start, end in merged:
        if end <= position:
            continue
        pieces.append(text[position : max(start, position)])
        position = end
    pieces.append(text[position:])
    return "".join(pieces)
