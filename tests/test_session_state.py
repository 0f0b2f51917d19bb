"""The live state: an index that stays what ``index_init`` makes of the written state, event after event;
the snapshot made once per change; what each change did."""

from __future__ import annotations

import random

import pytest

from relevance_plan.data import DOMAINS_DIR
from relevance_plan.generators import WORLDS, Settings
from relevance_plan.io import load_domain, load_task
from relevance_plan.pddl.formulas import names_in
from relevance_plan.pddl.parser import read_problem
from relevance_plan.relevance.analysis.facts import fan_in
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.session.state import LiveScene


def assert_indexed_as_written(scene: LiveScene) -> None:
    """The live index holds what indexing the written state gives: the same lists, in the same order."""
    written = PlanningTask(scene.domain, read_problem(scene.problem_text(), scene.domain)).init_index
    assert scene.index.by_predicate == {p: list(atoms) for p, atoms in written.by_predicate.items()}
    assert scene.index.by_object == {name: list(atoms) for name, atoms in written.by_object.items()}
    assert scene.index.functional == written.functional
    assert scene.index.singletons == written.singletons
    assert {key: scene.index.fan(*key) for key in fan_in(written)} == pytest.approx(fan_in(written))
    degrees = {len(atoms) for atoms in written.by_object.values()}
    for low in range(0, max(degrees) + 1, 3):
        assert scene.index.any_degree_between(low, low + 2) == any(low < d <= low + 2 for d in degrees)


def test_the_index_follows_facts_objects_and_removals_as_the_written_state_reads():
    domain = load_domain(DOMAINS_DIR / "scenegraph" / "domain.pddl")
    scene = LiveScene(domain, read_problem(WORLDS["scenegraph"].problem(4, 1, Settings(size=150)).pddl_text, domain))
    assert_indexed_as_written(scene)
    rng = random.Random(4)
    places = [n for n, t in scene.objects.items() if t == "place"]
    receptacles = [n for n, t in scene.objects.items() if t == "receptacle"]
    for step in range(150):
        items = [n for n, t in scene.objects.items() if t == "item"]
        roll = rng.random()
        if roll < 0.3:  # a second place for an item: (in ?i ?r) stops being functional, then is again
            item, there = rng.choice(items), rng.choice(receptacles)
            scene.set(("in", item, there)) if rng.random() < 0.5 else scene.unset(("in", item, there))
        elif roll < 0.45:
            scene.add_object(f"thing_{step}", "item", f"Thing_{step}")
            scene.set(("in", f"thing_{step}", rng.choice(receptacles)))
        elif roll < 0.6:
            scene.remove_object(rng.choice([n for n in items if n not in names_in(scene.goal)]))
        elif roll < 0.8:  # the agent nowhere, or in two places: agent-at stops being a singleton
            fact = ("agent-at", "robot", rng.choice(places))
            scene.set(fact) if rng.random() < 0.5 else scene.unset(fact)
        else:
            fact = ("opened", rng.choice(receptacles))
            scene.unset(fact) if fact in scene.facts else scene.set(fact)
        if step % 15 == 0:
            assert_indexed_as_written(scene)
    assert_indexed_as_written(scene)


def test_numeric_terms_link_objects_after_the_facts_in_the_order_values_were_first_set(tmp_path):
    WORLDS["coffee-numeric"].suite(1, 1, tmp_path, Settings("simple"))
    problem_path = sorted(p for p in tmp_path.glob("*.pddl") if p.name != "domain.pddl")[0]
    domain, problem = load_task(tmp_path / "domain.pddl", problem_path)
    scene = LiveScene(domain, problem)
    assert any(len(term) > 1 for term in scene.values)
    assert_indexed_as_written(scene)
    term = next(term for term in scene.values if len(term) > 1)
    scene.set_value(term, scene.values[term] + 1)  # a new value keeps the term where it was
    assert_indexed_as_written(scene)
    scene.remove_object(term[1])  # its values and terms go with it
    assert_indexed_as_written(scene)


def test_the_snapshot_is_made_once_per_change_and_each_change_is_recorded_once():
    domain = load_domain(DOMAINS_DIR / "scenegraph" / "domain.pddl")
    scene = LiveScene(domain, read_problem(WORLDS["scenegraph"].problem(2, 1, Settings(size=60)).pddl_text, domain))
    first = scene.snapshot_problem()
    assert scene.snapshot_problem() is first
    receptacle = next(n for n, t in scene.objects.items() if t == "receptacle")
    scene.add_object("cup_new", "item", "Cup_New")
    scene.set(("in", "cup_new", receptacle))
    assert scene.snapshot_problem() is not first and "cup_new" in scene.snapshot_problem().objects
    delta = scene.take_delta()
    assert delta.objects_added == ["cup_new"] and delta.added == [("in", "cup_new", receptacle)]
    assert not scene.take_delta()  # taken: nothing more changed since
    scene.remove_object("cup_new")
    delta = scene.take_delta()
    assert delta.objects_removed == ["cup_new"] and delta.removed == [("in", "cup_new", receptacle)]
    assert delta.removed_types == {"cup_new": "item"}


def test_the_objects_are_written_grouped_by_type_in_the_order_they_came():
    domain = load_domain(DOMAINS_DIR / "scenegraph" / "domain.pddl")
    scene = LiveScene(domain, read_problem(WORLDS["scenegraph"].problem(2, 1, Settings(size=60)).pddl_text, domain))
    scene.add_object("cup_new", "item", "cup_new")  # items come last: the order stays the scene's own
    scene.add_object("sink_new", "receptacle", "sink_new")  # a receptacle after the items: written with its type
    scene.add_object("lamp_new", "item", "lamp_new")
    written = read_problem(scene.problem_text(), domain).objects
    assert list(scene.snapshot_problem().objects) == list(written)
    types = list(dict.fromkeys(written.values()))
    assert types == list(dict.fromkeys(scene.objects.values()))[: len(types)]
    assert list(written).index("sink_new") < list(written).index("cup_new")
