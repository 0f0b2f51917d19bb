"""Reading PDDL, error lines, and writing pruned problems that keep the user's text."""

import pytest
from support import coffee_problem

from relevance_plan.errors import DomainMismatchError, PDDLParseError, UnsupportedFeatureError
from relevance_plan.io import load_domain
from relevance_plan.pddl.model import goal_objects
from relevance_plan.pddl.parser import read_domain, read_problem
from relevance_plan.pddl.writer import write_pruned_problem


@pytest.fixture
def coffee(coffee_domain_path):
    return load_domain(coffee_domain_path)


def test_domain_has_types_predicates_actions(coffee):
    assert coffee.name == "coffee"
    assert coffee.is_subtype("cup", "item") and coffee.is_subtype("container", "place")
    assert not coffee.is_subtype("cup", "place")
    assert {a.name for a in coffee.actions} >= {"pick", "put-down", "stack", "unstack", "serve-coffee"}
    assert coffee.predicates["on"] == (("?x", "item"), ("?y", "item"))


def test_problem_reads_objects_init_goal(coffee):
    problem = read_problem(coffee_problem(), coffee, "p.pddl")
    assert problem.objects["plastic_cup_1"] == "cup"
    assert ("on", "dinner_plate_1", "plastic_cup_1") in problem.init
    assert goal_objects(problem, coffee) == {"alice"}


def test_names_are_case_insensitive_but_spelling_is_kept(coffee):
    text = coffee_problem().replace("plastic_cup_1 paper_cup_1 - cup", "Plastic_Cup_1 paper_cup_1 - cup")
    problem = read_problem(text, coffee)
    assert "plastic_cup_1" in problem.objects
    assert problem.display("plastic_cup_1") == "Plastic_Cup_1"


@pytest.mark.parametrize(
    "mutate, error, line",
    [
        (lambda t: t.replace("(hand-empty)", "(hand-empty"), PDDLParseError, None),
        (lambda t: t.replace("(:domain coffee)", "(:domain cereal)"), DomainMismatchError, 2),
        (lambda t: t.replace("(hand-empty)", "(hand-full)"), DomainMismatchError, None),
        (lambda t: t.replace("(robot-at counter_1)", "(robot-at kitchen_9)"), DomainMismatchError, None),
        (lambda t: t.replace("- plate", "- saucer"), DomainMismatchError, None),
        (lambda t: t + "(extra)", PDDLParseError, None),
    ],
)
def test_bad_problems_raise_errors_with_file_and_line(coffee, mutate, error, line):
    with pytest.raises(error) as caught:
        read_problem(mutate(coffee_problem()), coffee, "bad.pddl")
    assert caught.value.path == "bad.pddl"
    assert caught.value.line is not None
    if line is not None:
        assert caught.value.line == line
    assert "\n" not in str(caught.value)


def test_pddl_plus_is_refused_naming_the_construct():
    with pytest.raises(UnsupportedFeatureError, match="processes"):
        read_domain("(define (domain d) (:requirements :processes) (:predicates (p)))", "d.pddl")
    with pytest.raises(UnsupportedFeatureError, match=":process"):
        read_domain("(define (domain d) (:predicates (p)) (:process q :parameters () :precondition (p)))", "d.pddl")
    text = (
        "(define (domain d) (:requirements :durative-actions :fluents) (:predicates (p)) (:functions (f))\n"
        " (:durative-action a :parameters () :duration (= ?duration 1) :condition (at start (p))\n"
        "  :effect (increase (f) (* #t 2))))"
    )
    with pytest.raises(UnsupportedFeatureError, match="#t") as caught:
        read_domain(text, "d.pddl")
    assert caught.value.line == 3


def test_problem_file_given_as_domain_is_explained(coffee):
    with pytest.raises(PDDLParseError, match="problem file, not a domain"):
        read_domain(coffee_problem(), "swapped.pddl")


def test_pruned_problem_keeps_names_layout_and_drops_facts(coffee):
    text = coffee_problem().replace("plastic_cup_1 paper_cup_1 - cup", "Plastic_Cup_1 paper_cup_1 - cup")
    problem = read_problem(text, coffee, "p.pddl")
    kept = set(problem.objects) - {"paper_cup_1", "dinner_plate_2"}
    pruned = write_pruned_problem(problem, kept)
    again = read_problem(pruned, coffee)
    assert set(again.objects) == kept
    assert again.init == {atom for atom in problem.init if set(atom[1:]) <= kept}
    assert "Plastic_Cup_1 - cup" in pruned  # user's spelling and grouping survive
    assert "paper_cup_1" not in pruned and "dinner_plate_2" not in pruned
    assert again.goal == problem.goal
    # every line is an original line, at most minus the removed names
    original_lines = set(text.splitlines())
    for line in pruned.splitlines():
        assert line in original_lines or any(
            line == original.replace(f"{name} ", "")
            for original in original_lines
            for name in ("paper_cup_1", "dinner_plate_2")
        ), line


