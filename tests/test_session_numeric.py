"""The live session on a numeric world: fluent values set by events, carried into every written problem."""

from __future__ import annotations

import json

import pytest
from support import run

from relevance_plan import Session
from relevance_plan.generators import WORLDS, Settings
from relevance_plan.io import load_task
from relevance_plan.pddl.model import goal_objects


@pytest.fixture(scope="module")
def numeric_suite(tmp_path_factory):
    out = tmp_path_factory.mktemp("coffee-numeric")
    WORLDS["coffee-numeric"].suite(1, 1, out, Settings("simple"))
    problem = sorted(p for p in out.glob("*.pddl") if p.name != "domain.pddl")[0]
    return out / "domain.pddl", problem


def test_a_set_fluent_event_changes_the_value_and_every_other_value_stays(numeric_suite):
    domain_path, problem_path = numeric_suite
    domain, problem = load_task(domain_path, problem_path)
    session = Session(domain, problem)
    report = session.handle({"event": "set", "fluent": ["battery"], "value": 3})
    assert report.error is None
    written = session.scene.read_problem()
    assert written.numeric_init[("battery",)] == 3.0
    unchanged = {k: v for k, v in problem.numeric_init.items() if k != ("battery",)}
    assert {k: written.numeric_init[k] for k in unchanged} == unchanged
    assert written.metric == problem.metric


def test_removing_an_object_drops_its_values_and_nothing_else(numeric_suite):
    domain_path, problem_path = numeric_suite
    domain, problem = load_task(domain_path, problem_path)
    session = Session(domain, problem)
    place = next(k[1] for k in problem.numeric_init if k[0] == "distance")
    assert place not in goal_objects(problem, domain)  # the session refuses to remove a goal's object
    report = session.handle({"event": "remove", "object": place})
    assert report.error is None, report.error
    written = session.scene.read_problem()
    assert not any(place in key[1:] for key in written.numeric_init)
    assert all(written.numeric_init[k] == v for k, v in problem.numeric_init.items() if place not in k[1:])


@pytest.mark.parametrize(
    "event, needle",
    [
        ({"event": "set", "fluent": ["no-such-function"], "value": 1}, "unknown function"),
        ({"event": "set", "fluent": ["battery", "extra"], "value": 1}, "takes 0 arguments"),
        ({"event": "set", "fluent": ["distance", "nowhere", "nowhere"], "value": 1}, "unknown object"),
        ({"event": "set", "fluent": ["battery"], "value": "3"}, "finite number"),
        ({"event": "set", "fluent": ["battery"], "value": True}, "finite number"),
        ({"event": "set", "fluent": ["battery"], "value": float("inf")}, "finite number"),
        ({"event": "set", "fluent": ["battery"], "value": 1e300}, "at most"),
        ({"event": "unset", "fluent": ["battery"]}, "never unset"),
    ],
)
def test_a_bad_fluent_event_is_refused_and_changes_nothing(numeric_suite, event, needle):
    domain_path, problem_path = numeric_suite
    domain, problem = load_task(domain_path, problem_path)
    session = Session(domain, problem)
    before = session.scene.problem_text()
    report = session.handle(event)
    assert report.error is not None and needle in report.error
    assert session.scene.problem_text() == before


def test_watch_takes_a_fluent_event_and_its_snapshot_holds_the_value(numeric_suite, tmp_path):
    domain_path, problem_path = numeric_suite
    events = tmp_path / "events.jsonl"
    events.write_text(json.dumps({"event": "set", "fluent": ["battery"], "value": 7}) + "\n")
    code, out, err = run("watch", domain_path, problem_path, "--events", events, "--snapshot", tmp_path / "snap")
    assert code == 0, err
    line = json.loads(out.splitlines()[0])
    assert "error" not in line
    snapshot = next((tmp_path / "snap").glob("*.pddl"), None)
    assert snapshot is not None
    assert "(= (battery) 7)" in " ".join(snapshot.read_text().split())
