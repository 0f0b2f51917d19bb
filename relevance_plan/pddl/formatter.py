"""Turn PDDL values back into text: any formula node, whole domains and problems (``Domain``, ``Problem``).

The pruning path never re-formats a user's file (``writer.py`` cuts it);
this formatter writes what we create ourselves (generated suites, the live
session's snapshots, compiled domains) and backs the parse -> format -> parse
round-trip tests.  Names are written as the user wrote them (``Spelling``):
a domain and a problem with their own spelling, a formula or an atom with
the one it is given.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping, Sequence

from relevance_plan.pddl import formulas as f
from relevance_plan.pddl.model import (
    UNSPELLED,
    Action,
    DerivedPredicate,
    Domain,
    Metric,
    Problem,
    Spelling,
    TimedLiteral,
    make_problem,
)

NAMES_PER_LINE = 12


def format_number(value: float) -> str:
    return str(int(value)) if float(value).is_integer() and abs(value) < 1e15 else repr(float(value))


def format_atom(atom: Sequence[str], spelling: Spelling = UNSPELLED) -> str:
    """``(predicate arg ...)`` of a ground atom tuple (or of a numeric term, ``(function arg ...)``)."""
    return "(" + " ".join([spelling.predicate(atom[0]), *map(spelling.object, atom[1:])]) + ")"


def format_step(action: str, args: Sequence[str], spelling: Spelling = UNSPELLED) -> str:
    """``(action arg ...)`` of a ground action."""
    return "(" + " ".join([spelling.action(action), *map(spelling.object, args)]) + ")"


def format_parameters(parameters: f.Parameters, spelling: Spelling = UNSPELLED) -> str:
    """``?x ?y - t ?z - u``: consecutive names of one type share it (variables, or constants spelled)."""

    def term(name: str) -> str:
        return name if f.is_variable(name) else spelling.object(name)

    return _typed_list(parameters, term, spelling.type)


def _typed_list(typed: Sequence[tuple[str, str]], name: Callable[[str], str], type_name: Callable[[str], str]) -> str:
    pieces: list[str] = []
    index = 0
    while index < len(typed):
        shared = typed[index][1]
        names = []
        while index < len(typed) and typed[index][1] == shared:
            names.append(name(typed[index][0]))
            index += 1
        pieces.append(" ".join(names) + f" - {type_name(shared)}")
    return " ".join(pieces)


def format_formula(node: f.Node, spelling: Spelling = UNSPELLED) -> str:
    """PDDL text of any formula node on one line."""

    def term(name: str) -> str:
        return name if f.is_variable(name) else spelling.object(name)

    def text(n: f.Node) -> str:
        if isinstance(n, f.Atom):
            return "(" + " ".join([spelling.predicate(n.predicate), *map(term, n.args)]) + ")"
        if isinstance(n, f.Fluent):
            return "(" + " ".join([spelling.predicate(n.function), *map(term, n.args)]) + ")"
        if isinstance(n, f.Number):
            return format_number(n.value)
        if isinstance(n, f.NumericVariable):
            return n.name
        if isinstance(n, f.Equality):
            return f"(= {term(n.left)} {term(n.right)})"
        if isinstance(n, (f.Exists, f.Forall)):
            keyword = "exists" if isinstance(n, f.Exists) else "forall"
            return f"({keyword} ({format_parameters(n.parameters, spelling)}) {text(n.body)})"
        if isinstance(n, f.Timed):
            return f"({f.TIMES[n.when]} {text(n.body)})"
        if isinstance(n, f.Preference):
            label = f"{n.name} " if n.name is not None else ""
            return f"(preference {label}{text(n.body)})"
        if isinstance(n, f.Modal):
            if n.operator == "at-end":
                return f"(at end {text(n.parts[0])})"
            return "(" + " ".join([n.operator, *map(format_number, n.numbers), *map(text, n.parts)]) + ")"
        head = _KEYWORDS.get(type(n)) or str(getattr(n, "op", "?"))  # Comparison, Arithmetic, NumericEffect
        return "(" + " ".join([head, *map(text, f.children(n))]) + ")"

    return text(node)


_KEYWORDS: Mapping[type, str] = {f.And: "and", f.Or: "or", f.Not: "not", f.Imply: "imply", f.When: "when"}

# --------------------------------------------------------------------------- domains


def format_domain(domain: Domain) -> str:
    """A domain value as PDDL, every name in its spelling."""
    spelling = domain.spelling
    lines = [f"(define (domain {domain.name})"]
    if domain.requirements:
        lines.append(f"  (:requirements {' '.join(sorted(domain.requirements))})")
    declared = {name: parent for name, parent in domain.types.items() if name != "object"}
    if declared:
        lines.append(f"  (:types {_typed_types(declared, spelling)})")
    if domain.constants:
        lines.append(f"  (:constants {format_parameters(tuple(domain.constants.items()), spelling)})")
    lines.append("  (:predicates")
    lines.extend(f"    ({_signature(name, params, spelling)})" for name, params in domain.predicates.items())
    lines.append("  )")
    if domain.functions:
        lines.append("  (:functions")
        lines.extend(
            f"    ({_signature(name, params, spelling)}) - number" for name, params in domain.functions.items()
        )
        lines.append("  )")
    if domain.constraints is not None:
        lines.append(f"  (:constraints {format_formula(domain.constraints, spelling)})")
    lines.extend(_format_derived(rule, spelling) for rule in domain.derived)
    lines.extend(_format_action(action, spelling) for action in domain.actions)
    lines.append(")")
    return "\n".join(lines) + "\n"


def _typed_types(types: Mapping[str, str], spelling: Spelling) -> str:
    return _typed_list(tuple(types.items()), spelling.type, spelling.type)


def _signature(name: str, params: f.Parameters, spelling: Spelling) -> str:
    shown = spelling.predicate(name)
    return f"{shown} {format_parameters(params, spelling)}" if params else shown


def _format_derived(rule: DerivedPredicate, spelling: Spelling) -> str:
    head = _signature(rule.head.predicate, rule.parameters, spelling)
    return f"  (:derived ({head})\n    {format_formula(rule.body, spelling)})"


def _format_action(action: Action, spelling: Spelling) -> str:
    keyword = ":durative-action" if action.durative else ":action"
    lines = [
        f"  ({keyword} {spelling.action(action.name)}",
        f"    :parameters ({format_parameters(action.parameters, spelling)})",
    ]
    if action.duration is not None:
        lines.append(f"    :duration {format_formula(action.duration, spelling)}")
    condition = format_formula(action.precondition, spelling)
    lines.append(f"    {':condition' if action.durative else ':precondition'} {condition}")
    lines.append(f"    :effect {format_formula(action.effect, spelling)})")
    return "\n".join(lines)


# --------------------------------------------------------------------------- problems


def format_problem(problem: Problem, comment: str | None = None) -> str:
    """A problem value as PDDL, objects grouped by type in first-appearance order, in the user's spelling."""
    spelling = problem.spelling
    lines: list[str] = []
    if comment:
        lines.extend("; " + line if line else ";" for line in comment.splitlines())
    lines.append(f"(define (problem {problem.name})")
    lines.append(f"  (:domain {problem.domain_name})")
    if problem.requirements:
        lines.append(f"  (:requirements {' '.join(sorted(problem.requirements))})")
    by_type: dict[str, list[str]] = {}
    for name, type_name in problem.objects.items():
        by_type.setdefault(type_name, []).append(spelling.object(name))
    lines.append("  (:objects")
    for type_name, names in by_type.items():
        suffix = "" if type_name == "object" else f" - {spelling.type(type_name)}"
        for start in range(0, len(names), NAMES_PER_LINE):
            lines.append(f"    {' '.join(names[start : start + NAMES_PER_LINE])}{suffix}")
    lines.append("  )")
    lines.append("  (:init")
    lines.extend("    " + format_atom(atom, spelling) for atom in _init_order(problem))
    lines.extend(
        f"    (= {format_atom(term, spelling)} {format_number(value)})" for term, value in problem.numeric_init.items()
    )
    lines.extend("    " + _format_timed_literal(literal, spelling) for literal in problem.timed_literals)
    lines.append("  )")
    lines.append(_format_goal(problem.goal, spelling))
    if problem.constraints is not None:
        lines.append(f"  (:constraints {format_formula(problem.constraints, spelling)})")
    if problem.metric is not None:
        lines.append(f"  (:metric {_format_metric(problem.metric, spelling)})")
    lines.append(")")
    return "\n".join(lines) + "\n"


