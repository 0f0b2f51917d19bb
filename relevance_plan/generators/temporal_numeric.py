"""Seeded many-object temporal and numeric worlds in the style of two IPC domains, written for this project.

``driverlog-temporal``
    Road locations on a plane, linked to their nearest neighbours (and
    joined into one network); some roads have a footpath location between
    their ends, the others can be walked directly.  Trucks and drivers stand
    at road locations; driving takes ``(drive-time a b)``, walking
    ``(walk-time a b)``, both from the distance.  The goal moves 2-3
    packages.  A sufficient set: the goal packages, one truck with a driver
    placed at it, and the road locations on shortest routes from the truck
    through each package's start and target.
``zenotravel-numeric``
    Cities on a plane with a distance for every pair; aircraft with fuel,
    a capacity of at least one slow flight between the farthest two
    cities, slow and fast burn rates and a zoom limit; ``(:metric minimize
    (total-fuel-used))``.  The goal moves 2-4 people.  A sufficient set: the
    goal people, their start and target cities, one aircraft and its city
    (it can refuel anywhere, so it can fly anywhere).

Each builder takes ``(rng, size)`` and returns a classic ``Instance`` whose
``values`` hold the numeric initial values.
"""

from __future__ import annotations

import math
import random

from relevance_plan.generators.classic import Instance
from relevance_plan.generators.graphs import geometric_graph, random_points, route
from relevance_plan.pddl import formulas as f
from relevance_plan.pddl.model import Metric

MAP_SIDE = 100.0


def build_driverlog_temporal(rng: random.Random, size: int) -> Instance:
    inst = Instance()
    roads_count = max(4, size // 5)
    vehicles = max(2, size // 30)
    names = [inst.add("location", f"s{i}") for i in range(1, roads_count + 1)]
    points = random_points(rng, names, MAP_SIDE)
    roads = geometric_graph(points, 2)
    walks: dict[str, list[str]] = {}
    footpaths = 0
    for a in names:
        for b in roads[a]:
            inst.facts.append(("road", a, b))
            inst.values[("drive-time", a, b)] = max(1, math.ceil(math.dist(points[a], points[b]) / 10))
            if a > b:
                continue
            ends = [a, b]
            if rng.random() < 0.5:  # a footpath location halfway
                footpaths += 1
                middle = inst.add("location", f"p{footpaths}")
                points[middle] = ((points[a][0] + points[b][0]) / 2, (points[a][1] + points[b][1]) / 2)
                ends = [a, middle, b]
            for x, y in zip(ends, ends[1:]):
                for u, v in ((x, y), (y, x)):
                    walks.setdefault(u, []).append(v)
    for a in walks:
        for b in walks[a]:
            inst.facts.append(("path", a, b))
            inst.values[("walk-time", a, b)] = max(1, math.ceil(3 * math.dist(points[a], points[b]) / 10))
    trucks = [inst.add("truck", f"truck{i}") for i in range(1, vehicles + 1)]
    drivers = [inst.add("driver", f"driver{i}") for i in range(1, vehicles + 1)]
    truck_at = {truck: rng.choice(names) for truck in trucks}
    for truck in trucks:
        inst.facts += [("at", truck, truck_at[truck]), ("empty", truck)]
    for position, driver in enumerate(drivers):
        # The first driver starts at the first truck: a sufficient set needs no walk.
        inst.facts.append(("at", driver, truck_at[trucks[0]] if position == 0 else rng.choice(names)))
    packages = [inst.add("package", f"pkg{i}") for i in range(1, max(3, size - len(inst.objects)) + 1)]
    where = {package: rng.choice(names) for package in packages}
    inst.facts += [("at", package, where[package]) for package in packages]
    stops = [truck_at[trucks[0]]]
    for package in rng.sample(packages, rng.randint(2, 3)):
        target = rng.choice([n for n in names if n != where[package]])
        inst.goal.append(("at", package, target))
        stops += [where[package], target]
    goal_packages = [atom[1] for atom in inst.goal]
    inst.necessary = sorted({*goal_packages, trucks[0], drivers[0], *route(roads, stops)})
    return inst


def build_zenotravel_numeric(rng: random.Random, size: int) -> Instance:
    inst = Instance()
    cities = [inst.add("city", f"city{i}") for i in range(1, max(3, size // 5) + 1)]
    points = random_points(rng, cities, 10 * MAP_SIDE)
    for a in cities:
        for b in cities:
            if a != b:
                inst.values[("distance", a, b)] = max(1, round(math.dist(points[a], points[b])))
    longest = max(inst.values.values())
    aircraft = [inst.add("aircraft", f"plane{i}") for i in range(1, max(2, size // 25) + 1)]
    plane_at = {}
    for plane in aircraft:
        slow = rng.randint(1, 4)
        capacity = math.ceil(longest * slow * rng.uniform(1.0, 2.5))
        plane_at[plane] = rng.choice(cities)
        inst.facts.append(("at", plane, plane_at[plane]))
        inst.values.update(
            {
                ("slow-burn", plane): slow,
                ("fast-burn", plane): slow * rng.randint(2, 3),
                ("capacity", plane): capacity,
                ("fuel", plane): rng.randint(0, capacity),
                ("onboard", plane): 0,
                ("zoom-limit", plane): rng.randint(1, 6),
            }
        )
    inst.values[("total-fuel-used",)] = 0
    inst.metric = Metric("minimize", f.Fluent("total-fuel-used"))
    people = [inst.add("person", f"person{i}") for i in range(1, max(4, size - len(inst.objects)) + 1)]
    where = {person: rng.choice(cities) for person in people}
    inst.facts += [("at", person, where[person]) for person in people]
    needed = {aircraft[0], plane_at[aircraft[0]]}
    for person in rng.sample(people, rng.randint(2, 4)):
        target = rng.choice([c for c in cities if c != where[person]])
        inst.goal.append(("at", person, target))
        needed.update({person, where[person], target})
    inst.necessary = sorted(needed)
    return inst
