"""Fit a problem read by unified-planning to an engine that does not take its kind.

Run only by the ``up:NAME`` child (``up.child``) and worker, after the PDDL reader and
before solving: this module imports unified_planning at the top, so nothing on
the main process's start-up path may import it.

unified-planning's reader turns every PDDL function into a real-valued fluent
and keeps the type hierarchy, and some engines refuse exactly that although
the problem says nothing they cannot do.  Each step below rewrites the
problem into an equivalent one without one such feature:

* whole numbers: real-valued fluents whose every value is a whole number
  (initial values, defaults, every value an effect gives) become integer
  fluents (Aries takes no real-valued fluent and no real-valued duration);
* flat types: every type below another becomes the type at the top of its
  hierarchy, and a static predicate per such type (true of its objects and
  of its subtypes' objects) guards each parameter or quantified variable of
  that type (Tamer's type checker rejects a type below another);
* defined values: a static numeric fluent left undefined for some arguments
  gets a static predicate telling where it is defined, which guards each
  action that reads it, and a default for the rest (Tamer takes no undefined
  initial value; in PDDL an action reading an undefined value cannot run).

Before those, for every engine, one convention: a numeric value the problem
never sets that effects increase or decrease starts from 0, as the tool's
validator counts it (docs/validation.md, "Values never set").

Names of actions and objects never change, so a plan of the rewritten problem
is a plan of the PDDL files as they are; the predicates added get names the
problem does not use.  A step that cannot apply (a value that is not whole, a
fluent an effect changes, PDDL+) leaves the problem as it was.
"""

from __future__ import annotations

import contextlib
import itertools
from collections import OrderedDict
from collections.abc import Callable, Iterable, Iterator, Mapping
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any

from unified_planning.exceptions import UPException
from unified_planning.model import (
    DurationInterval,
    DurativeAction,
    Fluent,
    InstantaneousAction,
    Object,
    Parameter,
    Problem,
    StartTiming,
    Variable,
)
from unified_planning.model.metrics import (
    MaximizeExpressionOnFinalState,
    MinimizeActionCosts,
    MinimizeExpressionOnFinalState,
    MinimizeMakespan,
    MinimizeSequentialPlanLength,
    Oversubscription,
    TemporalOversubscription,
)
from unified_planning.model.walkers import FluentsSubstituter
from unified_planning.model.walkers.identitydag import IdentityDagWalker

# The kind features each step replaces, each with the one it becomes (None: none).  A step runs
# only when the engine lacks a feature it replaces and takes what that becomes.
_REAL_NUMBERS = {
    "REAL_FLUENTS": "INT_FLUENTS",
    "REAL_TYPE_DURATIONS": "INT_TYPE_DURATIONS",
    "REAL_NUMBERS_IN_ACTIONS_COST": "INT_NUMBERS_IN_ACTIONS_COST",
}
_HIERARCHY = {"HIERARCHICAL_TYPING": "FLAT_TYPING"}
_UNDEFINED: dict[str, str | None] = {"UNDEFINED_INITIAL_NUMERIC": None}
_METRIC_NOTE = "solving without the metric, which it does not take"


class _CannotFit(Exception):
    """The step does not apply to this problem; the problem is left as it was."""


@dataclass(frozen=True)
class Fitted:
    """The problem to solve, one line per change made to it, and the kind features the engine still lacks."""

    problem: Any
    notes: tuple[str, ...] = ()
    lacking: tuple[str, ...] = ()


