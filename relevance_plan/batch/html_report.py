"""The report as one self-contained HTML page: per suite, its table and its cactus plot.

Nothing outside the page is referenced (no script, style sheet, font or
image): the figures are inline SVG drawn by ``plots`` when matplotlib is
installed, and a note says how to get them when it is not.  Every piece of
text from the store (suite, method, problem names) is escaped.
"""

from __future__ import annotations

import html
import re
from collections.abc import Sequence
from typing import Any

from relevance_plan import __version__
from relevance_plan.batch.report import build_report, report_notes, report_table, suite_labels
from relevance_plan.errors import UsageError, counted

_STYLE = """
body { font-family: sans-serif; margin: 2em; color: #222; max-width: 70em; }
table { border-collapse: collapse; margin: 1em 0; }
th, td { border: 1px solid #bbb; padding: 0.25em 0.6em; }
td { text-align: right; font-variant-numeric: tabular-nums; }
th { background: #eee; }
th.metric { text-align: left; font-weight: normal; }
figure { margin: 1em 0; }
figure svg { max-width: 100%; height: auto; }
.note { color: #555; }
"""

# matplotlib's RDF block names its vocabularies by URL; the page needs none of it.
_SVG_METADATA = re.compile(r"<metadata>.*?</metadata>\s*", re.DOTALL)


def _text(value: object) -> str:
    return html.escape(str(value), quote=True)


def _figures(rows: Sequence[dict[str, Any]]) -> tuple[dict[str | None, str], str]:
    """(inline SVG of each report figure, keyed as ``plots.report_figures``; a note when there are none)."""
    try:
        from relevance_plan.batch.plots import report_svgs, require_matplotlib

        require_matplotlib("figures")
    except UsageError as error:
        return {}, str(error)
    return {key: _SVG_METADATA.sub("", svg) for key, svg in report_svgs(rows).items()}, ""


def _unplotted(rows: Sequence[dict[str, Any]]) -> str:
    from relevance_plan.batch.plots import unplotted_note

    return unplotted_note(row["suite"] for row in rows)


def _table_html(methods: Sequence[str], label: str, lines: Sequence[tuple[str, Sequence[str]]]) -> list[str]:
    out = [f"<table><caption>{_text(label)}</caption>", '<thead><tr><th scope="col">metric</th>']
    out += [f'<th scope="col">{_text(method)}</th>' for method in methods]
    out.append("</tr></thead><tbody>")
    for metric, cells in lines:
        out.append(f'<tr><th scope="row" class="metric">{_text(metric)}</th>')
        out += [f"<td>{_text(cell)}</td>" for cell in cells]
        out.append("</tr>")
    out.append("</tbody></table>")
    return out


def _figure_html(svg: str, caption: str) -> list[str]:
    return ["<figure>", svg, f"<figcaption>{_text(caption)}</figcaption>", "</figure>"]


def format_html(rows: Sequence[dict[str, Any]], title: str = "relevance-plan report") -> str:
    """The page for ``rows`` (the rows of one store, as ``store.rows`` gives them)."""
    rows = list(rows)
    records = build_report(rows)
    methods, blocks = report_table(records)
    svgs, missing = _figures(rows) if rows else ({}, "")
    # A block is "SUITE" or "SUITE [PLANNER]": each suite's section holds its blocks, then its figure.
    raw_of = dict(zip(suite_labels(rows), (row["suite"] for row in rows)))
    out = [
        "<!DOCTYPE html>",
        '<html lang="en"><head><meta charset="utf-8">',
        f"<title>{_text(title)}</title>",
        f"<style>{_STYLE}</style>",
        "</head><body>",
        f"<h1>{_text(title)}</h1>",
        f'<p class="note">{counted(len(rows), "job")} in {counted(len({r["suite"] for r in rows}), "suite")};'
        f" written by relevance-plan {_text(__version__)}.</p>",
    ]
    if not rows:
        out.append("<p>no results</p>")
    if missing:
        out.append(f'<p class="note">No figures: {_text(missing)}</p>')
    elif svgs and (unplotted := _unplotted(rows)):
        out.append(f'<p class="note">{_text(unplotted.capitalize())}.</p>')
    if None in svgs:
        out.append("<section><h2>All suites</h2>")
        out += _figure_html(svgs[None], "Solved problems within a time, all suites")
        out += _figure_html(svgs[""], "Per problem: relevance vs pure")
        out.append("</section>")
    for suite in sorted({row["suite"] for row in rows}):
        out.append(f"<section><h2>{_text(suite)}</h2>")
        for label, lines in blocks:
            if raw_of.get(label) == suite:
                out += _table_html(methods, label, lines)
        if suite in svgs:
            out += _figure_html(svgs[suite], f"Solved problems within a time, {suite}")
        out.append("</section>")
    notes = report_notes(records)
    if notes:
        out.append("<section><h2>Notes</h2><ul>")
        out += [f"<li>{_text(note)}</li>" for note in notes]
        out.append("</ul></section>")
    out.append("</body></html>")
    return "\n".join(out) + "\n"
