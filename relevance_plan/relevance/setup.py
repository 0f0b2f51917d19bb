"""One scoring set-up for every front end: find the knowledge model, pick the scorer, score.

``score``, ``prune``, ``plan``, ``sweep``, ``compare``, the live session and
the unified-planning engine all call :func:`score_problem` with a
:class:`ScoringOptions`, so they choose knowledge models and scorers the same way.
"""

from __future__ import annotations

import os
from collections.abc import Iterable
from dataclasses import dataclass, field, replace

from relevance_plan.errors import UsageError
from relevance_plan.pddl.model import Domain
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.scoring.knowledge import (
    KnowledgeModel,
    check_knowledge_model_applies,
    find_knowledge_model,
    load_knowledge_model,
)
from relevance_plan.relevance.scoring.learning.learned_model import load_learned_model
from relevance_plan.relevance.scoring.learning.scorer import score_learned
from relevance_plan.relevance.scoring.scorers import SCORERS, ScoreRequest, ScoreResult
from relevance_plan.relevance.selection.prune import PruneSettings, Selection, Thresholds, prune_with_scores
from relevance_plan.sidecar import necessary_objects


@dataclass(frozen=True)
class ScoringOptions:
    """How objects are scored and thresholded (the options ``score``, ``prune`` and ``plan`` share)."""

    scorer: str | None = None  # None: 'model' when a knowledge model applies, else 'goal'
    model_path: str | None = None  # None: found next to the domain or among the shipped worlds
    objective: str | None = None
    activity: str | None = None  # the knowledge model's task (P(task | objective) = 1)
    human: str | None = None
    place_kinds: bool = False  # kinds and types the model does not list go under their nearest class (free text)
    thresholds: Thresholds = field(default_factory=Thresholds)
    seed: int = 0
    goal_filter: bool = True  # the first selection leaves out relevant objects no goal-directed action can use
    prefer_free: bool = True  # ... and, with a knowledge model, alternatives something stands on when a free one exists
    economical: bool = True  # ... and, of many candidates for one role, only those a relaxed plan needs

    def __post_init__(self) -> None:
        if self.scorer is not None:
            check_scorer(self.scorer)

    @property
    def learned_model_path(self) -> str | None:
        """MODEL of ``--scorer learned:MODEL`` (None for the other scorers)."""
        if self.scorer is None or not self.scorer.startswith(LEARNED_PREFIX):
            return None
        return self.scorer[len(LEARNED_PREFIX) :]


LEARNED_PREFIX = "learned:"
SCORER_CHOICES = (*SCORERS, LEARNED_PREFIX + "MODEL")  # what --scorer takes, as help and errors list it


def check_scorer(scorer: str) -> None:
    """UsageError unless ``scorer`` is a registered scorer or ``learned:MODEL``."""
    if scorer.startswith(LEARNED_PREFIX) and scorer != LEARNED_PREFIX:
        return
    if scorer in (LEARNED_PREFIX, LEARNED_PREFIX[:-1]):
        raise UsageError("the learned scorer needs its model: --scorer learned:MODEL (made by 'relevance-plan learn')")
    if scorer not in SCORERS:
        raise UsageError(f"unknown scorer '{scorer}' (choose from: {', '.join(SCORER_CHOICES)})")


@dataclass(frozen=True)
class Scoring:
    """What scoring one problem produced: the task, the knowledge model used (if any), the scores."""

    task: PlanningTask
    knowledge_model: KnowledgeModel | None
    scores: ScoreResult
    options: ScoringOptions = field(default_factory=ScoringOptions)

    @property
    def scorer(self) -> str:
        return self.scores.scorer

    def prune(self, thresholds: Thresholds, settings: PruneSettings = PruneSettings()) -> Selection:
        return prune_with_scores(self.task, self.scores, thresholds, self.knowledge_model, settings=settings)

    def first_selection(self, narrow: bool = True) -> Selection:
        """The objects ``prune`` writes and ``plan`` tries first: thresholds and closure, and when
        ``narrow`` (the relevance method) the goal filter, and blocked alternatives and those no
        relaxed plan needs set aside (a bet on the first attempt only: widening sets nothing more
        aside, and brings these back last); with a knowledge model that asks for it
        (``reachability_check``), the reachability check as without a model, negative preconditions
        counted (``completion``)."""
        checked = narrow and self.knowledge_model is not None and self.knowledge_model.reachability_check
        settings = PruneSettings(
            goal_filter=self.options.goal_filter and narrow,
            prefer_free=self.options.prefer_free and narrow,
            economical=self.options.economical and narrow,
            repair=True if checked and self.scorer == "model" else None,
        )
        selection = self.prune(self.options.thresholds, settings)
        if checked and self.scorer == "model":
            from relevance_plan.relevance.selection.completion import complete_selection

            return complete_selection(selection, self.knowledge_model)
        return selection


