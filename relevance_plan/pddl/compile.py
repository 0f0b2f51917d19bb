"""Compilations: the same classical task in fewer PDDL features, and the way back for its plans.

A planner that lacks a feature can still solve a task that uses it once the
feature is compiled away.  Each compilation here is a function from a
domain and a problem to a :class:`Compilation`: a new domain and problem
without one feature, and :meth:`Compilation.map_back`, which turns a plan of
the compiled task into a plan of the given one.  :data:`COMPILATIONS` lists
them, each with the features it removes, in the order they must run (a later one removes what an earlier one may
add: conditional effects become negated preconditions, existentials become
disjunctions):

- ``quantified-preconditions``: an existential at the top of a precondition
  becomes extra action parameters (dropped when mapping back); every other
  quantifier in a condition becomes the conjunction or disjunction of its
  instances over the task's objects and constants;
- ``conditional-effects``: universal effects are instantiated; an action
  with k effect conditions becomes one action per combination (2^k), the
  chosen conditions and the negations of the others added to its
  precondition;
- ``disjunctive-preconditions``: conditions in negation normal form, then
  one action per disjunct of the precondition's disjunctive normal form; a
  disjunctive goal is reached by a new action (dropped when mapping back);
- ``equality``: ``(= a b)`` becomes a static predicate true of every object
  with itself;
- ``negative-preconditions``: a predicate used negatively gets a complement,
  initialised from the closed world and kept up to date by every effect on
  the predicate.  Where one action may add and delete the same atom (the
  add wins in PDDL), the action is split on whether the two atoms are the
  same.

Quantifiers are instantiated over the problem's objects, so a compiled
domain belongs to one problem.  Names are kept (compiled files are written
with the formatter, objects in the user's spelling); new actions and
predicates get fresh names.  A split action maps back to its original with
the original arguments.  Classical tasks only: a domain with durative
actions is refused.
"""

from __future__ import annotations

import dataclasses
import itertools
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass

from relevance_plan.errors import UnsupportedFeatureError
from relevance_plan.pddl.formulas import (
    TRUE,
    And,
    Arithmetic,
    Atom,
    Comparison,
    Equality,
    Exists,
    Fluent,
    Forall,
    Formula,
    GroundAtom,
    Imply,
    Not,
    Number,
    NumericEffect,
    NumericVariable,
    Or,
    Parameters,
    When,
    is_variable,
    names_in,
    substitute,
    walk,
)
from relevance_plan.pddl.model import Action, DerivedPredicate, Domain, ObjectsOfType, Problem, all_objects, frozen
from relevance_plan.pddl.plans import Plan, PlanStep

FALSE = Or(())

# Beyond these the compiled task is too large to be worth writing: refuse, naming the cause.
MAX_INSTANCES = 100_000  # quantifier instances in one condition
MAX_VARIANTS = 256  # actions one action becomes
MAX_COMPLEMENT_FACTS = 1_000_000  # initial facts of the complements of the negated predicates

# The requirements each compilation makes unnecessary; ``:adl`` is expanded into its parts first.
_ADL = frozenset(
    {
        ":strips",
        ":typing",
        ":negative-preconditions",
        ":disjunctive-preconditions",
        ":equality",
        ":quantified-preconditions",
        ":conditional-effects",
    }
)
_QUANTIFIED = frozenset({":quantified-preconditions", ":existential-preconditions", ":universal-preconditions"})


@dataclass(frozen=True, slots=True)
class Origin:
    """Where a compiled action comes from: the original action (None: a step the compilation
    added, dropped when mapping back) and, for each of its parameters, the index of the
    compiled step's argument that fills it or the constant it was bound to."""

    action: str | None
    args: tuple[int | str, ...] = ()


@dataclass(frozen=True)
class Compilation:
    """A task without one feature, and how its plans map back to the task it was compiled from."""

    name: str
    domain: Domain
    problem: Problem
    origins: Mapping[str, Origin]  # compiled action -> origin; an action not listed is the original's own

    def map_back(self, plan: Plan) -> Plan:
        steps: list[PlanStep] = []
        for step in plan.steps:
            origin = self.origins.get(step.action)
            if origin is None:
                steps.append(step)
            elif origin.action is not None:
                args = tuple(step.args[a] if isinstance(a, int) else a for a in origin.args)
                steps.append(PlanStep(origin.action, args, step.time, step.duration))
        return Plan(tuple(steps), plan.cost)


# --------------------------------------------------------------------------- shared pieces


