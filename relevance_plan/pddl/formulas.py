"""PDDL formulas as immutable typed nodes, and the one walk every consumer uses.

Conditions, effects, numeric expressions, timed parts and PDDL3 constraints
are small frozen dataclasses.  Terms stay plain strings (an object or
constant name, or a ``?variable``, lower-cased) and ground atoms stay tuples
``(predicate, arg, ...)``: states hold millions of those, and a tuple is the
cheapest hashable value Python has.

Every traversal goes through :func:`children` (the one place that knows
which fields of a node are sub-nodes).  On top of it sit the walks the
pipeline needs: :func:`walk`, :func:`literals` (atoms with their polarity),
:func:`effect_literals`, :func:`numeric_effects`, :func:`quantifiers`,
:func:`names_in` and :func:`substitute`.  Evaluation (the simulator) and
formatting dispatch on node types themselves; nothing else does.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Mapping
from dataclasses import dataclass
from typing import Any

Parameters = tuple[tuple[str, str], ...]  # ((?variable, type), ...)
GroundAtom = tuple[str, ...]  # (predicate, arg, ...)


def is_variable(term: str) -> bool:
    return term.startswith("?")


# --------------------------------------------------------------------------- numeric expressions


@dataclass(frozen=True, slots=True)
class Number:
    value: float


@dataclass(frozen=True, slots=True)
class Fluent:
    """A function term ``(f a ?x)``; ``total-cost``, ``total-time`` and ``is-violated`` included."""

    function: str
    args: tuple[str, ...] = ()


@dataclass(frozen=True, slots=True)
class NumericVariable:
    """``?duration`` in a duration constraint or a durative action's effect."""

    name: str


@dataclass(frozen=True, slots=True)
class Arithmetic:
    """``(+ a b)``, ``(- a b)``, ``(* a b)``, ``(/ a b)``; ``(- a)`` is negation (one argument)."""

    op: str
    args: tuple[Expression, ...]


Expression = Number | Fluent | NumericVariable | Arithmetic

# --------------------------------------------------------------------------- conditions


@dataclass(frozen=True, slots=True)
class Atom:
    predicate: str
    args: tuple[str, ...] = ()


@dataclass(frozen=True, slots=True)
class Equality:
    """``(= a b)`` between objects (numeric equality is a :class:`Comparison`)."""

    left: str
    right: str


@dataclass(frozen=True, slots=True)
class Not:
    body: Formula


@dataclass(frozen=True, slots=True)
class And:
    parts: tuple[Formula, ...] = ()


@dataclass(frozen=True, slots=True)
class Or:
    parts: tuple[Formula, ...] = ()


@dataclass(frozen=True, slots=True)
class Imply:
    condition: Formula
    consequence: Formula


@dataclass(frozen=True, slots=True)
class Exists:
    parameters: Parameters
    body: Formula


@dataclass(frozen=True, slots=True)
class Forall:
    """A universal condition, or a universally quantified effect."""

    parameters: Parameters
    body: Formula


@dataclass(frozen=True, slots=True)
class Comparison:
    """A numeric condition: ``op`` is one of ``< <= > >= =``."""

    op: str
    left: Expression
    right: Expression


TIMES = {"start": "at start", "end": "at end", "all": "over all"}


@dataclass(frozen=True, slots=True)
class Timed:
    """``(at start X)``, ``(at end X)``, ``(over all X)`` in a durative action (``when`` is a key of ``TIMES``)."""

    when: str
    body: Formula


@dataclass(frozen=True, slots=True)
class Preference:
    """A PDDL3 soft goal or soft constraint; ``name`` may be None (anonymous)."""

    name: str | None
    body: Formula


# PDDL3 trajectory-constraint operators and how many leading numbers each takes.
MODAL_OPERATORS = {
    "always": 0,
    "sometime": 0,
    "at-most-once": 0,
    "sometime-after": 0,
    "sometime-before": 0,
    "within": 1,
    "always-within": 1,
    "hold-after": 1,
    "hold-during": 2,
    "at-end": 0,  # (at end φ) inside :constraints
}


@dataclass(frozen=True, slots=True)
class Modal:
    """A PDDL3 trajectory constraint: ``(always φ)``, ``(within 5 φ)``, ``(sometime-after φ ψ)``, ..."""

    operator: str
    numbers: tuple[float, ...]
    parts: tuple[Formula, ...]


# --------------------------------------------------------------------------- effects


@dataclass(frozen=True, slots=True)
class When:
    condition: Formula
    effect: Formula


NUMERIC_EFFECT_OPS = ("assign", "increase", "decrease", "scale-up", "scale-down")


@dataclass(frozen=True, slots=True)
class NumericEffect:
    op: str
    fluent: Fluent
    value: Expression


