#!/usr/bin/env python
"""Hostile scenarios through every command: outputs that are links, planners that
escape, floods, deadlines, a live session fed bad events, broken surroundings,
temporal and numeric inputs, bad stores and models.

Each scenario runs the tool as a separate process in a fresh workspace and
passes only when all of these hold:

* the exit code is the one expected, and one of the documented table (or
  141, a reader that closed the pipe);
* no traceback (nor "Exception ignored") on stderr; a failure ends with a
  ``relevance-plan:`` line;
* no file of the workspace changed (hash, mode and link target before and
  after), except the outputs the scenario names;
* no process left: this script is a child subreaper (Linux), so anything
  the tool started and lost is re-parented here and found; processes
  naming the workspace in their command line are looked for too;
* the deadline held: with ``--timeout T`` the tool ends within T + 1 s
  after its own start-up (measured once: the median of three
  ``exit-codes`` runs);
* memory bounded: the peak RSS of the tool and what it waited for stays
  under the scenario's limit.

Prints PASS or FAIL per scenario, then the count; exits 1 if any failed.

    python benchmarks/bench_hostile.py             # every scenario (about 10 minutes on 2 cores)
    python benchmarks/bench_hostile.py --quick     # the short subset the test suite runs
    python benchmarks/bench_hostile.py --only NAME --only NAME
    python benchmarks/bench_hostile.py --list
"""

from __future__ import annotations

import argparse
import ctypes
import dataclasses
import hashlib
import json
import os
import re
import shutil
import signal
import statistics
import subprocess
import sys
import tempfile
import threading
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(REPO))

from relevance_plan.exitcodes import ExitCode  # noqa: E402
from relevance_plan.supervision.guard import reap_children  # noqa: E402

TOOL = [sys.executable, "-m", "relevance_plan"]
DOCUMENTED = {int(code) for code in ExitCode} | {141}
OK, TIME, INPUT, USAGE = 0, int(ExitCode.OUT_OF_TIME), int(ExitCode.INPUT_FILE), int(ExitCode.USAGE)
PDDL, UNSUPPORTED, MISMATCH = int(ExitCode.PDDL_SYNTAX), int(ExitCode.UNSUPPORTED_PDDL), int(ExitCode.DOMAIN_MISMATCH)
MODEL, STORE, PLANNER = int(ExitCode.MODEL), int(ExitCode.STORE), int(ExitCode.PLANNER)
INTERRUPTED, PIPE = int(ExitCode.INTERRUPTED), 141
NO_VALID = int(ExitCode.NO_VALID_PLAN)
HANG_LIMIT = 90.0  # any scenario: killed and failed past this
LEFTOVER_GRACE = 2.0  # the guard's own clean-up after the tool died may take a moment
_BAD_OUTPUT = re.compile(r"Traceback|Exception ignored|^\s+File \"", re.MULTILINE)


@dataclass(frozen=True)
class Result:
    code: int
    stdout: str
    stderr: str
    elapsed: float
    peak_mb: float
    work: Path


@dataclass(frozen=True)
class Scenario:
    """One hostile run.  ``args``: the tool's arguments; or ``shell``: a bash line using ``$TOOL``.

    Paths are relative to the workspace (the tool's cwd), which ``setup``
    fills after the common files (D.pddl, P.pddl, the planners/ folder).
    """

    name: str
    args: tuple = ()
    shell: str | None = None
    setup: Callable[[Path], None] | None = None
    codes: tuple = (OK,)
    stdin: bytes | None = None
    timeout: float | None = None  # the --timeout whose deadline must hold (within 1 s)
    budget: float | None = None  # or: seconds the run may take at most (beyond start-up)
    writes: tuple = ()  # glob patterns of workspace files the run may create or change
    check: Callable[[Result], str | None] | None = None
    during: Callable[[subprocess.Popen, Path], None] | None = None
    env: tuple = ()  # (name, value) pairs added to the environment
    max_rss_mb: int = 900
    quick: bool = False
    needs: Callable[[], str | None] | None = None  # a reason to skip, or None


# --------------------------------------------------------------------------- the workspace


def write(work: Path, name: str, data: str | bytes, mode: int | None = None) -> Path:
    path = work / name
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(data.encode() if isinstance(data, str) else data)
    if mode is not None:
        path.chmod(mode)
    return path


def make_workspace(root: Path) -> Path:
    work = Path(tempfile.mkdtemp(prefix="hostile-", dir=root))
    shutil.copy(REPO / "domains" / "coffee" / "domain.pddl", work / "D.pddl")
    shutil.copy(REPO / "problems" / "coffee-simple.pddl", work / "P.pddl")
    for name, body in BENCH_PLANNERS.items():
        write(work, f"planners/{name}", f"#!{sys.executable}\n{body}", 0o755)
    for name, text in PDDL_INPUTS.items():
        write(work, name, text)
    return work


def fingerprint(work: Path, allowed: tuple) -> dict[str, tuple]:
    """Every path under ``work`` but the allowed outputs: (mode, size, digest or link target)."""
    found = {}
    for folder, dirs, files in os.walk(work):
        for name in dirs + files:
            path = Path(folder) / name
            relative = str(path.relative_to(work))
            if any(Path(relative).match(pattern) or relative.startswith(pattern.rstrip("*")) for pattern in allowed):
                continue
            info = path.lstat()
            if path.is_symlink():
                found[relative] = (info.st_mode, os.readlink(path))
            elif path.is_file():
                found[relative] = (info.st_mode, info.st_size, hashlib.sha256(path.read_bytes()).hexdigest())
            else:
                found[relative] = (info.st_mode,)
    return found


# --------------------------------------------------------------------------- processes


def become_subreaper() -> bool:
    """Orphans of whatever the tool starts come to this process: none can go unseen."""
    if not sys.platform.startswith("linux"):
        return False
    libc = ctypes.CDLL(None, use_errno=True)
    return libc.prctl(36, 1, 0, 0, 0) == 0  # PR_SET_CHILD_SUBREAPER


def _descendants(root: int) -> list[int]:
    children: dict[int, list[int]] = {}
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                fields = Path(f"/proc/{entry}/stat").read_bytes().rsplit(b")", 1)[1].split()
            except (OSError, IndexError):
                continue
            if fields[0] not in (b"Z", b"X"):
                children.setdefault(int(fields[1]), []).append(int(entry))
    found, queue = [], [root]
    while queue:
        for child in children.get(queue.pop(), []):
            found.append(child)
            queue.append(child)
    return found


def _marked(marker: str) -> list[int]:
    found = []
    for entry in os.listdir("/proc"):
        if entry.isdigit() and int(entry) != os.getpid():
            try:
                if marker.encode() in Path(f"/proc/{entry}/cmdline").read_bytes():
                    state = Path(f"/proc/{entry}/stat").read_bytes().rsplit(b")", 1)[1].split()[0]
                    if state not in (b"Z", b"X"):
                        found.append(int(entry))
            except (OSError, IndexError):
                continue
    return found


def leftovers(work: Path) -> list[str]:
    """Processes still running after the tool ended (waits out the guard's own clean-up), then killed."""
    if not os.path.isdir("/proc"):
        return []
    deadline = time.monotonic() + LEFTOVER_GRACE
    while True:
        reap_children()
        alive = sorted(set(_descendants(os.getpid())) | set(_marked(str(work))))
        if not alive or time.monotonic() > deadline:
            break
        time.sleep(0.05)
    described = []
    for pid in alive:
        try:
            command = Path(f"/proc/{pid}/cmdline").read_bytes().replace(b"\0", b" ")[:80]
            described.append(f"{pid} {command!r}")
            os.kill(pid, signal.SIGKILL)
        except OSError:
            pass
    reap_children()
    return described


# --------------------------------------------------------------------------- one run


def _environment(scenario: Scenario) -> dict:
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(filter(None, [str(REPO), env.get("PYTHONPATH")]))
    env["TOOL"] = " ".join(TOOL)
    env.update(dict(scenario.env))
    return env


