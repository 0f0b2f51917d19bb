"""Compiling features away (``pddl.compile``): every compilation keeps the task's plans.

The property tests generate small ADL tasks, solve the original and each
compiled task with a breadth-first search over the builtin simulator (both
searches are complete and find shortest plans), and require that the
compiled task is solvable exactly when the original is, and that its plan,
mapped back, is a plan of the ORIGINAL task of the same length.  The
compiled task goes through the formatter and the parser on the way, as it
does on the way to a planner.  No planner runs here.
"""

from __future__ import annotations

import functools
import itertools
import random
from collections import deque

import pytest

from relevance_plan.errors import UnsupportedFeatureError
from relevance_plan.pddl import formulas as f
from relevance_plan.pddl.compile import (
    COMPILATIONS,
    compile_conditional_effects,
    compile_disjunctive_preconditions,
    compile_equality,
    compile_negative_preconditions,
    compile_quantified_preconditions,
)
from relevance_plan.pddl.formatter import format_domain, format_formula, format_problem
from relevance_plan.pddl.parser import read_domain, read_problem
from relevance_plan.pddl.plans import Plan, PlanStep
from relevance_plan.pddl.simulator import Simulator, initial_state
from relevance_plan.planning.planners.preparation import COMPILED_FEATURES, compile_for
from relevance_plan.planning.planners.requirements import HIERARCHICAL_TYPING, STRIPS, TYPING, problem_features
from relevance_plan.planning.validation import simulate

STATES = 3_000


class TooLarge(Exception):
    """The search space of a generated task is too large for the test: skip that task."""


def shortest_plan(domain, problem) -> Plan | None:
    """A shortest plan by breadth-first search over the builtin simulator, or None if there is none."""
    simulator = Simulator(domain, problem)
    start = initial_state(problem)
    simulator.derive(start)
    ground = [(action, binding) for action in domain.actions for binding in simulator.bindings(action.parameters, {})]
    frontier = deque([(start, ())])
    seen = {frozenset(start.facts)}
    while frontier:
        state, path = frontier.popleft()
        if simulator.holds(problem.goal, state, {}):
            return Plan(path)
        for action, binding in ground:
            if not simulator.holds(action.precondition, state, binding):
                continue
            successor = state.copy()
            simulator.effects(action.effect, state, binding).apply(successor)
            simulator.derive(successor)
            key = frozenset(successor.facts)
            if key in seen:
                continue
            seen.add(key)
            if len(seen) > STATES:
                raise TooLarge
            step = PlanStep(action.name, tuple(binding[variable] for variable, _ in action.parameters))
            frontier.append((successor, (*path, step)))
    return None


def through_text(compiled):
    """The compiled task as a planner gets it: formatted, then read back."""
    domain = read_domain(format_domain(compiled.domain))
    return domain, read_problem(format_problem(compiled.problem), domain)


def task(domain_text: str, problem_text: str):
    domain = read_domain(domain_text)
    return domain, read_problem(problem_text, domain)


def assert_keeps_plans(domain, problem, compile_task, original=...) -> tuple:
    """The compiled task is solvable iff the original is; its shortest plan maps back to a shortest plan."""
    if original is ...:
        original = shortest_plan(domain, problem)
    compiled = compile_task(domain, problem)
    compiled_domain, compiled_problem = through_text(compiled)
    found = shortest_plan(compiled_domain, compiled_problem)
    assert (found is None) == (original is None), (original, found)
    if found is not None:
        mapped = compiled.map_back(found)
        checked = simulate(domain, problem, mapped)
        assert checked.valid, (checked.message, found, mapped)
        assert len(mapped) == len(original)
    return compiled, found


# --------------------------------------------------------------------------- small ADL tasks, generated