Formula = (
    Atom
    | Equality
    | Not
    | And
    | Or
    | Imply
    | Exists
    | Forall
    | Comparison
    | Timed
    | Preference
    | Modal
    | When
    | NumericEffect
)
Node = Formula | Number | Fluent | NumericVariable | Arithmetic

TRUE = And(())

# --------------------------------------------------------------------------- the walk


def children(node: Node) -> tuple[Node, ...]:
    """The direct sub-nodes of ``node``, in source order (the only place that knows the fields)."""
    if isinstance(node, (And, Or)):
        return node.parts
    if isinstance(node, (Not, Timed, Preference, Exists, Forall)):
        return (node.body,)
    if isinstance(node, Imply):
        return (node.condition, node.consequence)
    if isinstance(node, When):
        return (node.condition, node.effect)
    if isinstance(node, Comparison):
        return (node.left, node.right)
    if isinstance(node, NumericEffect):
        return (node.fluent, node.value)
    if isinstance(node, Arithmetic):
        return node.args
    if isinstance(node, Modal):
        return node.parts
    return ()


def walk(node: Node) -> Iterator[Node]:
    """Every node of ``node``, itself first (pre-order)."""
    stack = [node]
    while stack:
        current = stack.pop()
        yield current
        stack.extend(reversed(children(current)))


def with_polarity(formula: Formula, positive: bool = True) -> Iterator[tuple[Formula, bool]]:
    """Every sub-condition of a condition, itself first, with its polarity: ``not`` flips it,
    ``imply`` flips its condition's, and a trajectory constraint that requires a part true at
    some points and false at others gives that part both.  Numeric expressions are not entered.

    Timed parts, preferences and quantifiers are looked through: this is the
    relaxed view (a durative action is its conditions at both ends).
    """
    yield formula, positive
    if isinstance(formula, Not):
        yield from with_polarity(formula.body, not positive)
    elif isinstance(formula, Imply):
        yield from with_polarity(formula.condition, not positive)
        yield from with_polarity(formula.consequence, positive)
    elif isinstance(formula, Modal) and formula.operator in ("at-most-once", "sometime-before", "sometime-after"):
        for part in formula.parts:
            yield from with_polarity(part, positive)
            yield from with_polarity(part, not positive)
    else:
        for child in children(formula):
            if not isinstance(child, (Number, Fluent, NumericVariable, Arithmetic)):
                yield from with_polarity(child, positive)


def literals(formula: Formula, positive: bool = True) -> Iterator[tuple[Atom, bool]]:
    """Every atom of a condition with its polarity (:func:`with_polarity`).  Numeric comparisons
    and object equality have no atoms."""
    for node, polarity in with_polarity(formula, positive):
        if isinstance(node, Atom):
            yield node, polarity


@dataclass(frozen=True, slots=True)
class EffectLiteral:
    """An atom an effect adds or deletes, under its condition and its quantified variables."""

    atom: Atom
    is_add: bool
    condition: Formula = TRUE
    quantified: Parameters = ()
    when: str | None = None  # "start" / "end" for a durative action's timed effect


def effect_literals(effect: Formula) -> Iterator[EffectLiteral]:
    """Every literal an effect can set (numeric effects are :func:`numeric_effects`)."""
    for node, condition, quantified, when in _primitive_effects(effect, TRUE, (), None):
        if isinstance(node, Atom):
            yield EffectLiteral(node, True, condition, quantified, when)
        elif isinstance(node, Not) and isinstance(node.body, Atom):
            yield EffectLiteral(node.body, False, condition, quantified, when)


def numeric_effects(effect: Formula) -> Iterator[tuple[NumericEffect, Formula, Parameters, str | None]]:
    """(effect, condition, quantified variables, time) of every numeric effect."""
    for node, condition, quantified, when in _primitive_effects(effect, TRUE, (), None):
        if isinstance(node, NumericEffect):
            yield node, condition, quantified, when


def _primitive_effects(
    effect: Formula, condition: Formula, quantified: Parameters, when: str | None
) -> Iterator[tuple[Formula, Formula, Parameters, str | None]]:
    """Each effect below ``and``, ``forall``, ``when`` and timing, in order, with the condition,
    quantified variables and time it is under."""
    if isinstance(effect, And):
        for part in effect.parts:
            yield from _primitive_effects(part, condition, quantified, when)
    elif isinstance(effect, Forall):
        yield from _primitive_effects(effect.body, condition, quantified + effect.parameters, when)
    elif isinstance(effect, When):
        combined = effect.condition if condition == TRUE else And((condition, effect.condition))
        yield from _primitive_effects(effect.effect, combined, quantified, when)
    elif isinstance(effect, Timed):
        yield from _primitive_effects(effect.body, condition, quantified, effect.when)
    else:
        yield effect, condition, quantified, when


