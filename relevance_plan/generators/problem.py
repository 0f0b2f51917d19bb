"""Turn a scene into a PDDL problem and into its ground-truth object sets.

Init:  ``(robot-at START)``, ``(hand-empty)``, ``(accessible P)`` for every
surface, ``(human-at H P)``, then for every item ``(at I P)`` (every item of a
pile is at the pile's place), ``(on-base I)`` for an item on no other item or
``(on I J)`` for one standing on J, ``(clear I)`` for an item with nothing on
it; coffee adds ``(empty C)`` for every cup, cereal ``(sealed B)`` for every
cereal box and ``(empty W)`` for every bowl.

Goal: what the human wants, not which object: ``(coffee-served H)``, or
``(cereal-served H)`` plus ``(at I P0)`` for every cereal box and milk at its
original place.

Ground truth (for the sidecar files):

``relevant``
    every task item (types in the world's ``relevant_types``), every human,
    the places holding any of them, and the robot's start place;
``necessary``
    the goal objects (humans, and in cereal every box and milk), one object
    per role (``choose_roles``), every item in the pile of any of these
    (what stands on it, transitively, and what it stands on), the places
    holding all of these, the humans' places and the robot's start place.
    Restricting the problem to these objects keeps it solvable, and a plan
    of the restriction is a plan of the full problem.

Invariant: ``necessary`` is a subset of ``relevant`` plus the pile-mates of
the chosen role objects and goal items (``blockers``); every object in
``necessary - relevant`` is an item sharing a pile with one of them.
"""

from __future__ import annotations

from relevance_plan.generators.scenes import CONTAINER, SURFACE, SceneLayout, name_key
from relevance_plan.pddl.formatter import format_problem_parts

Atom = tuple[str, ...]


def problem_objects(scene: SceneLayout) -> dict[str, list[str]]:
    """Objects grouped by PDDL type, in a fixed order."""
    objects: dict[str, list[str]] = {
        SURFACE: [p.name for p in scene.places if p.kind == SURFACE],
        CONTAINER: [p.name for p in scene.places if p.kind == CONTAINER],
        "human": [h.name for h in scene.humans],
    }
    for type_name in scene.world_spec.item_types:
        objects[type_name] = [i.name for i in scene.items if i.type == type_name]
    return objects


def problem_init(scene: SceneLayout) -> list[Atom]:
    init: list[Atom] = [("robot-at", scene.robot_start), ("hand-empty",)]
    init.extend(("accessible", p.name) for p in scene.places if p.accessible)
    init.extend(("human-at", h.name, h.place) for h in scene.humans)
    for item in scene.items:
        init.append(("at", item.name, item.place))
        init.append(("on-base", item.name) if item.on is None else ("on", item.name, item.on))
        if scene.item_above(item.name) is None:
            init.append(("clear", item.name))
    for predicate, type_name in scene.world_spec.init_markers:
        init.extend((predicate, i.name) for i in scene.items if i.type == type_name)
    return init


def returned_items(scene: SceneLayout) -> list[str]:
    """Items the goal wants back at their original place."""
    return [i.name for i in scene.items if i.type in scene.world_spec.returned_types]


def problem_goal(scene: SceneLayout) -> list[Atom]:
    world = scene.world_spec
    goal: list[Atom] = [(world.goal_predicate, h.name) for h in scene.humans]
    goal.extend(("at", name, scene.item(name).place) for name in returned_items(scene))
    return goal


def goal_objects(scene: SceneLayout) -> list[str]:
    """Objects named in the goal."""
    names: dict[str, None] = {}
    for atom in problem_goal(scene):
        for name in atom[1:]:
            names[name] = None
    return list(names)


def format_scene(scene: SceneLayout, name: str, comment: str | None = None) -> str:
    """The scene as PDDL problem text (``relevance_plan.pddl.formatter`` layout)."""
    return format_problem_parts(
        name=name,
        domain=scene.world,
        objects=problem_objects(scene),
        init=problem_init(scene),
        goal=problem_goal(scene),
        comment=comment,
    )


def relevant_objects(scene: SceneLayout) -> list[str]:
    """Every object a helpful person would consider for the objective."""
    chosen: set[str] = {scene.robot_start}
    for human in scene.humans:
        chosen.update((human.name, human.place))
    for item in scene.items:
        if scene.is_task_item(item.name):
            chosen.update((item.name, item.place))
    return sorted(chosen, key=name_key)


def choose_roles(scene: SceneLayout) -> dict[str, str]:
    """One object per role: fewest items stacked on it, then not shut in a
    closed container, then the first by name (``cup_2`` before ``cup_10``)."""
    roles: dict[str, str] = {}
    for role, type_name in scene.world_spec.roles:
        candidates = [i.name for i in scene.items if i.type == type_name]
        if not candidates:
            raise ValueError(f"scene {scene.name} has no {type_name} for role {role}")
        roles[role] = min(
            candidates,
            key=lambda n: (len(scene.items_above(n)), scene.in_closed_container(n), name_key(n)),
        )
    return roles


def necessary_objects(scene: SceneLayout, roles: dict[str, str] | None = None) -> list[str]:
    """A set of objects sufficient for a plan (see the module docstring)."""
    roles = choose_roles(scene) if roles is None else roles
    items: set[str] = set()
    for name in list(roles.values()) + returned_items(scene):
        items.update(scene.pile(name))
    chosen: set[str] = set(items) | {scene.robot_start}
    chosen.update(scene.item(name).place for name in items)
    for human in scene.humans:
        chosen.update((human.name, human.place))
    return sorted(chosen, key=name_key)


def blockers(scene: SceneLayout, roles: dict[str, str] | None = None) -> list[str]:
    """Items sharing a pile with a role object or a returned item, other than those."""
    roles = choose_roles(scene) if roles is None else roles
    anchors = set(roles.values()) | set(returned_items(scene))
    found: set[str] = set()
    for name in anchors:
        found.update(scene.pile(name))
    return sorted(found - anchors, key=name_key)
