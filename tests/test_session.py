"""The live session: events, triggers, incremental == from scratch, cues, planning, the watch command."""

from __future__ import annotations

import json
import random

import pytest
from click.testing import CliRunner
from support import coffee_problem

from relevance_plan.cli import main
from relevance_plan.data import DOMAINS_DIR, PROBLEMS_DIR
from relevance_plan.generators.padded import BLOCKSWORLD_DOMAIN, blocksworld_problem
from relevance_plan.io import load_domain, load_task
from relevance_plan.pddl.parser import read_domain, read_problem
from relevance_plan.pddl.plans import read_plan
from relevance_plan.planning.options import PlanOptions
from relevance_plan.planning.planners.registry import make_planner
from relevance_plan.planning.results import PlanStatus
from relevance_plan.planning.validation import validate_plan
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.setup import ScoringOptions, score_problem
from relevance_plan.session import TRIGGERS, Session

COFFEE_DOMAIN = DOMAINS_DIR / "coffee" / "domain.pddl"
COFFEE_SIMPLE = PROBLEMS_DIR / "coffee-simple.pddl"


def coffee_session(text: str | None = None, options: ScoringOptions = ScoringOptions(), **kw) -> Session:
    domain = load_domain(COFFEE_DOMAIN)
    problem = read_problem(text if text is not None else coffee_problem(), domain)
    return Session(domain, problem, options, domain_path=str(COFFEE_DOMAIN), **kw)


def from_scratch(session: Session):
    """Determination from scratch on the current state: write it out, read it back, score, prune
    (the paper's relevance, and the first selection ``prune`` writes)."""
    problem = read_problem(session.scene.problem_text(), session.domain)
    scoring = score_problem(PlanningTask(session.domain, problem), session.options, knowledge_model=session.model)
    return scoring.scores, scoring.prune(session.options.thresholds), scoring.first_selection()


def assert_same_as_scratch(session: Session, where: str = "", explanations: bool = True) -> None:
    scores, result, first = from_scratch(session)
    current = session.current_scores()
    assert current.sufficient == scores.sufficient, where
    assert current.insufficiency == scores.insufficiency, where
    if not scores.sufficient:
        return
    assert current.element_scores == scores.element_scores, where
    assert current.class_scores == scores.class_scores, where
    assert current.element_class == scores.element_class, where
    if explanations:
        assert current.explanations == scores.explanations, where
    assert current.unknown == scores.unknown, where
    determination = session.determination
    assert determination is not None and session.selection is not None, where
    assert determination.selected == result.selected == session.relevant, where
    assert determination.kept == result.kept, where
    assert {r.name for r in determination.restored} == {r.name for r in result.restored}, where
    assert session.kept == first.kept, where
    assert session.selection.set_aside == first.set_aside, where
    assert_relevant_covers_kept(session)


def assert_relevant_covers_kept(session: Session) -> None:
    """Every kept object is relevant or was put back (closure, soundness, the reachability repair)."""
    selection = session.selection
    assert selection is not None
    if not selection.unpruned_reason:
        assert session.kept - {r.name for r in selection.restored} <= session.relevant


def stand(item: str, place: str) -> list:
    return [["at", item, place], ["on-base", item], ["clear", item]]


# --------------------------------------------------------------------------- event kinds and triggers


def test_add_of_a_relevant_element_triggers_and_keeps_it():
    session = coffee_session()
    report = session.handle(
        {"event": "add", "object": "Mug_3", "type": "cup", "facts": stand("mug_3", "table_1") + [["empty", "mug_3"]]}
    )
    assert report.triggered and "element added: Mug_3" in report.reason
    assert "mug_3" in report.selection.kept and report.added == ("mug_3",)
    assert_same_as_scratch(session)


def test_remove_triggers_and_drops_the_element():
    session = coffee_session()
    assert "paper_cup_1" in session.kept
    report = session.handle({"event": "remove", "object": "paper_cup_1"})
    assert report.triggered and report.reason == "element removed: paper_cup_1"
    assert "paper_cup_1" in report.dropped and "paper_cup_1" not in session.scene.objects
    assert not any("paper_cup_1" in fact for fact in session.scene.facts)
    assert_same_as_scratch(session)


def test_a_fact_among_irrelevant_objects_triggers_nothing():
    session = coffee_session(coffee_problem(extra_plates=4, plate_on_cup=False))
    kept = session.kept
    assert "side_plate_1" not in kept and "side_plate_3" not in kept
    for event in (
        {"event": "set", "fact": ["on", "side_plate_1", "side_plate_3"]},
        {"event": "unset", "fact": ["clear", "side_plate_3"]},
        {"event": "unset", "fact": ["on", "side_plate_1", "side_plate_3"]},
    ):
        report = session.handle(event)
        assert not report.triggered, report.reason
        assert report.error is None
        assert session.kept == kept
        assert_same_as_scratch(session)


