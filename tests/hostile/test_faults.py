"""Supervision faults: guards and planners killed at seeded random moments, links and strangers in place of a
planner's working folder or log, limits on open files, negative initial literals of pruned objects."""

from __future__ import annotations

import json
import os
import random
import re
import shutil
import signal
import subprocess
import sys
import time
from collections.abc import Callable
from pathlib import Path

from support import REPO, TOOL

from hostile.inputs import PLAN_PURE, planner, says, tool_environment, write
from hostile.scenario import NO_VALID, OK, PLANNER, Result, Scenario, scenario_test

FAULT_SEED = 20261126
FAULT_PLANNERS = {
    # put a link to the user's folder (the workspace's mine/) where the working folder was
    "swap_folder.py": "import os, shutil, sys\nhere = os.getcwd()\nos.chdir('/')\nshutil.rmtree(here)\n"
    "os.symlink(sys.argv[1], here)\nprint('(move counter_1 table_1)')\n",
    # ... where its log was: a link to a file of the user's
    "swap_log.py": "import os, sys\nos.unlink('planner.log')\nos.symlink(sys.argv[1] + '/notes.txt', 'planner.log')\n",
    # ... a folder of its own, or a file
    "swap_for_folder.py": "import os, shutil\nhere = os.getcwd()\nos.chdir('/')\nshutil.rmtree(here)\n"
    "os.mkdir(here)\nopen(here + '/planner.log', 'w').write('mine')\n",
    "swap_for_file.py": "import os, shutil\nhere = os.getcwd()\nos.chdir('/')\nshutil.rmtree(here)\n"
    "open(here, 'w').write('a file')\n",
}
_FAULT_TMP = "tmp"  # the TMPDIR of the link scenarios: empty again once the tool has ended


def _fault_planners(work: Path) -> None:
    for name, body in FAULT_PLANNERS.items():
        write(work, f"planners/{name}", f"#!{sys.executable}\n{body}", 0o755)
    write(work, "mine/notes.txt", "the user's own notes\n")


def _long_problem(work: Path) -> None:
    """A coffee problem with 60 distractors: its full problem takes Fast Downward many seconds."""
    subprocess.run(
        TOOL + ["generate", "coffee", "--difficulty", "hard", "--count", "1", "--distractors", "60", "--out", "long"],
        cwd=work,
        env=tool_environment(),
        check=True,
        capture_output=True,
    )


def _guards_of(tool: int, marker: bytes = b"") -> list[int]:
    """The tool's guards (its children running the guard module) whose command line holds ``marker``."""
    found = []
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            fields = Path(f"/proc/{entry}/stat").read_bytes().rsplit(b")", 1)[1].split()
            command = Path(f"/proc/{entry}/cmdline").read_bytes()
        except (OSError, IndexError):
            continue
        if int(fields[1]) == tool and fields[0] not in (b"Z", b"X") and b"import guard" in command:
            if marker in command:
                found.append(int(entry))
    return sorted(found)


def _kill_after(seconds: float, marker: bytes = b"", depth: int = 0) -> Callable[[subprocess.Popen, Path], None]:
    """Once the tool has started a guard (one whose command line holds ``marker``), wait ``seconds`` and
    SIGKILL it (``depth`` 0), its child, the planner (1), or the planner's child (2: a component)."""

    def during(process: subprocess.Popen, work: Path) -> None:
        deadline = time.monotonic() + 30
        guards: list[int] = []
        while not guards and process.poll() is None and time.monotonic() < deadline:
            guards = _guards_of(process.pid, marker)
            time.sleep(0.01)
        if not guards:
            return
        time.sleep(seconds)
        victims: list[int] = []
        while not victims and process.poll() is None and time.monotonic() < deadline:
            # the guard running now: a pruned attempt's short budget may have ended meanwhile, and the
            # next attempt started under a guard of its own
            victims = _guards_of(process.pid, marker)[-1:]
            for _ in range(depth):  # the driver starts its components a moment after it starts
                victims = [child for pid in victims for child in _children(pid)]
            time.sleep(0.01)
        for pid in victims[:1]:
            try:
                os.kill(pid, signal.SIGKILL)
            except OSError:
                pass

    return during


def _children(pid: int) -> list[int]:
    try:
        with open(f"/proc/{pid}/task/{pid}/children") as stream:
            return [int(child) for child in stream.read().split()]
    except OSError:
        return []


def _tmp_left_empty(result: Result) -> str | None:
    """Nothing left in TMPDIR but a folder the planner put in place of its own, moved aside, not emptied
    (it could be a folder of the user's the planner moved there)."""
    folder = result.work / _FAULT_TMP
    left = sorted(path.name for path in folder.iterdir() if "-replaced-" not in path.name) if folder.is_dir() else []
    return f"left in TMPDIR: {', '.join(left[:3])}" if left else None


def _negative_literals(blocks: int) -> str:
    names = [f"x{i}" for i in range(1, blocks + 1)]
    init = ["(handempty)", *(f"(ontable {n}) (clear {n}) (not (holding {n}))" for n in names)]
    return (
        f"(define (problem negative-literals) (:domain blocksworld)\n  (:objects {' '.join(names)})\n"
        "  (:init\n    " + "\n    ".join(init) + ")\n  (:goal (and (on x1 x2) (on x2 x3))))\n"
    )


def _blocks_with_negative_literals(blocks: int) -> Callable[[Path], None]:
    def setup(work: Path) -> None:
        shutil.copy(REPO / "domains" / "blocksworld" / "domain.pddl", work / "B.pddl")
        write(work, "N.pddl", _negative_literals(blocks))

    return setup


