"""Scene graphs that cannot be imported, and a ZMQ publisher that sends garbage then stops: one line and its
exit code, nothing written; a live session that carries on past the bad update."""

from __future__ import annotations

import copy
import json
import os
from functools import lru_cache
from pathlib import Path

from support import REPO

from hostile.inputs import files, installed, says
from hostile.scenario import INPUT, OK, USAGE, Result, Scenario, scenario_test

APARTMENT = REPO / "benchmarks" / "corpus" / "spark-dsg" / "scene-graphs" / "apartment_dsg.json"
LABELS = b"objects: {5: chair, 11: lamp, 16: table}\nrooms: {0: living room}\n"
GOAL = "(on lamp_o84 table_o33)"
IMPORT = ("scene-graph", "import", "G.json", "-o", "out", "--labels", "L.yaml", "--goal", GOAL)
needs_spark_dsg = installed("spark_dsg")


@lru_cache(maxsize=1)
def apartment() -> dict:
    return json.loads(APARTMENT.read_text())


def changed(change) -> bytes:
    graph = copy.deepcopy(apartment())
    change(graph)
    return json.dumps(graph).encode()


def _dangling(graph: dict) -> None:
    graph["edges"].append(
        {
            "info": {"type": "EdgeAttributes", "weight": 1.0, "weighted": True},
            "source": 12345,
            "target": graph["nodes"][10]["id"],
        }
    )


def _layer_seven(graph: dict) -> None:
    graph["nodes"][0]["layer"] = 7
    graph["layer_ids"].append(7)


def _nan(graph: dict) -> None:
    graph["nodes"][0]["attributes"]["position"][0] = float("nan")


BAD_GRAPHS = {
    "truncated": lambda: APARTMENT.read_bytes()[:300_000],
    "dangling-edge": lambda: changed(_dangling),
    "unknown-layer": lambda: changed(_layer_seven),
    "duplicate-id": lambda: changed(lambda g: g["nodes"].append(copy.deepcopy(g["nodes"][0]))),
    "nan-position": lambda: changed(_nan),
    "empty": lambda: b"",
    "not-json": lambda: b"\x89PNG\r\n\x1a\n" + bytes(range(256)),
    "json-list": lambda: b"[1, 2, 3]",
}


def _nothing_written(result: Result) -> str | None:
    return "out/ has files" if (result.work / "out").exists() and any((result.work / "out").iterdir()) else None


def _bad_graph(label: str, make) -> Scenario:
    return Scenario(
        f"scene-graphs/{label}",
        args=IMPORT,
        setup=files(G_dot_json=make, L_dot_yaml=LABELS),
        codes=(INPUT,),
        writes=("out",),
        check=_nothing_written,
        quick=label in ("truncated", "dangling-edge", "nan-position"),
        needs=needs_spark_dsg,
    )


def _huge(work: Path) -> None:
    with open(work / "G.json", "wb") as stream:  # a sparse 200 MB file: refused before it is read
        stream.truncate(200 * 2**20)
    (work / "L.yaml").write_bytes(LABELS)


def _blocked(work: Path) -> None:
    """The apartment, and a ``spark_dsg`` first on the path that cannot be imported."""
    (work / "G.json").write_bytes(APARTMENT.read_bytes())
    (work / "L.yaml").write_bytes(LABELS)
    (work / "block" / "spark_dsg").mkdir(parents=True)
    (work / "block" / "spark_dsg" / "__init__.py").write_text("raise ImportError('blocked')\n")


PUBLISHER = """
import sys, time, spark_dsg
from spark_dsg.zmq import DsgSender
graph = spark_dsg.DynamicSceneGraph.load(sys.argv[1])
sender = DsgSender("ipc://zmq.sock")
good = graph.to_binary()
for _ in range(40):  # the subscriber joins whenever it has started; the same graph again is skipped
    sender._socket.send(good)
    time.sleep(0.25)
for message in [b"garbage, not a graph", b"", good[:1000]]:
    for _ in range(4):
        sender._socket.send(message)
        time.sleep(0.2)
"""


def _stream_survives(result: Result) -> str | None:
    lines = [json.loads(line) for line in result.stdout.splitlines() if line.strip()]
    updates = [line for line in lines if line.get("event") == "update"]
    if not updates or not updates[0].get("started"):
        return f"the first update did not start the session: {result.stdout[:300]!r}"
    errors = [line for line in updates[1:] if line.get("error")]
    return None if len(errors) == 3 and len(updates) == 4 else f"expected three refused updates: {updates!r}"[:400]


SCENARIOS = [_bad_graph(label, make) for label, make in BAD_GRAPHS.items()] + [
    Scenario(
        "scene-graphs/unknown-layer-left-out-on-request",
        args=(*IMPORT, "--ignore-unknown-layers"),
        setup=files(G_dot_json=lambda: changed(_layer_seven), L_dot_yaml=LABELS),
        codes=(OK,),
        writes=("out", "out/*"),
        check=says("left out 1 nodes on layer 7", where="stdout"),
        needs=needs_spark_dsg,
    ),
    Scenario(
        "scene-graphs/two-hundred-megabytes",
        args=IMPORT,
        setup=_huge,
        codes=(INPUT,),
        writes=("out",),
        check=says("200 MiB, more than the 64 MiB"),
        budget=10,
        quick=True,
        needs=needs_spark_dsg,
    ),
    Scenario(
        "scene-graphs/without-the-extra",
        args=IMPORT,
        setup=_blocked,
        env=(("PYTHONPATH", os.pathsep.join(["block", str(REPO)])),),
        codes=(USAGE,),
        writes=("out",),
        check=says("needs the 'hydra' extra: pip install 'relevance-plan[hydra]'"),
        quick=True,
    ),
    Scenario(
        "scene-graphs/zmq-publisher-sends-garbage-then-stops",
        shell="${TOOL%% *} pub.py G.json > /dev/null & $TOOL scene-graph watch --zmq ipc://zmq.sock --idle-timeout 3"
        " --labels L.yaml --goal '" + GOAL + "'; wait",
        setup=files(G_dot_json=lambda: APARTMENT.read_bytes(), L_dot_yaml=LABELS, pub_dot_py=PUBLISHER),
        writes=("zmq.sock",),
        check=_stream_survives,
        budget=40,
        needs=needs_spark_dsg,
    ),
]


test_scene_graphs = scenario_test(SCENARIOS)
