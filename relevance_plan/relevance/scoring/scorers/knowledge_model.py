"""The paper's relevance model (Section IV) over a knowledge-model file.

Class level:   R(C) = sum_T P(C | T, O) * P(T | O)
Element level: R(e) = R(C) * P(e | h, C, O) * P(h | C, O)
where P(h | C, O) is the relevance of the element's kind within its class and
P(e | h, C, O) the product of the placement factors of its low-level
attributes.  A human's recorded preferences replace the priors where present.
If P(T | O) is too uncertain (entropy above the model's bound), no objective
matches, or the model knows too few of the scene's objects, the result is
"insufficient cues": relevance is not decided.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING

from relevance_plan.errors import ModelError
from relevance_plan.pddl.formulas import Formula, predicates_in
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.scoring.knowledge import Human, KnowledgeModel, ModelClass
from relevance_plan.relevance.scoring.scene import Element, build_scene
from relevance_plan.relevance.scoring.scorers.base import ScoreRequest, ScoreResult

if TYPE_CHECKING:  # the text package is imported only when free text is given
    from relevance_plan.relevance.scoring.word_matching import WordMatch

UNKNOWN_CLASS = "(unknown)"
# More than this share of objects of unknown class: the model is not about this scene.
MAX_UNKNOWN_SHARE = 0.5


def activity_entropy(distribution: Mapping[str, float]) -> float:
    return max(0.0, -sum(p * math.log(p) for p in distribution.values() if p > 0))  # never -0.0


def classify(element: Element, knowledge_model: KnowledgeModel) -> ModelClass | None:
    """Kind names decide first (a 'mug' is a cup whatever its type), then the most specific type."""
    for model_class in knowledge_model.classes.values():
        if element.kind in model_class.kinds:
            return model_class
    for type_name in element.types:
        for model_class in knowledge_model.classes.values():
            if type_name in model_class.types:
                return model_class
    return None


def _choose_objective(goal: Formula, knowledge_model: KnowledgeModel, request: ScoreRequest) -> tuple[str | None, str]:
    if request.objective is not None:
        if request.objective not in knowledge_model.objectives:
            raise ModelError(
                f"unknown objective '{request.objective}' (model has: {', '.join(knowledge_model.objectives)})",
                path=knowledge_model.path,
            )
        return request.objective, ""
    goal_predicates = predicates_in(goal)
    matches = knowledge_model.objective_for_goal(goal_predicates)
    if not matches:
        return None, (
            f"no objective of the model matches the goal predicates ({', '.join(sorted(goal_predicates))})"
            f" — give --objective ({', '.join(knowledge_model.objectives)})"
        )
    most = max(len(knowledge_model.objectives[name].goal_predicates) for name in matches)
    best = [name for name in matches if len(knowledge_model.objectives[name].goal_predicates) == most]
    if len(best) > 1:
        return None, f"the goal fits several objectives ({', '.join(best)}) — give --objective"
    return best[0], ""


@dataclass
class KnowledgeContext:
    """What the scene-independent part of the model says for one goal and one request:
    the objective, P(task | objective), and how relevant each class and kind is.

    ``insufficiency`` is non-empty when the cues do not decide relevance (no
    objective, or P(task | O) too uncertain).  Element scores follow from the
    context and each element's own description (:func:`score_element`), which
    is what lets the live session re-score one element at a time.
    """

    knowledge_model: KnowledgeModel
    human: Human | None
    objective: str | None
    distribution: dict[str, float]
    entropy: float | None
    insufficiency: str = ""
    understood: tuple[WordMatch, ...] = ()  # the request's free text, mapped to the model's names
    _class_values: dict[str, float] = field(default_factory=dict, repr=False)

    def class_given_activity(self, activity: str, class_name: str) -> float:
        if self.human is not None:
            preferred = self.human.activity_classes.get(activity, {})
            if class_name in preferred:
                return preferred[class_name]
        # A class an activity does not mention is irrelevant to it.
        return self.knowledge_model.activity_classes[activity].get(class_name, 0.0)

    def kind_relevance(self, model_class: ModelClass, kind: str) -> float:
        human = self.human
        if human is not None and kind in human.kind_relevance.get(model_class.name, {}):
            return human.kind_relevance[model_class.name][kind]
        if model_class.fixed_relevance is not None and kind not in model_class.kind_relevance:
            return 1.0  # a fixed-relevance class (the human) has no kinds to weigh
        return model_class.kind_relevance.get(kind, model_class.default_kind_relevance)

    def class_relevance(self, class_name: str) -> float:
        """R(C) of a class not scored by its contents (places are scored by what they hold)."""
        value = self._class_values.get(class_name)
        if value is None:
            if class_name == UNKNOWN_CLASS:
                value = self.knowledge_model.unknown_class_relevance
            else:
                model_class = self.knowledge_model.classes[class_name]
                if model_class.fixed_relevance is not None:
                    value = model_class.fixed_relevance
                else:
                    value = sum(self.class_given_activity(t, class_name) * p for t, p in self.distribution.items())
            self._class_values[class_name] = value
        return value


def knowledge_context(goal: Formula, request: ScoreRequest) -> KnowledgeContext:
    """The objective and P(task | objective) for ``goal`` (a formula) under ``request``; an objective
    or an activity given as free text is mapped to the model's nearest (or asked about: insufficient cues)."""
    knowledge_model = request.knowledge_model
    if knowledge_model is None:
        raise ModelError("the model scorer needs a knowledge model (--model FILE)")
    human = None
    if request.human is not None:
        human = knowledge_model.humans.get(request.human)
        if human is None:
            known = ", ".join(knowledge_model.humans) or "none"
            raise ModelError(f"unknown human '{request.human}' (model has: {known})", path=knowledge_model.path)
    request, understood, not_understood = _understood(request, knowledge_model)
    if not_understood:
        return KnowledgeContext(knowledge_model, human, None, {}, None, not_understood, understood)
    objective, problem_with_objective = _choose_objective(goal, knowledge_model, request)
    if objective is None:
        return KnowledgeContext(knowledge_model, human, None, {}, None, problem_with_objective, understood)
    if request.activity is not None:
        if request.activity not in knowledge_model.activity_classes:
            raise ModelError(
                f"unknown activity '{request.activity}' (model has: {', '.join(knowledge_model.activity_classes)})",
                path=knowledge_model.path,
            )
        distribution = {request.activity: 1.0}
    elif human is not None and objective in human.objective_activities:
        distribution = dict(human.objective_activities[objective])
    else:
        distribution = dict(knowledge_model.objectives[objective].activities)
    entropy = activity_entropy(distribution)
    insufficiency = ""
    if entropy > knowledge_model.entropy_bound:
        leading = sorted(distribution.items(), key=lambda item: -item[1])[:3]
        shown = ", ".join(f"{name} {p:.2f}" for name, p in leading)
        insufficiency = (
            f"objective ambiguous: {shown} (entropy {entropy:.2f} > {knowledge_model.entropy_bound:.2f} nats)"
            " — give --activity or --human"
        )
    return KnowledgeContext(knowledge_model, human, objective, distribution, entropy, insufficiency, understood)


