"""The hostile sweep's inputs: the files of every workspace, misbehaving planners, and the small
pieces scenarios are built from (setups, checks, signals)."""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import time
from collections.abc import Callable
from pathlib import Path

from support import REPO, TOOL, make_row, write_store

from hostile.scenario import Result


def write(work: Path, name: str, data: str | bytes, mode: int | None = None) -> Path:
    path = work / name
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(data.encode() if isinstance(data, str) else data)
    if mode is not None:
        path.chmod(mode)
    return path


def tool_environment(extra: tuple = ()) -> dict[str, str]:
    """The environment the tool runs in: this checkout first on the path, ``$TOOL`` for shell lines, ``extra``
    (name, value) pairs."""
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(filter(None, [str(REPO), env.get("PYTHONPATH")]))
    env["TOOL"] = " ".join(TOOL)
    env.update(dict(extra))
    return env


# --------------------------------------------------------------------------- the files of every workspace

TEMPORAL_DOMAIN = """(define (domain rover-t)
  (:requirements :typing :durative-actions :numeric-fluents :timed-initial-literals)
  (:types place)
  (:predicates (at ?p - place) (road ?a ?b - place) (open ?p - place))
  (:functions (dist ?a ?b - place) (fuel))
  (:durative-action drive
    :parameters (?a ?b - place)
    :duration (= ?duration (dist ?a ?b))
    :condition (and (at start (at ?a)) (over all (road ?a ?b)) (at end (open ?b))
                    (at start (>= (fuel) (dist ?a ?b))))
    :effect (and (at start (not (at ?a))) (at end (at ?b)) (at start (decrease (fuel) (dist ?a ?b))))))
"""
TEMPORAL_PROBLEM = """(define (problem rover-t-1)
  (:domain rover-t)
  (:objects p0 p1 p2 x1 x2 x3 - place)
  (:init (at p0) (road p0 p1) (road p1 p2) (road p0 x1) (road x1 x2) (open p1) (open x1)
         (= (dist p0 p1) 2) (= (dist p1 p2) 3) (= (dist p0 x1) 1) (= (dist x1 x2) 1) (= (fuel) 20)
         (at 4 (open p2)))
  (:goal (at p2)))
"""
TIMED_PLAN = "0.000: (drive p0 p1) [2.000]\n4.010: (drive p1 p2) [3.000]\n"
NUMERIC_DOMAIN = """(define (domain counters)
  (:requirements :typing :numeric-fluents)
  (:types counter)
  (:predicates (ready ?c - counter))
  (:functions (value ?c - counter) (limit))
  (:action bump :parameters (?c - counter)
    :precondition (and (ready ?c) (< (value ?c) (limit)))
    :effect (increase (value ?c) 1)))
"""
NUMERIC_PROBLEM = """(define (problem counters-1) (:domain counters)
  (:objects c1 c2 c3 - counter)
  (:init (ready c1) (ready c2) (= (value c1) 0) (= (value c2) 0) (= (value c3) 0) (= (limit) 5))
  (:goal (>= (value c1) 3)))
"""
PDDL3_PROBLEM = """(define (problem coffee-pref) (:domain coffee)
  (:objects counter_1 table_1 - surface alice - human paper_cup_1 - cup cold_brew_1 - coffee-source
            creamer_1 - whitener stir_stick_1 - stirrer fridge_1 - container)
  (:init (robot-at counter_1) (hand-empty) (accessible counter_1) (accessible table_1) (human-at alice table_1)
         (empty paper_cup_1) (at paper_cup_1 table_1) (on-base paper_cup_1) (clear paper_cup_1)
         (at cold_brew_1 counter_1) (on-base cold_brew_1) (clear cold_brew_1)
         (at creamer_1 fridge_1) (on-base creamer_1) (clear creamer_1)
         (at stir_stick_1 counter_1) (on-base stir_stick_1) (clear stir_stick_1))
  (:goal (and (coffee-served alice) (preference tidy (clear stir_stick_1))))
  (:constraints (always (accessible counter_1))))
"""
PDDL_INPUTS = {
    "temporal/domain.pddl": TEMPORAL_DOMAIN,
    "temporal/p1.pddl": TEMPORAL_PROBLEM,
    "numeric/domain.pddl": NUMERIC_DOMAIN,
    "numeric/p1.pddl": NUMERIC_PROBLEM,
    "P3.pddl": PDDL3_PROBLEM,
}

