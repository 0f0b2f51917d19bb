"""Tables and figures from the rows of a results store (the "report" step).

Conventions (all numbers are computed from stored rows only):

- **time** of a job: its whole wall time as stored (``wall_time``: reading
  the problem, relevance scoring and pruning, every planner attempt and plan
  validation; i.e. relevance + planning as in the paper), except that a job
  with status ``out-of-time`` counts at its timeout value.  Mean and median
  are taken over ALL jobs of a (suite, method), failures included (they count
  at their measured time).
- **timeout rate**: share of jobs with status ``out-of-time``.
- **failure rate** (the paper's meaning: no valid plan from the pruned
  problem); not applicable to ``pure`` (shown as '–'):
    - *first attempt*: share of jobs whose first attempt was not ``solved``
      (includes a first attempt that ran out of its share of the time, and
      jobs that never reached the planner: input errors, insufficient cues);
      without relaxation this is the paper's failure rate;
    - *final*: share of jobs whose final status is neither ``solved`` nor
      ``out-of-time`` (what is left after relaxation).
- **× pure / × oracle**: median time of the method divided by the median
  time of ``pure`` (``oracle``) on the same suite, when that method was run.
- **objects kept**: mean objects kept / mean objects in the problem (the
  last attempt's count); **relevance (s)**: mean ``relevance_time``.
- ``n`` counts jobs: several seeds of one problem are several jobs.  Rows of
  one (suite, method) run under different options (timeout, planner config,
  thresholds, planner version) are pooled; the tables then say so.
"""

from __future__ import annotations

import csv
import io
import json
import os
import statistics
from collections.abc import Iterable, Sequence
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

from relevance_plan.errors import InputFileError, UsageError
from relevance_plan.planning.loop import METHODS

FORMATS = ("markdown", "csv", "latex")
NOT_APPLICABLE = "–"
PLOTS_INSTALL_HINT = "pip install 'relevance-plan[plots]'"

SOLVED = "solved"
OUT_OF_TIME = "out-of-time"


@dataclass(frozen=True)
class ReportRecord:
    suite: str
    method: str
    n: int
    solved: int
    mean_time: float
    median_time: float
    timeout_rate: float
    first_failure_rate: float | None  # None for pure
    failure_rate: float | None  # None for pure
    ratio_to_pure: float | None
    ratio_to_oracle: float | None
    mean_objects_kept: float
    mean_objects_total: float
    mean_kept_fraction: float | None
    mean_relevance_time: float
    configs: int = 1  # distinct (config_hash, planner_version) pooled in this record
    timeouts: tuple = field(default=())  # distinct timeout values

    def to_json(self) -> dict[str, Any]:
        data = asdict(self)
        data["timeouts"] = list(self.timeouts)
        return data


def job_time(row: dict[str, Any]) -> float:
    """A job's time for the tables: its wall time, or its timeout if it ran out of time."""
    if row["status"] == OUT_OF_TIME:
        return float(row["timeout"])
    return float(row["wall_time"])


def _method_order(method: str) -> tuple[int, str]:
    return (METHODS.index(method) if method in METHODS else len(METHODS), method)


def _mean(values: Sequence[float]) -> float:
    return sum(values) / len(values) if values else 0.0


def _share(count: int, total: int) -> float:
    return count / total if total else 0.0


def _ratio(numerator: float, denominator: float | None) -> float | None:
    if denominator is None or denominator <= 0:
        return None
    return numerator / denominator


def _option_set(row: dict[str, Any]) -> tuple:
    """The row's options without per-problem parts (the oracle's sidecar digest)."""
    try:
        config = json.loads(row.get("config_json") or "{}")
    except ValueError:
        config = {}
    config.pop("sidecar_hash", None)
    return (json.dumps(config, sort_keys=True), row.get("planner_version"))


def row_planner(row: dict[str, Any]) -> str:
    """The planner a row ran (rows stored before planners were chosen ran Fast Downward)."""
    try:
        config = json.loads(row.get("config_json") or "{}")
    except ValueError:
        config = {}
    planner = config.get("planner")
    return planner if isinstance(planner, str) else "fast-downward"