def test_a_plate_put_on_the_kept_cup_triggers_and_is_restored_by_closure():
    session = coffee_session(coffee_problem(plate_on_cup=False))
    assert "plastic_cup_1" in session.kept and "dinner_plate_2" not in session.kept
    report = session.handle({"event": "set", "fact": ["on", "dinner_plate_2", "plastic_cup_1"]})
    assert report.triggered and "kept plastic_cup_1" in report.reason
    determination = session.determination
    assert determination is not None
    restored = {r.name: r.describe() for r in determination.restored}
    assert restored["dinner_plate_2"] == "on top of plastic_cup_1 (on dinner_plate_2 plastic_cup_1)"
    # the first selection sets the blocked cup aside while the paper cup stands free; it stays relevant
    assert "plastic_cup_1" in report.dropped and "plastic_cup_1" in report.relevant
    assert "plastic_cup_1" in report.selection.set_aside and "dinner_plate_2" not in report.selection.kept
    assert_same_as_scratch(session)


def test_a_fact_that_changes_the_closure_rules_triggers_even_among_irrelevant_objects():
    # The robot is at one place, and every action that puts it somewhere takes it from where it
    # was: (robot-at ?p) is single-valued, and closure keeps its place.  Seen at a second place
    # (pantry_1, irrelevant), the robot ends that rule; seen only at the first again, it is back.
    session = coffee_session(COFFEE_SIMPLE.read_text())
    session.handle({"event": "add", "object": "pantry_1", "type": "surface", "facts": [["accessible", "pantry_1"]]})
    assert "pantry_1" not in session.kept
    for kind in ("set", "unset"):
        report = session.handle({"event": kind, "fact": ["robot-at", "pantry_1"]})
        assert report.triggered and report.reason.startswith("closure rules changed"), kind
        assert_same_as_scratch(session, kind)


def test_an_item_seen_in_its_new_place_before_it_leaves_the_old_one_changes_no_rule():
    # Every item has one place, and no action gives an item a second one (putting it down takes
    # it from the hand, picking it up takes it from its place), so (at ?i ?p) stays functional
    # while a minority of items are seen in two places: keeping an item keeps both its places.
    # A plate (irrelevant) moved as "there now", then "no longer here" fires nothing.
    session = coffee_session(COFFEE_SIMPLE.read_text())
    session.handle({"event": "add", "object": "pantry_1", "type": "surface", "facts": [["accessible", "pantry_1"]]})
    functional = session.scene.index.functional
    assert ("at", 0, 1) in functional and not {"dinner_plate_1", "cabinet_1", "pantry_1"} & session.kept
    for kind, place in (("set", "pantry_1"), ("unset", "cabinet_1")):
        report = session.handle({"event": kind, "fact": ["at", "dinner_plate_1", place]})
        assert not report.triggered, report.reasons
        assert session.scene.index.functional == functional
        assert_same_as_scratch(session, kind)


def test_items_seen_in_two_places_end_the_rule_once_they_are_half_of_the_items():
    # and every report on the way is what prune says, the scene reading each item's first place
    # in the written state's order (the session's own order of facts once made it another)
    session = coffee_session(COFFEE_SIMPLE.read_text())
    session.handle({"event": "add", "object": "pantry_1", "type": "surface", "facts": [["accessible", "pantry_1"]]})
    items = sorted({fact[1] for fact in session.scene.facts if fact[0] == "at"})
    for count, item in enumerate(items, 1):
        report = session.handle({"event": "set", "fact": ["at", item, "pantry_1"]})
        assert (("at", 0, 1) in session.scene.index.functional) == (2 * count < len(items)), item
        if 2 * count in (len(items), len(items) + 1):
            assert "closure rules changed" in report.reason
        assert_same_as_scratch(session, item)


def test_goal_human_and_cue_events_trigger_once_and_repeats_do_not():
    session = coffee_session(options=ScoringOptions(objective="drink-at-break"))
    for event, reason in (
        (
            {"event": "human", "name": "alice", "preferences": "alice"},
            "human changed: alice (recorded preferences 'alice')",
        ),
        ({"event": "goal", "goal": "(and (coffee-served alice) (stirred paper_cup_1))"}, "goal changed"),
        ({"event": "cue", "activity": "tea"}, "cue: activity tea"),
        ({"event": "cue", "objective": "serve-coffee-with-creamer"}, "cue: objective serve-coffee-with-creamer"),
    ):
        report = session.handle(event)
        assert report.triggered and report.reason == reason
        assert_same_as_scratch(session, reason)
        again = session.handle(event)
        assert not again.triggered and again.error is None
    assert session.options.human == "alice" and session.options.activity == "tea"
    assert "paper_cup_1" in session.selection.selected  # named in the goal


