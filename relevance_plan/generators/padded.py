"""Problems padded with objects the goal does not need, as PDDL text.

Blocksworld with extra towers and blocks stacked on the goal's blocks, and
gripper with extra balls: the smallest worlds on which pruning without a
knowledge model (the goal scorer) pays off on domains we did not design.
And an IPC driverlog-with-time instance with extra locations, trucks, drivers
and packages: where a temporal planner that cannot prove a pruned problem
unsolvable meets many interchangeable objects.  The benchmarks and the tests
build their padded problems here.
"""

from __future__ import annotations

import random

BLOCKSWORLD_DOMAIN = """(define (domain blocksworld)
  (:requirements :strips :typing)
  (:types block)
  (:predicates (on ?x - block ?y - block) (ontable ?x - block) (clear ?x - block)
               (handempty) (holding ?x - block))
  (:action pick-up
    :parameters (?x - block)
    :precondition (and (clear ?x) (ontable ?x) (handempty))
    :effect (and (not (ontable ?x)) (not (clear ?x)) (not (handempty)) (holding ?x)))
  (:action put-down
    :parameters (?x - block)
    :precondition (holding ?x)
    :effect (and (not (holding ?x)) (clear ?x) (handempty) (ontable ?x)))
  (:action stack
    :parameters (?x - block ?y - block)
    :precondition (and (holding ?x) (clear ?y))
    :effect (and (not (holding ?x)) (not (clear ?y)) (clear ?x) (handempty) (on ?x ?y)))
  (:action unstack
    :parameters (?x - block ?y - block)
    :precondition (and (on ?x ?y) (clear ?x) (handempty))
    :effect (and (holding ?x) (clear ?y) (not (clear ?x)) (not (handempty)) (not (on ?x ?y)))))
"""


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
        f"(define (problem bw-{extra}-{seed}) (:domain blocksworld)\n"
        f"  (:objects {objects} - block)\n"
        "  (:init " + "\n    ".join(init) + ")\n"
        "  (:goal (and (on a b) (on b c))))\n"
    )


GRIPPER_DOMAIN = """(define (domain gripper-typed)
  (:requirements :strips :typing)
  (:types room ball gripper)
  (:predicates (at-robby ?r - room) (at ?b - ball ?r - room) (free ?g - gripper)
               (carry ?o - ball ?g - gripper))
  (:action move
    :parameters (?from ?to - room)
    :precondition (at-robby ?from)
    :effect (and (at-robby ?to) (not (at-robby ?from))))
  (:action pick
    :parameters (?obj - ball ?room - room ?g - gripper)
    :precondition (and (at ?obj ?room) (at-robby ?room) (free ?g))
    :effect (and (carry ?obj ?g) (not (at ?obj ?room)) (not (free ?g))))
  (:action drop
    :parameters (?obj - ball ?room - room ?g - gripper)
    :precondition (and (carry ?obj ?g) (at-robby ?room))
    :effect (and (at ?obj ?room) (free ?g) (not (carry ?obj ?g)))))
"""


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
