"""``relevance-plan watch``: a live session over JSON-lines events, one JSON line out per event."""

from __future__ import annotations

import json
import sys
from pathlib import Path

import click

from relevance_plan.cli.common import handle_errors, planning_options, scoring_options, take_plan_options
from relevance_plan.errors import InputFileError
from relevance_plan.session import EventReport, Session


def report_json(report: EventReport, session: Session) -> dict:
    """The output line of one event (names in the user's spelling)."""
    show = session.scene.display.get
    data: dict = {
        "seq": report.seq,
        "event": report.event,
        "triggered": report.triggered,
        "reason": report.reason,
        "sufficient": report.sufficient,
        "stale": report.stale,
    }
    if report.error is not None:
        data["error"] = report.error
    if not report.sufficient:
        data["insufficiency"] = report.insufficiency
    if report.triggered:
        selection = report.selection
        kept = selection.kept if selection is not None else frozenset()
        data["kept"] = sorted(show(n, n) for n in kept)
        data["restored"] = [
            {"object": show(r.name, r.name), "reason": r.reason}
            for r in (selection.restored if selection is not None else ())
        ]
        data["removed"] = len(selection.removed) if selection is not None else None
    data["added"] = [show(n, n) for n in report.added]
    data["dropped"] = [show(n, n) for n in report.dropped]  # a dropped object may have left: its name as given
    data["ask"] = (
        None
        if report.ask is None
        else {"cue": report.ask.cue, "question": report.ask.question, "options": list(report.ask.options)}
    )
    data["determination_ms"] = round(report.seconds * 1000, 3)
    if report.plan is not None:
        data["plan_status"] = report.plan.status.value
        data["plan"] = ["(" + " ".join([s.action, *(show(a, a) for a in s.args)]) + ")" for s in report.plan.steps]
        data["plan_source"] = report.plan.source
        data["plan_message"] = report.plan.message
    return data


def _lines(events_path: str):
    if events_path == "-":
        yield from sys.stdin
        return
    from relevance_plan.io import read_text

    yield from read_text(events_path, "events file").splitlines()


@click.command()
@click.argument("domain_path", metavar="DOMAIN", type=click.Path(dir_okay=False))
@click.argument("problem_path", metavar="PROBLEM", type=click.Path(dir_okay=False))
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
@click.option(
    "--snapshot",
    "snapshot_dir",
    type=click.Path(file_okay=False),
    default=None,
    help="After the last event, write DIR/current.pddl and DIR/pruned.pddl.",
)
@scoring_options
@planning_options()
@handle_errors
def watch(domain_path, problem_path, events_path, plan_in_loop, snapshot_dir, **values):
    """Keep relevance (and, with --plan, a validated plan) current over a stream of scene events."""
    from relevance_plan.io import load_task, scratch_directory, write_text_atomic
    from relevance_plan.planning.planners import make_planner

    options = take_plan_options(values)
    planner = make_planner(options.planner, options.planner_config, check=plan_in_loop)
    domain, problem = load_task(domain_path, problem_path)
    if snapshot_dir is not None:
        try:
            Path(snapshot_dir).mkdir(parents=True, exist_ok=True)
        except OSError as error:
            raise InputFileError(f"cannot create the snapshot directory: {error.strerror}", path=snapshot_dir) from None
    with scratch_directory("relevance-plan-watch-") as scratch:
        runs = iter(range(1, 1 << 62))

        def run_planner(text: str, limit):
            path = write_text_atomic(Path(scratch) / f"problem-{next(runs)}.pddl", text)
            return planner.run(domain_path, str(path), time_limit=limit, memory_limit_mb=options.memory_limit_mb)

        session = Session(
            domain,
            problem,
            options.scoring,
            domain_path=domain_path,
            plan_options=options,
            run_planner=run_planner,
            plan_in_loop=plan_in_loop,
        )
        try:
            for line in _lines(events_path):
                if not line.strip():
                    continue
                report = session.handle_line(line)
                click.echo(json.dumps(report_json(report, session)))
                sys.stdout.flush()
        except KeyboardInterrupt:
            click.echo("relevance-plan: watch: interrupted; the session ended", err=True)
    if snapshot_dir is not None:
        current, pruned = session.snapshot()
        write_text_atomic(Path(snapshot_dir) / "current.pddl", current)
        write_text_atomic(Path(snapshot_dir) / "pruned.pddl", pruned)
