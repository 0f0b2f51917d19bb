"""Every other command given hostile options: generate, sweep, compare, demo, exit-codes, plan, score, watch."""

from __future__ import annotations

from hostile.inputs import PLAN_PURE, both, files, link, one_line, says, store, suite
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
    # an output on standard output beside a flag printing there: refused before any work, in every command
    *(
        Scenario(
            f"commands/{args[0]}-{label}-beside-{flag.strip('-')}-on-stdout",
            args=(*args, flag),
            setup=store,
            codes=(USAGE,),
            check=one_line("would both write to standard output"),
            quick=args[0] == "draft-model",
        )
        for args, label, flag in (
            (("draft-model", "D.pddl", "P.pddl", "-o", "-"), "model", "--json"),
            (("draft-model", "D.pddl", "P.pddl", "-o", "/dev/stdout"), "model-via-dev-stdout", "--json"),
            (("plan", "D.pddl", "P.pddl", "--plan-file", "-"), "plan", "--json"),
            (("report", "s.sqlite", "--html", "-"), "page", "--csv"),
        )
    ),
]


# click's usage errors: one line naming what is wrong, exit 2, for every command
COMMAND_ARGS = {
    "generate": ("coffee", "--out", "g"),
    "score": ("D.pddl", "P.pddl"),
    "prune": ("D.pddl", "P.pddl", "-o", "small.pddl"),
    "plan": ("D.pddl", "P.pddl"),
    "validate": ("D.pddl", "P.pddl", "P.pddl"),
    "watch": ("D.pddl", "P.pddl", "--events", "P.pddl"),
    "compare": ("suite",),
    "report": ("s.sqlite",),
    "sweep": ("suite",),
    "demo": (),
    "learn": ("D.pddl", "P.pddl", "-o", "m.json"),
    "examples": ("ex",),
    "exit-codes": (),
}
USAGE_ERRORS = [
    *(
        Scenario(
            f"commands/{name}-unknown-option",
            args=(name, *args, "--no-such-option"),
            codes=(2,),
            check=one_line("--no-such-option"),
            quick=name == "report",
        )
        for name, args in COMMAND_ARGS.items()
    ),
    Scenario("commands/no-command", args=(), codes=(2,), check=one_line("no command")),
    Scenario("commands/unknown-command", args=("plna",), codes=(2,), check=one_line("plna")),
    Scenario("commands/plan-missing-problem", args=("plan", "D.pddl"), codes=(2,), check=one_line("PROBLEM")),
    Scenario("commands/prune-missing-output", args=("prune", "D.pddl", "P.pddl"), codes=(2,), check=one_line("-o")),
    Scenario("commands/plan-option-without-value", args=("plan", "D.pddl", "P.pddl", "--timeout"), codes=(2,)),
]
# every numeric option: a number out of its range is exit 30 in one line naming it
NUMBERS = [
    Scenario(
        f"commands/{name}-{option.strip('-')}-{label}",
        args=(name, *COMMAND_ARGS[name], option, value),
        setup=suite,
        codes=(USAGE,),
        check=one_line(option),
        quick=label == "nan" and name in ("learn", "validate"),
    )
    for name, option, label, value in (
        ("learn", "--timeout", "nan", "nan"),
        ("learn", "--time-limit", "nan", "nan"),
        ("validate", "--timeout", "nan", "nan"),
        ("demo", "--timeout", "inf", "inf"),
        ("compare", "--scheduler-timeout", "nan", "nan"),
        ("compare", "--seeds", "huge", str(10**30)),
        ("compare", "--jobs", "zero", "0"),
        ("generate", "--size", "huge", str(10**12)),
        ("generate", "--count", "negative", "-5"),
        ("report", "--dpi", "zero", "0"),
        ("sweep", "--taus", "nan", "0.1,nan"),
        ("plan", "--memory-limit", "tiny", "1"),
        ("plan", "--tau-element", "huge", "1e308"),
        ("watch", "--timeout", "negative", "-1"),
        ("score", "--tau-class", "nan", "nan"),
    )
]
# every option of names: a name it does not know is exit 30 in one line naming it, in every command
NAMES = [
    Scenario(
        f"commands/{name}-{option.strip('-')}-unknown-name",
        args=(name, *COMMAND_ARGS[name], option, value),
        setup=suite,
        codes=(USAGE,),
        check=one_line("'fast'"),
        quick=name in ("plan", "validate"),
    )
    for name, option, value in (
        ("plan", "--method", "fast"),
        ("plan", "--scorer", "fast"),
        ("plan", "--validator", "builtin,fast"),
        ("plan", "--planner", "fast"),
        ("compare", "--methods", "relevance,fast"),
        ("compare", "--planners", "auto,fast"),
        ("score", "--scorer", "fast"),
        ("watch", "--validator", "fast"),
        ("validate", "--validator", "fast"),
        ("learn", "--labels", "fast"),
        ("report", "--format", "fast"),
        ("report", "--plot-format", "fast"),
        ("generate", "--difficulty", "fast"),
    )
]
SCENARIOS += USAGE_ERRORS + NUMBERS + NAMES


test_commands = scenario_test(SCENARIOS)
