"""Seeded 3D-scene-graph worlds: an agent, rooms, places, doors, receptacles and hundreds of items.

The layers of a scene graph as the robot task-planning benchmarks built on
them use it: rooms hold places (navigation nodes, linked into a connected
graph inside each room); rooms are joined by doors between a place of
each (a spanning tree of rooms plus a few extra doors; some doors start
closed); receptacles (fridges, cabinets, drawers, tables, shelves, ...)
stand at places, the openable ones mostly closed; items lie in or on
receptacles.  One agent with one hand starts at a random place.

``size`` is about the number of objects: one room per 50, 3-6 places and
2-5 receptacles per room, the rest items.  The goal puts 1-3 items into
other receptacles and, for a third of the problems, brings the agent back
to where it started.

``SceneGraphEvents`` makes seeded event streams for such a scene (items
moved, added and removed, receptacles and doors opened and closed, new
goals, plan requests), for the live session's tests and benchmark.

A sufficient set (``necessary``): the agent, the goal items, their
receptacles and their target receptacles, and the places, rooms and doors on
shortest routes from the agent's place through each item's place and its
target's (and back, when the goal asks).  Every move is reversible and doors
stay open, so a plan can visit these places in any order.
"""

from __future__ import annotations

import random
from collections.abc import Iterable, Mapping

from relevance_plan.generators.classic import Instance
from relevance_plan.generators.graphs import Graph, add_edge, shortest_path, spanning_tree

ROOM_KINDS = ("kitchen", "living_room", "bedroom", "bathroom", "office", "hallway", "dining_room", "laundry", "garage")
RECEPTACLE_KINDS: tuple[tuple[str, bool], ...] = (  # (kind, openable)
    ("fridge", True),
    ("cabinet", True),
    ("drawer", True),
    ("wardrobe", True),
    ("microwave", True),
    ("dishwasher", True),
    ("table", False),
    ("counter", False),
    ("shelf", False),
    ("desk", False),
    ("sofa", False),
    ("bed", False),
)
ITEM_KINDS = (
    "apple", "banana", "mug", "cup", "plate", "bowl", "fork", "spoon", "knife", "bottle", "can", "book",
    "magazine", "remote", "phone", "laptop", "charger", "pen", "notebook", "towel", "soap", "toothbrush",
    "shampoo", "pillow", "blanket", "shirt", "sock", "shoe", "hat", "keys", "wallet", "glasses", "toy",
    "ball", "candle", "vase", "plant", "clock", "lamp", "box",
)  # fmt: skip
CLOSED_DOOR = 0.3
OPEN_RECEPTACLE = 0.2
RETURN_GOAL = 1 / 3