def fit_problem(environment: Any, engine: str, problem: Any) -> Fitted:
    """``problem`` rewritten, as far as the steps go, into one whose kind ``engine`` takes.

    A step runs only when it would replace a feature the engine lacks; each gives an
    equivalent problem, so the rewritten one is used even when the engine
    still lacks something (an engine's declared kind is advisory: it may
    solve it all the same).  Then, when the engine still does not take the
    problem, its quality metric is dropped: a metric ranks plans, and any
    plan is still one.  ``problem`` itself is not changed.

    Before any of that, whatever the engine, a value the problem never sets
    that effects increase or decrease starts from 0 (:func:`_counted_from_zero`).
    """
    fitted, notes = problem, []
    with contextlib.suppress(_CannotFit, UPException):
        fitted, note = _counted_from_zero(problem)
        notes.append(note)
    try:
        engine_class = environment.factory.engine(engine)
    except Exception:  # an unknown engine is reported by the solve
        return Fitted(fitted, tuple(notes))
    kind = fitted.kind  # computed anew on every access: once per problem here
    if engine_class.supports(kind):
        return Fitted(fitted, tuple(notes))
    takes = frozenset(engine_class.supported_kind().features)
    for replaces, step in ((_REAL_NUMBERS, _whole_numbers), (_HIERARCHY, _flat_types), (_UNDEFINED, _defined_values)):
        lacks = frozenset(kind.features) - takes
        if not any(old in lacks and (new is None or new in takes) for old, new in replaces.items()):
            continue
        try:
            fitted, note = step(fitted)
        except (_CannotFit, UPException):
            continue
        kind = fitted.kind
        notes.append(note)
    if fitted.quality_metrics and not engine_class.supports(kind):
        fitted = fitted.clone() if fitted is problem else fitted
        fitted.clear_quality_metrics()
        kind = fitted.kind
        if engine_class.supports(kind):
            notes.append(_METRIC_NOTE)
    lacking = () if engine_class.supports(kind) else tuple(sorted(frozenset(kind.features) - takes))
    return Fitted(fitted, tuple(notes), lacking)


# -- values never set --------------------------------------------------------------------------------


def _counted_from_zero(problem: Any) -> tuple[Any, str]:
    """A numeric fluent left unset for some arguments that effects increase or decrease starts from 0.

    The tool's validator and VAL count such a value from 0 (an action cost
    the problem does not initialise; docs/validation.md), and so does LPG;
    unified-planning's engines take it as undefined for good (ENHSP reports
    the problem unsolvable, Tamer refuses it).  With a default of 0, every
    plan valid under that convention is a plan of the rewritten problem, so
    an engine's proof that it has none holds for the original; a plan that
    reads such a value before it is counted is refused by the validation.
    """
    em = problem.environment.expression_manager
    counted = set()
    for effect in _effects(problem):
        fluent = effect.fluent.fluent()
        if (effect.is_increase() or effect.is_decrease()) and fluent not in problem.fluents_defaults:
            counted.add(fluent)
    unset = [
        fluent
        for fluent in problem.fluents
        if fluent in counted
        and any(problem.initial_value(em.FluentExp(fluent, args)) is None for args in _groundings(problem, fluent))
    ]
    if not unset:
        raise _CannotFit

    def zero(fluent: Any, value: Any) -> Any:
        if fluent in unset:
            return em.Int(0) if fluent.type.is_int_type() else em.Real(Fraction(0))
        return value

    names = ", ".join(fluent.name for fluent in unset)
    return _rebuild(problem, _Rewrite(default=zero)), f"counted {names} from 0 where the problem leaves it unset"


def _effects(problem: Any) -> Iterator[Any]:
    """Every effect of the problem: its actions' and its timed effects."""
    for action in problem.actions:
        if isinstance(action, InstantaneousAction):
            yield from action.effects
        elif isinstance(action, DurativeAction):
            for effects in action.effects.values():
                yield from effects
    for effects in problem.timed_effects.values():
        yield from effects


# -- whole numbers ---------------------------------------------------------------------------------


def _whole_numbers(problem: Any) -> tuple[Any, str]:
    """Every real-valued fluent as an integer fluent, when all its values are whole numbers."""
    env = problem.environment
    real = [fluent for fluent in problem.fluents if fluent.type.is_real_type()]
    if not real:
        raise _CannotFit
    integer = env.type_manager.IntType()
    renamed = {fluent: Fluent(fluent.name, integer, fluent.signature, env) for fluent in real}
    for target, initial in problem.explicit_initial_values.items():
        if target.fluent() in renamed:
            _whole(initial)
    for fluent in real:
        if fluent in problem.fluents_defaults:
            _whole(problem.fluents_defaults[fluent])
    substituter = FluentsSubstituter(renamed, env)

    def value(expression: Any) -> Any:
        # A whole real constant (from a default or an initial value) becomes an integer.
        if expression.is_real_constant():
            return env.expression_manager.Int(_whole(expression))
        return substituter.substitute_fluents(expression)

    # An effect giving a value that is not whole (a real constant, a division) to an integer
    # fluent fails unified-planning's type check while rebuilding: the step does not apply.
    rebuilt = _rebuild(problem, _Rewrite(expression=value, fluent=lambda fluent: renamed.get(fluent, fluent)))
    count = len(real)
    plural = "s" if count != 1 else ""
    return (
        rebuilt,
        f"turned {count} real-valued fluent{plural} into integer fluent{plural} (every value is whole) to run",
    )