class _Task:
    """The task being compiled: its objects by type, and names not yet taken."""

    def __init__(self, domain: Domain, problem: Problem):
        if domain.temporal:
            raise UnsupportedFeatureError("durative actions cannot be compiled to fewer features", path=domain.path)
        self.domain = domain
        self.problem = problem
        self.objects = all_objects(domain, problem)
        self.of_type = ObjectsOfType(domain, self.objects)
        self.taken = {
            *domain.predicates,
            *domain.functions,
            *domain.types,
            *self.objects,
            *(action.name for action in domain.actions),
        }

    def bindings(self, parameters: Parameters) -> Iterator[dict[str, str]]:
        names = [variable for variable, _ in parameters]
        for values in itertools.product(*(self.of_type(kind) for _, kind in parameters)):
            yield dict(zip(names, values))

    def fresh(self, base: str) -> str:
        """``base``, or ``base-2``, ``base-3``, ...: a name no predicate, action, type or object has."""
        name, number = base, 1
        while name in self.taken:
            number += 1
            name = f"{base}-{number}"
        self.taken.add(name)
        return name


def _conjoin(parts: Iterable[Formula]) -> Formula:
    """The conjunction of ``parts``, nested conjunctions flattened, true parts dropped, false absorbing."""
    return _junction(And, FALSE, parts)


def _disjoin(parts: Iterable[Formula]) -> Formula:
    """The disjunction of ``parts``, nested disjunctions flattened, false parts dropped, true absorbing."""
    return _junction(Or, TRUE, parts)


def _junction(kind: type[And] | type[Or], absorbing: Formula, parts: Iterable[Formula]) -> Formula:
    """``kind`` of ``parts`` flattened (each once), or ``absorbing`` when one of them is; one part is itself."""
    flat: list[Formula] = []
    for part in parts:
        if part == absorbing:
            return absorbing
        flat.extend(part.parts if isinstance(part, kind) else (part,))
    unique = tuple(dict.fromkeys(flat))
    return unique[0] if len(unique) == 1 else kind(unique)


def _conjuncts(formula: Formula) -> tuple[Formula, ...]:
    return formula.parts if isinstance(formula, And) else (formula,)


_NEGATED_COMPARISON = {"<": ">=", "<=": ">", ">": "<=", ">=": "<"}


def negation_normal_form(formula: Formula, positive: bool = True) -> Formula:
    """``formula`` with negations only on atoms and equalities, ``imply`` spelled as ``or``."""
    if isinstance(formula, Not):
        return negation_normal_form(formula.body, not positive)
    if isinstance(formula, (And, Or)):
        parts = [negation_normal_form(part, positive) for part in formula.parts]
        return _conjoin(parts) if isinstance(formula, And) == positive else _disjoin(parts)
    if isinstance(formula, Imply):
        return negation_normal_form(Or((Not(formula.condition), formula.consequence)), positive)
    if isinstance(formula, (Forall, Exists)):
        body = negation_normal_form(formula.body, positive)
        keep = isinstance(formula, Forall) == positive
        return Forall(formula.parameters, body) if keep else Exists(formula.parameters, body)
    if isinstance(formula, Comparison) and not positive and formula.op in _NEGATED_COMPARISON:
        return Comparison(_NEGATED_COMPARISON[formula.op], formula.left, formula.right)
    return formula if positive else Not(formula)


def _map_literals(formula: Formula, change: Callable[[Formula], Formula]) -> Formula:
    """A condition in negation normal form with each literal (atom, equality, comparison, or its
    negation) replaced by ``change(literal)``."""
    if isinstance(formula, (And, Or)):
        parts = [_map_literals(part, change) for part in formula.parts]
        return _conjoin(parts) if isinstance(formula, And) else _disjoin(parts)
    if isinstance(formula, (Forall, Exists)):
        return type(formula)(formula.parameters, _map_literals(formula.body, change))
    return change(formula)


def _map_effect(
    effect: Formula, change: Callable[[Formula], Formula], condition: Callable[[Formula], Formula]
) -> Formula:
    """An effect with each literal or numeric effect replaced by ``change(it)`` and each ``when``
    condition by ``condition(it)``."""
    if isinstance(effect, And):
        return And(tuple(_map_effect(part, change, condition) for part in effect.parts))
    if isinstance(effect, When):
        return When(condition(effect.condition), _map_effect(effect.effect, change, condition))
    if isinstance(effect, Forall):
        return Forall(effect.parameters, _map_effect(effect.body, change, condition))
    return change(effect)


def _unchanged(node: Formula) -> Formula:
    return node


def _requirements(requirements: frozenset[str], dropped: frozenset[str]) -> frozenset[str]:
    if ":adl" in requirements:
        requirements = (requirements - {":adl"}) | _ADL
    return requirements - dropped


