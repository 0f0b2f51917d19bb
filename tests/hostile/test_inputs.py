"""Hostile inputs in bulk, run through every command in this process (click's runner).

Each case must end with an exit code from the documented table, no
traceback, one stderr line when it fails, and every file the user owns
byte-identical (and with the same mode) afterwards.
"""

from __future__ import annotations

import os
import random
import stat
from pathlib import Path

import pytest
from click.testing import CliRunner
from support import COFFEE_DOMAIN, COFFEE_MODEL, alias_bomb, coffee_problem, goal_of, replace_goal, write_file

from hostile.harness import fingerprint
from relevance_plan.cli import main
from relevance_plan.exitcodes import ExitCode

DOCUMENTED = {int(code) for code in ExitCode}


# --------------------------------------------------------------------------- generators of hostile text


def hostile_problems() -> dict[str, bytes]:
    base = coffee_problem(extra_plates=2)
    goal = goal_of(base)
    rng = random.Random(11)
    huge = "p" * 100_000
    return {
        "deep-and": replace_goal(base, "(and " * 500 + goal + ")" * 500).encode(),
        "deep-not": replace_goal(base, "(not " * 700 + goal + ")" * 700).encode(),
        "deep-parens-only": ("(" * 100_000).encode(),
        "closing-parens": (")" * 1000).encode(),
        "huge-object-name": base.replace("side_plate_1", huge).encode(),
        "huge-unknown-section": base.replace("(:goal", "(" + huge + ") (:goal").encode(),
        "binary": bytes(rng.randrange(256) for _ in range(4096)),
        "latin-1": base.replace("side_plate_1", "assiette_é").encode("latin-1"),
        "bom": b"\xef\xbb\xbf" + base.encode(),
        "nul-in-name": base.replace("side_plate_1", "side\x00plate").encode(),
        "nul-at-start": b"\x00" + base.encode(),
        "control-chars": base.replace("side_plate_1", "side\x1b[31mplate").encode(),
        "non-ascii-name": base.replace("side_plate_1", "assiette_é_1").encode(),
        "non-ascii-comment": ("; café ☕ 🍰\n" + base).encode(),
        "empty": b"",
        "only-comments": b"; nothing here\n; at all\n",
        "unbalanced": base[:-5].encode(),
        "two-definitions": (base + base).encode(),
        "domain-as-problem": COFFEE_DOMAIN.read_bytes(),
        "unknown-object-in-goal": replace_goal(base, "(coffee-served nobody)").encode(),
        "numeric-goal": replace_goal(base, "(> (total-cost) 3)").encode(),
        "many-objects": base.replace(
            "(:objects", "(:objects " + " ".join(f"x{i} - plate" for i in range(3000))
        ).encode(),
        "crlf": base.replace("\n", "\r\n").encode(),
        "tabs-and-formfeeds": base.replace(" ", "\t\f ").encode(),
    }


def hostile_domains() -> dict[str, bytes]:
    text = COFFEE_DOMAIN.read_text()
    at = text.index(":precondition") + len(":precondition")
    deep = text[:at] + " " + "(and " * 600 + "(hand-empty)" + ")" * 600 + text[at:].split(")", 0)[0]
    params = text.index(":parameters (") + len(":parameters (")
    return {
        "deep-precondition": deep.encode(),
        "duplicate-parameter": (text[:params] + "?a ?a " + text[params:]).encode(),
        "binary": bytes(range(256)) * 8,
        "durative": text.replace(":action", ":durative-action", 1).encode(),
        "problem-as-domain": coffee_problem().encode(),
        "bom": b"\xef\xbb\xbf" + text.encode(),
    }


def hostile_models() -> dict[str, bytes]:
    model = COFFEE_MODEL.read_text()
    return {
        "alias-bomb": alias_bomb(),
        "alias-bomb-in-mapping": b"base: &b {x: 1}\nmore: *b\n",
        "deep-flow": ("x: " + "[" * 5000 + "]" * 5000).encode(),
        "deep-block": "".join("  " * i + f"k{i}:\n" for i in range(300)).encode(),
        "python-tag": b"!!python/object/apply:os.system ['echo owned']\n",
        "custom-tag": b"domain: !secret coffee\n",
        "binary": bytes(range(256)) * 4,
        "bom": b"\xef\xbb\xbf" + model.encode(),
        "infinite-probability": model.replace("0.", "1e400 #", 1).encode(),
        "nan-probability": model.replace("0.", ".nan #", 1).encode(),
        "list-top-level": b"- a\n- b\n",
        "empty": b"",
        "huge-key": ("x" * 200_000 + ": 1\n").encode(),
        "nul": b"domain: co\x00ffee\n",
    }


