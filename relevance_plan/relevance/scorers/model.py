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

from relevance_plan.errors import ModelError
from relevance_plan.relevance.knowledge import KnowledgeModel, ModelClass
from relevance_plan.pddl.reader import formula_atoms
from relevance_plan.relevance.scene import Element, build_scene
from relevance_plan.relevance.scorers.base import ScoreRequest, ScoreResult, PlanningTask

UNKNOWN_CLASS = "(unknown)"
# More than this share of objects of unknown class: the model is not about this scene.
MAX_UNKNOWN_SHARE = 0.5


def task_entropy(distribution) -> float:
    return -sum(p * math.log(p) for p in distribution.values() if p > 0)


def classify(element: Element, model: KnowledgeModel) -> ModelClass | None:
    """Kind names decide first (a 'mug' is a cup whatever its type), then the most specific type."""
    for model_class in model.classes.values():
        if element.kind in model_class.kinds:
            return model_class
    for type_name in element.types:
        for model_class in model.classes.values():
            if type_name in model_class.types:
                return model_class
    return None


def _choose_objective(task: PlanningTask, model: KnowledgeModel, request: ScoreRequest) -> tuple[str | None, str]:
    if request.objective is not None:
        if request.objective not in model.objectives:
            raise ModelError(
                f"unknown objective '{request.objective}' (model has: {', '.join(model.objectives)})", path=model.path
            )
        return request.objective, ""
    goal_predicates = {atom[1] for atom, _ in formula_atoms(task.problem.goal)}
    matches = model.objective_for_goal(goal_predicates)
    if not matches:
        return None, (
            f"no objective of the model matches the goal predicates ({', '.join(sorted(goal_predicates))})"
            f" — give --objective ({', '.join(model.objectives)})"
        )
    most = max(len(model.objectives[name].goal_predicates) for name in matches)
    best = [name for name in matches if len(model.objectives[name].goal_predicates) == most]
    if len(best) > 1:
        return None, f"the goal fits several objectives ({', '.join(best)}) — give --objective"
    return best[0], ""