def test_trigger_registry_names():
    assert set(TRIGGERS) == {
        "element-added",
        "element-removed",
        "goal-changed",
        "human-changed",
        "cue-received",
        "kept-touched",
        "relevance-crossed",
        "closure-rules-changed",
        "selection-read",
    }


def test_opening_a_closed_container_can_make_its_contents_relevant():
    # creamer_1 sits in the closed fridge: placement factor 0.85.  With tau_e between the
    # two scores, opening the fridge lifts it over the threshold: a fact among objects
    # that were not kept, which must still trigger.
    session = coffee_session(options=ScoringOptions(human="bob"))
    inside = session.current_scores().element_scores["creamer_1"]
    tau = inside + 0.01
    from relevance_plan.relevance.selection.prune import Thresholds

    session = coffee_session(options=ScoringOptions(human="bob", thresholds=Thresholds(0.2, tau)))
    assert "creamer_1" not in session.kept and "fridge_1" not in session.kept
    report = session.handle({"event": "set", "fact": ["accessible", "fridge_1"]})
    assert report.triggered and "relevance crossed the thresholds: creamer_1" in report.reason
    assert "creamer_1" in session.kept
    assert_same_as_scratch(session)


# --------------------------------------------------------------------------- incremental == from scratch

TYPES = ["cup", "plate", "whitener", "napkin", "tea", "stirrer", "bowl", "drink", "sweetener", "food"]
KINDS = {
    "cup": "paper_cup",
    "plate": "side_plate",
    "whitener": "whole_milk",
    "napkin": "napkin",
    "tea": "tea_bag",
    "stirrer": "stir_stick",
    "bowl": "bowl",
    "drink": "water_bottle",
    "sweetener": "sugar_packet",
    "food": "bagel",
}


def random_event(rng: random.Random, session: Session, counter: list, new_place_first: bool = False) -> dict:
    """A random event; ``new_place_first``: an item is moved by being seen at a new place, then no
    longer at the old one (two events, others in between), instead of the other way round."""
    scene = session.scene
    places = [n for n, t in scene.objects.items() if t in ("surface", "container")]
    items = [n for n, t in scene.objects.items() if t not in ("surface", "container", "human")]
    humans = [n for n, t in scene.objects.items() if t == "human"]
    located = {f[1]: f[2] for f in scene.facts if f[0] == "at"}
    roll = rng.random()
    if new_place_first and 0.3 <= roll < 0.7:
        return _seen_in_the_new_place_first(rng, scene.facts, places, located) or random_event(rng, session, counter)
    if roll < 0.2 or len(items) < 3:
        counter[0] += 1
        type_name = rng.choice(TYPES)
        name = f"{KINDS[type_name]}_{100 + counter[0]}"
        facts = stand(name, rng.choice(places))
        if type_name == "cup":
            facts.append(["empty", name])
        if rng.random() < 0.3 and items:
            below = rng.choice(items)
            facts = [["at", name, located.get(below, places[0])], ["on", name, below], ["clear", name]]
        return {"event": "add", "object": name, "type": type_name, "facts": facts}
    if roll < 0.3:
        goal_names = {a for f in [session.scene.goal] for a in str(f).replace("'", " ").split()}
        candidates = [n for n in items + (places if len(places) > 2 else []) if n not in goal_names]
        if candidates:
            return {"event": "remove", "object": rng.choice(candidates)}
    if roll < 0.55 and located:
        item = rng.choice(sorted(located))
        if rng.random() < 0.5:
            return {"event": "unset", "fact": ["at", item, located[item]]}
        return {"event": "unset" if rng.random() < 0.3 else "set", "fact": ["clear", item]}
    if roll < 0.7:
        unplaced = [i for i in items if i not in located]
        if unplaced:
            return {"event": "set", "fact": ["at", rng.choice(unplaced), rng.choice(places)]}
        a, b = rng.sample(items, 2)
        return {"event": rng.choice(["set", "unset"]), "fact": ["on", a, b]}
    if roll < 0.8:
        return {"event": rng.choice(["set", "unset"]), "fact": ["accessible", rng.choice(places)]}
    if roll < 0.85 and humans:
        cups = [n for n, t in scene.objects.items() if t == "cup"]
        goal = f"(coffee-served {humans[0]})"
        if cups and rng.random() < 0.5:
            goal = f"(and {goal} (stirred {rng.choice(cups)}))"
        return {"event": "goal", "goal": goal}
    if roll < 0.9 and humans:
        return {"event": "human", "name": humans[0], "preferences": rng.choice(["alice", "bob", None])}
    if roll < 0.92:
        robot = next((f for f in scene.facts if f[0] == "robot-at"), None)
        if robot is not None and rng.random() < 0.5:
            return {"event": "unset", "fact": list(robot)}
        if robot is None:
            return {"event": "set", "fact": ["robot-at", rng.choice(places)]}
        counter[0] += 1
        name = f"guest_{counter[0]}"
        return {"event": "add", "object": name, "type": "human", "facts": [["human-at", name, rng.choice(places)]]}
    if roll < 0.96:
        if rng.random() < 0.5:
            return {
                "event": "cue",
                "activity": rng.choice(["cold-brew-coffee", "tea", "water", "hot-coffee-with-creamer"]),
            }
        return {"event": "cue", "objective": rng.choice(["drink-at-break", "serve-coffee-with-creamer"])}
    return rng.choice(
        [
            {"event": "set", "fact": ["on", "nothing_here", places[0]]},
            {"event": "set", "fact": ["teleport", places[0]]},
            {"event": "goal", "goal": "(coffee-served"},
            {"event": "remove", "object": "ghost"},
        ]
    )


