"""The Python API: prune or plan a problem given as files or as PDDL text.

    import relevance_plan as rp

    selection = rp.prune("domain.pddl", "problem.pddl")          # what plan tries first
    print(selection.describe()["removed"], len(selection.text))  # the pruned problem, user's spelling
    result = rp.plan("domain.pddl", "problem.pddl", timeout=60)  # prune, plan, validate, widen
    if result.status is rp.PlanStatus.SOLVED:
        print(result.plan_text())

Both accept a path (``str`` or ``os.PathLike``) or the PDDL text itself for
the domain and for the problem; names keep the user's spelling in every
output.  ``prune`` takes the scoring options, ``plan`` every option of
:class:`~relevance_plan.planning.options.PlanOptions`.  Errors are the
package's own (:class:`~relevance_plan.errors.RelevancePlanError` and its
subclasses, carrying the file and line); nothing here prints or exits.
"""

from __future__ import annotations

import os
import tempfile
from pathlib import Path
from typing import Any

from relevance_plan.errors import UsageError
from relevance_plan.io import Source, is_pddl_text, load_sources
from relevance_plan.pddl.sexpr import collection_paused
from relevance_plan.planning.options import Method, PlanOptions
from relevance_plan.planning.results import PlanResult
from relevance_plan.planning.run import plan_task
from relevance_plan.progress import ProgressCallback
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.selection.prune import Selection, Thresholds
from relevance_plan.relevance.setup import ScoringOptions, score_problem


def _thresholds(options: dict[str, Any]) -> dict[str, Any]:
    if "model_task" in options:  # the name of ``activity`` until 0.12, taken for one more release
        if "activity" in options:
            raise UsageError("give activity only (model_task is its name until 0.12)")
        options["activity"] = options.pop("model_task")
    tau_class = options.pop("tau_class", None)
    tau_element = options.pop("tau_element", None)
    if tau_class is not None or tau_element is not None:
        default = Thresholds()
        options["thresholds"] = Thresholds(
            default.tau_class if tau_class is None else float(tau_class),
            default.tau_element if tau_element is None else float(tau_element),
        )
    return options


def prune(domain: Source, problem: Source, **options: Any) -> Selection:
    """The objects ``plan`` tries first, and the pruned problem (``Selection.text``).

    Options: ``scorer``, ``model_path``, ``objective``, ``activity``, ``human``,
    ``tau_class``, ``tau_element``, ``seed``, ``goal_filter``, ``prefer_free``, ``economical``.
    """
    scoring_options = ScoringOptions(**_thresholds(dict(options)))
    with collection_paused():  # one pass of the collector over the facts afterwards, not several during
        parsed_domain, parsed_problem = load_sources(domain, problem)
        domain_path = None if is_pddl_text(domain) else str(domain)
        problem_path = None if is_pddl_text(problem) else str(problem)
        task = PlanningTask(parsed_domain, parsed_problem)
        scoring = score_problem(task, scoring_options, domain_path=domain_path, problem_path=problem_path)
        return scoring.first_selection()


def plan(domain: Source, problem: Source, *, progress: ProgressCallback | None = None, **options: Any) -> PlanResult:
    """Prune, plan, validate on the original problem and widen until solved (as ``relevance-plan plan``).

    Options are the fields of :class:`PlanOptions` (``method``, ``planner``, ``planner_config``,
    ``timeout``, ``widen``, ``validators``, the scoring options...), plus ``tau_class`` and
    ``tau_element``.  Text is written to a private temporary folder for the planner, verbatim.
    ``race`` defaults as in the CLI: on for relevance with two or more usable cores.
    """
    from relevance_plan.planning.race import race_by_default

    chosen = dict(options)
    if chosen.get("race") is None:
        chosen["race"] = race_by_default(chosen.get("method", Method.RELEVANCE))
    plan_options = PlanOptions(**_thresholds(chosen))
    with tempfile.TemporaryDirectory(prefix="relevance-plan-api-") as scratch:
        domain_path = _as_file(domain, Path(scratch) / "domain.pddl")
        problem_path = _as_file(problem, Path(scratch) / "problem.pddl")
        return plan_task(domain_path, problem_path, plan_options, progress=progress)


def _as_file(source: Source, target: Path) -> str:
    if not is_pddl_text(source):
        return os.fspath(source)
    target.write_text(str(source), encoding="utf-8")
    return str(target)
