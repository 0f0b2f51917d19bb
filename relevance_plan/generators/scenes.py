"""The two kitchen worlds and their four base scenes, as immutable data.

A scene lists places, items, humans and the robot's start place.  Places are
surfaces (always accessible) or containers (closed at the start).  An item is
at one place and either stands on the base of that place or directly on one
other item at the same place (a pile).  Object names are ``<kind>_<index>``
in lowercase (``plastic_cup_1``); ``kind_of`` strips the index.

Natural task dependencies
-------------------------
A *task item* is an item whose PDDL type is in the world's
``relevant_types`` (the things a helpful person would consider for the
objective).  A natural task dependency is an ordered pair (object, requires)
of one of these kinds, computed from the scene by ``compute_dependencies``:

``in-closed-container``
    a task item is inside a container that is closed at the start:
    the container must be opened first;
``covered``
    some item stands directly on a task item: that item (``requires``) must
    be moved before the task item can be picked up;
``sealed``
    a cereal box is sealed: it must itself be opened before pouring
    (``requires`` is the box);
``return``
    the goal wants a task item back at its original place at the end
    (every cereal box and every milk in the cereal world).

Coffee-simple has none; cereal-simple and cereal-hard have exactly 20.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from functools import cached_property

from relevance_plan.generators.catalog import KITCHENWARE_TYPES
from relevance_plan.relevance.scoring.scene import kind_of  # noqa: F401  (one rule for a name's kind)

SURFACE = "surface"
CONTAINER = "container"
PLACE_KINDS = (SURFACE, CONTAINER)

DIFFICULTIES = ("simple", "hard")

DEPENDENCY_KINDS = ("in-closed-container", "covered", "sealed", "return")

_NAME = re.compile(r"^([a-z]+(?:_[a-z]+)*)_([1-9][0-9]*)$")


def name_key(name: str) -> tuple[str, int]:
    """Sort key that orders ``cup_2`` before ``cup_10``."""
    match = _NAME.match(name)
    return (match.group(1), int(match.group(2))) if match else (name, 0)


@dataclass(frozen=True)
class KitchenSpec:
    """What a kitchen world's domain needs from a scene and what its objective is."""

    name: str
    item_types: tuple[str, ...]
    """Every item type of the domain, in declaration order."""
    relevant_types: tuple[str, ...]
    """Types a helpful person would consider for the objective."""
    roles: tuple[tuple[str, str], ...]
    """(role, type): one object per role is enough for a plan."""
    goal_predicate: str
    """Unary predicate over the human: what the human wants."""
    returned_types: tuple[str, ...]
    """Items of these types must be back at their original place at the end."""
    init_markers: tuple[tuple[str, str], ...]
    """(predicate, type): a unary fact true at the start for every such item."""


# The kitchen domains by world name (the worlds themselves are generators.worlds.WORLDS).
KITCHENS: dict[str, KitchenSpec] = {
    "coffee": KitchenSpec(
        name="coffee",
        item_types=(
            "cup",
            "coffee-source",
            "whitener",
            "stirrer",
            "sweetener",
            "napkin",
            "ice-holder",
            "tea",
            "drink",
            "plate",
            "bowl",
            *KITCHENWARE_TYPES[1:],
        ),
        relevant_types=("cup", "coffee-source", "whitener", "stirrer", "napkin", "sweetener", "ice-holder"),
        roles=(("cup", "cup"), ("coffee-source", "coffee-source"), ("whitener", "whitener"), ("stirrer", "stirrer")),
        goal_predicate="coffee-served",
        returned_types=(),
        init_markers=(("empty", "cup"),),
    ),
    "cereal": KitchenSpec(
        name="cereal",
        item_types=(
            "bowl",
            "cereal",
            "milk",
            "spoon",
            "napkin",
            "sweetener",
            "fruit",
            "cup",
            *KITCHENWARE_TYPES,
        ),
        relevant_types=("bowl", "cereal", "milk", "spoon", "napkin", "sweetener", "fruit"),
        roles=(("bowl", "bowl"), ("spoon", "spoon"), ("cereal", "cereal"), ("milk", "milk")),
        goal_predicate="cereal-served",
        returned_types=("cereal", "milk"),
        init_markers=(("sealed", "cereal"), ("empty", "bowl")),
    ),
}


