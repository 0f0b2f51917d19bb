"""Which PDDL features a domain and problem use, and the refusal when a planner does not take them.

Feature names are PDDL's requirement names (without the colon), computed
from what the files actually contain, not from their ``:requirements``
(which often over- or under-declare).  Universal effects count as
``conditional-effects``, as in PDDL; numeric fluents mean more than action
costs: a numeric effect on anything but ``total-cost``, a numeric
comparison, or a function in a duration.  Four names are ours, for typings
some planners' readers reject: ``hierarchical-typing`` (a type below
another declared type), and ``(either a b)`` by where it stands, since
readers take it in some places only: ``either-predicate-types`` (a
predicate's parameters: Fast Downward's translator reads it there and
nowhere else), ``either-types`` (a parameter of an action, a derived
predicate or a function, or a constant of the domain) and
``either-object-types`` (an object of the problem: LPG reads the others,
not this).  Each
planner adapter declares the features it takes and calls
:func:`refuse_unsupported` from its ``check``.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator

from relevance_plan.errors import UnsupportedFeatureError
from relevance_plan.pddl.formulas import (
    Comparison,
    Equality,
    Exists,
    Fluent,
    Forall,
    Formula,
    Imply,
    Modal,
    NumericEffect,
    Or,
    Preference,
    When,
    conjuncts,
    literals,
    quantifiers,
    walk,
)
from relevance_plan.pddl.model import Domain, Problem

STRIPS = "strips"
TYPING = "typing"
HIERARCHICAL_TYPING = "hierarchical-typing"
EITHER_TYPES = "either-types"
EITHER_PREDICATE_TYPES = "either-predicate-types"
EITHER_OBJECT_TYPES = "either-object-types"
NEGATIVE_PRECONDITIONS = "negative-preconditions"
DISJUNCTIVE_PRECONDITIONS = "disjunctive-preconditions"
EQUALITY = "equality"
EXISTENTIAL_PRECONDITIONS = "existential-preconditions"
UNIVERSAL_PRECONDITIONS = "universal-preconditions"
CONDITIONAL_EFFECTS = "conditional-effects"
ACTION_COSTS = "action-costs"
NUMERIC_FLUENTS = "numeric-fluents"
DURATIVE_ACTIONS = "durative-actions"
DURATION_INEQUALITIES = "duration-inequalities"
DERIVED_PREDICATES = "derived-predicates"
TIMED_INITIAL_LITERALS = "timed-initial-literals"
PREFERENCES = "preferences"
CONSTRAINTS = "constraints"

FEATURES = (
    STRIPS,
    TYPING,
    HIERARCHICAL_TYPING,
    EITHER_TYPES,
    EITHER_PREDICATE_TYPES,
    EITHER_OBJECT_TYPES,
    NEGATIVE_PRECONDITIONS,
    DISJUNCTIVE_PRECONDITIONS,
    EQUALITY,
    EXISTENTIAL_PRECONDITIONS,
    UNIVERSAL_PRECONDITIONS,
    CONDITIONAL_EFFECTS,
    ACTION_COSTS,
    NUMERIC_FLUENTS,
    DURATIVE_ACTIONS,
    DURATION_INEQUALITIES,
    DERIVED_PREDICATES,
    TIMED_INITIAL_LITERALS,
    PREFERENCES,
    CONSTRAINTS,
)

# Classical planning with everything ADL adds, action costs and derived predicates.
CLASSICAL = frozenset(FEATURES) - {
    NUMERIC_FLUENTS,
    DURATIVE_ACTIONS,
    DURATION_INEQUALITIES,
    TIMED_INITIAL_LITERALS,
    PREFERENCES,
    CONSTRAINTS,
}
# What makes a problem temporal: it needs a planner that schedules.
TEMPORAL = frozenset({DURATIVE_ACTIONS, DURATION_INEQUALITIES, TIMED_INITIAL_LITERALS})

COST = "total-cost"
# The metric may name the plan's duration; that is no numeric fluent of the domain.
_METRIC_WORDS = frozenset({COST, "total-time"})


def problem_features(domain: Domain, problem: Problem) -> frozenset[str]:
    """The features the domain and the problem use."""
    return domain_features(domain) | _problem_only_features(problem)


def domain_features(domain: Domain) -> frozenset[str]:
    found = {STRIPS} | typing_features(domain)
    if domain.temporal:
        found.add(DURATIVE_ACTIONS)
        found |= duration_features(action.duration for action in domain.actions if action.duration is not None)
    if domain.derived:
        found.add(DERIVED_PREDICATES)
    if domain.constraints is not None:
        found |= {CONSTRAINTS} | condition_features([domain.constraints])
    found |= condition_features([action.precondition for action in domain.actions])
    found |= condition_features([rule.body for rule in domain.derived])
    found |= effect_features([action.effect for action in domain.actions])
    return frozenset(found)


def typing_features(domain: Domain) -> frozenset[str]:
    found = set()
    if any(name != "object" for name in domain.types):
        found.add(TYPING)
    if any(parent not in ("", "object") for parent in domain.types.values()):
        found.add(HIERARCHICAL_TYPING)
    declared = [*domain.constants.values(), *(t for _, t in _typed_parameters(domain))]
    if any(_either(type_name) for type_name in declared):
        found.add(EITHER_TYPES)
    if any(_either(t) for parameters in domain.predicates.values() for _, t in parameters):
        found.add(EITHER_PREDICATE_TYPES)
    return frozenset(found)


def _either(type_name: str) -> bool:
    return type_name.startswith("(either")


def _typed_parameters(domain: Domain) -> Iterator[tuple[str, str]]:
    """The parameters of the functions, actions and derived predicates (a predicate's are apart)."""
    for parameters in domain.functions.values():
        yield from parameters
    for action in domain.actions:
        yield from action.parameters
    for rule in domain.derived:
        yield from rule.parameters


def duration_features(durations: Iterable[Formula]) -> frozenset[str]:
    """A duration other than one ``=`` constraint is an inequality; a function in it is a numeric fluent."""
    found = set()
    for duration in durations:
        parts = list(conjuncts(duration))
        if len(parts) != 1 or not isinstance(parts[0], Comparison) or parts[0].op != "=":
            found.add(DURATION_INEQUALITIES)
        if any(isinstance(node, Fluent) for node in walk(duration)):
            found.add(NUMERIC_FLUENTS)
    return frozenset(found)


def _problem_only_features(problem: Problem) -> frozenset[str]:
    found = set(condition_features([problem.goal]))
    if any(_either(type_name) for type_name in problem.objects.values()):
        found.add(EITHER_OBJECT_TYPES)
    if problem.constraints is not None:
        found |= {CONSTRAINTS} | condition_features([problem.constraints])
    if problem.timed_literals:
        found.add(TIMED_INITIAL_LITERALS)
    if problem.metric is not None:
        named = {node.function for node in walk(problem.metric.expression) if isinstance(node, Fluent)}
        if COST in named:
            found.add(ACTION_COSTS)
        if named - _METRIC_WORDS:
            found.add(NUMERIC_FLUENTS)
    return frozenset(found)


def condition_features(conditions: Iterable[Formula]) -> frozenset[str]:
    """What conditions (preconditions, goals, rule bodies, constraints) use."""
    found: set[str] = set()
    for condition in conditions:
        for node in walk(condition):
            if isinstance(node, (Or, Imply)):
                found.add(DISJUNCTIVE_PRECONDITIONS)
            elif isinstance(node, Equality):
                found.add(EQUALITY)
            elif isinstance(node, Comparison):
                found.add(NUMERIC_FLUENTS)
            elif isinstance(node, Preference):
                found.add(PREFERENCES)
            elif isinstance(node, Modal):
                found.add(CONSTRAINTS)
        if any(not positive for _, positive in literals(condition)):
            found.add(NEGATIVE_PRECONDITIONS)
        for quantifier, positive in quantifiers(condition):
            universal = isinstance(quantifier, Forall) == positive
            found.add(UNIVERSAL_PRECONDITIONS if universal else EXISTENTIAL_PRECONDITIONS)
    return frozenset(found)


def effect_features(effects: Iterable[Formula]) -> frozenset[str]:
    """What effects use, their conditions included."""
    found: set[str] = set()
    for effect in effects:
        for node in walk(effect):
            if isinstance(node, When):
                found.add(CONDITIONAL_EFFECTS)
                found |= condition_features([node.condition])
            elif isinstance(node, Forall):
                found.add(CONDITIONAL_EFFECTS)
            elif isinstance(node, NumericEffect):
                found.add(ACTION_COSTS if node.fluent.function == COST else NUMERIC_FLUENTS)
            elif isinstance(node, (Exists, Comparison)):
                found |= condition_features([node])
    return frozenset(found)


def refuse_unsupported(planner: str, takes: frozenset[str] | None, domain: Domain, problem: Problem) -> None:
    """Raise :class:`UnsupportedFeatureError` naming what ``planner`` lacks (``takes`` None: unknown, it decides)."""
    if takes is None:
        return
    in_domain = domain_features(domain) - takes
    missing = sorted(in_domain | (_problem_only_features(problem) - takes))
    if not missing:
        return
    raise UnsupportedFeatureError(
        f"{planner} does not take {', '.join(missing)}, which this {'domain' if in_domain else 'problem'} uses;"
        " choose another --planner",
        path=domain.path if in_domain else problem.path,
    )
