"""unified-planning's engines under faults: nothing left in the temporary folder however a run ends (the race
stopping an engine, signals, its worker killed), one convention for values never set, and numbers an
engine's reader refuses."""

from __future__ import annotations

import signal

from hostile.inputs import NUMERIC_DOMAIN, NUMERIC_PROBLEM, TEMPORAL_PROBLEM, after, files, installed, one_line, says
from hostile.inputs import silent as nothing_on_stderr
from hostile.scenario import INTERRUPTED, NO_VALID, OK, PLANNER, TIME, UNSUPPORTED, Scenario, scenario_test
from hostile.test_faults import _kill_after

ARIES, TAMER = installed("up_aries"), installed("up_tamer")
ENHSP = installed("up_enhsp", java=True)
T, N = ("temporal/domain.pddl", "temporal/p1.pddl"), ("numeric/domain.pddl", "numeric/p1.pddl")
PLAN = ("-q", "--plan-file", "out.plan", "--timeout", "60")
OUT = ("out.plan", "out.plan.*")
# ENHSP counts to 200,000 one step at a time: long enough to be stopped while it searches
LONG_COUNT = files(
    numeric__long_dot_pddl=NUMERIC_PROBLEM.replace("(= (limit) 5)", "(= (limit) 1000000)").replace(
        "(>= (value c1) 3)", "(>= (value c1) 200000)"
    )
)
# the counter is never set; bump increases it without reading it: counted from 0 by every route
COUNTER_DOMAIN = NUMERIC_DOMAIN.replace("(and (ready ?c) (< (value ?c) (limit)))", "(ready ?c)").replace(
    ":effect (increase (value ?c) 1)", ":effect (and (increase (value ?c) 1))"
)
COUNTER = files(
    counter__domain_dot_pddl=COUNTER_DOMAIN,
    counter__p_dot_pddl="(define (problem c) (:domain counters) (:objects c1 - counter) (:init (ready c1))"
    " (:goal (>= (value c1) 2)))",
)
BAD_PLAN = files(bad_dot_plan="(pick-up plastic_cup_1 kitchen_counter_1)\n")
VALIDATE_UP = "exec $TOOL validate D.pddl {problem} bad.plan --validator up"


def _long_enhsp(name: str, during, codes: tuple) -> Scenario:
    """ENHSP counting a long way, without the race, ``during`` doing something to the run."""
    return Scenario(
        name,
        args=("plan", N[0], "numeric/long.pddl", "--planner", "up:enhsp", "--no-race", *PLAN),
        setup=LONG_COUNT,
        codes=codes,
        during=during,
        writes=OUT,
        needs=ENHSP,
    )


LEFT_NOTHING = [
    Scenario(
        "engines/aries-temporal", args=("plan", *T, "--planner", "up:aries", *PLAN), writes=OUT, needs=ARIES, quick=True
    ),
    Scenario("engines/aries-numeric", args=("plan", *N, "--planner", "up:aries", *PLAN), writes=OUT, needs=ARIES),
    Scenario("engines/tamer-temporal", args=("plan", *T, "--planner", "up:tamer", *PLAN), writes=OUT, needs=TAMER),
    Scenario("engines/enhsp-numeric", args=("plan", *N, "--planner", "up:enhsp", *PLAN), writes=OUT, needs=ENHSP),
    Scenario(
        "engines/enhsp-stopped-by-the-race",
        args=("plan", N[0], "numeric/long.pddl", "--race", *PLAN),
        setup=LONG_COUNT,
        codes=(OK, TIME),
        writes=OUT,
        needs=ENHSP,
    ),
    *(
        _long_enhsp(f"engines/enhsp-{name}-while-it-searches", after(3.0, signum), codes)
        for name, signum, codes in (
            ("sigterm", signal.SIGTERM, (INTERRUPTED, OK)),
            ("sigint", signal.SIGINT, (INTERRUPTED, OK)),
            ("kill-9-of-the-tool", signal.SIGKILL, (128 + signal.SIGKILL, OK)),
        )
    ),
    Scenario(
        "engines/aries-sigterm-while-it-searches",
        args=("plan", *T, "--planner", "up:aries", *PLAN),
        codes=(INTERRUPTED, OK),
        during=after(1.5, signal.SIGTERM),
        writes=OUT,
        needs=ARIES,
    ),
    *(
        _long_enhsp(
            f"engines/enhsp-worker-{whom}-killed",
            _kill_after(2.5, b"up.worker", depth=depth),
            (OK, PLANNER, NO_VALID, TIME),
        )
        for whom, depth in (("guard", 0), ("process", 1))
    ),
]

CONVENTIONS = [
    Scenario(
        "engines/a-counter-never-set-plan-and-validate-agree",
        shell="$TOOL plan counter/domain.pddl counter/p.pddl -q --no-race --plan-file out.plan > /dev/null"
        " && exec $TOOL validate counter/domain.pddl counter/p.pddl out.plan",
        setup=COUNTER,
        writes=("out.plan",),
        check=says("valid: plan of 2 steps", where="stdout"),
        needs=ENHSP,
    ),
    Scenario(
        "engines/a-timed-literal-at-1e308-is-unsupported",
        args=("plan", T[0], "temporal/far.pddl", *PLAN),
        setup=files(temporal__far_dot_pddl=TEMPORAL_PROBLEM.replace("(at 4 (open p2))", "(at 1e308 (open p2))")),
        codes=(UNSUPPORTED,),
        check=says("its reader refuses the problem, which the tool's reader takes"),
        writes=OUT,
        needs=TAMER,
    ),
    Scenario(
        "engines/validate-with-unified-planning-says-nothing-else",
        shell=VALIDATE_UP.format(problem="P.pddl"),
        setup=BAD_PLAN,
        codes=(13,),
        check=nothing_on_stderr,
        needs=TAMER,
    ),
    Scenario(
        "engines/a-planner-package-warning-needs-verbose",
        shell=VALIDATE_UP.format(problem="P.pddl") + " --verbose",
        setup=BAD_PLAN,
        codes=(13,),
        check=says("pkg_resources"),
        needs=installed("up_lpg"),
    ),
    Scenario(
        "engines/validate-with-unified-planning-refusing-in-one-line",
        shell=VALIDATE_UP.format(problem="P3.pddl"),
        setup=BAD_PLAN,
        codes=(13, 41),
        check=lambda result: nothing_on_stderr(result) if result.code == 13 else one_line()(result),
        needs=TAMER,
    ),
]

SCENARIOS = LEFT_NOTHING + CONVENTIONS


test_engines = scenario_test(SCENARIOS)
