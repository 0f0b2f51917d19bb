"""Small class-goal worlds for the witness proof's tests: domains and a seeded problem generator.

The domains have the shape of Taskography's lifted rearrangement: items and
receptacles have classes, ``(rel vase shelf)`` holds once any vase is in any
shelf, putting an item in adds the relation of the classes and taking it out
deletes it.  Each variant changes one thing the proof must get right (a
second goal predicate added by the same action, subtypes, ``either``,
constants, derived goals, conditional or quantified effects, a way out that
keeps the relation ...); the generator builds problems around them (items
and receptacles of two classes now and then, an item of type ``object``)
with goals written
in every way the proof must read alike (an atom twice, in capitals, inside a
second ``and``) or must not count (true initially, under ``or``, ``not``, an
existential).
"""

from __future__ import annotations

import random
from dataclasses import dataclass

REQUIREMENTS = (
    ":typing :negative-preconditions :disjunctive-preconditions :existential-preconditions"
    " :universal-preconditions :conditional-effects :derived-predicates :equality"
)

BASE = """(define (domain rearrange-{name})
  (:requirements {requirements})
  (:types agent room receptacle rclass iclass item {subtypes})
  {constants}
  (:predicates (at ?a - agent ?r - room) (connected ?x - room ?y - room) (itemin ?i - item ?r - room)
               (recin ?c - receptacle ?r - room) (in ?i - item ?c - receptacle) (inany ?i - item)
               (holds ?a - agent ?i - item) (holdsany ?a - agent) (itemclass ?i - item ?k - iclass)
               (recclass ?c - receptacle ?l - rclass) (rel ?k - iclass ?l - rclass)
               (fragile ?i - item) (padded ?c - receptacle) (sticky ?c - receptacle) (open ?c - receptacle)
               {predicates})
  {derived}
  (:action go :parameters (?a - agent ?from - room ?to - room)
    :precondition (and (at ?a ?from) (connected ?from ?to))
    :effect (and (at ?a ?to) (not (at ?a ?from))))
  (:action pick :parameters (?a - agent ?i - item ?r - room)
    :precondition (and (at ?a ?r) (itemin ?i ?r) (not (inany ?i)) (not (holdsany ?a)))
    :effect (and (holds ?a ?i) (holdsany ?a) (not (itemin ?i ?r))))
  (:action pickoff :parameters (?a - agent ?i - item ?k - iclass ?c - receptacle ?l - rclass ?r - room)
    :precondition (and (at ?a ?r) (itemin ?i ?r) (in ?i ?c) (itemclass ?i ?k) (recclass ?c ?l)
                       (not (holdsany ?a)))
    :effect (and (holds ?a ?i) (holdsany ?a) (not (itemin ?i ?r)) (not (in ?i ?c)) (not (inany ?i)) {forget}))
  (:action put :parameters (?a - agent ?i - {put_item} ?k - iclass ?c - receptacle ?l - rclass ?r - room)
    :precondition (and (at ?a ?r) (recin ?c ?r) (holds ?a ?i) (itemclass ?i ?k) (recclass ?c ?l) {put_condition})
    :effect (and (in ?i ?c) (inany ?i) (itemin ?i ?r) {relate} (not (holds ?a ?i)) (not (holdsany ?a))))
  {actions})
"""

LIFT = """(:action lift :parameters (?a - agent ?i - item ?c - receptacle ?r - room)
    :precondition (and (at ?a ?r) (itemin ?i ?r) (in ?i ?c) (not (holdsany ?a)))
    :effect (and (holds ?a ?i) (holdsany ?a) (not (itemin ?i ?r)) (not (in ?i ?c)) (not (inany ?i))))"""
TRANSFER = """(:action transfer
    :parameters (?a - agent ?i - item ?k - iclass ?c1 - receptacle ?l1 - rclass ?c2 - receptacle ?l2 - rclass ?r - room)
    :precondition (and (at ?a ?r) (itemin ?i ?r) (recin ?c2 ?r) (in ?i ?c1) (itemclass ?i ?k) (recclass ?c1 ?l1)
                       (recclass ?c2 ?l2))
    :effect (and (not (in ?i ?c1)) (in ?i ?c2) (rel ?k ?l2) {forget}))"""
DISPLAY = """(:action display
    :parameters (?a - agent ?i - item ?k - iclass ?c - receptacle ?l1 - rclass ?l2 - rclass ?r - room)
    :precondition (and (at ?a ?r) (recin ?c ?r) (holds ?a ?i) (itemclass ?i ?k) (recclass ?c ?l1) (recclass ?c ?l2))
    :effect (and (in ?i ?c) (inany ?i) (itemin ?i ?r) (rel ?k ?l1) (rel ?k ?l2) (not (holds ?a ?i))
                 (not (holdsany ?a))))"""