def _compiled(
    name: str,
    task: _Task,
    actions: Sequence[tuple[Action, Origin | None]],
    *,
    dropped: frozenset[str],
    goal: Formula | None = None,
    derived: tuple[DerivedPredicate, ...] | None = None,
    predicates: Mapping[str, Parameters] | None = None,
    init: Iterable[GroundAtom] = (),
) -> Compilation:
    """The compiled task: these actions (each with its origin), the domain's other parts as given.

    Objects the compiled domain names (instances of quantifiers) become its constants: a domain
    cannot name a problem's objects.
    """
    domain, problem = task.domain, task.problem
    rules = domain.derived if derived is None else derived
    parts = [node for action, _ in actions for node in (action.precondition, action.effect)]
    named = {name for node in [*parts, *(rule.body for rule in rules)] for name in names_in(node)}
    moved = {name: kind for name, kind in problem.objects.items() if name in named}
    new_domain = dataclasses.replace(
        domain,
        requirements=_requirements(domain.requirements, dropped),
        constants=frozen({**domain.constants, **moved}),
        predicates=frozen({**domain.predicates, **(predicates or {})}),
        actions=tuple(action for action, _ in actions),
        derived=rules,
        path=None,
    )
    added = frozenset(tuple(atom) for atom in init)
    new_problem = dataclasses.replace(
        problem,
        objects=frozen({name: kind for name, kind in problem.objects.items() if name not in moved}),
        init=problem.init | added if added else problem.init,
        goal=problem.goal if goal is None else goal,
        requirements=_requirements(problem.requirements, dropped),
        text="",
        path=None,
        object_groups=(),
        init_spans=(),
    )
    origins = {action.name: origin for action, origin in actions if origin is not None}
    return Compilation(name, new_domain, new_problem, frozen(origins))


def _instance(formula: Formula, binding: Mapping[str, str]) -> Formula:
    """``formula`` with its free variables bound (a formula stays a formula)."""
    node = substitute(formula, binding)
    assert not isinstance(node, (Number, Fluent, NumericVariable, Arithmetic))
    return node


def _identity(action: Action) -> Origin:
    return Origin(action.name, tuple(range(len(action.parameters))))


# --------------------------------------------------------------------------- quantifiers


def compile_quantified_preconditions(domain: Domain, problem: Problem) -> Compilation:
    task = _Task(domain, problem)

    def ground(formula: Formula) -> Formula:
        return _ground_quantifiers(formula, task)

    actions: list[tuple[Action, Origin | None]] = []
    for action in domain.actions:
        parameters, precondition = _lift_existentials(action.parameters, action.precondition)
        changed = dataclasses.replace(
            action,
            parameters=parameters,
            precondition=ground(precondition),
            effect=_map_effect(action.effect, _unchanged, ground),
        )
        lifted = len(parameters) > len(action.parameters)
        actions.append((changed, Origin(action.name, tuple(range(len(action.parameters)))) if lifted else None))
    derived = tuple(dataclasses.replace(rule, body=ground(rule.body)) for rule in domain.derived)
    return _compiled(
        "quantified-preconditions", task, actions, dropped=_QUANTIFIED, goal=ground(problem.goal), derived=derived
    )


def _lift_existentials(parameters: Parameters, precondition: Formula) -> tuple[Parameters, Formula]:
    """Existentials among the top-level conjuncts become parameters (renamed apart)."""
    taken = {variable for variable, _ in parameters}
    added: list[tuple[str, str]] = []
    kept: list[Formula] = []
    pending = list(_conjuncts(precondition))
    while pending:
        part = pending.pop(0)
        if isinstance(part, And):
            pending[:0] = part.parts
            continue
        if not isinstance(part, Exists):
            kept.append(part)
            continue
        renaming: dict[str, str] = {}
        for variable, kind in part.parameters:
            name, number = variable, 1
            while name in taken:
                number += 1
                name = f"{variable}-{number}"
            taken.add(name)
            renaming[variable] = name
            added.append((name, kind))
        pending[:0] = _conjuncts(_instance(part.body, renaming))
    if not added:
        return parameters, precondition
    return parameters + tuple(added), _conjoin(kept)


def _ground_quantifiers(formula: Formula, task: _Task) -> Formula:
    """Every quantifier of a condition replaced by the conjunction or disjunction of its instances."""
    if isinstance(formula, (Forall, Exists)):
        body = _ground_quantifiers(formula.body, task)
        instances: list[Formula] = []
        for binding in task.bindings(formula.parameters):
            instances.append(_instance(body, binding))
            if len(instances) > MAX_INSTANCES:
                raise UnsupportedFeatureError(
                    f"a quantifier over {_describe(formula.parameters)} has more than {MAX_INSTANCES} instances:"
                    " too many to compile away",
                    path=task.domain.path,
                )
        return _conjoin(instances) if isinstance(formula, Forall) else _disjoin(instances)
    if isinstance(formula, (And, Or)):
        parts = [_ground_quantifiers(part, task) for part in formula.parts]
        return _conjoin(parts) if isinstance(formula, And) else _disjoin(parts)
    if isinstance(formula, Not):
        return Not(_ground_quantifiers(formula.body, task))
    if isinstance(formula, Imply):
        return Imply(_ground_quantifiers(formula.condition, task), _ground_quantifiers(formula.consequence, task))
    return formula