@dataclass(frozen=True)
class Place:
    name: str
    kind: str  # SURFACE or CONTAINER

    @property
    def accessible(self) -> bool:
        """Surfaces are accessible from the start; containers start closed."""
        return self.kind == SURFACE


@dataclass(frozen=True)
class Item:
    name: str
    type: str
    place: str
    on: str | None = None
    """The item this one stands directly on (same place), or None."""


@dataclass(frozen=True)
class HumanPlacement:
    name: str
    place: str


@dataclass(frozen=True, order=True)
class Dependency:
    object: str
    kind: str
    requires: str

    def as_dict(self) -> dict[str, str]:
        return {"kind": self.kind, "object": self.object, "requires": self.requires}


@dataclass(frozen=True)
class SceneLayout:
    """An immutable world state; validated on construction.

    ``dependencies`` is computed from the other fields (see the module
    docstring) and stored with the scene.
    """

    world: str
    difficulty: str
    places: tuple[Place, ...]
    items: tuple[Item, ...]
    humans: tuple[HumanPlacement, ...]
    robot_start: str
    dependencies: tuple[Dependency, ...] = field(init=False, compare=False)

    def __post_init__(self) -> None:
        _check_scene(self)
        object.__setattr__(self, "dependencies", compute_dependencies(self))

    @property
    def name(self) -> str:
        return f"{self.world}-{self.difficulty}"

    @property
    def world_spec(self) -> KitchenSpec:
        return KITCHENS[self.world]

    @property
    def objects_total(self) -> int:
        """Places + items + humans (the robot is not an object)."""
        return len(self.places) + len(self.items) + len(self.humans)

    def place(self, name: str) -> Place:
        return self._places[name]

    def item(self, name: str) -> Item:
        return self._items[name]

    def item_above(self, name: str) -> str | None:
        """The item standing directly on ``name``, if any."""
        return self._above.get(name)

    # Lookup tables, built once per scene; cached_property writes to the
    # instance dictionary directly, so it works on a frozen dataclass.
    @cached_property
    def _places(self) -> dict[str, Place]:
        return {p.name: p for p in self.places}

    @cached_property
    def _items(self) -> dict[str, Item]:
        return {i.name: i for i in self.items}

    @cached_property
    def _above(self) -> dict[str, str]:
        return {i.on: i.name for i in self.items if i.on is not None}

    def items_above(self, name: str) -> list[str]:
        """Everything stacked on ``name``, transitively, nearest first."""
        result = []
        current = self.item_above(name)
        while current is not None:
            result.append(current)
            current = self.item_above(current)
        return result

    def items_below(self, name: str) -> list[str]:
        """Everything ``name`` stands on, transitively, nearest first."""
        result = []
        current = self.item(name).on
        while current is not None:
            result.append(current)
            current = self.item(current).on
        return result

    def pile(self, name: str) -> list[str]:
        """The whole pile ``name`` belongs to, bottom first."""
        return list(reversed(self.items_below(name))) + [name] + self.items_above(name)

    def in_closed_container(self, name: str) -> bool:
        return not self.place(self.item(name).place).accessible

    def is_task_item(self, name: str) -> bool:
        return self.item(name).type in self.world_spec.relevant_types

    def object_names(self) -> list[str]:
        return [p.name for p in self.places] + [i.name for i in self.items] + [h.name for h in self.humans]


