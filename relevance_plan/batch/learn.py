"""Learning per-object relevance from solved problems (``relevance-plan learn``).

Each training problem is solved on the full problem (Fast Downward by default,
within a per-problem limit), the plan validated on it, and its objects
labelled:

* ``plan``: the objects the plan names, the goal's, and what closure puts
  back for them (as the pruner would).  One planner run per problem.
* ``minimal``: PLOI's greedy minimal sufficient set, started from the plan's
  set: drop one object (with what closure then no longer needs), plan on
  what is left, and keep it dropped when a plan valid on the original problem
  is still found.  One planner run per labelled object.

Then a logistic model is fitted on the objects' features
(``relevance.scoring.learning.fit``).  ``learn_from_store`` takes the solved runs of
a results store instead of planning again.
"""

from __future__ import annotations

import json
import os
import random
import tempfile
import time
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass, replace
from pathlib import Path

from relevance_plan.errors import DomainMismatchError, PlanFormatError, UsageError
from relevance_plan.io import load_domain, load_problem, write_text_atomic
from relevance_plan.pddl.model import Domain, Problem
from relevance_plan.pddl.plans import Plan
from relevance_plan.planning.planners.base import PlannerStatus, RunOutcome
from relevance_plan.planning.planners.registry import DEFAULT_PLANNER_CONFIG, make_planner
from relevance_plan.planning.validation import validate_plan
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.scoring.learning.features import FeatureConfig, object_features
from relevance_plan.relevance.scoring.learning.fit import LabelledProblem, fit_learned_model, with_hubs
from relevance_plan.relevance.scoring.learning.learned_model import LearnedModel
from relevance_plan.relevance.scoring.scorers import ScoreResult
from relevance_plan.relevance.selection.prune import prune_with_scores

LABEL_KINDS = ("plan", "minimal")
DEFAULT_LABELS = "plan"


@dataclass
class LearnReport:
    model: LearnedModel
    problems: list[LabelledProblem]
    skipped: list[tuple[str, str]]  # (problem, why it was not used)
    seconds: float


Say = Callable[[str], None]


def _check_labels(labels: str) -> None:
    if labels not in LABEL_KINDS:
        raise UsageError(f"unknown label kind '{labels}' (choose from: {', '.join(LABEL_KINDS)})")


def _quiet(message: str) -> None:
    pass


def plan_objects(task: PlanningTask, plan: Plan) -> frozenset[str]:
    """The objects a plan names, the goal's, and what closure puts back for them (the ``plan`` labels)."""
    named = {arg for step in plan for arg in step.args if arg in task.problem.objects} | task.pinned_objects
    return closed(task, named)


def closed(task: PlanningTask, names: Iterable[str]) -> frozenset[str]:
    """``names`` with what the pruner's closure puts back for them."""
    chosen = frozenset(names)
    scores = ScoreResult("labels", {name: 1.0 if name in chosen else 0.0 for name in task.problem.objects})
    return prune_with_scores(task, scores).kept


@dataclass(frozen=True)
class TrainingPlanner:
    """The planner that solves the training problems (a registry name) and its configuration."""

    name: str = "fast-downward"
    config: str = DEFAULT_PLANNER_CONFIG


class Solver:
    """Solves a problem (or a subset of its objects) and validates the plan on the original problem."""

    def __init__(self, domain_path: str, planner: TrainingPlanner, time_limit: float, scratch: str):
        self.domain_path = domain_path
        self.planner = make_planner(planner.name, planner.config)
        self.time_limit = time_limit
        self.scratch = scratch
        self.runs = 0

    def solve(self, task: PlanningTask, problem_path: str, kept: frozenset[str] | None = None) -> Plan | str:
        """A plan of the problem (of ``kept`` only, when given), valid on the original problem; or why
        there is none."""
        target = problem_path
        if kept is not None:
            from relevance_plan.pddl.writer import write_pruned_problem

            self.runs += 1
            target = str(
                write_text_atomic(
                    Path(self.scratch) / f"subset-{self.runs}.pddl", write_pruned_problem(task.problem, kept)
                )
            )
        outcome = self.planner.run(self.domain_path, target, time_limit=self.time_limit, memory_limit_mb=None)
        if outcome.status is not PlannerStatus.SOLVED:
            return self.unsolved(outcome)
        validation = validate_plan(task.domain, task.problem, outcome.plan, None, time.monotonic() + self.time_limit)
        return outcome.plan if validation.accepted else f"its plan is not valid ({validation.message})"

    def unsolved(self, outcome: RunOutcome) -> str:
        """Why a run gave no plan, in the planner's verdict: a proof that there is none is not a timeout."""
        if outcome.status is PlannerStatus.UNSOLVABLE:
            return "unsolvable (the planner proved it has no plan)"
        if outcome.status is PlannerStatus.OUT_OF_TIME:
            return f"not solved within {self.time_limit:g} s"
        return f"not solved: {outcome.status.value}" + (f" ({outcome.reason})" if outcome.reason else "")


