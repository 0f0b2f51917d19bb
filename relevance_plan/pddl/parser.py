"""Read PDDL text into ``Domain`` and ``Problem`` values (``model.py``): PDDL 3.1 without PDDL+.

Typed STRIPS and ADL, action costs and numeric fluents, durative actions
(with duration inequalities), derived predicates, timed initial literals,
``either`` types, and PDDL3 preferences and trajectory constraints, which
are read and passed through.  PDDL+ (processes, events, continuous effects)
and object fluents are refused in one line naming the construct.

Errors name the file and the line.  A mistake inside the domain is a PDDL
error (exit 32); a problem that uses a name its domain lacks does not belong
to the domain (exit 34).  It is fast on big problems (no grounding, one pass
over the text) and keeps the spans the cutting writer needs.
"""

from __future__ import annotations

import itertools
import operator
import re
from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from types import MappingProxyType
from typing import Any, NoReturn

from relevance_plan.errors import (
    DomainMismatchError,
    OutOfTimeError,
    PDDLParseError,
    RelevancePlanError,
    UnsupportedFeatureError,
)
from relevance_plan.pddl import formulas as f
from relevance_plan.pddl.model import (
    NUMBER,
    Action,
    DerivedPredicate,
    Domain,
    InitSpan,
    Metric,
    ObjectGroup,
    Problem,
    Spelling,
    TimedLiteral,
    frozen,
)
from relevance_plan.pddl.sexpr import Item, Node, Symbol, check_deadline, collection_paused, parse_sexpr

# Requirements are accepted as written but these, of PDDL+ and of other formalisms, refused naming the construct.
UNSUPPORTED_REQUIREMENTS = {
    ":continuous-effects": "continuous effects (PDDL+)",
    ":processes": "processes (PDDL+)",
    ":events": "events (PDDL+)",
    ":time": "continuous time (PDDL+)",
    ":object-fluents": "object fluents",
    ":probabilistic-effects": "probabilistic effects (PPDDL)",
    ":non-deterministic": "non-deterministic effects (FOND)",
    ":rewards": "rewards (PPDDL)",
}
# Effects of other planning formalisms, refused naming the construct.
UNSUPPORTED_EFFECTS = {
    "oneof": "non-deterministic effects ('oneof', FOND)",
    "probabilistic": "probabilistic effects ('probabilistic', PPDDL)",
}
# Functions every planner knows without a declaration.
BUILTIN_FUNCTIONS = {"total-cost": (), "total-time": ()}

_NUMBER_RE = re.compile(r"[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?")
_COMPARISONS = ("<", "<=", ">", ">=", "=")
_ARITHMETIC = ("+", "-", "*", "/")


def _number(text: str) -> float | None:
    return float(text) if _NUMBER_RE.fullmatch(text) else None


@dataclass(frozen=True)
class _Scope:
    """What names mean where a formula is read."""

    types: Mapping[str, str]
    predicates: Mapping[str, f.Parameters]
    functions: Mapping[str, f.Parameters]
    objects: Mapping[str, str] | None  # None: any name (the problem is not known yet)
    variables: Mapping[str, str]
    in_problem: bool = False  # unknown names then mean the problem does not fit its domain
    durative: bool = False  # ``at start`` / ``over all`` / ``?duration`` allowed
    trajectory: bool = False  # PDDL3 modal operators allowed (:constraints)
    preferences: bool = False

    def with_variables(self, parameters: f.Parameters) -> _Scope:
        variables = dict(self.variables)
        variables.update(parameters)
        return replace(self, variables=variables)


