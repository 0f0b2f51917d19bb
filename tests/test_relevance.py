"""The relevance model's formulas, cue sufficiency, closure rules and scorers on tiny problems."""

import math
import sys

import pytest
from support import coffee_problem

from relevance_plan.data import DOMAINS_DIR
from relevance_plan.errors import MissingExtraError, ModelError, UsageError
from relevance_plan.generators import WORLDS, Settings
from relevance_plan.generators.padded import BLOCKSWORLD_DOMAIN, GRIPPER_DOMAIN, blocksworld_problem, gripper_problem
from relevance_plan.io import load_domain
from relevance_plan.pddl.parser import read_domain, read_problem
from relevance_plan.relevance.analysis.constraint_rules import infer_constraint_rules, single_valued_predicates
from relevance_plan.relevance.analysis.facts import index_init
from relevance_plan.relevance.analysis.goal_regression import _Regression
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.scoring.knowledge import parse_knowledge_model
from relevance_plan.relevance.scoring.scorers import SCORERS, ScoreRequest
from relevance_plan.relevance.scoring.scorers.knowledge_model import activity_entropy
from relevance_plan.relevance.selection.closure import close_over_constraints
from relevance_plan.relevance.selection.prune import PruneSettings, Thresholds, prune_with_scores, select_relevant

MODEL = """
version: 1
domain: coffee
entropy_bound: 1.0
defaults: {unknown_class_relevance: 0.05, kind_relevance: 0.5}
objectives:
  coffee:
    goal_predicates: [coffee-served]
    tasks: {hot: 0.75, iced: 0.25}
  drink:
    tasks: {hot: 0.4, tea: 0.35, water: 0.25}
tasks:
  hot: {coffee: 1.0, cup: 0.9, whitener: 0.8, stirrer: 0.6}
  iced: {coffee: 1.0, cup: 0.9, whitener: 0.4}
  tea: {cup: 0.9}
  water: {cup: 0.5}
classes:
  coffee: {types: [coffee-source]}
  cup:
    types: [cup]
    kind_relevance: {plastic_cup: 0.8, paper_cup: 0.4}
  whitener: {types: [whitener], kind_relevance: {default: 0.5}}
  stirrer: {types: [stirrer]}
  plate: {types: [plate]}
  person: {types: [human], relevance: 1.0}
  location: {types: [place], relevance_from: contents}
placement:
  in-closed-container: 0.8
  covered: 0.9
humans:
  dana:
    objectives:
      drink: {tea: 1.0}
    tasks:
      tea: {whitener: 0.7}
    kind_relevance:
      cup: {paper_cup: 1.0}
"""


@pytest.fixture
def task(coffee_domain_path):
    domain = load_domain(coffee_domain_path)
    return PlanningTask(domain, read_problem(coffee_problem(), domain, "p.pddl"))


@pytest.fixture
def model():
    return parse_knowledge_model(MODEL, "m.yaml")


def score(planning_task, model, **kwargs):
    return SCORERS["model"](planning_task, ScoreRequest(knowledge_model=model, **kwargs))


def test_class_relevance_sums_over_tasks(task, model):
    result = score(task, model)
    assert result.objective == "coffee"
    assert result.class_scores["cup"] == pytest.approx(0.9 * 0.75 + 0.9 * 0.25)
    assert result.class_scores["whitener"] == pytest.approx(0.8 * 0.75 + 0.4 * 0.25)
    assert result.class_scores["stirrer"] == pytest.approx(0.6 * 0.75)  # iced does not mention stirrers
    assert result.class_scores["plate"] == 0.0


def test_element_relevance_is_class_times_kind_times_placement(task, model):
    result = score(task, model)
    r_cup = result.class_scores["cup"]
    # the plastic cup has a plate on it: covered 0.9
    assert result.element_scores["plastic_cup_1"] == pytest.approx(r_cup * 0.8 * 0.9)
    assert result.element_scores["paper_cup_1"] == pytest.approx(r_cup * 0.4)
    # the creamer is in the closed fridge: placement 0.8; class default kind 0.5
    assert result.element_scores["creamer_1"] == pytest.approx(result.class_scores["whitener"] * 0.5 * 0.8)
    # places are as relevant as the best item they hold
    assert result.element_scores["fridge_1"] == pytest.approx(result.element_scores["creamer_1"])