def _describe(parameters: Parameters) -> str:
    return " ".join(f"{variable} - {kind}" for variable, kind in parameters)


# --------------------------------------------------------------------------- conditional effects


def compile_conditional_effects(domain: Domain, problem: Problem) -> Compilation:
    task = _Task(domain, problem)
    actions: list[tuple[Action, Origin | None]] = []
    for action in domain.actions:
        actions.extend(_unconditional_variants(action, task))
    return _compiled("conditional-effects", task, actions, dropped=frozenset({":conditional-effects"}))


def _unconditional_variants(action: Action, task: _Task) -> list[tuple[Action, Origin | None]]:
    """The action as actions without effect conditions or universal effects: one per combination of
    its effect conditions (the action itself, its universal effects instantiated, when it has none)."""
    guarded: dict[Formula, list[Formula]] = {}
    for condition, primitive in _effect_primitives(action.effect, TRUE, task):
        guarded.setdefault(condition, []).append(primitive)
    plain = guarded.pop(TRUE, [])
    if not guarded:
        return [(dataclasses.replace(action, effect=And(tuple(plain))), None)]
    conditions = list(guarded)
    if 2 ** len(conditions) > MAX_VARIANTS:
        raise UnsupportedFeatureError(
            f"action '{action.name}' has {len(conditions)} effect conditions: {2 ** len(conditions)} actions"
            " are too many to compile them away",
            path=task.domain.path,
        )
    variants: list[tuple[Action, Origin | None]] = []
    for chosen in itertools.product((True, False), repeat=len(conditions)):
        # negations in normal form: a negated conjunction is a disjunction, and says so
        chosen_conditions = (c if on else negation_normal_form(Not(c)) for c, on in zip(conditions, chosen))
        precondition = _conjoin([action.precondition, *chosen_conditions])
        effects = plain + [e for c, on in zip(conditions, chosen) if on for e in guarded[c]]
        variant = Action(task.fresh(f"{action.name}-when"), action.parameters, precondition, And(tuple(effects)))
        variants.append((variant, _identity(action)))
    return variants


def _effect_primitives(effect: Formula, condition: Formula, task: _Task) -> Iterator[tuple[Formula, Formula]]:
    """(condition, literal or numeric effect) for every part of an effect, universal effects instantiated."""
    if isinstance(effect, And):
        for part in effect.parts:
            yield from _effect_primitives(part, condition, task)
    elif isinstance(effect, When):
        yield from _effect_primitives(effect.effect, _conjoin([condition, effect.condition]), task)
    elif isinstance(effect, Forall):
        for binding in task.bindings(effect.parameters):
            yield from _effect_primitives(_instance(effect.body, binding), condition, task)
    else:
        yield condition, effect


# --------------------------------------------------------------------------- disjunctions


def compile_disjunctive_preconditions(domain: Domain, problem: Problem) -> Compilation:
    task = _Task(domain, problem)
    actions: list[tuple[Action, Origin | None]] = []
    for action in domain.actions:
        effect = _split_disjunctive_whens(action, task)
        disjuncts = _disjunctive_normal_form(negation_normal_form(action.precondition), action.name, task)
        if len(disjuncts) == 1:
            actions.append((dataclasses.replace(action, precondition=disjuncts[0], effect=effect), None))
            continue
        for disjunct in disjuncts:
            variant = dataclasses.replace(
                action, name=task.fresh(f"{action.name}-or"), precondition=disjunct, effect=effect
            )
            actions.append((variant, _identity(action)))
    derived = tuple(
        dataclasses.replace(rule, body=disjunct)
        for rule in domain.derived
        for disjunct in _disjunctive_normal_form(negation_normal_form(rule.body), rule.head.predicate, task)
    )
    goal_options = _disjunctive_normal_form(negation_normal_form(problem.goal), "the goal", task)
    predicates: dict[str, Parameters] = {}
    goal = goal_options[0] if len(goal_options) == 1 else FALSE
    if len(goal_options) > 1:
        # A disjunctive goal: one new action per option reaches a new goal atom.
        reached = task.fresh("goal-reached")
        predicates[reached] = ()
        for option in goal_options:
            actions.append((Action(task.fresh("reach-goal"), (), option, Atom(reached)), Origin(None)))
        goal = Atom(reached)
    return _compiled(
        "disjunctive-preconditions",
        task,
        actions,
        dropped=frozenset({":disjunctive-preconditions"}),
        goal=goal,
        derived=derived,
        predicates=predicates,
    )


