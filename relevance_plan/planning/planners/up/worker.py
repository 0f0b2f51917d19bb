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
"""

from __future__ import annotations

import json
import resource
import socket
import sys

from relevance_plan.planning.planners.up.child import register_engine, solve_files

# Printed to the log before each request's output, so the tool can cut out one attempt's part.
HEADER = "=== request {number}"


def _used() -> tuple[float, float]:
    """(cpu seconds, peak memory MB) of this process and the children it reaped."""
    own, children = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = own.ru_utime + own.ru_stime + children.ru_utime + children.ru_stime
    return cpu, max(own.ru_maxrss, children.ru_maxrss) / 1024.0


def main(arguments: list[str]) -> int:
    engine, address = arguments
    import unified_planning.io  # noqa: F401
    import unified_planning.shortcuts as shortcuts  # the cost every attempt's child paid: paid once here

    shortcuts.get_environment().credits_stream = None
    register_engine(engine)
    try:
        shortcuts.get_environment().factory.engine(engine)  # loads the engine's own modules
    except Exception as error:  # the request's answer will say what is wrong
        print(f"{engine}: cannot load the engine: {type(error).__name__}: {error}", flush=True)
    connection = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    connection.connect(address)
    with connection, connection.makefile("rwb") as stream:
        for number, line in enumerate(stream, start=1):
            request = json.loads(line)
            print(HEADER.format(number=number), flush=True)
            before, _ = _used()
            code = solve_files(
                engine, request["domain"], request["problem"], request["plan"], request["verdict"], request["timeout"]
            )
            sys.stdout.flush()
            sys.stderr.flush()
            after, peak = _used()
            answer = {"code": code, "cpu_time": after - before, "peak_memory_mb": peak}
            stream.write(json.dumps(answer).encode() + b"\n")
            stream.flush()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