def hostile_sidecars() -> dict[str, bytes]:
    return {
        "necessary-not-strings": b'{"necessary": [1, {"a": 2}], "relevant": []}',
        "necessary-string": b'{"necessary": "cup", "relevant": "cup"}',
        "deep-json": b"[" * 100_000 + b"]" * 100_000,
        "nan": b'{"necessary": NaN}',
        "binary": bytes(range(256)),
        "huge-number": b'{"necessary": [], "relevant": [], "seed": 1e999999}',
        "top-level-list": b"[]",
    }


def hostile_stores() -> dict[str, bytes]:
    return {
        "empty": b"",
        "text": b"results\n",
        "sqlite-header-garbage": b"SQLite format 3\x00" + bytes(range(256)) * 8,
        "binary": bytes(range(256)) * 16,
    }


# --------------------------------------------------------------------------- checking one run


class Checker:
    def __init__(self, user: Path):
        self.user = user
        self.runner = CliRunner()
        self.codes: list = []

    def __call__(self, *args, allowed: set | None = None):
        before = fingerprint(self.user)
        result = self.runner.invoke(main, [str(a) for a in args])
        where = " ".join(str(a)[:80] for a in args)
        if result.exception is not None and not isinstance(result.exception, SystemExit):
            raise AssertionError(f"{where}: traceback") from result.exception
        code = result.exit_code
        assert code in DOCUMENTED, f"{where}: exit code {code}"
        assert "Traceback" not in result.stdout + result.stderr, where
        if code != 0:  # click's usage errors (exit 2) included
            lines = result.stderr.splitlines()
            assert len(lines) == 1 and lines[0].startswith("relevance-plan"), f"{where}: {result.stderr[:2000]!r}"
            assert len(lines[0]) < 2000, f"{where}: a {len(lines[0])}-character line"
        if allowed is not None:
            assert code in allowed, f"{where}: exit code {code}, expected one of {sorted(allowed)}: {result.stderr}"
        assert fingerprint(self.user) == before, f"{where}: a user file changed"
        self.codes.append(code)
        return code


@pytest.fixture
def workspace(tmp_path):
    user = tmp_path / "user"
    user.mkdir()
    out = tmp_path / "out"
    out.mkdir()
    domain = user / "domain.pddl"
    domain.write_bytes(COFFEE_DOMAIN.read_bytes())
    problem = user / "problem.pddl"
    problem.write_text(coffee_problem(extra_plates=2))
    model = user / "model.yaml"
    model.write_bytes(COFFEE_MODEL.read_bytes())
    return Checker(user), user, out, domain, problem, model


def user_suite(user: Path, domain: Path, problem: Path | None = None) -> Path:
    """The user's folder ``suite``: the domain, and a copy of ``problem`` as ``p.pddl`` when given."""
    suite = user / "suite"
    suite.mkdir()
    (suite / "domain.pddl").write_bytes(domain.read_bytes())
    if problem is not None:
        (suite / "p.pddl").write_bytes(problem.read_bytes())
    return suite


# --------------------------------------------------------------------------- the runs


@pytest.mark.planner
def test_hostile_problems_through_score_prune_and_plan(workspace):
    check, user, out, domain, _, _ = workspace
    bad = {name: write_file(user, f"{name}.pddl", data) for name, data in hostile_problems().items()}
    write_file(user, "no-events.jsonl", b"\x00\xff not json\n" + b"[" * 10000 + b"\n")
    for name, path in bad.items():
        check("score", domain, path, "--json")
        check("prune", domain, path, "-o", out / f"{name}.pddl")
        check("plan", domain, path, "-q", "--timeout", "30", "--plan-file", out / f"{name}.plan")
        check("watch", domain, path, "--events", user / "no-events.jsonl")
    # The failures are the parser's, with documented codes, not crashes.
    assert ExitCode.PDDL_SYNTAX in check.codes and ExitCode.INPUT_FILE in check.codes