def _check_scene(scene: SceneLayout) -> None:
    if scene.world not in KITCHENS:
        raise ValueError(f"unknown world {scene.world!r}")
    world = KITCHENS[scene.world]
    names = scene.object_names()
    duplicates = sorted({n for n in names if names.count(n) > 1}) if len(set(names)) != len(names) else []
    if duplicates:
        raise ValueError(f"duplicate object names: {duplicates}")
    for name in names:
        if not _NAME.match(name):
            raise ValueError(f"object name {name!r} is not <kind>_<index>")
    places = {p.name: p for p in scene.places}
    for place in scene.places:
        if place.kind not in PLACE_KINDS:
            raise ValueError(f"place {place.name}: kind must be one of {PLACE_KINDS}")
    if scene.robot_start not in places:
        raise ValueError(f"robot start {scene.robot_start!r} is not a place")
    for human in scene.humans:
        if human.place not in places:
            raise ValueError(f"human {human.name}: unknown place {human.place!r}")
    items = {i.name: i for i in scene.items}
    supporters: set[str] = set()
    for item in scene.items:
        if item.type not in world.item_types:
            raise ValueError(f"item {item.name}: type {item.type!r} is not an item type of {world.name}")
        if item.place not in places:
            raise ValueError(f"item {item.name}: unknown place {item.place!r}")
        if item.on is not None:
            below = items.get(item.on)
            if below is None:
                raise ValueError(f"item {item.name} stands on unknown item {item.on!r}")
            if below.place != item.place:
                raise ValueError(f"item {item.name} stands on {item.on}, which is at another place")
            if item.on in supporters:
                raise ValueError(f"two items stand directly on {item.on}")
            supporters.add(item.on)
    for item in scene.items:  # no cycles: every pile reaches a base
        seen = {item.name}
        current = item.on
        while current is not None:
            if current in seen:
                raise ValueError(f"items {sorted(seen)} stand on each other in a cycle")
            seen.add(current)
            current = items[current].on


def compute_dependencies(scene: SceneLayout) -> tuple[Dependency, ...]:
    """Natural task dependencies of a scene (see the module docstring), sorted."""
    world = KITCHENS[scene.world]
    found: list[Dependency] = []
    above = {i.on: i.name for i in scene.items if i.on is not None}
    places = {p.name: p for p in scene.places}
    for item in scene.items:
        if item.type not in world.relevant_types:
            continue
        if not places[item.place].accessible:
            found.append(Dependency(item.name, "in-closed-container", item.place))
        if item.name in above:
            found.append(Dependency(item.name, "covered", above[item.name]))
        if ("sealed", item.type) in world.init_markers:
            found.append(Dependency(item.name, "sealed", item.name))
        if item.type in world.returned_types:
            found.append(Dependency(item.name, "return", item.place))
    order = {kind: k for k, kind in enumerate(DEPENDENCY_KINDS)}
    return tuple(sorted(found, key=lambda d: (name_key(d.object), order[d.kind], name_key(d.requires))))


# --- the four base scenes ----------------------------------------------------


def _kitchen(
    world: str,
    difficulty: str,
    surfaces: tuple[str, ...],
    containers: tuple[str, ...],
    table: str,
    items: Mapping[str, tuple[tuple[str, ...], ...]],
) -> SceneLayout:
    """A base scene: the robot starts at the first kitchen counter and the human waits at ``table``;
    ``items`` by place, each ``(name, type)`` or ``(name, type, the item it stands on)``."""
    return SceneLayout(
        world=world,
        difficulty=difficulty,
        places=(*(Place(name, SURFACE) for name in surfaces), *(Place(name, CONTAINER) for name in containers)),
        items=tuple(
            Item(spec[0], spec[1], place, spec[2] if len(spec) > 2 else None)
            for place, specs in items.items()
            for spec in specs
        ),
        humans=(HumanPlacement("person_1", table),),
        robot_start="kitchen_counter_1",
    )


def _hard_kitchen(world: str, table: str, items: Mapping[str, tuple[tuple[str, ...], ...]]) -> SceneLayout:
    """A hard scene's kitchen: two counters, the human's table and a shelf; two cabinets, a fridge, a drawer."""
    surfaces = ("kitchen_counter_1", "kitchen_counter_2", table, "shelf_1")
    return _kitchen(world, "hard", surfaces, ("cabinet_1", "cabinet_2", "fridge_1", "drawer_1"), table, items)


COFFEE_SIMPLE = _kitchen(
    "coffee",
    "simple",
    surfaces=("kitchen_counter_1", "serving_table_1"),
    containers=("cabinet_1",),
    table="serving_table_1",
    items={
        "kitchen_counter_1": (
            ("cold_brew_coffee_1", "coffee-source"),
            ("whole_milk_1", "whitener"),
            ("reduced_milk_1", "whitener"),
            ("plastic_cup_1", "cup"),
            ("ice_bucket_1", "ice-holder"),
            ("cutting_board_1", "board"),
        ),
        "serving_table_1": (
            ("creamer_1", "whitener"),
            ("paper_cup_1", "cup"),
            ("stir_stick_1", "stirrer"),
            ("napkin_1", "napkin"),
            ("sugar_packet_1", "sweetener"),
            ("tea_bag_1", "tea"),
            ("water_bottle_1", "drink"),
            ("serving_tray_1", "tray"),
        ),
        "cabinet_1": (("dinner_plate_1", "plate"),),
    },
)


