"""``relevance-plan scene-graph``: a Hydra scene graph (or a Matterport3D house) in, a problem out, or a live session.

- ``import GRAPH -o DIR``: DIR/domain.pddl (the hydra domain), DIR/problem.pddl
  and DIR/problem.json (every object's graph node), with the goals given
  (atoms, or words resolved to class goals); a label or a goal that cannot be
  placed is a question (exit 12) and nothing is written;
- ``watch GRAPH... | --zmq URL``: the first graph starts a live session, each
  later one is diffed into its events (one JSON line each, as ``watch``
  answers them, with the update's number and the objects' graph nodes).
"""

from __future__ import annotations

import sys
from pathlib import Path

import click

from relevance_plan.cli.arguments.numbers import NumberOption
from relevance_plan.cli.arguments.paths import own_command_path_checks
from relevance_plan.cli.common import (
    fail,
    file_option,
    handle_errors,
    json_option,
    json_text,
    planning_options,
    scoring_options,
    take_plan_options,
)
from relevance_plan.exitcodes import ExitCode

OUTPUT_FILES = ("domain.pddl", "problem.pddl", "problem.json")
SIMILARITY = NumberOption(float, 0.0, 1.0, what="a similarity")
GRAPH_MEGABYTES = NumberOption(float, 0.0, 65536.0, above=True, what="megabytes")
IDLE_SECONDS = NumberOption(float, 0.0, 86400.0, above=True, what="seconds")


def import_options(command):
    """The options every scene-graph command reads a graph with."""
    for decorator in reversed(
        [
            click.option(
                "--goal",
                "goals",
                multiple=True,
                help="A goal: PDDL atoms over the imported names, or words"
                " ('bring a cup to the kitchen'); repeat for more.",
            ),
            file_option(
                "--labels",
                "labels_path",
                help="YAML naming the graph's labels: objects: {5: chair},"
                " rooms: {0: kitchen} (default: the graph's own label space).",
            ),
            click.option(
                "--start",
                default=None,
                help="The robot's place (a name, NodeSymbol or node id) when the"
                " graph has no agent poses, or instead of its latest pose.",
            ),
            click.option(
                "--class-floor",
                type=SIMILARITY,
                default=None,
                help="Least similarity for placing a label under a class (default 0.55).",
            ),
            click.option(
                "--goal-floor",
                type=SIMILARITY,
                default=None,
                help="Least similarity for reading a goal's words as a class (default 0.45).",
            ),
            click.option(
                "--max-graph-mb",
                type=GRAPH_MEGABYTES,
                default=64,
                show_default=True,
                help="Refuse a graph file (or update) larger than this.",
            ),
            click.option(
                "--ignore-unknown-layers",
                is_flag=True,
                help="Leave out nodes on layers other than objects, places, rooms and buildings (and say how many).",
            ),
        ]
    ):
        command = decorator(command)
    return command


def _options(values: dict):
    from relevance_plan.scene_graphs.importer import ImportOptions

    defaults = ImportOptions()
    return ImportOptions(
        labels=values.pop("labels_path"),
        start=values.pop("start"),
        class_floor=defaults.class_floor if (f := values.pop("class_floor")) is None else f,
        goal_floor=defaults.goal_floor if (g := values.pop("goal_floor")) is None else g,
        max_bytes=int(values.pop("max_graph_mb") * 2**20),
        ignore_unknown_layers=values.pop("ignore_unknown_layers"),
    )


def _ask(result, as_json: bool) -> None:
    """The questions of an import (labels or goals it cannot place): printed, exit 12."""
    if as_json:
        click.echo(json_text(_report(result)))
    for question in result.questions:
        click.echo(f"question: {question}", err=True)
    fail(f"insufficient cues: {len(result.questions)} question(s) about the scene graph", ExitCode.INSUFFICIENT_CUES)


def _report(result, written: list[str] | None = None) -> dict:
    scene = result.scene
    return {
        "source": scene.source,
        "objects": len(scene.objects),
        "facts": len(scene.facts),
        "placements": [p.as_json() for p in scene.placements],
        "goals": [r.as_json() for r in result.resolutions],
        "questions": result.questions,
        "notes": list(scene.notes),
        "written": written or [],
    }


@click.group("scene-graph")
def scene_graph():
    """Hydra scene graphs (spark-dsg JSON) and Matterport3D houses as planning problems (the 'hydra' extra)."""