def test_hostile_domains(workspace):
    check, user, out, _, problem, _ = workspace
    for name, data in hostile_domains().items():
        path = write_file(user, f"{name}-domain.pddl", data)
        check("score", path, problem, allowed={30, 31, 32, 33, 34})
        check("plan", path, problem, "-q", "--plan-file", out / "plan", allowed={30, 31, 32, 33, 34})


def test_hostile_models(workspace):
    check, user, out, domain, problem, _ = workspace
    for name, data in hostile_models().items():
        path = write_file(user, f"{name}.yaml", data)
        # YAML itself allows a byte-order mark.
        allowed = {0} if name == "bom" else {ExitCode.MODEL, ExitCode.INPUT_FILE}
        check("score", domain, problem, "--model", path, allowed=allowed)
        check("prune", domain, problem, "--model", path, "-o", out / "x.pddl", allowed=allowed)


@pytest.mark.planner
def test_hostile_suites_through_sweep_compare_and_report(workspace):
    check, user, out, domain, problem, _ = workspace
    suite = user_suite(user, domain)
    problems = hostile_problems()
    for name in ("deep-and", "binary", "bom", "non-ascii-name", "empty", "huge-object-name"):
        write_file(suite, f"{name}.pddl", problems[name])
    for index, data in enumerate(hostile_sidecars().values()):
        write_file(suite, f"good-{index}.pddl", problem.read_bytes())
        write_file(suite, f"good-{index}.json", data)
    store = out / "results.sqlite"
    check("compare", suite, "--methods", "relevance,oracle", "--store", store, "-q", "--timeout", "30", allowed={0})
    check("report", store, allowed={0})
    check("sweep", suite, allowed={ExitCode.INPUT_FILE, ExitCode.PDDL_SYNTAX})
    for name, data in hostile_stores().items():
        path = write_file(user, f"{name}.sqlite", data)
        check("report", path, allowed={ExitCode.STORE})
        if data:  # an empty file is where compare may start a new store
            check("compare", suite, "--methods", "pure", "--store", path, "-q", allowed={ExitCode.STORE})


NUMBERS = [
    ("--timeout", "inf"),
    ("--timeout", "-inf"),
    ("--timeout", "nan"),
    ("--timeout", "0"),
    ("--timeout", "1e308"),
    ("--timeout", "1e12"),
    ("--memory-limit", "0"),
    ("--memory-limit", "-1"),
    ("--memory-limit", str(10**15)),
    ("--tau-class", "nan"),
    ("--tau-class", "inf"),
    ("--tau-element", "-0.5"),
    ("--tau-element", "1e308"),
]


@pytest.mark.planner
def test_hostile_numbers_for_plan_compare_score_and_sweep(workspace):
    check, user, out, domain, problem, _ = workspace
    suite = user_suite(user, domain, problem)
    plan = ["plan", domain, problem, "-q", "--plan-file", out / "plan"]
    compare = ["compare", suite, "--store", out / "s.sqlite", "-q"]
    for option, value in NUMBERS:
        check(*plan, option, value, allowed={ExitCode.USAGE})
        check(*compare, option, value, allowed={ExitCode.USAGE})
    for value in ("0", "-1", str(10**6)):
        check(*compare, "--jobs", value, allowed={ExitCode.USAGE} if int(value) < 1 else {0})
    check(*compare, "--scheduler-timeout", "inf", "--scheduler", "tcp://127.0.0.1:1", allowed={ExitCode.USAGE})
    check(*compare, "--seeds", "a,b", allowed={ExitCode.USAGE})
    check("score", domain, problem, "--seed", str(10**40), "--scorer", "random", allowed={0})
    for value in ("nan", "inf", "", "0.1,,x", "-1", "1e400"):
        check("sweep", suite, "--taus", value, allowed={ExitCode.USAGE, ExitCode.INPUT_FILE})