_FORKED_SLEEPER = """import os, time
if os.fork() == 0:
    os.setsid()
    if os.fork() == 0:
        time.sleep(1000)
    os._exit(0)
"""
# Planners that misbehave; each gets DOMAIN PROBLEM [PLAN].  Children keep the script's command line
# (fork, no exec), so the workspace path in it marks them too.
BENCH_PLANNERS = {
    "never.py": "import time\ntime.sleep(1000)\n",
    "detach.py": _FORKED_SLEEPER + "time.sleep(1000)\n",
    "detach_and_answer.py": _FORKED_SLEEPER + "print('(move counter_1 table_1)')\n",
    "kill_guard.py": _FORKED_SLEEPER + "import signal\ntime.sleep(0.3)\nos.kill(os.getppid(), signal.SIGKILL)\n"
    "time.sleep(1000)\n",
    "stop_guard.py": "import os, signal, time\nos.kill(os.getppid(), signal.SIGSTOP)\ntime.sleep(1000)\n",
    "ignore_term.py": "import signal, time\nfor s in (signal.SIGTERM, signal.SIGHUP, signal.SIGINT):\n"
    "    signal.signal(s, signal.SIG_IGN)\ntime.sleep(1000)\n",
    "swarm.py": "import os, time\nfor i in range(40):\n    if os.fork() == 0:\n        if i % 2: os.setsid()\n"
    "        time.sleep(1000)\n        os._exit(0)\ntime.sleep(1000)\n",
    "chain.py": "import os, sys, time\nfor depth in range(15):\n    if os.fork() != 0:\n        break\n"
    "    if depth % 3 == 0: os.setsid()\ntime.sleep(1000)\n",
    "close_and_detach.py": "import os, time\nif os.fork() == 0:\n    os.setsid()\n    for fd in (0, 1, 2):\n"
    "        os.close(fd)\n    time.sleep(1000)\nprint('(move counter_1 table_1)')\n",
    "flood_stdout.py": "import sys\nline = ('x' * 99 + '\\n') * 10000\n"
    "for _ in range(150):\n    sys.stdout.write(line)\n",
    "long_line.py": "import sys\nfor _ in range(20):\n    sys.stdout.write('y' * 2**20)\n",
    "comment_lines.py": "import sys\nsys.stdout.write('; c\\n' * 2_000_000)\n",
    "huge_plan_file.py": "import sys\nwith open(sys.argv[-1], 'w') as f:\n"
    "    line = '(move counter_1 table_1)\\n' * 40000\n"
    "    for _ in range(200):\n        f.write(line)\n",
    "spaces.py": "print('(move' + ' ' * 120000 + 'counter_1 table_1)')\n",
    "fifo_plan.py": "import os, sys\nos.mkfifo(sys.argv[-1])\n",
    "zero_plan.py": "import os, sys\nos.symlink('/dev/zero', sys.argv[-1])\n",
    "remove_workdir.py": "import os, shutil\nshutil.rmtree(os.getcwd())\nprint('(move counter_1 table_1)')\n",
    "no_space.py": "import sys\nprint('OSError: [Errno 28] No space left on device')\nsys.exit(1)\n",
    "timed_plan.py": f"print({TIMED_PLAN!r}, end='')\n",
    "garbage.py": "import sys\nsys.stdout.buffer.write(bytes(range(256)) * 64)\n",
    "crash.py": "import os, signal\nos.kill(os.getpid(), signal.SIGSEGV)\n",
}


def big_problem(objects: int, single_line: bool = False) -> str:
    """The coffee problem with ``objects`` extra plates standing on the counter."""
    text = (REPO / "problems" / "coffee-simple.pddl").read_text()
    names = " ".join(f"x{i}" for i in range(objects))
    facts = " ".join(f"(at x{i} kitchen_counter_1) (on-base x{i}) (clear x{i})" for i in range(objects))
    text = text.replace("(:objects", f"(:objects {names} - plate", 1).replace("(:init", f"(:init {facts}", 1)
    return text.replace("\n", " ") if single_line else text.replace(") (", ")\n(")


def slow_model() -> str:
    """A coffee model padded to about 2 MB of mappings (slow for a YAML reader), otherwise valid."""
    text = (REPO / "domains" / "coffee" / "relevance.yaml").read_text()
    padding = "".join(f"  t{i}:\n" + "".join(f"    c{j}: 0.5\n" for j in range(20)) for i in range(8000))
    return text.replace("activities:\n", "activities:\n" + padding, 1)


# --------------------------------------------------------------------------- small helpers for scenarios


def files(**named: str | bytes | Callable[[], str | bytes]) -> Callable[[Path], None]:
    """A setup writing these files (``__`` in a keyword stands for '/', ``_dot_`` for '.'); a callable
    makes its file's text when the scenario runs (a large one is not built while tests are collected)."""

    def setup(work: Path) -> None:
        for key, data in named.items():
            write(work, key.replace("__", "/").replace("_dot_", "."), data() if callable(data) else data)

    return setup


def both(*setups: Callable[[Path], None]) -> Callable[[Path], None]:
    def setup(work: Path) -> None:
        for one in setups:
            one(work)

    return setup


def link(name: str, target: str) -> Callable[[Path], None]:
    def setup(work: Path) -> None:
        (work / name).parent.mkdir(parents=True, exist_ok=True)
        (work / name).symlink_to(target)

    return setup