def _whole(constant: Any) -> int:
    """The integer a constant numeric expression stands for; _CannotFit for anything else."""
    if constant.is_int_constant():
        return int(constant.int_constant_value())
    if constant.is_real_constant():
        number = Fraction(constant.real_constant_value())
        if number.denominator == 1:
            return int(number)
    raise _CannotFit


# -- flat types ------------------------------------------------------------------------------------


def _flat_types(problem: Any) -> tuple[Any, str]:
    """Every type below another as the top of its hierarchy, guarded by a static predicate."""
    below = [t for t in problem.user_types if t.father is not None]
    if not below:
        raise _CannotFit
    env = problem.environment
    em = env.expression_manager
    names = _Names(problem)
    guards: dict[Any, Any] = {}

    def top(type_: Any) -> Any:
        while type_.is_user_type() and type_.father is not None:
            type_ = type_.father
        return type_

    def guard(type_: Any, argument: Any) -> Any:
        """``is_T(argument)`` for a type below another; None for a type at the top."""
        if not type_.is_user_type() or type_.father is None:
            return None
        if type_ not in guards:
            signature = [Parameter("x", top(type_), env)]
            guards[type_] = Fluent(names.fresh(f"is_{type_.name}"), env.type_manager.BoolType(), signature, env)
        return em.FluentExp(guards[type_], [argument])

    def fluent(old: Any) -> Any:
        signature = [Parameter(p.name, top(p.type), env) for p in old.signature]
        if all(new.type == p.type for new, p in zip(signature, old.signature)) and top(old.type) == old.type:
            return old
        return Fluent(old.name, top(old.type), signature, env)

    fluents = {old: fluent(old) for old in problem.fluents}
    walker = _Flattener(env, fluents, top, guard)

    def parameter_guards(old_action: Any, new_action: Any) -> list[Any]:
        found = (guard(p.type, em.ParameterExp(new_action.parameter(p.name))) for p in old_action.parameters)
        return [g for g in found if g is not None]

    rewrite = _Rewrite(
        expression=walker.rewrite,
        fluent=fluents.__getitem__,
        retype=top,
        guards=parameter_guards,
        forall_guard=lambda variable: guard(variable.type, em.VariableExp(walker.variable(variable))),
    )
    rebuilt = _rebuild(problem, rewrite)
    # Each guard holds for the objects of its type and of the types below it.
    for type_, helper in guards.items():
        rebuilt.add_fluent(helper, default_initial_value=False)
        for obj in problem.all_objects:
            if type_.is_compatible(obj.type):
                rebuilt.set_initial_value(em.FluentExp(helper, [em.ObjectExp(rebuilt.object(obj.name))]), True)
    _define_widened(problem, rebuilt, fluents)
    return rebuilt, f"flattened the type hierarchy ({len(below)} type{'s' if len(below) != 1 else ''}) to run"


def _define_widened(problem: Any, rebuilt: Any, fluents: Mapping[Any, Any]) -> None:
    """A numeric fluent whose arguments now take objects of other types gets a value for them too.

    Only guarded actions read a fluent, with arguments of the types it was
    declared with, so these values are never read; without them the problem
    would have undefined initial values that it did not have.
    """
    em = problem.environment.expression_manager
    for old, new in fluents.items():
        if old is new or not (new.type.is_int_type() or new.type.is_real_type()) or old in problem.fluents_defaults:
            continue
        zero = em.Int(0) if new.type.is_int_type() else em.Real(Fraction(0))
        for arguments in itertools.product(*(rebuilt.objects(p.type) for p in new.signature)):
            originals = [problem.object(obj.name) for obj in arguments]
            if all(p.type.is_compatible(obj.type) for p, obj in zip(old.signature, originals)):
                continue
            rebuilt.set_initial_value(em.FluentExp(new, [em.ObjectExp(obj) for obj in arguments]), zero)


