"""Problems padded with objects the goal does not need.

Blocksworld with extra towers and blocks stacked on the goal's blocks, and
gripper with extra balls, as PDDL text: the smallest worlds on which pruning
without a knowledge model (the goal scorer) pays off on domains we did not
design.  An IPC driverlog-with-time instance with extra locations, trucks,
drivers and packages: where a temporal planner that cannot prove a pruned
problem unsolvable meets many interchangeable objects.  :func:`pad_with_clones`
pads any parsed problem (an IPC one, say) by cloning objects the goal does
not name, with all their initial facts.  The benchmarks and the tests build
their padded problems here.
"""

from __future__ import annotations

import random
from collections.abc import Iterable
from dataclasses import replace

from relevance_plan.data import DOMAINS_DIR
from relevance_plan.errors import UsageError
from relevance_plan.io import read_text
from relevance_plan.pddl.formulas import GroundAtom, numeric_effects
from relevance_plan.pddl.model import Domain, Problem, TimedLiteral, frozen, pinned_objects
from relevance_plan.relevance.analysis.types import static_predicates

# The shipped typed domains the padded problems are written for (package data, read once).
BLOCKSWORLD_DOMAIN = read_text(DOMAINS_DIR / "blocksworld-typed" / "domain.pddl", "domain file")
GRIPPER_DOMAIN = read_text(DOMAINS_DIR / "gripper-typed" / "domain.pddl", "domain file")


def blocksworld_problem(extra: int, seed: int = 0, in_the_way: int = 2) -> str:
    """Goal: a on b on c.  ``in_the_way`` extra blocks sit on a; the rest form random towers."""
    rng = random.Random(seed)
    goal_blocks = ["a", "b", "c"]
    extras = [f"x{i}" for i in range(1, extra + 1)]
    init = ["(handempty)"]
    for block in ("b", "c"):
        init += [f"(ontable {block})", f"(clear {block})"]
    pile = ["a"] + extras[:in_the_way]
    init.append("(ontable a)")
    for lower, upper in zip(pile, pile[1:]):
        init.append(f"(on {upper} {lower})")
    init.append(f"(clear {pile[-1]})")
    rest = extras[in_the_way:]
    rng.shuffle(rest)
    towers = [rest[i : i + 4] for i in range(0, len(rest), 4)]
    for tower in towers:
        init.append(f"(ontable {tower[0]})")
        for lower, upper in zip(tower, tower[1:]):
            init.append(f"(on {upper} {lower})")
        init.append(f"(clear {tower[-1]})")
    objects = " ".join(goal_blocks + extras)
    return (
        f"(define (problem bw-{extra}-{seed}) (:domain blocksworld-typed)\n"
        f"  (:objects {objects} - block)\n"
        "  (:init " + "\n    ".join(init) + ")\n"
        "  (:goal (and (on a b) (on b c))))\n"
    )


def gripper_problem(extra: int, rooms: int = 6) -> str:
    """Goal: two balls to room r2; ``extra`` other balls scattered over the rooms."""
    room_names = [f"r{i}" for i in range(1, rooms + 1)]
    balls = ["ball1", "ball2"] + [f"extra{i}" for i in range(1, extra + 1)]
    init = ["(at-robby r1)", "(free left)", "(free right)"]
    for index, ball in enumerate(balls):
        init.append(f"(at {ball} {room_names[index % rooms] if index >= 2 else 'r1'})")
    return (
        f"(define (problem gripper-{extra}) (:domain gripper-typed)\n"
        f"  (:objects {' '.join(room_names)} - room {' '.join(balls)} - ball left right - gripper)\n"
        "  (:init " + " ".join(init) + ")\n"
        "  (:goal (and (at ball1 r2) (at ball2 r2))))\n"
    )


DRIVERLOG_CITIES = ("s0", "s1", "s2")


