"""Derived predicates in the plan checker: the join that finds a rule's candidate bindings derives
exactly what trying every object for every parameter derives (random rules, random states)."""

from __future__ import annotations

import random

import pytest

from relevance_plan.pddl import formulas as f
from relevance_plan.pddl.parser import read_domain, read_problem
from relevance_plan.pddl.simulator import Simulator, initial_state

BASIC = {"p": ("a",), "q": ("a", "b"), "r": ("b", "b")}  # predicate -> its parameters' types
OBJECTS = {"a": ["a1", "a2", "a3"], "b": ["b1", "b2", "b3", "a1"]}  # a is a subtype of b


def _atom(rng: random.Random, variables: dict[str, str], predicates: dict[str, tuple[str, ...]]) -> str:
    name = rng.choice(sorted(predicates))
    args = []
    for type_name in predicates[name]:
        fitting = [v for v, t in variables.items() if t == type_name or (type_name == "b" and t == "a")]
        args.append(rng.choice(fitting) if fitting and rng.random() < 0.85 else rng.choice(OBJECTS[type_name]))
    return f"({name} {' '.join(args)})"


def _body(rng: random.Random, variables: dict[str, str], predicates: dict[str, tuple[str, ...]], depth: int) -> str:
    roll = rng.random()
    if depth == 0 or roll < 0.3:
        return _atom(rng, variables, predicates)
    if roll < 0.5:
        parts = " ".join(_body(rng, variables, predicates, depth - 1) for _ in range(rng.randint(2, 3)))
        return f"(and {parts})"
    if roll < 0.6:
        return f"(or {_body(rng, variables, predicates, depth - 1)} {_body(rng, variables, predicates, depth - 1)})"
    if roll < 0.7:
        return f"(not {_atom(rng, variables, BASIC)})"  # negation on basic predicates only: stratified
    if roll < 0.75 and len(variables) >= 2:
        left, right = rng.sample(sorted(variables), 2)
        return f"(not (= {left} {right}))"
    quantifier = "exists" if roll < 0.92 else "forall"
    variable, type_name = f"?v{depth}{rng.randint(0, 9)}", rng.choice("ab")
    if variable in variables:
        return _atom(rng, variables, predicates)
    inner = {**variables, variable: type_name}
    return f"({quantifier} ({variable} - {type_name}) {_body(rng, inner, predicates, depth - 1)})"


def _domain_text(rng: random.Random) -> str:
    predicates = dict(BASIC)
    rules = []
    for index in range(3):
        head_types = tuple(rng.choice("ab") for _ in range(rng.randint(1, 2)))
        variables = {f"?x{i}": t for i, t in enumerate(head_types)}
        typed = " ".join(f"{v} - {t}" for v, t in variables.items())
        head = f"(d{index} {typed})"
        for _ in range(rng.randint(1, 2)):
            rules.append(f"(:derived {head} {_body(rng, variables, predicates, 3)})")
        predicates[f"d{index}"] = head_types  # later rules may read earlier derived predicates (positively)
    declared = " ".join(
        f"({name} {' '.join(f'?y{i} - {t}' for i, t in enumerate(types))})" for name, types in predicates.items()
    )
    return (
        "(define (domain random-derived) (:requirements :adl :derived-predicates)"
        f" (:types b - object a - b) (:constants a1 a2 a3 - a b1 b2 b3 - b) (:predicates {declared})"
        f" {' '.join(rules)}"
        " (:action noop :parameters () :precondition (and) :effect (and)))"
    )


def _reference(simulator: Simulator, state) -> set:
    """Every object for every parameter, to a fixpoint, stratum by stratum."""
    derived = simulator.domain.derived_predicates
    facts = {fact for fact in state.facts if fact[0] not in derived}
    state.facts = facts
    for stratum in simulator._strata:
        changed = True
        while changed:
            changed = False
            for rule in stratum:
                for binding in simulator.bindings(rule.parameters, {}):
                    fact = f.ground(rule.head, binding)
                    if fact not in facts and simulator.holds(rule.body, state, binding):
                        facts.add(fact)
                        changed = True
    return facts


@pytest.mark.parametrize("seed", range(40))
def test_the_join_derives_what_every_binding_derives(seed):
    rng = random.Random(seed)
    domain = read_domain(_domain_text(rng))
    for trial in range(5):
        init = []
        for name, types in BASIC.items():
            for _ in range(rng.randint(0, 6)):
                init.append("(" + name + " " + " ".join(rng.choice(OBJECTS[t]) for t in types) + ")")
        problem = read_problem(
            f"(define (problem r{trial}) (:domain random-derived) (:init {' '.join(init)}) (:goal (and)))",
            domain,
        )
        simulator = Simulator(domain, problem)
        joined, every = initial_state(problem), initial_state(problem)
        simulator.derive(joined)
        assert joined.facts == _reference(simulator, every), (seed, trial)
