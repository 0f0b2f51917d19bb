"""Figures drawn from the report's and the sweep's tables (the only module that imports matplotlib).

matplotlib is the optional 'plots' extra: ``require_matplotlib`` says how to
install it, and the commands call it before doing any work.  Every figure is
drawn into memory first and each file written through a temporary name, so an
error leaves no half-written plot; every file carries our name in its metadata
(PNG "Software", SVG and PDF "Creator"), which is how a later run knows it may
replace it.
"""

from __future__ import annotations

import functools
import hashlib
import io
import os
import re
from collections.abc import Callable, Iterable, Sequence
from pathlib import Path
from typing import Any

from relevance_plan.batch.report import format_count, paired_times, solved_times
from relevance_plan.batch.sweep import METRICS, N_MEANING, SweepResult, metric_grid, truth_tables
from relevance_plan.errors import InputFileError, UsageError
from relevance_plan.io import write_bytes_atomic

PLOTS_INSTALL_HINT = "pip install 'relevance-plan[plots]'"
PLOT_FORMATS = ("png", "svg", "pdf")
DEFAULT_DPI = 150
PLOT_STEMS = ("cactus", "relevance-vs-pure")  # then one cactus-SUITE per suite
PLOT_FILES = tuple(f"{stem}.png" for stem in PLOT_STEMS)
# Written into every plot we make: a plot file without it is the user's own.
SOFTWARE = "relevance-plan"
_MARKS = {
    "png": (b"\x89PNG", b"Software\x00" + SOFTWARE.encode()),  # the tEXt chunk
    "svg": (b"<?xml", b"<dc:title>" + SOFTWARE.encode() + b"</dc:title>"),  # the creator in the RDF metadata
    "pdf": (b"%PDF", b"/Creator (" + SOFTWARE.encode() + b")"),  # the document information
}
_MARK_WITHIN = {"png": 4096, "svg": 4096, "pdf": 1 << 24}  # a PDF's information dictionary comes last


def require_matplotlib(what: str = "plots") -> None:
    """``UsageError`` naming the extra to install when matplotlib is missing."""
    try:
        import matplotlib.figure  # noqa: F401
        from matplotlib.backends.backend_agg import FigureCanvasAgg  # noqa: F401
    except ImportError:
        raise UsageError(f"{what} need matplotlib, which is not installed: {PLOTS_INSTALL_HINT}") from None


def _figure(**options):
    from matplotlib.figure import Figure

    return Figure(**options)


def render(figure, fmt: str = "png", dpi: int = DEFAULT_DPI) -> bytes:
    """The figure as a PNG, SVG or PDF file's bytes, our name in its metadata."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    if fmt not in PLOT_FORMATS:
        raise UsageError(f"unknown plot format '{fmt}' (choose from: {', '.join(PLOT_FORMATS)})")
    FigureCanvasAgg(figure)
    buffer = io.BytesIO()
    key = "Software" if fmt == "png" else "Creator"
    figure.savefig(buffer, format=fmt, dpi=dpi, metadata={key: SOFTWARE})
    return buffer.getvalue()


def _save(figure, path: Path, dpi: int = 120) -> Path:
    return write_bytes_atomic(path, render(figure, "png", dpi))


# --------------------------------------------------------------------------- report


def _cactus(rows: Sequence[dict[str, Any]], suite: str | None = None):
    from matplotlib.ticker import MaxNLocator

    figure = _figure(figsize=(6.4, 4.4), layout="constrained")
    axes = figure.add_subplot()
    for method, times in solved_times(rows).items():
        if times:
            # Start at zero solved so that even one solved problem shows a step.
            axes.step([times[0], *times], range(len(times) + 1), where="post", label=f"{method} ({len(times)})")
        else:
            axes.plot([], [], label=f"{method} (0)")
    axes.set_xscale("log")
    axes.set_ylim(bottom=0)
    axes.yaxis.set_major_locator(MaxNLocator(integer=True))
    axes.set_xlabel("time per problem (s): relevance + planning")
    axes.set_ylabel("problems solved")
    axes.set_title("Solved problems within a time " + ("(all suites)" if suite is None else f"({suite})"))
    axes.grid(True, which="both", alpha=0.3)
    axes.legend()
    return figure


def _scatter(rows: Sequence[dict[str, Any]]):
    figure = _figure(figsize=(5.2, 5.2), layout="constrained")
    axes = figure.add_subplot()
    pairs = paired_times(rows)
    timeout = max((float(r["timeout"]) for r in rows), default=1.0)
    if pairs:
        for suite in sorted({p.suite for p in pairs}):
            mine = [p for p in pairs if p.suite == suite]
            axes.scatter([p.pure_time for p in mine], [p.relevance_time for p in mine], label=suite, alpha=0.8, s=24)
        low = max(min(min(p.pure_time, p.relevance_time) for p in pairs) / 2, 1e-3)
        high = timeout * 1.5
        axes.plot([low, high], [low, high], color="grey", linewidth=0.8, linestyle=":", label="equal time")
        axes.axvline(timeout, color="red", linewidth=0.8, linestyle="--", label=f"timeout ({timeout:g} s)")
        axes.axhline(timeout, color="red", linewidth=0.8, linestyle="--")
        axes.set_xlim(low, high)
        axes.set_ylim(low, high)
        axes.set_xscale("log")
        axes.set_yscale("log")
        axes.legend(fontsize="small")
    else:
        message = "no problem has both relevance and pure results"
        axes.text(0.5, 0.5, message, ha="center", va="center", transform=axes.transAxes)
    axes.set_xlabel("pure planning time (s)")
    axes.set_ylabel("relevance time (s): relevance + planning")
    axes.set_title("Per problem: relevance vs pure")
    axes.grid(True, which="both", alpha=0.3)
    return figure


def _ours(path: Path) -> bool:
    """A plot this tool wrote (it carries our name in its metadata)."""
    fmt = path.suffix.lstrip(".").lower()
    if fmt not in _MARKS:
        return False
    start, mark = _MARKS[fmt]
    try:
        with open(path, "rb") as stream:
            head = stream.read(_MARK_WITHIN[fmt])
    except OSError:
        return False
    return head.startswith(start) and mark in head


def _file_part(suite: str) -> str:
    """A suite's name as part of a file name: letters, digits, '.', '_' and '-' only."""
    return re.sub(r"[^A-Za-z0-9._-]+", "-", suite).strip(".-") or "suite"