def build_report(rows: Iterable[dict[str, Any]]) -> list[ReportRecord]:
    """One record per (suite, method), suites by name, methods in METHODS order.

    When the rows come from more than one planner, each planner gets its own
    block, labelled ``SUITE [PLANNER]``, so that relevance, pure and random
    are compared per planner and the ratios never mix planners.
    """
    rows = list(rows)
    several = len({row_planner(row) for row in rows}) > 1
    groups: dict[tuple[str, str], list[dict[str, Any]]] = {}
    for row in rows:
        suite = f"{row['suite']} [{row_planner(row)}]" if several else row["suite"]
        groups.setdefault((suite, row["method"]), []).append(row)
    medians = {key: statistics.median(job_time(r) for r in group) for key, group in groups.items()}
    records = []
    for suite, method in sorted(groups, key=lambda key: (key[0], _method_order(key[1]))):
        group = groups[(suite, method)]
        n = len(group)
        times = [job_time(r) for r in group]
        median = medians[(suite, method)]
        pure = method == "pure"
        first_failures = sum(1 for r in group if r["first_attempt_status"] != SOLVED)
        final_failures = sum(1 for r in group if r["status"] not in (SOLVED, OUT_OF_TIME))
        fractions = [r["objects_kept"] / r["objects_total"] for r in group if r["objects_total"]]
        records.append(
            ReportRecord(
                suite=suite,
                method=method,
                n=n,
                solved=sum(1 for r in group if r["status"] == SOLVED),
                mean_time=_mean(times),
                median_time=median,
                timeout_rate=_share(sum(1 for r in group if r["status"] == OUT_OF_TIME), n),
                first_failure_rate=None if pure else _share(first_failures, n),
                failure_rate=None if pure else _share(final_failures, n),
                ratio_to_pure=_ratio(median, medians.get((suite, "pure"))),
                ratio_to_oracle=_ratio(median, medians.get((suite, "oracle"))),
                mean_objects_kept=_mean([r["objects_kept"] for r in group]),
                mean_objects_total=_mean([r["objects_total"] for r in group]),
                mean_kept_fraction=_mean(fractions) if fractions else None,
                mean_relevance_time=_mean([r["relevance_time"] for r in group]),
                configs=len({_option_set(r) for r in group}),
                timeouts=tuple(sorted({float(r["timeout"]) for r in group})),
            )
        )
    return records


# --------------------------------------------------------------------------- tables

# (label, attribute, format) of the per-suite metric rows; ratio rows appear only
# when the suite has pure / oracle results.
_METRICS: tuple[tuple[str, str, str], ...] = (
    ("time (s)", "mean_time", "{:.2f}"),
    ("median (s)", "median_time", "{:.2f}"),
    ("timeout", "timeout_rate", "{:.2f}"),
    ("fail (first attempt)", "first_failure_rate", "{:.2f}"),
    ("fail (final)", "failure_rate", "{:.2f}"),
    ("median × pure", "ratio_to_pure", "{:.2f}"),
    ("median × oracle", "ratio_to_oracle", "{:.2f}"),
    ("objects kept", "objects", ""),
    ("relevance (s)", "mean_relevance_time", "{:.3f}"),
    ("n", "n", "{}"),
)


def _cell(record: ReportRecord | None, attribute: str, pattern: str) -> str:
    if record is None:
        return NOT_APPLICABLE
    if attribute == "objects":
        return f"{record.mean_objects_kept:.1f}/{record.mean_objects_total:.1f}"
    value = getattr(record, attribute)
    return NOT_APPLICABLE if value is None else pattern.format(value)


def _table(records: Sequence[ReportRecord]) -> tuple[list[str], list[tuple[str, list[tuple[str, list[str]]]]]]:
    """(method columns, [(suite, [(metric label, cells)])]) in the paper's shape."""
    methods = sorted({r.method for r in records}, key=_method_order)
    suites = sorted({r.suite for r in records})
    by_key = {(r.suite, r.method): r for r in records}
    blocks = []
    for suite in suites:
        present = {m for m in methods if (suite, m) in by_key}
        lines = []
        for label, attribute, pattern in _METRICS:
            if attribute == "ratio_to_pure" and "pure" not in present:
                continue
            if attribute == "ratio_to_oracle" and "oracle" not in present:
                continue
            lines.append((label, [_cell(by_key.get((suite, m)), attribute, pattern) for m in methods]))
        blocks.append((suite, lines))
    return methods, blocks