def test_entropy_test_reports_ambiguity_with_leading_tasks(task, model):
    result = score(task, model, objective="drink")
    assert not result.sufficient
    assert result.activity_entropy == pytest.approx(activity_entropy({"hot": 0.4, "tea": 0.35, "water": 0.25}))
    assert result.activity_entropy == pytest.approx(
        -(0.4 * math.log(0.4) + 0.35 * math.log(0.35) + 0.25 * math.log(0.25))
    )
    assert "objective ambiguous: hot 0.40, tea 0.35" in result.insufficiency
    assert "--activity or --human" in result.insufficiency


def test_task_or_human_resolves_ambiguity(task, model):
    assert score(task, model, objective="drink", activity="hot").sufficient
    preferred = score(task, model, objective="drink", human="dana")
    assert preferred.sufficient and preferred.activity_distribution == {"tea": 1.0}
    assert preferred.class_scores["whitener"] == pytest.approx(0.7)  # the human's preference, not the prior (absent)
    assert preferred.element_scores["paper_cup_1"] == pytest.approx(0.9 * 1.0)  # dana's kind preference


def test_no_matching_objective_is_insufficient(coffee_domain_path, model):
    domain = load_domain(coffee_domain_path)
    text = coffee_problem().replace("(coffee-served alice)", "(stirred plastic_cup_1)")
    result = score(PlanningTask(domain, read_problem(text, domain)), model)
    assert not result.sufficient and "--objective" in result.insufficiency


def test_unknown_names_are_errors(task, model):
    with pytest.raises(ModelError, match="unknown human 'zed'"):
        score(task, model, human="zed")
    # one token is a name, never words: near no name of the model, it is the model's error
    with pytest.raises(ModelError, match="unknown objective 'lunch' \\(the model's objectives: "):
        score(task, model, objective="lunch")
    with pytest.raises(ModelError, match="unknown activity 'soup' \\(the model's activities: "):
        score(task, model, activity="soup")


@pytest.mark.parametrize(
    "kwargs, match",
    [
        ({"objective": "a light lunch"}, "unknown objective 'a light lunch'"),
        ({"activity": "hot soup"}, "unknown activity 'hot soup'"),
    ],
)
def test_an_objective_or_task_the_model_lacks_is_free_text_which_needs_the_extra(
    task, model, kwargs, match, monkeypatch
):
    monkeypatch.setitem(sys.modules, "numpy", None)  # what an import finds when numpy is not installed
    with pytest.raises(MissingExtraError, match=match) as raised:
        score(task, model, **kwargs)
    assert "'text' extra" in str(raised.value) and "\n" not in str(raised.value)


def test_unknown_classes_get_the_default_and_are_listed(coffee_domain_path, model):
    domain = load_domain(coffee_domain_path)
    text = coffee_problem().replace("dinner_plate_1 dinner_plate_2 - plate", "dinner_plate_1 dinner_plate_2 - board")
    result = score(PlanningTask(domain, read_problem(text, domain)), model)
    assert set(result.unknown) == {"dinner_plate_1", "dinner_plate_2"}
    assert result.element_scores["dinner_plate_2"] == 0.05


def test_thresholds_apply_to_classes_then_elements(task, model):
    result = score(task, model)
    selected = select_relevant(task, result, Thresholds(0.2, 0.2))
    assert {"plastic_cup_1", "paper_cup_1", "cold_brew_1", "creamer_1", "stir_stick_1", "alice"} <= selected
    assert "dinner_plate_2" not in selected
    # a class threshold above R(stirrer) drops the stick though its element score alone would pass
    strict = select_relevant(task, result, Thresholds(0.5, 0.2))
    assert "stir_stick_1" not in strict and "plastic_cup_1" in strict
    assert "alice" in select_relevant(task, result, Thresholds(1.0, 1.0))  # goal objects always


@pytest.mark.parametrize("value", [-0.1, 1.5])
def test_thresholds_outside_unit_interval_are_rejected(value):
    with pytest.raises(UsageError):
        Thresholds(value, 0.2)