class _Reader:
    """Reads one file's lists: symbols, terms, parameters and the formulas (conditions, effects,
    numeric expressions); every failure names the file and the line.  Headers and typed lists
    are read by the functions below the class."""

    def __init__(self, path: str | None):
        self.path = path

    def fail(self, message: str, where: Item | None, error: type[RelevancePlanError] = PDDLParseError) -> NoReturn:
        raise error(message, path=self.path, line=where.line if where is not None else None)

    def mismatch(self, scope: _Scope) -> type[RelevancePlanError]:
        return DomainMismatchError if scope.in_problem else PDDLParseError

    def symbol(self, item: Item, what: str) -> str:
        if not isinstance(item, Symbol):
            self.fail(f"expected {what}, found a list", item)
        return item.text.lower()

    def opened(self, node: Item, what: str) -> tuple[Node, str | None, list[Item]] | None:
        """A list, its head keyword (None: not a keyword) and its arguments; None for ``()``, which
        is true; a symbol where ``what`` is expected fails."""
        if isinstance(node, Symbol):
            self.fail(f"expected {what}, found '{node.text}'", node)
        if not node.items:
            return None
        return node, _keyword_of(node), node.items[1:]

    def parameters(self, node: Item, scope: _Scope | None, *, unique: bool = True) -> f.Parameters:
        if not isinstance(node, Node):
            self.fail("expected a parameter list", node)
        pairs, _ = _typed_list(self, node.items, "parameter list")
        params: list[tuple[str, str]] = []
        for symbol, type_name in pairs:
            if not symbol.text.startswith("?"):
                self.fail(f"parameter '{symbol.text}' must start with '?'", symbol)
            name = symbol.text.lower()
            if scope is not None:
                for member in type_name.removeprefix("(either ").rstrip(")").split():
                    if member not in scope.types:
                        self.fail(f"unknown type '{member}'", symbol, self.mismatch(scope))
            if unique and any(name == other for other, _ in params):
                self.fail(f"parameter '{symbol.text}' is declared twice", symbol)
            params.append((name, type_name))
        return tuple(params)

    # ---------------------------------------------------------------- terms and expressions

    def term(self, item: Item, scope: _Scope, context: str) -> str:
        if isinstance(item, Node):
            self.fail(
                f"a function term as an argument of '{context}' (object fluents) is not supported",
                item,
                UnsupportedFeatureError,
            )
        text = item.text.lower()
        if text.startswith("?"):
            if text not in scope.variables:
                self.fail(f"unknown variable '{item.text}'", item)
        elif scope.objects is not None and text not in scope.objects:
            self.fail(f"unknown object or constant '{item.text}' in '({context} ...)'", item, self.mismatch(scope))
        return text

    def expression(self, item: Item, scope: _Scope) -> f.Expression:
        if isinstance(item, Symbol):
            value = _number(item.text)
            if value is not None:
                return f.Number(value)
            text = item.text.lower()
            if text == "#t":
                self.fail("continuous effects ('#t', PDDL+) are not supported", item, UnsupportedFeatureError)
            if text == "?duration" and scope.durative:
                return f.NumericVariable(text)
            if text in scope.functions or text in BUILTIN_FUNCTIONS:
                return f.Fluent(text)  # a 0-ary function written without parentheses
            self.fail(f"expected a number or a numeric expression, found '{item.text}'", item)
        head = _keyword_of(item)
        if head is None:
            self.fail("expected a numeric expression", item)
        args = item.items[1:]
        if head in _ARITHMETIC:
            if not args or (head != "-" and len(args) < 2):
                self.fail(f"'{head}' needs {'one or more' if head == '-' else 'two or more'} arguments", item)
            return f.Arithmetic(head, tuple(self.expression(arg, scope) for arg in args))
        return self.fluent(item, scope)

    def fluent(self, node: Node, scope: _Scope) -> f.Fluent:
        name = self.symbol(node.items[0], "a function name")
        if name == "is-violated":
            return f.Fluent(name, tuple(self.symbol(arg, "a preference name") for arg in node.items[1:]))
        declared = scope.functions.get(name, BUILTIN_FUNCTIONS.get(name))
        if declared is None:
            self.fail(f"undeclared function '{name}'", node, self.mismatch(scope))
        args = tuple(self.term(arg, scope, name) for arg in node.items[1:])
        if len(args) != len(declared):
            self.fail(f"function '{name}' takes {len(declared)} arguments, got {len(args)}", node, self.mismatch(scope))
        return f.Fluent(name, args)

    def effect_target(self, item: Item, scope: _Scope) -> f.Fluent | None:
        """The function term a numeric effect changes; IPC 2002's zenotravel writes a 0-ary one bare."""
        if isinstance(item, Node):
            return self.fluent(item, scope)
        name = item.text.lower()
        if not scope.functions.get(name, ()) and (name in scope.functions or name in BUILTIN_FUNCTIONS):
            return f.Fluent(name)
        return None

    def numeric_operand(self, item: Item) -> bool:
        if isinstance(item, Node):
            return True
        return _number(item.text) is not None or item.text.lower() == "?duration"

    # ---------------------------------------------------------------- conditions

    def condition(self, node: Item, scope: _Scope) -> f.Formula:
        opened = self.opened(node, "a condition")
        if opened is None:
            return f.TRUE
        node, head, args = opened
        if head is None:
            self.fail("expected a condition", node)
        if head in ("and", "or"):
            parts = tuple(self.condition(part, scope) for part in args)
            return f.And(parts) if head == "and" else f.Or(parts)
        if head == "not":
            if len(args) != 1:
                self.fail("'not' takes one condition", node)
            return f.Not(self.condition(args[0], scope))
        if head == "imply":
            if len(args) != 2:
                self.fail("'imply' takes two conditions", node)
            return f.Imply(self.condition(args[0], scope), self.condition(args[1], scope))
        if head in ("exists", "forall"):
            if len(args) != 2:
                self.fail(f"'{head}' takes a parameter list and a condition", node)
            params = self.parameters(args[0], scope)
            body = self.condition(args[1], scope.with_variables(params))
            return f.Exists(params, body) if head == "exists" else f.Forall(params, body)
        if head in _COMPARISONS and len(args) == 2 and (head != "=" or any(map(self.numeric_operand, args))):
            return f.Comparison(head, self.expression(args[0], scope), self.expression(args[1], scope))
        special = self.special_condition(node, head, args, scope)
        if special is not None:
            return special
        return self.atom(node, scope)

    def special_condition(self, node: Node, head: str, args: list[Item], scope: _Scope) -> f.Formula | None:
        """Timed conditions, preferences and PDDL3 modal operators; None for an ordinary atom."""
        timed = self.timed_part(node, head, args, scope)
        if timed is not None:
            return f.Timed(timed[0], self.condition(timed[1], scope))
        if head == "preference" and args:
            if not (scope.preferences or scope.trajectory):
                self.fail("'preference' outside a goal, precondition or constraint", node)
            if len(args) == 2:
                return f.Preference(self.symbol(args[0], "a preference name"), self.condition(args[1], scope))
            if len(args) == 1:
                return f.Preference(None, self.condition(args[0], scope))
            self.fail("'preference' takes a name and a condition", node)
        if scope.trajectory and head in f.MODAL_OPERATORS and head not in scope.predicates:
            return self.modal(node, head, args, scope)
        if scope.trajectory and head == "at" and len(args) == 2 and _keyword_of_symbol(args[0]) == "end":
            return f.Modal("at-end", (), (self.condition(args[1], scope),))
        return None

    def timed_part(self, node: Node, head: str, args: list[Item], scope: _Scope) -> tuple[str, Node] | None:
        if not scope.durative or len(args) != 2 or not isinstance(args[1], Node):
            return None
        second = _keyword_of_symbol(args[0])
        if head == "at" and second in ("start", "end"):
            return second, args[1]
        if head == "over" and second == "all":
            return "all", args[1]
        return None

    def modal(self, node: Node, head: str, args: list[Item], scope: _Scope) -> f.Modal:
        count = f.MODAL_OPERATORS[head]
        numbers: list[float] = []
        for item in args[:count]:
            value = _number(item.text) if isinstance(item, Symbol) else None
            if value is None:
                self.fail(f"'{head}' expects {count} number(s) before its condition(s)", node)
            numbers.append(value)
        wanted = 2 if head in ("sometime-after", "sometime-before", "always-within") else 1
        parts = args[count:]
        if len(parts) != wanted:
            self.fail(f"'{head}' takes {wanted} condition(s)", node)
        return f.Modal(head, tuple(numbers), tuple(self.condition(part, scope) for part in parts))

    def atom(self, node: Node, scope: _Scope) -> f.Atom | f.Equality:
        head = _keyword_of(node)
        if head is None:
            self.fail("expected an atom", node)
        args = tuple(self.term(item, scope, head) for item in node.items[1:])
        if head == "=":
            if len(args) != 2:
                self.fail("'=' takes two arguments", node)
            return f.Equality(args[0], args[1])
        declared = scope.predicates.get(head)
        if declared is None:
            if head in scope.functions:
                self.fail(f"function '{head}' used as a predicate", node, self.mismatch(scope))
            self.fail(f"unknown predicate '{head}'", node, self.mismatch(scope))
        if len(declared) != len(args):
            self.fail(
                f"predicate '{head}' takes {len(declared)} arguments, got {len(args)}", node, self.mismatch(scope)
            )
        return f.Atom(head, args)

    # ---------------------------------------------------------------- effects

    def effect(self, node: Item, scope: _Scope) -> f.Formula:
        opened = self.opened(node, "an effect")
        if opened is None:
            return f.TRUE
        node, head, args = opened
        if head == "and":
            return f.And(tuple(self.effect(part, scope) for part in args))
        if head == "not":
            if len(args) != 1 or not isinstance(args[0], Node):
                self.fail("'not' in an effect takes one atom", node)
            inner = self.atom(args[0], scope)
            if not isinstance(inner, f.Atom):
                self.fail("'not' in an effect takes one atom", node)
            return f.Not(inner)
        if head == "forall":
            if len(args) != 2:
                self.fail("'forall' in an effect takes a parameter list and an effect", node)
            params = self.parameters(args[0], scope)
            return f.Forall(params, self.effect(args[1], scope.with_variables(params)))
        if head == "when":
            if len(args) != 2:
                self.fail("'when' takes a condition and an effect", node)
            return f.When(self.condition(args[0], scope), self.effect(args[1], scope))
        if head in f.NUMERIC_EFFECT_OPS:
            return self.numeric_effect(node, head, args, scope)
        if head in UNSUPPORTED_EFFECTS and head not in scope.predicates:
            self.fail(f"{UNSUPPORTED_EFFECTS[head]} are not supported", node, UnsupportedFeatureError)
        timed = self.timed_part(node, head or "", args, scope)
        if timed is not None:
            if timed[0] == "all":
                self.fail("'over all' is not allowed in an effect", node)
            return f.Timed(timed[0], self.effect(timed[1], scope))
        atom = self.atom(node, scope)
        if not isinstance(atom, f.Atom):
            self.fail("'=' is not an effect (use 'assign' for numeric values)", node)
        return atom

    def numeric_effect(self, node: Node, head: str, args: list[Item], scope: _Scope) -> f.NumericEffect:
        if len(args) != 2:
            self.fail(f"'{head}' takes a function term and a value", node)
        target = self.effect_target(args[0], scope)
        if target is None:
            self.fail(f"'{head}' takes a function term and a value", node)
        return f.NumericEffect(head, target, self.expression(args[1], scope))