def padded_driverlog(text: str, extra: int, seed: int = 1) -> str:
    """IPC 2002 driverlog (with time) instance 3, as written in the corpus, with ``extra`` objects
    of each kind the goal does not need: locations (each linked by road and path to a place
    already there), trucks, drivers and packages at the instance's cities."""
    rng = random.Random(seed)
    objects, facts = [], []
    places = list(DRIVERLOG_CITIES)
    for i in range(1, extra + 1):
        location, truck, driver, package = f"xloc{i}", f"xtruck{i}", f"xdriver{i}", f"xobj{i}"
        objects += [f"{location} - location", f"{truck} - truck", f"{driver} - driver", f"{package} - obj"]
        other = rng.choice(places)
        minutes = rng.randint(10, 90)
        for a, b in ((location, other), (other, location)):
            facts += [f"(link {a} {b})", f"(= (time-to-drive {a} {b}) {minutes})"]
            facts += [f"(path {a} {b})", f"(= (time-to-walk {a} {b}) {minutes * 3})"]
        places.append(location)
        facts += [f"(at {truck} {rng.choice(DRIVERLOG_CITIES)})", f"(empty {truck})"]
        facts += [f"(at {driver} {rng.choice(DRIVERLOG_CITIES)})", f"(at {package} {rng.choice(DRIVERLOG_CITIES)})"]
    text = text.replace("\t)\n\t(:init", "\t" + "\n\t".join(objects) + "\n\t)\n\t(:init", 1)
    return text.replace("\t(:init\n", "\t(:init\n\t" + "\n\t".join(facts) + "\n", 1)


# --------------------------------------------------------------------------- any problem, padded with clones

CLONE_MARK = "-pad"  # a clone's name: its source's, this mark and a number


