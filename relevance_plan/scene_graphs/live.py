"""Successive scene graphs as the live session's events: each update diffed against the one before.

Both graphs are imported the same way (``problem.import_graph``), so the
difference is one of objects and facts: objects that appear are ``add``
events (with the facts that name only objects already there), facts that
come are ``set``, facts that go are ``unset``, objects that go are
``remove`` (their facts go with them).  The new state is seen before the old
one goes (sets before unsets), as the session's event streams keep it: an
object that moves is at its new place before it leaves the old one.

Updates come from files (one graph each) or from spark-dsg's ZMQ stream
(``spark_dsg.zmq.DsgSender`` publishes each graph in its binary encoding);
an update that cannot be read is an error of that update alone.
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from typing import Any

from relevance_plan.errors import MissingExtraError, SceneGraphError
from relevance_plan.scene_graphs.problem import TYPE_ORDER, ImportedScene


def scene_events(before: ImportedScene, after: ImportedScene) -> list[dict[str, Any]]:
    """The events that turn ``before`` into ``after`` (see the module docstring)."""
    old, new = set(before.facts), set(after.facts)
    gone = [name for name in before.objects if name not in after.objects or after.objects[name] != before.objects[name]]
    gone_set = set(gone)
    present = {name for name in before.objects if name not in gone_set}
    events: list[dict[str, Any]] = []
    added = sorted(
        (name for name in after.objects if name not in present), key=lambda n: (TYPE_ORDER.index(after.objects[n]), n)
    )
    by_object: dict[str, list[tuple[str, ...]]] = {}
    for fact in sorted(new - old):
        by_object.setdefault(fact[1] if len(fact) > 1 else "", []).append(fact)
    placed: set[tuple[str, ...]] = set()
    for name in added:
        present.add(name)
        facts = [f for f in sorted(new - old) if name in f[1:] and all(a in present for a in f[1:]) and f not in placed]
        placed.update(facts)
        events.append({"event": "add", "object": name, "type": after.objects[name], "facts": [list(f) for f in facts]})
    events += [{"event": "set", "fact": list(f)} for f in sorted(new - old - placed)]
    events += [{"event": "unset", "fact": list(f)} for f in sorted(old - new) if not gone_set.intersection(f[1:])]
    events += [{"event": "remove", "object": name} for name in gone]
    return events


@dataclass(frozen=True)
class Update:
    """One graph of a stream: its number, where it came from, and its bytes or the file it is in."""

    number: int
    source: str
    data: bytes | None = None
    path: str | None = None
    error: str | None = None  # the stream itself failed here


def file_updates(paths: Sequence[str]) -> Iterator[Update]:
    for number, path in enumerate(paths, start=1):
        yield Update(number, path, path=path)


def zmq_updates(url: str, idle_timeout: float, max_bytes: int, first_timeout: float | None = None) -> Iterator[Update]:
    """The graphs a spark-dsg publisher sends to ``url``, until none came for ``idle_timeout`` seconds
    (``first_timeout`` for the first); a message equal to the one before is skipped."""
    try:
        import zmq
    except ImportError:
        from relevance_plan.scene_graphs.dsg import HYDRA_EXTRA_INSTALL

        raise MissingExtraError(f"following a ZMQ stream needs the 'hydra' extra: {HYDRA_EXTRA_INSTALL}") from None
    context = zmq.Context()
    socket = context.socket(zmq.SUB)
    try:
        socket.setsockopt(zmq.MAXMSGSIZE, max_bytes)
        socket.setsockopt(zmq.LINGER, 0)
        socket.setsockopt_string(zmq.SUBSCRIBE, "")
        try:
            socket.connect(url)
        except zmq.ZMQError as error:
            raise SceneGraphError(f"cannot connect to the ZMQ stream: {error}", path=url) from None
        yield from _received(socket, url, idle_timeout, first_timeout if first_timeout is not None else idle_timeout)
    finally:
        socket.close(linger=0)
        context.term()


def _received(socket: Any, url: str, idle_timeout: float, first_timeout: float) -> Iterator[Update]:
    previous: bytes | None = None
    number = 0
    waiting = first_timeout
    while True:
        if not socket.poll(max(1, int(waiting * 1000))):
            return
        data = socket.recv(copy=True)
        waiting = idle_timeout
        if data == previous:
            continue
        previous = data
        number += 1
        yield Update(number, f"{url} (update {number})", data=data)


class GraphSession:
    """A live session fed by scene graphs: the first readable graph starts it (with the goals), each later
    one becomes its events.  :meth:`apply` answers one update with JSON-ready lines: one per event (the
    session's report, the update's number and the graph nodes of the objects it names), then the update's
    own line (how many events, or its error)."""

    def __init__(
        self, goals: Sequence[str], options: Any, scoring: Any, plan_options: Any = None, plan_in_loop: bool = False
    ):
        from relevance_plan.scene_graphs.classes import NO_MAPPING, load_vocabulary, read_label_mapping

        self.goals = tuple(goals)
        self.options = options
        self.scoring = scoring
        self.plan_options = plan_options
        self.plan_in_loop = plan_in_loop
        self.vocabulary = load_vocabulary()
        self.mapping = read_label_mapping(options.labels) if options.labels else NO_MAPPING
        self.session: Any = None
        self.scene: ImportedScene | None = None

    def apply(self, update: Update) -> list[dict[str, Any]]:
        head = {"event": "update", "update": update.number, "source": update.source}
        if update.error is not None:
            return [{**head, "error": update.error}]
        try:
            graph = self._read(update)
            if self.session is None:
                return [self._start(graph, head)]
            from relevance_plan.scene_graphs.problem import import_graph

            scene = import_graph(graph, self.vocabulary, self.mapping, self.options.class_floor, self.options.start)
        except SceneGraphError as error:
            return [{**head, "error": str(error)}]
        if scene.questions:
            return [{**head, "error": "; ".join(p.question for p in scene.questions)}]
        assert self.scene is not None
        lines = [self._answer(event, update.number, scene) for event in scene_events(self.scene, scene)]
        self.scene = scene
        errors = sum(1 for line in lines if line.get("error"))
        return lines + [{**head, "events": len(lines), "rejected": errors, "kept": sorted(self.session.kept)}]

    def _read(self, update: Update) -> Any:
        from relevance_plan.scene_graphs.importer import binary_graph, read_graph

        if update.path is not None:
            return read_graph(update.path, self.options)
        return binary_graph(update.data or b"", update.source, self.options)

    def _start(self, graph: Any, head: dict[str, Any]) -> dict[str, Any]:
        from relevance_plan.scene_graphs.importer import DOMAIN_FILE, import_scene
        from relevance_plan.session import Session

        result = import_scene(graph, self.goals, self.options, "live")
        if result.questions or result.text is None:
            return {**head, "error": "; ".join(result.questions)}
        self.session = Session(
            str(DOMAIN_FILE), result.text, self.scoring, plan_options=self.plan_options, plan_in_loop=self.plan_in_loop
        )
        self.scene = result.scene
        goals = [r.as_json() for r in result.resolutions]
        return {
            **head,
            "started": True,
            "objects": len(result.scene.objects),
            "goals": goals,
            "kept": sorted(self.session.kept),
        }

    def _answer(self, event: dict[str, Any], number: int, scene: ImportedScene) -> dict[str, Any]:
        report = self.session.handle(event).to_json()
        named = [event["object"]] if "object" in event else event.get("fact", [])[1:]
        refs = {**(self.scene.refs if self.scene else {}), **scene.refs}
        nodes = {name: refs[name].node for name in named if name in refs and refs[name].node is not None}
        return {**report, "update": number, "nodes": nodes}