# --------------------------------------------------------------------------- headers and typed lists


def _keyword_of(node: object) -> str | None:
    """The head keyword of a list (lower-cased); None for a symbol, ``()`` or a list headed by a list."""
    if isinstance(node, Node) and node.items and isinstance(node.items[0], Symbol):
        return node.items[0].text.lower()
    return None


def _keyword_of_symbol(item: Item) -> str | None:
    return item.text.lower() if isinstance(item, Symbol) else None


def _header(reader: _Reader, root: Node, kind: str) -> tuple[str, list[Item]]:
    items = root.items
    if not items or _keyword_of(root) != "define":
        reader.fail("expected '(define ...)'", root)
    if len(items) < 2 or not isinstance(items[1], Node) or len(items[1].items) != 2:
        reader.fail(f"expected '({kind} NAME)' after define", items[1] if len(items) > 1 else root)
    head = items[1]
    head_kind = reader.symbol(head.items[0], kind)
    if head_kind != kind:
        other = "problem" if kind == "domain" else "domain"
        if head_kind == other:
            reader.fail(f"this is a PDDL {other} file, not a {kind} file", head)
        reader.fail(f"expected '({kind} NAME)', found '({head_kind} ...)'", head)
    return reader.symbol(head.items[1], f"{kind} name"), items[2:]


def _requirements(reader: _Reader, body: list[Item]) -> frozenset[str]:
    found = set()
    for item in body:
        requirement = reader.symbol(item, "a requirement")
        if requirement in UNSUPPORTED_REQUIREMENTS:
            reader.fail(
                f"requirement '{requirement}': {UNSUPPORTED_REQUIREMENTS[requirement]} are not supported",
                item,
                UnsupportedFeatureError,
            )
        if not requirement.startswith(":"):
            reader.fail(f"requirement '{requirement}' must start with ':'", item)
        found.add(requirement)
    return frozenset(found)


def _type_name(reader: _Reader, item: Item) -> str:
    if isinstance(item, Node):
        if _keyword_of(item) != "either" or len(item.items) < 2:
            reader.fail("expected a type name or '(either TYPE ...)'", item)
        members = [reader.symbol(member, "a type name") for member in item.items[1:]]
        return "(either " + " ".join(members) + ")" if len(members) > 1 else members[0]
    return item.text.lower()