class _Flattener(IdentityDagWalker):  # type: ignore[misc]  # unified-planning ships no type information
    """Rebuilds an expression over the flat types: fluents, objects, parameters and variables
    retyped (names unchanged), and each quantified variable of a type below another guarded."""

    def __init__(
        self,
        environment: Any,
        fluents: Mapping[Any, Any],
        top: Callable[[Any], Any],
        guard: Callable[[Any, Any], Any],
    ) -> None:
        IdentityDagWalker.__init__(self, environment, True)
        self._fluents = fluents
        self._top = top
        self._guard = guard

    def rewrite(self, expression: Any) -> Any:
        return self.walk(expression)

    def variable(self, variable: Any) -> Any:
        return Variable(variable.name, self._top(variable.type), self.environment)

    def walk_fluent_exp(self, expression: Any, args: list[Any], **kwargs: Any) -> Any:
        return self.manager.FluentExp(self._fluents[expression.fluent()], args)

    def walk_object_exp(self, expression: Any, args: list[Any], **kwargs: Any) -> Any:
        obj = expression.object()
        return self.manager.ObjectExp(Object(obj.name, self._top(obj.type), self.environment))

    def walk_param_exp(self, expression: Any, args: list[Any], **kwargs: Any) -> Any:
        parameter = expression.parameter()
        return self.manager.ParameterExp(Parameter(parameter.name, self._top(parameter.type), self.environment))

    def walk_variable_exp(self, expression: Any, args: list[Any], **kwargs: Any) -> Any:
        return self.manager.VariableExp(self.variable(expression.variable()))

    def walk_exists(self, expression: Any, args: list[Any], **kwargs: Any) -> Any:
        variables, guards = self._quantified(expression.variables())
        return self.manager.Exists(self.manager.And(*guards, args[0]), *variables)

    def walk_forall(self, expression: Any, args: list[Any], **kwargs: Any) -> Any:
        variables, guards = self._quantified(expression.variables())
        body = self.manager.Implies(self.manager.And(*guards), args[0]) if guards else args[0]
        return self.manager.Forall(body, *variables)

    def _quantified(self, variables: Any) -> tuple[list[Any], list[Any]]:
        new = [self.variable(v) for v in variables]
        found = (self._guard(old.type, self.manager.VariableExp(v)) for old, v in zip(variables, new))
        return new, [g for g in found if g is not None]


# -- defined values --------------------------------------------------------------------------------


def _defined_values(problem: Any) -> tuple[Any, str]:
    """A static numeric fluent's undefined values replaced by a guard on the actions that read it."""
    env = problem.environment
    em = env.expression_manager
    static = problem.get_static_fluents()
    defined: dict[Any, list[Any]] = {}
    for fluent in problem.fluents:
        if not (fluent.type.is_int_type() or fluent.type.is_real_type()) or fluent in problem.fluents_defaults:
            continue
        values = [(args, problem.initial_value(em.FluentExp(fluent, args))) for args in _groundings(problem, fluent)]
        if all(value is not None for _, value in values):
            continue
        if fluent not in static:
            raise _CannotFit  # an effect may give it a value later: a static guard would be wrong
        defined[fluent] = [args for args, value in values if value is not None]
    if not defined:
        raise _CannotFit
    for expression in _outside_actions(problem):
        if any(f.fluent() in defined for f in env.free_vars_extractor.get(expression)):
            raise _CannotFit  # read outside an action: no precondition can guard it
    names = _Names(problem)
    helpers = {
        fluent: Fluent(names.fresh(f"defined_{fluent.name}"), env.type_manager.BoolType(), fluent.signature, env)
        for fluent in defined
    }

    def reads(old_action: Any, new_action: Any) -> list[Any]:
        found: list[Any] = []
        # An action's cost is counted only when it runs, so the action's guard covers it too.
        costs = (m.costs.get(old_action) for m in problem.quality_metrics if isinstance(m, MinimizeActionCosts))
        for expression in [*_action_expressions(old_action), *(cost for cost in costs if cost is not None)]:
            for read in env.free_vars_extractor.get(expression):
                if read.fluent() in helpers:
                    if any(not (a.is_parameter_exp() or a.is_object_exp()) for a in read.args):
                        raise _CannotFit  # a quantified variable or a nested fluent
                    guard = em.FluentExp(helpers[read.fluent()], read.args)
                    if guard not in found:
                        found.append(guard)
        return found

    def default(fluent: Any, value: Any) -> Any:
        if fluent in helpers:
            return em.Int(0) if fluent.type.is_int_type() else em.Real(Fraction(0))
        return value

    rebuilt = _rebuild(problem, _Rewrite(guards=reads, default=default))
    for fluent, helper in helpers.items():
        rebuilt.add_fluent(helper, default_initial_value=False)
        for args in defined[fluent]:
            rebuilt.set_initial_value(em.FluentExp(helper, args), True)
    count = len(helpers)
    named = ", ".join(fluent.name for fluent in helpers)
    return (
        rebuilt,
        f"guarded the undefined values of {count} numeric fluent{'s' if count != 1 else ''} ({named}) to run",
    )