def _start(scenario: Scenario, work: Path) -> subprocess.Popen:
    # "{w}": the workspace's absolute path (a planner template needs one: the planner runs elsewhere)
    args = [str(a).replace("{w}", str(work)) for a in scenario.args]
    command = ["bash", "-c", scenario.shell.replace("{w}", str(work))] if scenario.shell else TOOL + args
    return subprocess.Popen(
        command,
        cwd=work,
        env=_environment(scenario),
        stdin=subprocess.PIPE if scenario.stdin is not None else subprocess.DEVNULL,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        start_new_session=True,
    )


def execute(scenario: Scenario, work: Path) -> Result:
    """Run the scenario's command; its rusage covers the tool and everything it waited for."""
    started = time.monotonic()
    process = _start(scenario, work)
    chunks: dict[str, bytes] = {}

    def drain(name: str, stream) -> None:
        chunks[name] = stream.read()

    readers = [
        threading.Thread(target=drain, args=(n, s)) for n, s in (("out", process.stdout), ("err", process.stderr))
    ]
    for reader in readers:
        reader.start()
    if scenario.stdin is not None:
        try:
            process.stdin.write(scenario.stdin)
            process.stdin.close()
        except OSError:
            pass
    if scenario.during is not None:
        scenario.during(process, work)
    timer = threading.Timer(HANG_LIMIT, lambda: os.killpg(process.pid, signal.SIGKILL))
    timer.start()
    _, status, usage = os.wait4(process.pid, 0)
    timer.cancel()
    elapsed = time.monotonic() - started
    process.returncode = os.waitstatus_to_exitcode(status)
    for reader in readers:
        reader.join(10)
    code = process.returncode if process.returncode >= 0 else 128 - process.returncode
    decode = lambda name: chunks.get(name, b"").decode("utf-8", errors="replace")  # noqa: E731
    return Result(code, decode("out"), decode("err"), elapsed, usage.ru_maxrss / 1024.0, work)


def judge(scenario: Scenario, result: Result, before: dict, startup: float) -> list[str]:
    problems = []
    if result.code not in scenario.codes:
        last = result.stderr.strip().splitlines()[-1:] or [""]
        problems.append(f"exit {result.code}, expected {'/'.join(map(str, scenario.codes))}: {last[0][:160]}")
    if result.code not in DOCUMENTED and result.code not in scenario.codes:  # kill -9: 137 is expected
        problems.append(f"exit {result.code} is not a documented code")
    if _BAD_OUTPUT.search(result.stderr) or _BAD_OUTPUT.search(result.stdout):
        problems.append("a traceback: " + result.stderr.strip().splitlines()[-1][:160])
    killed = result.code == 128 + signal.SIGKILL  # kill -9 leaves the tool no time to say anything
    if result.code not in (OK, PIPE, INTERRUPTED) and not scenario.shell and not killed:
        lines = result.stderr.strip().splitlines()
        if not lines or not lines[-1].startswith("relevance-plan"):
            problems.append(f"no 'relevance-plan:' line on failure: {lines[-1:]}")
    if scenario.timeout is not None and result.elapsed > scenario.timeout + 1.0 + startup:
        problems.append(f"deadline missed: {result.elapsed:.1f} s for --timeout {scenario.timeout:g}")
    if scenario.budget is not None and result.elapsed > scenario.budget + startup:
        problems.append(f"took {result.elapsed:.1f} s, over its {scenario.budget:g} s")
    if result.peak_mb > scenario.max_rss_mb:
        problems.append(f"peak memory {result.peak_mb:.0f} MB over {scenario.max_rss_mb} MB")
    after = fingerprint(result.work, scenario.writes)
    changed = sorted(name for name in before.keys() | after.keys() if before.get(name) != after.get(name))
    if changed:
        problems.append(f"files changed: {', '.join(changed[:5])}")
    if scenario.check is not None:
        found = scenario.check(result)
        if found:
            problems.append(found)
    return problems


def run_one(scenario: Scenario, root: Path, startup: float) -> tuple[str, list[str], float]:
    """('PASS' | 'FAIL' | 'SKIP', reasons, seconds)."""
    if scenario.needs is not None and (reason := scenario.needs()):
        return "SKIP", [reason], 0.0
    work = make_workspace(root)
    try:
        if scenario.setup is not None:
            scenario.setup(work)
        before = fingerprint(work, scenario.writes)
        result = execute(scenario, work)
        problems = judge(scenario, result, before, startup)
        left = leftovers(work)
        if left:
            problems.append("processes left: " + "; ".join(left[:3]))
        return ("FAIL" if problems else "PASS"), problems, result.elapsed
    finally:
        _make_removable(work)
        shutil.rmtree(work, ignore_errors=True)


def _make_removable(work: Path) -> None:
    for folder, dirs, _ in os.walk(work):
        for name in dirs:
            try:
                (Path(folder) / name).chmod(0o755)
            except OSError:
                pass


def measure_startup() -> float:
    """The tool's start-up, the time before its own clock starts: the median of three trivial runs."""
    env = _environment(Scenario("startup"))
    times = []
    for _ in range(3):
        started = time.monotonic()
        subprocess.run(TOOL + ["exit-codes"], env=env, stdout=subprocess.DEVNULL, check=False)
        times.append(time.monotonic() - started)
    return statistics.median(times)


# --------------------------------------------------------------------------- the scenarios

SCENARIO_BUILDERS: list[Callable[[], list[Scenario]]] = []  # filled below, one per class


def all_scenarios() -> list[Scenario]:
    scenarios = [scenario for build in SCENARIO_BUILDERS for scenario in build()]
    names = [scenario.name for scenario in scenarios]
    assert len(names) == len(set(names)), "scenario names must be unique"
    return scenarios


# --------------------------------------------------------------------------- inputs

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
    return text.replace("tasks:\n", "tasks:\n" + padding, 1)


# --------------------------------------------------------------------------- small helpers for scenarios


def files(**named: str | bytes) -> Callable[[Path], None]:
    """A setup writing these files (``__`` in a keyword stands for '/', ``_dot_`` for '.')."""

    def setup(work: Path) -> None:
        for key, data in named.items():
            write(work, key.replace("__", "/").replace("_dot_", "."), data)

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


PYTHON_OK = ("OK",)


# --------------------------------------------------------------------------- 1. outputs


def _log_in_order(name: str) -> Callable[[Result], str | None]:
    """The shell wrote H, the tool its text, the shell F: all three kept, in that order."""

    def check(result: Result) -> str | None:
        text = (result.work / name).read_text(errors="replace")
        ok = text.startswith("H\n") and text.rstrip().endswith("F") and text.count("(") > 3
        return None if ok else f"{name} is not H, the text, F: {text[:40]!r} ... {text[-40:]!r}"

    return check


def output_scenarios() -> list[Scenario]:
    prune = ("prune", "D.pddl", "P.pddl", "-o")
    notes = files(notes="my notes\n")
    scenarios = [
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
        Scenario("outputs/dev-stderr", args=prune + ("/dev/stderr",), check=says("(define")),
        Scenario("outputs/descriptor-not-open", args=prune + ("/dev/fd/7",), codes=(INPUT,)),
        # the tool's stdin is /dev/null here: writing through the link is right
        Scenario("outputs/descriptor-to-dev-null", args=prune + ("/dev/stdin",), codes=(OK,)),
        Scenario("outputs/trailing-slash-on-a-file", args=prune + ("notes/",), setup=notes, codes=(INPUT,), quick=True),
        Scenario("outputs/trailing-slash-new-name", args=prune + ("fresh/",), codes=(INPUT,)),
        Scenario(
            "outputs/plan-file-trailing-slash-before-planning",
            args=("plan", "D.pddl", "P.pddl", "--plan-file", "notes/", "--planner", planner("never.py")),
            setup=notes,
            codes=(INPUT,),
            budget=10,
        ),
        Scenario("outputs/link-to-the-domain", args=prune + ("alias",), setup=link("alias", "D.pddl"), codes=(USAGE,)),
        Scenario("outputs/link-to-the-problem", args=prune + ("alias",), setup=link("alias", "P.pddl"), codes=(USAGE,)),
        Scenario("outputs/the-problem-itself", args=prune + ("P.pddl",), codes=(USAGE,)),
        Scenario(
            "outputs/hard-link-to-the-problem",
            args=prune + ("hard.pddl",),
            setup=lambda w: os.link(w / "P.pddl", w / "hard.pddl"),
            codes=(USAGE,),
        ),
        Scenario(
            "outputs/link-loop",
            args=prune + ("loop",),
            setup=both(link("loop", "loop2"), link("loop2", "loop")),
            codes=(INPUT,),
        ),
        Scenario(
            "outputs/read-only-file",
            args=prune + ("ro.pddl",),
            setup=lambda w: write(w, "ro.pddl", "x", 0o444),
            codes=(INPUT,),
        ),
        Scenario("outputs/empty-name", args=prune + ("",), codes=(INPUT, USAGE)),
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
            setup=notes,
            codes=(INPUT,),
        ),
        Scenario(
            "outputs/snapshot-written-fresh",
            args=("watch", "D.pddl", "P.pddl", "--snapshot", "W", "--events", "ev.jsonl"),
            setup=files(ev_dot_jsonl='{"event": "set", "fact": ["hand-empty"]}\n'),
            writes=("W", "W/*"),
        ),
    ]
    return scenarios + _plot_scenarios()


