"""The learned scorer: features, the model file, training from solved problems, planning with a model."""

from __future__ import annotations

import json
import re
from dataclasses import replace
from pathlib import Path

import pytest

from relevance_plan.batch.learn import LabelledProblem, fit_model
from relevance_plan.data import DOMAINS_DIR
from relevance_plan.errors import ModelError
from relevance_plan.generators.classic import generate_classic_problem
from relevance_plan.io import load_domain
from relevance_plan.pddl.parser import read_problem
from relevance_plan.relevance.learning.features import FeatureConfig, object_features
from relevance_plan.relevance.learning.model import load_learned_model, model_text
from relevance_plan.relevance.learning.scorer import KEEP_AT, calibrated, score_learned
from relevance_plan.relevance.scorers import PlanningTask
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
    model = fit_model(load_domain(FERRY), [labelled(i) for i in range(6)], CONFIG, "plan", 0)
    path = tmp_path_factory.mktemp("model") / "ferry.json"
    path.write_text(model_text(model), encoding="utf-8")
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
    again = load_learned_model(write_file(model_file.parent, "again.json", model_text(model)))
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
    from relevance_plan.relevance.prune import prune_with_scores

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


@pytest.mark.parametrize("damage", ["corrupt", "truncated", "other-format"])
def test_a_damaged_model_file_is_refused_naming_the_file(model_file, tmp_path, damage):
    text = model_file.read_text()
    broken = {
        "corrupt": "\x00\x01 not json",
        "truncated": text[: len(text) // 2],
        "other-format": json.dumps({"format": "something-else"}),
    }[damage]
    path = write_file(tmp_path, "broken.json", broken)
    problem = write_file(tmp_path, "p.pddl", ferry_text(1)[0])
    code, _, err = run("plan", FERRY, problem, "--scorer", f"learned:{path}")
    assert code == 35
    assert str(path) in one_line_error(err)
    with pytest.raises(ModelError):
        load_learned_model(path)


def test_the_learned_scorer_needs_its_model():
    code, _, err = run("score", FERRY, FERRY, "--scorer", "learned")
    assert code == 2 and "learned:MODEL" in err


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
    code, out, err = run("learn", FERRY, *training, "-o", model, "--time-limit", "30", "-q")
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