def test_pruning_a_whole_type_group_removes_its_type(coffee):
    problem = read_problem(coffee_problem(), coffee)
    kept = set(problem.objects) - {"dinner_plate_1", "dinner_plate_2"}
    pruned = write_pruned_problem(problem, kept)
    assert "- plate" not in pruned
    assert set(read_problem(pruned, coffee).objects) == kept


def test_keeping_everything_returns_the_text_unchanged(coffee):
    text = coffee_problem()
    problem = read_problem(text, coffee)
    assert write_pruned_problem(problem, set(problem.objects)) == text


def test_atomic_write_gives_an_ordinary_file_mode(tmp_path):
    import os

    from relevance_plan.io import write_text_atomic

    reference = tmp_path / "plain.txt"
    reference.write_text("x")
    written = write_text_atomic(tmp_path / "atomic.txt", "x")
    assert os.stat(written).st_mode == os.stat(reference).st_mode
    assert [p.name for p in tmp_path.iterdir() if p.name.endswith(".tmp")] == []


def test_errors_keep_path_and_line_across_processes():
    import pickle

    from relevance_plan.errors import PDDLParseError

    error = pickle.loads(pickle.dumps(PDDLParseError("unbalanced parenthesis", path="p.pddl", line=7)))
    assert isinstance(error, PDDLParseError)
    assert (error.path, error.line, str(error)) == ("p.pddl", 7, "p.pddl:7: unbalanced parenthesis")


@pytest.mark.parametrize("effect", ["(forall (?y))", "(forall)", "(forall (?y) (p ?y) (p ?y))"])
def test_a_forall_effect_with_a_missing_part_is_a_syntax_error(effect):
    text = (
        "(define (domain d) (:requirements :adl) (:predicates (p ?x))\n"
        f" (:action a :parameters (?x) :precondition (p ?x) :effect {effect}))"
    )
    with pytest.raises(PDDLParseError, match="'forall' in an effect takes") as caught:
        read_domain(text, "d.pddl")
    assert caught.value.line == 2


def test_a_dash_glued_to_its_type_is_read_as_published_domains_write_it():
    domain = read_domain(
        "(define (domain d) (:requirements :typing) (:types ball room)"
        " (:predicates (at ?b -ball ?r - room)) (:action a :parameters (?b -ball) :precondition (and) :effect (and)))"
    )
    assert domain.predicates["at"] == (("?b", "ball"), ("?r", "room"))
    assert domain.actions[0].parameters == (("?b", "ball"),)


def test_a_variable_glued_to_its_predicate_is_read_as_published_domains_write_it():
    domain = read_domain(
        "(define (domain d) (:requirements :typing) (:types plane)"
        " (:predicates (aircraft?a - plane) (ready ?a - plane))"
        " (:action go :parameters (?a - plane) :precondition (aircraft?a) :effect (ready?a)))"
    )
    assert domain.predicates["aircraft"] == (("?a", "plane"),)
    assert "?a" in str(domain.actions[0].precondition)


def test_a_bare_zero_ary_function_is_a_numeric_effect_target_and_a_one_ary_one_is_not():
    head = "(define (domain d) (:requirements :fluents) (:types t) (:functions (used) (fuel ?x - t)) "
    domain = read_domain(head + "(:action a :parameters (?x - t) :effect (increase used (fuel ?x))))")
    assert str(domain.actions[0].effect) == str(
        read_domain(head + "(:action a :parameters (?x - t) :effect (increase (used) (fuel ?x))))").actions[0].effect
    )
    with pytest.raises(PDDLParseError, match="takes a function term"):
        read_domain(head + "(:action a :parameters (?x - t) :effect (increase fuel 1)))")


@pytest.mark.parametrize(
    "effect, construct",
    [("(oneof (p) (q))", "non-deterministic effects"), ("(probabilistic 0.5 (p))", "probabilistic effects")],
)
def test_fond_and_ppddl_effects_are_refused_naming_the_construct(effect, construct):
    text = f"(define (domain d) (:predicates (p) (q)) (:action a :parameters () :precondition (and) :effect {effect}))"
    with pytest.raises(UnsupportedFeatureError, match=construct):
        read_domain(text, "d.pddl")