# A store of more suites than this gets the two plots of all suites only (``--suite NAME`` draws one
# suite's): a cactus per suite of thousands of suites would take minutes and gigabytes to draw.
MAX_SUITE_PLOTS = 200


def plotted_suites(suites: Iterable[str]) -> list[str]:
    """The suites that get a cactus plot of their own: all of them, unless there are too many."""
    found = sorted(set(suites))
    return found if len(found) <= MAX_SUITE_PLOTS else []


def unplotted_note(suites: Iterable[str]) -> str:
    """Why no suite got a plot of its own ('' when each did)."""
    count = len(set(suites))
    if count <= MAX_SUITE_PLOTS:
        return ""
    return f"no plot per suite: {count} suites, more than {MAX_SUITE_PLOTS} (--suite NAME draws one suite's)"


def plot_names(suites: Sequence[str], fmt: str = "png") -> dict[str | None, str]:
    """The file name of each cactus plot (None: all suites; then each plotted suite) and of the scatter ("")."""
    names: dict[str | None, str] = {None: f"cactus.{fmt}", "": f"relevance-vs-pure.{fmt}"}
    taken = set(names.values())
    for suite in plotted_suites(suites):
        name = f"cactus-{_file_part(suite)}.{fmt}"
        if name in taken:  # two suites that differ only in characters a file name leaves out
            name = f"cactus-{_file_part(suite)}-{hashlib.sha256(suite.encode()).hexdigest()[:8]}.{fmt}"
        names[suite] = name
        taken.add(name)
    return names


def check_plot_targets(
    directory: str | os.PathLike,
    store: str | os.PathLike | None = None,
    fmt: str = "png",
    suites: Sequence[str] = (),
) -> list[Path]:
    """The plot files of ``directory``, refused (``UsageError``) where one would replace a file
    that is not a plot of ours: the results store, or the user's own ``cactus.png``."""
    if fmt not in PLOT_FORMATS:
        raise UsageError(f"unknown plot format '{fmt}' (choose from: {', '.join(PLOT_FORMATS)})")
    directory = Path(directory)
    if directory.exists() and not directory.is_dir():
        raise InputFileError("--plots names a file, not a folder", path=str(directory))
    targets = [directory / name for name in plot_names(suites, fmt).values()]
    for target in targets:
        if not os.path.lexists(target):
            continue
        if store is not None and target.exists() and os.path.samefile(target, store):
            raise UsageError(f"plot {target} would replace the results store; choose another --plots folder")
        if not _ours(target):
            raise UsageError(
                f"{target} exists and is not a plot written by relevance-plan; move it away or choose another"
                " --plots folder"
            )
    return targets


def report_figures(rows: Sequence[dict[str, Any]]) -> dict[str | None, Callable[[], Any]]:
    """How to draw each of the report's figures, keyed as ``plot_names``: the cactus of all suites (None),
    the scatter (""), then a cactus per plotted suite.  Each is drawn when called, so that one figure
    at a time is alive."""
    rows = list(rows)
    figures: dict[str | None, Callable[[], Any]] = {None: lambda: _cactus(rows), "": lambda: _scatter(rows)}
    for suite in plotted_suites(r["suite"] for r in rows):
        figures[suite] = functools.partial(_cactus, [r for r in rows if r["suite"] == suite], suite)
    return figures