def _typed_list(reader: _Reader, items: list[Item], what: str) -> tuple[list[tuple[Symbol, str]], list[ObjectGroup]]:
    """'a b - t c - u d' -> [(symbol, type)] and the groups ((symbols...), type item | None)."""
    result: list[tuple[Symbol, str]] = []
    groups: list[ObjectGroup] = []
    pending: list[Symbol] = []
    index = 0
    while index < len(items):
        item = items[index]
        if isinstance(item, Node):
            reader.fail(f"unexpected list in {what}", item)
        if len(item.text) > 1 and item.text[0] == "-" and item.text[1].isalpha():
            # '?x -type', a dash glued to its type as some published domains write it
            if not pending:
                reader.fail(f"type given to nothing in {what}", item)
            type_name = item.text[1:].lower()
            result.extend((symbol, type_name) for symbol in pending)
            groups.append((tuple(pending), item))
            pending = []
            index += 1
            continue
        if item.text == "-":
            if index + 1 >= len(items):
                reader.fail(f"missing type after '-' in {what}", item)
            if not pending:
                reader.fail(f"type given to nothing in {what}", item)
            type_item = items[index + 1]
            type_name = _type_name(reader, type_item)
            result.extend((symbol, type_name) for symbol in pending)
            groups.append((tuple(pending), type_item))
            pending = []
            index += 2
            continue
        pending.append(item)
        index += 1
    if pending:
        result.extend((symbol, "object") for symbol in pending)
        groups.append((tuple(pending), None))
    return result, groups


# --------------------------------------------------------------------------- domains


_SPELLED_IN_DOMAINS = ("actions", "predicates", "types", "constants")  # ``Spelling``'s tables a domain fills


@dataclass
class _DomainParts:
    requirements: frozenset[str] = frozenset()
    types: dict[str, str] = field(default_factory=lambda: {"object": ""})
    constants: dict[str, str] = field(default_factory=dict)
    predicates: dict[str, f.Parameters] = field(default_factory=dict)
    functions: dict[str, f.Parameters] = field(default_factory=dict)
    function_types: dict[str, str] = field(default_factory=dict)
    action_nodes: list[Node] = field(default_factory=list)
    derived_nodes: list[Node] = field(default_factory=list)
    constraint_node: Item | None = None
    # how each name was first written, by kind (``Spelling``'s tables)
    written: dict[str, dict[str, str]] = field(default_factory=lambda: {kind: {} for kind in _SPELLED_IN_DOMAINS})

    def spell(self, kind: str, name: str) -> None:
        self.written[kind].setdefault(name.lower(), name)

    def spelling(self) -> Spelling:
        # a name first written in lower case needs no entry: it is shown as the model holds it
        return Spelling(
            **{kind: frozen({k: v for k, v in names.items() if k != v}) for kind, names in self.written.items()}
        )


def read_domain(text: str, path: str | None = None, deadline: float | None = None) -> Domain:
    """Build a Domain from PDDL text; errors name ``path`` and the line.

    ``deadline`` (``time.monotonic()`` seconds): past it, ``OutOfTimeError``.
    """
    with collection_paused():
        return _read_domain(text, path, deadline)


def _read_domain(text: str, path: str | None, deadline: float | None) -> Domain:
    reader = _Reader(path)
    name, sections = _header(reader, parse_sexpr(text, path, deadline), "domain")
    parts = _DomainParts()
    for section in sections:
        _read_domain_section(reader, section, parts)
    scope = _Scope(
        MappingProxyType(parts.types),
        MappingProxyType(parts.predicates),
        MappingProxyType(parts.functions),
        MappingProxyType(parts.constants),
        {},
        preferences=True,
    )
    actions = []
    seen: set[str] = set()
    for node in parts.action_nodes:
        action = _read_action(reader, node, scope)
        if action.name in seen:
            reader.fail(f"action '{action.name}' is defined twice", node)
        seen.add(action.name)
        parts.spell("actions", _text(node.items[1]))
        actions.append(action)
    derived = tuple(_read_derived(reader, node, scope) for node in parts.derived_nodes)
    constraints = None
    if parts.constraint_node is not None:
        constraints = reader.condition(parts.constraint_node, replace(scope, trajectory=True))
    return Domain(
        name=name,
        requirements=parts.requirements,
        types=frozen(parts.types),
        constants=frozen(parts.constants),
        predicates=frozen(parts.predicates),
        actions=tuple(actions),
        path=path,
        functions=frozen(parts.functions),
        function_types=frozen(parts.function_types),
        derived=derived,
        constraints=constraints,
        spelling=parts.spelling(),
    )


def _read_domain_section(reader: _Reader, section: Item, parts: _DomainParts) -> None:
    key = _keyword_of(section)
    if key is None or not isinstance(section, Node):
        reader.fail("expected a '(:section ...)'", section)
    body = section.items[1:]
    if key == ":requirements":
        parts.requirements = parts.requirements | _requirements(reader, body)
    elif key == ":types":
        _read_types(reader, body, parts)
    elif key == ":constants":
        pairs, _ = _typed_list(reader, body, ":constants")
        for symbol, type_name in pairs:
            _check_type(reader, type_name, parts.types, symbol, f"constant '{symbol.text}'", PDDLParseError)
            parts.constants[symbol.text.lower()] = type_name
            parts.spell("constants", symbol.text)
    elif key == ":predicates":
        for item in body:
            if not isinstance(item, Node) or not item.items:
                reader.fail("expected '(predicate ?x - type ...)'", item)
            predicate, params = _read_signature(reader, item, "predicate", parts.predicates, parts.types)
            parts.predicates[predicate] = params
            parts.spell("predicates", _text(item.items[0]))
    elif key == ":functions":
        _read_functions(reader, body, parts)
    elif key in (":action", ":durative-action"):
        parts.action_nodes.append(section)
    elif key == ":derived":
        parts.derived_nodes.append(section)
    elif key == ":constraints":
        if len(body) != 1:
            reader.fail("expected '(:constraints CONDITION)'", section)
        parts.constraint_node = body[0]
    elif key in (":process", ":event"):
        reader.fail(f"'{key}' (PDDL+) is not supported", section, UnsupportedFeatureError)
    else:
        reader.fail(f"unknown domain section '{key}'", section)


