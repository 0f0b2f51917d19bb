"""The live session on scene graphs: after every event of long random streams (items moved, added and
removed, receptacles and doors opened and closed, the agent seen elsewhere, new goals), each report
is what a fresh determination on the written state says, down to the reasons and the scores."""

from __future__ import annotations

import random

import pytest

from relevance_plan.data import DOMAINS_DIR
from relevance_plan.generators import WORLDS, Settings
from relevance_plan.generators.scenegraph import SceneGraphEvents
from relevance_plan.io import load_domain
from relevance_plan.pddl.formulas import literals
from relevance_plan.pddl.parser import read_problem
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.selection.closure import ConstraintClosure
from relevance_plan.relevance.setup import ScoringOptions, score_problem
from relevance_plan.session import EventReport, Session

SCENEGRAPH_DOMAIN = DOMAINS_DIR / "scenegraph" / "domain.pddl"
# how often each kind of change comes, out of 100
MIX = {"move": 46, "move-goal": 4, "receptacle": 12, "door": 12, "agent": 4, "add": 10, "remove": 8, "goal": 4}


def scene_session(size: int, seed: int, new_place_first: bool = False) -> tuple[Session, SceneGraphEvents]:
    """A session on a generated scene, and its events (``new_place_first``: every item's move seen in
    the new receptacle before it leaves the old)."""
    domain = load_domain(SCENEGRAPH_DOMAIN)
    problem = read_problem(WORLDS["scenegraph"].problem(seed, 1, Settings(size=size)).pddl_text, domain)
    session = Session(domain, problem, ScoringOptions())
    goal = [(atom.predicate, *atom.args) for atom, _ in literals(problem.goal)]
    rng = random.Random(seed)
    events = SceneGraphEvents(dict(problem.objects), problem.init, goal, rng, new_place_first=new_place_first)
    return session, events


def fresh_report(session: Session) -> dict:
    """What a fresh determination says on the written current state, in the report's terms."""
    problem = read_problem(session.scene.problem_text(), session.domain)
    scoring = score_problem(PlanningTask(session.domain, problem), session.options, knowledge_model=session.model)
    first = scoring.first_selection()
    return {
        "kept": sorted(problem.display(n) for n in first.kept),
        "relevant": sorted(problem.display(n) for n in scoring.prune(session.options.thresholds).selected),
        "restored": [
            {"object": problem.display(r.name), "reason": r.describe(problem.spelling)} for r in first.restored
        ],
        "removed": len(first.removed),
        "set_aside": first.set_aside,
        "scores": scoring.scores,
    }


def assert_as_fresh(session: Session, report: EventReport, where: str) -> None:
    """The selection in force after the event, as its report shows it, equals a fresh determination."""
    expected = fresh_report(session)
    shown = {
        "kept": report.kept,
        "relevant": report.relevant,
        "restored": [
            {"object": report.show(r.name), "reason": r.describe(report.spelling)} for r in report.selection.restored
        ],
        "removed": report.removed,
    }
    if report.triggered:
        assert {key: report.to_json()[key] for key in shown} == shown, where
    for key in ("kept", "relevant", "restored", "removed"):
        assert shown[key] == expected[key], f"{where}: {key}"
    assert session.selection.set_aside == expected["set_aside"], where
    current, scores = session.current_scores(), expected["scores"]
    assert current.element_scores == scores.element_scores, where
    assert current.explanations == scores.explanations, where
    assert current.alternatives == scores.alternatives, where
    assert current.element_class == scores.element_class, where


def run_stream(size: int, seed: int, events: int, new_place_first: bool = False) -> dict[str, int]:
    """``events`` changes drawn from ``MIX``, each checked; returns how many events triggered and how
    many kept the selection in force."""
    session, stream = scene_session(size, seed, new_place_first)
    rng = random.Random(seed)
    kinds = [kind for kind, weight in MIX.items() for _ in range(weight)]
    counts = {"events": 0, "triggered": 0}
    for step in range(events):
        kind = rng.choice(kinds)
        among = session.kept if rng.random() < 0.5 else ()
        for event in stream.make(kind, among):
            report = session.handle(event)
            assert report.error is None, (event, report.error)
            counts["events"] += 1
            counts["triggered"] += report.triggered
            assert_as_fresh(session, report, f"seed {seed} step {step}: {event}")
    return counts


