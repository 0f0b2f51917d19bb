"""Relevance quality over a suite: the paper's tau_c x tau_e sweep.

Each problem is read and scored once (scores do not depend on the
thresholds); each grid cell then only thresholds and closes.  Every suite
gives the objects kept per cell and the time taken; where the generator's
sidecar gives the ground truth, the selection is also measured against its
``relevant`` set (the paper's numbers are before constraints) and what the
planner gets, after closure, against ``necessary``.
"""

from __future__ import annotations

import time
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path

from relevance_plan.batch.report import format_count
from relevance_plan.batch.suites import SuiteProblem, find_suite_problems
from relevance_plan.errors import InputFileError, UsageError
from relevance_plan.io import load_domain, load_problem
from relevance_plan.pddl.model import Domain
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.scoring.knowledge import KnowledgeModel
from relevance_plan.relevance.scoring.metrics import SetMetrics, mean_metrics, set_metrics
from relevance_plan.relevance.selection.prune import Thresholds
from relevance_plan.relevance.setup import ScoringOptions, resolve_knowledge_model, score_problem
from relevance_plan.sidecar import read_sidecar_for

METRICS = ("recall", "precision", "f1", "N")
N_MEANING = "N = objects chosen / objects in the ground truth (1 = the right number)"


@dataclass(frozen=True)
class SweepResult:
    suite: str
    scorer: str
    problems: int  # problems scored (insufficient cues excluded)
    taus: tuple
    relevant: dict  # (tau_c, tau_e) -> SetMetrics of the selection vs `relevant`; empty without ground truth
    necessary: dict  # (tau_c, tau_e) -> SetMetrics of the kept set vs `necessary`; empty without ground truth
    insufficient: int
    with_truth: int = 0  # problems whose sidecar gives `relevant` and `necessary` (the metrics' problems)
    kept: dict = field(default_factory=dict)  # (tau_c, tau_e) -> mean objects kept after closure
    objects_total: float = 0.0  # mean objects per problem
    scoring_time: float = 0.0  # mean seconds to read and score one problem
    cell_time: float = 0.0  # mean seconds to threshold and close one problem at one cell

    def to_json(self) -> dict:
        def cells(table):
            return [
                {"tau_class": c, "tau_element": e, **{k: round(v, 4) for k, v in m.as_dict().items()}}
                for (c, e), m in sorted(table.items())
            ]

        return {
            "suite": self.suite,
            "scorer": self.scorer,
            "problems": self.problems,
            "insufficient": self.insufficient,
            "with_truth": self.with_truth,
            "relevant": cells(self.relevant),
            "necessary": cells(self.necessary),
            "objects_total": round(self.objects_total, 4),
            "kept": [
                {"tau_class": c, "tau_element": e, "objects_kept": round(v, 4)}
                for (c, e), v in sorted(self.kept.items())
            ],
            "scoring_time": round(self.scoring_time, 6),
            "cell_time": round(self.cell_time, 6),
        }


@dataclass
class _Tally:
    """What the problems of a sweep add up to, cell by cell."""

    taus: Sequence[float]
    relevant: dict = field(default_factory=dict)
    necessary: dict = field(default_factory=dict)
    kept: dict = field(default_factory=dict)
    totals: list = field(default_factory=list)
    scoring_times: list = field(default_factory=list)
    cell_times: list = field(default_factory=list)
    insufficient: int = 0
    with_truth: int = 0
    scorer: str | None = None

    def cells(self) -> list[tuple[float, float]]:
        return [(c, e) for c in self.taus for e in self.taus]


def _truth(problem_path: Path) -> tuple[frozenset, frozenset] | None:
    """(relevant, necessary) from the problem's sidecar; None without one (a malformed one raises)."""
    sidecar = read_sidecar_for(problem_path)
    if sidecar is None or sidecar.relevant is None or sidecar.necessary is None:
        return None
    return sidecar.relevant, sidecar.necessary


def _sweep_problem(entry: SuiteProblem, domain: Domain, model, options: ScoringOptions, tally: _Tally) -> None:
    started = time.perf_counter()
    truth = _truth(entry.problem)
    task = PlanningTask(domain, load_problem(entry.problem, domain))
    scoring = score_problem(task, options, domain_path=entry.domain, problem_path=entry.problem, knowledge_model=model)
    tally.scoring_times.append(time.perf_counter() - started)
    tally.scorer = scoring.scorer
    if not scoring.scores.sufficient:
        tally.insufficient += 1
        return
    tally.totals.append(len(task.problem.objects))
    tally.with_truth += truth is not None
    started = time.perf_counter()
    for cell in tally.cells():
        result = scoring.prune(Thresholds(*cell))
        tally.kept.setdefault(cell, []).append(len(result.kept))
        if truth is not None:
            tally.relevant.setdefault(cell, []).append(set_metrics(result.selected, truth[0]))
            tally.necessary.setdefault(cell, []).append(set_metrics(result.kept, truth[1]))
    tally.cell_times.append((time.perf_counter() - started) / len(tally.cells()))


