"""The learned scorer: features, the model file, training from solved problems, planning with a model."""

from __future__ import annotations

import json
import re
from dataclasses import replace
from pathlib import Path

import pytest

from relevance_plan.data import DOMAINS_DIR
from relevance_plan.errors import ModelError
from relevance_plan.generators.classic import generate_classic_problem
from relevance_plan.io import load_domain
from relevance_plan.pddl.parser import read_domain, read_problem
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.scoring.learning.features import NAMED, FeatureConfig, hub_predicates, object_features
from relevance_plan.relevance.scoring.learning.fit import LabelledProblem, fit_learned_model, with_hubs
from relevance_plan.relevance.scoring.learning.learned_model import learned_model_text, load_learned_model
from relevance_plan.relevance.scoring.learning.scorer import KEEP_AT, calibrated, score_learned
from tests.support import one_line_error, run, write_file

FERRY = Path(DOMAINS_DIR) / "ferry-typed" / "domain.pddl"
GRIPPER = Path(DOMAINS_DIR) / "gripper-typed" / "domain.pddl"
CONFIG = FeatureConfig(iterations=2, buckets=512)


def ferry_text(index: int, size: int = 10) -> tuple[str, list[str]]:
    problem = generate_classic_problem("ferry-typed", 0, index, size=size)
    return problem.pddl_text, list(problem.sidecar["necessary"])


def ferry_task(text: str) -> PlanningTask:
    domain = load_domain(FERRY)
    return PlanningTask(domain, read_problem(text, domain, "problem.pddl"))


def reordered(text: str) -> str:
    """The same problem with its object declarations and initial facts in reverse order."""
    objects = re.search(r"\(:objects\n(.*?)\n  \)", text, re.S)
    init = re.search(r"\(:init\n(.*?)\n  \)", text, re.S)
    assert objects and init
    flipped = text.replace(objects.group(1), "\n".join(reversed(objects.group(1).splitlines())))
    return flipped.replace(init.group(1), "\n".join(reversed(init.group(1).splitlines())))


def labelled(index: int) -> LabelledProblem:
    """A training problem labelled by the generator's sufficient set (no planner)."""
    text, necessary = ferry_text(index)
    task = ferry_task(text)
    features = object_features(task, CONFIG)
    return LabelledProblem(
        f"ferry-{index}",
        len(task.problem.objects),
        frozenset(necessary),
        dict(features.vectors),
        types=frozenset(t for types in features.types.values() for t in types),
        predicates=frozenset(p for ps in features.predicates.values() for p in ps),
    )


@pytest.fixture(scope="module")
def model_file(tmp_path_factory) -> Path:
    model = fit_learned_model(load_domain(FERRY), [labelled(i) for i in range(6)], CONFIG, "plan", 0)
    path = tmp_path_factory.mktemp("model") / "ferry.json"
    path.write_text(learned_model_text(model), encoding="utf-8")
    return path


def test_features_do_not_depend_on_the_order_of_objects_or_facts():
    text, _ = ferry_text(3, size=20)
    first = object_features(ferry_task(text), CONFIG)
    second = object_features(ferry_task(reordered(text)), CONFIG)
    assert reordered(text) != text
    assert first.vectors == second.vectors
    assert first.goal_scores == second.goal_scores


def test_a_model_round_trips_through_its_file(model_file):
    model = load_learned_model(model_file)
    again = load_learned_model(write_file(model_file.parent, "again.json", learned_model_text(model)))
    task = ferry_task(ferry_text(20, size=30)[0])
    vectors = object_features(task, model.config).vectors
    assert {n: model.probability(v) for n, v in vectors.items()} == {
        n: again.probability(v) for n, v in vectors.items()
    }
    assert json.loads(model_file.read_text())["domain"]["name"] == "ferry-typed"


