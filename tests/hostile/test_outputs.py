"""Hostile outputs: links to standard output and to the inputs, odd names, snapshots and plots over the user's files."""

from __future__ import annotations

import os
from collections.abc import Callable

from support import REPO

from hostile.inputs import both, files, link, planner, says, store, suite, write
from hostile.scenario import INPUT, OK, USAGE, Result, Scenario, scenario_test


def _log_in_order(name: str) -> Callable[[Result], str | None]:
    """The shell wrote H, the tool its text, the shell F: all three kept, in that order."""

    def check(result: Result) -> str | None:
        text = (result.work / name).read_text(errors="replace")
        ok = text.startswith("H\n") and text.rstrip().endswith("F") and text.count("(") > 3
        return None if ok else f"{name} is not H, the text, F: {text[:40]!r} ... {text[-40:]!r}"

    return check


PRUNE = ("prune", "D.pddl", "P.pddl", "-o")
NOTES = files(notes="my notes\n")

FILES = [
    Scenario(
        "outputs/link-to-dev-stdout-appends",
        shell="ln -s /dev/stdout out-link; { echo H; $TOOL prune D.pddl P.pddl -o out-link; echo F; } >> log",
        setup=files(log=""),
        writes=("log", "out-link"),
        check=_log_in_order("log"),
        quick=True,
    ),
    Scenario(
        "outputs/dev-stdout-keeps-the-offset",
        shell="{ echo H; $TOOL prune D.pddl P.pddl -o /dev/stdout; echo F; } > log",
        writes=("log",),
        check=_log_in_order("log"),
    ),
    Scenario(
        "outputs/proc-self-fd-1",
        shell="{ echo H; $TOOL prune D.pddl P.pddl -o /proc/self/fd/1; echo F; } >> log",
        setup=files(log=""),
        writes=("log",),
        check=_log_in_order("log"),
    ),
    Scenario(
        "outputs/plan-file-through-a-link-to-stdout",
        shell="ln -s /proc/self/fd/1 plan-link; { echo H; $TOOL plan D.pddl P.pddl -q --plan-file plan-link; "
        "echo F; } >> log",
        setup=files(log=""),
        writes=("log", "plan-link"),
        check=_log_in_order("log"),
    ),
    Scenario("outputs/dev-stderr", args=PRUNE + ("/dev/stderr",), check=says("(define")),
    Scenario("outputs/descriptor-not-open", args=PRUNE + ("/dev/fd/7",), codes=(INPUT,)),
    # the tool's stdin is /dev/null here: writing through the link is right
    Scenario("outputs/descriptor-to-dev-null", args=PRUNE + ("/dev/stdin",), codes=(OK,)),
    Scenario("outputs/trailing-slash-on-a-file", args=PRUNE + ("notes/",), setup=NOTES, codes=(INPUT,), quick=True),
    Scenario("outputs/trailing-slash-new-name", args=PRUNE + ("fresh/",), codes=(INPUT,)),
    Scenario(
        "outputs/plan-file-trailing-slash-before-planning",
        args=("plan", "D.pddl", "P.pddl", "--plan-file", "notes/", "--planner", planner("never.py")),
        setup=NOTES,
        codes=(INPUT,),
        budget=10,
    ),
    Scenario("outputs/link-to-the-domain", args=PRUNE + ("alias",), setup=link("alias", "D.pddl"), codes=(USAGE,)),
    Scenario("outputs/link-to-the-problem", args=PRUNE + ("alias",), setup=link("alias", "P.pddl"), codes=(USAGE,)),
    Scenario("outputs/the-problem-itself", args=PRUNE + ("P.pddl",), codes=(USAGE,)),
    Scenario(
        "outputs/hard-link-to-the-problem",
        args=PRUNE + ("hard.pddl",),
        setup=lambda w: os.link(w / "P.pddl", w / "hard.pddl"),
        codes=(USAGE,),
    ),
    Scenario(
        "outputs/link-loop",
        args=PRUNE + ("loop",),
        setup=both(link("loop", "loop2"), link("loop2", "loop")),
        codes=(INPUT,),
    ),
    Scenario(
        "outputs/read-only-file",
        args=PRUNE + ("ro.pddl",),
        setup=lambda w: write(w, "ro.pddl", "x", 0o444),
        codes=(INPUT,),
    ),
    Scenario("outputs/empty-name", args=PRUNE + ("",), codes=(INPUT, USAGE)),
    Scenario(
        "outputs/snapshot-over-the-input-problem",
        args=("watch", "D.pddl", "W/current.pddl", "--snapshot", "W", "--events", "ev.jsonl"),
        setup=files(
            W__current_dot_pddl=(REPO / "problems" / "coffee-simple.pddl").read_text(),
            ev_dot_jsonl='{"event": "plan"}\n',
        ),
        codes=(USAGE,),
        budget=10,
        check=says("same file"),
        quick=True,
    ),
    Scenario(
        "outputs/snapshot-link-to-the-domain",
        args=("watch", "D.pddl", "P.pddl", "--snapshot", "W", "--events", "ev.jsonl"),
        setup=both(files(ev_dot_jsonl='{"event": "plan"}\n'), link("W/pruned.pddl", "../D.pddl")),
        codes=(USAGE,),
        budget=10,
    ),
    Scenario(
        "outputs/snapshot-link-to-the-events",
        args=("watch", "D.pddl", "P.pddl", "--snapshot", "W", "--events", "ev.jsonl"),
        setup=both(files(ev_dot_jsonl='{"event": "plan"}\n'), link("W/current.pddl", "../ev.jsonl")),
        codes=(USAGE,),
    ),
    Scenario(
        "outputs/snapshot-folder-is-a-file",
        args=("watch", "D.pddl", "P.pddl", "--snapshot", "notes", "--events", "/dev/null"),
        setup=NOTES,
        codes=(INPUT,),
    ),
    Scenario(
        "outputs/snapshot-written-fresh",
        args=("watch", "D.pddl", "P.pddl", "--snapshot", "W", "--events", "ev.jsonl"),
        setup=files(ev_dot_jsonl='{"event": "set", "fact": ["hand-empty"]}\n'),
        writes=("W", "W/*"),
    ),
]