def _groundings(problem: Any, fluent: Any) -> Iterator[list[Any]]:
    em = problem.environment.expression_manager
    for objects in itertools.product(*(problem.objects(p.type) for p in fluent.signature)):
        yield [em.ObjectExp(obj) for obj in objects]


def _action_expressions(action: Any) -> Iterator[Any]:
    """Every expression an action reads: conditions, duration, effects (targets, values, conditions)."""
    if isinstance(action, InstantaneousAction):
        yield from action.preconditions
        effects = list(action.effects)
    else:
        for conditions in action.conditions.values():
            yield from conditions
        yield action.duration.lower
        yield action.duration.upper
        effects = [effect for listed in action.effects.values() for effect in listed]
    for effect in effects:
        yield from (effect.fluent, effect.value, effect.condition)


def _outside_actions(problem: Any) -> Iterator[Any]:
    yield from problem.goals
    for goals in problem.timed_goals.values():
        yield from goals
    for effects in problem.timed_effects.values():
        for effect in effects:
            yield from (effect.fluent, effect.value, effect.condition)
    yield from problem.trajectory_constraints
    for metric in problem.quality_metrics:
        yield from _metric_expressions(metric)


def _metric_expressions(metric: Any) -> Iterator[Any]:
    if isinstance(metric, MinimizeActionCosts):
        # Each action's own cost is read with the action (see _defined_values); the default is not.
        if metric.default is not None:
            yield metric.default
    elif isinstance(metric, (MinimizeExpressionOnFinalState, MaximizeExpressionOnFinalState)):
        yield metric.expression
    elif isinstance(metric, Oversubscription):
        yield from metric.goals
    elif isinstance(metric, TemporalOversubscription):
        yield from (goal for _, goal in metric.goals)


# -- rebuilding a problem --------------------------------------------------------------------------


class _Names:
    """Names the problem does not use, for the predicates a step adds."""

    def __init__(self, problem: Any) -> None:
        self._problem = problem
        self._taken: set[str] = set()

    def fresh(self, base: str) -> str:
        name, number = base, 1
        while self._problem.has_name(name) or name in self._taken:
            number += 1
            name = f"{base}_{number}"
        self._taken.add(name)
        return name


def _unchanged(value: Any) -> Any:
    return value


@dataclass(frozen=True)
class _Rewrite:
    """What a step changes; everything else is copied as it is."""

    expression: Callable[[Any], Any] = _unchanged
    fluent: Callable[[Any], Any] = _unchanged
    retype: Callable[[Any], Any] = _unchanged
    # Conditions the rebuilt action needs before the old ones (at start for a durative action).
    guards: Callable[[Any, Any], list[Any]] = field(default=lambda old, new: [])
    # The guard of a variable of an effect's forall (None: none needed).
    forall_guard: Callable[[Any], Any] = field(default=lambda variable: None)
    # The new default value of a fluent, given its old one (None: no default).
    default: Callable[[Any, Any], Any] = field(default=lambda fluent, value: value)


def _rebuild(problem: Any, rewrite: _Rewrite) -> Any:
    """A new problem with every expression, fluent and type passed through ``rewrite``."""
    if problem.processes or problem.events:
        raise _CannotFit  # PDDL+: none of the steps is written for it
    env = problem.environment
    expression = rewrite.expression
    new = Problem(problem.name, env, initial_defaults=problem.initial_defaults)
    new.epsilon = problem.epsilon
    new.discrete_time = problem.discrete_time
    new.self_overlapping = problem.self_overlapping
    for old in problem.fluents:
        default = rewrite.default(old, problem.fluents_defaults.get(old))
        new.add_fluent(rewrite.fluent(old), default_initial_value=None if default is None else expression(default))
    new.add_objects(Object(obj.name, rewrite.retype(obj.type), env) for obj in problem.all_objects)
    actions = {}
    for old in problem.actions:
        actions[old] = _rebuild_action(old, rewrite)
        new.add_action(actions[old])
    for goal in problem.goals:
        new.add_goal(expression(goal))
    for interval, goal in _each(problem.timed_goals):
        new.add_timed_goal(interval, expression(goal))
    for timing, effect in _each(problem.timed_effects):
        _add_effect(new, effect, rewrite, timing)
    for constraint in problem.trajectory_constraints:
        new.add_trajectory_constraint(expression(constraint))
    for target, value in problem.explicit_initial_values.items():
        new.set_initial_value(expression(target), expression(value))
    for metric in problem.quality_metrics:
        new.add_quality_metric(_rebuild_metric(metric, actions, expression, env))
    return new


