"""Relevance quality over a generated suite: the paper's tau_c x tau_e sweep.

Each problem is read and scored once (scores do not depend on the
thresholds); each grid cell then only thresholds and closes.  Against the
sidecar's ``relevant`` set we measure the thresholded selection (the paper's
numbers are before constraints); against ``necessary`` we measure what the
planner gets, after closure.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from relevance_plan.errors import InputFileError, UsageError
from relevance_plan.io import find_suite_problems, load_domain, load_problem
from relevance_plan.relevance.metrics import mean_metrics, set_metrics
from relevance_plan.relevance.prune import Thresholds
from relevance_plan.relevance.scorers import PlanningTask
from relevance_plan.relevance.setup import ScoringOptions, resolve_model, score_problem
from relevance_plan.relevance.sidecar import read_sidecar_for


@dataclass(frozen=True)
class SweepResult:
    suite: str
    scorer: str
    problems: int
    taus: tuple
    relevant: dict  # (tau_c, tau_e) -> SetMetrics of the selection vs `relevant`
    necessary: dict  # (tau_c, tau_e) -> SetMetrics of the kept set vs `necessary`
    insufficient: int

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
            "relevant": cells(self.relevant),
            "necessary": cells(self.necessary),
        }


def sweep_suite(suite_dir: Path, taus: Sequence[float], options: ScoringOptions = ScoringOptions()) -> SweepResult:
    """Mean precision / recall / F1 / N of every (tau_c, tau_e) cell over the suite's problems.

    Each problem is scored once with ``options`` (its thresholds are not used:
    the grid replaces them).
    """
    domain_path, problem_paths = find_suite_problems(suite_dir)
    domain = load_domain(domain_path)
    model = resolve_model(domain, str(domain_path), options.model_path)
    relevant_cells: dict = {(c, e): [] for c in taus for e in taus}
    necessary_cells: dict = {(c, e): [] for c in taus for e in taus}
    insufficient = 0
    counted = 0
    scorer = None
    for problem_path in problem_paths:
        sidecar = read_sidecar_for(problem_path, required=True)
        if sidecar.relevant is None or sidecar.necessary is None:
            raise InputFileError("sidecar lacks 'relevant' or 'necessary' lists", path=sidecar.path)
        task = PlanningTask(domain, load_problem(problem_path, domain))
        scoring = score_problem(task, options, domain_path=domain_path, problem_path=problem_path, model=model)
        scorer = scoring.scorer
        if not scoring.scores.sufficient:
            insufficient += 1
            continue
        counted += 1
        for tau_c in taus:
            for tau_e in taus:
                result = scoring.prune(Thresholds(tau_c, tau_e))
                relevant_cells[(tau_c, tau_e)].append(set_metrics(result.selected, sidecar.relevant))
                necessary_cells[(tau_c, tau_e)].append(set_metrics(result.kept, sidecar.necessary))
    if counted == 0:
        raise UsageError(f"no problem in {suite_dir} could be scored (insufficient cues on all {insufficient})")
    return SweepResult(
        suite=str(suite_dir),
        scorer=scorer,
        problems=counted,
        taus=tuple(taus),
        relevant={key: mean_metrics(values) for key, values in relevant_cells.items()},
        necessary={key: mean_metrics(values) for key, values in necessary_cells.items()},
        insufficient=insufficient,
    )


def format_sweep(result: SweepResult) -> str:
    lines = [
        f"suite {result.suite}: {result.problems} problems, scorer {result.scorer}"
        + (f", {result.insufficient} with insufficient cues (skipped)" if result.insufficient else "")
    ]
    for title, table in (
        ("selection vs relevant (before closure)", result.relevant),
        ("kept vs necessary (after closure)", result.necessary),
    ):
        for metric in ("precision", "recall", "f1", "N"):
            lines.append("")
            lines.append(f"{metric} — {title}; rows tau_c, columns tau_e")
            lines.append("tau_c\\tau_e " + " ".join(f"{e:>6.2f}" for e in result.taus))
            for c in result.taus:
                cells = " ".join(f"{table[(c, e)].as_dict()[metric]:6.2f}" for e in result.taus)
                lines.append(f"{c:>11.2f} {cells}")
    return "\n".join(lines)


def write_heatmap(result: SweepResult, path: str) -> None:
    """Eight heatmaps like the paper's figure (needs the 'plots' extra)."""
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        raise UsageError("--heatmap needs matplotlib: pip install 'relevance-plan[plots]'") from None
    import numpy as np

    from relevance_plan.io import write_bytes_atomic

    figure, axes = plt.subplots(2, 4, figsize=(16, 7.5))
    for row, (label, table) in enumerate((("relevant", result.relevant), ("necessary", result.necessary))):
        for column, metric in enumerate(("recall", "precision", "f1", "N")):
            grid = np.array([[table[(c, e)].as_dict()[metric] for e in result.taus] for c in result.taus])
            axis = axes[row][column]
            image = axis.imshow(grid, origin="lower", cmap="viridis")
            axis.set_xticks(range(len(result.taus)), [f"{t:g}" for t in result.taus])
            axis.set_yticks(range(len(result.taus)), [f"{t:g}" for t in result.taus])
            axis.set_xlabel("tau_e")
            axis.set_ylabel("tau_c")
            axis.set_title(f"{metric} ({label})")
            for i in range(len(result.taus)):
                for j in range(len(result.taus)):
                    axis.text(j, i, f"{grid[i, j]:.2f}", ha="center", va="center", color="white", fontsize=8)
            figure.colorbar(image, ax=axis, fraction=0.046)
    figure.suptitle(f"{result.suite} — {result.problems} problems, scorer {result.scorer}")
    figure.tight_layout()
    import io as _io

    buffer = _io.BytesIO()
    figure.savefig(buffer, format="png", dpi=100)
    plt.close(figure)
    write_bytes_atomic(path, buffer.getvalue())