class AdlTasks:
    """Random small ADL tasks: two types (``b`` under ``a``), three predicates, a constant,
    conditions with every connective, effects with conditions and universal parts."""

    PREDICATES = {"p": ("a",), "q": ("a", "a"), "r": ()}

    def __init__(self, seed: int):
        self.random = random.Random(seed)
        self.fresh = 0

    def atom(self, terms: list[str]) -> f.Atom:
        name = self.random.choice(list(self.PREDICATES))
        return f.Atom(name, tuple(self.random.choice(terms) for _ in self.PREDICATES[name]))

    def variable(self) -> tuple[str, str]:
        self.fresh += 1
        return f"?v{self.fresh}", self.random.choice(["a", "b"])

    def condition(self, terms: list[str], depth: int) -> f.Formula:
        kinds = ["atom", "atom", "not"] + (["and", "or", "imply", "exists", "forall", "equal"] if depth else [])
        kind = self.random.choice(kinds)
        if kind == "atom":
            return self.atom(terms)
        if kind == "not":
            return f.Not(self.atom(terms))
        if kind in ("and", "or"):
            parts = tuple(self.condition(terms, depth - 1) for _ in range(2))
            return f.And(parts) if kind == "and" else f.Or(parts)
        if kind == "imply":
            return f.Imply(self.condition(terms, depth - 1), self.condition(terms, depth - 1))
        if kind == "equal":
            equality = f.Equality(self.random.choice(terms), self.random.choice(terms))
            return equality if self.random.random() < 0.5 else f.Not(equality)
        variable = self.variable()
        body = self.condition([*terms, variable[0]], depth - 1)
        return f.Exists((variable,), body) if kind == "exists" else f.Forall((variable,), body)

    def literal(self, terms: list[str]) -> f.Formula:
        atom = self.atom(terms)
        return atom if self.random.random() < 0.6 else f.Not(atom)

    def effect(self, terms: list[str]) -> f.Formula:
        parts: list[f.Formula] = []
        for _ in range(self.random.randint(1, 3)):
            kind = self.random.choice(["literal", "literal", "when", "forall"])
            if kind == "literal":
                parts.append(self.literal(terms))
            elif kind == "when":
                parts.append(f.When(self.condition(terms, 1), self.literal(terms)))
            else:
                variable = self.variable()
                inner = [*terms, variable[0]]
                body = (
                    self.literal(inner) if self.random.random() < 0.5 else f.When(self.atom(inner), self.literal(inner))
                )
                parts.append(f.Forall((variable,), body))
        return f.And(tuple(parts))

    def make(self) -> tuple[str, str]:
        actions = []
        for number in range(self.random.randint(3, 4)):
            parameters = [(f"?x{i}", self.random.choice(["a", "b"])) for i in range(self.random.randint(0, 2))]
            terms = [variable for variable, _ in parameters] + ["k"]
            signature = " ".join(f"{variable} - {kind}" for variable, kind in parameters)
            precondition = f.And(tuple(self.condition(terms, 1) for _ in range(self.random.randint(0, 2))))
            actions.append(
                f"(:action act{number} :parameters ({signature})\n"
                f"  :precondition {format_formula(precondition)}\n"
                f"  :effect {format_formula(self.effect(terms))})"
            )
        domain = (
            "(define (domain adl) (:requirements :adl) (:types a - object b - a) (:constants k - b)\n"
            "(:predicates (p ?x - a) (q ?x ?y - a) (r))\n" + "\n".join(actions) + ")"
        )
        objects = ["o1", "o2"] + (["o3"] if self.random.random() < 0.5 else [])
        kinds = {name: self.random.choice(["a", "b"]) for name in objects}
        everything = [*objects, "k"]
        init = {format_formula(self.atom(everything)) for _ in range(self.random.randint(0, 4))}
        start = (
            f"(define (problem t) (:domain adl) (:objects {' '.join(f'{o} - {kinds[o]}' for o in objects)})\n"
            f"(:init {' '.join(sorted(init))})\n(:goal "
        )
        goal = self.goal(domain, start + "(and)))", everything)
        return domain, start + format_formula(goal) + "))"

    def goal(self, domain_text: str, problem_text: str, names: list[str]) -> f.Formula:
        """Mostly a goal that holds where a random walk ends (and not at the start): most tasks are solvable."""
        domain, problem = task(domain_text, problem_text)
        simulator = Simulator(domain, problem)
        start = initial_state(problem)
        state = start
        ground = [(a, b) for a in domain.actions for b in simulator.bindings(a.parameters, {})]
        for _ in range(self.random.randint(1, 4)):
            applicable = [(a, b) for a, b in ground if simulator.holds(a.precondition, state, b)]
            if not applicable:
                break
            action, binding = self.random.choice(applicable)
            successor = state.copy()
            simulator.effects(action.effect, state, binding).apply(successor)
            state = successor
        changed = sorted(state.facts ^ start.facts)
        if not changed or self.random.random() < 0.15:
            return f.And((self.literal(names), self.condition(names, 2)))  # solvable or not, who knows
        fact = self.random.choice(changed)
        literal = f.Atom(fact[0], fact[1:]) if fact in state.facts else f.Not(f.Atom(fact[0], fact[1:]))
        for _ in range(20):
            condition = self.condition(names, self.random.choice([1, 2]))
            if simulator.holds(condition, state, {}):
                return f.And((literal, condition))
        return literal


TASKS = 150


@functools.cache
def adl_tasks() -> tuple:
    """``TASKS`` generated tasks whose goal does not hold at the start, each with a shortest plan
    (None: unsolvable); tasks too large to search are left out."""
    found = []
    for seed in itertools.count():
        domain, problem = task(*AdlTasks(seed).make())
        try:
            plan = shortest_plan(domain, problem)
        except TooLarge:
            continue
        if plan is not None and not plan.steps:
            continue
        found.append((domain, problem, plan))
        if len(found) == TASKS:
            return tuple(found)
    raise AssertionError("unreachable")