def _rebuild_action(old: Any, rewrite: _Rewrite) -> Any:
    env = old.environment
    expression = rewrite.expression
    parameters = OrderedDict((p.name, rewrite.retype(p.type)) for p in old.parameters)
    if type(old) is InstantaneousAction:
        if old.simulated_effect is not None:
            raise _CannotFit
        new = InstantaneousAction(old.name, parameters, env)
        for condition in [*rewrite.guards(old, new), *map(expression, old.preconditions)]:
            new.add_precondition(condition)
        for effect in old.effects:
            _add_effect(new, effect, rewrite)
        return new
    if type(old) is DurativeAction:
        if old.continuous_effects or old.simulated_effects:
            raise _CannotFit
        new = DurativeAction(old.name, parameters, env)
        duration = old.duration
        new.set_duration_constraint(
            DurationInterval(
                expression(duration.lower),
                expression(duration.upper),
                duration.is_left_open(),
                duration.is_right_open(),
            )
        )
        for guard in rewrite.guards(old, new):
            new.add_condition(StartTiming(), guard)
        for interval, condition in _each(old.conditions):
            new.add_condition(interval, expression(condition))
        for timing, effect in _each(old.effects):
            _add_effect(new, effect, rewrite, timing)
        return new
    raise _CannotFit  # sensing actions and other kinds: not from PDDL


def _each(timed: Mapping[Any, Iterable[Any]]) -> Iterator[tuple[Any, Any]]:
    """(timing, item) for each item of a mapping from timings (or intervals) to lists: goals,
    conditions, effects."""
    return ((timing, item) for timing, items in timed.items() for item in items)


def _add_effect(target: Any, effect: Any, rewrite: _Rewrite, timing: Any = None) -> None:
    """``effect`` rewritten, added to an action or (with its timing) to the problem's timed effects."""
    expression = rewrite.expression
    em = effect.environment.expression_manager
    variables = [rewrite.expression(em.VariableExp(v)).variable() for v in effect.forall]
    guards = [g for g in map(rewrite.forall_guard, effect.forall) if g is not None]
    condition = em.And(*guards, expression(effect.condition)) if guards else expression(effect.condition)
    if effect.is_increase():
        add = target.add_increase_effect
    elif effect.is_decrease():
        add = target.add_decrease_effect
    elif effect.is_assignment():
        add = target.add_timed_effect if isinstance(target, Problem) else target.add_effect
    else:
        raise _CannotFit
    arguments = (expression(effect.fluent), expression(effect.value), condition, variables)
    add(*((timing,) if timing is not None else ()), *arguments)


def _rebuild_metric(metric: Any, actions: Mapping[Any, Any], expression: Callable[[Any], Any], env: Any) -> Any:
    if isinstance(metric, MinimizeActionCosts):
        costs = {actions[action]: expression(cost) for action, cost in metric.costs.items()}
        default = None if metric.default is None else expression(metric.default)
        return MinimizeActionCosts(costs, default, env)
    if isinstance(metric, MinimizeExpressionOnFinalState):
        return MinimizeExpressionOnFinalState(expression(metric.expression), env)
    if isinstance(metric, MaximizeExpressionOnFinalState):
        return MaximizeExpressionOnFinalState(expression(metric.expression), env)
    if isinstance(metric, (MinimizeMakespan, MinimizeSequentialPlanLength)):
        return metric
    if isinstance(metric, Oversubscription):
        return Oversubscription(_merged((expression(goal), gain) for goal, gain in metric.goals.items()), env)
    if isinstance(metric, TemporalOversubscription):
        goals = ((interval, expression(goal)) for interval, goal in metric.goals)
        return TemporalOversubscription(_merged(zip(goals, metric.goals.values())), env)
    raise _CannotFit


def _merged(pairs: Iterable[tuple[Any, Any]]) -> dict[Any, Any]:
    """Gains of goals that became one expression add up."""
    merged: dict[Any, Any] = {}
    for goal, gain in pairs:
        merged[goal] = merged.get(goal, 0) + gain
    return merged