def _no_negative_literal_of_a_pruned_object(result: Result) -> str | None:
    text = (result.work / "pruned.pddl").read_text()
    declared = set(re.search(r"\(:objects([^)]*)\)", text).group(1).split())
    stray = set(re.findall(r"\(not \(holding (\w+)\)\)", text)) - declared
    return f"negative literals of pruned objects left: {sorted(stray)[:3]}" if stray else None


def _solved_at_first_attempt(result: Result) -> str | None:
    try:
        found = json.loads(result.stdout)
    except ValueError:
        return "no JSON result"
    if found.get("status") != "solved" or found.get("attempts") != 1 or not found.get("pruned"):
        return f"{found.get('status')} after {found.get('attempts')} attempt(s), pruned: {found.get('pruned')}"
    return None


LONG = ("plan", "long/domain.pddl", "long/coffee-hard-001.pddl", "-q", "--plan-file", "out.plan")
RACE = (*PLAN_PURE[:3], "--race", "-q", "--plan-file", "out.plan", "--timeout", "60", "--planner", planner("never.py"))
GUARD_KILLED = says("guard was killed (by SIGKILL)")


def _guard_kills(moments: random.Random) -> list[Scenario]:
    """The guard killed: at once a planner error, whatever the other side of a race is doing (--timeout 60:
    waiting for it would miss the 20 s budget)."""
    scenarios = []
    for _ in range(4):
        delay = round(moments.uniform(0.0, 3.0), 2)
        scenarios += [
            Scenario(
                f"faults/guard-of-fast-downward-killed-at-{delay}s",
                args=(*LONG, "--method", "pure", "--timeout", "60"),
                setup=_long_problem,
                codes=(PLANNER,),
                during=_kill_after(delay),
                budget=20 + delay,
                check=GUARD_KILLED,
                writes=("long", "long/*"),
            ),
            *(
                Scenario(
                    f"faults/guard-of-{whose}-killed-at-{delay}s{suffix}",
                    args=RACE,
                    codes=(PLANNER,),
                    during=_kill_after(delay, marker),
                    budget=20 + delay,
                    check=GUARD_KILLED,
                )
                for whose, suffix, marker in (
                    ("a-pruned-attempt", "-in-a-race", b"pruned-"),
                    ("the-race", "", b"P.pddl"),
                )
            ),
        ]
    return scenarios


def _planner_kills(moments: random.Random) -> list[Scenario]:
    """The planner killed (the driver, or a component of it): a planner error, nothing left behind."""
    scenarios = []
    for depth, whom in ((1, "driver"), (2, "component")):
        for _ in range(2):
            delay = round(moments.uniform(0.3, 3.0), 2)
            scenarios.append(
                Scenario(
                    f"faults/fast-downward-{whom}-killed-at-{delay}s",
                    args=(*LONG, "--method", "pure", "--timeout", "60"),
                    setup=_long_problem,
                    codes=(PLANNER,),
                    during=_kill_after(delay, depth=depth),
                    budget=20 + delay,
                    writes=("long", "long/*"),
                )
            )
    return scenarios


# links and strangers in the planner's working folder: nothing written to the user's folder (the
# workspace's fingerprint), nothing left in TMPDIR
STRANGERS = [
    Scenario(
        f"faults/planner-{name.removesuffix('.py').replace('_', '-')}",
        shell=f"mkdir -p {_FAULT_TMP} && TMPDIR=$PWD/{_FAULT_TMP} exec $TOOL plan D.pddl P.pddl --method pure"
        f" -q --plan-file out.plan --planner 'cmd:{{w}}/planners/{name} {{w}}/mine {{domain}} {{problem}}'",
        setup=_fault_planners,
        codes=(OK, PLANNER, NO_VALID),
        check=_tmp_left_empty,
        writes=(_FAULT_TMP, "out.plan"),
    )
    for name in FAULT_PLANNERS
]
# limits on open files, with and without a descriptor the shell left open above the limit
OPEN_FILE_LIMITS = [
    Scenario(
        f"faults/ulimit-n-{limit}{'-fd-20-open' if stray else ''}-{method}",
        shell=f"{stray}ulimit -n {limit} && exec $TOOL plan D.pddl P.pddl --method {method} -q"
        " --plan-file out.plan --timeout 60",
        writes=("out.plan",),
    )
    for limit in (16, 12, 10)
    for stray in ("", "exec 20</dev/null; ")
    for method in ("pure", "relevance")
]
# negative initial literals about pruned objects: cut with them; the list and the flat reading of :init
NEGATIVE_LITERALS = [
    Scenario(
        f"faults/negative-literals-of-pruned-objects-{what}-{blocks}-blocks",
        args=args,
        setup=_blocks_with_negative_literals(blocks),
        check=check,
        writes=(output,),
    )
    for blocks in (40, 800)
    for what, args, check, output in (
        (
            "cut",
            ("prune", "B.pddl", "N.pddl", "-o", "pruned.pddl"),
            _no_negative_literal_of_a_pruned_object,
            "pruned.pddl",
        ),
        (
            "plan",
            ("plan", "B.pddl", "N.pddl", "--no-race", "--json", "-q", "--plan-file", "out.plan"),
            _solved_at_first_attempt,
            "out.plan",
        ),
    )
]
_MOMENTS = random.Random(FAULT_SEED)  # one generator, drawn in this order: the guards', then the planners' kills
SCENARIOS = [*_guard_kills(_MOMENTS), *_planner_kills(_MOMENTS), *STRANGERS, *OPEN_FILE_LIMITS, *NEGATIVE_LITERALS]


test_faults = scenario_test(SCENARIOS)
