"""Planners that escape: detached, swarming, ignoring signals, stopping their guard; signals to the tool.

Each scenario runs twice: with the planners in a cgroup of their own (where
one can be made here) and without one (``RELEVANCE_PLAN_NO_CGROUP=1``).
"""

from __future__ import annotations

import dataclasses
import signal

from hostile.inputs import NO_CGROUP, PLAN_PURE, after, cgroup_usable, files, planner, suite
from hostile.scenario import INTERRUPTED, NO_VALID, PLANNER, TIME, Scenario, scenario_test

COMPARE = ("compare", "suite", "--methods", "pure", "--store", "s.sqlite", "-q")


def _watchdog_scenarios(tag: str, env: tuple) -> list[Scenario]:
    """Planners the watchdog must end at the deadline, or whose leftovers it must end."""
    return [
        *(
            Scenario(
                f"processes/{tag}/watchdog-{name[:-3]}",
                args=PLAN_PURE + ("--timeout", "2", "--planner", planner(name)),
                codes=(TIME,),
                timeout=2,
                env=env,
                quick=name == "detach.py",
            )
            for name in ("detach.py", "swarm.py", "chain.py", "ignore_term.py", "stop_guard.py")
        ),
        *(
            Scenario(
                f"processes/{tag}/{name}",
                args=PLAN_PURE + ("--timeout", "2", "--planner", template),
                codes=(TIME,),
                timeout=2,
                env=env,
            )
            for name, template in (
                ("timeout-wrapper", "cmd:timeout 100 {w}/planners/detach.py {domain} {problem}"),
                ("setsid-wrapper", "cmd:setsid {w}/planners/never.py {domain} {problem}"),
            )
        ),
        *(
            Scenario(
                f"processes/{tag}/{name}", args=PLAN_PURE + ("--planner", planner(script)), codes=(NO_VALID,), env=env
            )
            for name, script in (
                ("answers-and-leaves-a-daemon", "detach_and_answer.py"),
                ("closes-its-output-and-detaches", "close_and_detach.py"),
            )
        ),
    ]


WATCH = ("watch", "D.pddl", "P.pddl", "--events", "ev.jsonl")
SETUPS = {COMPARE: suite, WATCH: files(ev_dot_jsonl='{"event": "plan"}\n')}
# (name, the tool's arguments, the planner, the signal, seconds after the start, quick)
SIGNALS = (
    ("sigterm-to-the-tool", PLAN_PURE, "detach.py", signal.SIGTERM, 2.0, True),
    ("sighup-to-the-tool", PLAN_PURE, "swarm.py", signal.SIGHUP, 2.0, False),
    ("kill-9-of-the-tool", PLAN_PURE, "detach.py", signal.SIGKILL, 2.0, True),
    ("kill-9-of-a-compare", COMPARE, "chain.py", signal.SIGKILL, 3.0, False),
    ("sigint-to-a-compare", COMPARE, "detach.py", signal.SIGINT, 3.0, False),
    ("sigterm-to-watch-while-planning", WATCH, "detach.py", signal.SIGTERM, 3.0, False),
)


def _signal_scenarios(tag: str, env: tuple) -> list[Scenario]:
    """Signals to the tool while a planner runs: the tool ends (killed, or interrupted), and its planners with it."""
    return [
        Scenario(
            f"processes/{tag}/{name}",
            args=command + ("--planner", planner(script)),
            setup=SETUPS.get(command),
            codes=(128 + signal.SIGKILL,) if signum == signal.SIGKILL else (INTERRUPTED,),
            during=after(seconds, signum),
            writes=("s.sqlite*",) if command == COMPARE else (),
            env=env,
            quick=quick,
        )
        for name, command, script, signum, seconds, quick in SIGNALS
    ]


def _process_scenarios(tag: str, env: tuple) -> list[Scenario]:
    needs = cgroup_usable if tag == "cgroup" else None
    scenarios = _watchdog_scenarios(tag, env) + _signal_scenarios(tag, env)
    return [dataclasses.replace(scenario, needs=needs) for scenario in scenarios]


SCENARIOS = [
    *_process_scenarios("cgroup", ()),
    *_process_scenarios("no-cgroup", NO_CGROUP),
    Scenario(
        "processes/cgroup/planner-kills-its-guard",
        args=PLAN_PURE + ("--timeout", "3", "--planner", planner("kill_guard.py")),
        codes=(PLANNER, TIME),
        timeout=3,
        needs=cgroup_usable,
    ),
]


test_processes = scenario_test(SCENARIOS)