def _row(method: str, wall: float) -> dict:
    """One solved job, as a results store holds it."""
    config = json.dumps({"method": method, "timeout": 60.0}, sort_keys=True)
    return {
        "problem_hash": "hash-p01", "method": method, "config_hash": f"config-{method}", "planner_version": "1",
        "suite": "suite", "problem": "p01.pddl", "world": "coffee", "difficulty": "simple", "seed": 0,
        "status": "solved", "valid": 1, "exit_code": 0, "wall_time": wall, "relevance_time": 0.1,
        "planner_time": wall - 0.1, "objects_total": 20, "objects_kept": 8, "attempts": 1,
        "first_attempt_status": "solved", "plan_length": 12, "timeout": 60.0, "message": "",
        "config_json": config, "finished_at": "2026-01-01T00:00:00+00:00", "result_json": "{}",
    }  # fmt: skip


def _store(work: Path, name: str = "s.sqlite") -> None:
    """A results store with a relevance and a pure row, made with the tool's own store module."""
    from relevance_plan.batch.store import ResultStore

    with ResultStore(work / name) as store:
        store.add(_row("relevance", 1.5))
        store.add(_row("pure", 4.0))


def _plot_scenarios() -> list[Scenario]:
    plots = ("report", "s.sqlite", "--plots", "PL")
    return [
        Scenario(
            "outputs/plots-over-the-store",
            args=("report", "PL/cactus.png", "--plots", "PL"),
            setup=lambda w: (w / "PL").mkdir() or _store(w, "PL/cactus.png"),
            codes=(USAGE,),
        ),
        Scenario(
            "outputs/plots-over-a-users-png",
            args=plots,
            setup=both(_store, files(PL__cactus_dot_png=b"\x89PNG my own picture")),
            codes=(USAGE,),
            quick=True,
        ),
        Scenario(
            "outputs/plots-link-to-the-domain",
            args=plots,
            setup=both(_store, link("PL/relevance-vs-pure.png", "../D.pddl")),
            codes=(USAGE,),
        ),
        Scenario("outputs/plots-folder-is-a-file", args=plots, setup=both(_store, files(PL="x")), codes=(INPUT,)),
        Scenario(
            "outputs/plots-twice-replace-their-own",
            shell="$TOOL report s.sqlite --plots PL > /dev/null && $TOOL report s.sqlite --plots PL",
            setup=_store,
            writes=("PL/*", "PL"),
        ),
        Scenario(
            "outputs/heatmap-over-a-suite-file",
            args=("sweep", "suite", "--heatmap", "suite/domain.pddl", "--scorer", "goal"),
            setup=_suite,
            codes=(USAGE,),
        ),
    ]


def _suite(work: Path, problems: int = 1) -> None:
    (work / "suite").mkdir(exist_ok=True)
    shutil.copy(work / "D.pddl", work / "suite" / "domain.pddl")
    for number in range(1, problems + 1):
        shutil.copy(work / "P.pddl", work / "suite" / f"p{number:02d}.pddl")


SCENARIO_BUILDERS.append(output_scenarios)


# --------------------------------------------------------------------------- 2. processes


def _process_scenarios(tag: str, env: tuple) -> list[Scenario]:
    needs = cgroup_usable if tag == "cgroup" else None
    scenarios = []
    for name in ("detach.py", "swarm.py", "chain.py", "ignore_term.py", "stop_guard.py"):
        scenarios.append(
            Scenario(
                f"processes/{tag}/watchdog-{name[:-3]}",
                args=PLAN_PURE + ("--timeout", "2", "--planner", planner(name)),
                codes=(TIME,),
                timeout=2,
                env=env,
                quick=name == "detach.py",
            )
        )
    scenarios += [
        Scenario(
            f"processes/{tag}/timeout-wrapper",
            args=PLAN_PURE
            + ("--timeout", "2", "--planner", "cmd:timeout 100 {w}/planners/detach.py {domain} {problem}"),
            codes=(TIME,),
            timeout=2,
            env=env,
        ),
        Scenario(
            f"processes/{tag}/setsid-wrapper",
            args=PLAN_PURE + ("--timeout", "2", "--planner", "cmd:setsid {w}/planners/never.py {domain} {problem}"),
            codes=(TIME,),
            timeout=2,
            env=env,
        ),
        Scenario(
            f"processes/{tag}/answers-and-leaves-a-daemon",
            args=PLAN_PURE + ("--planner", planner("detach_and_answer.py")),
            codes=(NO_VALID,),
            env=env,
        ),
        Scenario(
            f"processes/{tag}/closes-its-output-and-detaches",
            args=PLAN_PURE + ("--planner", planner("close_and_detach.py")),
            codes=(NO_VALID,),
            env=env,
        ),
        Scenario(
            f"processes/{tag}/sigterm-to-the-tool",
            args=PLAN_PURE + ("--planner", planner("detach.py")),
            codes=(INTERRUPTED,),
            during=after(2.0, signal.SIGTERM),
            env=env,
            quick=True,
        ),
        Scenario(
            f"processes/{tag}/sighup-to-the-tool",
            args=PLAN_PURE + ("--planner", planner("swarm.py")),
            codes=(INTERRUPTED,),
            during=after(2.0, signal.SIGHUP),
            env=env,
        ),
        Scenario(
            f"processes/{tag}/kill-9-of-the-tool",
            args=PLAN_PURE + ("--planner", planner("detach.py")),
            codes=(128 + signal.SIGKILL,),
            during=after(2.0, signal.SIGKILL),
            env=env,
            quick=True,
        ),
        Scenario(
            f"processes/{tag}/kill-9-of-a-compare",
            args=(
                "compare",
                "suite",
                "--methods",
                "pure",
                "--store",
                "s.sqlite",
                "-q",
                "--planner",
                planner("chain.py"),
            ),
            setup=_suite,
            codes=(128 + signal.SIGKILL,),
            during=after(3.0, signal.SIGKILL),
            writes=("s.sqlite*",),
            env=env,
        ),
        Scenario(
            f"processes/{tag}/sigint-to-a-compare",
            args=(
                "compare",
                "suite",
                "--methods",
                "pure",
                "--store",
                "s.sqlite",
                "-q",
                "--planner",
                planner("detach.py"),
            ),
            setup=_suite,
            codes=(INTERRUPTED,),
            during=after(3.0, signal.SIGINT),
            writes=("s.sqlite*",),
            env=env,
        ),
        Scenario(
            f"processes/{tag}/sigterm-to-watch-while-planning",
            args=("watch", "D.pddl", "P.pddl", "--events", "ev.jsonl", "--planner", planner("detach.py")),
            setup=files(ev_dot_jsonl='{"event": "plan"}\n'),
            codes=(INTERRUPTED,),
            during=after(3.0, signal.SIGTERM),
            env=env,
        ),
    ]
    return [dataclasses.replace(scenario, needs=needs) for scenario in scenarios]


