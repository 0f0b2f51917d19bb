"""Tables from the rows of a results store (the "report" step); ``plots`` draws them.

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
      without widening this is the paper's failure rate;
    - *final*: share of jobs whose final status is neither ``solved`` nor
      ``out-of-time`` (what is left after widening).
- **pure / method** (and **oracle / method**): the median time of ``pure``
  (``oracle``) on the same suite divided by the method's median time: how
  many times faster than pure the method is (above 1: faster).  The one
  direction used everywhere, shown when that suite has pure (oracle) rows.
- **objects kept**: mean objects kept / mean objects in the problem (the
  last attempt's count); **relevance (s)**: mean ``relevance_time``.
- **plan cost**: mean ``plan_cost`` of the solved jobs whose cost is known
  (the validated total-cost, or the length of a plan without action costs);
  '?' when none is (rows of a store written before costs were recorded).
- **cost / pure**: the geometric mean, over the (problem, seed) pairs that
  both the method and ``pure`` solved with a known, non-zero cost, of the
  method's cost divided by pure's (above 1: longer or costlier plans than
  pure); a pair's cost is the median of its solved rows.
- **solved**: solved jobs / jobs.
- counts print as integers ("15/48"); a mean over jobs keeps its fraction
  only when it has one ("15.5/48").
- ``n`` counts jobs: several seeds of one problem are several jobs.  Rows of
  one (suite, method) run under different options (timeout, planner config,
  thresholds, planner version) are pooled; the tables then say so.
"""

from __future__ import annotations

import csv
import io
import json
import math
import statistics
from collections.abc import Iterable, Sequence
from dataclasses import asdict, dataclass, field
from typing import Any

from relevance_plan.errors import UsageError
from relevance_plan.planning.options import METHODS, Method

FORMATS = ("markdown", "csv", "latex")
NOT_APPLICABLE = "–"
UNKNOWN = "?"

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
    pure_over_method: float | None  # median of pure / median of this method: times faster than pure
    oracle_over_method: float | None
    mean_objects_kept: float
    mean_objects_total: float
    mean_kept_fraction: float | None
    mean_relevance_time: float
    mean_plan_cost: float | None = None  # over solved jobs with a known cost
    costs_known: int = 0  # solved jobs with a known cost
    cost_over_pure: float | None = None  # geometric mean of cost(method) / cost(pure) over pairs both solved
    cost_pairs: int = 0  # the pairs that ratio is taken over
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


def _ratio(numerator: float | None, denominator: float) -> float | None:
    if numerator is None or denominator <= 0:
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


def _problem_key(row: dict[str, Any]) -> tuple:
    return (row["problem_hash"] if "problem_hash" in row else row["problem"], row["seed"])


def solved_costs(group: Sequence[dict[str, Any]]) -> dict[tuple, float]:
    """Per (problem, seed), the median known cost of its solved rows."""
    costs: dict[tuple, list[float]] = {}
    for row in group:
        if row["status"] == SOLVED and row.get("plan_cost") is not None:
            costs.setdefault(_problem_key(row), []).append(float(row["plan_cost"]))
    return {key: statistics.median(values) for key, values in costs.items()}


def cost_ratio(method: dict[tuple, float], pure: dict[tuple, float]) -> tuple[float | None, int]:
    """(geometric mean of method / pure over the shared keys with non-zero costs, how many)."""
    logs = [math.log(method[key] / pure[key]) for key in method.keys() & pure.keys() if method[key] > 0 < pure[key]]
    return (math.exp(sum(logs) / len(logs)) if logs else None), len(logs)


def suite_labels(rows: Sequence[dict[str, Any]]) -> list[str]:
    """Each row's block label: its suite, or ``SUITE [PLANNER]`` when the rows come from several planners."""
    several = len({row_planner(row) for row in rows}) > 1
    return [f"{row['suite']} [{row_planner(row)}]" if several else row["suite"] for row in rows]