def test_closure_restores_blockers_places_and_robot_position(task, model):
    result = prune_with_scores(task, score(task, model), Thresholds(), model)
    reasons = {r.name: r for r in result.restored}
    assert reasons["dinner_plate_1"].rule == "blocker"
    assert reasons["dinner_plate_1"].describe() == "on top of plastic_cup_1 (on dinner_plate_1 plastic_cup_1)"
    assert "dinner_plate_2" in result.removed
    kept_places = {"counter_1", "fridge_1", "table_1"} & result.kept
    assert kept_places == {"counter_1", "fridge_1", "table_1"}


def test_closure_says_on_top_of_only_where_the_model_s_support_role_names_the_predicate(task, model):
    """A blocker's fact is read as stacking only when the knowledge model says ``on`` is its support
    role (the default it documents); without that, the reason is the fact itself."""
    for scene, expected in (
        ("", "on top of plastic_cup_1 (on dinner_plate_1 plastic_cup_1)"),
        ('scene: {support: "on"}\n', "on top of plastic_cup_1 (on dinner_plate_1 plastic_cup_1)"),
        ("scene: {support: none}\n", "undoing (on dinner_plate_1 plastic_cup_1) frees plastic_cup_1"),
    ):
        other = parse_knowledge_model(MODEL + scene, "m.yaml")
        result = prune_with_scores(task, score(task, other), Thresholds(), other)
        assert {r.name: r for r in result.restored}["dinner_plate_1"].describe() == expected, scene
    kept = frozenset({"plastic_cup_1"})
    _, restored = close_over_constraints(
        kept, infer_constraint_rules(task.domain, task.init_index), task.init_index, task.problem.objects.keys()
    )
    assert {r.name: r for r in restored}["dinner_plate_1"].describe() == (
        "undoing (on dinner_plate_1 plastic_cup_1) frees plastic_cup_1"  # no model: nothing says it is stacking
    )


BINS_DOMAIN = """(define (domain bins)
  (:requirements :strips :typing)
  (:types thing bin)
  (:predicates (in ?t - thing ?b - bin) (empty ?b - bin) (filled ?b - bin))
  (:action take-out :parameters (?t - thing ?b - bin)
    :precondition (in ?t ?b) :effect (and (not (in ?t ?b)) (empty ?b)))
  (:action fill :parameters (?b - bin) :precondition (empty ?b) :effect (filled ?b)))
"""
BINS_MODEL = """
version: 1
domain: bins
scene: {containment: in, support: none, location: none, access: none, human_location: none}
objectives:
  fill: {goal_predicates: [filled], tasks: {fill: 1.0}}
tasks:
  fill: {bin: 1.0}
classes:
  bin: {types: [bin]}
  thing: {types: [thing]}
"""


def test_closure_says_inside_where_the_model_s_containment_role_names_the_predicate():
    domain = read_domain(BINS_DOMAIN)
    problem = read_problem(
        "(define (problem p) (:domain bins) (:objects ball_1 - thing bin_1 bin_2 - bin)"
        " (:init (in ball_1 bin_1) (empty bin_2)) (:goal (filled bin_1)))",
        domain,
    )
    task = PlanningTask(domain, problem)
    model = parse_knowledge_model(BINS_MODEL, "m.yaml")
    result = prune_with_scores(task, score(task, model), Thresholds(), model)
    assert {r.name: r.describe() for r in result.restored}["ball_1"] == "inside bin_1 (in ball_1 bin_1)"


def test_blocked_alternatives_are_set_aside_when_a_free_one_is_kept(task, model):
    scores = score(task, model)
    plain = prune_with_scores(task, scores, Thresholds(), model)
    assert {"plastic_cup_1", "paper_cup_1", "dinner_plate_1"} <= plain.kept and plain.set_aside == frozenset()
    narrowed = prune_with_scores(task, scores, Thresholds(), model, settings=PruneSettings(prefer_free=True))
    # the plate stands on the plastic cup; the paper cup stands free and serves as well
    assert narrowed.set_aside == {"plastic_cup_1"}
    assert "paper_cup_1" in narrowed.kept
    assert not {"plastic_cup_1", "dinner_plate_1"} & narrowed.kept
    assert plain.kept - narrowed.kept == {"plastic_cup_1", "dinner_plate_1"}