def process_scenarios() -> list[Scenario]:
    scenarios = _process_scenarios("cgroup", ()) + _process_scenarios("no-cgroup", NO_CGROUP)
    scenarios.append(
        Scenario(
            "processes/cgroup/planner-kills-its-guard",
            args=PLAN_PURE + ("--timeout", "3", "--planner", planner("kill_guard.py")),
            codes=(PLANNER, TIME),
            timeout=3,
            needs=cgroup_usable,
        )
    )
    return scenarios


SCENARIO_BUILDERS.append(process_scenarios)


# --------------------------------------------------------------------------- 3. deadlines and floods


def _ratio_at_most(limit: float) -> Callable[[Result], str | None]:
    """The shell printed three clock readings around two runs: the first run may take ``limit`` x the second."""

    def check(result: Result) -> str | None:
        start, middle, end = (float(value) for value in result.stdout.split()[-3:])
        ratio = (middle - start) / max(end - middle, 1e-3)
        return None if ratio <= limit else f"the single line took {ratio:.1f} x as long as with newlines"

    return check


def deadline_scenarios() -> list[Scenario]:
    plan = ("plan", "D.pddl", "P.pddl", "-q", "--plan-file", "out.plan")
    big = files(big_dot_pddl=big_problem(150_000))
    scenarios = [
        Scenario(
            "deadlines/huge-problem-reading",
            args=("plan", "D.pddl", "big.pddl", "-q", "--timeout", "2"),
            setup=big,
            codes=(TIME,),
            timeout=2,
            quick=True,
        ),
        Scenario(
            "deadlines/huge-problem-pure",
            args=("plan", "D.pddl", "big.pddl", "-q", "--timeout", "3", "--method", "pure"),
            setup=big,
            codes=(TIME,),
            timeout=3,
        ),
        Scenario(
            "deadlines/huge-problem-compare-job",
            args=("compare", "bigsuite", "--methods", "pure", "--timeout", "2", "--store", "s.sqlite", "-q"),
            setup=_big_suite,
            codes=(OK,),
            timeout=2,
            writes=("s.sqlite*",),
        ),
        Scenario(
            "deadlines/slow-model",
            args=plan + ("--model", "slow.yaml", "--timeout", "2"),
            setup=files(slow_dot_yaml=slow_model()),
            codes=(TIME, MODEL),
            timeout=2,
        ),
        Scenario(
            "deadlines/planner-fast-downward-too-slow",
            args=("plan", "D.pddl", "mid.pddl", "-q", "--method", "pure", "--timeout", "3"),
            setup=files(mid_dot_pddl=big_problem(3000)),
            codes=(TIME,),
            timeout=3,
        ),
        Scenario(
            "deadlines/validation-of-a-huge-forall",
            args=("plan", "D.pddl", "forall.pddl", "-q", "--method", "pure", "--timeout", "4"),
            setup=files(forall_dot_pddl=_forall_goal(400)),
            codes=(TIME, OK),
            timeout=4,
        ),
        Scenario(
            "deadlines/watch-plan-event-never-answered",
            args=(
                "watch",
                "D.pddl",
                "P.pddl",
                "--events",
                "ev.jsonl",
                "--timeout",
                "2",
                "--planner",
                planner("never.py"),
            ),
            setup=files(ev_dot_jsonl='{"event": "plan"}\n'),
            timeout=2,
            check=says("out-of-time", where="stdout"),
        ),
        Scenario(
            "deadlines/compare-jobs-never-answered",
            args=(
                "compare",
                "suite",
                "--methods",
                "pure,relevance",
                "--timeout",
                "1",
                "--store",
                "s.sqlite",
                "-q",
                "--planner",
                planner("never.py"),
            ),
            setup=_suite,
            budget=6,
            writes=("s.sqlite*",),
        ),
        Scenario(
            "deadlines/single-line-as-fast-as-lines",
            shell="date +%s.%N; $TOOL prune D.pddl line.pddl -o o1.pddl"
            " >/dev/null; date +%s.%N; $TOOL prune D.pddl lines.pddl -o o2.pddl > /dev/null; date +%s.%N",
            setup=files(line_dot_pddl=big_problem(22_000, True), lines_dot_pddl=big_problem(22_000)),
            writes=("o1.pddl", "o2.pddl"),
            check=_ratio_at_most(1.5),
        ),
    ]
    for seconds in (1, 2, 3):
        scenarios.append(
            Scenario(
                f"deadlines/never-answers-{seconds}s",
                args=PLAN_PURE + ("--timeout", str(seconds), "--planner", planner("never.py")),
                codes=(TIME,),
                timeout=seconds,
                quick=seconds == 1,
            )
        )
    return scenarios + _flood_scenarios()


def _big_suite(work: Path) -> None:
    (work / "bigsuite").mkdir()
    shutil.copy(work / "D.pddl", work / "bigsuite" / "domain.pddl")
    write(work, "bigsuite/p01.pddl", big_problem(150_000))


def _forall_goal(objects: int) -> str:
    text = (REPO / "problems" / "coffee-simple.pddl").read_text()
    names = " ".join(f"q{i}" for i in range(objects))
    goal = "(forall (?x ?y ?z - plate) (or (not (clear ?x)) (clear ?x) (clear ?y) (clear ?z)))"
    return text.replace("(:objects", f"(:objects {names} - plate", 1).replace("(:goal (and", f"(:goal (and {goal}", 1)


def _flood_scenarios() -> list[Scenario]:
    def flood(name: str, script: str, codes: tuple, plan_file: bool = False, rss: int = 300) -> Scenario:
        args = PLAN_PURE + ("--timeout", "20", "--planner", planner(script, plan_file))
        return Scenario(f"floods/{name}", args=args, codes=codes, budget=15, max_rss_mb=rss)

    return [
        flood("150-mb-on-stdout", "flood_stdout.py", (PLANNER,)),
        flood("20-mb-single-line-on-stdout", "long_line.py", (PLANNER,)),
        flood("two-million-comment-lines", "comment_lines.py", (NO_VALID,)),
        flood("200-mb-plan-file", "huge_plan_file.py", (PLANNER,), plan_file=True),
        flood("plan-line-of-120000-spaces", "spaces.py", (NO_VALID,)),
        flood("plan-file-is-a-fifo", "fifo_plan.py", (PLANNER,), plan_file=True),
        flood("plan-file-links-to-dev-zero", "zero_plan.py", (PLANNER,), plan_file=True),
        flood("binary-on-stdout", "garbage.py", (PLANNER,)),
        flood("planner-segfaults", "crash.py", (PLANNER,)),
        Scenario(
            "floods/prune-a-10-mb-problem",
            args=("prune", "D.pddl", "big.pddl", "-o", "out.pddl"),
            setup=files(big_dot_pddl=big_problem(150_000)),
            writes=("out.pddl",),
            max_rss_mb=1500,
            budget=80,
        ),
    ]


SCENARIO_BUILDERS.append(deadline_scenarios)


# --------------------------------------------------------------------------- 4. the live session

GOOD_EVENT = {"event": "set", "fact": ["hand-empty"]}
INJECTED = "x ) (:init (coffee-served person_1)) (:metric"