def test_every_compilation_declares_features_the_planners_know():
    from relevance_plan.planning.planners.requirements import FEATURES

    for name, compiler in COMPILATIONS.items():
        assert compiler.removes and compiler.removes <= set(FEATURES), name
        assert COMPILED_FEATURES[name] == compiler.removes


@pytest.mark.parametrize("name", list(COMPILATIONS))
def test_every_compilation_keeps_the_plans_of_small_adl_tasks(name):
    checked = solvable = 0
    for domain, problem, plan in adl_tasks():
        try:
            compiled, found = assert_keeps_plans(domain, problem, COMPILATIONS[name], plan)
        except TooLarge:
            continue
        assert not problem_features(*through_text(compiled)) & COMPILED_FEATURES[name]  # the feature is gone
        checked += 1
        solvable += found is not None
    assert checked >= TASKS * 3 // 4 and 0 < solvable < checked  # solvable and unsolvable tasks were tried


def test_all_compilations_together_leave_a_strips_task_with_the_same_plans():
    takes = frozenset({STRIPS, TYPING, HIERARCHICAL_TYPING})  # type hierarchies are read, not compiled
    checked = 0
    for domain, problem, plan in adl_tasks():
        try:
            compiled, _ = assert_keeps_plans(domain, problem, lambda d, p: compile_for(takes, d, p), plan)
        except (TooLarge, UnsupportedFeatureError):
            continue  # too large to search, or too many effect conditions to compile
        assert problem_features(*through_text(compiled)) <= takes
        checked += 1
    assert checked >= TASKS // 2


# --------------------------------------------------------------------------- each compilation, by hand

ROOMS = """
(define (domain rooms) (:requirements :adl :typing)
  (:types room)
  (:predicates (at ?r - room) (open ?r - room) (lit ?r - room))
  (:action go :parameters (?from ?to - room)
    :precondition (and (at ?from) (not (at ?to)) (or (open ?to) (lit ?to)))
    :effect (and (at ?to) (not (at ?from))))
  (:action light :parameters (?r - room)
    :precondition (exists (?s - room) (and (at ?s) (not (= ?s ?r))))
    :effect (and (lit ?r) (forall (?s - room) (when (lit ?s) (open ?s))))))
"""
ROOMS_PROBLEM = """
(define (problem p) (:domain rooms)
  (:objects Hall Kitchen Cellar - room)
  (:init (at Hall) (open Hall))
  (:goal (and (at Cellar) (forall (?r - room) (or (open ?r) (not (lit ?r)))))))
"""


def test_negative_preconditions_become_complements_kept_up_by_the_effects():
    domain, problem = task(ROOMS, ROOMS_PROBLEM)
    compiled = compile_negative_preconditions(domain, problem)
    assert compiled.domain.predicates["not-at"] == domain.predicates["at"]
    assert ("not-at", "kitchen") in compiled.problem.init and ("not-at", "hall") not in compiled.problem.init
    go = compiled.domain.action("go")
    assert "(not-at ?to)" in format_formula(go.precondition)
    assert format_formula(go.effect) == "(and (at ?to) (not (not-at ?to)) (not (at ?from)) (not-at ?from))"
    # the user's spelling of the objects survives into the compiled file
    assert "Kitchen" in format_problem(compiled.problem)


def test_an_action_that_may_add_and_delete_the_same_atom_is_split_on_it():
    domain, problem = task(
        """(define (domain d) (:requirements :negative-preconditions)
             (:predicates (p ?x) (done))
             (:action swap :parameters (?x ?y) :precondition (p ?y) :effect (and (p ?x) (not (p ?y))))
             (:action finish :parameters (?x) :precondition (and (p ?x) (not (p ?x))) :effect (done)))""",
        "(define (problem t) (:domain d) (:objects a b) (:init (p a)) (:goal (and (p a) (not (p b)))))",
    )
    compiled, found = assert_keeps_plans(domain, problem, compile_negative_preconditions)
    names = {action.name: action for action in compiled.domain.actions}
    same = [a for a in names.values() if a.name.startswith("swap-case") and len(a.parameters) == 1]
    assert len(same) == 1  # ?x = ?y: the delete is dropped, the add wins
    assert compiled.map_back(Plan((PlanStep(same[0].name, ("a",)),))).steps == (PlanStep("swap", ("a", "a")),)
    assert found is not None and len(found) == 0  # the goal already holds


def test_a_clash_the_precondition_rules_out_needs_no_split():
    domain, problem = task(ROOMS, ROOMS_PROBLEM)
    compiled = compile_negative_preconditions(domain, problem)
    assert [a.name for a in compiled.domain.actions] == ["go", "light"]  # (at ?from), (not (at ?to)): ?from ≠ ?to
    assert not compiled.origins


