"""What ``score`` and ``prune`` print: the relevance tables, each object's decision, one object's chain.

Each object's line names the step that kept or dropped it
(``relevance.selection.decisions``): the goal, the thresholds, closure, a dependency,
the reachability check, soundness, the goal filter, set aside.  Free text the
model understood is shown with its similarity.
"""

from __future__ import annotations

import click

from relevance_plan.errors import UsageError
from relevance_plan.relevance.scoring.scorers import ScoreResult
from relevance_plan.relevance.selection.decisions import classes_kept, decide, kept_summary, why
from relevance_plan.relevance.selection.prune import Selection


def selection_json(result: Selection) -> dict:
    """The selection and its scores as ``score --json`` and ``prune --json`` print them."""
    problem = result.task.problem
    scores = result.scores
    decisions = decide(result)
    classes = classes_kept(result, decisions)
    matches = {match.vocabulary.value: match for match in scores.understood}
    return {
        **result.describe(),
        "scorer": scores.scorer,
        "sufficient": scores.sufficient,
        "insufficiency": scores.insufficiency or None,
        "objective": scores.objective,
        "objective_match": matches["objective"].as_json() if "objective" in matches else None,
        "activities": scores.activity_distribution,
        "activity_match": matches["activity"].as_json() if "activity" in matches else None,
        "activity_entropy": scores.activity_entropy,
        # their names until 0.12, written for one more release
        "tasks": scores.activity_distribution,
        "task_match": matches["activity"].as_json() if "activity" in matches else None,
        "task_entropy": scores.activity_entropy,
        "kinds_placed": [m.as_json() for m in scores.understood if m.vocabulary.value == "class"],
        "tau_class": result.thresholds.tau_class,
        "tau_element": result.thresholds.tau_element,
        "selected": [problem.display(n) for n in problem.objects if n in result.selected],
        "scores": {problem.display(n): round(decisions[n].score, 6) for n in scores.element_scores},
        "classes": {c: {"relevance": round(s, 6), **classes[c].as_json()} for c, s in scores.class_scores.items()},
        "element_class": {problem.display(n): _class_shown(result, c) for n, c in scores.element_class.items()},
        "unknown_class": [problem.display(n) for n in scores.unknown],
        "decisions": {problem.display(n): decision.as_json() for n, decision in decisions.items()},
    }


def scores_header(scores: ScoreResult) -> list[str]:
    """The scorer, the objective and activities, and what free text was understood as."""
    header = f"scorer: {scores.scorer}"
    if scores.objective:
        ranked = sorted(scores.activity_distribution.items(), key=lambda i: -i[1])
        activities = ", ".join(f"{t} {p:.2f}" for t, p in ranked)
        header += (
            f"   objective: {scores.objective}   activities: {activities}   H = {scores.activity_entropy:.2f} nats"
        )
    return [header, *understood_lines(scores.understood)]


def understood_lines(matches, resolved_only: bool = False) -> list[str]:
    """What each free text was taken for, with its similarity and runners-up, or why it was not;
    ``resolved_only``: the ones taken (a caller that prints the insufficiency names the others)."""
    lines = []
    for match in matches:
        if match.chosen is not None:
            lines.append(
                f"understood: '{match.text}' as {match.vocabulary.value} {match.chosen} ({_similarity(match)})"
            )
        elif not resolved_only:
            lines.append(f"not understood: {match.insufficiency}")
    return lines


def _similarity(match) -> str:
    shown = f"similarity {match.similarity:.2f}"
    if match.runners_up:
        shown += "; next: " + ", ".join(f"{c.name} {c.similarity:.2f}" for c in match.runners_up)
    return shown


def _class_shown(result: Selection, class_name: str) -> str:
    # without class scores, the classes are the objects' PDDL types: shown as the domain spells them
    return class_name if result.scores.class_scores else result.task.problem.spelling.type(class_name)