def test_the_model_ranks_needed_objects_above_distractors(model_file):
    model = load_learned_model(model_file)
    text, necessary = ferry_text(30, size=40)
    task = ferry_task(text)
    vectors = object_features(task, model.config).vectors
    needed = [model.probability(vectors[n]) for n in necessary if n not in task.goal_objects]
    others = [model.probability(vectors[n]) for n in task.problem.objects if n not in necessary]
    assert needed and others
    assert sum(needed) / len(needed) > 2 * sum(others) / len(others)
    # and the first selection keeps every object a plan needs, fewer than all
    from relevance_plan.relevance.selection.prune import prune_with_scores

    kept = prune_with_scores(task, score_learned(task, model)).kept
    assert set(necessary) <= kept and len(kept) < len(task.problem.objects)


def test_the_calibration_maps_the_models_threshold_onto_the_default_element_threshold():
    assert calibrated(0.3, 0.3) == pytest.approx(KEEP_AT)
    assert calibrated(0.0, 0.3) == 0.0 and calibrated(1.0, 0.3) == pytest.approx(1.0)
    assert calibrated(0.2, 0.3) < calibrated(0.31, 0.3)


def test_objects_of_a_type_the_model_never_saw_are_kept(model_file):
    model = replace(load_learned_model(model_file), seen_types=frozenset({"location"}))
    task = ferry_task(ferry_text(5, size=20)[0])
    result = score_learned(task, model)
    cars = [n for n, t in task.problem.objects.items() if t == "car"]
    assert all(result.element_scores[n] == 1.0 for n in cars)
    assert "never saw" in result.explanations[next(n for n in cars if n not in task.goal_objects)]


def test_a_model_of_another_domain_is_refused_in_one_line(model_file, tmp_path):
    problem = generate_classic_problem("gripper-typed", 0, 0, size=10)
    path = write_file(tmp_path, "gripper.pddl", problem.pddl_text)
    code, _, err = run("score", GRIPPER, path, "--scorer", f"learned:{model_file}")
    assert code == 35
    assert "learned for domain 'ferry-typed', not 'gripper-typed'" in one_line_error(err)