def after(seconds: float, signum: int) -> Callable[[subprocess.Popen, Path], None]:
    def during(process: subprocess.Popen, work: Path) -> None:
        time.sleep(seconds)
        try:
            os.kill(process.pid, signum)
        except OSError:
            pass

    return during


def says(*needles: str, where: str = "stderr") -> Callable[[Result], str | None]:
    def check(result: Result) -> str | None:
        text = getattr(result, where)
        missing = [n for n in needles if n not in text]
        return f"{where} lacks {missing}: {text.strip()[-200:]!r}" if missing else None

    return check


def cgroup_usable() -> str | None:
    """None when the tool can give its planners a cgroup of their own here, else why not."""
    try:
        own = next(line[3:].strip() for line in open("/proc/self/cgroup") if line.startswith("0::"))
        mounts = [line.split() for line in open("/proc/self/mountinfo")]
        point = next(f[4] for f in mounts if "-" in f and f[f.index("-") + 1] == "cgroup2")
        probe = os.path.join(point, own.lstrip("/"), f"relevance-plan-probe-{os.getpid()}")
        os.mkdir(probe)
        os.rmdir(probe)
    except (OSError, StopIteration):
        return "no writable cgroup v2 here"
    return None


NO_CGROUP = (("RELEVANCE_PLAN_NO_CGROUP", "1"),)
PLAN_PURE = ("plan", "D.pddl", "P.pddl", "--method", "pure", "--no-widen", "-q", "--plan-file", "out.plan")


def planner(name: str, plan_file: bool = False) -> str:
    return f"cmd:{{w}}/planners/{name} {{domain}} {{problem}}" + (" {plan}" if plan_file else "")


def quiet_code(*codes: int, one_line: bool = False) -> Callable[[Result], str | None]:
    """The shell printed 'exit=N': N is one of ``codes``; stderr is empty (or one 'relevance-plan:' line)."""

    def check(result: Result) -> str | None:
        found = re.search(r"exit=(\d+)", result.stdout)
        if found is None or int(found.group(1)) not in codes:
            return f"exit {found.group(1) if found else '?'}, expected {codes}: {result.stderr.strip()[-160:]!r}"
        lines = result.stderr.strip().splitlines()
        if one_line and len(lines) <= 1 and all(line.startswith("relevance-plan") for line in lines):
            return None
        return None if not lines else f"not quiet: {lines[-3:]}"

    return check


def suite(work: Path, problems: int = 1) -> None:
    """A suite folder of the workspace's domain and ``problems`` copies of its problem."""
    (work / "suite").mkdir(exist_ok=True)
    shutil.copy(work / "D.pddl", work / "suite" / "domain.pddl")
    for number in range(1, problems + 1):
        shutil.copy(work / "P.pddl", work / "suite" / f"p{number:02d}.pddl")


METHODS_AND_TIMES = (("relevance", 1.5), ("pure", 4.0))


def store(work: Path, name: str = "s.sqlite") -> None:
    """A results store with a relevance and a pure row, made with the tool's own store module."""
    rows = [make_row("suite", "p01", method, wall=wall, relevance=0.1, kept=8) for method, wall in METHODS_AND_TIMES]
    write_store(work / name, rows)


def installed(*modules: str, java: bool = False) -> Callable[[], str | None]:
    """A ``needs`` check: None when the Python ``modules`` (and, with ``java``, a Java runtime) are here."""

    def check() -> str | None:
        import importlib.util

        missing = [name for name in modules if importlib.util.find_spec(name) is None]
        if missing:
            return f"not installed: {', '.join(missing)}"
        if java and shutil.which("java") is None:
            return "no Java runtime"
        return None

    return check


def one_line(*needles: str) -> Callable[[Result], str | None]:
    """stderr is exactly one 'relevance-plan:' line, holding ``needles``."""

    def check(result: Result) -> str | None:
        lines = result.stderr.strip().splitlines()
        if len(lines) != 1 or not lines[0].startswith("relevance-plan"):
            return f"not one line on stderr: {lines[:4]}"
        missing = [needle for needle in needles if needle not in lines[0]]
        return f"the line lacks {missing}: {lines[0][:200]!r}" if missing else None

    return check


def silent(result: Result) -> str | None:
    """Nothing at all on stderr (another package's warning or log line included)."""
    return f"stderr not empty: {result.stderr.strip().splitlines()[:3]}" if result.stderr.strip() else None


def json_only(result: Result) -> str | None:
    """stdout is one JSON value, strictly (no NaN or Infinity), and nothing else."""
    import json

    def refuse(constant: str) -> None:
        raise ValueError(f"not JSON: {constant}")

    try:
        json.loads(result.stdout, parse_constant=refuse)
    except ValueError as error:
        return f"stdout is not JSON alone ({error}): {result.stdout[:120]!r}"
    return None


def every(*checks: Callable[[Result], str | None]) -> Callable[[Result], str | None]:
    def check(result: Result) -> str | None:
        return next((found for found in (c(result) for c in checks) if found), None)

    return check