def _understood(
    request: ScoreRequest, knowledge_model: KnowledgeModel
) -> tuple[ScoreRequest, tuple[WordMatch, ...], str]:
    """The request with its free-text objective and activity replaced by the model's names, the
    mappings, and why the cues are insufficient when one of them is not clear ("" when both are)."""
    objective, activity = request.objective, request.activity
    if (objective is None or objective in knowledge_model.objectives) and (
        activity is None or activity in knowledge_model.activity_classes
    ):
        return request, (), ""
    from relevance_plan.relevance.scoring.word_matching import ModelVocabulary
    from relevance_plan.relevance.scoring.word_understanding import OPTIONS, understand

    matches = []
    if objective is not None and objective not in knowledge_model.objectives:
        matches.append(understand(objective, knowledge_model, ModelVocabulary.OBJECTIVE))
        objective = matches[-1].chosen
    if activity is not None and activity not in knowledge_model.activity_classes:
        matches.append(understand(activity, knowledge_model, ModelVocabulary.ACTIVITY))
        activity = matches[-1].chosen
    unclear = [
        f"{match.insufficiency} — say it otherwise, or give {OPTIONS[match.vocabulary]} NAME"
        for match in matches
        if match.chosen is None
    ]
    return replace(request, objective=objective, activity=activity), tuple(matches), "; ".join(unclear)