def _read_signature(
    reader: _Reader, item: Node, what: str, declared: Mapping[str, f.Parameters], types: Mapping[str, str]
) -> tuple[str, f.Parameters]:
    """``(name ?x - type ...)`` of a predicate or a function: its name and typed parameters, checked."""
    name = reader.symbol(item.items[0], f"a {what} name")
    if name in declared:
        reader.fail(f"{what} '{name}' is declared twice", item)
    params = reader.parameters(Node(item.items[1:], item.start, item.end, item.line), None, unique=False)
    for (_, type_name), element in zip(params, item.items[1:]):
        _check_type(reader, type_name, types, element, f"{what} '{name}'", PDDLParseError)
    return name, params


def _check_type(
    reader: _Reader, type_name: str, types: Mapping[str, str], where: Item, what: str, error: type[RelevancePlanError]
) -> None:
    for member in type_name.removeprefix("(either ").rstrip(")").split():
        if member not in types:
            reader.fail(f"{what} uses unknown type '{member}'", where, error)


def _read_types(reader: _Reader, body: list[Item], parts: _DomainParts) -> None:
    types = parts.types
    pairs, groups = _typed_list(reader, body, ":types")
    for symbol, parent in pairs:
        name = symbol.text.lower()
        if parent.startswith("(either"):
            parent = "object"  # a type cannot have two parents here; objects of it still match 'object'
        types[name] = parent if name != "object" else ""
        parts.spell("types", symbol.text)
    for _, parent_item in groups:
        if isinstance(parent_item, Symbol):  # a parent only ever named as one: spelled where it is
            parts.spell("types", parent_item.text.removeprefix("-"))  # '-type' glued, as some domains write it
    for parent in list(types.values()):
        if parent and parent not in types:
            types[parent] = "object"  # a parent used but never declared is a subtype of object


def _read_functions(reader: _Reader, body: list[Item], parts: _DomainParts) -> None:
    index = 0
    while index < len(body):
        item = body[index]
        if isinstance(item, Symbol) and item.text == "-":
            if index + 1 >= len(body):
                reader.fail("missing type after '-' in :functions", item)
            kind = _type_name(reader, body[index + 1])
            if kind != NUMBER:
                reader.fail(
                    f"object fluents (functions of type '{kind}') are not supported", item, UnsupportedFeatureError
                )
            index += 2
            continue
        if not isinstance(item, Node) or not item.items:
            reader.fail("expected '(function ?x - type ...)' in :functions", item)
        name, params = _read_signature(reader, item, "function", parts.functions, parts.types)
        parts.functions[name] = params
        parts.function_types[name] = NUMBER
        parts.spell("predicates", _text(item.items[0]))
        index += 1


_ACTION_FIELDS = (":parameters", ":precondition", ":effect")
_DURATIVE_FIELDS = (":parameters", ":duration", ":condition", ":effect")


def _read_action(reader: _Reader, node: Node, scope: _Scope) -> Action:
    items = node.items
    durative = _keyword_of(node) == ":durative-action"
    if len(items) < 2:
        reader.fail(f"'{_keyword_of(node)}' needs a name", node)
    name = reader.symbol(items[1], "an action name")
    allowed = _DURATIVE_FIELDS if durative else _ACTION_FIELDS
    fields: dict[str, Item] = {}
    index = 2
    while index < len(items):
        key_item = items[index]
        key = reader.symbol(key_item, "', '".join(allowed))
        if key not in allowed:
            reader.fail(f"unknown field '{key}' in action '{name}' (expected {', '.join(allowed)})", key_item)
        if index + 1 >= len(items):
            reader.fail(f"'{key}' of action '{name}' has no value", key_item)
        fields[key] = items[index + 1]
        index += 2
    params = reader.parameters(fields[":parameters"], scope) if ":parameters" in fields else ()
    inner = replace(scope.with_variables(params), durative=durative)
    condition_key = ":condition" if durative else ":precondition"
    precondition = reader.condition(fields[condition_key], inner) if condition_key in fields else f.TRUE
    effect = reader.effect(fields[":effect"], inner) if ":effect" in fields else f.TRUE
    duration = None
    if durative:
        if ":duration" not in fields:
            reader.fail(f"durative action '{name}' has no ':duration'", node)
        duration = _read_duration(reader, fields[":duration"], inner, name)
    return Action(name, params, precondition, effect, duration)


def _read_duration(reader: _Reader, node: Item, scope: _Scope, action: str) -> f.Formula:
    duration = reader.condition(node, scope)
    comparisons = [n for n in f.walk(duration) if isinstance(n, f.Comparison)]
    if (
        not comparisons
        or not all(f.NumericVariable("?duration") in (c.left, c.right) for c in comparisons)
        or any(isinstance(n, (f.Atom, f.Or, f.Not, f.Exists, f.Forall)) for n in f.walk(duration))
    ):
        reader.fail(
            f"malformed ':duration' of action '{action}': expected '(= ?duration EXPR)' or a conjunction of"
            " comparisons with ?duration",
            node,
        )
    return duration


def _read_derived(reader: _Reader, node: Node, scope: _Scope) -> DerivedPredicate:
    if len(node.items) != 3 or not isinstance(node.items[1], Node) or not node.items[1].items:
        reader.fail("expected '(:derived (PREDICATE ?x ...) CONDITION)'", node)
    head_node = node.items[1]
    predicate = reader.symbol(head_node.items[0], "a predicate name")
    params = reader.parameters(Node(head_node.items[1:], head_node.start, head_node.end, head_node.line), scope)
    declared = scope.predicates.get(predicate)
    if declared is None:
        reader.fail(f"derived predicate '{predicate}' is not declared in :predicates", head_node)
    if len(declared) != len(params):
        reader.fail(f"derived predicate '{predicate}' takes {len(declared)} arguments, got {len(params)}", head_node)
    body = reader.condition(node.items[2], scope.with_variables(params))
    return DerivedPredicate(f.Atom(predicate, tuple(v for v, _ in params)), params, body)


# --------------------------------------------------------------------------- problems


@dataclass
class _InitParts:
    facts: dict[f.GroundAtom, int]  # in the order the file first states them, each with its rank
    numeric: dict[f.GroundAtom, float]
    timed: list[TimedLiteral]
    spans: list[InitSpan]