def _disjunctive_normal_form(formula: Formula, owner: str, task: _Task) -> list[Formula]:
    """The disjuncts (conjunctions of literals) of a condition in negation normal form."""
    formula = _open_disjunctive_quantifiers(formula, task)
    options: list[tuple[Formula, ...]] = [()]
    for part in _conjuncts(formula):
        alternatives = part.parts if isinstance(part, Or) else (part,)
        expanded: list[tuple[Formula, ...]] = []
        for alternative in alternatives:
            inner = (
                _disjunctive_normal_form(alternative, owner, task)
                if isinstance(alternative, (And, Or))
                else [alternative]
            )
            expanded.extend(option + _conjuncts(choice) for option in options for choice in inner)
        options = expanded
        if len(options) > MAX_VARIANTS:
            raise UnsupportedFeatureError(
                f"the precondition of {owner} has more than {MAX_VARIANTS} disjuncts: too many to compile away",
                path=task.domain.path,
            )
    return list(dict.fromkeys(_conjoin(option) for option in options if FALSE not in option))


def _open_disjunctive_quantifiers(formula: Formula, task: _Task) -> Formula:
    """A quantifier with a disjunction inside has no disjunctive normal form: its instances replace it."""
    if isinstance(formula, (Forall, Exists)):
        if any(isinstance(node, Or) for node in walk(formula.body)):
            return negation_normal_form(_ground_quantifiers(formula, task))
        return formula
    if isinstance(formula, (And, Or)):
        parts = [_open_disjunctive_quantifiers(part, task) for part in formula.parts]
        return _conjoin(parts) if isinstance(formula, And) else _disjoin(parts)
    return formula


def _split_disjunctive_whens(action: Action, task: _Task) -> Formula:
    """``(when (or a b) e)`` as ``(when a e)`` and ``(when b e)``: applying a literal twice changes
    nothing, but a numeric effect would apply twice, so that case is refused."""

    def split(effect: Formula) -> Formula:
        if isinstance(effect, And):
            return And(tuple(split(part) for part in effect.parts))
        if isinstance(effect, Forall):
            return Forall(effect.parameters, split(effect.body))
        if not isinstance(effect, When):
            return effect
        inner = split(effect.effect)
        disjuncts = _disjunctive_normal_form(negation_normal_form(effect.condition), f"'{action.name}'", task)
        if len(disjuncts) > 1 and any(isinstance(node, NumericEffect) for node in _effect_parts(inner)):
            raise UnsupportedFeatureError(
                f"action '{action.name}' has a numeric effect under a disjunctive condition, which cannot be"
                " compiled away",
                path=task.domain.path,
            )
        whens = tuple(When(disjunct, inner) for disjunct in disjuncts)
        return whens[0] if len(whens) == 1 else And(whens)

    return split(action.effect)


def _effect_parts(effect: Formula) -> Iterator[Formula]:
    if isinstance(effect, And):
        for part in effect.parts:
            yield from _effect_parts(part)
    elif isinstance(effect, (When, Forall)):
        yield from _effect_parts(effect.effect if isinstance(effect, When) else effect.body)
    else:
        yield effect


# --------------------------------------------------------------------------- equality


def compile_equality(domain: Domain, problem: Problem) -> Compilation:
    task = _Task(domain, problem)
    same = task.fresh("same-object")

    def replace_equality(literal: Formula) -> Formula:
        if isinstance(literal, Equality):
            return Atom(same, (literal.left, literal.right))
        if isinstance(literal, Not) and isinstance(literal.body, Equality):
            return Not(Atom(same, (literal.body.left, literal.body.right)))
        return literal

    def condition(formula: Formula) -> Formula:
        return _map_literals(negation_normal_form(formula), replace_equality)

    actions: list[tuple[Action, Origin | None]] = [
        (
            dataclasses.replace(
                action,
                precondition=condition(action.precondition),
                effect=_map_effect(action.effect, _unchanged, condition),
            ),
            None,
        )
        for action in domain.actions
    ]
    return _compiled(
        "equality",
        task,
        actions,
        dropped=frozenset({":equality"}),
        goal=condition(problem.goal),
        derived=tuple(dataclasses.replace(rule, body=condition(rule.body)) for rule in domain.derived),
        predicates={same: (("?a", "object"), ("?b", "object"))},
        init=((same, name, name) for name in task.objects),
    )


# --------------------------------------------------------------------------- negative preconditions


