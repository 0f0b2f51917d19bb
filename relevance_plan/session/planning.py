"""Planning in a live session: the attempt loop on the current state, a still-valid plan kept.

:class:`SessionPlanner` plans the current full state with the one attempt
loop of ``planning.attempts``, starting from the first selection in force;
a previous plan that is still valid on the current state is kept without
calling the planner.  It starts no process itself: the planner is a function
from problem text and time limit to a ``RunOutcome`` (:func:`planner_in_folder`
makes the default one).
"""

from __future__ import annotations

import itertools
import tempfile
import time
import weakref
from collections.abc import Callable
from dataclasses import replace
from pathlib import Path

from relevance_plan.io import write_text_atomic
from relevance_plan.pddl.formatter import format_domain
from relevance_plan.pddl.formulas import Formula
from relevance_plan.pddl.model import Domain
from relevance_plan.pddl.plans import Plan
from relevance_plan.pddl.writer import write_pruned_problem
from relevance_plan.planning.attempts import AttemptLoop, run_attempts
from relevance_plan.planning.options import PlanOptions
from relevance_plan.planning.planners.base import RunOutcome
from relevance_plan.planning.results import PlanStatus
from relevance_plan.planning.summary import RunFacts, summarise
from relevance_plan.planning.validation import validate_plan
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.scoring.scorers import ScoreResult
from relevance_plan.relevance.selection.prune import Selection
from relevance_plan.relevance.setup import Scoring
from relevance_plan.session.determination import Determination
from relevance_plan.session.events import Event
from relevance_plan.session.reports import PlanReport
from relevance_plan.session.rescoring import restrict
from relevance_plan.session.triggers import Change

# Runs the planner on a problem (PDDL text of the current domain) within a time limit (None: none).
RunPlanner = Callable[[str, "float | None"], RunOutcome]


class SessionPlanner:
    """Plans for the state ``determination`` keeps current, with ``options``, through ``run_planner``
    (None: no planner); ``in_loop``: plan after each determination that changes what a plan reads."""

    def __init__(
        self, determination: Determination, options: PlanOptions, run_planner: RunPlanner | None, in_loop: bool
    ):
        self.determination = determination
        self.options = options
        self.run_planner = run_planner
        self.in_loop = in_loop
        self.plan_steps: Plan | None = None
        self.planned_kept: frozenset | None = None
        self.planned_goal: Formula | None = None

    def plan_for(self, event: Event, reasons: tuple, change: Change, previous: Selection | None) -> PlanReport | None:
        """The plan this event asks for: on a ``plan`` event, or (planning in the loop) after a
        determination that changed the kept set, the goal, or a fact about a kept object."""
        if event.kind == "plan":
            if self.run_planner is None:
                return PlanReport(PlanStatus.INPUT_ERROR, message="this session has no planner")
            return self.plan()
        determination = self.determination
        scene = determination.updates.scene
        kept_before = previous.kept if previous is not None else frozenset()
        if (
            reasons
            and self.in_loop
            and determination.selection is not None
            and determination.updates.scores.sufficient
            and not scene.idle_goal
            and (
                determination.selection.kept != self.planned_kept
                or scene.goal != self.planned_goal
                or change.touched & (kept_before | change.kept)
            )
        ):
            return self.plan()
        return None

    def plan(self) -> PlanReport:
        """A plan for the current state: the previous one if still valid, else the attempt loop."""
        if self.run_planner is None:
            return PlanReport(PlanStatus.INPUT_ERROR, message="this session has no planner")
        run_planner = self.run_planner
        started = time.perf_counter()
        options = self.options
        determination = self.determination
        updates = determination.updates
        problem = updates.scene.read_problem()
        task = PlanningTask(determination.domain, problem)
        if self.plan_steps is not None:
            validation = validate_plan(determination.domain, problem, self.plan_steps, options.validators)
            if validation.valid:
                self._planned(self.plan_steps)
                return PlanReport(
                    PlanStatus.SOLVED,
                    self.plan_steps,
                    "previous",
                    f"previous plan still valid on the current state ({validation.validator})",
                )
        selection = None
        scorer = None
        if determination.selection is None and updates.scores.sufficient:
            determination.determine()  # an idle session holds no determination yet
        if options.method.prunes:
            if determination.selection is None:
                return PlanReport(PlanStatus.INSUFFICIENT_CUES, message=updates.scores.result().insufficiency)
            scores = updates.scores.result()
            if not scores.sufficient:  # plan with the selection in force (stale)
                scores = restrict(determination.selection.scores, problem.objects)
            scorer = scores.scorer
            selection = self._selection_on(task, scores)
        relevance_time = time.perf_counter() - started

        def call_planner(objects: Selection | None, limit: float | None) -> RunOutcome:
            return run_planner(problem.text if objects is None else objects.text, limit)

        loop = AttemptLoop(task, call_planner, options, started, determination.model)
        attempts, widening = run_attempts(loop, selection)
        planner = attempts[0].outcome.planner if attempts else options.planner
        facts = RunFacts(task, started, relevance_time + widening, selection, planner=planner, scorer=scorer)
        result = summarise(facts, options, attempts)
        if result.status is PlanStatus.SOLVED:
            self._planned(result.plan)
        return PlanReport(result.status, result.plan, "planner", result.message, result)

    def _selection_on(self, task: PlanningTask, scores: ScoreResult) -> Selection:
        """The first selection the attempt loop starts from, on ``task`` (the current state read back
        from its text): the one in force when the plan's options make the same one (the same scores,
        thresholds and narrowing), else made again."""
        options = self.options
        determination = self.determination
        in_force = determination.updates.options
        scoring = Scoring(task, determination.model, scores, options.scoring)
        same = (scoring.options.thresholds, scoring.options.goal_filter, scoring.options.prefer_free) == (
            in_force.thresholds,
            in_force.goal_filter,
            in_force.prefer_free,
        )
        selection = determination.selection
        if (
            selection is None
            or determination.basis is None  # stale, or made before the scene changed
            or not same
            or scoring.options.economical != in_force.economical
            or not options.narrows_first
            or not scores.sufficient
        ):
            return scoring.first_selection(options.narrows_first)
        problem = task.problem
        text = problem.text if selection.unpruned_reason else write_pruned_problem(problem, selection.kept)
        return replace(selection, task=task, scores=scores, text=text)

    def _planned(self, steps: Plan) -> None:
        self.plan_steps = steps
        self.planned_kept = self.determination.kept
        self.planned_goal = self.determination.updates.scene.goal


def planner_in_folder(owner: object, options: PlanOptions, domain_path: str | None, domain: str | Domain) -> RunPlanner:
    """A planner call that writes each problem into a private folder, removed with ``owner``
    (the domain too, from its text, when it has no file); each problem file goes once planned."""
    from relevance_plan.planning.planners.registry import make_planner

    folder = tempfile.TemporaryDirectory(prefix="relevance-plan-session-")
    weakref.finalize(owner, folder.cleanup)
    if domain_path is None:
        domain_path = str(
            write_text_atomic(
                Path(folder.name) / "domain.pddl", domain if isinstance(domain, str) else format_domain(domain)
            )
        )
    runs = itertools.count(1)

    def run(text: str, limit: float | None) -> RunOutcome:
        planner = make_planner(options.planner, options.planner_config)
        path = write_text_atomic(Path(folder.name) / f"problem-{next(runs)}.pddl", text)
        try:
            return planner.run(str(domain_path), str(path), time_limit=limit, memory_limit_mb=options.memory_limit_mb)
        finally:
            path.unlink(missing_ok=True)

    return run