@scene_graph.command("import")
@click.argument("graph_path", metavar="GRAPH", type=click.Path(dir_okay=False))
@file_option(
    "-o", "--output", "out_dir", folder=True, required=True, help="Folder for domain.pddl, problem.pddl, problem.json."
)
@click.option("--name", default=None, help="The problem's name (default: the graph file's name).")
@import_options
@json_option("Print the import's report as JSON.")
@handle_errors
def import_graph(graph_path, out_dir, name, goals, as_json, **values):
    """Write GRAPH as a problem of the hydra domain, with the goals given, and its node map."""
    from relevance_plan.io import write_text_atomic
    from relevance_plan.scene_graphs.importer import DOMAIN_FILE, import_scene, read_graph

    options = _options(values)
    if not goals:
        raise click.UsageError("give at least one --goal (atoms over the imported names, or words)")
    targets = _targets(out_dir, graph_path)
    result = import_scene(read_graph(graph_path, options), goals, options, name or Path(graph_path).stem)
    if result.questions:
        _ask(result, as_json)
    texts = [DOMAIN_FILE.read_text(encoding="utf-8"), result.text, json_text(result.sidecar) + "\n"]
    for target, text in zip(targets, texts):
        write_text_atomic(target, text)
    written = [str(t) for t in targets]
    if as_json:
        click.echo(json_text(_report(result, written)))
        return
    for resolution in result.resolutions:
        parts = "; ".join(f"'{p.phrase}' as {p.chosen} ({p.similarity:.2f})" for p in resolution.parts)
        click.echo(f"goal: '{resolution.text}' -> ({' '.join(resolution.atom or ())}): {parts}")
    for placement in result.scene.placements:
        if placement.how not in ("vocabulary", "unnamed"):
            click.echo(
                f"label: {placement.layer} {placement.label} '{placement.name}' as {placement.chosen}"
                f" ({placement.how}, {placement.similarity:.2f})"
            )
    for note in result.scene.notes:
        click.echo(f"note: {note}")
    click.echo(f"wrote {len(result.scene.objects)} objects, {len(result.scene.facts)} facts to {', '.join(written)}")


def _targets(out_dir: str, graph_path: str) -> list[Path]:
    from relevance_plan.cli.files import check_output_file
    from relevance_plan.errors import InputFileError

    folder = Path(out_dir)
    if folder.exists() and not folder.is_dir():
        raise InputFileError("-o names a file, not a folder", path=out_dir)
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as error:
        raise InputFileError(f"cannot create the folder: {error.strerror}", path=out_dir) from None
    targets = [folder / name for name in OUTPUT_FILES]
    for target in targets:
        check_output_file(target, "output file", [graph_path])
    return targets


@scene_graph.command("watch")
@click.argument("graph_paths", metavar="GRAPH...", nargs=-1, type=click.Path(dir_okay=False))
@click.option(
    "--zmq", "zmq_url", default=None, help="Follow spark-dsg's ZMQ stream at this URL (tcp://127.0.0.1:8001)."
)
@click.option(
    "--idle-timeout",
    type=IDLE_SECONDS,
    default=10.0,
    show_default=True,
    help="With --zmq: end the session when no update came for this many seconds.",
)
@click.option("--plan", "plan_in_loop", is_flag=True, help="Keep a validated plan current, as watch --plan does.")
@import_options
@scoring_options
@planning_options()
@handle_errors
def watch(graph_paths, zmq_url, idle_timeout, plan_in_loop, goals, **values):
    """A live session over successive scene graphs (files, or a ZMQ stream): one JSON line per event."""
    from relevance_plan.planning.planners.registry import make_planner
    from relevance_plan.scene_graphs.live import GraphSession, file_updates, zmq_updates

    options = _options(values)
    plan_options = take_plan_options(values)
    # a planner that does not exist is refused before any graph is read, as watch refuses it
    make_planner(plan_options.planner, plan_options.planner_config, check=plan_in_loop)
    if bool(graph_paths) == bool(zmq_url):
        raise click.UsageError("give the graphs as files, or --zmq URL, not both and not neither")
    if not goals:
        raise click.UsageError("give at least one --goal (atoms over the imported names, or words)")
    updates = file_updates(graph_paths) if graph_paths else zmq_updates(zmq_url, idle_timeout, options.max_bytes)
    live = GraphSession(goals, options, plan_options.scoring, plan_options, plan_in_loop)
    try:
        for update in updates:
            for line in live.apply(update):
                click.echo(json_text(line, indent=None))
            sys.stdout.flush()
    except KeyboardInterrupt:
        click.echo("relevance-plan: scene-graph watch: interrupted; the session ended", err=True)
        sys.exit(int(ExitCode.INTERRUPTED))
    if live.session is None:
        fail("no scene graph of the stream could start the session", ExitCode.INPUT_FILE)


for _command in scene_graph.commands.values():
    own_command_path_checks(_command)