def _seen_in_the_new_place_first(rng: random.Random, facts, places: list, located: dict) -> dict | None:
    """Half of a move: an item seen at a second place, or one of an item's two places no longer seen."""
    places_of: dict[str, list] = {}
    for fact in sorted(facts):
        if fact[0] == "at":
            places_of.setdefault(fact[1], []).append(fact[2])
    doubled = sorted(item for item, held in places_of.items() if len(held) > 1)
    if doubled and rng.random() < 0.5:
        item = rng.choice(doubled)
        return {"event": "unset", "fact": ["at", item, rng.choice(places_of[item])]}
    if located:
        item = rng.choice(sorted(located))
        there = [place for place in places if place not in places_of.get(item, ())]
        if there:
            return {"event": "set", "fact": ["at", item, rng.choice(there)]}
    return None


@pytest.mark.parametrize("seed", range(6))
def test_incremental_determination_equals_from_scratch_on_random_streams(seed):
    run_coffee_stream(seed)


@pytest.mark.parametrize("seed", range(6, 9))
def test_incremental_determination_equals_from_scratch_when_items_are_seen_in_the_new_place_first(seed):
    run_coffee_stream(seed, new_place_first=True)


def run_coffee_stream(seed: int, new_place_first: bool = False) -> None:
    """120 random events on the coffee scene, each state checked against a determination from scratch."""
    rng = random.Random(seed)
    session = coffee_session(COFFEE_SIMPLE.read_text(), options=ScoringOptions())
    counter = [0]
    triggered = halfway = 0
    for step in range(120):
        event = random_event(rng, session, counter, new_place_first)
        report = session.handle(event)
        triggered += report.triggered
        placed = [fact[1] for fact in session.scene.facts if fact[0] == "at"]
        halfway += len(set(placed)) < len(placed)  # some item in two places
        assert_same_as_scratch(session, f"seed {seed} step {step}: {event}")
        if step % 20 == 19 and session.sufficient:  # and as the Python API's prune, from the written scene
            import relevance_plan as rp

            how = {"objective": session.options.objective, "human": session.options.human}
            pruned = rp.prune(COFFEE_DOMAIN, session.scene.problem_text(), **how, activity=session.options.activity)
            assert session.kept == pruned.kept, f"seed {seed} step {step}"
    assert 0 < triggered < 120
    assert (halfway > 0) == new_place_first


@pytest.mark.parametrize("seed", range(2))
def test_incremental_equals_from_scratch_with_the_goal_scorer(seed):
    domain = read_domain(BLOCKSWORLD_DOMAIN)
    problem = read_problem(blocksworld_problem(12, seed=seed), domain)
    session = Session(domain, problem, ScoringOptions(scorer="goal"))
    rng = random.Random(seed)
    blocks = list(problem.objects)
    for step in range(40):
        a, b = rng.sample(blocks, 2)
        event = rng.choice(
            [
                {"event": rng.choice(["set", "unset"]), "fact": ["on", a, b]},
                {"event": rng.choice(["set", "unset"]), "fact": ["clear", a]},
                {
                    "event": "add",
                    "object": f"n{step}",
                    "type": "block",
                    "facts": [["ontable", f"n{step}"], ["clear", f"n{step}"]],
                },
            ]
        )
        session.handle(event)
        assert_same_as_scratch(session, f"step {step}: {event}")


