"""Immutable PDDL model and the reader that builds it from text.

A small, fast reader for typed PDDL (STRIPS with ADL conditions and
conditional effects).  It exists because unified-planning's reader costs
seconds on problems with thousands of objects, renames objects, and must not
be asked for ``initial_values``.  Symbols are lower-cased, as PDDL
is case-insensitive; the problem keeps the user's spelling of every object and
the source spans the writer needs to cut the file without re-formatting it.

Formulas are nested tuples:
  ("atom", predicate, (args...))      args are object names or ?variables
  ("and", f, ...) ("or", f, ...) ("not", f) ("imply", f, g)
  ("exists", ((var, type), ...), f) ("forall", ((var, type), ...), f)
  ("true",)
Effects:
  ("and", e, ...) ("atom", ...) ("not", ("atom", ...))
  ("forall", params, e) ("when", condition, e) ("cost",)   # numeric, ignored
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Mapping
from dataclasses import dataclass, field
from types import MappingProxyType

from relevance_plan.errors import DomainMismatchError, PDDLParseError, UnsupportedFeatureError
from relevance_plan.pddl.sexpr import Node, Symbol, parse_sexpr

SUPPORTED_REQUIREMENTS = frozenset(
    {
        ":strips",
        ":typing",
        ":negative-preconditions",
        ":disjunctive-preconditions",
        ":equality",
        ":existential-preconditions",
        ":universal-preconditions",
        ":quantified-preconditions",
        ":conditional-effects",
        ":adl",
        ":action-costs",
    }
)

Formula = tuple
GroundAtom = tuple  # (predicate, arg1, arg2, ...)
Parameters = tuple  # ((variable, type), ...)


def _frozen(mapping: dict) -> Mapping:
    return MappingProxyType(dict(mapping))


@dataclass(frozen=True)
class Action:
    name: str
    parameters: Parameters
    precondition: Formula
    effect: Formula


@dataclass(frozen=True, eq=False)
class Domain:
    name: str
    requirements: frozenset
    types: Mapping[str, str]  # type -> parent type ("object" has parent "")
    constants: Mapping[str, str]  # constant -> type
    predicates: Mapping[str, Parameters]
    actions: tuple
    path: str | None = None

    def ancestors(self, type_name: str) -> tuple[str, ...]:
        """The type itself and every supertype, most specific first."""
        chain = []
        seen = set()
        current = type_name
        while current and current not in seen:
            chain.append(current)
            seen.add(current)
            current = self.types.get(current, "object" if current != "object" else "")
        return tuple(chain)

    def is_subtype(self, type_name: str, of: str) -> bool:
        return of == "object" or of in self.ancestors(type_name)

    def action(self, name: str) -> Action | None:
        return self._actions_by_name.get(name)

    @property
    def _actions_by_name(self) -> Mapping[str, Action]:
        cached = self.__dict__.get("_action_index")
        if cached is None:
            cached = {action.name: action for action in self.actions}
            object.__setattr__(self, "_action_index", cached)
        return cached


@dataclass(frozen=True, eq=False)
class Problem:
    name: str
    domain_name: str
    objects: Mapping[str, str]  # object -> type, in file order
    init: frozenset  # ground atoms that are true
    goal: Formula
    text: str = field(repr=False)
    path: str | None = None
    display_names: Mapping[str, str] = field(default_factory=dict, repr=False)
    # Source layout, for cutting the file (see writer.py).
    object_groups: tuple = field(default=(), repr=False)  # ((symbols...), type_symbol | None)
    init_spans: tuple = field(default=(), repr=False)  # ((start, end), frozenset(objects))
    init_line: Mapping[GroundAtom, int] = field(default_factory=dict, repr=False)

    def display(self, name: str) -> str:
        return self.display_names.get(name, name)


def goal_objects(problem: Problem, domain: Domain) -> frozenset:
    """Objects named in the goal (constants excluded: they are never pruned)."""
    names = {arg for arg in formula_constants(problem.goal) if arg in problem.objects}
    return frozenset(names - set(domain.constants))


def formula_constants(formula: Formula) -> Iterator[str]:
    kind = formula[0]
    if kind == "atom":
        for arg in formula[2]:
            if not arg.startswith("?"):
                yield arg
    elif kind in ("and", "or"):
        for part in formula[1:]:
            yield from formula_constants(part)
    elif kind == "not":
        yield from formula_constants(formula[1])
    elif kind == "imply":
        yield from formula_constants(formula[1])
        yield from formula_constants(formula[2])
    elif kind in ("exists", "forall"):
        yield from formula_constants(formula[2])
    elif kind == "when":
        yield from formula_constants(formula[1])
        yield from formula_constants(formula[2])


def formula_atoms(formula: Formula, positive: bool = True) -> Iterator[tuple[Formula, bool]]:
    """Yield every atom of a condition with its polarity."""
    kind = formula[0]
    if kind == "atom":
        yield formula, positive
    elif kind in ("and", "or"):
        for part in formula[1:]:
            yield from formula_atoms(part, positive)
    elif kind == "not":
        yield from formula_atoms(formula[1], not positive)
    elif kind == "imply":
        yield from formula_atoms(formula[1], not positive)
        yield from formula_atoms(formula[2], positive)
    elif kind in ("exists", "forall"):
        yield from formula_atoms(formula[2], positive)


def effect_literals(effect: Formula) -> Iterator[tuple[Formula, bool, Formula]]:
    """Yield (atom, is_add, condition) for every literal an effect can set."""
    yield from _effect_literals(effect, ("true",))


def _effect_literals(effect: Formula, condition: Formula) -> Iterator[tuple[Formula, bool, Formula]]:
    kind = effect[0]
    if kind == "atom":
        yield effect, True, condition
    elif kind == "not":
        yield effect[1], False, condition
    elif kind == "and":
        for part in effect[1:]:
            yield from _effect_literals(part, condition)
    elif kind == "forall":
        yield from _effect_literals(effect[2], condition)
    elif kind == "when":
        yield from _effect_literals(effect[2], ("and", condition, effect[1]))


# --------------------------------------------------------------------------- reading


class _Reader:
    def __init__(self, path: str | None):
        self.path = path

    def fail(self, message: str, where: Node | Symbol | None, error=PDDLParseError):
        raise error(message, path=self.path, line=where.line if where is not None else None)

    def symbol(self, item, what: str) -> str:
        if not isinstance(item, Symbol):
            self.fail(f"expected {what}, found a list", item)
        return item.text.lower()

    def keyword_of(self, node) -> str | None:
        if isinstance(node, Node) and node.items and isinstance(node.items[0], Symbol):
            return node.items[0].text.lower()
        return None

    def header(self, root: Node, kind: str) -> tuple[str, list]:
        items = root.items
        if not items or self.keyword_of(root) != "define":
            self.fail("expected '(define ...)'", root)
        if len(items) < 2 or not isinstance(items[1], Node) or len(items[1].items) != 2:
            self.fail(f"expected '({kind} NAME)' after define", items[1] if len(items) > 1 else root)
        head = items[1]
        head_kind = self.symbol(head.items[0], kind)
        if head_kind != kind:
            other = "problem" if kind == "domain" else "domain"
            if head_kind == other:
                self.fail(f"this is a PDDL {other} file, not a {kind} file", head)
            self.fail(f"expected '({kind} NAME)', found '({head_kind} ...)'", head)
        return self.symbol(head.items[1], f"{kind} name"), items[2:]

    def typed_list(self, items: list, what: str, allow_untyped_default: str = "object"):
        """Parse 'a b - t c - u d' into [(symbol, type, type_symbol|None)] and groups."""
        result = []
        groups = []
        pending: list[Symbol] = []
        index = 0
        while index < len(items):
            item = items[index]
            if isinstance(item, Node):
                self.fail(f"unexpected list in {what}", item)
            if item.text == "-":
                if index + 1 >= len(items):
                    self.fail(f"missing type after '-' in {what}", item)
                type_item = items[index + 1]
                if isinstance(type_item, Node):
                    if self.keyword_of(type_item) == "either":
                        self.fail("'either' types are not supported", type_item, UnsupportedFeatureError)
                    self.fail(f"expected a type name after '-' in {what}", type_item)
                if not pending:
                    self.fail(f"type '{type_item.text}' given to nothing in {what}", item)
                type_name = type_item.text.lower()
                result.extend((symbol, type_name) for symbol in pending)
                groups.append((tuple(pending), type_item))
                pending = []
                index += 2
                continue
            pending.append(item)
            index += 1
        if pending:
            result.extend((symbol, allow_untyped_default) for symbol in pending)
            groups.append((tuple(pending), None))
        return result, groups

    # ---------------------------------------------------------------- formulas

    def parameters(self, node: Node, types: Mapping[str, str] | None) -> Parameters:
        if not isinstance(node, Node):
            self.fail("expected a parameter list", node)
        pairs, _ = self.typed_list(node.items, "parameter list")
        params = []
        for symbol, type_name in pairs:
            if not symbol.text.startswith("?"):
                self.fail(f"parameter '{symbol.text}' must start with '?'", symbol)
            if types is not None and type_name not in types:
                self.fail(f"unknown type '{type_name}'", symbol, DomainMismatchError)
            if any(symbol.text.lower() == name for name, _ in params):
                self.fail(f"parameter '{symbol.text}' is declared twice", symbol)
            params.append((symbol.text.lower(), type_name))
        return tuple(params)

    def condition(self, node, ctx) -> Formula:
        if isinstance(node, Symbol):
            self.fail(f"expected a condition, found '{node.text}'", node)
        if not node.items:
            return ("and",)
        head = self.keyword_of(node)
        if head is None:
            self.fail("expected a condition", node)
        args = node.items[1:]
        if head == "and":
            return ("and",) + tuple(self.condition(part, ctx) for part in args)
        if head == "or":
            return ("or",) + tuple(self.condition(part, ctx) for part in args)
        if head == "not":
            if len(args) != 1:
                self.fail("'not' takes one condition", node)
            return ("not", self.condition(args[0], ctx))
        if head == "imply":
            if len(args) != 2:
                self.fail("'imply' takes two conditions", node)
            return ("imply", self.condition(args[0], ctx), self.condition(args[1], ctx))
        if head in ("exists", "forall"):
            if len(args) != 2:
                self.fail(f"'{head}' takes a parameter list and a condition", node)
            params = self.parameters(args[0], ctx.types)
            inner = dict(ctx.variables)
            inner.update(params)
            return (head, params, self.condition(args[1], ctx.with_variables(inner)))
        if head in ("<", ">", "<=", ">="):
            self.fail(f"numeric condition '{head}' is not supported", node, UnsupportedFeatureError)
        return self.atom(node, ctx)

    def atom(self, node: Node, ctx) -> Formula:
        head = self.keyword_of(node)
        args = []
        for item in node.items[1:]:
            if isinstance(item, Node):
                self.fail(
                    f"nested list in atom '{head}' (numeric fluents are not supported)", item, UnsupportedFeatureError
                )
            text = item.text.lower()
            if text.startswith("?"):
                if ctx.variables is not None and text not in ctx.variables:
                    self.fail(f"unknown variable '{item.text}'", item)
            elif ctx.objects is not None and text not in ctx.objects:
                self.fail(f"unknown object or constant '{item.text}' in '({head} ...)'", item, DomainMismatchError)
            args.append(text)
        if head == "=":
            if len(args) != 2:
                self.fail("'=' takes two arguments", node)
        elif ctx.predicates is not None:
            if head not in ctx.predicates:
                self.fail(f"unknown predicate '{head}'", node, DomainMismatchError)
            if len(ctx.predicates[head]) != len(args):
                self.fail(
                    f"predicate '{head}' takes {len(ctx.predicates[head])} arguments, got {len(args)}",
                    node,
                    DomainMismatchError,
                )
        return ("atom", head, tuple(args))

    def effect(self, node, ctx) -> Formula:
        if isinstance(node, Symbol):
            self.fail(f"expected an effect, found '{node.text}'", node)
        if not node.items:
            return ("and",)
        head = self.keyword_of(node)
        args = node.items[1:]
        if head == "and":
            return ("and",) + tuple(self.effect(part, ctx) for part in args)
        if head == "not":
            if len(args) != 1 or self.keyword_of(args[0]) in (None, "and", "not", "forall", "when"):
                self.fail("'not' in an effect takes one atom", node)
            return ("not", self.atom(args[0], ctx))
        if head == "forall":
            if len(args) != 2:
                self.fail("'forall' in an effect takes a parameter list and an effect", node)
            params = self.parameters(args[0], ctx.types)
            inner = dict(ctx.variables)
            inner.update(params)
            return ("forall", params, self.effect(args[1], ctx.with_variables(inner)))
        if head == "when":
            if len(args) != 2:
                self.fail("'when' takes a condition and an effect", node)
            return ("when", self.condition(args[0], ctx), self.effect(args[1], ctx))
        if head == "increase":
            target = args[0] if args else None
            if isinstance(target, Node) and self.keyword_of(target) == "total-cost":
                return ("cost",)
            self.fail("only '(increase (total-cost) ...)' numeric effects are supported", node, UnsupportedFeatureError)
        if head in ("decrease", "assign", "scale-up", "scale-down"):
            self.fail(f"numeric effect '{head}' is not supported", node, UnsupportedFeatureError)
        return self.atom(node, ctx)


@dataclass(frozen=True)
class _Context:
    types: Mapping[str, str] | None
    predicates: Mapping[str, Parameters] | None
    objects: Mapping[str, str] | None
    variables: Mapping[str, str] | None

    def with_variables(self, variables: Mapping[str, str]) -> _Context:
        return _Context(self.types, self.predicates, self.objects, variables)


def read_domain(text: str, path: str | None = None) -> Domain:
    """Build a Domain from PDDL text; errors name ``path`` and the line."""
    reader = _Reader(path)
    root = parse_sexpr(text, path)
    name, sections = reader.header(root, "domain")
    requirements: set[str] = set()
    types: dict[str, str] = {"object": ""}
    constants: dict[str, str] = {}
    predicates: dict[str, Parameters] = {}
    action_nodes: list[Node] = []
    for section in sections:
        key = reader.keyword_of(section)
        if key is None:
            reader.fail("expected a '(:section ...)'", section)
        body = section.items[1:]
        if key == ":requirements":
            for item in body:
                requirement = reader.symbol(item, "a requirement")
                if requirement not in SUPPORTED_REQUIREMENTS:
                    reader.fail(f"requirement '{item.text}' is not supported", item, UnsupportedFeatureError)
                requirements.add(requirement)
        elif key == ":types":
            pairs, _ = reader.typed_list(body, ":types")
            for symbol, parent in pairs:
                types[symbol.text.lower()] = parent if symbol.text.lower() != "object" else ""
            for parent in set(types.values()) - {""}:
                types.setdefault(parent, "object")
        elif key == ":constants":
            pairs, _ = reader.typed_list(body, ":constants")
            constants.update((symbol.text.lower(), type_name) for symbol, type_name in pairs)
        elif key == ":predicates":
            for item in body:
                if not isinstance(item, Node) or not item.items:
                    reader.fail("expected '(predicate ?x - type ...)'", item)
                predicate = reader.symbol(item.items[0], "a predicate name")
                predicates[predicate] = reader.parameters(Node(item.items[1:], item.start, item.end, item.line), None)
        elif key == ":action":
            action_nodes.append(section)
        elif key == ":functions":
            # Only (total-cost) is accepted: action costs are ignored by validation.
            for item in body:
                if isinstance(item, Node) and reader.keyword_of(item) != "total-cost":
                    reader.fail(
                        "numeric functions other than (total-cost) are not supported", item, UnsupportedFeatureError
                    )
        elif key in (":derived", ":durative-action", ":process", ":event", ":constraints"):
            reader.fail(f"'{key}' is not supported", section, UnsupportedFeatureError)
        else:
            reader.fail(f"unknown domain section '{key}'", section)
    for parent in list(types.values()):
        if parent and parent not in types:
            types[parent] = "object"
    for predicate, params in predicates.items():
        for _, type_name in params:
            if type_name not in types:
                raise PDDLParseError(f"predicate '{predicate}' uses unknown type '{type_name}'", path=path)
    for constant, type_name in constants.items():
        if type_name not in types:
            raise PDDLParseError(f"constant '{constant}' has unknown type '{type_name}'", path=path)
    domain_ctx = _Context(MappingProxyType(types), MappingProxyType(predicates), MappingProxyType(constants), {})
    actions = tuple(_read_action(reader, node, domain_ctx) for node in action_nodes)
    return Domain(
        name=name,
        requirements=frozenset(requirements),
        types=_frozen(types),
        constants=_frozen(constants),
        predicates=_frozen(predicates),
        actions=actions,
        path=path,
    )


def _read_action(reader: _Reader, node: Node, ctx: _Context) -> Action:
    items = node.items
    if len(items) < 2:
        reader.fail("':action' needs a name", node)
    name = reader.symbol(items[1], "an action name")
    fields: dict[str, object] = {}
    index = 2
    while index < len(items):
        key_item = items[index]
        key = reader.symbol(key_item, "':parameters', ':precondition' or ':effect'")
        if key not in (":parameters", ":precondition", ":effect"):
            reader.fail(f"unknown action field '{key}' in action '{name}'", key_item)
        if index + 1 >= len(items):
            reader.fail(f"'{key}' of action '{name}' has no value", key_item)
        fields[key] = items[index + 1]
        index += 2
    params = reader.parameters(fields[":parameters"], ctx.types) if ":parameters" in fields else ()
    variables = dict(params)
    action_ctx = ctx.with_variables(variables)
    precondition = reader.condition(fields[":precondition"], action_ctx) if ":precondition" in fields else ("and",)
    effect = reader.effect(fields[":effect"], action_ctx) if ":effect" in fields else ("and",)
    return Action(name, params, precondition, effect)


def read_problem(text: str, domain: Domain, path: str | None = None) -> Problem:
    """Build a Problem for ``domain`` from PDDL text; errors name ``path`` and the line."""
    reader = _Reader(path)
    root = parse_sexpr(text, path)
    name, sections = reader.header(root, "problem")
    domain_name = None
    objects: dict[str, str] = {}
    display: dict[str, str] = {}
    object_groups: tuple = ()
    init_nodes: list[Node] = []
    goal_node = None
    seen: set[str] = set()
    for section in sections:
        key = reader.keyword_of(section)
        if key is None:
            reader.fail("expected a '(:section ...)'", section)
        if key in seen and key != ":init":
            reader.fail(f"section '{key}' appears twice", section)
        seen.add(key)
        body = section.items[1:]
        if key == ":domain":
            if len(body) != 1:
                reader.fail("expected '(:domain NAME)'", section)
            domain_name = reader.symbol(body[0], "a domain name")
            if domain_name != domain.name:
                reader.fail(
                    f"problem is for domain '{body[0].text}', but the domain file defines '{domain.name}'",
                    section,
                    DomainMismatchError,
                )
        elif key == ":requirements":
            for item in body:
                requirement = reader.symbol(item, "a requirement")
                if requirement not in SUPPORTED_REQUIREMENTS:
                    reader.fail(f"requirement '{item.text}' is not supported", item, UnsupportedFeatureError)
        elif key == ":objects":
            pairs, object_groups = reader.typed_list(body, ":objects")
            for symbol, type_name in pairs:
                lowered = symbol.text.lower()
                if type_name not in domain.types:
                    reader.fail(f"object '{symbol.text}' has unknown type '{type_name}'", symbol, DomainMismatchError)
                if lowered in objects or lowered in domain.constants:
                    reader.fail(f"object '{symbol.text}' is declared twice", symbol)
                objects[lowered] = type_name
                display[lowered] = symbol.text
            object_groups = tuple(object_groups)
        elif key == ":init":
            init_nodes.extend(body)
        elif key == ":goal":
            if len(body) != 1:
                reader.fail("expected '(:goal CONDITION)'", section)
            goal_node = body[0]
        elif key == ":metric":
            pass  # kept verbatim by the writer; the planner reads it
        elif key in (":constraints", ":timed-initial-literals"):
            reader.fail(f"'{key}' is not supported", section, UnsupportedFeatureError)
        else:
            reader.fail(f"unknown problem section '{key}'", section)
    if domain_name is None:
        raise PDDLParseError("missing '(:domain NAME)'", path=path, line=root.line)
    if goal_node is None:
        raise PDDLParseError("missing '(:goal ...)'", path=path, line=root.line)
    known = dict(domain.constants)
    known.update(objects)
    ctx = _Context(domain.types, domain.predicates, MappingProxyType(known), {})
    init: set[GroundAtom] = set()
    spans: list = []
    init_line: dict[GroundAtom, int] = {}
    for node in init_nodes:
        if not isinstance(node, Node) or not node.items:
            reader.fail("expected an atom in ':init'", node)
        head = reader.keyword_of(node)
        if head == "=":
            # numeric initial value such as (= (total-cost) 0): kept verbatim
            mentioned = frozenset(
                item.text.lower()
                for sub in node.items[1:]
                if isinstance(sub, Node)
                for item in sub.items[1:]
                if isinstance(item, Symbol)
            )
            spans.append(((node.start, node.end), mentioned & objects.keys()))
            continue
        if head == "not":
            continue  # closed-world: a negative initial literal changes nothing
        atom = reader.atom(node, ctx)
        ground = (atom[1],) + atom[2]
        init.add(ground)
        init_line.setdefault(ground, node.line)
        spans.append(((node.start, node.end), frozenset(arg for arg in atom[2] if arg in objects)))
    goal = reader.condition(goal_node, ctx)
    return Problem(
        name=name,
        domain_name=domain_name,
        objects=_frozen(objects),
        init=frozenset(init),
        goal=goal,
        text=text,
        path=path,
        display_names=_frozen(display),
        object_groups=object_groups,
        init_spans=tuple(spans),
        init_line=_frozen(init_line),
    )


def objects_of_type(domain: Domain, problem: Problem, type_name: str) -> tuple[str, ...]:
    """Objects and constants whose type is ``type_name`` or one of its subtypes."""
    everything = dict(domain.constants)
    everything.update(problem.objects)
    return tuple(name for name, kind in everything.items() if domain.is_subtype(kind, type_name))


def all_objects(domain: Domain, problem: Problem) -> Mapping[str, str]:
    everything = dict(domain.constants)
    everything.update(problem.objects)
    return everything


def iter_atoms(atoms: Iterable[GroundAtom], predicate: str) -> Iterator[GroundAtom]:
    return (atom for atom in atoms if atom[0] == predicate)