def score_by_model(task: PlanningTask, request: ScoreRequest) -> ScoreResult:
    model = request.model
    if model is None:
        raise ModelError("the model scorer needs a knowledge model (--model FILE)")
    human = None
    if request.human is not None:
        human = model.humans.get(request.human)
        if human is None:
            known = ", ".join(model.humans) or "none"
            raise ModelError(f"unknown human '{request.human}' (model has: {known})", path=model.path)
    scene = build_scene(task.domain, task.problem, model.scene)
    objective, problem_with_objective = _choose_objective(task, model, request)

    def insufficient(message: str, distribution=None, entropy=None) -> ScoreResult:
        return ScoreResult(
            "model",
            {name: 0.0 for name in task.problem.objects},
            sufficient=False,
            insufficiency=message,
            objective=objective,
            task_distribution=dict(distribution or {}),
            task_entropy=entropy,
        )

    if objective is None:
        return insufficient(problem_with_objective)

    if request.model_task is not None:
        if request.model_task not in model.task_classes:
            raise ModelError(
                f"unknown task '{request.model_task}' (model has: {', '.join(model.task_classes)})", path=model.path
            )
        distribution = {request.model_task: 1.0}
    elif human is not None and objective in human.objective_tasks:
        distribution = dict(human.objective_tasks[objective])
    else:
        distribution = dict(model.objectives[objective].tasks)
    entropy = task_entropy(distribution)
    if entropy > model.entropy_bound:
        leading = sorted(distribution.items(), key=lambda item: -item[1])[:3]
        shown = ", ".join(f"{name} {p:.2f}" for name, p in leading)
        return insufficient(
            f"objective ambiguous: {shown} (entropy {entropy:.2f} > {model.entropy_bound:.2f} nats)"
            " — give --task or --human",
            distribution,
            entropy,
        )

    def class_given_task(task_name: str, class_name: str) -> float:
        if human is not None:
            preferred = human.task_classes.get(task_name, {})
            if class_name in preferred:
                return preferred[class_name]
        # A class a task does not mention is irrelevant to it.
        return model.task_classes[task_name].get(class_name, 0.0)

    def kind_relevance(model_class: ModelClass, kind: str) -> float:
        if human is not None and kind in human.kind_relevance.get(model_class.name, {}):
            return human.kind_relevance[model_class.name][kind]
        if model_class.fixed_relevance is not None and kind not in model_class.kind_relevance:
            return 1.0  # a fixed-relevance class (the human) has no kinds to weigh
        return model_class.kind_relevance.get(kind, model_class.default_kind_relevance)

    element_class: dict[str, str] = {}
    for name, element in scene.elements.items():
        found = classify(element, model)
        element_class[name] = found.name if found is not None else UNKNOWN_CLASS
    unknown = tuple(sorted(name for name, c in element_class.items() if c == UNKNOWN_CLASS))
    if scene.elements and len(unknown) > MAX_UNKNOWN_SHARE * len(scene.elements):
        return insufficient(
            f"the model knows the class of only {len(scene.elements) - len(unknown)} of {len(scene.elements)}"
            " objects — give a model for this domain (--model) or use --scorer goal",
            distribution,
            entropy,
        )

    class_scores: dict[str, float] = {}
    for class_name in sorted(set(element_class.values())):
        if class_name == UNKNOWN_CLASS:
            class_scores[class_name] = model.unknown_class_relevance
            continue
        model_class = model.classes[class_name]
        if model_class.fixed_relevance is not None:
            class_scores[class_name] = model_class.fixed_relevance
        elif not model_class.from_contents:
            class_scores[class_name] = sum(
                class_given_task(task_name, class_name) * p for task_name, p in distribution.items()
            )

    scores: dict[str, float] = {}
    explanations: dict[str, str] = {}
    for name, element in scene.elements.items():
        class_name = element_class[name]
        if class_name == UNKNOWN_CLASS:
            scores[name] = model.unknown_class_relevance
            explanations[name] = f"class unknown to the model: default {model.unknown_class_relevance:g}"
            continue
        model_class = model.classes[class_name]
        if model_class.from_contents:
            continue
        class_relevance = class_scores[class_name]
        kind_p = kind_relevance(model_class, element.kind)
        placement = 1.0
        factors = []
        for condition in sorted(element.conditions):
            factor = model.placement.get(condition)
            if factor is not None:
                placement *= factor
                factors.append(f"{condition} {factor:g}")
        scores[name] = class_relevance * placement * kind_p
        explanations[name] = (
            f"R({class_name})={class_relevance:.2f} x P(kind {element.kind})={kind_p:.2f}"
            f" x placement={placement:.2f}" + (f" ({', '.join(factors)})" if factors else "")
        )
    # Places (and other classes scored by contents) are as relevant as the best
    # item they hold whose class is relevant; the class threshold is applied later.
    contents: dict[str, float] = {}
    for name, element in scene.elements.items():
        if element.place is not None and name in scores:
            contents[element.place] = max(contents.get(element.place, 0.0), scores[name])
    for name, element in scene.elements.items():
        if name in scores:
            continue
        scores[name] = contents.get(name, 0.0)
        explanations[name] = f"holds items of relevance up to {scores[name]:.2f}"
    for class_name in class_scores.keys() | set(element_class.values()):
        if class_name != UNKNOWN_CLASS and model.classes[class_name].from_contents:
            members = [scores[name] for name, c in element_class.items() if c == class_name]
            class_scores[class_name] = max(members, default=0.0)
    return ScoreResult(
        "model",
        scores,
        element_class=element_class,
        class_scores=class_scores,
        explanations=explanations,
        unknown=unknown,
        objective=objective,
        task_distribution=distribution,
        task_entropy=entropy,
    )