# --------------------------------------------------------------------------- idle, insufficient cues, invalid events

IDLE_SCENE = """(define (problem break-table)
  (:domain coffee)
  (:objects counter_1 table_1 - surface  plastic_cup_1 - cup  cold_brew_1 - coffee-source
            whole_milk_1 - whitener  stir_stick_1 - stirrer  napkin_1 - napkin)
  (:init (robot-at counter_1) (hand-empty) (accessible counter_1) (accessible table_1)
         (at plastic_cup_1 counter_1) (on-base plastic_cup_1) (clear plastic_cup_1) (empty plastic_cup_1)
         (at cold_brew_1 counter_1) (on-base cold_brew_1) (clear cold_brew_1)
         (at whole_milk_1 table_1) (on-base whole_milk_1) (clear whole_milk_1)
         (at stir_stick_1 table_1) (on-base stir_stick_1) (clear stir_stick_1)
         (at napkin_1 table_1) (on-base napkin_1) (clear napkin_1))
  (:goal (and)))
"""


def test_idle_scene_triggers_nothing_until_someone_is_served():
    session = coffee_session(IDLE_SCENE, options=ScoringOptions(objective="drink-at-break"))
    assert session.idle and session.selection is None
    for event in (
        {"event": "add", "object": "donut_1", "type": "food", "facts": stand("donut_1", "table_1")},
        {"event": "set", "fact": ["on", "napkin_1", "whole_milk_1"]},
        {"event": "remove", "object": "donut_1"},
        {"event": "add", "object": "alice", "type": "human", "facts": [["human-at", "alice", "table_1"]]},
    ):
        report = session.handle(event)
        assert not report.triggered and report.error is None
    report = session.handle({"event": "human", "name": "alice", "preferences": "alice"})
    assert report.triggered and report.sufficient and "cold_brew_1" in report.relevant
    # the goal is still (and): relevant to Alice, but no planner needs the coffee yet
    assert "cold_brew_1" not in report.selection.kept
    assert not session.idle
    assert_same_as_scratch(session)


def test_insufficient_cues_keep_the_previous_decision_stale_until_a_cue():
    session = coffee_session(options=ScoringOptions(objective="drink-at-break", human="alice"))
    assert session.sufficient
    before = session.kept
    report = session.handle({"event": "human", "name": "alice", "preferences": None})
    assert report.triggered and not report.sufficient and report.stale
    assert "objective ambiguous" in report.insufficiency
    assert report.ask.cue == "activity" and report.ask.options[0] == "cold-brew-coffee"
    assert report.selection.kept == before  # the previous selection stays in force
    # While stale, element events still trigger but the selection waits for cues.
    report = session.handle({"event": "add", "object": "mug_9", "type": "cup", "facts": stand("mug_9", "table_1")})
    assert report.triggered and report.stale and session.kept == before and report.ask.cue == "activity"
    assert_same_as_scratch(session)
    report = session.handle({"event": "cue", "activity": "cold-brew-coffee"})
    assert report.triggered and report.sufficient and not report.stale
    assert "mug_9" in report.added
    assert_same_as_scratch(session)


def test_no_objective_asks_for_one():
    session = coffee_session(IDLE_SCENE)
    session.handle({"event": "add", "object": "bob", "type": "human", "facts": [["human-at", "bob", "table_1"]]})
    report = session.handle({"event": "human", "name": "bob", "preferences": None})
    assert not report.sufficient and report.ask.cue == "objective"
    report = session.handle({"event": "cue", "objective": "drink-at-break"})
    assert not report.sufficient and report.ask.cue == "activity"
    report = session.handle({"event": "cue", "activity": "cold-brew-coffee"})
    assert report.sufficient and report.selection is not None and report.ask.cue == "preference"


