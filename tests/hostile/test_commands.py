"""Every other command given hostile options: generate, sweep, compare, demo, exit-codes, plan, score, watch."""

from __future__ import annotations

from hostile.inputs import PLAN_PURE, both, files, link, says, suite
from hostile.scenario import INPUT, NO_VALID, OK, PDDL, PLANNER, USAGE, Scenario, scenario_test

SCENARIOS = [
    Scenario(
        "commands/generate-negative-count",
        args=("generate", "coffee", "--count", "-1", "--out", "g"),
        codes=(USAGE,),
    ),
    Scenario("commands/generate-unknown-world", args=("generate", "moonbase", "--out", "g"), codes=(USAGE,)),
    Scenario(
        "commands/generate-out-is-a-file",
        args=("generate", "coffee", "--out", "notes"),
        setup=files(notes="x"),
        codes=(INPUT,),
    ),
    Scenario(
        "commands/generate-into-a-users-folder",
        args=("generate", "coffee", "--count", "1", "--out", "mine"),
        setup=files(mine__notes_dot_txt="keep me"),
        codes=(USAGE, INPUT),
    ),
    Scenario(
        "commands/generate-then-sweep",
        shell="$TOOL generate gripper --count 2 --size 10 --out g > /dev/null "
        "&& $TOOL sweep g --taus 0.2,0.4 > /dev/null",
        writes=("g", "g/*"),
    ),
    Scenario("commands/sweep-nan-tau", args=("sweep", "suite", "--taus", "nan"), setup=suite, codes=(USAGE,)),
    Scenario(
        "commands/sweep-of-a-hostile-suite",
        args=("sweep", "suite", "--scorer", "goal"),
        setup=both(suite, files(suite__p02_dot_pddl="(define (problem"), link("suite/p03.pddl", "nowhere")),
        codes=(OK, PDDL),
    ),
    Scenario("commands/compare-zero-jobs", args=("compare", "suite", "--jobs", "0"), setup=suite, codes=(USAGE,)),
    Scenario(
        "commands/compare-unknown-method",
        args=("compare", "suite", "--methods", "magic"),
        setup=suite,
        codes=(USAGE,),
    ),
    Scenario("commands/compare-missing-suite", args=("compare", "nosuite", "--store", "s.sqlite"), codes=(INPUT,)),
    Scenario("commands/demo-zero-count", args=("demo", "--count", "0"), codes=(USAGE,)),
    Scenario(
        "commands/demo-tiny-keeps-nothing-of-yours",
        args=("demo", "--tiny", "-q", "--jobs", "1", "--timeout", "20"),
        budget=85,
    ),
    Scenario("commands/exit-codes", args=("exit-codes",), check=says("INTERRUPTED", where="stdout")),
    Scenario("commands/plan-absurd-timeout", args=PLAN_PURE + ("--timeout", "1e300"), codes=(USAGE,)),
    Scenario("commands/plan-nan-timeout", args=PLAN_PURE + ("--timeout", "nan"), codes=(USAGE,)),
    Scenario("commands/plan-unknown-planner", args=PLAN_PURE + ("--planner", "warp-drive"), codes=(USAGE, PLANNER)),
    Scenario(
        "commands/plan-template-with-shell-syntax",
        args=PLAN_PURE + ("--planner", "cmd:{w}/planners/timed_plan.py {domain} {problem} ; rm -rf / $(reboot)"),
        codes=(PLANNER, NO_VALID),
    ),
    Scenario("commands/score-tau-above-one", args=("score", "D.pddl", "P.pddl", "--tau-class", "2"), codes=(USAGE,)),
    Scenario(
        "commands/watch-no-events",
        args=("watch", "D.pddl", "P.pddl", "--events", "empty.jsonl"),
        setup=files(empty_dot_jsonl=""),
    ),
    Scenario(
        "commands/prune-with-json-to-stdout-twice",
        args=("prune", "D.pddl", "P.pddl", "-o", "/dev/stdout", "--json"),
        codes=(USAGE,),
    ),
]


test_commands = scenario_test(SCENARIOS)