def hostile_events() -> dict[str, bytes]:
    """A bad event line each (bytes: some are not UTF-8)."""

    def add(name) -> bytes:
        return json.dumps({"event": "add", "object": name, "type": "cup", "facts": [["empty", name]]}).encode()

    events = {f"add-named-{label}": add(name) for label, name in _BAD_NAMES.items()}
    events.update(
        {
            "deep-json-array": b"[" * 100_000 + b"]" * 100_000,
            "deep-json-object": b'{"a":' * 100_000 + b"1" + b"}" * 100_000,
            "invalid-utf8-name": b'{"event": "add", "object": "cup\xff", "type": "cup"}',
            "invalid-utf8-outside-strings": b'{"event": "add"\xfe\xff}',
            "lone-surrogate-name": b'{"event": "add", "object": "cup\\ud800", "type": "cup"}',
            "injection-in-type": json.dumps({"event": "add", "object": "cup9", "type": INJECTED}).encode(),
            "injection-in-a-fact": json.dumps({"event": "set", "fact": ["empty", INJECTED]}).encode(),
            "injection-in-a-predicate": json.dumps({"event": "set", "fact": [INJECTED]}).encode(),
            "injection-in-the-goal": json.dumps(
                {"event": "goal", "goal": "(and) ) (:init (coffee-served alice)"}
            ).encode(),
            "comment-in-the-goal": json.dumps({"event": "goal", "goal": "(and) ; )) (:init (x"}).encode(),
            "goal-two-lists": json.dumps({"event": "goal", "goal": "(and) (and)"}).encode(),
            "goal-unknown-object": json.dumps({"event": "goal", "goal": "(coffee-served nobody)"}).encode(),
            "human-injection": json.dumps({"event": "human", "name": INJECTED, "preferences": None}).encode(),
            "cue-list": json.dumps({"event": "cue", "task": ["tea"]}).encode(),
            "remove-a-goal-object": json.dumps({"event": "remove", "object": "alice"}).encode(),
            "unknown-kind": json.dumps({"event": "explode"}).encode(),
            "json-array": b"[1, 2, 3]",
            "json-null": b"null",
            "json-number-name": json.dumps({"event": "add", "object": 7, "type": "cup"}).encode(),
            "facts-not-a-list": json.dumps({"event": "add", "object": "cup9", "type": "cup", "facts": "x"}).encode(),
            "fact-with-a-number": json.dumps({"event": "set", "fact": ["empty", 3]}).encode(),
            "huge-line": b'{"event": "add", "object": "' + b"a" * 2_000_000 + b'", "type": "cup"}',
            "nul-byte": b'{"event": "add", "object": "cup\\u0000x", "type": "cup"}',
            "not-json": b"this is not json",
            "huge-integer": b'{"event": "add", "object": "cup9", "type": "cup", "n": ' + b"9" * 5000 + b"}",
        }
    )
    return events


_BAD_NAMES = {
    "two-words": "two words",
    "semicolon": "cup;9",
    "dash": "-",
    "variable": "?x",
    "keyword": ":init",
    "open-paren": "(",
    "close-paren": ")",
    "digit-first": "9cup",
    "newline": "cup\nnine",
    "tab": "cup\t9",
    "injection": INJECTED,
    "empty": "",
    "spaces": "   ",
    "control": "cup\x1b[31m",
}


def _session_survives(result: Result) -> str | None:
    """Two answers: the bad event refused, the good one after it taken; the snapshot re-reads, nothing injected."""
    from relevance_plan.io import load_domain
    from relevance_plan.pddl.parser import read_problem

    answers = [json.loads(line) for line in result.stdout.splitlines() if line.strip()]
    if len(answers) != 2 or "error" not in answers[0] or "error" in answers[1]:
        return f"expected the bad event refused and the good one taken: {result.stdout[:300]!r}"
    snapshot = read_problem((result.work / "W" / "current.pddl").read_text(), load_domain(result.work / "D.pddl"))
    if any(fact[0] == "coffee-served" for fact in snapshot.init) or snapshot.metric is not None:
        return "the snapshot holds what the event injected"
    return None


def session_scenarios() -> list[Scenario]:
    scenarios = []
    for label, line in hostile_events().items():
        events = line + b"\n" + json.dumps(GOOD_EVENT).encode() + b"\n"
        scenarios.append(
            Scenario(
                f"session/{label}",
                args=("watch", "D.pddl", "P.pddl", "--events", "ev.jsonl", "--snapshot", "W"),
                setup=files(ev_dot_jsonl=events),
                writes=("W/*", "W"),
                check=_session_survives,
                quick=label in ("deep-json-array", "add-named-injection", "invalid-utf8-name"),
            )
        )
    stdin_events = hostile_events()["add-named-two-words"] + b"\n" + json.dumps(GOOD_EVENT).encode() + b"\n"
    return scenarios + [
        Scenario(
            "session/events-on-stdin",
            args=("watch", "D.pddl", "P.pddl", "--snapshot", "W"),
            stdin=stdin_events,
            writes=("W/*", "W"),
            check=_session_survives,
        ),
        Scenario(
            "session/sigterm-exits-130-with-a-snapshot",
            shell="mkfifo ev; $TOOL watch D.pddl P.pddl --events ev --snapshot W & tool=$!; exec 3> ev; "
            "echo '" + json.dumps(GOOD_EVENT) + "' >&3; sleep 3; kill -TERM $tool; wait $tool; echo exit=$?; "
            "exec 3>&-; test -s W/current.pddl",
            writes=("W/*", "W", "ev"),
            budget=25,
            check=says("exit=130", where="stdout"),
        ),
        Scenario(
            "session/answers-a-live-pipe-at-once",
            shell="mkfifo ev; { echo '" + json.dumps(GOOD_EVENT) + "'; sleep 6; } > ev & "
            "$TOOL watch D.pddl P.pddl --events ev > answers & sleep 4; wc -l < answers; wait",
            writes=("ev", "answers"),
            check=lambda r: None if r.stdout.split()[:1] == ["1"] else f"no answer before the end: {r.stdout!r}",
        ),
        Scenario(
            "session/piped-into-head",
            shell="yes '" + json.dumps(GOOD_EVENT) + "' | head -5000 | $TOOL watch D.pddl P.pddl | head -1; "
            "echo exit=${PIPESTATUS[2]}",
            check=lambda r: (
                None
                if re.search(r"exit=(0|141)\b", r.stdout) and not r.stderr.strip()
                else f"not a quiet end: {r.stdout[-30:]!r} {r.stderr[-200:]!r}"
            ),
        ),
    ]


SCENARIO_BUILDERS.append(session_scenarios)


# --------------------------------------------------------------------------- 5. messages and codes


def _domain_edit(old: str, new: str, count: int = 1) -> str:
    text = (REPO / "domains" / "coffee" / "domain.pddl").read_text()
    assert old in text, old
    return text.replace(old, new, count)


def bad_domains() -> dict[str, tuple[str, str]]:
    """A domain with one mistake of its own, and what the message must name."""
    text = (REPO / "domains" / "coffee" / "domain.pddl").read_text()
    first = text.index("(:action")
    second = text.index("(:action", first + 1)
    return {
        "action-defined-twice": (text[:second] + text[first:second] + text[second:], "defined twice"),
        "predicate-declared-twice": (_domain_edit("(:predicates", "(:predicates (hand-empty)"), "declared twice"),
        "undeclared-predicate": (_domain_edit("(hand-empty)", "(hand-emptyx)"), "unknown predicate"),
        "undeclared-type-in-parameters": (_domain_edit("?c - cup", "?c - mug"), "unknown type"),
        "undeclared-type-in-predicates": (
            _domain_edit("(:predicates", "(:predicates (owns ?x - gizmo)"),
            "unknown type",
        ),
        "constant-of-unknown-type": (
            _domain_edit("(:predicates", "(:constants k1 - gizmo) (:predicates"),
            "unknown type",
        ),
        "unknown-section": (_domain_edit("(:predicates", "(:gadgets) (:predicates"), "unknown domain section"),
        "unknown-variable": (
            _domain_edit("(robot-at ?c) (hand-empty)", "(robot-at ?nowhere) (hand-empty)"),
            "unknown variable",
        ),
        "wrong-arity": (_domain_edit("(hand-empty)", "(hand-empty ?c)"), "arguments"),
        "undeclared-function": (
            _domain_edit("(robot-at ?c) (hand-empty)", "(robot-at ?c) (> (weight ?c) 3)"),
            "function",
        ),
    }


