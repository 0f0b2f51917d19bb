"""Worker process of the ``up:NAME`` planners: unified-planning and the engine imported once, every attempt solved.

Run as ``python -m relevance_plan.planning.planners.up.worker ENGINE SOCKET``
by ``up.pool.EngineWorker``, under the guard like every planner.  It imports
unified-planning and loads the engine, then connects to the Unix socket
SOCKET (the connection says it is ready) and answers one request a line,
in JSON: ``{"domain", "problem", "plan", "verdict", "timeout"}`` in,
``{"code", "cpu_time", "peak_memory_mb"}`` out, where ``code`` is what the
child (``up.child``) would have exited with and the plan and verdict files
are the child's.  Its output goes to the run's log, one header line per
request.  The tool kills it (and whatever the engine started) when an
attempt overruns, when the race's other side wins, and at the end of the
run; the guard kills it when the tool dies.

A request ``{"fork": SOCKET2, "log": LOG2, "nice": N}`` asks for a copy of the worker
(``os.fork``: unified-planning and the engine come imported, where a new
worker would spend seconds of a core importing them again).  The copy leads
a process group of its own, so that the tool can kill it alone, runs N
steps lower in priority (``os.nice``), writes its
output to LOG2, connects to SOCKET2 and serves its own requests there; the
answer is ``{"pid"}``.  The copy is never reaped here: its pid stays taken
until this worker ends, so the tool cannot kill a stranger by that number.
The race asks for one before the full problem's request, while the worker
is idle and has no engine running.
"""

from __future__ import annotations

import contextlib
import json
import os
import resource
import socket
import sys
import traceback
from typing import Any

from relevance_plan.planning.planners.up.child import register_engine, solve_files
from relevance_plan.planning.planners.up.deferred import defer_configspace

# Printed to the log before each request's output, so the tool can cut out one attempt's part.
HEADER = "=== request {number}"


def _used() -> tuple[float, float]:
    """(cpu seconds, peak memory MB) of this process and the children it reaped."""
    own, children = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = own.ru_utime + own.ru_stime + children.ru_utime + children.ru_stime
    return cpu, max(own.ru_maxrss, children.ru_maxrss) / 1024.0


def main(arguments: list[str]) -> int:
    engine, address = arguments
    defer_configspace()  # a second of a core that no one-shot solve needs
    import unified_planning.io  # noqa: F401
    import unified_planning.shortcuts as shortcuts  # the cost every attempt's child paid: paid once here

    shortcuts.get_environment().credits_stream = None
    register_engine(engine)
    try:
        shortcuts.get_environment().factory.engine(engine)  # loads the engine's own modules
    except Exception as error:  # the request's answer will say what is wrong
        print(f"{engine}: cannot load the engine: {type(error).__name__}: {error}", flush=True)
    _serve(engine, address)
    return 0


def _serve(engine: str, address: str) -> None:
    """Connect to ``address`` and answer its requests until the tool closes the connection."""
    connection = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    connection.connect(address)
    with connection, connection.makefile("rwb") as stream:
        number = 0
        for line in stream:
            request = json.loads(line)
            if "fork" in request:
                answer: dict[str, object] = {
                    "pid": _fork(engine, request["fork"], request["log"], request.get("nice", 0), connection, stream)
                }
            else:
                number += 1
                answer = _solve(engine, number, request)
            stream.write(json.dumps(answer).encode() + b"\n")
            stream.flush()


def _solve(engine: str, number: int, request: dict[str, Any]) -> dict[str, object]:
    print(HEADER.format(number=number), flush=True)
    before, _ = _used()
    code = solve_files(
        engine, request["domain"], request["problem"], request["plan"], request["verdict"], request["timeout"]
    )
    sys.stdout.flush()
    sys.stderr.flush()
    after, peak = _used()
    return {"code": code, "cpu_time": after - before, "peak_memory_mb": peak}


def _fork(engine: str, address: str, log: str, nice: int, *inherited: Any) -> int:
    """A copy of this worker serving ``address``, its output to ``log``, ``nice`` steps lower in
    priority; its pid (its process group)."""
    sys.stdout.flush()
    sys.stderr.flush()
    pid = os.fork()
    if pid:
        with contextlib.suppress(OSError):
            os.setpgid(pid, pid)  # the copy does it too: whichever runs first
        return pid
    code = 1
    try:
        os.setpgid(0, 0)
        if nice:
            os.nice(nice)  # the engine it starts inherits it
        for handle in inherited:  # the parent's connection: its end must close when the parent dies
            handle.close()
        output = os.open(log, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o644)
        os.dup2(output, 1)
        os.dup2(output, 2)
        os.close(output)
        _serve(engine, address)
        code = 0
    except BaseException:
        traceback.print_exc()
    finally:
        sys.stdout.flush()
        sys.stderr.flush()
        os._exit(code)  # never back into the parent's loop


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