@pytest.mark.parametrize(
    "line, message",
    [
        ("{not json", "not a JSON object"),
        ("[1, 2]", "an event must be a JSON object"),
        ('{"event": "explode"}', "unknown event"),
        ('{"event": "remove", "object": "ghost"}', "unknown object 'ghost'"),
        ('{"event": "remove", "object": "alice"}', "named in the goal"),
        ('{"event": "set", "fact": ["on", "plastic_cup_1"]}', "takes 2 arguments, got 1"),
        ('{"event": "set", "fact": ["levitating", "plastic_cup_1"]}', "unknown predicate 'levitating'"),
        ('{"event": "unset", "fact": ["clear", "ghost"]}', "unknown object 'ghost'"),
        ('{"event": "add", "object": "mug_1", "type": "teapot"}', "unknown type 'teapot'"),
        ('{"event": "add", "object": "paper_cup_1", "type": "cup"}', "already in the scene"),
        (
            '{"event": "add", "object": "mug_1", "type": "cup", "facts": [["at", "mug_1", "moon"]]}',
            "unknown object 'moon'",
        ),
        ('{"event": "goal", "goal": "(and (coffee-served alice)"}', "goal does not parse"),
        ('{"event": "goal", "goal": "(coffee-served nobody)"}', "goal does not parse"),
        ('{"event": "goal", "goal": "(served alice)"}', "unknown predicate"),
        ('{"event": "human", "name": "alice", "preferences": "carol"}', "unknown preference profile 'carol'"),
        ('{"event": "cue", "activity": "juggling"}', "unknown activity"),
        ('{"event": "cue"}', "either 'activity' or 'objective'"),
    ],
)
def test_invalid_events_are_rejected_and_the_session_carries_on(line, message):
    session = coffee_session()
    kept, facts, objects = session.kept, set(session.scene.facts), dict(session.scene.objects)
    report = session.handle_line(line)
    assert report.error is not None and message in report.error
    assert not report.triggered
    assert session.kept == kept and session.scene.facts == facts and session.scene.objects == objects
    report = session.handle({"event": "add", "object": "mug_5", "type": "cup", "facts": stand("mug_5", "table_1")})
    assert report.triggered and report.error is None and report.seq == 2


# --------------------------------------------------------------------------- planning in the loop


class CountingPlanner:
    def __init__(self, tmp_path):
        self.planner = make_planner("fast-downward", "lama-first", check=True)
        self.tmp_path = tmp_path
        self.calls = 0

    def __call__(self, text, limit):
        self.calls += 1
        path = self.tmp_path / f"p{self.calls}.pddl"
        path.write_text(text)
        return self.planner.run(str(COFFEE_DOMAIN), str(path), time_limit=limit, memory_limit_mb=None)


@pytest.mark.planner
def test_every_reported_plan_is_valid_on_the_current_state_and_still_valid_plans_are_kept(tmp_path):
    planner = CountingPlanner(tmp_path)
    session = coffee_session(
        COFFEE_SIMPLE.read_text(), run_planner=planner, plan_in_loop=True, plan_options=PlanOptions(timeout=60)
    )
    events = [
        {"event": "plan"},
        {"event": "add", "object": "donut_1", "type": "food", "facts": stand("donut_1", "serving_table_1")},
        {
            "event": "add",
            "object": "Mug_2",
            "type": "cup",
            "facts": stand("mug_2", "serving_table_1") + [["empty", "mug_2"]],
        },
        {"event": "set", "fact": ["on", "dinner_plate_1", "plastic_cup_1"]},
        {"event": "remove", "object": "cold_brew_coffee_1"},
        {
            "event": "add",
            "object": "espresso_1",
            "type": "coffee-source",
            "facts": stand("espresso_1", "kitchen_counter_1"),
        },
        {"event": "plan"},
    ]
    plans = []
    for event in events:
        calls = planner.calls
        report = session.handle(event)
        if report.plan is not None:
            assert (planner.calls > calls) == (report.plan.source == "planner")
        if report.plan is not None and event.get("object") == "cold_brew_coffee_1":
            assert report.plan.status is PlanStatus.UNSOLVABLE  # the only coffee left the scene
        elif report.plan is not None:
            assert report.plan.status is PlanStatus.SOLVED, report.plan.message
            current = session.scene.read_problem()
            assert validate_plan(session.domain, current, report.plan.steps).valid
            plans.append((event["event"], report.plan.source))
    assert plans[0] == ("plan", "planner")
    assert ("add", "previous") in plans  # Mug_2 joined the kept set; the plan did not need it
    assert ("add", "planner") in plans  # espresso arrived after the coffee left: plan again
    assert plans[-1] == ("plan", "previous")


# --------------------------------------------------------------------------- the watch command


def run_watch(tmp_path, events, *args):
    events_file = tmp_path / "events.jsonl"
    events_file.write_text("\n".join(e if isinstance(e, str) else json.dumps(e) for e in events) + "\n")
    result = CliRunner().invoke(
        main, ["watch", str(COFFEE_DOMAIN), str(COFFEE_SIMPLE), "--events", str(events_file), *args]
    )
    return result, [json.loads(line) for line in result.stdout.splitlines()]


