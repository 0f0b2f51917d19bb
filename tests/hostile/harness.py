"""The hostile sweep's machinery: one scenario run as a separate process in a fresh workspace, and judged.

A scenario passes only when all of these hold:

* the exit code is the one expected, and one of the documented table (or
  141, a reader that closed the pipe);
* no traceback (nor "Exception ignored") on stderr; a failure ends with a
  ``relevance-plan:`` line;
* no file of the workspace changed (hash, mode and link target before and
  after), except the outputs the scenario names;
* nothing left in the temporary folder: each run gets one of its own (``$TMPDIR``, outside the
  workspace) that must be empty again once it has ended, unless it was killed with SIGKILL
  (then only the guards clean up, and the tool's own scratch folder stays);
* no process left: the process that runs the scenario is a child subreaper
  (Linux), so anything the tool started and lost is re-parented to it and
  found; processes naming the workspace in their command line are looked
  for too;
* the deadline held: with ``--timeout T`` the tool ends within T + 1 s
  after its own start-up (measured once per test session: the median of
  three ``exit-codes`` runs);
* memory bounded: the peak RSS of the tool and what it waited for stays
  under the scenario's limit.

The test process never becomes a subreaper itself (it would adopt, and
this module kill, what other tests leave running): ``check`` runs each
scenario through ``python -m hostile.harness MODULE NAME STARTUP`` in a
process of its own, which prints its verdict as one JSON line.
"""

from __future__ import annotations

import ctypes
import hashlib
import importlib
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
from pathlib import Path

import pytest
from support import REPO, TOOL

from hostile.inputs import BENCH_PLANNERS, PDDL_INPUTS, tool_environment, write
from hostile.scenario import INTERRUPTED, OK, PIPE, Result, Scenario
from relevance_plan.exitcodes import ExitCode
from relevance_plan.supervision.guard import reap_children

TESTS = REPO / "tests"
DOCUMENTED = {int(code) for code in ExitCode} | {PIPE}
HANG_LIMIT = 90.0  # any scenario: killed and failed past this
LEFTOVER_GRACE = 2.0  # the guard's own clean-up after the tool died may take a moment
_BAD_OUTPUT = re.compile(r"Traceback|Exception ignored|^\s+File \"", re.MULTILINE)


# --------------------------------------------------------------------------- the workspace


def make_workspace(root: Path) -> Path:
    work = Path(tempfile.mkdtemp(prefix="hostile-", dir=root))
    shutil.copy(REPO / "domains" / "coffee" / "domain.pddl", work / "D.pddl")
    shutil.copy(REPO / "problems" / "coffee-simple.pddl", work / "P.pddl")
    for name, body in BENCH_PLANNERS.items():
        write(work, f"planners/{name}", f"#!{sys.executable}\n{body}", 0o755)
    for name, text in PDDL_INPUTS.items():
        write(work, name, text)
    return work


def fingerprint(work: Path, allowed: tuple = ()) -> dict[str, tuple]:
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


def _start(scenario: Scenario, work: Path, temporary: Path) -> subprocess.Popen:
    # "{w}": the workspace's absolute path (a planner template needs one: the planner runs elsewhere)
    args = [str(a).replace("{w}", str(work)) for a in scenario.args]
    command = ["bash", "-c", scenario.shell.replace("{w}", str(work))] if scenario.shell else TOOL + args
    return subprocess.Popen(
        command,
        cwd=work,
        env=tool_environment((("TMPDIR", str(temporary)), *scenario.env)),
        stdin=subprocess.PIPE if scenario.stdin is not None else subprocess.DEVNULL,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        start_new_session=True,
    )


def execute(scenario: Scenario, work: Path, temporary: Path) -> Result:
    """Run the scenario's command with ``temporary`` as its $TMPDIR; its rusage covers the tool and
    everything it waited for."""
    started = time.monotonic()
    process = _start(scenario, work, temporary)
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
    temporary = root / f"tmp-{work.name}"
    try:
        if scenario.setup is not None:
            scenario.setup(work)
        before = fingerprint(work, scenario.writes)
        temporary.mkdir()
        result = execute(scenario, work, temporary)
        problems = judge(scenario, result, before, startup)
        left = leftovers(work)
        if left:
            problems.append("processes left: " + "; ".join(left[:3]))
        files = sorted(path.name for path in temporary.iterdir())
        if files and result.code != 128 + signal.SIGKILL:
            problems.append(f"left in the temporary folder: {', '.join(files[:3])}")
        return ("FAIL" if problems else "PASS"), problems, result.elapsed
    finally:
        for folder in (work, temporary):
            _make_removable(folder)
            shutil.rmtree(folder, ignore_errors=True)


def _make_removable(work: Path) -> None:
    for folder, dirs, _ in os.walk(work):
        for name in dirs:
            try:
                (Path(folder) / name).chmod(0o755)
            except OSError:
                pass


def measure_startup() -> float:
    """The tool's start-up, the time before its own clock starts: the median of three trivial runs."""
    env = tool_environment()
    times = []
    for _ in range(3):
        started = time.monotonic()
        subprocess.run(TOOL + ["exit-codes"], env=env, stdout=subprocess.DEVNULL, check=False)
        times.append(time.monotonic() - started)
    return statistics.median(times)


# --------------------------------------------------------------------------- the test process's side


def check(module: str, scenario: Scenario, startup: float) -> None:
    """Run ``scenario`` (of the test module ``module``) in a subreaper process of its own; fail with its reasons."""
    if scenario.needs is not None and (reason := scenario.needs()):
        pytest.skip(reason)
    command = [sys.executable, "-m", "hostile.harness", module, scenario.name, repr(startup)]
    done = subprocess.run(command, cwd=TESTS, capture_output=True, text=True, timeout=HANG_LIMIT + 60)
    lines = done.stdout.strip().splitlines()
    assert done.returncode == 0 and lines, (
        f"the scenario's runner failed (exit {done.returncode}): {done.stderr[-2000:]}"
    )
    verdict = json.loads(lines[-1])
    if verdict["verdict"] == "SKIP":
        pytest.skip("; ".join(verdict["reasons"]))
    assert verdict["verdict"] == "PASS", "\n".join(verdict["reasons"])


def main(argv: list[str]) -> int:
    """The runner: ``MODULE NAME STARTUP``; prints {"verdict", "reasons", "seconds"} as one JSON line."""
    module, name, startup = argv
    (scenario,) = [s for s in importlib.import_module(module).SCENARIOS if s.name == name]
    become_subreaper()
    with tempfile.TemporaryDirectory(prefix="relevance-plan-hostile-") as root:
        verdict, reasons, seconds = run_one(scenario, Path(root), float(startup))
    print(json.dumps({"verdict": verdict, "reasons": reasons, "seconds": round(seconds, 2)}))
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