def message_scenarios() -> list[Scenario]:
    scenarios = [
        Scenario(
            f"messages/domain-{label}",
            args=("score", "bad.pddl", "P.pddl"),
            setup=files(bad_dot_pddl=text),
            codes=(PDDL,),
            check=says("bad.pddl:", needle),
            quick=label == "action-defined-twice",
        )
        for label, (text, needle) in bad_domains().items()
    ]
    problem = (REPO / "problems" / "coffee-simple.pddl").read_text()
    no_init = problem[: problem.index("(:init")] + problem[problem.index("(:goal") :]
    scenarios += [
        Scenario(
            "messages/no-init-ends-with-the-translators-complaint",
            args=PLAN_PURE[:2] + ("noinit.pddl",) + PLAN_PURE[3:],
            setup=files(noinit_dot_pddl=no_init),
            codes=(PDDL,),
            check=lambda r: None if r.stderr.strip().endswith(":init") else f"ends so: {r.stderr[-120:]!r}",
        ),
        Scenario(
            "messages/cr-line-endings-with-a-comment",
            args=("score", "D.pddl", "cr.pddl"),
            setup=files(cr_dot_pddl=("; a comment\n" + problem).replace("\n", "\r")),
        ),
        Scenario(
            "messages/only-whitespace",
            args=("score", "D.pddl", "ws.pddl"),
            setup=files(ws_dot_pddl="\r\n \t\r"),
            codes=(PDDL,),
            check=says("empty"),
        ),
        Scenario(
            "messages/only-comments-is-not-empty",
            args=("score", "D.pddl", "c.pddl"),
            setup=files(c_dot_pddl="; one\r; two\r"),
            codes=(PDDL,),
            check=says("only comments"),
        ),
        Scenario(
            "messages/problem-of-another-domain",
            args=("score", "D.pddl", "other.pddl"),
            setup=files(other_dot_pddl=problem.replace("(:domain coffee)", "(:domain cereal)")),
            codes=(MISMATCH,),
        ),
        Scenario(
            "messages/planner-deletes-its-folder",
            args=PLAN_PURE + ("--planner", planner("remove_workdir.py")),
            codes=(PLANNER,),
            check=says("removed its working folder"),
        ),
        Scenario(
            "messages/planner-deletes-its-folder-and-plan",
            args=PLAN_PURE + ("--planner", planner("remove_workdir.py", True)),
            codes=(PLANNER,),
        ),
        Scenario(
            "messages/full-temporary-folder-is-not-a-crash",
            args=PLAN_PURE + ("--planner", planner("no_space.py")),
            codes=(INPUT,),
            check=says("no space left"),
        ),
        Scenario(
            "messages/exit-codes-to-dev-full",
            shell="$TOOL exit-codes > /dev/full; echo exit=$?",
            check=_quiet_code(INPUT, one_line=True),
            quick=True,
        ),
        Scenario(
            "messages/score-to-dev-full",
            shell="$TOOL score D.pddl P.pddl > /dev/full; echo exit=$?",
            check=_quiet_code(INPUT, one_line=True),
        ),
        Scenario(
            "messages/score-into-head",
            shell="$TOOL score D.pddl big.pddl --scorer goal | head -1 > /dev/null; echo exit=${PIPESTATUS[0]}",
            setup=files(big_dot_pddl=big_problem(3000)),
            check=_quiet_code(0, 141),
        ),
        Scenario(
            "messages/exit-codes-into-head",
            shell="$TOOL exit-codes | head -1 > /dev/null; echo exit=${PIPESTATUS[0]}",
            check=_quiet_code(0, 141),
        ),
        Scenario(
            "messages/stdout-closed",
            shell="$TOOL score D.pddl P.pddl >&-; echo exit=$? >&2",
            check=lambda r: None if "exit=31" in r.stderr else f"not refused: {r.stderr[-100:]!r}",
        ),
        Scenario(
            "messages/stdin-closed-for-watch",
            shell="$TOOL watch D.pddl P.pddl <&-; echo exit=$?",
            check=_quiet_code(0, INPUT, one_line=True),
        ),
        Scenario("messages/process-substitution-for-score", shell="$TOOL score <(cat D.pddl) P.pddl > /dev/null"),
        Scenario(
            "messages/process-substitution-refused-by-plan",
            shell="$TOOL plan <(cat D.pddl) P.pddl -q; echo exit=$?",
            check=_quiet_code(INPUT, one_line=True),
        ),
        Scenario("messages/dev-stdin-for-prune", shell="$TOOL prune D.pddl /dev/stdin -o - < P.pddl > /dev/null"),
        Scenario(
            "messages/dev-stdin-refused-by-plan",
            shell="$TOOL plan D.pddl /dev/stdin -q --method pure < P.pddl; echo exit=$?",
            check=_quiet_code(INPUT, one_line=True),
        ),
        Scenario("messages/directory-as-domain", args=("score", "planners", "P.pddl"), codes=(INPUT,)),
        Scenario("messages/device-as-problem", args=("score", "D.pddl", "/dev/zero"), codes=(INPUT,)),
        Scenario(
            "messages/tool-out-of-memory",
            shell="ulimit -v 400000; $TOOL score D.pddl big.pddl > /dev/null; echo exit=$?",
            setup=files(big_dot_pddl=big_problem(150_000)),
            check=_quiet_code(21, one_line=True),
        ),
        Scenario(
            "messages/no-home-and-c-locale",
            args=("score", "D.pddl", "P.pddl"),
            env=(("HOME", "/nonexistent"), ("LC_ALL", "C")),
        ),
    ]
    return scenarios


def _quiet_code(*codes: int, one_line: bool = False) -> Callable[[Result], str | None]:
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


SCENARIO_BUILDERS.append(message_scenarios)


# --------------------------------------------------------------------------- 6. temporal, numeric, PDDL3


def temporal_scenarios() -> list[Scenario]:
    t, n = "temporal/domain.pddl", "numeric/domain.pddl"
    tp = ("plan", t, "temporal/p1.pddl", "-q", "--plan-file", "out.plan")

    def problem_edit(old: str, new: str) -> Callable[[Path], None]:
        return files(temporal__bad_dot_pddl=TEMPORAL_PROBLEM.replace(old, new))

    def domain_edit(old: str, new: str) -> Callable[[Path], None]:
        return files(temporal__baddomain_dot_pddl=TEMPORAL_DOMAIN.replace(old, new))

    return [
        Scenario("temporal/score", args=("score", t, "temporal/p1.pddl")),
        Scenario("temporal/prune", args=("prune", t, "temporal/p1.pddl", "-o", "out.pddl"), writes=("out.pddl",)),
        Scenario(
            "temporal/fast-downward-refuses-in-one-line",
            args=tp + ("--planner", "fast-downward"),
            codes=(UNSUPPORTED,),
            quick=True,
        ),
        Scenario(
            "temporal/timed-plan-validated", args=tp + ("--planner", planner("timed_plan.py")), writes=("out.plan",)
        ),
        Scenario(
            "temporal/timed-plan-on-a-pruned-problem-json",
            args=tp + ("--json", "--planner", planner("timed_plan.py")),
            writes=("out.plan",),
            check=says('"status": "solved"', where="stdout"),
        ),
        Scenario(
            "temporal/watch-a-durative-scene",
            args=("watch", t, "temporal/p1.pddl", "--events", "ev.jsonl"),
            setup=files(ev_dot_jsonl=json.dumps({"event": "set", "fact": ["open", "x3"]}) + "\n"),
        ),
        Scenario(
            "temporal/malformed-duration",
            args=("score", "temporal/baddomain.pddl", "temporal/p1.pddl"),
            setup=domain_edit("(= ?duration (dist ?a ?b))", "(> ?duration)"),
            codes=(PDDL,),
        ),
        Scenario(
            "temporal/duration-without-duration-variable",
            args=("score", "temporal/baddomain.pddl", "temporal/p1.pddl"),
            setup=domain_edit("(= ?duration (dist ?a ?b))", "(= (fuel) 3)"),
            codes=(PDDL,),
        ),
        Scenario(
            "temporal/undeclared-function",
            args=("score", "temporal/baddomain.pddl", "temporal/p1.pddl"),
            setup=domain_edit("(>= (fuel) (dist ?a ?b))", "(>= (battery) 1)"),
            codes=(PDDL,),
        ),
        Scenario(
            "temporal/negative-til-time",
            args=("score", t, "temporal/bad.pddl"),
            setup=problem_edit("(at 4 (open p2))", "(at -4 (open p2))"),
            codes=(PDDL,),
        ),
        Scenario(
            "temporal/til-of-an-unknown-object",
            args=("score", t, "temporal/bad.pddl"),
            setup=problem_edit("(at 4 (open p2))", "(at 4 (open p9))"),
            codes=(MISMATCH,),
        ),
        Scenario(
            "temporal/initial-value-not-a-number",
            args=("score", t, "temporal/bad.pddl"),
            setup=problem_edit("(= (fuel) 20)", "(= (fuel) lots)"),
            codes=(UNSUPPORTED, PDDL),
        ),
        Scenario(
            "temporal/huge-number",
            args=("score", t, "temporal/bad.pddl"),
            setup=problem_edit("(= (fuel) 20)", "(= (fuel) 1e999)"),
            codes=(OK, PDDL),
        ),
        Scenario(
            "temporal/pddl-plus-process",
            args=("score", "temporal/baddomain.pddl", "temporal/p1.pddl"),
            setup=domain_edit(
                "(:durative-action drive",
                "(:process leak :parameters () :precondition (and) "
                ":effect (decrease (fuel) (* #t 1))) (:durative-action drive",
            ),
            codes=(UNSUPPORTED,),
        ),
        Scenario(
            "temporal/pddl-plus-requirement",
            args=("score", "temporal/baddomain.pddl", "temporal/p1.pddl"),
            setup=domain_edit(":timed-initial-literals)", ":timed-initial-literals :continuous-effects)"),
            codes=(UNSUPPORTED,),
        ),
        Scenario(
            "temporal/object-fluents",
            args=("score", "temporal/baddomain.pddl", "temporal/p1.pddl"),
            setup=domain_edit("(fuel))", "(fuel) (tank) - place)"),
            codes=(UNSUPPORTED,),
        ),
        Scenario("numeric/score", args=("score", n, "numeric/p1.pddl")),
        Scenario(
            "numeric/prune", args=("prune", n, "numeric/p1.pddl", "-o", "-"), check=says("(value c1)", where="stdout")
        ),
        Scenario(
            "numeric/fast-downward-refuses",
            args=("plan", n, "numeric/p1.pddl", "-q", "--planner", "fast-downward"),
            codes=(UNSUPPORTED,),
        ),
        Scenario(
            "pddl3/prune-keeps-constraints",
            args=("prune", "D.pddl", "P3.pddl", "-o", "-"),
            check=says(":constraints", "preference", where="stdout"),
        ),
        Scenario(
            "pddl3/fast-downward-refuses",
            args=("plan", "D.pddl", "P3.pddl", "-q", "--planner", "fast-downward"),
            codes=(UNSUPPORTED,),
        ),
    ]