def test_watch_writes_one_line_per_event_and_a_snapshot_prune_agrees_with(tmp_path):
    events = [
        {"event": "add", "object": "Mug_2", "type": "cup", "facts": stand("Mug_2", "serving_table_1")},
        "this is not json",
        {"event": "set", "fact": ["on", "dinner_plate_1", "tea_bag_1"]},
        {"event": "set", "fact": ["on", "dinner_plate_1", "Mug_2"]},
        {"event": "set", "fact": ["on", "ghost", "Mug_2"]},
    ]
    result, lines = run_watch(tmp_path, events, "--snapshot", str(tmp_path / "snap"))
    assert result.exit_code == 0, result.stderr
    assert [line["seq"] for line in lines] == [1, 2, 3, 4, 5]
    for line in lines:
        assert {
            "seq",
            "event",
            "triggered",
            "reason",
            "sufficient",
            "added",
            "dropped",
            "ask",
            "determination_ms",
        } <= line.keys()
    assert lines[0]["triggered"] and "Mug_2" in lines[0]["kept"] and lines[0]["kept"] == sorted(lines[0]["kept"])
    assert lines[1]["error"].startswith("not a JSON object") and not lines[1]["triggered"]
    assert "error" in lines[4] and "unknown object 'ghost'" in lines[4]["error"]
    # the plate blocks Mug_2: the first selection sets the mug aside (free cups remain); it stays relevant
    assert lines[3]["triggered"] and "Mug_2" in lines[3]["dropped"] and "Mug_2" in lines[3]["relevant"]
    kept = next(line["kept"] for line in reversed(lines) if line["triggered"])

    current = tmp_path / "snap" / "current.pddl"
    domain, problem = load_task(COFFEE_DOMAIN, current)
    assert "Mug_2" in problem.spelling.objects.values()  # the user's spelling
    pruned = read_problem((tmp_path / "snap" / "pruned.pddl").read_text(), domain)
    assert sorted(pruned.display(n) for n in pruned.objects) == kept
    # the session reports as kept the first selection prune writes; relevant is the paper's relevant set
    scoring = score_problem(PlanningTask(domain, problem), ScoringOptions())
    assert sorted(problem.display(n) for n in scoring.first_selection().kept) == kept
    relevant = next(line["relevant"] for line in reversed(lines) if line["triggered"])
    assert relevant == sorted(problem.display(n) for n in scoring.prune(ScoringOptions().thresholds).selected)
    result = CliRunner().invoke(
        main, ["prune", str(COFFEE_DOMAIN), str(current), "-o", str(tmp_path / "p.pddl"), "--json"]
    )
    assert result.exit_code == 0, result.stderr
    assert sorted(json.loads(result.stdout)["kept"]) == kept


@pytest.mark.planner
def test_watch_with_plan_reports_validated_plans(tmp_path):
    events = [
        {
            "event": "add",
            "object": "mug_2",
            "type": "cup",
            "facts": stand("mug_2", "serving_table_1") + [["empty", "mug_2"]],
        },
        {"event": "remove", "object": "plastic_cup_1"},
        {"event": "remove", "object": "paper_cup_1"},
        {"event": "plan"},
    ]
    result, lines = run_watch(tmp_path, events, "--plan", "--snapshot", str(tmp_path / "snap"), "--timeout", "60")
    assert result.exit_code == 0, result.stderr
    planned = [line for line in lines if "plan_status" in line]
    assert planned and all(line["plan_status"] == "solved" for line in planned)
    assert lines[-1]["plan_source"] == "previous"
    domain, problem = load_task(COFFEE_DOMAIN, tmp_path / "snap" / "current.pddl")
    steps = read_plan("\n".join(lines[-1]["plan"]))
    assert validate_plan(domain, problem, steps).valid
    assert any("mug_2" in step for step in lines[-1]["plan"])


def test_watch_missing_file_is_one_line_and_exit_code_31(tmp_path):
    result = CliRunner().invoke(
        main, ["watch", str(COFFEE_DOMAIN), str(tmp_path / "missing.pddl"), "--events", "-"], input=""
    )
    assert result.exit_code == 31
    assert result.stderr.count("\n") == 1 and "Traceback" not in result.stderr
    result = CliRunner().invoke(
        main, ["watch", str(COFFEE_DOMAIN), str(COFFEE_SIMPLE), "--events", str(tmp_path / "none.jsonl")]
    )
    assert result.exit_code == 31 and "events file not found" in result.stderr