def class_of(element: Element, knowledge_model: KnowledgeModel) -> str:
    found = classify(element, knowledge_model)
    return found.name if found is not None else UNKNOWN_CLASS


def scored_by_contents(class_name: str, knowledge_model: KnowledgeModel) -> bool:
    return class_name != UNKNOWN_CLASS and knowledge_model.classes[class_name].from_contents


def score_element(context: KnowledgeContext, element: Element, class_name: str) -> tuple[float, str]:
    """R(e) and its explanation for an element whose class is not scored by its contents."""
    knowledge_model = context.knowledge_model
    if class_name == UNKNOWN_CLASS:
        return (
            knowledge_model.unknown_class_relevance,
            f"class unknown to the model: default {knowledge_model.unknown_class_relevance:g}",
        )
    model_class = knowledge_model.classes[class_name]
    class_relevance = context.class_relevance(class_name)
    kind_p = context.kind_relevance(model_class, element.kind)
    placement = 1.0
    factors = []
    for condition in sorted(element.conditions):
        factor = knowledge_model.placement.get(condition)
        if factor is not None:
            placement *= factor
            factors.append(f"{condition} {factor:g}")
    return class_relevance * placement * kind_p, (
        f"R({class_name})={class_relevance:.2f} x P(kind {element.kind})={kind_p:.2f}"
        f" x placement={placement:.2f}" + (f" ({', '.join(factors)})" if factors else "")
    )


def contents_explanation(score: float) -> str:
    return f"holds items of relevance up to {score:.2f}"


def unknown_share_problem(known: int, total: int) -> str:
    """Why the model cannot judge a scene with ``known`` of ``total`` elements classified ("" if it can)."""
    if total and total - known > MAX_UNKNOWN_SHARE * total:
        return (
            f"the model knows the class of only {known} of {total}"
            " objects — give a model for this domain (--model) or use --scorer goal"
        )
    return ""


def insufficient_result(objects: Iterable[str], context: KnowledgeContext, message: str) -> ScoreResult:
    return ScoreResult(
        "model",
        {name: 0.0 for name in objects},
        sufficient=False,
        insufficiency=message,
        objective=context.objective,
        activity_distribution=dict(context.distribution),
        activity_entropy=context.entropy,
        understood=context.understood,
    )


GOAL_EXPLANATION = "named in the goal"


def with_goal_objects(
    scores: dict[str, float], explanations: dict[str, str], goal_objects: Iterable[str]
) -> tuple[dict[str, float], dict[str, str]]:
    """Objects the goal names have relevance 1, whatever the formula says (it still decides their places')."""
    for name in goal_objects:
        if name in scores:
            scores[name], explanations[name] = 1.0, GOAL_EXPLANATION
    return scores, explanations