def _notes(records: Sequence[ReportRecord]) -> list[str]:
    notes = []
    timeouts = sorted({t for r in records for t in r.timeouts})
    if timeouts:
        shown = ", ".join(f"{t:g}" for t in timeouts)
        notes.append(
            f"time = relevance + planning (+ validation) per job, out-of-time jobs counted at the timeout ({shown} s)"
        )
    for r in records:
        if r.configs > 1:
            notes.append(f"{r.suite} / {r.method} pools {r.configs} different option sets or planner versions")
    return notes


def _markdown(records: Sequence[ReportRecord]) -> str:
    methods, blocks = _table(records)
    lines = ["| suite | metric | " + " | ".join(methods) + " |", "|---|---|" + "---|" * len(methods)]
    for suite, rows in blocks:
        for index, (label, cells) in enumerate(rows):
            lines.append(f"| {suite if index == 0 else ''} | {label} | " + " | ".join(cells) + " |")
    lines += [""] + [f"- {note}" for note in _notes(records)]
    return "\n".join(lines).rstrip() + "\n"


_LATEX_SPECIALS = {
    "\\": r"\textbackslash{}",
    "&": r"\&",
    "%": r"\%",
    "$": r"\$",
    "#": r"\#",
    "_": r"\_",
    "{": r"\{",
    "}": r"\}",
    "~": r"\textasciitilde{}",
    "^": r"\textasciicircum{}",
    NOT_APPLICABLE: "--",
    "×": r"$\times$",
}


def _latex_escape(text: str) -> str:
    return "".join(_LATEX_SPECIALS.get(char, char) for char in text)


def _latex(records: Sequence[ReportRecord]) -> str:
    methods, blocks = _table(records)
    lines = [
        "% relevance-plan report; needs \\usepackage{booktabs}",
        *(f"% {_latex_escape(note)}" for note in _notes(records)),
        "\\begin{tabular}{ll" + "r" * len(methods) + "}",
        "\\toprule",
        "world & metric & " + " & ".join(_latex_escape(m) for m in methods) + " \\\\",
    ]
    for suite, rows in blocks:
        lines.append("\\midrule")
        for index, (label, cells) in enumerate(rows):
            first = _latex_escape(suite) if index == 0 else ""
            lines.append(f"{first} & {_latex_escape(label)} & " + " & ".join(_latex_escape(c) for c in cells) + " \\\\")
    lines += ["\\bottomrule", "\\end{tabular}"]
    return "\n".join(lines) + "\n"


CSV_FIELDS = (
    "suite",
    "method",
    "n",
    "solved",
    "mean_time",
    "median_time",
    "timeout_rate",
    "first_failure_rate",
    "failure_rate",
    "ratio_to_pure",
    "ratio_to_oracle",
    "mean_objects_kept",
    "mean_objects_total",
    "mean_kept_fraction",
    "mean_relevance_time",
    "configs",
)


def _csv(records: Sequence[ReportRecord]) -> str:
    """One line per (suite, method) with every number; not applicable = empty field."""
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(CSV_FIELDS)
    for record in records:
        values = []
        for name in CSV_FIELDS:
            value = getattr(record, name)
            if value is None:
                values.append("")
            elif isinstance(value, float):
                values.append(f"{value:.6g}")
            else:
                values.append(value)
        writer.writerow(values)
    return buffer.getvalue()


def format_report(records: Sequence[ReportRecord], fmt: str = "markdown") -> str:
    """The table as markdown or LaTeX (the paper's shape: per suite, rows time /
    timeout / fail and the extra metrics, one column per method) or CSV (one
    line per suite and method)."""
    if fmt not in FORMATS:
        raise UsageError(f"unknown report format '{fmt}' (choose from: {', '.join(FORMATS)})")
    if fmt == "csv":
        return _csv(records)
    if not records:
        return "no results\n" if fmt == "markdown" else "% no results\n"
    return _markdown(records) if fmt == "markdown" else _latex(records)


# --------------------------------------------------------------------------- plots


def _figure_classes():
    try:
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.figure import Figure
    except ImportError:
        raise UsageError(f"plots need matplotlib: {PLOTS_INSTALL_HINT}") from None
    return Figure, FigureCanvasAgg