SCENARIO_BUILDERS.append(temporal_scenarios)


# --------------------------------------------------------------------------- 7. stores, batches and models


def _store_missing_a_column(work: Path) -> None:
    import sqlite3

    with sqlite3.connect(work / "s.sqlite") as connection:
        connection.execute("CREATE TABLE results (problem_hash TEXT, method TEXT)")
        connection.execute("CREATE TABLE meta (key TEXT PRIMARY KEY, value TEXT)")
        connection.execute("INSERT INTO meta VALUES ('schema_version', '1')")


def store_scenarios() -> list[Scenario]:
    compare = ("compare", "suite", "--methods", "pure", "--store", "s.sqlite", "-q", "--timeout", "30")
    return [
        Scenario(
            "stores/compare-into-a-store-missing-a-column",
            args=compare + ("--planner", planner("never.py")),
            setup=both(_suite, _store_missing_a_column),
            codes=(STORE,),
            budget=10,
        ),
        Scenario(
            "stores/report-a-store-missing-a-column",
            args=("report", "s.sqlite"),
            setup=_store_missing_a_column,
            codes=(STORE,),
        ),
        Scenario("stores/report-a-text-file", args=("report", "notes"), setup=files(notes="hello\n"), codes=(STORE,)),
        Scenario(
            "stores/compare-store-is-the-domain",
            args=("compare", "suite", "--store", "suite/domain.pddl"),
            setup=_suite,
            codes=(USAGE, STORE),
        ),
        Scenario(
            "stores/dangling-problem-link-is-one-job",
            args=compare + ("--planner", planner("timed_plan.py")),
            setup=both(_suite, link("suite/p02.pddl", "gone.pddl")),
            writes=("s.sqlite*",),
            check=says("2 jobs", where="stdout"),
        ),
        Scenario(
            "stores/fifo-problem-is-one-job",
            args=compare + ("--planner", planner("timed_plan.py")),
            setup=both(_suite, lambda w: os.mkfifo(w / "suite" / "p02.pddl")),
            writes=("s.sqlite*",),
            budget=30,
        ),
        Scenario(
            "stores/full-disk-leaves-no-empty-store",
            shell="ulimit -f 1; $TOOL compare suite --methods pure "
            "--store s.sqlite -q --planner '" + planner("timed_plan.py") + "'; echo exit=$?; test ! -e s.sqlite"
            " || test -s s.sqlite",
            setup=_suite,
            writes=("s.sqlite*",),
            check=_quiet_code(0, STORE, INPUT, one_line=True),
        ),
        Scenario(
            "stores/report-json-and-csv-together",
            args=("report", "s.sqlite", "--json", "--csv"),
            setup=_store,
            codes=(USAGE,),
        ),
    ] + _model_scenarios()


def bad_models() -> dict[str, str]:
    text = (REPO / "domains" / "coffee" / "relevance.yaml").read_text()
    return {
        "entropy-bound-nan": text.replace("entropy_bound: 1.0", "entropy_bound: .nan"),
        "scene-predicate-as-a-list": text.replace("location: at", "location: [at, on]"),
        "scene-predicate-the-domain-lacks": text.replace("location: at", "location: floats-at"),
        "dependency-on-an-unknown-predicate": text.replace(
            "dependencies: []", "dependencies: [{predicate: glued, when_kept: 1, restore: 2, reason: x}]"
        ),
        "dependency-position-beyond-arity": text.replace(
            "dependencies: []", "dependencies: [{predicate: at, when_kept: 1, restore: 7, reason: x}]"
        ),
        "integer-of-5000-digits": text.replace("entropy_bound: 1.0", "entropy_bound: " + "9" * 5000),
        "probability-above-one": text.replace("coffee: 0.98", "coffee: 1.98", 1),
        "not-a-mapping": "- just\n- a list\n",
        "alias-bomb": "a0: &a0 [x, x, x, x, x, x, x, x, x]\n"
        + "".join(f"a{i}: &a{i} [" + ", ".join([f"*a{i - 1}"] * 9) + "]\n" for i in range(1, 9)),
        "deep-nesting": "a: " + "[" * 5000 + "]" * 5000 + "\n",
        "binary": "\x00\x01\x02 not yaml",
    }


def _model_scenarios() -> list[Scenario]:
    scenarios = [
        Scenario(
            f"models/{label}",
            args=("score", "D.pddl", "P.pddl", "--model", "bad.yaml"),
            setup=files(bad_dot_yaml=text),
            codes=(MODEL,),
            quick=label == "entropy-bound-nan",
        )
        for label, text in bad_models().items()
    ]
    broken = files(relevance_dot_yaml="version: [unclosed\n")
    return scenarios + [
        Scenario(
            "models/broken-model-beside-the-domain-is-not-needed-by-goal",
            args=("score", "D.pddl", "P.pddl", "--scorer", "goal"),
            setup=broken,
        ),
        Scenario(
            "models/broken-model-beside-the-domain-refused-by-model",
            args=("score", "D.pddl", "P.pddl", "--scorer", "model"),
            setup=broken,
            codes=(MODEL,),
        ),
    ]


SCENARIO_BUILDERS.append(store_scenarios)


# --------------------------------------------------------------------------- 8. every other command