def score_by_knowledge_model(task: PlanningTask, request: ScoreRequest) -> ScoreResult:
    context = knowledge_context(task.problem.goal, request)
    knowledge_model = context.knowledge_model
    if context.insufficiency:
        return insufficient_result(task.problem.objects, context, context.insufficiency)
    facts = task.problem.facts_in_order()  # an object's first place is the file's first
    scene = build_scene(task.domain, task.problem.objects, facts, knowledge_model.scene, task.deadline)
    task.check_time("describing the scene")
    element_class: dict[str, str] = {
        name: class_of(element, knowledge_model) for name, element in scene.elements.items()
    }
    placed: tuple[WordMatch, ...] = ()
    if request.place_kinds:
        element_class, placed = _place_unknown(scene.elements, element_class, knowledge_model)
        context = replace(context, understood=context.understood + placed)
    task.check_time("classifying the objects")
    unknown = tuple(sorted(name for name, c in element_class.items() if c == UNKNOWN_CLASS))
    problem = unknown_share_problem(len(scene.elements) - len(unknown), len(scene.elements))
    if problem:
        return insufficient_result(task.problem.objects, context, problem)

    class_scores: dict[str, float] = {}
    for class_name in sorted(set(element_class.values())):
        if not scored_by_contents(class_name, knowledge_model):
            class_scores[class_name] = context.class_relevance(class_name)

    scores: dict[str, float] = {}
    explanations: dict[str, str] = {}
    for count, (name, element) in enumerate(scene.elements.items()):
        if not count & 0xFFF:
            task.check_time("scoring the objects")
        class_name = element_class[name]
        if not scored_by_contents(class_name, knowledge_model):
            scores[name], explanations[name] = score_element(context, element, class_name)
    _score_by_contents(scene.elements, element_class, knowledge_model, scores, explanations, class_scores)
    with_goal_objects(scores, explanations, task.goal_objects)
    for match in placed:
        for name, element in scene.elements.items():
            if match.chosen is not None and match.text in (element.kind, element.type) and name in explanations:
                explanations[name] += (
                    f"; '{match.text}' placed under {match.chosen} (similarity {match.similarity:.2f})"
                )
    return scored_result(context, scores, element_class, class_scores, explanations, unknown)


def scored_result(
    context: KnowledgeContext,
    scores: dict[str, float],
    element_class: dict[str, str],
    class_scores: dict[str, float],
    explanations: dict[str, str],
    unknown: tuple[str, ...],
) -> ScoreResult:
    """The knowledge model's scores with the context that gave them (the cues, what words were taken for)."""
    return ScoreResult(
        "model",
        scores,
        element_class=element_class,
        class_scores=class_scores,
        explanations=explanations,
        unknown=unknown,
        objective=context.objective,
        activity_distribution=context.distribution,
        activity_entropy=context.entropy,
        understood=context.understood,
    )


def _score_by_contents(
    elements: Mapping[str, Element],
    element_class: Mapping[str, str],
    knowledge_model: KnowledgeModel,
    scores: dict[str, float],
    explanations: dict[str, str],
    class_scores: dict[str, float],
) -> None:
    """Places (and other classes scored by contents) are as relevant as the best item they hold
    whose class is relevant; the class threshold is applied later."""
    contents: dict[str, float] = {}
    for name, element in elements.items():
        if element.place is not None and name in scores:
            contents[element.place] = max(contents.get(element.place, 0.0), scores[name])
    for name in elements:
        if name in scores:
            continue
        scores[name] = contents.get(name, 0.0)
        explanations[name] = contents_explanation(scores[name])
    for class_name in class_scores.keys() | set(element_class.values()):
        if scored_by_contents(class_name, knowledge_model):
            members = [scores[name] for name, c in element_class.items() if c == class_name]
            class_scores[class_name] = max(members, default=0.0)


def _place_unknown(
    elements: Mapping[str, Element], element_class: dict[str, str], knowledge_model: KnowledgeModel
) -> tuple[dict[str, str], tuple[WordMatch, ...]]:
    """The classes of the elements the model does not know, by their kind's (else their type's)
    nearest class, and the mappings (a kind that resembles no class stays unknown: a question)."""
    unknown = [elements[name] for name, c in element_class.items() if c == UNKNOWN_CLASS]
    if not unknown:
        return element_class, ()
    from relevance_plan.relevance.scoring.word_understanding import understand_kinds

    by_kind = {m.text: m for m in understand_kinds([e.kind for e in unknown], knowledge_model)}
    unplaced = [e.type for e in unknown if by_kind[e.kind].chosen is None and e.type not in by_kind]
    by_type = {m.text: m for m in understand_kinds(unplaced, knowledge_model)} if unplaced else {}
    placed = dict(element_class)
    for element in unknown:
        match = by_kind[element.kind] if by_kind[element.kind].chosen is not None else by_type.get(element.type)
        if match is not None and match.chosen is not None:
            placed[element.name] = match.chosen
    return placed, tuple(by_kind.values()) + tuple(by_type.values())