def test_a_blocked_object_without_a_free_alternative_stays(task, model):
    # tau_e = 0.4 selects the plastic cup (R = 0.65) but not the paper cup (R = 0.36)
    result = prune_with_scores(
        task, score(task, model), Thresholds(0.2, 0.4), model, settings=PruneSettings(prefer_free=True)
    )
    assert "paper_cup_1" not in result.selected
    assert result.set_aside == frozenset()
    assert {"plastic_cup_1", "dinner_plate_1"} <= result.kept


def test_types_are_not_treated_as_alternatives(task):
    # the goal scorer's classes are PDDL types: every block of a tower may be needed
    scores = SCORERS["goal"](task, ScoreRequest())
    assert (
        prune_with_scores(task, scores, Thresholds(), settings=PruneSettings(prefer_free=True)).set_aside == frozenset()
    )


def test_closure_rules_are_inferred_from_schemas(task):
    rules = infer_constraint_rules(task.domain, task.init_index)
    kinds = {(r.predicate, r.when_kept, r.restore, r.kind) for r in rules}
    assert ("on", 1, 0, "blocker") in kinds  # what stands on a kept item
    assert ("at", 0, 1, "anchor") in kinds  # the place of a kept item
    assert single_valued_predicates(task.domain, task.init_index) == {"robot-at"}


def test_closure_is_transitive_and_pure():
    domain = read_domain(BLOCKSWORLD_DOMAIN)
    problem = read_problem(blocksworld_problem(10, in_the_way=3), domain)
    index = index_init(problem)
    kept = frozenset({"a", "b", "c"})
    closed, restored = close_over_constraints(
        kept, infer_constraint_rules(domain, index), index, problem.objects.keys()
    )
    assert {"x1", "x2", "x3"} <= closed
    assert kept == {"a", "b", "c"}  # input unchanged
    assert [r.name for r in restored][:3] == ["x1", "x2", "x3"]


def test_model_dependencies_extend_closure(task):
    text = MODEL + "dependencies:\n  - {predicate: human-at, when_kept: 2, restore: 1, reason: who sits there}\n"
    model = parse_knowledge_model(text, "m.yaml")
    result = prune_with_scores(task, score(task, model), Thresholds(), model)
    assert "alice" in result.kept


def test_goal_scorer_finds_roles_without_a_model(task):
    result = SCORERS["goal"](task, ScoreRequest())
    assert result.element_scores["alice"] == 1.0
    assert result.element_scores["plastic_cup_1"] == pytest.approx(0.6)
    assert result.element_scores["creamer_1"] == pytest.approx(0.36)
    assert result.element_scores["dinner_plate_2"] == 0.0


def test_goal_scorer_on_classic_domains():
    domain = read_domain(GRIPPER_DOMAIN)
    task = PlanningTask(domain, read_problem(gripper_problem(30), domain))
    result = prune_with_scores(task, SCORERS["goal"](task, ScoreRequest()))
    assert {"ball1", "ball2", "left", "right", "r1", "r2"} <= result.kept
    assert len(result.kept) < 15
    domain = read_domain(BLOCKSWORLD_DOMAIN)
    task = PlanningTask(domain, read_problem(blocksworld_problem(60, in_the_way=2), domain))
    result = prune_with_scores(task, SCORERS["goal"](task, ScoreRequest()))
    assert result.kept == {"a", "b", "c", "x1", "x2"}