def test_hostile_numbers_for_generate_and_demo(workspace):
    check, _, out, _, _, _ = workspace
    for args in (
        ["--count", "0"],
        ["--count", str(10**12)],
        ["--distractors", "-3"],
        ["--distractors", str(10**12)],
        ["--seed", str(10**40), "--count", "1"],
    ):
        target = out / "gen"
        check("generate", "coffee", "--out", target, *args, allowed={ExitCode.USAGE} if "--seed" not in args else {0})
    for args in (
        ["--jobs", "0"],
        ["--timeout", "-1"],
        ["--timeout", "inf"],
        ["--count", "0"],
        ["--distractors", "-3"],
        ["--tiny", "--distractors", "-3"],
        ["--jobs", "-5", "--tiny"],
    ):
        check("demo", "--workdir", out / "demo", *args, allowed={ExitCode.USAGE})
        assert not (out / "demo").exists()
    check("generate", "tea\x00pot", "--out", out / "tea", allowed={ExitCode.USAGE})


@pytest.mark.planner
def test_hostile_planner_names_and_configurations(workspace):
    check, _, out, domain, problem, _ = workspace
    plan = ["plan", domain, problem, "-q", "--plan-file", out / "p"]
    check(*plan, "--planner-config", "no-such-alias", allowed={ExitCode.USAGE})
    check(*plan, "--planner-config", "   ", allowed={ExitCode.USAGE})
    for planner in (
        "cmd:",
        "up:no-such-engine",
        "no-such-planner",
        "cmd:'unbalanced",
        "cmd:echo {nosuch}",
        "cmd:/no/such/planner {domain} {problem}",
    ):
        check(*plan, "--planner", planner, allowed={ExitCode.USAGE, ExitCode.PLANNER})
    check("exit-codes", allowed={0})
    check("--help", allowed={0})


def test_self_overwrites_and_odd_targets(workspace):
    check, user, out, domain, problem, model = workspace
    suite = user_suite(user, domain, problem)
    link = user / "link-to-problem"
    link.symlink_to(problem)
    readonly = user / "readonly.plan"
    readonly.write_text("keep me")
    readonly.chmod(0o444)
    fifo_dir = user / "a-directory"
    fifo_dir.mkdir()
    common = [domain, problem, "--model", model]
    for target in (problem, domain, model, link, user / ".." / "user" / "problem.pddl"):
        check("prune", *common, "-o", target, allowed={ExitCode.USAGE})
        check("plan", *common, "-q", "--plan-file", target, allowed={ExitCode.USAGE})
    check("sweep", suite, "--heatmap", suite / "domain.pddl", allowed={ExitCode.USAGE})
    for target in (readonly, fifo_dir, user / "missing-dir" / "x.pddl"):
        check("prune", *common, "-o", target, allowed={ExitCode.INPUT_FILE})
        check("plan", *common, "-q", "--plan-file", target, allowed={ExitCode.INPUT_FILE})
    check("prune", *common, "-o", "/dev/null", allowed={0})
    assert stat.S_ISCHR(os.stat("/dev/null").st_mode)
    for path in ("/dev/zero", fifo_dir, user / "nope.pddl", "bad\x00name.pddl"):
        check("score", domain, path, allowed={ExitCode.INPUT_FILE})
        check("score", path, problem, allowed={ExitCode.INPUT_FILE})
        check("report", path, allowed={ExitCode.INPUT_FILE})
    check("generate", "coffee", "--count", "1", "--out", problem, allowed={ExitCode.INPUT_FILE})
    check("generate", "coffee", "--count", "1", "--out", user, allowed={ExitCode.USAGE})
    too_long = user / ("x" * 5000)
    for args in (
        ["prune", *common, "-o", too_long],
        ["plan", *common, "-q", "--plan-file", too_long / "p"],
        ["score", domain, too_long],
        ["generate", "coffee", "--out", too_long],
        ["report", too_long],
        ["sweep", too_long],
        ["compare", too_long, "-q", "--store", out / "s.sqlite"],
        ["compare", suite, "-q", "--store", too_long],
    ):
        check(*args, allowed={ExitCode.INPUT_FILE})
    check("compare", suite, "--store", fifo_dir, "-q", allowed={ExitCode.INPUT_FILE})
    check("compare", suite, "--store", problem, "-q", allowed={ExitCode.STORE})
