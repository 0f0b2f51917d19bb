"""Many-goal forms of two classic worlds: the goal names many objects, the task needs few vehicles.

``logistics-manygoals``
    Every package is in the goal (each to a location in another city) and
    there are many airplanes (a quarter of the objects) and 1-3 trucks per
    city.  One airplane can carry every package, and one truck per city
    serves that city: a sufficient set holds every package, its start and
    target locations, their cities and airports, the first truck of each
    such city with its location, and ONE airplane with its airport.
``miconic-manygoals``
    A tenth of the passengers must be served; a sufficient set holds them,
    their floors and the lift's floor.

Both use the classic domains (``logistics``, ``miconic`` and their
``-typed`` forms), so a problem is written as the classic world's.
"""

from __future__ import annotations

import random

from relevance_plan.generators.classic import Instance, logistics_map, miconic_building


def build_logistics_manygoals(rng: random.Random, size: int) -> Instance:
    inst = Instance()
    packages_count = max(3, size // 6)
    airplanes_count = max(3, size // 4)
    cities_count = max(2, (size - packages_count - airplanes_count) // 6)
    city_locations, airport_of, trucks_in, truck_at = logistics_map(rng, inst, cities_count)
    airports = list(airport_of.values())
    airplanes = [inst.add("airplane", f"plane{a}") for a in range(1, airplanes_count + 1)]
    plane_at = {plane: rng.choice(airports) for plane in airplanes}
    inst.facts += [("at", plane, plane_at[plane]) for plane in airplanes]
    cities = list(city_locations)
    city_of = {location: city for city, locations in city_locations.items() for location in locations}
    needed = {airplanes[0], plane_at[airplanes[0]], city_of[plane_at[airplanes[0]]]}
    for p in range(1, packages_count + 1):
        package = inst.add("package", f"pkg{p}")
        start = rng.choice(city_locations[rng.choice(cities)])
        inst.facts.append(("at", package, start))
        target_city = rng.choice([c for c in cities if c != city_of[start]])
        target = rng.choice(city_locations[target_city])
        inst.goal.append(("at", package, target))
        needed.add(package)
        for city, location in ((city_of[start], start), (target_city, target)):
            truck = trucks_in[city][0]
            needed.update({city, location, airport_of[city], truck, truck_at[truck]})
    inst.necessary = sorted(needed)
    return inst


def build_miconic_manygoals(rng: random.Random, size: int) -> Instance:
    inst, lift, trips = miconic_building(rng, size, 10)
    passengers = list(trips)
    needed = {lift}
    for person in rng.sample(passengers, max(2, len(passengers) // 10)):
        inst.goal.append(("served", person))
        needed.update({person, *trips[person]})
    inst.necessary = sorted(needed)
    return inst