@pytest.mark.parametrize("world,size", [("miconic-manygoals", 200), ("logistics-manygoals-typed", 120)])
def test_goal_regression_checks_the_initial_state_as_a_full_scan_would(world, size):
    generated = WORLDS[world].problem(1, 1, Settings(size=size))
    domain = load_domain(DOMAINS_DIR / generated.sidecar["domain"] / "domain.pddl")
    problem = read_problem(generated.pddl_text, domain)
    regression = _Regression(domain, problem, index_init(problem))
    regression.run()
    objects = sorted(problem.objects)
    patterns = set(regression.best)
    # every object named at every position, the others left to any object: hits and misses
    for predicate in {atom[0] for atom in problem.init}:
        arity = len(next(atom for atom in problem.init if atom[0] == predicate)) - 1
        for position in range(arity):
            for name in objects[:: max(1, len(objects) // 40)]:
                args = [("type", "object")] * arity
                args[position] = ("obj", name)
                patterns.add((predicate, tuple(args)))

    def full_scan(pattern):
        predicate, args = pattern
        return any(
            atom[0] == predicate
            and all(
                atom[1 + i] == value if kind == "obj" else domain.is_subtype(problem.objects[atom[1 + i]], value)
                for i, (kind, value) in enumerate(args)
            )
            for atom in problem.init
        )

    checked = [(pattern, regression.initially_satisfiable(pattern)) for pattern in sorted(patterns)]
    assert checked == [(pattern, full_scan(pattern)) for pattern, _ in checked]
    assert {True, False} <= {answer for _, answer in checked}


def test_random_scorer_is_seeded(task):
    first = SCORERS["random"](task, ScoreRequest(seed=3))
    again = SCORERS["random"](task, ScoreRequest(seed=3))
    other = SCORERS["random"](task, ScoreRequest(seed=4))
    assert first.element_scores == again.element_scores
    assert first.element_scores != other.element_scores


def test_oracle_needs_a_sidecar(task):
    with pytest.raises(UsageError, match="sidecar"):
        SCORERS["oracle"](task, ScoreRequest())
    result = SCORERS["oracle"](task, ScoreRequest(necessary=frozenset({"paper_cup_1"})))
    assert result.element_scores["paper_cup_1"] == 1.0 and result.element_scores["plastic_cup_1"] == 0.0


@pytest.mark.parametrize(
    "mutate, match, line",
    [
        (lambda t: t.replace("hot: 0.75, iced: 0.25", "hot: 0.75, iced: 1.25"), "outside \\[0, 1\\]", 9),
        (lambda t: t.replace("hot: 0.75, iced: 0.25", "hot: 0.5, iced: 0.25"), "sums to 0.750", 9),
        (lambda t: t.replace("cup: 0.9, whitener: 0.8", "cup: 0.9, milkk: 0.8"), "unknown class 'milkk'", 13),
        (lambda t: t.replace("in-closed-container: 0.8", "in-closed-container: high"), "must be a number", 28),
        (lambda t: t.replace("version: 1", "version: 7"), "'version' must be 1", 2),
        (lambda t: t.replace("  tea: {cup: 0.9}\n", ""), "activity 'tea' that has no entry", None),
        (lambda t: t.replace("tasks: {hot: 0.75", "tasks: {hot: [0.75"), "invalid YAML", 9),
        (lambda t: t + "colors: [red]\n", "unknown key 'colors'", None),
    ],
)
def test_invalid_models_name_file_and_line(mutate, match, line):
    with pytest.raises(ModelError, match=match) as caught:
        parse_knowledge_model(mutate(MODEL), "bad.yaml")
    assert caught.value.path == "bad.yaml"
    if line is not None:
        assert caught.value.line == line


def test_the_goal_regression_answers_alike_from_the_first_facts_and_from_their_classes(monkeypatch):
    """Past its first facts a pattern of classes only is answered from the predicate's distinct rows
    of classes (150,000 plates stated before the one cup that is clear): the same analysis as
    scanning every fact, on a problem where the match comes last and on one where none does."""
    from relevance_plan.pddl.parser import read_domain, read_problem
    from relevance_plan.relevance.analysis import goal_regression

    domain = read_domain(
        """(define (domain d) (:requirements :strips :typing) (:types cup plate - thing)
  (:predicates (clear ?x - thing) (holding ?x - thing) (has-cloth))
  (:action take :parameters (?x - cup) :precondition (clear ?x) :effect (holding ?x))
  (:action wipe :parameters (?x - cup) :precondition (has-cloth) :effect (clear ?x)))"""
    )
    plates = " ".join(f"p{i}" for i in range(3000))
    for cup_is_clear in (True, False):
        init = " ".join(f"(clear p{i})" for i in range(3000)) + (" (clear c1)" if cup_is_clear else "")
        problem = read_problem(
            f"(define (problem q) (:domain d) (:objects {plates} - plate c1 - cup) (:init {init})"
            " (:goal (exists (?c - cup) (holding ?c))))",
            domain,
        )
        by_rows = goal_regression.analyse_goal(domain, problem)
        monkeypatch.setattr(goal_regression, "_SCAN_FIRST", 10**9)
        by_scan = goal_regression.analyse_goal(domain, problem)
        monkeypatch.undo()
        assert by_rows == by_scan
        # a clear cup: no need to wipe one; none: the cloth matters
        assert ("has-cloth" in by_rows.relevant_predicates) is not cup_is_clear