def build_report(rows: Iterable[dict[str, Any]]) -> list[ReportRecord]:
    """One record per (suite, method), suites by name, methods in METHODS order.

    When the rows come from more than one planner, each planner gets its own
    block, labelled ``SUITE [PLANNER]``, so that relevance, pure and random
    are compared per planner and the ratios never mix planners.
    """
    rows = list(rows)
    labels = suite_labels(rows)
    groups: dict[tuple[str, str], list[dict[str, Any]]] = {}
    for row, suite in zip(rows, labels):
        groups.setdefault((suite, row["method"]), []).append(row)
    medians = {key: statistics.median(job_time(r) for r in group) for key, group in groups.items()}
    costs = {key: solved_costs(group) for key, group in groups.items()}
    records = []
    for suite, method in sorted(groups, key=lambda key: (key[0], _method_order(key[1]))):
        group = groups[(suite, method)]
        n = len(group)
        times = [job_time(r) for r in group]
        median = medians[(suite, method)]
        pure = method == Method.PURE
        first_failures = sum(1 for r in group if r["first_attempt_status"] != SOLVED)
        final_failures = sum(1 for r in group if r["status"] not in (SOLVED, OUT_OF_TIME))
        fractions = [r["objects_kept"] / r["objects_total"] for r in group if r["objects_total"]]
        known = [float(r["plan_cost"]) for r in group if r["status"] == SOLVED and r.get("plan_cost") is not None]
        pure_costs = costs.get((suite, Method.PURE))
        over_pure, pairs = cost_ratio(costs[(suite, method)], pure_costs) if pure_costs is not None else (None, 0)
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
                pure_over_method=_ratio(medians.get((suite, Method.PURE)), median),
                oracle_over_method=_ratio(medians.get((suite, Method.ORACLE)), median),
                mean_objects_kept=_mean([r["objects_kept"] for r in group]),
                mean_objects_total=_mean([r["objects_total"] for r in group]),
                mean_kept_fraction=_mean(fractions) if fractions else None,
                mean_relevance_time=_mean([r["relevance_time"] for r in group]),
                mean_plan_cost=_mean(known) if known else None,
                costs_known=len(known),
                cost_over_pure=over_pure,
                cost_pairs=pairs,
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
    ("pure / method (median)", "pure_over_method", "{:.2f}"),
    ("oracle / method (median)", "oracle_over_method", "{:.2f}"),
    ("plan cost", "mean_plan_cost", "{:.1f}"),
    ("cost / pure (geo. mean)", "cost_over_pure", "{:.2f}"),
    ("objects kept", "objects", ""),
    ("relevance (s)", "mean_relevance_time", "{:.3f}"),
    ("solved", "coverage", ""),
    ("n", "n", "{}"),
)


def _cell(record: ReportRecord | None, attribute: str, pattern: str) -> str:
    if record is None:
        return NOT_APPLICABLE
    if attribute == "objects":
        return f"{format_count(record.mean_objects_kept)}/{format_count(record.mean_objects_total)}"
    if attribute == "coverage":
        return f"{record.solved}/{record.n}"
    if attribute == "mean_plan_cost" and record.solved and not record.costs_known:
        return UNKNOWN
    if attribute == "cost_over_pure" and record.solved and not record.costs_known:
        return UNKNOWN
    value = getattr(record, attribute)
    return NOT_APPLICABLE if value is None else pattern.format(value)


def report_table(records: Sequence[ReportRecord]) -> tuple[list[str], list[tuple[str, list[tuple[str, list[str]]]]]]:
    """(method columns, [(suite, [(metric label, cells)])]) in the paper's shape."""
    methods = sorted({r.method for r in records}, key=_method_order)
    suites = sorted({r.suite for r in records})
    by_key = {(r.suite, r.method): r for r in records}
    blocks = []
    for suite in suites:
        present = {m for m in methods if (suite, m) in by_key}
        lines = []
        for label, attribute, pattern in _METRICS:
            if attribute in ("pure_over_method", "cost_over_pure") and Method.PURE not in present:
                continue
            if attribute == "oracle_over_method" and Method.ORACLE not in present:
                continue
            lines.append((label, [_cell(by_key.get((suite, m)), attribute, pattern) for m in methods]))
        blocks.append((suite, lines))
    return methods, blocks


def format_count(value: float) -> str:
    """A count as an integer ("15"); a mean of counts keeps one decimal only when it has one ("15.5")."""
    return f"{value:.0f}" if float(value).is_integer() else f"{value:.1f}"