@pytest.mark.planner
def test_watch_reads_standard_input_until_it_ends(tmp_path):
    result = CliRunner().invoke(
        main,
        ["watch", str(COFFEE_DOMAIN), str(COFFEE_SIMPLE)],
        input='{"event": "set", "fact": ["clear", "dinner_plate_1"]}\n\n{"event": "plan"}\n',
    )
    assert result.exit_code == 0, result.stderr
    lines = [json.loads(line) for line in result.stdout.splitlines()]
    assert len(lines) == 2 and lines[0]["triggered"] is False


# --------------------------------------------------------------------------- the shipped example and the README

REPO = COFFEE_DOMAIN.parents[4] if (COFFEE_DOMAIN.parents[4] / "examples").is_dir() else None


@pytest.mark.skipif(REPO is None, reason="needs the source tree (examples/, README.md)")
def test_the_shipped_example_replays_the_paper_demonstration():
    domain, problem = load_task(COFFEE_DOMAIN, REPO / "examples" / "coffee-break" / "scene.pddl")
    session = Session(domain, problem, ScoringOptions(objective="drink-at-break"))
    lines = (REPO / "examples" / "coffee-break" / "events.jsonl").read_text().splitlines()
    reports = [session.handle_line(line) for line in lines]
    assert all(r.error is None for r in reports)
    assert [r.triggered for r in reports] == [False] * 6 + [True] * 6 + [False]
    alice, alice_goal, bob_arrives, bob, bob_goal, cue = reports[6:12]
    assert alice.sufficient and "paper_cup_1" not in alice.selection.kept  # she dislikes paper cups
    assert alice.ask is None and bob_arrives.sufficient
    assert not bob.sufficient and bob.ask.cue == "activity" and bob.stale
    assert not bob_goal.sufficient and bob_goal.selection.kept == bob_arrives.selection.kept
    assert cue.sufficient and not cue.stale and cue.ask.cue == "preference" and "bob" in cue.selection.kept


def test_watch_on_the_shipped_example_reports_what_prune_keeps_after_every_event(tmp_path):
    import relevance_plan as rp
    from relevance_plan.data import EXAMPLES_DIR

    scene = EXAMPLES_DIR / "coffee-break" / "scene.pddl"
    lines = (EXAMPLES_DIR / "coffee-break" / "events.jsonl").read_text().splitlines()
    domain, problem = load_task(COFFEE_DOMAIN, scene)
    session = Session(domain, problem, ScoringOptions(objective="drink-at-break"))
    for count, line in enumerate(lines, 1):
        report = session.handle_line(line)
        # watch on the events so far: its last determination and its snapshot
        events_file = tmp_path / "events.jsonl"
        events_file.write_text("\n".join(lines[:count]) + "\n")
        snap = tmp_path / f"snap-{count}"
        args = [str(COFFEE_DOMAIN), str(scene), "--events", str(events_file), "--objective", "drink-at-break"]
        result = CliRunner().invoke(main, ["watch", *args, "--snapshot", str(snap)])
        assert result.exit_code == 0, result.stderr
        out = [json.loads(text) for text in result.stdout.splitlines()]
        determined = [o for o in out if o["triggered"] and o["sufficient"]]
        if session.selection is None:
            assert not determined
            continue
        current = (snap / "current.pddl").read_text()
        assert current == session.scene.problem_text()
        how = session.options  # the human and task cues the events gave
        pruned = rp.prune(COFFEE_DOMAIN, current, objective=how.objective, human=how.human, activity=how.activity)
        shown = {pruned.task.problem.display(n) for n in pruned.kept}
        if report.sufficient:
            assert {session.scene.display[n] for n in session.kept} == shown, line
        assert sorted(shown) == determined[-1]["kept"] or not report.sufficient, line
        assert set(determined[-1]["relevant"]) >= set(determined[-1]["kept"]) - {
            r["object"] for r in determined[-1]["restored"]
        }
        assert_relevant_covers_kept(session)
    assert determined[-1]["kept"] != determined[-1]["relevant"]  # the first selection narrows


@pytest.mark.skipif(REPO is None, reason="needs the source tree (examples/, README.md)")
def test_the_readme_session_snippet_runs(monkeypatch):
    readme = (REPO / "README.md").read_text()
    snippet = next(block for block in readme.split("```python")[1:] if "rp.Session" in block)
    monkeypatch.chdir(REPO)
    namespace: dict = {}
    exec(snippet.split("```")[0], namespace)
    report = namespace["report"]
    assert report.triggered and report.reason == "human changed: Alice (recorded preferences 'alice')"