def read_problem(text: str, domain: Domain, path: str | None = None, deadline: float | None = None) -> Problem:
    """Build a Problem for ``domain`` from PDDL text; errors name ``path`` and the line.

    ``deadline`` (``time.monotonic()`` seconds): past it, ``OutOfTimeError``.
    """
    with collection_paused():
        return _read_problem(text, domain, path, deadline)


def _read_problem(text: str, domain: Domain, path: str | None, deadline: float | None) -> Problem:
    body = _init_body(text)
    # A big :init of plain atoms (125,000 ``above`` facts) is read with string methods instead of
    # one node per token: first as one stretch, up to its first '))'; where something else stands in
    # it (a numeric value, a negative or timed literal), as the stretches between such entries, which
    # the list reader reads.  Anything else it does not expect, the full reading reads and reports.
    for find_stretches in (_one_stretch, _stretches_between_entries):
        stretches = find_stretches(text, body) if body is not None else None
        if stretches is None:  # too few atoms before the first '))' may still be enough between entries
            continue
        try:
            atoms = _plain_atoms(text, stretches)
            root = parse_sexpr(text, path, deadline, skip=stretches)
            return _read_problem_from(text, root, domain, path, deadline, atoms)
        except OutOfTimeError:
            raise
        except _NotPlain:
            continue
        except RelevancePlanError:
            break
    return _read_problem_from(text, parse_sexpr(text, path, deadline), domain, path, deadline, None)


class _NotPlain(PDDLParseError):
    """Something other than blanks and plain atoms in a stretch of :init."""


# The one ``(:init`` of a problem; the end of a body of plain atoms (no nested list, no comment);
# blanks up to a ')'; an entry holding a list; what splits a stretch of plain atoms into blanks and
# atoms' insides; an atom's predicate; its arguments.
_INIT_START = re.compile(r"\(\s*:init(?=[\s();])", re.IGNORECASE)
_LAST_ATOM = re.compile(r"\)\s*\)")
_CLOSING = re.compile(r"\s*\)")
_HOLDS_A_LIST = re.compile(r"\([^()]*\(")
_BRACKET = re.compile(r"[()]")
_HEAD = operator.itemgetter(0)
_ARGUMENTS = operator.itemgetter(slice(1, None))
FLAT_INIT_FROM = 2000  # atoms in :init before the string-method reading pays

# The atoms of :init's stretches of plain atoms, lower-cased and split into words; where each opens;
# where each closes.
_PlainAtoms = tuple[list[tuple[str, ...]], list[int], list[int]]


def _init_body(text: str) -> int | None:
    """Where the body of the one :init starts; None if there are several, or it is in a comment."""
    found = list(_INIT_START.finditer(text))
    if len(found) != 1:
        return None
    start = found[0].start()
    line_start = max(text.rfind("\n", 0, start), text.rfind("\r", 0, start)) + 1
    if ";" in text[line_start:start]:
        return None  # in a comment
    return found[0].end()


def _one_stretch(text: str, body: int) -> list[tuple[int, int]] | None:
    """The :init body up to its first '))', where a body of plain atoms ends (they hold no bracket)."""
    last = _LAST_ATOM.search(text, body)
    return _worth_reading(text, body, [(body, last.end() - 1)]) if last is not None else None


def _stretches_between_entries(text: str, body: int) -> list[tuple[int, int]] | None:
    """The stretches of the :init body between its entries holding a list, to its closing ')'; None
    once past the first 2,000 entries they are more than half as many as the atoms before them (each
    entry costs more to find and read this way than in the full reading, each atom less)."""
    stretches: list[tuple[int, int]] = []
    start = body
    atoms = 0
    last = _LAST_ATOM.search(text, start)
    while last is not None:
        if len(stretches) > FLAT_INIT_FROM and 2 * len(stretches) > atoms:
            return None
        closing = _CLOSING.match(text, start)  # the body ends right after an entry (or is empty)
        if closing is not None:
            stretches.append((start, closing.end() - 1))
            return _worth_reading(text, body, stretches)
        entry = _HOLDS_A_LIST.search(text, start, last.start())
        if entry is None:
            stretches.append((start, last.end() - 1))
            return _worth_reading(text, body, stretches)
        entry_end = _list_end(text, entry.start())
        if entry_end is None:
            return None
        stretches.append((start, entry.start()))
        atoms += text.count("(", start, entry.start())
        start = entry_end
        if last.start() < start:  # that '))' closed the entry
            last = _LAST_ATOM.search(text, start)
    return None


def _list_end(text: str, start: int) -> int | None:
    """The offset after the ')' closing the list that opens at ``start``."""
    depth = 0
    for bracket in _BRACKET.finditer(text, start):
        depth += 1 if bracket.group() == "(" else -1
        if not depth:
            return bracket.end()
    return None


def _worth_reading(text: str, body: int, stretches: list[tuple[int, int]]) -> list[tuple[int, int]] | None:
    """``stretches`` if they hold enough atoms, and the body no comment and no CR."""
    end = stretches[-1][1]
    if sum(text.count("(", start, stop) for start, stop in stretches) < FLAT_INIT_FROM:
        return None
    if text.find(";", body, end) >= 0 or text.find("\r", body, end) >= 0:
        return None
    return stretches