def print_score_table(result: Selection) -> None:
    """The class table and the element table; nothing when the cues are insufficient (the command
    says so once, as its error)."""
    scores = result.scores
    problem = result.task.problem
    if not scores.sufficient:
        for line in understood_lines(scores.understood, resolved_only=True):
            click.echo(line, err=True)  # what the words were taken for; the error itself is said once, by the command
        return
    for line in scores_header(scores):
        click.echo(line)
    decisions = decide(result)
    if scores.class_scores:
        classes = classes_kept(result, decisions)
        click.echo("")
        click.echo(f"{'class':<18} {'R(C)':>6}  kept")
        for class_name, value in sorted(scores.class_scores.items(), key=lambda i: (-i[1], i[0])):
            kept = classes[class_name]
            shown = f"{'yes' if kept.any_kept else 'no'} ({kept.kept} of {kept.objects})"
            click.echo(f"{class_name:<18} {value:6.3f}  {shown}")
    click.echo("")
    width = max((len(problem.display(n)) for n in problem.objects), default=10)
    steps = max((len(d.step) for d in decisions.values()), default=4)
    click.echo(f"{'element':<{width}} {'class':<16} {'R(e)':>6}  {'kept':<8} {'step':<{steps}} why")
    order = sorted(problem.objects, key=lambda n: (-decisions[n].score, n))
    for name in order:
        decision = decisions[name]
        click.echo(
            f"{problem.display(name):<{width}} {_class_shown(result, scores.element_class.get(name, '-')):<16}"
            f" {decision.score:6.3f}  {decision.status:<8} {decision.step:<{steps}} {decision.reason}"
        )
    click.echo("")
    click.echo(kept_summary(result))
    if scores.unknown:
        click.echo(
            f"class unknown to the model (default relevance): {', '.join(problem.display(n) for n in scores.unknown)}"
        )


def why_json(result: Selection, shown: str) -> dict:
    chain = why(result, _object_named(result, shown))
    display = result.task.problem.display
    node_map = _node_map(result)
    nodes = {} if node_map is None else {"graph_node": node_map.nodes.get(chain[0].name)}
    return {
        **nodes,
        "object": display(chain[0].name),
        "class": _class_of(result, chain[0].name),
        "class_relevance": result.scores.class_score(chain[0].name),
        "relevance": round(chain[0].score, 6),
        "explanation": result.scores.explanations.get(chain[0].name, ""),
        **chain[0].as_json(),
        "because": [{"object": display(d.name), **d.as_json()} for d in chain[1:]],
    }


def print_why(result: Selection, shown: str) -> None:
    """One object's decision, its scores, and the chain of objects that brought it back."""
    chain = why(result, _object_named(result, shown))
    scores, display = result.scores, result.task.problem.display
    first = chain[0]
    click.echo(f"{display(first.name)}: {'kept' if first.kept else 'not kept'} ({first.step}): {first.reason}")
    class_name = _class_of(result, first.name)
    if class_name is not None:
        class_score = scores.class_score(first.name)
        shown_class = (
            f", R(C) = {class_score:.3f} (tau_c {result.thresholds.tau_class:g})" if class_score is not None else ""
        )
        click.echo(f"  class {class_name}{shown_class}")
    explanation = scores.explanations.get(first.name, "")
    click.echo(
        f"  R(e) = {first.score:.3f} (tau_e {result.thresholds.tau_element:g})"
        + (f": {explanation}" if explanation else "")
    )
    node_map = _node_map(result)
    if node_map is not None:
        click.echo(f"  {node_map.describe(first.name)}")
    for decision in chain[1:]:
        click.echo(f"  because {display(decision.name)} is kept ({decision.step}): {decision.reason}")
        if node_map is not None:
            click.echo(f"    {display(decision.name)}: {node_map.describe(decision.name)}")


def _node_map(result: Selection):
    """The graph nodes of a problem imported from a scene graph (its sidecar), else None."""
    from relevance_plan.scene_graphs.sidecar import read_node_map

    return read_node_map(result.task.problem.path)


def _class_of(result: Selection, name: str) -> str | None:
    class_name = result.scores.element_class.get(name)
    return None if class_name is None else _class_shown(result, class_name)


def _object_named(result: Selection, shown: str) -> str:
    problem = result.task.problem
    name = shown.lower()
    if name in problem.objects:
        return name
    from difflib import get_close_matches

    near = get_close_matches(name, list(problem.objects), n=3)
    hint = f" (did you mean: {', '.join(problem.display(n) for n in near)}?)" if near else ""
    raise UsageError(f"--why: no object '{shown}' in the problem{hint}")