def write_plots(
    rows: Sequence[dict[str, Any]],
    directory: str | os.PathLike,
    store: str | os.PathLike | None = None,
    fmt: str = "png",
    dpi: int = DEFAULT_DPI,
) -> list[Path]:
    """Write ``cactus.FMT``, ``relevance-vs-pure.FMT`` and a ``cactus-SUITE.FMT`` per suite into
    ``directory`` (created if needed).

    ``store`` (the results store the rows came from) is never overwritten.  Every figure is
    drawn before the first file is written.
    """
    require_matplotlib()
    if dpi <= 0:
        raise UsageError(f"--dpi must be a positive number of dots per inch, got {dpi}")
    rows = list(rows)
    directory = Path(directory)
    suites = sorted({r["suite"] for r in rows})
    check_plot_targets(directory, store, fmt, suites)
    names = plot_names(suites, fmt)
    drawn = {key: render(draw(), fmt, dpi) for key, draw in report_figures(rows).items()}
    try:
        directory.mkdir(parents=True, exist_ok=True)
    except OSError as error:
        raise InputFileError(f"cannot create the plot directory: {error.strerror}", path=str(directory)) from None
    return [write_bytes_atomic(directory / names[key], data) for key, data in drawn.items()]


_SVG_START = re.compile(rb"<svg[\s>]")
_SVG_IDS = re.compile(r'(\bid=")([^"]+)(")|(url\(#)([^)]+)(\))|(href="#)([^"]+)(")')


def inline_svg(data: bytes, prefix: str) -> str:
    """An SVG file's ``<svg>`` element for an HTML page: no XML prolog, its ids prefixed so that
    several figures on one page do not share one."""
    start = _SVG_START.search(data)
    text = data[start.start() if start else 0 :].decode("utf-8")

    def renamed(match: re.Match) -> str:
        groups = [g for g in match.groups() if g is not None]
        return f"{groups[0]}{prefix}-{groups[1]}{groups[2]}"

    return _SVG_IDS.sub(renamed, text)


def report_svgs(rows: Sequence[dict[str, Any]]) -> dict[str | None, str]:
    """The report's figures (keyed as ``report_figures``) as inline SVG elements."""
    require_matplotlib("SVG figures")
    return {
        key: inline_svg(render(draw(), "svg"), f"figure{index}")
        for index, (key, draw) in enumerate(report_figures(rows).items())
    }


# --------------------------------------------------------------------------- sweep


def _colour_range(metric: str, grid: list[list[float]]) -> tuple[float, float]:
    """Shares on a fixed 0-1 scale; N from 0 to its largest value (a constant panel gets a real scale)."""
    if metric != "N" and metric != "kept":
        return 0.0, 1.0
    return 0.0, max(1.0, max(max(row) for row in grid))


def text_colour(shade: float) -> str:
    """Readable text on a viridis cell at ``shade`` (0-1): viridis runs from dark purple to light yellow."""
    return "black" if shade > 0.55 else "white"


def _panel(axis, figure, result: SweepResult, grid: list[list[float]], metric: str, title: str) -> None:
    low, high = _colour_range(metric, grid)
    image = axis.imshow(grid, origin="lower", cmap="viridis", vmin=low, vmax=high)
    ticks = [f"{t:g}" for t in result.taus]
    axis.set_xticks(range(len(ticks)), ticks)
    axis.set_yticks(range(len(ticks)), ticks)
    axis.set_xlabel("tau_e")
    axis.set_ylabel("tau_c")
    axis.set_title(title)
    for i, row in enumerate(grid):
        for j, value in enumerate(row):
            colour = text_colour((value - low) / (high - low))
            axis.text(j, i, f"{value:.2f}", ha="center", va="center", color=colour, fontsize=8)
    figure.colorbar(image, ax=axis, fraction=0.046)


def _sweep_panels(result: SweepResult) -> list[tuple[str, list[list[float]], str]]:
    """(metric, grid, title) of every panel, one row of four per ground-truth table, else the kept counts."""
    panels = []
    for label, _, table in truth_tables(result):
        for metric in METRICS:
            panels.append((metric, metric_grid(result, table, metric), f"{metric} ({label})"))
    if not panels:
        panels.append(("kept", metric_grid(result, result.kept), "objects kept (after closure)"))
    return panels


def heatmap_figure(result: SweepResult):
    """The sweep's heatmaps like the paper's figure: a row of four per ground-truth table, else kept counts."""
    panels = _sweep_panels(result)
    columns = min(len(panels), len(METRICS))
    rows = -(-len(panels) // columns)
    figure = _figure(figsize=(max(4 * columns, 7), 3.75 * rows + 0.8), layout="constrained")
    axes = figure.subplots(rows, columns, squeeze=False)
    for index, (metric, grid, title) in enumerate(panels):
        _panel(axes[index // columns][index % columns], figure, result, grid, metric, title)
    caption = f"{Path(result.suite).name} — {result.problems} problems, scorer {result.scorer}"
    if result.with_truth:
        caption += f"\n{N_MEANING}"
    else:
        caption += f"\nno ground truth: objects kept of {format_count(result.objects_total)} per problem on average"
    figure.suptitle(caption)
    return figure


def write_heatmap(result: SweepResult, path: str | os.PathLike) -> Path:
    """Write ``heatmap_figure`` as a PNG (needs the 'plots' extra); returns where it wrote."""
    require_matplotlib("--heatmap")
    return _save(heatmap_figure(result), Path(path), dpi=100)