@pytest.mark.parametrize("seed", range(3))
def test_every_report_equals_a_fresh_determination_on_a_random_stream(seed):
    counts = run_stream(250, seed, 60)
    assert 0 < counts["triggered"] < counts["events"]


@pytest.mark.slow
@pytest.mark.parametrize("seed", range(3, 9))
def test_every_report_equals_a_fresh_determination_on_long_random_streams(seed):
    counts = run_stream(1200, seed, 400)
    assert 0 < counts["triggered"] < counts["events"]


@pytest.mark.parametrize("seed", range(3))
def test_every_report_equals_a_fresh_determination_when_items_are_seen_in_the_new_place_first(seed):
    # between the two events of a move the item is in two receptacles: each report there too
    counts = run_stream(250, seed, 60, new_place_first=True)
    assert 0 < counts["triggered"] < counts["events"]


@pytest.mark.slow
@pytest.mark.parametrize("seed", range(3, 6))
def test_every_report_equals_a_fresh_determination_on_long_streams_seen_in_the_new_place_first(seed):
    counts = run_stream(1200, seed, 400, new_place_first=True)
    assert 0 < counts["triggered"] < counts["events"]


# --------------------------------------------------------------------------- what an event can change


@pytest.mark.parametrize("new_place_first", [False, True], ids=["old-place-first", "new-place-first"])
def test_items_moved_far_from_what_the_selection_read_trigger_nothing_and_new_ones_keep_it(new_place_first):
    # in either order: an item briefly in two receptacles is one no action makes, and changes no rule
    session, stream = scene_session(600, 1, new_place_first)
    read = session.basis.repair.objects
    for _ in range(10):
        for event in stream.make("move"):
            report = session.handle(event)
            if not read & set(event["fact"][1:]):
                assert not report.triggered, report.reasons
    report = session.handle(stream.make("add")[0])
    assert report.triggered and report.made is False and report.to_json()["selection"] == "kept"
    assert_as_fresh(session, report, "an item added")


def test_a_door_the_repair_read_makes_the_selection_again_and_a_far_one_changes_nothing():
    session, stream = scene_session(600, 1)
    read = session.basis.repair.objects
    doors = [name for name in stream.doors if name in read]
    far = [name for name in stream.doors if name not in read and not session.basis.agents & {name}]
    assert doors and far
    reports = [session.handle(event) for event in stream.make("door", doors[:1])]
    assert any(r.triggered and "selection read: the reachability repair read" in r.reason for r in reports)
    assert all(r.made in (True, None) for r in reports) and any(r.made for r in reports)
    assert_as_fresh(session, reports[-1], "a door it read")
    for event in stream.make("door", far[:1]):
        report = session.handle(event)
        assert not report.triggered or report.made is False, report.reasons
        assert_as_fresh(session, report, "a door far away")


def test_changes_while_nobody_is_served_make_the_next_selection_in_full():
    session, stream = scene_session(300, 2)
    assert session.handle({"event": "goal", "goal": "(and)"}).triggered
    assert session.idle
    for event in stream.make("move") + stream.make("door"):
        assert not session.handle(event).triggered
    goal = "(and " + " ".join(f"(in {item} {stream.holder[item]})" for item in stream.items[:1]) + ")"
    report = session.handle({"event": "goal", "goal": goal})
    assert report.triggered and report.made is True
    assert_as_fresh(session, report, "served again")


def test_a_task_analysis_the_session_does_not_follow_stops_keeping_the_selection(monkeypatch):
    from relevance_plan.session import reuse

    session, stream = scene_session(300, 3)
    monkeypatch.setattr(reuse, "ANALYSES", reuse.ANALYSES | {"new_analysis"})
    session.selection.task.__dict__["new_analysis"] = ()  # as a stage would leave it, once computed
    task = session.selection.task
    basis = reuse.selection_basis(task, session.selection, session.basis.repair, ConstraintClosure.of(task, None))
    assert basis.other_analyses == {"new_analysis"}
    event = stream.make("move")[0]
    session.handle(event)
    changes = reuse.EventChanges(session.scene.take_delta(), frozenset())
    assert "new_analysis" in reuse.selection_read(basis, session.scene, changes)