def compile_negative_preconditions(domain: Domain, problem: Problem) -> Compilation:
    task = _Task(domain, problem)
    goal = negation_normal_form(problem.goal)
    bodies = [negation_normal_form(rule.body) for rule in domain.derived]
    actions = [
        (dataclasses.replace(a, precondition=negation_normal_form(a.precondition)), None) for a in domain.actions
    ]
    complementer = _Complementer(task, actions, [goal, *bodies])
    refused = set(complementer.complement) & domain.derived_predicates
    if refused:
        raise UnsupportedFeatureError(
            f"derived predicate '{sorted(refused)[0]}' is used negatively, which cannot be compiled away",
            path=domain.path,
        )
    compiled: list[tuple[Action, Origin | None]] = []
    for action, origin in complementer.actions:
        for variant, split in complementer.split(action):
            compiled.append((complementer.complemented(variant), _compose(origin, split)))
    complement = complementer.complement
    predicates: dict[str, Parameters] = {complement[p]: domain.predicates[p] for p in complement}
    init = list(_complement_facts(task, complement))
    if complementer.distinct:
        predicates[complementer.distinct] = (("?a", "object"), ("?b", "object"))
        init.extend((complementer.distinct, a, b) for a in task.objects for b in task.objects if a != b)
    return _compiled(
        "negative-preconditions",
        task,
        compiled,
        dropped=frozenset({":negative-preconditions"}),
        goal=_positive(goal, complement),
        derived=tuple(
            dataclasses.replace(rule, body=_positive(body, complement)) for rule, body in zip(domain.derived, bodies)
        ),
        predicates=predicates,
        init=init,
    )


def _compose(first: Origin | None, then: Origin | None) -> Origin | None:
    """The origin of an action made from an action that was itself made from another."""
    if then is None:
        return first
    if first is None:
        return then
    return Origin(first.action, tuple(a if isinstance(a, str) else then.args[a] for a in first.args))


def _negated_predicates(conditions: Iterable[Formula]) -> set[str]:
    found: set[str] = set()

    def note(literal: Formula) -> Formula:
        if isinstance(literal, Not) and isinstance(literal.body, Atom):
            found.add(literal.body.predicate)
        return literal

    for condition in conditions:
        _map_literals(condition, note)
    return found


def _positive(condition: Formula, complement: Mapping[str, str]) -> Formula:
    """A condition in negation normal form with each negated atom of ``complement``'s predicates
    replaced by the complement's atom."""

    def replace(literal: Formula) -> Formula:
        if isinstance(literal, Not) and isinstance(literal.body, Atom) and literal.body.predicate in complement:
            return Atom(complement[literal.body.predicate], literal.body.args)
        return literal

    return _map_literals(condition, replace)


def _flatten_effect(effect: Formula) -> Formula:
    if not isinstance(effect, And):
        return effect
    parts: list[Formula] = []
    for part in effect.parts:
        flat = _flatten_effect(part)
        parts.extend(flat.parts if isinstance(flat, And) else (flat,))
    return And(tuple(parts))


def _complement_facts(task: _Task, complement: Mapping[str, str]) -> Iterator[GroundAtom]:
    """The closed world: a complement holds initially of every typed tuple its predicate does not."""
    count = 0
    for predicate, name in complement.items():
        for binding in task.bindings(task.domain.predicates[predicate]):
            atom = (predicate, *binding.values())
            if atom in task.problem.init:
                continue
            count += 1
            if count > MAX_COMPLEMENT_FACTS:
                raise UnsupportedFeatureError(
                    f"the complement of '{predicate}' needs more than {MAX_COMPLEMENT_FACTS} initial facts:"
                    " too many to compile negative preconditions away",
                    path=task.problem.path,
                )
            yield (name, *binding.values())


@dataclass(frozen=True, slots=True)
class _EffectLiteral:
    """A literal of an action's effect on a complemented predicate, in its context."""

    atom: Atom
    is_add: bool
    plain: bool  # neither conditional nor under a universal effect