def resolve_knowledge_model(
    domain: Domain, domain_path: str | None, model_path: str | None, names: Iterable[str] = ()
) -> KnowledgeModel | None:
    """The explicit ``--model``, else one found next to the domain or shipped for the domain's name
    (or one of ``names``); an explicit knowledge model that does not fit the domain is an error."""
    if model_path is not None:
        return check_knowledge_model_applies(load_knowledge_model(model_path), domain)
    for name in (domain.name, *names):
        found = find_knowledge_model(name, domain_path)
        if found is None:
            continue
        knowledge_model = load_knowledge_model(found)
        if knowledge_model.domain == name:
            applies = check_knowledge_model_applies(replace(knowledge_model, domain=domain.name), domain)
            return replace(applies, domain=knowledge_model.domain)
    return None


# The options only a knowledge model reads, as the command line spells them.
CUE_OPTIONS = {"objective": "--objective", "activity": "--activity", "human": "--human", "place_kinds": "--place-kinds"}


def given_cues(options: ScoringOptions) -> list[str]:
    """The command-line names of the knowledge-model options ``options`` sets."""
    return [flag for field_name, flag in CUE_OPTIONS.items() if getattr(options, field_name) not in (None, False)]


def without_cues(options: ScoringOptions) -> ScoringOptions:
    """``options`` without the knowledge-model options (for a fallback to another scorer that says so)."""
    return replace(options, objective=None, activity=None, human=None, place_kinds=False)


def check_cues_used(options: ScoringOptions, scorer: str, domain_name: str) -> None:
    """UsageError when options only a knowledge model reads are given to another scorer: never ignored."""
    given = given_cues(options)
    if not given or scorer == "model":
        return
    why = (
        f"no knowledge model applies to domain '{domain_name}'"
        if options.scorer is None
        else f"--scorer {scorer} is chosen"
    )
    raise UsageError(
        f"{' and '.join(given)} {'needs' if len(given) == 1 else 'need'} the knowledge-model scorer, but {why}:"
        " give --model FILE ('relevance-plan draft-model' drafts one), or leave "
        + ("it" if len(given) == 1 else "them")
        + " out"
    )


def choose_scorer(method: str, knowledge_model: KnowledgeModel | None, override: str | None) -> str:
    """The scorer a method uses: the override, else the knowledge model's when one applies, else the goal scorer."""
    if override:
        return override
    if method == "relevance":
        return "model" if knowledge_model is not None else "goal"
    return method


def score_problem(
    task: PlanningTask,
    options: ScoringOptions,
    *,
    method: str = "relevance",
    domain_path: str | os.PathLike[str] | None = None,
    problem_path: str | os.PathLike[str] | None = None,
    knowledge_model: KnowledgeModel | None = None,
) -> Scoring:
    """Score every object of ``task``.

    ``knowledge_model`` skips the look-up (a front end that found it already);
    ``problem_path`` locates the sidecar the oracle needs.
    """
    if knowledge_model is None and options.scorer in (None, "model"):
        # Only the model scorer reads a knowledge model: a broken file next to the domain must not stop the others.
        knowledge_model = resolve_knowledge_model(
            task.domain, None if domain_path is None else str(domain_path), options.model_path
        )
    learned_path = options.learned_model_path
    if learned_path is not None:
        learned = load_learned_model(learned_path)
        learned.check_applies(task.domain)
        task.check_time("scoring the objects")
        scores = score_learned(task, learned)
        task.check_time("scoring the objects")
        return Scoring(task, None, scores, options)
    scorer = choose_scorer(method, knowledge_model, options.scorer)
    if scorer == "model" and knowledge_model is None:
        raise UsageError(f"no knowledge model found for domain '{task.domain.name}': give --model or use --scorer goal")
    if method == "relevance":
        check_cues_used(options, scorer, task.domain.name)
    necessary = None
    if scorer == "oracle" and problem_path is not None:
        necessary = necessary_objects(problem_path)
    request = ScoreRequest(
        knowledge_model=knowledge_model,
        objective=options.objective,
        activity=options.activity,
        human=options.human,
        seed=options.seed,
        necessary=necessary,
        place_kinds=options.place_kinds,
    )
    task.check_time("scoring the objects")
    scores = SCORERS[scorer](task, request)
    task.check_time("scoring the objects")
    return Scoring(task, knowledge_model, scores, options)


__all__ = [
    "SCORER_CHOICES",
    "Scoring",
    "ScoringOptions",
    "check_cues_used",
    "given_cues",
    "check_scorer",
    "choose_scorer",
    "resolve_knowledge_model",
    "score_problem",
    "without_cues",
]