def minimal_objects(
    task: PlanningTask, problem_path: str, start: frozenset[str], solver: Solver, seed: int
) -> frozenset[str]:
    """PLOI's greedy minimal sufficient set, from a sufficient ``start``: each object in turn
    (seeded order) is dropped when the rest, closed, still plans."""
    current = start
    order = sorted(start - task.pinned_objects)
    random.Random(seed).shuffle(order)
    for name in order:
        if name not in current:
            continue
        trial = closed(task, current - {name})
        if name in trial:
            continue  # closure puts it back: the pruner could not drop it either
        if isinstance(solver.solve(task, problem_path, trial), Plan):
            current = trial
    return current


def _labelled(
    task: PlanningTask,
    positives: frozenset[str],
    config: FeatureConfig,
    started: float,
    runs: int,
) -> LabelledProblem:
    features = object_features(task, config)
    return LabelledProblem(
        task.problem.path or "",
        len(task.problem.objects),
        positives,
        dict(features.vectors),
        time.perf_counter() - started,
        runs,
        frozenset(t for types in features.types.values() for t in types),
        frozenset(p for predicates in features.predicates.values() for p in predicates),
    )


def label_problem(
    domain: Domain,
    problem_path: str,
    solver: Solver,
    labels: str,
    config: FeatureConfig,
    seed: int,
) -> LabelledProblem | str:
    """The problem's labelled objects, or why it cannot be used."""
    started = time.perf_counter()
    task = PlanningTask(domain, load_problem(problem_path, domain))
    runs_before = solver.runs
    plan = solver.solve(task, problem_path)
    if isinstance(plan, str):
        return plan
    positives = plan_objects(task, plan)
    if labels == "minimal":
        positives = minimal_objects(task, problem_path, positives, solver, seed)
    return _labelled(task, positives, config, started, 1 + solver.runs - runs_before)


def learn(
    domain_path: str | os.PathLike[str],
    problem_paths: Sequence[str | os.PathLike[str]],
    *,
    time_limit: float = 60.0,
    labels: str = DEFAULT_LABELS,
    seed: int = 0,
    planner: TrainingPlanner = TrainingPlanner(),
    config: FeatureConfig = FeatureConfig(),
    say: Say = _quiet,
) -> LearnReport:
    """Solve and label each training problem, then fit a model (see the module's docstring)."""
    _check_labels(labels)
    if not problem_paths:
        raise UsageError("learn needs at least one training problem")
    started = time.perf_counter()
    domain = load_domain(domain_path)
    # all read before any planning: another domain's problem stops the run at once
    config = with_hubs(config, domain, [_check_domain(domain, path) for path in problem_paths])
    labelled: list[LabelledProblem] = []
    skipped: list[tuple[str, str]] = []
    with tempfile.TemporaryDirectory(prefix="relevance-plan-learn-") as scratch:
        solver = Solver(os.fspath(domain_path), planner, time_limit, scratch)
        for number, path in enumerate(problem_paths, 1):
            result = label_problem(domain, os.fspath(path), solver, labels, config, seed)
            if isinstance(result, str):
                skipped.append((os.fspath(path), result))
                say(f"[{number}/{len(problem_paths)}] {path}: skipped ({result})")
                continue
            labelled.append(result)
            say(
                f"[{number}/{len(problem_paths)}] {path}: {len(result.positives)} of {result.objects} objects needed"
                f" ({result.planner_runs} planner run(s), {result.solve_time:.1f} s)"
            )
    return _report(domain, labelled, skipped, config, labels, seed, started)