def _save(figure, canvas_class, path: Path) -> Path:
    from relevance_plan.io import write_bytes_atomic

    canvas_class(figure)
    buffer = io.BytesIO()
    figure.savefig(buffer, format="png", dpi=120)
    return write_bytes_atomic(path, buffer.getvalue())


def _cactus(rows: Sequence[dict[str, Any]], Figure):
    figure = Figure(figsize=(6.4, 4.4), layout="constrained")
    axes = figure.add_subplot()
    methods = sorted({r["method"] for r in rows}, key=_method_order)
    for method in methods:
        times = sorted(job_time(r) for r in rows if r["method"] == method and r["status"] == SOLVED)
        if times:
            # Start at zero solved so that even one solved problem shows a step.
            axes.step([times[0], *times], range(len(times) + 1), where="post", label=f"{method} ({len(times)})")
        else:
            axes.plot([], [], label=f"{method} (0)")
    from matplotlib.ticker import MaxNLocator

    axes.set_xscale("log")
    axes.set_ylim(bottom=0)
    axes.yaxis.set_major_locator(MaxNLocator(integer=True))
    axes.set_xlabel("time per problem (s): relevance + planning")
    axes.set_ylabel("problems solved")
    axes.set_title("Solved problems within a time (all suites)")
    axes.grid(True, which="both", alpha=0.3)
    axes.legend()
    return figure


def _pairs(rows: Sequence[dict[str, Any]]) -> list[tuple[str, float, float, bool, bool]]:
    """(suite, pure time, relevance time, pure timed out, relevance timed out) per problem and seed."""
    grouped: dict[tuple, dict[str, list[dict]]] = {}
    for row in rows:
        if row["method"] in ("pure", "relevance"):
            key = (row["suite"], row["problem_hash"] if "problem_hash" in row else row["problem"], row["seed"])
            grouped.setdefault(key, {}).setdefault(row["method"], []).append(row)
    pairs = []
    for (suite, _, _), methods in sorted(grouped.items(), key=lambda item: tuple(map(str, item[0]))):
        if "pure" in methods and "relevance" in methods:
            pure, relevance = methods["pure"], methods["relevance"]
            pairs.append(
                (
                    suite,
                    statistics.median(job_time(r) for r in pure),
                    statistics.median(job_time(r) for r in relevance),
                    all(r["status"] == OUT_OF_TIME for r in pure),
                    all(r["status"] == OUT_OF_TIME for r in relevance),
                )
            )
    return pairs


def _scatter(rows: Sequence[dict[str, Any]], Figure):
    figure = Figure(figsize=(5.2, 5.2), layout="constrained")
    axes = figure.add_subplot()
    pairs = _pairs(rows)
    timeout = max((float(r["timeout"]) for r in rows), default=1.0)
    if pairs:
        for suite in sorted({p[0] for p in pairs}):
            mine = [p for p in pairs if p[0] == suite]
            axes.scatter([p[1] for p in mine], [p[2] for p in mine], label=suite, alpha=0.8, s=24)
        low = max(min(min(p[1], p[2]) for p in pairs) / 2, 1e-3)
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
        axes.text(
            0.5,
            0.5,
            "no problem has both relevance and pure results",
            ha="center",
            va="center",
            transform=axes.transAxes,
        )
    axes.set_xlabel("pure planning time (s)")
    axes.set_ylabel("relevance time (s): relevance + planning")
    axes.set_title("Per problem: relevance vs pure")
    axes.grid(True, which="both", alpha=0.3)
    return figure


def write_plots(rows: Sequence[dict[str, Any]], directory: str | os.PathLike) -> list[Path]:
    """Write ``cactus.png`` and ``relevance-vs-pure.png`` into ``directory`` (created if needed)."""
    Figure, canvas = _figure_classes()
    directory = Path(directory)
    try:
        directory.mkdir(parents=True, exist_ok=True)
    except OSError as error:
        raise InputFileError(f"cannot create the plot directory: {error.strerror}", path=str(directory)) from None
    rows = list(rows)
    return [
        _save(_cactus(rows, Figure), canvas, directory / "cactus.png"),
        _save(_scatter(rows, Figure), canvas, directory / "relevance-vs-pure.png"),
    ]