def report_notes(records: Sequence[ReportRecord]) -> list[str]:
    notes = []
    if any(r.pure_over_method is not None or r.oracle_over_method is not None for r in records):
        notes.append("pure / method = median time of pure divided by the method's: times faster than pure")
    if any(r.cost_over_pure is not None for r in records):
        notes.append(
            "cost / pure = geometric mean of the method's plan cost divided by pure's, over problems both solved"
        )
    if any(r.solved and not r.costs_known for r in records):
        notes.append("? = plan cost unknown (rows stored before plan costs were recorded)")
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
    methods, blocks = report_table(records)
    lines = ["| suite | metric | " + " | ".join(methods) + " |", "|---|---|" + "---|" * len(methods)]
    for suite, rows in blocks:
        for index, (label, cells) in enumerate(rows):
            lines.append(f"| {suite if index == 0 else ''} | {label} | " + " | ".join(cells) + " |")
    lines += [""] + [f"- {note}" for note in report_notes(records)]
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
    methods, blocks = report_table(records)
    lines = [
        "% relevance-plan report; needs \\usepackage{booktabs}",
        *(f"% {_latex_escape(note)}" for note in report_notes(records)),
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
    "pure_over_method",
    "oracle_over_method",
    "mean_objects_kept",
    "mean_objects_total",
    "mean_kept_fraction",
    "mean_relevance_time",
    "mean_plan_cost",
    "cost_over_pure",
    "cost_pairs",
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


# --------------------------------------------------------------------------- one row per job

# (field, type) of the per-job rows of ``report --json`` / ``--csv``: the store's
# columns a script needs, plus the planner and validation time from the row's options and result.
JOB_FIELDS: tuple[tuple[str, type], ...] = (
    ("suite", str),
    ("problem", str),
    ("method", str),
    ("planner", str),
    ("seed", int),
    ("status", str),
    ("valid", int),
    ("wall_time", float),
    ("relevance_time", float),
    ("planner_time", float),
    ("validation_time", float),
    ("objects_kept", int),
    ("objects_total", int),
    ("attempts", int),
    ("first_attempt_status", str),
    ("plan_length", int),
    ("plan_cost", float),
    ("exit_code", int),
    ("timeout", float),
    ("world", str),
    ("difficulty", str),
    ("message", str),
    ("problem_hash", str),
    ("config_hash", str),
    ("planner_version", str),
    ("finished_at", str),
)
JOB_FORMATS = ("json", "csv")


def _validation_time(row: dict[str, Any]) -> float | None:
    try:
        value = json.loads(row.get("result_json") or "{}").get("validation_time")
    except (ValueError, AttributeError):
        return None
    return float(value) if isinstance(value, (int, float)) else None


def job_rows(rows: Iterable[dict[str, Any]]) -> list[dict[str, Any]]:
    """One plain dict per stored job (fields of ``JOB_FIELDS``), in the store's order."""
    jobs = []
    for row in rows:
        job = {name: row.get(name) for name, _ in JOB_FIELDS}
        job["planner"] = row_planner(row)
        job["validation_time"] = _validation_time(row)
        jobs.append(job)
    return jobs


def _csv_value(value: Any) -> str:
    if value is None:
        return ""
    return repr(value) if isinstance(value, float) else str(value)  # repr: reads back as the same float


def format_jobs(rows: Iterable[dict[str, Any]], fmt: str = "json") -> str:
    """The per-job rows as a JSON array or as CSV with a header (an empty field is a missing value)."""
    if fmt not in JOB_FORMATS:
        raise UsageError(f"unknown per-job format '{fmt}' (choose from: {', '.join(JOB_FORMATS)})")
    jobs = job_rows(rows)
    if fmt == "json":
        return json.dumps(jobs, indent=2, ensure_ascii=False) + "\n"
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(name for name, _ in JOB_FIELDS)
    for job in jobs:
        writer.writerow(_csv_value(job[name]) for name, _ in JOB_FIELDS)
    return buffer.getvalue()


# --------------------------------------------------------------------------- what the plots draw


def solved_times(rows: Sequence[dict[str, Any]]) -> dict[str, list[float]]:
    """Per method (in METHODS order), the sorted times of its solved jobs (a cactus plot's steps)."""
    methods = sorted({r["method"] for r in rows}, key=_method_order)
    return {
        method: sorted(job_time(r) for r in rows if r["method"] == method and r["status"] == SOLVED)
        for method in methods
    }


@dataclass(frozen=True)
class TimePair:
    """One problem and seed run by both pure and relevance (a point of the scatter plot)."""

    suite: str
    pure_time: float
    relevance_time: float
    pure_timed_out: bool
    relevance_timed_out: bool


def paired_times(rows: Sequence[dict[str, Any]]) -> list[TimePair]:
    """Pure and relevance times of every (problem, seed) that has both, medians over repeated rows."""
    grouped: dict[tuple, dict[str, list[dict]]] = {}
    for row in rows:
        if row["method"] in (Method.PURE, Method.RELEVANCE):
            key = (row["suite"], row["problem_hash"] if "problem_hash" in row else row["problem"], row["seed"])
            grouped.setdefault(key, {}).setdefault(row["method"], []).append(row)
    pairs = []
    for (suite, _, _), methods in sorted(grouped.items(), key=lambda item: tuple(map(str, item[0]))):
        if Method.PURE in methods and Method.RELEVANCE in methods:
            pure, relevance = methods[Method.PURE], methods[Method.RELEVANCE]
            pairs.append(
                TimePair(
                    suite,
                    statistics.median(job_time(r) for r in pure),
                    statistics.median(job_time(r) for r in relevance),
                    all(r["status"] == OUT_OF_TIME for r in pure),
                    all(r["status"] == OUT_OF_TIME for r in relevance),
                )
            )
    return pairs
