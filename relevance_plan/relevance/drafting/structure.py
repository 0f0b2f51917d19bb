"""What a domain's action schemas say about its scene: where things are, what must be opened, what an action needs.

Nothing here looks at a problem.  The schemas of taking something from
somewhere (a precondition ``P(?x, ?p)`` the action deletes while it adds
``holding ?x``) say which predicates place things; whether that place is where
the robot goes (``robot-at ?p``: a location) or a thing of its own (a
container) says which role; a condition on the place in that action
(``(open ?s)``, ``(not (locked ?s))``) says what gives access to it.  A static
relation an action requires between the thing it operates and something the
robot must hold (``(fits ?k ?s)`` with ``(holding ?k)``) is a dependency: the
storage kept, its key is needed.  Each finding carries the schema it came
from, for the drafted model's comments.
"""

from __future__ import annotations

from collections import Counter, defaultdict
from collections.abc import Iterable, Mapping
from dataclasses import dataclass

from relevance_plan.pddl.formulas import Atom, effect_literals, literals
from relevance_plan.pddl.model import Action, Domain
from relevance_plan.relevance.analysis.constraint_rules import blocking_predicates
from relevance_plan.relevance.analysis.types import static_predicates
from relevance_plan.relevance.scoring.scene import SCENE_ROLES

# A type (or one of its supertypes) with one of these names stands for a person.
HUMAN_TYPE_WORDS = frozenset(
    {"human", "person", "people", "nurse", "doctor", "patient", "customer", "guest", "visitor", "worker", "user"}
)


@dataclass(frozen=True)
class Finding:
    """A scene role's predicate (None: the domain has none) and why."""

    predicate: str | None
    why: str


@dataclass(frozen=True)
class DraftedDependency:
    """Keeping the object at ``when_kept`` of a ``predicate`` fact keeps the one at ``restore`` (0-based)."""

    predicate: str
    when_kept: int
    restore: int
    reason: str
    why: str  # where it was found, for the comment


@dataclass(frozen=True)
class _Taking:
    """An action that takes the thing ``thing`` from ``P(thing, place)``."""

    action: Action
    atom: Atom  # P(?thing, ?place) as the action's precondition names it
    held: str  # the unary predicate it adds about the thing (holding)

    @property
    def thing(self) -> str:
        return self.atom.args[0]

    @property
    def place(self) -> str:
        return self.atom.args[1]


@dataclass(frozen=True)
class DomainStructure:
    """What the schemas say: the scene roles, the robot's places, what can be carried, the held predicates."""

    roles: Mapping[str, Finding]
    robot_places: frozenset[str]  # types the robot moves between
    portable: frozenset[str]  # types of things an action takes (and their subtypes)
    held: frozenset[str]  # unary predicates saying the robot holds something
    humans: frozenset[str]  # types that stand for a person
    place_types: frozenset[str]  # types of the places the location and containment roles name


def find_structure(domain: Domain) -> DomainStructure:
    """The scene roles and the other facts of the schemas that drafting uses."""
    takings = _takings(domain)
    robot_at = _robot_places(domain)
    robot_places = {t for place in robot_at.values() for t in _subtypes(domain, place)}
    portable = frozenset(t for taking in takings for t in _subtypes(domain, _type_of(taking.action, taking.thing)))
    humans = frozenset(t for t in domain.types if any(a in HUMAN_TYPE_WORDS for a in domain.ancestors(t)))
    roles: dict[str, Finding] = {}
    support = sorted(p for p, _, _ in blocking_predicates(domain) if _between_alike(domain, p))
    roles["support"] = (
        Finding(support[0], f"taking what stands on something frees it ({_users(domain, support[0])})")
        if support
        else Finding(None, "no action takes one thing off another")
    )
    placing = [t for t in takings if t.atom.predicate not in support]
    roles.update(_placement_roles(domain, placing, robot_places, frozenset(robot_at)))
    roles["human_location"] = _human_location(domain, humans, robot_places)
    places = {
        _parameter_type(domain, roles[role].predicate, 1)
        for role in ("location", "containment")
        if roles[role].predicate is not None
    }
    return DomainStructure(
        roles={role: roles[role] for role in SCENE_ROLES},
        robot_places=frozenset(robot_places),
        portable=portable,
        held=frozenset(t.held for t in takings),
        humans=humans,
        place_types=frozenset(t for p in places if p is not None for t in _subtypes(domain, p)),
    )


def _takings(domain: Domain) -> list[_Taking]:
    """Every action that deletes a precondition ``P(?x, ?p)`` and adds a unary fact about ``?x``."""
    found = []
    for action in domain.actions:
        required = [atom for atom, positive in literals(action.precondition) if positive]
        effects = list(effect_literals(action.effect))
        deleted = {item.atom for item in effects if not item.is_add}
        added = [item.atom for item in effects if item.is_add and len(item.atom.args) == 1]
        for atom in required:
            if len(atom.args) != 2 or atom not in deleted or atom.args[0] == atom.args[1]:
                continue
            for add in added:
                if add.args == (atom.args[0],) and add.predicate != atom.predicate:
                    found.append(_Taking(action, atom, add.predicate))
                    break
    return found


def _robot_places(domain: Domain) -> dict[str, str]:
    """Predicate -> type of the robot's position: ``R(?p)`` that an action does nothing but move
    from one argument to another (``move``: adds ``robot-at ?to``, deletes ``robot-at ?from``)."""
    found = {}
    for action in domain.actions:
        effects = list(effect_literals(action.effect))
        if len(effects) != 2 or {item.is_add for item in effects} != {True, False}:
            continue
        add, delete = (item.atom for item in sorted(effects, key=lambda item: not item.is_add))
        if add.predicate == delete.predicate and len(add.args) == 1 and add.args != delete.args:
            found[add.predicate] = _type_of(action, add.args[0])
    return found