PLOTS = ("report", "s.sqlite", "--plots", "PL")
# the report's plots and the sweep's heat map
FIGURES = [
    Scenario(
        "outputs/plots-over-the-store",
        args=("report", "PL/cactus.png", "--plots", "PL"),
        setup=lambda w: (w / "PL").mkdir() or store(w, "PL/cactus.png"),
        codes=(USAGE,),
    ),
    Scenario(
        "outputs/plots-over-a-users-png",
        args=PLOTS,
        setup=both(store, files(PL__cactus_dot_png=b"\x89PNG my own picture")),
        codes=(USAGE,),
        quick=True,
    ),
    Scenario(
        "outputs/plots-link-to-the-domain",
        args=PLOTS,
        setup=both(store, link("PL/relevance-vs-pure.png", "../D.pddl")),
        codes=(USAGE,),
    ),
    Scenario("outputs/plots-folder-is-a-file", args=PLOTS, setup=both(store, files(PL="x")), codes=(INPUT,)),
    Scenario(
        "outputs/plots-twice-replace-their-own",
        shell="$TOOL report s.sqlite --plots PL > /dev/null && $TOOL report s.sqlite --plots PL",
        setup=store,
        writes=("PL/*", "PL"),
    ),
    Scenario(
        "outputs/heatmap-over-a-suite-file",
        args=("sweep", "suite", "--heatmap", "suite/domain.pddl", "--scorer", "goal"),
        setup=suite,
        codes=(USAGE,),
    ),
]

SCENARIOS = FILES + FIGURES


test_outputs = scenario_test(SCENARIOS)
