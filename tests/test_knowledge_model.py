"""Knowledge models: what is refused (one line, exit 35, the file and line), where models are found."""

from __future__ import annotations

import shutil

import pytest
from support import COFFEE_DOMAIN, COFFEE_MODEL, PROBLEMS, one_line_error, run

from relevance_plan.errors import ModelError
from relevance_plan.exitcodes import ExitCode
from relevance_plan.io import load_domain
from relevance_plan.relevance.scoring.knowledge import (
    check_knowledge_model_applies,
    find_knowledge_model,
    parse_knowledge_model,
)

MODEL_TEXT = COFFEE_MODEL.read_text()
NO_DEPENDENCIES = MODEL_TEXT.replace("dependencies: []\n", "")


def _with(replacements: dict[str, str]) -> str:
    text = MODEL_TEXT
    for old, new in replacements.items():
        assert old in text, old
        text = text.replace(old, new, 1)
    return text


@pytest.mark.parametrize(
    "text, message",
    [
        (_with({"entropy_bound: 1.0": "entropy_bound: .nan"}), "entropy_bound"),
        (_with({"entropy_bound: 1.0": "entropy_bound: .inf"}), "entropy_bound"),
        (_with({"coffee: 0.98": "coffee: " + "9" * 5000}), "invalid YAML value"),
        (_with({"coffee: 0.98": "coffee: 1" + "0" * 400}), "must be a number in [0, 1]"),
        (_with({'support: "on"': "support: [on, under]"}), "scene.support must be one predicate name"),
        (_with({'support: "on"': "support: on"}), "scene.support must be one predicate name"),
        (
            NO_DEPENDENCIES + "dependencies:\n  - {predicate: 'on', when_kept: 1, restore: 99}\n",
            "1-based argument position",
        ),
        (
            NO_DEPENDENCIES + "dependencies:\n  - {predicate: 'two words', when_kept: 1, restore: 2}\n",
            "one predicate name",
        ),
    ],
)
def test_malformed_models_are_refused_naming_the_entry(text, message):
    with pytest.raises(ModelError) as caught:
        parse_knowledge_model(text, "m.yaml")
    assert message in caught.value.message
    assert "\n" not in str(caught.value) and caught.value.path == "m.yaml"


@pytest.mark.parametrize(
    "extra, message",
    [
        ("dependencies:\n  - {predicate: levitates, when_kept: 1, restore: 2}\n", "not a predicate of domain"),
        ("dependencies:\n  - {predicate: 'on', when_kept: 1, restore: 3}\n", r"beyond its 2 argument\(s\)"),
    ],
)
def test_a_model_that_does_not_fit_the_domain_is_refused(extra, message):
    model = parse_knowledge_model(NO_DEPENDENCIES + extra, "m.yaml")
    with pytest.raises(ModelError, match=message) as caught:
        check_knowledge_model_applies(model, load_domain(COFFEE_DOMAIN))
    assert caught.value.line is not None


def test_a_scene_predicate_the_domain_lacks_is_refused():
    model = parse_knowledge_model(_with({"location: at": "location: located"}), "m.yaml")
    with pytest.raises(ModelError, match="scene.location 'located' is not a predicate"):
        check_knowledge_model_applies(model, load_domain(COFFEE_DOMAIN))


def test_every_bad_model_is_exit_35_in_one_line_through_the_cli(tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text(NO_DEPENDENCIES + "dependencies:\n  - {predicate: 'on', when_kept: 1, restore: 3}\n")
    code, _, stderr = run("score", COFFEE_DOMAIN, PROBLEMS / "coffee-simple.pddl", "--model", bad)
    assert code == ExitCode.MODEL and "bad.yaml" in one_line_error(stderr)


def test_a_broken_model_next_to_the_domain_does_not_stop_the_goal_scorer(tmp_path):
    shutil.copy(COFFEE_DOMAIN, tmp_path / "domain.pddl")
    (tmp_path / "relevance.yaml").write_text("version: [unclosed\n")
    problem = PROBLEMS / "coffee-simple.pddl"
    assert run("score", tmp_path / "domain.pddl", problem, "--scorer", "goal")[0] == 0
    code, _, stderr = run("score", tmp_path / "domain.pddl", problem)
    assert code == ExitCode.MODEL and "relevance.yaml" in one_line_error(stderr)


def test_a_domain_name_is_never_a_path_to_a_model(tmp_path):
    assert find_knowledge_model("coffee", None) is not None  # shipped
    for name in ("../..", "../coffee", "coffee/../coffee", "/etc", "."):
        assert find_knowledge_model(name, None) is None