def _read_flat_init(
    atoms: _PlainAtoms,
    scope: _Scope,
    objects: Mapping[str, str],
    path: str | None = None,
    deadline: float | None = None,
) -> _InitParts:
    """What :func:`_read_init` makes of ``atoms``; a PDDLParseError at the first one it would refuse
    (the caller then reads the file in full, for the full message and its line)."""
    grounds, opens, closes = atoms
    if not all(grounds):
        raise PDDLParseError("not a plain atom")
    args = list(map(_ARGUMENTS, grounds))
    predicates, known = scope.predicates, scope.objects or {}
    for head, arity in set(zip(map(_HEAD, grounds), map(len, args))):
        declared = predicates.get(head)
        if declared is None or len(declared) != arity:
            raise PDDLParseError("not a plain atom")
    if not known.keys() >= set(itertools.chain.from_iterable(args)):
        raise PDDLParseError("not a plain atom")
    check_deadline(deadline, "reading ':init'", path)
    names = objects.keys()
    if known.keys() - names:  # a domain constant is no object of the problem: never cut for it
        args = [tuple(sorted(names & atom_args)) for atom_args in args]
    facts = dict(zip(grounds, itertools.count()))
    if len(facts) < len(grounds):  # stated twice: the rank above is the last statement's
        facts = dict(zip(facts, itertools.count()))
    return _InitParts(facts, {}, [], list(zip(opens, closes, args)))


def _plain_atoms(text: str, stretches: list[tuple[int, int]]) -> _PlainAtoms:
    """The atoms of the stretches; _NotPlain if anything else is there.

    Whole-stretch steps, each one pass in C (a Python loop per atom is what made big files slow): a
    stretch alternates blanks and atoms, so splitting it at the brackets leaves each atom's inside at
    an odd place, and the pieces' lengths give each bracket's offset.  Each step's input is dropped
    once used: on the biggest files each is as large as the file.
    """
    grounds: list[tuple[str, ...]] = []
    opens: list[int] = []
    closes: list[int] = []
    for start, end in stretches:
        inside = text[start:end]
        ascii_only = inside.isascii()  # else atom by atom: a non-ASCII lower case may change a length
        pieces = _BRACKET.split(inside.lower() if ascii_only else inside)
        del inside
        if "".join(pieces[0::2]).strip():  # something between atoms, or a list inside one
            raise _NotPlain("not a plain atom")
        brackets = list(map(operator.add, itertools.accumulate(map(len, pieces)), itertools.count(start)))
        opens += brackets[0:-1:2]
        closes += map(operator.add, brackets[1::2], itertools.repeat(1))
        del brackets
        insides = pieces[1::2]
        del pieces
        if not ascii_only:
            insides = list(map(str.lower, insides))
        grounds += map(tuple, map(str.split, insides))
    return grounds, opens, closes


def _read_problem_from(
    text: str,
    root: Node,
    domain: Domain,
    path: str | None,
    deadline: float | None,
    atoms: _PlainAtoms | None,
) -> Problem:
    reader = _Reader(path)
    name, sections = _header(reader, root, "problem")
    found, requirements = _problem_sections(reader, root, sections, domain)
    objects, display, groups = _read_objects(reader, found.get(":objects"), domain)
    check_deadline(deadline, "reading the objects", path)
    known = dict(domain.constants)
    known.update(objects)
    scope = _Scope(domain.types, domain.predicates, domain.functions, MappingProxyType(known), {}, in_problem=True)
    init = _read_problem_init(reader, found["init"], scope, objects, deadline, atoms)
    goal = _read_goal(reader, found.get(":goal"), replace(scope, preferences=True))
    constraints = None
    if ":constraints" in found:
        constraints = _single(reader, found[":constraints"], ":constraints", replace(scope, trajectory=True))
    return Problem(
        name=name,
        domain_name=domain.name,
        objects=frozen(objects),
        init=frozenset(init.facts),
        goal=goal,
        text=text,
        path=path,
        spelling=domain.spelling.with_objects(frozen(display)),
        numeric_init=frozen(init.numeric),
        timed_literals=tuple(init.timed),
        constraints=constraints,
        metric=_read_metric(reader, found.get(":metric"), scope),
        requirements=requirements,
        object_groups=groups,
        init_spans=tuple(init.spans),
        init_order=MappingProxyType(init.facts),
    )


def _problem_sections(
    reader: _Reader, root: Node, sections: list[Item], domain: Domain
) -> tuple[dict[str, Any], frozenset[str]]:
    """The problem's sections by keyword (``init``: the entries of every ``:init``), and its requirements."""
    found: dict[str, Any] = {"init": []}
    requirements: frozenset[str] = frozenset()
    for section in sections:
        key = _keyword_of(section)
        if key is None or not isinstance(section, Node):
            reader.fail("expected a '(:section ...)'", section)
        if key in found and key != ":init":
            reader.fail(f"section '{key}' appears twice", section)
        body = section.items[1:]
        if key == ":domain":
            found[key] = _domain_name(reader, section, domain)
        elif key == ":requirements":
            requirements = _requirements(reader, body)
            found[key] = True
        elif key == ":init":
            found["init"].extend(body)
        elif key in (":objects", ":goal", ":constraints", ":metric"):
            found[key] = section
        elif key == ":length":
            found[key] = True  # PDDL 1.2's plan-length hint: planners ignore it
        else:
            reader.fail(f"unknown problem section '{key}'", section)
    if ":domain" not in found:
        reader.fail("missing '(:domain NAME)'", root)
    if ":goal" not in found and ":constraints" not in found:
        reader.fail("missing '(:goal ...)'", root)
    return found, requirements


def _domain_name(reader: _Reader, section: Node, domain: Domain) -> str:
    """The name of ``(:domain NAME)``; DomainMismatchError unless it is ``domain``'s."""
    body = section.items[1:]
    if len(body) != 1:
        reader.fail("expected '(:domain NAME)'", section)
    domain_name = reader.symbol(body[0], "a domain name")
    if domain_name != domain.name:
        reader.fail(
            f"problem is for domain '{domain_name}', but the domain file defines '{domain.name}'",
            section,
            DomainMismatchError,
        )
    return domain_name


def _read_problem_init(
    reader: _Reader,
    entries: list[Item],
    scope: _Scope,
    objects: Mapping[str, str],
    deadline: float | None,
    atoms: _PlainAtoms | None,
) -> _InitParts:
    """The initial state: every entry read, or (``atoms``) the plain atoms read flat and the other entries in full."""
    if atoms is None:
        return _read_init(reader, entries, scope, objects, deadline)
    init = _read_flat_init(atoms, scope, objects, reader.path, deadline)
    if not entries:
        return init
    # the entries between the stretches: numeric values, negative and timed literals
    others = _read_init(reader, entries, scope, objects, deadline)
    if others.facts:
        raise PDDLParseError("a fact among the entries")  # none holds one: read in full if it did
    return _InitParts(init.facts, others.numeric, others.timed, sorted(init.spans + others.spans))