def _damaged(text: str, damage: str) -> str:
    model = json.loads(text)
    if damage == "corrupt":
        return "\x00\x01 not json"
    if damage == "truncated":
        return text[: len(text) // 2]
    if damage == "other-format":
        return json.dumps({"format": "something-else"})
    if damage == "deep-nesting":
        return text.replace('"training": {', '"training": {"deep": ' + "[" * 100_000 + "]" * 100_000 + ", ", 1)
    changed = {
        "infinite-weight": ("weights", {**model["weights"], "named": dict.fromkeys(model["weights"]["named"], 1e999)}),
        "text-for-a-number": ("threshold", "0.5"),
        "a-bool-for-a-number": ("threshold", True),
        "features-a-list": ("features", [3, 512]),
        "iterations-infinite": ("features", {**model["features"], "iterations": 1e999}),
        "names-not-text": ("seen_types", [1, 2]),
        "training-a-list": ("training", [1]),
    }[damage]
    return json.dumps({**model, changed[0]: changed[1]})


DAMAGES = [
    "corrupt",
    "truncated",
    "other-format",
    "deep-nesting",
    "infinite-weight",
    "text-for-a-number",
    "a-bool-for-a-number",
    "features-a-list",
    "iterations-infinite",
    "names-not-text",
    "training-a-list",
]


@pytest.mark.parametrize("damage", DAMAGES)
def test_a_damaged_model_file_is_refused_naming_the_file(model_file, tmp_path, damage):
    broken = _damaged(model_file.read_text(), damage)
    path = write_file(tmp_path, "broken.json", broken)
    problem = write_file(tmp_path, "p.pddl", ferry_text(1)[0])
    code, _, err = run("plan", FERRY, problem, "--scorer", f"learned:{path}")
    assert code == 35
    assert str(path) in one_line_error(err)
    with pytest.raises(ModelError):
        load_learned_model(path)


def test_a_missing_model_file_is_exit_31_as_every_missing_file(tmp_path):
    problem = write_file(tmp_path, "p.pddl", ferry_text(1)[0])
    for command in ("score", "plan"):
        for missing in (tmp_path / "nowhere.json", tmp_path):
            code, _, err = run(command, FERRY, problem, "--scorer", f"learned:{missing}")
            assert code == 31 and str(missing) in one_line_error(err)
    code, _, err = run("score", FERRY, problem, "--model", tmp_path / "nowhere.yaml")
    assert code == 31 and "nowhere.yaml" in one_line_error(err)


def test_the_learned_scorer_needs_its_model():
    code, _, err = run("score", FERRY, FERRY, "--scorer", "learned")
    assert code == 30 and "learned:MODEL" in one_line_error(err)  # a bad value of --scorer, as any other


def test_training_problems_of_another_domain_are_refused_before_planning(tmp_path):
    gripper = write_file(tmp_path, "g.pddl", generate_classic_problem("gripper-typed", 0, 0, size=10).pddl_text)
    ferry = write_file(tmp_path, "f.pddl", ferry_text(0)[0])
    out = tmp_path / "model.json"
    code, _, err = run("learn", FERRY, ferry, gripper, "-o", out)
    assert code == 34
    one_line_error(err)
    assert not out.exists()


@pytest.mark.planner
def test_learn_then_plan_with_the_model_gives_a_plan_valid_on_the_original(tmp_path):
    training = [write_file(tmp_path, f"train{i}.pddl", ferry_text(i)[0]) for i in range(4)]
    model = tmp_path / "ferry.json"
    code, out, err = run("learn", FERRY, *training, "-o", model, "--timeout", "30", "-q")
    assert code == 0, err
    assert "learned from 4 problems" in out
    loaded = load_learned_model(model)
    assert loaded.labels == "plan" and loaded.training["problems"] == 4
    text, necessary = ferry_text(40, size=40)
    scores = score_learned(ferry_task(text), loaded).element_scores
    task = ferry_task(text)
    distractors = [n for n in task.problem.objects if n not in necessary]
    assert sum(scores[n] for n in necessary) / len(necessary) > sum(scores[n] for n in distractors) / len(distractors)
    problem = write_file(tmp_path, "test.pddl", text)
    code, out, err = run(
        "plan", FERRY, problem, "--scorer", f"learned:{model}", "--no-race", "--json", "--plan-file", tmp_path / "p"
    )
    assert code == 0, err
    result = json.loads(out)
    assert result["status"] == "solved" and result["valid"] and result["validation"] == "valid"
    assert result["objects_kept"] < result["objects_total"]


GATE_DOMAIN = """(define (domain gate)
  (:requirements :strips)
  (:predicates (open) (inside))
  (:action enter :parameters () :precondition (open) :effect (inside)))
"""
GATE_PROBLEM = "(define (problem shut) (:domain gate) (:init) (:goal (inside)))\n"


@pytest.mark.planner
def test_a_training_problem_proved_unsolvable_is_reported_so(tmp_path):
    domain = write_file(tmp_path, "gate.pddl", GATE_DOMAIN)
    problem = write_file(tmp_path, "shut.pddl", GATE_PROBLEM)
    code, _, err = run("learn", domain, problem, "-o", tmp_path / "m.json", "--timeout", "10")
    assert code == 30 and "not solved within" not in err
    assert "unsolvable (the planner proved it has no plan)" in err.splitlines()[-1]
    assert "[1/1]" in err.splitlines()[0] and "skipped (unsolvable" in err.splitlines()[0]
    assert not (tmp_path / "m.json").exists()


@pytest.mark.planner
def test_solved_training_problems_without_objects_are_nothing_to_learn_from(tmp_path):
    domain = write_file(tmp_path, "gate.pddl", GATE_DOMAIN)
    problem = write_file(tmp_path, "open.pddl", GATE_PROBLEM.replace("(:init)", "(:init (open))"))
    code, _, err = run("learn", domain, problem, "-o", tmp_path / "m.json", "-q", "--timeout", "10")
    assert code == 30 and "no objects" in one_line_error(err)


SHUTTLE_DOMAIN = """(define (domain shuttle)
  (:requirements :strips :typing)
  (:types place crate)
  (:predicates (at ?c - crate ?p - place) (here ?p - place) (different ?a - place ?b - place) (dock ?p - place))
  (:action go :parameters (?a - place ?b - place)
    :precondition (and (here ?a) (different ?a ?b)) :effect (and (here ?b) (not (here ?a)))))
"""


def shuttle_task(places: int, crates: int, skip: tuple[int, int] | None = None, reverse: bool = False) -> PlanningTask:
    """Places linked pairwise by ``different`` (a hub predicate), crates at some of them; ``skip``
    leaves out one ``different`` fact; ``reverse`` lists objects and facts backwards."""
    names = [f"p{i}" for i in range(places)]
    objects = [f"{n} - place" for n in names] + [f"c{i} - crate" for i in range(crates)]
    facts = ["(here p0)", "(dock p1)"] + [f"(at c{i} p{i % places})" for i in range(crates)]
    facts += [f"(different p{a} p{b})" for a in range(places) for b in range(places) if a != b and (a, b) != skip]
    if reverse:
        objects, facts = objects[::-1], facts[::-1]
    text = (
        "(define (problem shuttle-1) (:domain shuttle)\n(:objects "
        + " ".join(objects)
        + ")\n(:init "
        + " ".join(facts)
        + ")\n(:goal (at c0 p1)))\n"
    )
    domain = read_domain(SHUTTLE_DOMAIN, "shuttle.pddl")
    return PlanningTask(domain, read_problem(text, domain, "shuttle-1.pddl"))


def test_a_predicate_linking_every_pair_is_a_hub_and_a_sparse_one_is_not():
    assert hub_predicates(shuttle_task(12, 3)) == {"different"}
    assert hub_predicates(shuttle_task(3, 30)) == frozenset()  # 6 facts among 33 objects


def test_a_hub_marks_positions_instead_of_linking_pairs():
    # every place still fills both positions of 'different' without one of its facts: nothing changes
    full = object_features(shuttle_task(12, 3), CONFIG).vectors
    assert object_features(shuttle_task(12, 3, skip=(4, 7)), CONFIG).vectors == full
    # a predicate the model treats as a hub is one on a small problem too
    small = shuttle_task(3, 30)
    linked = object_features(small, CONFIG).vectors
    marked = object_features(small, replace(CONFIG, hubs=frozenset({"different"}))).vectors
    assert linked != marked
    assert (
        object_features(shuttle_task(3, 30, skip=(1, 2)), replace(CONFIG, hubs=frozenset({"different"}))).vectors
        == marked
    )


def test_features_with_a_hub_do_not_depend_on_the_order_of_objects_or_facts():
    assert (
        object_features(shuttle_task(15, 6), CONFIG).vectors
        == object_features(shuttle_task(15, 6, reverse=True), CONFIG).vectors
    )


def test_learning_marks_a_hub_of_any_training_problem_on_every_problem(model_file, tmp_path):
    domain = read_domain(SHUTTLE_DOMAIN, "shuttle.pddl")
    config = with_hubs(CONFIG, domain, [shuttle_task(3, 30).problem, shuttle_task(12, 3).problem])
    assert config.hubs == {"different"}
    # the model file keeps them
    model = replace(load_learned_model(model_file), config=config)
    assert load_learned_model(write_file(tmp_path, "hubs.json", learned_model_text(model))).config == config


def test_describing_only_the_judged_objects_leaves_their_features_as_they_were():
    task = ferry_task(ferry_text(7, size=30)[0])
    everything = object_features(task, CONFIG)
    judged = object_features(task, CONFIG, only_judged=True)
    left_out = {n for n in task.problem.objects if n in task.goal_objects or not everything.goal_scores.get(n)}
    assert left_out and len(left_out) < len(task.problem.objects)
    for name, vector in judged.vectors.items():
        if name in left_out:
            assert all(index < NAMED for index in vector)
        else:
            assert vector == everything.vectors[name]