SWAP = """(:action swap :parameters (?a - agent ?i1 - item ?i2 - item ?c - receptacle ?r - room)
    :precondition (and (at ?a ?r) (recin ?c ?r) (holds ?a ?i1) (in ?i2 ?c))
    :effect (and (in ?i1 ?c) (inany ?i1) (itemin ?i1 ?r) (not (holds ?a ?i1))
                 (holds ?a ?i2) (not (in ?i2 ?c)) (not (inany ?i2)) (not (itemin ?i2 ?r))))"""

DEFAULTS = {
    "requirements": REQUIREMENTS,
    "subtypes": "",
    "constants": "",
    "predicates": "",
    "derived": "",
    "forget": "(not (rel ?k ?l))",
    "put_item": "item",
    "put_condition": "",
    "relate": "(rel ?k ?l)",
    "actions": "",
}

# variant -> what it changes in BASE
VARIANTS: dict[str, dict[str, str]] = {
    "plain": {},
    "no-typing-requirement": {"requirements": ":strips :negative-preconditions"},
    "subtypes": {"subtypes": "light heavy - item", "put_item": "light"},
    "either": {"subtypes": "light heavy - item", "put_item": "(either light heavy)"},
    "class-constants": {"constants": "(:constants vase cup - iclass shelf table - rclass)"},
    "item-constant": {"constants": "(:constants spare - item)"},
    "derived-goal": {
        "predicates": "(tidy ?k - iclass)",
        "derived": "(:derived (tidy ?k - iclass) (exists (?l - rclass) (rel ?k ?l)))",
    },
    "two-predicates": {
        "predicates": "(near ?k - iclass ?l - rclass)",
        "relate": "(rel ?k ?l) (near ?k ?l)",
        "forget": "(not (rel ?k ?l)) (not (near ?k ?l))",
    },
    "or-condition": {"put_condition": "(or (fragile ?i) (padded ?c))"},
    "lift-keeps-relation": {"actions": LIFT},
    "conditional-forget": {"forget": "(when (not (sticky ?c)) (not (rel ?k ?l)))"},
    "conditional-relate": {"relate": "(when (open ?c) (rel ?k ?l))"},
    "forall-relate": {"relate": "(forall (?m - rclass) (when (recclass ?c ?m) (rel ?k ?m)))"},
    "relate-twice": {"actions": DISPLAY},
    "forall-forget": {"forget": "(forall (?m - rclass) (when (recclass ?c ?m) (not (rel ?k ?m))))"},
    "swap-two-items": {"actions": SWAP},
    "transfer-keeps": {"actions": TRANSFER.format(forget="")},
    "transfer-forgets": {"actions": TRANSFER.format(forget="(not (rel ?k ?l1))")},
}
# the proof must give no verdict on these: it cannot read their types, an adder of the goal predicate adds
# it under a condition, through forall or twice, an item is a constant, or an action may bind one item to two
# parameters
REFUSED = frozenset(
    {"either", "conditional-relate", "forall-relate", "relate-twice", "item-constant", "swap-two-items"}
)
GOAL_STYLES = ("distinct", "twice", "capitals", "nested-and", "true-initially", "or", "not", "exists")
ITEM_CLASSES = ("vase", "cup")
RECEPTACLE_CLASSES = ("shelf", "table")


def domain_text(variant: str) -> str:
    return BASE.format(name=variant, **{**DEFAULTS, **VARIANTS[variant]})


@dataclass(frozen=True)
class World:
    """One generated problem: its variant, goal style and the two files' text."""

    variant: str
    style: str
    domain: str
    problem: str

    @property
    def name(self) -> str:
        return f"{self.variant}/{self.style}"


