"""``relevance-plan watch``: a live session over JSON-lines events, one JSON line out per event.

Each event is answered as soon as its line arrives (a live pipe is read line
by line, never to its end first), and nothing of an event is kept once its
line is written: a session of any length holds the current scene only.  A line that is not valid UTF-8, not JSON,
too long or not a valid event gets its error line and the session carries
on.  The snapshot files are checked before the first event and written
after the last, also when the session is interrupted (exit 130) or its
reader goes away.
"""

from __future__ import annotations

import sys
from collections.abc import Iterator
from pathlib import Path
from typing import BinaryIO

import click

from relevance_plan.cli.common import (
    file_option,
    handle_errors,
    json_text,
    planning_options,
    race_option,
    scoring_options,
    take_plan_options,
    task_arguments,
)
from relevance_plan.errors import InputFileError, UsageError
from relevance_plan.exitcodes import ExitCode

SNAPSHOT_FILES = ("current.pddl", "pruned.pddl")


def read_event_lines(stream: BinaryIO, limit: int | None = None) -> Iterator[str]:
    """The lines of ``stream`` as they arrive, as text.

    Bytes that are not UTF-8 are kept as lone surrogates, so the event they
    belong to is refused by the event checks, not the whole stream.  A line
    longer than ``limit`` bytes (its ending, ``\\n`` or ``\\r\\n``, not counted)
    comes back cut to ``limit + 2`` bytes, which the session refuses, and the
    rest of it is skipped, never held whole.  ``limit`` defaults to the session's.
    """
    if limit is None:
        from relevance_plan.session.events import MAX_EVENT_BYTES

        limit = MAX_EVENT_BYTES
    while True:
        line = stream.readline(limit + 2)  # a line of ``limit`` bytes and its ending, or more
        if not line:
            return
        if len(line) == limit + 2 and not line.endswith(b"\n"):
            while (rest := stream.readline(limit)) and not rest.endswith(b"\n"):
                pass
        yield line.decode("utf-8", errors="surrogateescape")


def _open_events(events_path: str) -> BinaryIO:
    if events_path == "-":
        if sys.stdin is None:
            raise InputFileError("standard input is closed; give --events a file")
        return sys.stdin.buffer
    from relevance_plan.io import check_input_file

    check_input_file(events_path, "events file")
    try:
        return open(events_path, "rb")  # noqa: SIM115 - closed by watch
    except OSError as error:
        raise InputFileError(f"cannot read events file: {error.strerror}", path=events_path) from None


def _check_snapshot_targets(snapshot_dir: str, inputs: list) -> list[Path]:
    """The snapshot files, checked (and their folder made) before the first event."""
    from relevance_plan.cli.files import check_output_file

    folder = Path(snapshot_dir)
    if folder.exists() and not folder.is_dir():
        raise InputFileError("--snapshot names a file, not a folder", path=snapshot_dir)
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as error:
        raise InputFileError(f"cannot create the snapshot directory: {error.strerror}", path=snapshot_dir) from None
    targets = [folder / name for name in SNAPSHOT_FILES]
    for target in targets:
        check_output_file(target, "snapshot file", inputs)
    return targets


@click.command()
@task_arguments
@click.option(
    "--events",
    "events_path",
    default="-",
    show_default=True,
    type=click.Path(dir_okay=False, allow_dash=True),
    help="JSON-lines events file ('-': standard input).",
)
@click.option(
    "--plan",
    "plan_in_loop",
    is_flag=True,
    help="Plan again whenever a determination changes the kept set (a 'plan' event always plans).",
)
@file_option(
    "--snapshot", "snapshot_dir", folder=True, help="After the last event, write DIR/current.pddl and DIR/pruned.pddl."
)
@scoring_options
@planning_options()
@race_option
@handle_errors
def watch(domain_path, problem_path, events_path, plan_in_loop, snapshot_dir, race, **values):
    """Keep relevance (and, with --plan, a validated plan) current over a stream of scene events.

    A session plans with one planner at a time: --no-race is what it does, --race is refused."""
    from relevance_plan.io import load_task, write_text_atomic
    from relevance_plan.planning.planners.registry import make_planner
    from relevance_plan.session import Session  # imported here: other commands never need the session

    if race:
        raise UsageError("watch plans with one planner at a time and never races: leave out --race")
    options = take_plan_options(values)
    targets = None
    if snapshot_dir is not None:
        inputs = [domain_path, problem_path, options.model_path, None if events_path == "-" else events_path]
        targets = _check_snapshot_targets(snapshot_dir, inputs)
    make_planner(options.planner, options.planner_config, check=plan_in_loop)
    events = _open_events(events_path)
    domain, problem = load_task(domain_path, problem_path)
    session = Session(
        domain, problem, options.scoring, domain_path=domain_path, plan_options=options, plan_in_loop=plan_in_loop
    )
    del problem  # the session holds the scene: the file as read (its text, every span) can go
    ending = None
    try:
        for line in read_event_lines(events):
            if not line.strip():
                continue
            report = session.handle_line(line)
            click.echo(json_text(report.to_json(), indent=None))
            sys.stdout.flush()
    except KeyboardInterrupt as error:
        ending = error
    except BrokenPipeError as error:
        ending = error
    finally:
        if events_path != "-":
            events.close()
    if targets is not None:
        for target, text in zip(targets, session.snapshot()):
            write_text_atomic(target, text)
    if isinstance(ending, BrokenPipeError):
        raise ending  # the reader went away: quietly, once the snapshot is written
    if ending is not None:
        by = f" by {ending}" if str(ending) else ""
        click.echo(f"relevance-plan: watch: interrupted{by}; the session ended", err=True)
        sys.exit(int(ExitCode.INTERRUPTED))
