"""Applying events: the live scene and its scores, changed one event at a time.

:class:`SceneUpdates` holds what the events change: the scene (``state.py``),
the scoring options the events set (a goal, the human served, a cue), the
live scores (``rescoring.py``) and which elements pass the thresholds.  It
says what each event changed, for the triggers and the determination to read;
it decides nothing about relevance.
"""

from __future__ import annotations

from dataclasses import replace

from relevance_plan.planning.methods import Method
from relevance_plan.relevance.scoring.knowledge import KnowledgeModel
from relevance_plan.relevance.setup import ScoringOptions, choose_scorer
from relevance_plan.session.events import Event
from relevance_plan.session.rescoring import ALL, FullScores, LiveGoalScores, LiveModelScores
from relevance_plan.session.state import LiveScene, SceneDelta

LiveScores = LiveModelScores | LiveGoalScores | FullScores


class SceneUpdates:
    """The live scene, the scoring options in force and the scores, kept current event by event."""

    def __init__(
        self, scene: LiveScene, model: KnowledgeModel | None, options: ScoringOptions, domain_path: str | None
    ):
        self.scene = scene
        self.options = options
        self.scores: LiveScores = live_scores(scene, model, options, domain_path)
        self.served: str | None = None  # the human of the last 'human' event
        self.passing: set = set()
        self.recount_passing()

    @property
    def idle(self) -> bool:
        """Nobody to serve (no goal, no human): element and fact events trigger nothing."""
        return self.scene.idle_goal and self.served is None

    def apply(self, event: Event, determined: bool) -> tuple[bool, object, SceneDelta]:
        """Change the scene; returns (whether anything changed, the elements whose scores may differ
        (``ALL``: any), what changed in the scene).  ``determined``: a determination is in force (a
        cue said again then changes nothing)."""
        scene = self.scene
        options = self.options
        if event.kind == "add":
            # check_event fills what each kind needs; the asserts only tell the type checker
            assert event.name is not None and event.type is not None and event.display is not None
            scene.add_object(event.name, event.type, event.display)
            for fact in event.facts:
                scene.set(fact)
        elif event.kind == "remove":
            assert event.name is not None
            scene.remove_object(event.name)
            if self.served == event.name:  # the human served left: their preferences and cues go too
                self.served = None
                options = replace(options, human=None, activity=None)
        elif event.fluent is not None:
            assert event.value is not None
            scene.set_value(event.fluent, event.value)
        elif event.kind in ("set", "unset"):
            fact = event.facts[0]
            scene.set(fact) if event.kind == "set" else scene.unset(fact)
        elif event.kind == "goal":
            assert event.goal is not None
            if event.goal != scene.goal:
                scene.set_goal(event.goal)
        elif event.kind == "human":
            options = replace(options, human=event.profile, activity=None)
            if event.name != self.served:
                self.served = event.name
                return self._rescore(scene.take_delta(), options, True)
        elif event.kind == "cue":
            if event.activity is None and event.objective is None:
                return False, set(), scene.take_delta()  # words not understood: nothing changes, the report asks
            if event.activity is not None:
                options = replace(options, activity=event.activity)
            else:
                options = replace(options, objective=event.objective)
            # the cue in force, said again: worth a determination only if none was made yet
            return self._rescore(scene.take_delta(), options, options == self.options and not determined)
        return self._rescore(scene.take_delta(), options, False)

    def _rescore(self, delta: SceneDelta, options: ScoringOptions, served: bool) -> tuple[bool, object, SceneDelta]:
        """The scores after the scene's changes and the new options (a new goal, human or cue)."""
        rescored = self.scores.update(delta)
        if options != self.options or delta.goal:
            self.options = options
            again = self.scores.set_options(options)
            rescored = ALL if again is ALL or rescored is ALL else rescored | again
            return True, rescored, delta
        return bool(delta) or served, rescored, delta

    def update_passing(self, rescored) -> set:
        """Update which elements pass the thresholds; returns those that crossed."""
        if rescored is ALL:
            before = set(self.passing)
            self.recount_passing()
            return before ^ self.passing
        crossed = set()
        thresholds = self.options.thresholds
        for name in set(rescored) | (self.passing - self.scene.objects.keys()):
            now = name in self.scene.objects and self.scores.passes(name, thresholds)
            if now != (name in self.passing):
                crossed.add(name)
                (self.passing.add if now else self.passing.discard)(name)
        return crossed

    def recount_passing(self) -> None:
        thresholds = self.options.thresholds
        if self.scores.sufficient:
            self.passing = {n for n in self.scene.objects if self.scores.passes(n, thresholds)}
        else:
            self.passing = set()

    def understood(self) -> tuple:
        """What the free text in force (``--objective`` or ``--activity`` in words) was taken for."""
        context = getattr(self.scores, "context", None)  # the live knowledge model's, without a full result
        if context is not None:
            return context.understood
        return () if isinstance(self.scores, LiveGoalScores) else self.scores.result().understood


def touched_names(event: Event) -> frozenset:
    """The objects an event names: the one added or removed, and those in its facts and fluent."""
    names = {event.name} if event.kind in ("add", "remove") else set()
    for fact in event.facts:
        names.update(fact[1:])
    if event.fluent is not None:
        names.update(event.fluent[1:])
    return frozenset(names)


def live_scores(
    scene: LiveScene, model: KnowledgeModel | None, options: ScoringOptions, domain_path: str | None
) -> LiveScores:
    """The live form of the scorer the options choose (the knowledge model's, the goal's), else
    the scorer re-run in full on every change."""
    scorer = choose_scorer(Method.RELEVANCE.value, model, options.scorer)
    # placing unknown kinds (--place-kinds) is the scorer's own step: scored in full on each change
    if scorer == "model" and model is not None and not options.place_kinds:
        return LiveModelScores(scene, model, options)
    if scorer == "goal" and options.learned_model_path is None:
        return LiveGoalScores(scene)
    return FullScores(scene, model, options, domain_path)
