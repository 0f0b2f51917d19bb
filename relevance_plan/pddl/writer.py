"""Write a pruned problem by cutting the user's own file.

The output is the original text minus the pruned objects' declarations and
every :init entry that mentions them: facts, negative literals, numeric
values and timed literals alike.  Names, comments, requirements, the goal,
the constraints and the metric stay exactly as the user wrote them, so any
planner can read the result and its plan applies unchanged to the original
problem.  Cost is linear in the file size, however the file is laid out
(one line or many): no re-formatting, no grounding.
"""

from __future__ import annotations

from collections.abc import Set

from relevance_plan.pddl.model import Problem


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
    keeps = frozenset(kept).issuperset
    for start, end, mentioned in problem.init_spans:
        if mentioned and not keeps(mentioned):
            cuts.append((start, end))
    return apply_cuts(problem.text, cuts)


def apply_cuts(text: str, cuts: list[tuple[int, int]]) -> str:
    """Remove the spans, the blanks after each (before it when it ends its line), and any line they leave empty."""
    if not cuts:
        return text
    removed: list[tuple[int, int]] = []
    by_line: dict[int, list[tuple[int, int]]] = {}
    for run in _runs(text, sorted(cuts)):
        # Spans with only blanks between them, on lines one after another: the lines they fill go at
        # once (213,085 of 213,126 facts); only the first and the last line may keep something.
        first_end = text.find("\n", run[0][0])
        last_start = text.rfind("\n", 0, run[-1][1]) + 1
        line_start = text.rfind("\n", 0, run[0][0]) + 1
        head = 0
        if text[line_start : run[0][0]].strip():  # the first line keeps what comes before the run
            while head < len(run) and (first_end < 0 or run[head][0] < first_end):
                by_line.setdefault(line_start, []).append(run[head])
                head += 1
            line_start = first_end + 1
        tail = len(run)
        line_end = text.find("\n", run[-1][1])
        if line_end < 0:
            line_end = len(text)
        if text[run[-1][1] : line_end].strip():  # the last line keeps what comes after it
            while tail > head and run[tail - 1][0] >= last_start:
                tail -= 1
                by_line.setdefault(last_start, []).append(run[tail])
            line_end = last_start - 1
        if head < tail:
            removed.append((line_start, min(line_end + 1, len(text))))
    for line_start, spans in by_line.items():
        spans.sort()
        line_end = text.find("\n", spans[-1][1])
        if line_end < 0:
            line_end = len(text)
        removed.extend(_cuts_on_line(text, line_start, line_end, spans))
    removed.sort()
    pieces: list[str] = []
    position = 0
    for start, end in removed:
        if end <= position:
            continue
        pieces.append(text[position : max(start, position)])
        position = end
    pieces.append(text[position:])
    return "".join(pieces)


def _runs(text: str, cuts: list[tuple[int, int]]) -> list[list[tuple[int, int]]]:
    # Sorted spans grouped where only blanks with at most one line break lie between two (a blank
    # line between them is the user's and stays).
    runs: list[list[tuple[int, int]]] = []
    run: list[tuple[int, int]] = []
    previous_end = -1
    for start, end in cuts:
        if run:
            gap = text[previous_end:start]
            if gap.strip() or gap.count("\n") > 1 or start < previous_end:
                runs.append(run)
                run = []
        run.append((start, end))
        previous_end = end
    runs.append(run)
    return runs


def _cuts_on_line(text: str, line_start: int, line_end: int, spans: list[tuple[int, int]]) -> list[tuple[int, int]]:
    # The last character of the line outside every span that is not blank: one pass over the line.
    last_kept = -1
    position = line_start
    for start, end in [*spans, (line_end, line_end)]:
        segment = text[position:start].rstrip()
        if segment.strip():
            last_kept = position + len(segment) - 1
        position = max(position, end)
    if last_kept < 0:
        return [(line_start, min(line_end + 1, len(text)))]  # nothing left: the whole line goes
    result = []
    for start, end in spans:
        if start > last_kept:
            # Last thing on its line: take the blanks before it instead.
            while start > line_start and text[start - 1] in " \t":
                start -= 1
        else:
            while end < line_end and text[end] in " \t":
                end += 1
        result.append((start, end))
    return result