def _layout(rng: random.Random, inst: Instance, size: int) -> tuple[Graph, dict, dict, list[str]]:
    """Rooms, places, doors and receptacles; returns (place graph, door of each door edge,
    room of each place, receptacles)."""
    graph: Graph = {}
    door_of: dict[tuple[str, str], str] = {}
    room_of: dict[str, str] = {}
    rooms = [inst.add("room", f"{rng.choice(ROOM_KINDS)}_{r}") for r in range(1, max(2, size // 50) + 1)]
    places_in: dict[str, list[str]] = {}
    for r, room in enumerate(rooms, start=1):
        places = [inst.add("place", f"place_{r}_{k}") for k in range(1, rng.randint(3, 6) + 1)]
        places_in[room] = places
        local: Graph = {}
        spanning_tree(rng, places, local)
        if len(places) > 3:
            add_edge(local, *rng.sample(places, 2))
        for place in places:
            room_of[place] = room
            inst.facts.append(("in-room", place, room))
            for other in local[place]:
                inst.facts.append(("connected", place, other))
                add_edge(graph, place, other)
    # A tree of doors keeps every room reachable; a few more doors make cycles.
    pairs = [(rooms[rng.randrange(r)], rooms[r]) for r in range(1, len(rooms))]
    pairs += [(a, b) for a, b in (rng.sample(rooms, 2) for _ in range(len(rooms) // 4))]
    for number, (room_a, room_b) in enumerate(pairs, start=1):
        door = inst.add("door", f"door_{number}")
        a, b = rng.choice(places_in[room_a]), rng.choice(places_in[room_b])
        inst.facts += [("door-between", door, a, b), ("door-between", door, b, a)]
        inst.facts.append(("door-closed", door) if rng.random() < CLOSED_DOOR else ("door-open", door))
        add_edge(graph, a, b)
        door_of[(a, b)] = door_of[(b, a)] = door
    receptacles: list[str] = []
    for room in rooms:
        for _ in range(rng.randint(2, 5)):
            kind, openable = rng.choice(RECEPTACLE_KINDS)
            receptacle = inst.add("receptacle", f"{kind}_{len(receptacles) + 1}")
            receptacles.append(receptacle)
            inst.facts.append(("receptacle-at", receptacle, rng.choice(places_in[room])))
            if openable:
                inst.facts.append(("openable", receptacle))
            opened = not openable or rng.random() < OPEN_RECEPTACLE
            inst.facts.append(("opened" if opened else "closed", receptacle))
    return graph, door_of, room_of, receptacles


def build_scenegraph(rng: random.Random, size: int) -> Instance:
    inst = Instance()
    agent = inst.add("agent", "robot")
    graph, door_of, room_of, receptacles = _layout(rng, inst, size)
    place_of = {fact[1]: fact[2] for fact in inst.facts if fact[0] == "receptacle-at"}
    start = rng.choice(list(room_of))
    inst.facts += [("agent-at", agent, start), ("hand-free", agent)]
    items = [inst.add("item", f"{rng.choice(ITEM_KINDS)}_{i}") for i in range(1, max(3, size - len(inst.objects)) + 1)]
    holder = {item: rng.choice(receptacles) for item in items}
    inst.facts += [("in", item, holder[item]) for item in items]
    stops = [start]
    needed = {agent}
    for item in rng.sample(items, rng.randint(1, 3)):
        target = rng.choice([r for r in receptacles if r != holder[item]])
        inst.goal.append(("in", item, target))
        needed.update({item, holder[item], target})
        stops += [place_of[holder[item]], place_of[target]]
    if rng.random() < RETURN_GOAL:
        inst.goal.append(("agent-at", agent, start))
        stops.append(start)
    for a, b in zip(stops, stops[1:]):
        leg = shortest_path(graph, a, b)
        needed.update(leg)
        needed.update(room_of[place] for place in leg)
        needed.update(door_of[step] for step in zip(leg, leg[1:]) if step in door_of)
    needed.add(room_of[start])
    inst.necessary = sorted(needed)
    return inst


# --------------------------------------------------------------------------- event streams

EVENT_KINDS = ("move", "move-goal", "receptacle", "door", "agent", "add", "remove", "goal", "plan")


class SceneGraphEvents:
    """Seeded scene events for a scene-graph problem, as ``watch`` reads them (dictionaries).

    It follows the scene itself (where each item is, which receptacles and
    doors are open, the goal), so every event it makes is valid when the
    events are applied in order.  :meth:`make` gives the events of one kind:

    * ``move``: an item the goal does not name is taken out of its receptacle
      and put into another (two events: ``unset``, then ``set``; with
      ``new_place_first``, ``set`` then ``unset``, as perception may report it);
    * ``move-goal``: the same for an item the goal names, seen in its new
      receptacle before it is gone from the old one;
    * ``receptacle`` / ``door``: an openable receptacle or a door is opened
      or closed (``set`` the new state, then ``unset`` the old one); ``among``
      chooses from the given objects when it names some of that kind;
    * ``agent``: the agent is seen at another place (then no longer at the old one);

    What the goal needs is seen in its new state before its old state goes:
    between the two events the goal stays reachable (a goal item in no
    receptacle, a door neither open nor closed, would make it unreachable
    until the second event, and the reachability repair searches the whole
    scene before it says so).
    * ``add``: a new item in some receptacle; ``remove``: an item the goal
      does not name leaves the scene;
    * ``goal``: a new goal, one to three items into other receptacles;
    * ``plan``: a plan request.
    """

    def __init__(
        self,
        objects: Mapping[str, str],
        facts: Iterable[tuple],
        goal: Iterable[tuple],
        rng: random.Random,
        *,
        new_place_first: bool = False,
    ):
        self.rng = rng
        self.new_place_first = new_place_first  # a move seen in the new receptacle before it leaves the old
        self.items = sorted(name for name, kind in objects.items() if kind == "item")
        self.places = sorted(name for name, kind in objects.items() if kind == "place")
        self.agent_at: dict[str, str] = {}
        self.receptacles = sorted(name for name, kind in objects.items() if kind == "receptacle")
        self.doors = sorted(name for name, kind in objects.items() if kind == "door")
        self.holder: dict[str, str] = {}
        self.openable: set[str] = set()
        self.open: set[str] = set()
        for fact in facts:
            if fact[0] == "in":
                self.holder[fact[1]] = fact[2]
            elif fact[0] == "openable":
                self.openable.add(fact[1])
            elif fact[0] in ("opened", "door-open"):
                self.open.add(fact[1])
            elif fact[0] == "agent-at":
                self.agent_at[fact[1]] = fact[2]
        self.goal_items = sorted({atom[1] for atom in goal if atom[0] == "in"})
        self.added = 0

    def make(self, kind: str, among: Iterable[str] = ()) -> list[dict]:
        """The events of one change of ``kind`` (one of ``EVENT_KINDS``)."""
        rng = self.rng
        if kind in ("move", "move-goal", "remove"):
            goal = set(self.goal_items)
            pool = [i for i in self.items if (i in goal) == (kind == "move-goal") and i in self.holder]
            item = rng.choice(pool)
            if kind == "remove":
                self.items.remove(item)
                del self.holder[item]
                return [{"event": "remove", "object": item}]
            there = rng.choice([r for r in self.receptacles if r != self.holder[item]])
            events = [_fact("unset", "in", item, self.holder[item]), _fact("set", "in", item, there)]
            self.holder[item] = there
            return events[::-1] if kind == "move-goal" or self.new_place_first else events
        if kind in ("receptacle", "door"):
            return self._toggle(kind, set(among))
        if kind == "agent":
            agent = rng.choice(sorted(self.agent_at))
            there = rng.choice([p for p in self.places if p != self.agent_at[agent]])
            events = [_fact("set", "agent-at", agent, there), _fact("unset", "agent-at", agent, self.agent_at[agent])]
            self.agent_at[agent] = there
            return events
        if kind == "add":
            self.added += 1
            name = f"{rng.choice(ITEM_KINDS)}_new_{self.added}"
            self.items.append(name)
            self.holder[name] = rng.choice(self.receptacles)
            return [{"event": "add", "object": name, "type": "item", "facts": [["in", name, self.holder[name]]]}]
        if kind == "goal":
            return [{"event": "goal", "goal": self._goal()}]
        if kind == "plan":
            return [{"event": "plan"}]
        raise ValueError(f"unknown kind of scene event {kind!r} (expected one of: {', '.join(EVENT_KINDS)})")

    def _toggle(self, kind: str, among: set[str]) -> list[dict]:
        pool = sorted(self.openable) if kind == "receptacle" else self.doors
        chosen = [name for name in pool if name in among] or pool
        name = self.rng.choice(chosen)
        opened, closed = ("opened", "closed") if kind == "receptacle" else ("door-open", "door-closed")
        old, new = (opened, closed) if name in self.open else (closed, opened)
        (self.open.discard if name in self.open else self.open.add)(name)
        return [_fact("set", new, name), _fact("unset", old, name)]

    def _goal(self) -> str:
        rng = self.rng
        chosen = rng.sample([i for i in self.items if i in self.holder], rng.randint(1, 3))
        atoms = [(item, rng.choice([r for r in self.receptacles if r != self.holder[item]])) for item in chosen]
        self.goal_items = sorted(chosen)
        return "(and " + " ".join(f"(in {item} {target})" for item, target in atoms) + ")"


def _fact(event: str, *fact: str) -> dict:
    return {"event": event, "fact": list(fact)}
