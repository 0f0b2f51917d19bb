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


# Every schema error names the line of the entry at fault, at every depth, whether the model's own
# reading finds it or its check against the domain: (what is written, what it becomes, the message).
EDITS = [
    ("version: 1", "version: 2", "'version' must be 1"),
    ("domain: coffee", "domain: cereal", "model is for domain 'cereal'"),
    ("entropy_bound: 1.0 ", "entropy_bound: -1 ", "'entropy_bound'"),
    ("  unknown_class_relevance: 0.05", "  unknown_class_relevance: 7", "outside [0, 1]"),
    ("  location: at", "  location: inside", "scene.location 'inside' is not a predicate"),
    ("  location: at", "  location: hand-empty", "takes 0 argument(s)"),
    ("  location: at", "  location: at\n  containment: inside", "scene.containment 'inside' is not a predicate"),
    ("      iced-coffee-with-creamer: 0.4", "      iced-coffee-with-creamer: often", "must be a number"),
    ("    whitener: 0.9\n    stirrer: 0.85", "    whitener: 0.9\n    stirrer: 1.85", "outside [0, 1]"),
    ("    types: [tea]", "    types: [tea, 3]", "'types' must be a list of names"),
    ("    kind_relevance: {default: 0.9}\n  ice:", "    kind_relevance: {default: 9}\n  ice:", "outside [0, 1]"),
    ("    relevance_from: contents", "    relevance_from: walls", "'relevance_from' must be 'contents'"),
    ("      cup: {paper_cup: 0.1}", "      cup: {paper_cup: 1.1}", "outside [0, 1]"),
    ("      whitener: {whole_milk: 0.95", "      whitener: {whole_milk: " + "9" * 5000, "invalid YAML value"),
    ("  reachable: 1.0", "  reachable: 1.0\n  floating: 0.5", "unknown placement condition 'floating'"),
    ("  stirrer:\n    types: [stirrer]", "  stirrer:\n    tipes: [stirrer]", "unknown key 'tipes'"),
]


def _edited_line(edited: str, old: str, new: str) -> int:
    """The line of ``edited`` where the first line ``new`` brought stands."""
    lines = new.split("\n")
    first = next(number for number, text in enumerate(lines) if text not in old.split("\n"))
    return edited[: edited.index(new)].count("\n") + first + 1


@pytest.mark.parametrize("old, new, message", EDITS, ids=[new.split(":")[0].strip() for _, new, _ in EDITS])
def test_every_schema_error_names_its_line_at_every_depth(tmp_path, old, new, message):
    bad = tmp_path / "bad.yaml"
    bad.write_text(_with({old: new}))
    code, _, stderr = run("score", COFFEE_DOMAIN, PROBLEMS / "coffee-simple.pddl", "--model", bad)
    line = one_line_error(stderr)
    assert code == ExitCode.MODEL and message in line, line
    assert f"bad.yaml:{_edited_line(bad.read_text(), old, new)}: " in line, line


def test_a_drafted_model_edited_to_a_predicate_the_domain_lacks_names_the_line(tmp_path):
    drafted = tmp_path / "drafted.yaml"
    code, _, stderr = run("draft-model", COFFEE_DOMAIN, PROBLEMS / "coffee-simple.pddl", "-o", drafted, "-q")
    assert code == 0, stderr
    text = drafted.read_text()
    assert "  containment: none" in text
    drafted.write_text(text.replace("  containment: none", "  containment: inside", 1))
    code, _, stderr = run("plan", COFFEE_DOMAIN, PROBLEMS / "coffee-simple.pddl", "--model", drafted, "-q")
    number = text[: text.index("  containment: none")].count("\n") + 1
    assert code == ExitCode.MODEL and f"drafted.yaml:{number}: scene.containment 'inside'" in one_line_error(stderr)


def test_a_document_that_is_no_mapping_is_refused_at_its_first_line():
    with pytest.raises(ModelError) as caught:
        parse_knowledge_model("- one\n- two\n", "m.yaml")
    assert caught.value.line == 1 and str(caught.value).startswith("m.yaml:1: ")