class _Complementer:
    """Complements for the negated predicates, kept up to date by every action's effects.

    An add of ``(p a)`` deletes ``(not-p a)``, a delete of ``(p b)`` adds
    ``(not-p b)``.  When one action may add and delete the same atom, the add
    wins in PDDL, so the complement's add (from the delete) must not happen.
    An action whose conditional or universal effects may do that first loses
    its effect conditions (one action per combination, as
    :func:`compile_conditional_effects` does).  Then an action whose
    unconditional effects may do it is split (:meth:`split`) into the case
    where the two atoms are the same (the parameters unified, the delete
    dropped) and the cases where one argument differs, guarded by a static
    ``distinct`` predicate.  A clash the precondition rules out (``(p ?x)`` and
    ``(not (p ?y))`` with ?x = ?y) needs nothing.
    """

    def __init__(self, task: _Task, actions: Sequence[tuple[Action, Origin | None]], conditions: list[Formula]):
        self.task = task
        self.distinct = ""  # the static predicate's name, once one is needed
        self.complement: dict[str, str] = {}
        actions = list(actions)
        # Expanding an action adds negated effect conditions to its precondition: repeat until nothing changes.
        while True:
            negated = _negated_predicates(
                [
                    *conditions,
                    *(a.precondition for a, _ in actions),
                    *(
                        negation_normal_form(w.condition)
                        for a, _ in actions
                        for w in walk(a.effect)
                        if isinstance(w, When)
                    ),
                ]
            )
            for predicate in sorted(negated - set(self.complement)):
                self.complement[predicate] = task.fresh(f"not-{predicate}")
            risky = [index for index, (action, _) in enumerate(actions) if self._conditional_clash(action)]
            if not risky:
                break
            for index in reversed(risky):
                action, origin = actions[index]
                actions[index : index + 1] = [
                    (dataclasses.replace(v, precondition=negation_normal_form(v.precondition)), _compose(origin, o))
                    for v, o in _unconditional_variants(action, task)
                ]
        self.actions: list[tuple[Action, Origin | None]] = actions

    def _distinct(self, left: str, right: str) -> Atom:
        if not self.distinct:
            self.distinct = self.task.fresh("distinct")
        return Atom(self.distinct, (left, right))

    def _literals(self, effect: Formula, inside: bool = False) -> Iterator[_EffectLiteral]:
        """The effect's literals on complemented predicates; ``plain`` when neither conditional nor universal."""
        if isinstance(effect, And):
            for part in effect.parts:
                yield from self._literals(part, inside)
        elif isinstance(effect, (When, Forall)):
            yield from self._literals(effect.effect if isinstance(effect, When) else effect.body, True)
        elif isinstance(effect, Atom) and effect.predicate in self.complement:
            yield _EffectLiteral(effect, True, not inside)
        elif isinstance(effect, Not) and isinstance(effect.body, Atom) and effect.body.predicate in self.complement:
            yield _EffectLiteral(effect.body, False, not inside)

    def _clash(self, action: Action, added: Atom, deleted: Atom, types: Mapping[str, str]) -> dict[str, str] | None:
        """The unifier under which the two atoms may be the same in a state the action applies in, or None."""
        if added.predicate != deleted.predicate:
            return None
        unifier = _unify(added.args, deleted.args, types, self.task)
        if unifier is None or _contradictory(_instance(action.precondition, unifier), self.distinct):
            return None
        return unifier

    def _conditional_clash(self, action: Action) -> bool:
        """Whether a conditional or universal literal may meet one of the opposite sign."""
        literals = list(self._literals(action.effect))
        if all(literal.plain for literal in literals):
            return False
        types = _effect_types(action)
        return any(
            self._clash(action, added.atom, deleted.atom, types) is not None
            for added in literals
            if added.is_add
            for deleted in literals
            if not deleted.is_add and not (added.plain and deleted.plain)
        )

    # ---------------------------------------------------------------- splitting

    def split(self, action: Action) -> list[tuple[Action, Origin | None]]:
        variants = self._split(action, tuple(variable for variable, _ in action.parameters), 0)
        if len(variants) == 1 and variants[0][0] is action:
            return [(action, None)]
        results: list[tuple[Action, Origin | None]] = []
        for variant, terms in variants:
            positions = [variable for variable, _ in variant.parameters]
            args = tuple(positions.index(t) if is_variable(t) else t for t in terms)
            renamed = dataclasses.replace(variant, name=self.task.fresh(f"{action.name}-case"))
            results.append((renamed, Origin(action.name, args)))
        return results

    def _split(self, action: Action, terms: tuple[str, ...], depth: int) -> list[tuple[Action, tuple[str, ...]]]:
        clash = self._plain_clash(action)
        if clash is None:
            return [(action, terms)]
        if depth > 8:
            raise UnsupportedFeatureError(
                f"action '{action.name}' adds and deletes too many atoms of negated predicates to compile them away",
                path=self.task.domain.path,
            )
        added, deleted, unifier = clash
        variants = self._split(_unified(action, unifier, deleted), tuple(unifier.get(t, t) for t in terms), depth + 1)
        for left, right in zip(added.args, deleted.args):
            if left != right:
                guard = self._distinct(left, right)
                guarded = dataclasses.replace(action, precondition=_conjoin([action.precondition, guard]))
                variants.extend(self._split(guarded, terms, depth + 1))
        return variants

    def _plain_clash(self, action: Action) -> tuple[Atom, Atom, dict[str, str]] | None:
        literals = [literal for literal in self._literals(action.effect) if literal.plain]
        types = dict(action.parameters)
        for added in (literal.atom for literal in literals if literal.is_add):
            for deleted in (literal.atom for literal in literals if not literal.is_add):
                unifier = self._clash(action, added, deleted, types)
                if unifier is not None:
                    return added, deleted, unifier
        return None

    # ---------------------------------------------------------------- complementing

    def complemented(self, action: Action) -> Action:
        """The action with positive preconditions, and effects that keep the complements up to date."""

        def keep_up(effect: Formula) -> Formula:
            if isinstance(effect, And):
                return And(tuple(keep_up(part) for part in effect.parts))
            if isinstance(effect, When):
                return When(_positive(negation_normal_form(effect.condition), self.complement), keep_up(effect.effect))
            if isinstance(effect, Forall):
                return Forall(effect.parameters, keep_up(effect.body))
            if isinstance(effect, Atom) and effect.predicate in self.complement:
                return And((effect, Not(Atom(self.complement[effect.predicate], effect.args))))
            if isinstance(effect, Not) and isinstance(effect.body, Atom) and effect.body.predicate in self.complement:
                return And((effect, Atom(self.complement[effect.body.predicate], effect.body.args)))
            return effect

        return dataclasses.replace(
            action,
            precondition=_positive(action.precondition, self.complement),
            effect=_flatten_effect(keep_up(action.effect)),
        )