def command_scenarios() -> list[Scenario]:
    return [
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
        Scenario("commands/sweep-nan-tau", args=("sweep", "suite", "--taus", "nan"), setup=_suite, codes=(USAGE,)),
        Scenario(
            "commands/sweep-of-a-hostile-suite",
            args=("sweep", "suite", "--scorer", "goal"),
            setup=both(_suite, files(suite__p02_dot_pddl="(define (problem"), link("suite/p03.pddl", "nowhere")),
            codes=(OK, PDDL),
        ),
        Scenario("commands/compare-zero-jobs", args=("compare", "suite", "--jobs", "0"), setup=_suite, codes=(USAGE,)),
        Scenario(
            "commands/compare-unknown-method",
            args=("compare", "suite", "--methods", "magic"),
            setup=_suite,
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
        Scenario(
            "commands/score-tau-above-one", args=("score", "D.pddl", "P.pddl", "--tau-class", "2"), codes=(USAGE,)
        ),
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


SCENARIO_BUILDERS.append(command_scenarios)


# --------------------------------------------------------------------------- 9. supervision faults
# Kills of the guard and of the planner at moments drawn from a seeded generator, links put in place of
# the planner's working folder or log, limits on open files, negative initial literals of pruned objects.

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
        env=_environment(Scenario("generate")),
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
            victims = [guards[-1]]
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


def fault_scenarios() -> list[Scenario]:
    import random

    moments = random.Random(FAULT_SEED)
    scenarios = []
    never = planner("never.py")
    long = ("plan", "long/domain.pddl", "long/coffee-hard-001.pddl", "-q", "--plan-file", "out.plan")
    guard_killed = says("guard was killed (by SIGKILL)")
    # the guard killed: at once a planner error, whatever the other side of a race is doing (--timeout 60:
    # waiting for it would miss the 20 s budget)
    for _ in range(4):
        delay = round(moments.uniform(0.0, 3.0), 2)
        scenarios += [
            Scenario(
                f"faults/guard-of-fast-downward-killed-at-{delay}s",
                args=(*long, "--method", "pure", "--timeout", "60"),
                setup=_long_problem,
                codes=(PLANNER,),
                during=_kill_after(delay),
                budget=20 + delay,
                check=guard_killed,
                writes=("long", "long/*"),
            ),
            Scenario(
                f"faults/guard-of-a-pruned-attempt-killed-at-{delay}s-in-a-race",
                args=(*PLAN_PURE[:3], "--race", "-q", "--plan-file", "out.plan", "--timeout", "60", "--planner", never),
                codes=(PLANNER,),
                during=_kill_after(delay, b"pruned-"),
                budget=20 + delay,
                check=guard_killed,
            ),
            Scenario(
                f"faults/guard-of-the-race-killed-at-{delay}s",
                args=(*PLAN_PURE[:3], "--race", "-q", "--plan-file", "out.plan", "--timeout", "60", "--planner", never),
                codes=(PLANNER,),
                during=_kill_after(delay, b"P.pddl"),
                budget=20 + delay,
                check=guard_killed,
            ),
        ]
    # the planner killed (the driver, or a component of it): a planner error, nothing left behind
    for depth, whom in ((1, "driver"), (2, "component")):
        for _ in range(2):
            delay = round(moments.uniform(0.3, 3.0), 2)
            scenarios.append(
                Scenario(
                    f"faults/fast-downward-{whom}-killed-at-{delay}s",
                    args=(*long, "--method", "pure", "--timeout", "60"),
                    setup=_long_problem,
                    codes=(PLANNER,),
                    during=_kill_after(delay, depth=depth),
                    budget=20 + delay,
                    writes=("long", "long/*"),
                )
            )
    # links and strangers in the planner's working folder: nothing written to the user's folder (the
    # workspace's fingerprint), nothing left in TMPDIR
    for name in FAULT_PLANNERS:
        scenarios.append(
            Scenario(
                f"faults/planner-{name.removesuffix('.py').replace('_', '-')}",
                shell=f"mkdir -p {_FAULT_TMP} && TMPDIR=$PWD/{_FAULT_TMP} exec $TOOL plan D.pddl P.pddl --method pure"
                f" -q --plan-file out.plan --planner 'cmd:{{w}}/planners/{name} {{w}}/mine {{domain}} {{problem}}'",
                setup=_fault_planners,
                codes=(OK, PLANNER, NO_VALID),
                check=_tmp_left_empty,
                writes=(_FAULT_TMP, "out.plan"),
            )
        )
    # limits on open files, with and without a descriptor the shell left open above the limit
    for limit in (16, 12, 10):
        for stray in ("", "exec 20</dev/null; "):
            for method in ("pure", "relevance"):
                scenarios.append(
                    Scenario(
                        f"faults/ulimit-n-{limit}{'-fd-20-open' if stray else ''}-{method}",
                        shell=f"{stray}ulimit -n {limit} && exec $TOOL plan D.pddl P.pddl --method {method} -q"
                        " --plan-file out.plan --timeout 60",
                        writes=("out.plan",),
                    )
                )
    # negative initial literals about pruned objects: cut with them; the list and the flat reading of :init
    for blocks in (40, 800):
        scenarios += [
            Scenario(
                f"faults/negative-literals-of-pruned-objects-cut-{blocks}-blocks",
                args=("prune", "B.pddl", "N.pddl", "-o", "pruned.pddl"),
                setup=_blocks_with_negative_literals(blocks),
                check=_no_negative_literal_of_a_pruned_object,
                writes=("pruned.pddl",),
            ),
            Scenario(
                f"faults/negative-literals-of-pruned-objects-plan-{blocks}-blocks",
                args=("plan", "B.pddl", "N.pddl", "--no-race", "--json", "-q", "--plan-file", "out.plan"),
                setup=_blocks_with_negative_literals(blocks),
                check=_solved_at_first_attempt,
                writes=("out.plan",),
            ),
        ]
    return scenarios


SCENARIO_BUILDERS.append(fault_scenarios)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0],
        epilog="Every scenario takes about 10 minutes on 2 cores; --quick takes under a minute.",
        formatter_class=argparse.RawTextHelpFormatter,
    )
    parser.add_argument("--quick", action="store_true", help="only the short subset the test suite runs")
    parser.add_argument("--only", action="append", default=[], metavar="NAME", help="run this scenario (repeatable)")
    parser.add_argument(
        "--class", dest="kind", metavar="CLASS", help="only the scenarios named CLASS/... (e.g. faults)"
    )
    parser.add_argument("--list", action="store_true", help="list the scenarios and exit")
    options = parser.parse_args(argv)
    scenarios = all_scenarios()
    if options.only:
        unknown = set(options.only) - {s.name for s in scenarios}
        if unknown:
            parser.error(f"unknown scenario(s): {', '.join(sorted(unknown))}")
        scenarios = [s for s in scenarios if s.name in options.only]
    elif options.kind:
        scenarios = [s for s in scenarios if s.name.split("/")[0] == options.kind]
    elif options.quick:
        scenarios = [s for s in scenarios if s.quick]
    if options.list:
        for scenario in scenarios:
            print(scenario.name + ("  (quick)" if scenario.quick else ""))
        return 0
    subreaper = become_subreaper()
    startup = measure_startup()
    print(f"{len(scenarios)} scenarios; tool start-up {startup:.2f} s; subreaper: {'yes' if subreaper else 'no'}")
    failures = skipped = 0
    tally: dict[str, dict[str, int]] = {}  # class (the name's first part) -> verdict -> count
    with tempfile.TemporaryDirectory(prefix="relevance-plan-hostile-") as root:
        for scenario in scenarios:
            verdict, reasons, seconds = run_one(scenario, Path(root), startup)
            failures += verdict == "FAIL"
            skipped += verdict == "SKIP"
            counts = tally.setdefault(scenario.name.split("/")[0], {"PASS": 0, "FAIL": 0, "SKIP": 0})
            counts[verdict] += 1
            print(f"{verdict}  {scenario.name}  ({seconds:.1f} s)" + "".join(f"\n      {r}" for r in reasons))
            sys.stdout.flush()
    for kind, counts in tally.items():
        print(f"  {kind}: {counts['PASS']} of {counts['PASS'] + counts['FAIL']} passed, {counts['SKIP']} skipped")
    ran = len(scenarios) - skipped
    print(f"{ran} scenarios run, {ran - failures} passed, {failures} failed, {skipped} skipped")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