def _check_domain(domain: Domain, path: str | os.PathLike[str]) -> Problem:
    problem = load_problem(path, domain)
    if problem.domain_name != domain.name:
        raise DomainMismatchError(
            f"problem is for domain '{problem.domain_name}', not '{domain.name}'", path=os.fspath(path)
        )
    return problem


def _report(
    domain: Domain,
    labelled: list[LabelledProblem],
    skipped: list[tuple[str, str]],
    config: FeatureConfig,
    labels: str,
    seed: int,
    started: float,
) -> LearnReport:
    if not labelled:
        path, why = skipped[0] if skipped else ("", "")
        more = f" (and {len(skipped) - 1} more)" if len(skipped) > 1 else ""
        raise UsageError(f"no training problem was solved, nothing to learn from: {path}: {why}{more}")
    if not any(problem.vectors for problem in labelled):
        raise UsageError("the solved training problems have no objects: nothing to learn from")
    model = fit_learned_model(domain, labelled, config, labels, seed)
    seconds = time.perf_counter() - started
    training = dict(model.training, seconds=round(seconds, 2))
    return LearnReport(replace(model, training=training), labelled, skipped, seconds)


def learn_from_store(
    domain_path: str | os.PathLike[str],
    store_path: str | os.PathLike[str],
    problem_paths: Sequence[str | os.PathLike[str]],
    *,
    labels: str = DEFAULT_LABELS,
    seed: int = 0,
    time_limit: float = 60.0,
    config: FeatureConfig = FeatureConfig(),
    say: Say = _quiet,
) -> LearnReport:
    """Learn from the solved, validated runs of a results store: a row's plan labels the problem file
    among ``problem_paths`` of the same suite (folder name) and file name; ``minimal`` labels plan
    again from there."""
    from relevance_plan.batch.store import read_rows
    from relevance_plan.pddl.plans import read_plan

    _check_labels(labels)
    if not problem_paths:
        raise UsageError("give the problem files the store's runs solved (PROBLEM...) with --store")
    started = time.perf_counter()
    domain = load_domain(domain_path)
    by_name = {(Path(p).parent.name, Path(p).name): os.fspath(p) for p in problem_paths}
    plans: dict[str, str] = {}
    for row in read_rows(store_path):
        path = by_name.get((row["suite"], row["problem"]))
        if path is None or path in plans or row["status"] != "solved" or not row["valid"]:
            continue
        steps = json.loads(row["result_json"]).get("plan") or []  # an object: the store checked its rows
        if isinstance(steps, list) and steps and all(isinstance(step, str) for step in steps):
            plans[path] = "\n".join(steps)
    config = with_hubs(config, domain, [_check_domain(domain, path) for path in plans])
    labelled: list[LabelledProblem] = []
    skipped = [(os.fspath(p), "no solved run in the store") for p in problem_paths if os.fspath(p) not in plans]
    with tempfile.TemporaryDirectory(prefix="relevance-plan-learn-") as scratch:
        solver = Solver(os.fspath(domain_path), TrainingPlanner(), time_limit, scratch)
        for number, (path, text) in enumerate(sorted(plans.items()), 1):
            begun = time.perf_counter()
            task = PlanningTask(domain, load_problem(path, domain))
            try:
                plan = read_plan(text)
            except PlanFormatError:
                skipped.append((path, "its stored plan is not a plan"))
                continue
            if not validate_plan(task.domain, task.problem, plan, None, time.monotonic() + time_limit).accepted:
                skipped.append((path, "its stored plan is not valid on the problem"))
                continue
            positives = plan_objects(task, plan)
            runs = solver.runs
            if labels == "minimal":
                positives = minimal_objects(task, path, positives, solver, seed)
            labelled.append(_labelled(task, positives, config, begun, solver.runs - runs))
            say(f"[{number}/{len(plans)}] {path}: {len(positives)} of {len(task.problem.objects)} objects needed")
    return _report(domain, labelled, skipped, config, labels, seed, started)
