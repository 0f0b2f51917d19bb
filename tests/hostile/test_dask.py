"""compare on Dask under faults: ports that answer as no scheduler does, and a scheduler killed mid-run.

A stranger on a port is a thread of the process that runs the scenario (its ``setup``), so nothing it
leaves is taken for the tool's; a real scheduler and worker are the scenario's own shell's children,
stopped by it before it ends.
"""

from __future__ import annotations

import socket
import struct
import threading
from pathlib import Path

from hostile.inputs import both, installed, one_line, planner, quiet_code, suite
from hostile.scenario import SCHEDULER, Scenario, scenario_test

DASK = installed("distributed")
COMPARE = "exec $TOOL compare suite --methods pure --store s.sqlite -q --scheduler-timeout 3"


def stranger(greeting: bytes, close: bool = False):
    """A setup: a server on a free local port (written to the workspace's ``port``) that greets every
    connection with ``greeting``, then closes it (``close``) or keeps it open and says nothing more."""

    def setup(work: Path) -> None:
        listener = socket.create_server(("127.0.0.1", 0))
        (work / "port").write_text(str(listener.getsockname()[1]))

        def serve() -> None:
            kept = []
            while True:
                connection, _ = listener.accept()
                try:
                    connection.sendall(greeting)
                except OSError:
                    pass
                if close:
                    connection.close()
                else:
                    kept.append(connection)

        threading.Thread(target=serve, daemon=True).start()

    return setup


GREETINGS = {
    "text": (b"garbage " * 200, False),
    "a-web-server": (b"HTTP/1.1 400 Bad Request\r\nContent-Length: 0\r\n\r\n", False),
    "silence": (b"", False),
    "closes-at-once": (b"", True),
    "a-short-length-then-garbage": (struct.pack("Q", 16) + b"\xff" * 16, False),
    "a-huge-length": (struct.pack("Q", 2**60), False),
    "nul-bytes": (b"\x00" * 64, False),
}

STRANGERS = [
    Scenario(
        f"dask/a-port-that-is-no-scheduler-{label}",
        shell=COMPARE + " --scheduler tcp://127.0.0.1:$(cat port)",
        setup=both(suite, stranger(greeting, close)),
        codes=(SCHEDULER,),
        check=one_line("Dask"),
        budget=12,
        needs=DASK,
        quick=label == "text",
    )
    for label, (greeting, close) in GREETINGS.items()
]

# A scheduler and a worker of the shell's own; the scheduler killed while the worker runs a job.
_CLUSTER = (
    "PY=${{TOOL%% -m*}}; TOOL_TMPDIR=$TMPDIR; "
    "P=$($PY -c 'import socket; s = socket.socket(); s.bind((\"127.0.0.1\", 0)); print(s.getsockname()[1])'); "
    "mkdir dw; export TMPDIR=$PWD/dw; "  # the cluster's temporary files are its own, not the tool's
    "$PY -m dask scheduler --host 127.0.0.1 --port $P --no-dashboard >/dev/null 2>&1 & S=$!; "
    "$PY -m dask worker tcp://127.0.0.1:$P --nworkers 1 --nthreads 1 --no-dashboard --local-directory dw"
    " >/dev/null 2>&1 & W=$!; sleep 6; "
    "TMPDIR=$TOOL_TMPDIR $TOOL compare suite --methods pure --store s.sqlite -q --timeout 40"
    " --scheduler tcp://127.0.0.1:$P --planner '{planner}' & T=$!; sleep {seconds}; "
    "{{ kill -9 $S; wait $S; }} 2>/dev/null; wait $T; echo exit=$?; kill $W; wait $W"
)
CLUSTER = [
    Scenario(
        "dask/the-scheduler-killed-mid-run",
        shell=_CLUSTER.format(planner=planner("never.py"), seconds=5),
        setup=suite,
        check=quiet_code(SCHEDULER, one_line=True),
        writes=("s.sqlite*", "dw", "dw/*"),
        budget=60,
        needs=DASK,
    ),
]

SCENARIOS = STRANGERS + CLUSTER


test_dask = scenario_test(SCENARIOS)