def _single(reader: _Reader, section: Node, key: str, scope: _Scope) -> f.Formula:
    body = section.items[1:]
    if len(body) != 1:
        reader.fail(f"expected '({key} CONDITION)'", section)
    return reader.condition(body[0], scope)


def _read_goal(reader: _Reader, section: Node | None, scope: _Scope) -> f.Formula:
    if section is None:
        return f.TRUE  # a problem of trajectory constraints only
    return _single(reader, section, ":goal", scope)


def _read_objects(
    reader: _Reader, section: Node | None, domain: Domain
) -> tuple[dict[str, str], dict[str, str], tuple[ObjectGroup, ...]]:
    objects: dict[str, str] = {}
    display: dict[str, str] = {}
    if section is None:
        return objects, display, ()
    pairs, groups = _typed_list(reader, section.items[1:], ":objects")
    for symbol, type_name in pairs:
        lowered = symbol.text.lower()
        for member in type_name.removeprefix("(either ").rstrip(")").split():
            if member not in domain.types:
                reader.fail(f"object '{symbol.text}' has unknown type '{member}'", symbol, DomainMismatchError)
        if lowered in objects or lowered in domain.constants:
            reader.fail(f"object '{symbol.text}' is declared twice", symbol)
        objects[lowered] = type_name
        if symbol.text != lowered:  # a name written in lower case is shown as the model holds it
            display[lowered] = symbol.text
    return objects, display, tuple(groups)


def _read_init(
    reader: _Reader, nodes: list[Item], scope: _Scope, objects: Mapping[str, str], deadline: float | None = None
) -> _InitParts:
    parts = _InitParts({}, {}, [], [])
    for count, node in enumerate(nodes):
        if not count & 0xFFF:
            check_deadline(deadline, "reading ':init'", reader.path, node.line)
        if not isinstance(node, Node) or not node.items:
            reader.fail("expected an atom in ':init'", node)
        head = _keyword_of(node)
        mentioned: set[str] = set()
        if head == "at" and len(node.items) == 3 and _number(_text(node.items[1])) is not None:
            parts.timed.append(_read_timed_literal(reader, node, scope, mentioned))
        elif head == "=":
            term, value = _read_numeric_value(reader, node, scope)
            parts.numeric[term] = value
            mentioned.update(term[1:])
        elif head == "not":
            if len(node.items) != 2 or not isinstance(node.items[1], Node):
                reader.fail("'not' in ':init' takes one atom", node)
            atom = reader.atom(node.items[1], scope)
            mentioned.update(_atom_terms(atom))  # closed world: changes nothing, but cut with its objects
        else:
            atom = reader.atom(node, scope)
            if not isinstance(atom, f.Atom):
                reader.fail("an equality is not an initial fact", node)
            ground = (atom.predicate, *atom.args)
            parts.facts.setdefault(ground, len(parts.facts))
            mentioned.update(atom.args)
        parts.spans.append((node.start, node.end, tuple(sorted(mentioned & objects.keys()))))
    return parts


def _text(item: Item) -> str:
    return item.text if isinstance(item, Symbol) else ""


def _atom_terms(atom: f.Atom | f.Equality) -> tuple[str, ...]:
    return atom.args if isinstance(atom, f.Atom) else (atom.left, atom.right)


def _read_numeric_value(reader: _Reader, node: Node, scope: _Scope) -> tuple[f.GroundAtom, float]:
    if len(node.items) != 3 or not isinstance(node.items[1], Node):
        reader.fail("expected '(= (FUNCTION ARG ...) NUMBER)' in ':init'", node)
    fluent = reader.fluent(node.items[1], scope)
    value_item = node.items[2]
    value = _number(value_item.text) if isinstance(value_item, Symbol) else None
    if value is None:
        reader.fail(
            f"the initial value of '{fluent.function}' must be a number (object fluents are not supported)",
            node,
            UnsupportedFeatureError if isinstance(value_item, Symbol) else PDDLParseError,
        )
    return (fluent.function, *fluent.args), value


def _read_timed_literal(reader: _Reader, node: Node, scope: _Scope, mentioned: set[str]) -> TimedLiteral:
    time = _number(_text(node.items[1]))
    assert time is not None
    if time < 0:
        reader.fail(f"a timed initial literal at a negative time ({time:g})", node)
    inner = node.items[2]
    if not isinstance(inner, Node):
        reader.fail("expected '(at TIME FACT)'", node)
    head = _keyword_of(inner)
    if head == "=":
        term, value = _read_numeric_value(reader, inner, scope)
        mentioned.update(term[1:])
        return TimedLiteral(time, fluent=term, value=value)
    negated = head == "not"
    if negated:
        if len(inner.items) != 2 or not isinstance(inner.items[1], Node):
            reader.fail("'not' in a timed literal takes one atom", inner)
        inner = inner.items[1]
    atom = reader.atom(inner, scope)
    if not isinstance(atom, f.Atom):
        reader.fail("expected a fact in a timed literal", inner)
    mentioned.update(atom.args)
    return TimedLiteral(time, atom=(atom.predicate, *atom.args), negated=negated)


def _read_metric(reader: _Reader, section: Node | None, scope: _Scope) -> Metric | None:
    if section is None:
        return None
    body = section.items[1:]
    if len(body) != 2:
        reader.fail("expected '(:metric minimize|maximize EXPRESSION)'", section)
    direction = reader.symbol(body[0], "'minimize' or 'maximize'")
    if direction not in ("minimize", "maximize"):
        reader.fail(f"expected 'minimize' or 'maximize', found '{direction}'", body[0])
    return Metric(direction, reader.expression(body[1], replace(scope, durative=False)))