def _mean(values: Sequence[float]) -> float:
    return sum(values) / len(values) if values else 0.0


def sweep_suite(suite_dir: Path, taus: Sequence[float], options: ScoringOptions = ScoringOptions()) -> SweepResult:
    """Objects kept, timing and (with ground truth) mean precision / recall / F1 / N of every
    (tau_c, tau_e) cell over the suite's problems, in any layout ``compare`` reads.

    Each problem is scored once with ``options`` (its thresholds are not used:
    the grid replaces them).  A problem without a domain or that is not a
    regular file raises ``InputFileError``.
    """
    tally = _Tally(taus)
    domains: dict[Path, tuple[Domain, KnowledgeModel | None]] = {}
    for entry in find_suite_problems(suite_dir):
        if entry.error is not None or entry.domain is None:
            raise InputFileError(entry.error or "no domain file found for this problem", path=str(entry.problem))
        if entry.domain not in domains:
            domain = load_domain(entry.domain)
            domains[entry.domain] = (domain, resolve_knowledge_model(domain, str(entry.domain), options.model_path))
        _sweep_problem(entry, *domains[entry.domain], options, tally)
    if not tally.totals:
        raise UsageError(f"no problem in {suite_dir} could be scored (insufficient cues on all {tally.insufficient})")
    assert tally.scorer is not None  # set by the first problem scored
    return SweepResult(
        suite=str(suite_dir),
        scorer=tally.scorer,
        problems=len(tally.totals),
        taus=tuple(taus),
        relevant={cell: mean_metrics(values) for cell, values in tally.relevant.items()},
        necessary={cell: mean_metrics(values) for cell, values in tally.necessary.items()},
        insufficient=tally.insufficient,
        with_truth=tally.with_truth,
        kept={cell: _mean(values) for cell, values in tally.kept.items()},
        objects_total=_mean(tally.totals),
        scoring_time=_mean(tally.scoring_times),
        cell_time=_mean(tally.cell_times),
    )


def truth_tables(result: SweepResult) -> list[tuple[str, str, dict[tuple, SetMetrics]]]:
    """(short label, title, table) of each ground-truth comparison the result has."""
    tables = [
        ("relevant", "selection vs relevant (before closure)", result.relevant),
        ("necessary", "kept vs necessary (after closure)", result.necessary),
    ]
    return [entry for entry in tables if entry[2]]


def metric_grid(result: SweepResult, table: dict, metric: str | None = None) -> list[list[float]]:
    """Rows tau_c, columns tau_e of ``table`` (of one metric of a table of SetMetrics)."""
    return [[table[(c, e)].as_dict()[metric] if metric else table[(c, e)] for e in result.taus] for c in result.taus]


def _grid(result: SweepResult, grid: list[list[float]]) -> list[str]:
    lines = ["tau_c\\tau_e " + " ".join(f"{e:>6.2f}" for e in result.taus)]
    for c, row in zip(result.taus, grid):
        lines.append(f"{c:>11.2f} " + " ".join(f"{value:6.2f}" for value in row))
    return lines


def format_sweep(result: SweepResult) -> str:
    truth = (
        f"ground truth on {result.with_truth}"
        if result.with_truth
        else "no ground truth (no sidecars with 'relevant' and 'necessary'): objects kept and timing only"
    )
    lines = [
        f"suite {result.suite}: {result.problems} problems, scorer {result.scorer}, {truth}"
        + (f", {result.insufficient} with insufficient cues (skipped)" if result.insufficient else "")
    ]
    for _, title, table in truth_tables(result):
        for metric in METRICS:
            lines += ["", f"{metric} — {title}; rows tau_c, columns tau_e"]
            lines += _grid(result, metric_grid(result, table, metric))
    if result.with_truth:
        lines += ["", N_MEANING]
    mean = format_count(result.objects_total)
    lines += ["", f"objects kept (after closure) of {mean} on average; rows tau_c, columns tau_e"]
    lines += _grid(result, metric_grid(result, result.kept))
    lines += [
        "",
        f"time: {result.scoring_time:.3f} s per problem to read and score, "
        f"{result.cell_time * 1000:.2f} ms per problem and cell to threshold and close",
    ]
    return "\n".join(lines)