def format_problem_parts(
    name: str,
    domain: str,
    objects: Mapping[str, Sequence[str]],
    init: Iterable[Sequence[str]],
    goal: Iterable[Sequence[str]],
    comment: str | None = None,
) -> str:
    """A problem from plain parts: ``objects`` maps a type to its names, ``goal`` is a conjunction of atoms."""
    typed = {object_name: type_name for type_name, names in objects.items() for object_name in names}
    goal_formula = f.And(tuple(f.Atom(atom[0], tuple(atom[1:])) for atom in goal))
    problem = make_problem(name, domain, typed, (tuple(atom) for atom in init), goal_formula)
    return format_problem(problem, comment)


def _init_order(problem: Problem) -> Iterable[f.GroundAtom]:
    # Facts in the order the problem's own text had them when it has one, else sorted.
    if problem.init_order:
        return sorted(problem.init, key=lambda atom: (problem.init_order.get(atom, -1), atom))
    return sorted(problem.init)


def _format_goal(goal: f.Formula, spelling: Spelling) -> str:
    if isinstance(goal, f.And) and goal.parts and all(isinstance(p, f.Atom) for p in goal.parts):
        return "\n".join(["  (:goal (and", *("    " + format_formula(p, spelling) for p in goal.parts), "  ))"])
    return f"  (:goal {format_formula(goal, spelling)})"


def _format_timed_literal(literal: TimedLiteral, spelling: Spelling) -> str:
    if literal.fluent is not None:
        inner = f"(= {format_atom(literal.fluent, spelling)} {format_number(literal.value or 0.0)})"
    else:
        assert literal.atom is not None
        inner = format_atom(literal.atom, spelling)
        if literal.negated:
            inner = f"(not {inner})"
    return f"(at {format_number(literal.time)} {inner})"


def _format_metric(metric: Metric, spelling: Spelling) -> str:
    return f"{metric.direction} {format_formula(metric.expression, spelling)}"