def pad_with_clones(domain: Domain, problem: Problem, extra: int, seed: int = 0) -> Problem:
    """``problem`` with ``extra`` more objects, each a clone of an object the goal does not need.

    Sources are the problem's objects that the goal, the constraints and the
    metric do not name (domain constants are never objects of the problem).
    The clones go round robin over the sources' types, in the order the
    problem first declares them, so that every kind of object gets copies;
    within a type, the sources come in an order shuffled by ``seed``, one
    after the other.  A clone has a fresh name and its source's type.  Of the
    initial facts and numeric values that mention the source, it gets, with
    itself in the source's place (every occurrence):

    - those of static predicates and functions (that no action and no timed
      literal changes): a clone of a location has its roads and distances;
    - of the others (the state), those whose first argument is the source: a
      clone of a truck stands where the truck stands and has its fuel, but
      what stands at a cloned location is not copied, so that no object of
      the problem is in two places.  Timed literals follow the same rule.

    The goal, constraints and metric are unchanged.  The result has no
    source text: write it with ``pddl.formatter.format_problem``.

    ``UsageError`` when ``extra`` is negative, or when it is positive and no
    object can be cloned (every object is named by the goal, or there is none).
    """
    if extra < 0:
        raise UsageError(f"the number of clones must be at least 0, got {extra}")
    if extra == 0:
        return problem
    pinned = pinned_objects(problem, domain)
    by_type: dict[str, list[str]] = {}
    for name, type_name in problem.objects.items():
        if name not in pinned:
            by_type.setdefault(type_name, []).append(name)
    if not by_type:
        why = "it declares no object" if not problem.objects else "the goal names every object it declares"
        raise UsageError(f"cannot pad problem '{problem.name}' with clones: {why}", path=problem.path)
    rng = random.Random(seed)
    for names in by_type.values():
        rng.shuffle(names)
    types = list(by_type)
    taken = _taken_names(domain, problem)
    clones: dict[str, str] = {}  # clone -> source, in the order made
    for index in range(extra):
        names = by_type[types[index % len(types)]]
        source = names[(index // len(types)) % len(names)]
        clones[_fresh_name(source, taken)] = source
    return _with_clones(problem, clones, _changing(domain, problem))


def _changing(domain: Domain, problem: Problem) -> frozenset[str]:
    """Predicates and functions whose values change: set by an action, a derived rule or a timed literal."""
    changing = set(domain.predicates) - static_predicates(domain)
    for action in domain.actions:
        changing.update(effect.fluent.function for effect, *_ in numeric_effects(action.effect))
    for literal in problem.timed_literals:
        term = literal.atom if literal.atom is not None else literal.fluent
        if term is not None:
            changing.add(term[0])
    return frozenset(changing)


def _copied(term: tuple[str, ...], source: str, changing: frozenset[str]) -> bool:
    """Whether a clone of ``source`` gets this fact, value or timed literal (see :func:`pad_with_clones`)."""
    return term[0] not in changing or (len(term) > 1 and term[1] == source)


def _taken_names(domain: Domain, problem: Problem) -> set[str]:
    """Names a clone must not take: objects, constants, and every name the domain defines (some
    readers refuse an object named like a predicate)."""
    taken = set(problem.objects) | set(domain.constants) | set(domain.types)
    taken |= set(domain.predicates) | set(domain.functions) | {action.name for action in domain.actions}
    return taken


def _fresh_name(source: str, taken: set[str]) -> str:
    number = 1
    while f"{source}{CLONE_MARK}{number}" in taken:
        number += 1
    name = f"{source}{CLONE_MARK}{number}"
    taken.add(name)
    return name


def _swap(atom: GroundAtom, source: str, clone: str) -> GroundAtom:
    return (atom[0], *(clone if arg == source else arg for arg in atom[1:]))


def _mentioning(atoms: Iterable[GroundAtom]) -> dict[str, list[GroundAtom]]:
    """Object name -> the atoms (in the order given) whose arguments name it."""
    index: dict[str, list[GroundAtom]] = {}
    for atom in atoms:
        for name in dict.fromkeys(atom[1:]):
            index.setdefault(name, []).append(atom)
    return index


def _with_clones(problem: Problem, clones: dict[str, str], changing: frozenset[str]) -> Problem:
    """``problem`` with each clone declared and given its source's initial facts and values."""
    facts = list(problem.facts_in_order())
    fact_index = _mentioning(facts)
    numeric_index = _mentioning(problem.numeric_init)
    timed_index: dict[str, list[TimedLiteral]] = {}
    for literal in problem.timed_literals:
        term = literal.atom if literal.atom is not None else literal.fluent
        for name in dict.fromkeys(term[1:] if term is not None else ()):
            timed_index.setdefault(name, []).append(literal)
    objects = dict(problem.objects)
    display = dict(problem.spelling.objects)
    order = {atom: number for number, atom in enumerate(facts)}
    numeric = dict(problem.numeric_init)
    timed = list(problem.timed_literals)
    for clone, source in clones.items():
        objects[clone] = problem.objects[source]
        display[clone] = problem.display(source) + clone[len(source) :]
        for atom in fact_index.get(source, ()):
            if _copied(atom, source, changing):
                order.setdefault(_swap(atom, source, clone), len(order))
        for term in numeric_index.get(source, ()):
            if _copied(term, source, changing):
                numeric[_swap(term, source, clone)] = problem.numeric_init[term]
        for literal in timed_index.get(source, ()):
            if literal.atom is not None and _copied(literal.atom, source, changing):
                timed.append(replace(literal, atom=_swap(literal.atom, source, clone)))
            elif literal.fluent is not None and _copied(literal.fluent, source, changing):
                timed.append(replace(literal, fluent=_swap(literal.fluent, source, clone)))
    return replace(
        problem,
        objects=frozen(objects),
        init=frozenset(order),
        text="",
        path=None,
        spelling=problem.spelling.with_objects(frozen(display)),
        numeric_init=frozen(numeric),
        timed_literals=tuple(timed),
        object_groups=(),
        init_spans=(),
        init_order=frozen(order),
    )