def test_disjunctions_split_actions_and_map_back_by_name():
    domain, problem = task(ROOMS, ROOMS_PROBLEM)
    compiled, _ = assert_keeps_plans(domain, problem, compile_disjunctive_preconditions)
    variants = [a for a in compiled.domain.actions if compiled.origins.get(a.name, None) is not None]
    assert {compiled.origins[a.name].action for a in variants} >= {"go"}
    plan = Plan((PlanStep(variants[0].name, ("hall", "kitchen")),))
    assert compiled.map_back(plan).steps[0].action == compiled.origins[variants[0].name].action


def test_a_disjunctive_goal_is_reached_by_an_action_dropped_when_mapping_back():
    domain, problem = task(
        "(define (domain d) (:predicates (p) (q)) (:action make-q :parameters () :precondition (and) :effect (q)))",
        "(define (problem t) (:domain d) (:init) (:goal (or (p) (q))))",
    )
    compiled, found = assert_keeps_plans(domain, problem, compile_disjunctive_preconditions)
    assert len(found) == 2 and len(compiled.map_back(found)) == 1
    assert isinstance(compiled.problem.goal, f.Atom)


def test_existentials_in_preconditions_become_parameters_dropped_when_mapping_back():
    domain, problem = task(ROOMS, ROOMS_PROBLEM)
    compiled, _ = assert_keeps_plans(domain, problem, compile_quantified_preconditions)
    light = compiled.domain.action("light")
    assert len(light.parameters) == 2 and compiled.origins["light"].args == (0,)
    assert compiled.map_back(Plan((PlanStep("light", ("cellar", "hall")),))).steps == (PlanStep("light", ("cellar",)),)
    # the universal goal is instantiated over the problem's objects
    assert "(open cellar)" in format_formula(compiled.problem.goal)


def test_conditional_effects_become_one_action_per_combination():
    domain, problem = task(ROOMS, ROOMS_PROBLEM)
    compiled, _ = assert_keeps_plans(domain, problem, compile_conditional_effects)
    lights = [a for a in compiled.domain.actions if compiled.origins.get(a.name, None) is not None]
    assert len(lights) == 2**3  # one condition per room
    assert all(compiled.origins[a.name].action == "light" for a in lights)


def test_too_many_effect_conditions_are_refused_in_one_line():
    objects = " ".join(f"r{i}" for i in range(12))
    domain, problem = task(ROOMS, ROOMS_PROBLEM.replace("Hall Kitchen Cellar", f"Hall Kitchen Cellar {objects}"))
    with pytest.raises(UnsupportedFeatureError, match="action 'light' has 15 effect conditions") as refused:
        compile_conditional_effects(domain, problem)
    assert "\n" not in str(refused.value)


def test_equality_becomes_a_static_predicate():
    domain, problem = task(ROOMS, ROOMS_PROBLEM)
    compiled, _ = assert_keeps_plans(domain, problem, compile_equality)
    assert ("same-object", "hall", "hall") in compiled.problem.init
    assert "(not (same-object ?s ?r))" in format_formula(compiled.domain.action("light").precondition)


def test_a_negated_derived_predicate_is_refused():
    domain, problem = task(
        """(define (domain d) (:requirements :derived-predicates :negative-preconditions)
             (:predicates (p) (d) (g))
             (:derived (d) (p))
             (:action a :parameters () :precondition (not (d)) :effect (g)))""",
        "(define (problem t) (:domain d) (:init) (:goal (g)))",
    )
    with pytest.raises(UnsupportedFeatureError, match="derived predicate 'd' is used negatively"):
        compile_negative_preconditions(domain, problem)


def test_new_names_never_take_a_name_the_task_uses():
    domain, problem = task(
        """(define (domain d) (:requirements :negative-preconditions)
             (:predicates (p) (not-p) (g))
             (:action a :parameters () :precondition (not (p)) :effect (g)))""",
        "(define (problem t) (:domain d) (:init (not-p)) (:goal (g)))",
    )
    compiled, _ = assert_keeps_plans(domain, problem, compile_negative_preconditions)
    assert "not-p-2" in compiled.domain.predicates and ("not-p-2",) in compiled.problem.init


def test_durative_domains_are_refused():
    domain, problem = task(
        """(define (domain d) (:requirements :durative-actions) (:predicates (p))
             (:durative-action a :parameters () :duration (= ?duration 1)
               :condition (at start (not (p))) :effect (at end (p))))""",
        "(define (problem t) (:domain d) (:init) (:goal (p)))",
    )
    with pytest.raises(UnsupportedFeatureError, match="durative actions cannot be compiled"):
        compile_negative_preconditions(domain, problem)