COFFEE_HARD = _hard_kitchen(
    "coffee",
    "serving_table_1",
    {
        "kitchen_counter_1": (
            ("coffee_pot_1", "coffee-source"),
            ("cutting_board_1", "board"),
            ("toaster_1", "appliance"),
        ),
        "kitchen_counter_2": (("plastic_cup_1", "cup"), ("plastic_cup_2", "cup"), ("ice_bucket_1", "ice-holder")),
        "serving_table_1": (
            ("paper_cup_1", "cup"),
            ("creamer_1", "whitener"),
            ("stir_stick_1", "stirrer"),
            ("stir_stick_2", "stirrer"),
            ("napkin_1", "napkin"),
            ("sugar_packet_1", "sweetener"),
            ("serving_tray_1", "tray"),
        ),
        "shelf_1": (("tea_bag_1", "tea"), ("honey_1", "sweetener")),
        "cabinet_1": (("mug_1", "cup"), ("ceramic_cup_1", "cup")),
        "cabinet_2": (("dinner_plate_1", "plate"), ("saucepan_1", "cookware")),
        "fridge_1": (
            ("cold_brew_coffee_1", "coffee-source"),
            ("whole_milk_1", "whitener"),
            ("reduced_milk_1", "whitener"),
            ("water_bottle_1", "drink"),
            ("orange_juice_1", "drink"),
        ),
        "drawer_1": (("teaspoon_1", "stirrer"), ("napkin_2", "napkin"), ("tea_towel_1", "linen")),
    },
)


CEREAL_SIMPLE = _kitchen(
    "cereal",
    "simple",
    surfaces=("kitchen_counter_1", "dining_table_1"),
    containers=("cabinet_1", "fridge_1", "drawer_1"),
    table="dining_table_1",
    items={
        "cabinet_1": (
            ("corn_flakes_1", "cereal"),
            ("granola_1", "cereal"),
            ("cereal_bowl_1", "bowl"),
            ("cereal_bowl_2", "bowl", "cereal_bowl_1"),
            ("cereal_bowl_3", "bowl", "cereal_bowl_2"),
            ("brown_sugar_1", "sweetener"),
        ),
        "fridge_1": (("whole_milk_1", "milk"), ("oat_milk_1", "milk"), ("strawberries_1", "fruit")),
        "drawer_1": (("spoon_1", "spoon"), ("spoon_2", "spoon"), ("napkin_1", "napkin")),
    },
)


CEREAL_HARD = _hard_kitchen(
    "cereal",
    "dining_table_1",
    {
        "kitchen_counter_1": (("banana_1", "fruit"), ("cutting_board_1", "board")),
        "kitchen_counter_2": (("cereal_bowl_3", "bowl"),),
        "dining_table_1": (("napkin_1", "napkin"),),
        "shelf_1": (("bran_flakes_1", "cereal"),),
        "cabinet_1": (("corn_flakes_1", "cereal"), ("granola_1", "cereal"), ("honey_1", "sweetener")),
        "cabinet_2": (
            ("cereal_bowl_1", "bowl"),
            ("cereal_bowl_2", "bowl", "cereal_bowl_1"),
            ("dinner_plate_1", "plate", "cereal_bowl_2"),
            ("plastic_cup_1", "cup"),
        ),
        "fridge_1": (("whole_milk_1", "milk"), ("almond_milk_1", "milk"), ("blueberries_1", "fruit")),
        "drawer_1": (("spoon_1", "spoon"), ("spoon_2", "spoon")),
    },
)

SCENES: dict[str, SceneLayout] = {
    scene.name: scene for scene in (COFFEE_SIMPLE, COFFEE_HARD, CEREAL_SIMPLE, CEREAL_HARD)
}
"""Base scenes by ``<world>-<difficulty>``."""