def _effect_types(action: Action) -> dict[str, str]:
    """The types of the action's parameters and of its universal effects' variables (``object``
    for a name two of them give different types: the unifier then stays on the safe side)."""
    types = dict(action.parameters)
    stack = [action.effect]
    while stack:
        effect = stack.pop()
        if isinstance(effect, And):
            stack.extend(effect.parts)
        elif isinstance(effect, When):
            stack.append(effect.effect)
        elif isinstance(effect, Forall):
            for variable, kind in effect.parameters:
                types[variable] = kind if types.get(variable, kind) == kind else "object"
            stack.append(effect.body)
    return types


def _unify(
    left: tuple[str, ...], right: tuple[str, ...], types: Mapping[str, str], task: _Task
) -> dict[str, str] | None:
    """The most general binding of variables that makes the two argument lists equal, or None."""
    binding: dict[str, str] = {}

    def resolve(term: str) -> str:
        while term in binding:
            term = binding[term]
        return term

    for a, b in zip(left, right):
        a, b = resolve(a), resolve(b)
        if a == b:
            continue
        if not is_variable(a) and not is_variable(b):
            return None
        variable, other = (a, b) if is_variable(a) else (b, a)
        other_type = types.get(other) if is_variable(other) else task.objects.get(other)
        variable_type = types.get(variable, "object")
        if other_type is None:
            return None
        if not (task.domain.is_subtype(other_type, variable_type) or task.domain.is_subtype(variable_type, other_type)):
            return None
        if is_variable(other) and task.domain.is_subtype(variable_type, other_type) and variable_type != other_type:
            variable, other = other, variable  # keep the more specific type
        binding[variable] = other
    return {variable: resolve(variable) for variable in binding}


def _contradictory(precondition: Formula, distinct: str) -> bool:
    """Whether a precondition's top-level conjuncts hold a literal and its negation, or ``(distinct t t)``."""
    parts = set(_conjuncts(precondition))
    for part in parts:
        if isinstance(part, Not) and part.body in parts:
            return True
        if isinstance(part, Atom) and part.predicate == distinct and part.args[0] == part.args[1]:
            return True
    return False


def _unified(action: Action, unifier: Mapping[str, str], deleted: Atom) -> Action:
    """The action with the unifier applied and the delete the add overrides removed."""
    parameters = tuple((variable, kind) for variable, kind in action.parameters if variable not in unifier)
    gone = Not(_instance(deleted, unifier))
    kept = tuple(part for part in _conjuncts(_instance(action.effect, unifier)) if part != gone)
    precondition = _instance(action.precondition, unifier)
    return dataclasses.replace(action, parameters=parameters, precondition=precondition, effect=And(kept))


# --------------------------------------------------------------------------- the registry


@dataclass(frozen=True)
class Compiler:
    """A compilation of this module and the PDDL features it removes (requirement names without the
    colon, as ``planning.planners.requirements`` computes them from a task)."""

    compile: Callable[[Domain, Problem], Compilation]
    removes: frozenset[str]

    def __call__(self, domain: Domain, problem: Problem) -> Compilation:
        return self.compile(domain, problem)


# Run in this order: a later compilation removes what an earlier one may add.
COMPILATIONS: dict[str, Compiler] = {
    "quantified-preconditions": Compiler(
        compile_quantified_preconditions, frozenset({"universal-preconditions", "existential-preconditions"})
    ),
    "conditional-effects": Compiler(compile_conditional_effects, frozenset({"conditional-effects"})),
    "disjunctive-preconditions": Compiler(compile_disjunctive_preconditions, frozenset({"disjunctive-preconditions"})),
    "equality": Compiler(compile_equality, frozenset({"equality"})),
    "negative-preconditions": Compiler(compile_negative_preconditions, frozenset({"negative-preconditions"})),
}