def quantifiers(formula: Formula, positive: bool = True) -> Iterator[tuple[Exists | Forall, bool]]:
    """Every quantifier of a condition with its polarity (a universal is one under positive
    polarity, or an existential under negative polarity)."""
    for node, polarity in with_polarity(formula, positive):
        if isinstance(node, (Exists, Forall)):
            yield node, polarity


def terms_of(node: Node) -> Iterator[str]:
    """Every term (name or variable) that appears as an argument in ``node``."""
    for current in walk(node):
        if isinstance(current, (Atom, Fluent)):
            yield from current.args
        elif isinstance(current, Equality):
            yield current.left
            yield current.right


def names_in(node: Node) -> Iterator[str]:
    """Object and constant names in ``node`` (variables left out); may repeat."""
    return (term for term in terms_of(node) if not is_variable(term))


def predicates_in(node: Node) -> set[str]:
    return {current.predicate for current in walk(node) if isinstance(current, Atom)}


def substitute(node: Node, binding: Mapping[str, str]) -> Node:
    """``node`` with its free variables replaced by ``binding``'s names (bound variables stay)."""
    return _rebuild(node, lambda term: binding.get(term, term), binding)


def _rebuild(node: Node, rename: Callable[[str], str], binding: Mapping[str, str]) -> Node:
    if isinstance(node, Atom):
        return Atom(node.predicate, tuple(rename(a) for a in node.args))
    if isinstance(node, Fluent):
        return Fluent(node.function, tuple(rename(a) for a in node.args))
    if isinstance(node, Equality):
        return Equality(rename(node.left), rename(node.right))
    if isinstance(node, (Exists, Forall)):
        shadowed = {variable for variable, _ in node.parameters}
        inner = {k: v for k, v in binding.items() if k not in shadowed}
        body: Any = _rebuild(node.body, lambda t: inner.get(t, t), inner)
        return type(node)(node.parameters, body)
    parts = children(node)
    if not parts:
        return node
    rebuilt: tuple[Any, ...] = tuple(_rebuild(part, rename, binding) for part in parts)
    if isinstance(node, And):
        return And(rebuilt)
    if isinstance(node, Or):
        return Or(rebuilt)
    if isinstance(node, Not):
        return Not(rebuilt[0])
    if isinstance(node, Imply):
        return Imply(rebuilt[0], rebuilt[1])
    if isinstance(node, Timed):
        return Timed(node.when, rebuilt[0])
    if isinstance(node, Preference):
        return Preference(node.name, rebuilt[0])
    if isinstance(node, When):
        return When(rebuilt[0], rebuilt[1])
    if isinstance(node, Comparison):
        return Comparison(node.op, rebuilt[0], rebuilt[1])
    if isinstance(node, NumericEffect):
        return NumericEffect(node.op, rebuilt[0], rebuilt[1])
    if isinstance(node, Arithmetic):
        return Arithmetic(node.op, rebuilt)
    if isinstance(node, Modal):
        return Modal(node.operator, node.numbers, rebuilt)
    raise TypeError(f"not a formula node: {node!r}")


def conjuncts(formula: Formula) -> Iterator[Formula]:
    """The parts of a top-level conjunction (timed parts looked through), else the formula itself."""
    if isinstance(formula, And):
        for part in formula.parts:
            yield from conjuncts(part)
    elif isinstance(formula, Timed):
        yield from conjuncts(formula.body)
    else:
        yield formula


def ground(atom: Atom, binding: Mapping[str, str]) -> GroundAtom:
    return (atom.predicate, *(binding.get(a, a) for a in atom.args))


def conjuncts_timed(formula: Formula) -> Iterator[Timed]:
    """The timed parts of a durative action's condition or effect (an untimed part counts as ``at start``)."""
    if isinstance(formula, And):
        for part in formula.parts:
            yield from conjuncts_timed(part)
    elif isinstance(formula, Timed):
        yield formula
    elif isinstance(formula, Preference):
        return  # soft: never checked
    else:
        yield Timed("start", formula)


def scoped_literals(
    formula: Formula, positive: bool = True, scope: Parameters = ()
) -> Iterator[tuple[Atom, bool, Parameters]]:
    """Like :func:`literals`, with the quantified variables (and their types) around each atom."""
    if isinstance(formula, Atom):
        yield formula, positive, scope
    elif isinstance(formula, Not):
        yield from scoped_literals(formula.body, not positive, scope)
    elif isinstance(formula, Imply):
        yield from scoped_literals(formula.condition, not positive, scope)
        yield from scoped_literals(formula.consequence, positive, scope)
    elif isinstance(formula, (Exists, Forall)):
        yield from scoped_literals(formula.body, positive, scope + formula.parameters)
    else:
        for part in children(formula):
            if not isinstance(part, (Number, Fluent, NumericVariable, Arithmetic)):
                yield from scoped_literals(part, positive, scope)