def generate(variant: str, seed: int) -> World:
    """A small problem of ``variant`` (two rooms, a few receptacles and items), its goal in a style
    chosen by ``seed``."""
    rng = random.Random(f"{variant}:{seed}")
    items_of = [cls for cls in ITEM_CLASSES if cls == "vase" or rng.random() < 0.5]
    receptacles = [
        (f"{cls}{n}", cls, rng.choice(("r0", "r1"))) for cls in RECEPTACLE_CLASSES for n in range(rng.choice((1, 1, 2)))
    ]
    # mostly one or two items of a class: few enough for a goal of two or three atoms about it to be short
    items = [(f"{cls}{n}", cls) for cls in items_of for n in range(rng.choice((0, 1, 1, 1, 1, 2)))]
    init = ["(at robot r0)", "(connected r0 r1)", "(connected r1 r0)"]
    init += [f"(recin {name} {room}) (recclass {name} {cls})" for name, cls, room in receptacles]
    init += [f"({rng.choice(('padded', 'sticky', 'open'))} {name})" for name, _, _ in receptacles if rng.random() < 0.5]
    if variant == "item-constant":
        items.append(("spare", "vase"))
    if rng.random() < 0.15:  # a receptacle of two classes: which relation taking an item off deletes is open
        name, cls, _ = rng.choice(receptacles)
        init.append(f"(recclass {name} {'table' if cls == 'shelf' else 'shelf'})")
    for name, cls in items:
        init.append(f"(itemclass {name} {cls})")
        if rng.random() < 0.1:  # an item of two classes
            init.append(f"(itemclass {name} {'cup' if cls == 'vase' else 'vase'})")
        if rng.random() < 0.3:
            init.append(f"(fragile {name})")
        if rng.random() < 0.3:
            receptacle, rclass, room = rng.choice(receptacles)
            init.append(f"(in {name} {receptacle}) (inany {name}) (itemin {name} {room}) (rel {cls} {rclass})")
        else:
            init.append(f"(itemin {name} {rng.choice(('r0', 'r1'))})")
    style = rng.choice(GOAL_STYLES)
    goal, extra = _goal(variant, style, rng, receptacles, sorted({cls for _, cls in items}) or ["vase"])
    declared = [name for name, _ in items if name != "spare"]
    item_type = "item" if not VARIANTS[variant].get("subtypes") else None
    # now and then an item of type object: no action's item parameter takes it
    kinds = [rng.choice(("light", "light", "heavy")) if item_type is None else item_type for _ in declared]
    kinds = [kind if rng.random() > 0.1 else "object" for kind in kinds]
    objects = " ".join(f"{name} - {kind}" for name, kind in zip(declared, kinds))
    objects += " " + " ".join(f"{name} - receptacle" for name, _, _ in receptacles)
    if variant != "class-constants":
        objects += " vase cup - iclass shelf table - rclass"
    if rng.random() < 0.3:
        objects += " junk - object"
    problem = f"""(define (problem {variant}-{seed}) (:domain rearrange-{variant})
  (:objects robot - agent r0 r1 - room {objects})
  (:init {" ".join(init + extra)})
  (:goal {goal}))"""
    return World(variant, style, domain_text(variant), problem)


def _goal(variant: str, style: str, rng: random.Random, receptacles: list, present: list[str]) -> tuple[str, list[str]]:
    """The goal in ``style`` over a few atoms of the variant's goal predicates, mostly about classes
    the problem has items of (``present``); with facts the style adds to the initial state."""
    predicates = ["rel", "near"] if variant == "two-predicates" else ["rel"]
    classes = present if rng.random() < 0.85 else list(ITEM_CLASSES)
    if rng.random() < 0.5:
        classes = [rng.choice(classes)]  # every atom about one class: the shape of a shortfall
    pairs = [(p, k, l) for p in predicates for k in classes for l in RECEPTACLE_CLASSES]
    atoms = [f"({p} {k} {l})" for p, k, l in rng.sample(pairs, min(len(pairs), rng.choice((1, 2, 2, 2, 3))))]
    if variant == "derived-goal" and rng.random() < 0.5:
        atoms.append(f"(tidy {rng.choice(ITEM_CLASSES)})")
    extra: list[str] = []
    if style == "twice":
        atoms = atoms + atoms
    elif style == "capitals":
        atoms = atoms + [atom.upper() for atom in atoms]
    elif style == "nested-and":
        atoms = [*atoms, f"(and {' '.join(atoms)})"]
    elif style == "true-initially":
        extra.append(atoms[0])
    elif style == "or":
        atoms = [f"(or {atoms[0]} (rel cup table))", *atoms[1:]]
    elif style == "not":
        atoms.append("(not (rel cup shelf))")
    elif style == "exists":
        target = receptacles[0][0]
        atoms.append(f"(exists (?v - item) (and (itemclass ?v vase) (in ?v {target})))")
    return f"(and {' '.join(atoms)})", extra


def worlds(count_per_variant: int, first_seed: int = 0) -> list[World]:
    seeds = range(first_seed, first_seed + count_per_variant)
    return [generate(variant, seed) for variant in VARIANTS for seed in seeds]
