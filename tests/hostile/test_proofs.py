"""plan on goals written to trip the proof of unsolvability: a goal atom written twice, in capitals or
inside a second ``and`` is one atom, and one object may serve two goal predicates.  The tool must plan
them and print a plan valid on the original problem, never say "unsolvable" (exit 10) for them; where
the shortfall is real it still proves it, in one line."""

from __future__ import annotations

import re
from pathlib import Path

from support import REPO
from witness_worlds import domain_text

from hostile.inputs import every, one_line, says, silent, write
from hostile.scenario import PDDL, Scenario, scenario_test

UNSOLVABLE = 10
LIFTED = REPO / "benchmarks" / "corpus" / "taskography" / "lifted"
# a tiny lifted test problem with one laptop and one goal atom about laptops (Fast Downward solves it)
TASKOGRAPHY = ("taskographyv4tiny5.pddl", "taskographyv4tiny5_test/problem42.pddl")
PLAN = ("plan", "d.pddl", "p.pddl", "-q", "--plan-file", "out.plan")
SOLVED = every(silent, says("status:      solved", "valid on the original problem", where="stdout"))


def house(variant: str, goal: str, items: str = "vase0 - item") -> str:
    """A problem of the witness worlds' ``variant``: the robot, a shelf and a table, ``items`` on the floor."""
    names = [part for part in items.split() if part not in ("-", "item")]
    facts = " ".join(f"(itemin {name} r0) (itemclass {name} {name.rstrip('0123456789')})" for name in names)
    return f"""(define (problem p) (:domain rearrange-{variant})
  (:objects robot - agent r0 r1 - room shelf0 table0 - receptacle vase cup - iclass shelf table - rclass {items})
  (:init (at robot r0) (connected r0 r1) (connected r1 r0) (recin shelf0 r1) (recin table0 r0)
         (recclass shelf0 shelf) (recclass table0 table) {facts})
  (:goal (and {goal})))"""


def house_files(variant: str, goal: str, items: str = "vase0 - item"):
    def setup(work: Path) -> None:
        write(work, "d.pddl", domain_text(variant))
        write(work, "p.pddl", house(variant, goal, items))

    return setup


def taskography(rewrite):
    """The Taskography problem with its goal's atoms rewritten by ``rewrite`` (their text -> the new goal's)."""

    def setup(work: Path) -> None:
        domain, problem = (LIFTED / name for name in TASKOGRAPHY)
        write(work, "d.pddl", domain.read_text())
        text = problem.read_text()
        write(work, "original.pddl", text)
        found = re.search(r"\(:goal\s*\(and(.*?)\)\s*\)\s*\)\s*$", text, re.S)
        assert found is not None, "the corpus problem's goal is no conjunction"
        write(work, "p.pddl", text[: found.start()] + f"(:goal (and {rewrite(found.group(1))}))\n)\n")

    return setup


def in_capitals(atoms: str) -> str:
    return atoms + " " + atoms.upper()


SCENARIOS = [
    Scenario(
        "proofs/an-atom-twice",
        args=PLAN,
        setup=house_files("plain", "(rel vase shelf) (rel vase shelf)"),
        writes=("out.plan",),
        check=SOLVED,
        quick=True,
    ),
    Scenario(
        "proofs/an-atom-in-capitals",
        args=PLAN,
        setup=house_files("plain", "(rel vase shelf) (REL Vase SHELF)"),
        writes=("out.plan",),
        check=SOLVED,
        quick=True,
    ),
    Scenario(
        "proofs/an-atom-in-a-second-and",
        args=PLAN,
        setup=house_files("plain", "(rel vase shelf) (and (rel vase shelf))"),
        writes=("out.plan",),
        check=SOLVED,
    ),
    Scenario(
        "proofs/one-vase-for-two-goal-predicates",
        args=PLAN,
        setup=house_files("two-predicates", "(rel vase shelf) (near vase shelf)"),
        writes=("out.plan",),
        check=SOLVED,
        quick=True,
    ),
    Scenario(
        "proofs/taskography-every-goal-atom-twice",
        args=PLAN,
        setup=taskography(lambda atoms: atoms + atoms),
        writes=("out.plan",),
        check=SOLVED,
        quick=True,
    ),
    Scenario(
        "proofs/taskography-every-goal-atom-again-in-capitals",
        args=PLAN,
        setup=taskography(in_capitals),
        writes=("out.plan",),
        check=SOLVED,
    ),
    Scenario(
        "proofs/taskography-the-original-plan-is-valid-for-the-doubled-goal",
        shell="$TOOL plan d.pddl original.pddl -q --plan-file out.plan > /dev/null"
        " && $TOOL validate d.pddl p.pddl out.plan",
        setup=taskography(lambda atoms: f"{atoms} (and {atoms})"),
        writes=("out.plan",),
        check=every(silent, says("valid", where="stdout")),
    ),
    # a real shortfall is still proved before planning, and said in one line
    Scenario(
        "proofs/two-distinct-atoms-and-one-vase-are-proved-unsolvable",
        args=PLAN,
        setup=house_files("plain", "(rel vase shelf) (rel vase table) (rel vase table)"),
        codes=(UNSOLVABLE,),
        check=one_line("2 distinct goal atoms", "proved before planning"),
        quick=True,
    ),
    Scenario(
        "proofs/an-object-declared-twice-is-refused",
        args=PLAN,
        setup=house_files("plain", "(rel vase shelf) (rel vase table)", "vase0 - item vase0 - item"),
        codes=(PDDL,),
        check=one_line("declared twice"),
    ),
]

test_proofs = scenario_test(SCENARIOS)