def _placement_roles(
    domain: Domain, takings: list[_Taking], robot_places: set[str], robot_at: frozenset[str]
) -> dict[str, Finding]:
    """location, containment, access and closed, from the actions that take things from places
    (``robot_at``: the predicates of the robot's own position, which say nothing about access)."""
    ignored = static_predicates(domain) | robot_at
    location: Counter[str] = Counter()
    containment: Counter[str] = Counter()
    access: dict[str, Counter[str]] = defaultdict(Counter)
    closed: dict[str, Counter[str]] = defaultdict(Counter)
    for taking in takings:
        predicate = taking.atom.predicate
        place_type = _type_of(taking.action, taking.place)
        opens, shuts = _access_conditions(taking, ignored)
        access[predicate].update(opens)
        closed[predicate].update(shuts)
        if place_type in robot_places:
            location[predicate] += 1
        else:
            containment[predicate] += 1 + bool(opens or shuts)  # a condition on the place: a container for sure
    roles = {
        "location": _best(location, "things lie at the robot's places", "no action takes a thing from a place"),
        "containment": _best(containment, "things are taken out of it", "no action takes a thing out of a container"),
    }
    # access is judged where it matters most: inside containers, else at the places themselves
    inside = roles["containment"].predicate or ""
    chosen = inside if access.get(inside) or closed.get(inside) else roles["location"].predicate or ""
    opens_here = access.get(chosen, Counter())
    shuts_here = closed.get(chosen, Counter())
    roles["access"] = _best(opens_here, f"taking from '{chosen}' needs it", "nothing must hold of a place to reach it")
    roles["closed"] = _best(shuts_here, f"taking from '{chosen}' needs it false", "nothing keeps a place shut")
    for role in ("location", "containment"):
        found = roles[role].predicate
        if found is not None:
            roles[role] = Finding(found, f"{roles[role].why} ({_users(domain, found)})")
    return roles


def _access_conditions(taking: _Taking, ignored: frozenset[str]) -> tuple[list[str], list[str]]:
    """Unary fluents the taking action needs of the place: true (``open``) and false (``locked``)."""
    opens: list[str] = []
    shuts: list[str] = []
    for atom, positive in literals(taking.action.precondition):
        if atom.args == (taking.place,) and atom.predicate not in ignored:
            (opens if positive else shuts).append(atom.predicate)
    return opens, shuts


def _best(counts: Counter[str], why: str, none: str) -> Finding:
    if not counts:
        return Finding(None, none)
    predicate = sorted(counts.items(), key=lambda item: (-item[1], item[0]))[0][0]
    return Finding(predicate, why)


def _human_location(domain: Domain, humans: frozenset[str], robot_places: set[str]) -> Finding:
    for predicate, parameters in sorted(domain.predicates.items()):
        if len(parameters) == 2 and parameters[0][1] in humans and parameters[1][1] in robot_places:
            return Finding(predicate, f"'{parameters[0][1]}' stands for a person, at the robot's places")
    return Finding(None, "no type stands for a person")


def find_dependencies(domain: Domain, structure: DomainStructure) -> list[DraftedDependency]:
    """Static relations an action requires between what it operates and something the robot holds.

    ``(fits ?k ?s)`` in ``unlock`` with ``(holding ?k)``: keeping a storage keeps the keys that fit
    it.  The held side is restored when the other side is kept, never the other way round (a key
    kept for some other reason needs no lock)."""
    static = static_predicates(domain)
    found: dict[tuple[str, int, int], DraftedDependency] = {}
    for action in domain.actions:
        required = [atom for atom, positive in literals(action.precondition) if positive]
        held = {atom.args[0] for atom in required if atom.predicate in structure.held and len(atom.args) == 1}
        for atom in required:
            if atom.predicate not in static or len(atom.args) != 2 or atom.args[0] == atom.args[1]:
                continue
            for restore, when_kept in ((0, 1), (1, 0)):
                tool, operated = atom.args[restore], atom.args[when_kept]
                if tool in held and operated not in held and (atom.predicate, when_kept, restore) not in found:
                    tool_type = _type_of(action, tool)
                    found[(atom.predicate, when_kept, restore)] = DraftedDependency(
                        atom.predicate,
                        when_kept,
                        restore,
                        f"the {tool_type} that {atom.predicate} it",
                        f"'{action.name}' needs ({atom.predicate} ...) and holds the {tool_type}",
                    )
    return list(found.values())


def _between_alike(domain: Domain, predicate: str) -> bool:
    """Whether the predicate relates things of one kind (a cup on a plate, a tube on a tube), as
    standing on something does, rather than a ball and the gripper that carries it."""
    first, second = (t for _, t in domain.predicates[predicate])
    return domain.is_subtype(first, second) or domain.is_subtype(second, first)


def _type_of(action: Action, variable: str) -> str:
    return dict(action.parameters).get(variable, "object")


def _parameter_type(domain: Domain, predicate: str | None, position: int) -> str | None:
    parameters = domain.predicates.get(predicate or "")
    return parameters[position][1] if parameters and position < len(parameters) else None


def _subtypes(domain: Domain, type_name: str) -> Iterable[str]:
    return [t for t in domain.types if domain.is_subtype(t, type_name)] or [type_name]


def _users(domain: Domain, predicate: str) -> str:
    users = [a.name for a in domain.actions if any(atom.predicate == predicate for atom, _ in literals(a.precondition))]
    return "used by " + ", ".join(users[:4]) + (" ..." if len(users) > 4 else "")
