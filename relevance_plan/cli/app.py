"""The ``relevance-plan`` command group.  Thin: parse arguments, call the library,
print, and turn errors into the exit codes of ``exitcodes.py``.  The CLI is
the only part of the package that exits.
"""

from __future__ import annotations

import functools
import importlib
import sys
from pathlib import Path

import click

from relevance_plan import __version__
from relevance_plan.cli.arguments.numbers import DISTRACTORS, OBJECTS, SEED, SUITE_SIZE
from relevance_plan.cli.common import (
    fail,
    file_option,
    handle_errors,
    json_option,
    json_text,
    keep_work_option,
    method_option,
    planning_options,
    quiet_option,
    race_option,
    scoring_options,
    take_plan_options,
    take_scoring,
    task_arguments,
    write_plan_files,
)
from relevance_plan.cli.exits import ToolGroup
from relevance_plan.errors import RelevancePlanError, UnsupportedFeatureError, UsageError, counted
from relevance_plan.exitcodes import EXIT_CODE_DESCRIPTIONS, ExitCode, exit_code_for_status
from relevance_plan.pddl.formatter import format_number
from relevance_plan.planning.results import PlanResult, PlanStatus
from relevance_plan.planning.run import plan_task
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.selection.prune import Selection
from relevance_plan.relevance.setup import Scoring, ScoringOptions, score_problem


def _score_and_prune(domain_path, problem_path, options: ScoringOptions) -> tuple[Scoring, Selection]:
    from relevance_plan.io import load_task
    from relevance_plan.pddl.sexpr import collection_paused

    with collection_paused():  # one pass of the collector over the facts afterwards, not several during
        domain, problem = load_task(domain_path, problem_path)
        scoring = score_problem(
            PlanningTask(domain, problem), options, domain_path=domain_path, problem_path=problem_path
        )
        return scoring, scoring.first_selection()


# Commands in modules of their own, imported when one of them is asked for: ``plan`` does without them.
LAZY_COMMANDS = {
    "compare": "relevance_plan.cli.batch",
    "report": "relevance_plan.cli.batch",
    "sweep": "relevance_plan.cli.batch",
    "demo": "relevance_plan.cli.batch",
    "watch": "relevance_plan.cli.watch",
    "learn": "relevance_plan.cli.batch",
    "validate": "relevance_plan.cli.validate",
    "draft-model": "relevance_plan.cli.draft",
    "scene-graph": "relevance_plan.cli.scene_graph",
}


class _Commands(ToolGroup):
    """The tool's command group; the commands of ``LAZY_COMMANDS`` join it on first use."""

    def list_commands(self, ctx: click.Context) -> list[str]:
        return sorted({*self.commands, *LAZY_COMMANDS})

    def get_command(self, ctx: click.Context, cmd_name: str) -> click.Command | None:
        if cmd_name not in self.commands and cmd_name in LAZY_COMMANDS:
            from relevance_plan.cli.arguments.paths import own_command_path_checks

            command = getattr(importlib.import_module(LAZY_COMMANDS[cmd_name]), cmd_name.replace("-", "_"))
            own_command_path_checks(command)
            self.add_command(command)
        return super().get_command(ctx, cmd_name)

    def resolve_command(self, ctx: click.Context, args: list[str]):
        try:
            return super().resolve_command(ctx, args)
        except click.exceptions.NoSuchCommand:
            for name in LAZY_COMMANDS:  # click suggests a command from those it holds
                self.get_command(ctx, name)
            return super().resolve_command(ctx, args)


@click.group(cls=_Commands, context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(__version__, prog_name="relevance-plan")
def main():
    """Relevance-based pruning for PDDL planning: score, prune, plan, validate.

    Fast Downward, the default planner, comes compiled inside the up-fast-downward
    wheel (its downward/fast-downward.py; $RELEVANCE_PLAN_FAST_DOWNWARD names another):
    'relevance-plan planners' prints where.  Shell completion:
    eval "$(_RELEVANCE_PLAN_COMPLETE=bash_source relevance-plan)" (zsh_source, fish_source).
    """


# --------------------------------------------------------------------------- generate


@main.command()
@click.argument("world", type=str)
@click.option("--difficulty", default="simple", show_default=True, help="Kitchen worlds: simple or hard.")
@click.option("--count", type=SUITE_SIZE, default=10, show_default=True, help="Number of problems.")
@click.option("--seed", type=SEED, default=0, show_default=True)
@file_option(
    "--out", "-o", "--output", "out_dir", folder=True, required=True, help="Suite directory to write (-o as elsewhere)."
)
@click.option(
    "--distractors",
    type=DISTRACTORS,
    default=None,
    help="Kitchen worlds: override the paper's distractor count.",
)
@click.option(
    "--size",
    type=OBJECTS,
    default=None,
    help="Classic and other sized worlds: about how many objects per problem"
    " (default: a size where pure planning takes seconds to a minute).",
)
@click.option(
    "--force", is_flag=True, help="Write into a non-empty directory that holds no suite, overwriting same-named files."
)
@handle_errors
def generate(world, difficulty, count, seed, out_dir, distractors, size, force):
    """Generate a seeded benchmark suite for WORLD.

    Kitchen worlds (--difficulty, --distractors): coffee, cereal, coffee-temporal,
    cereal-temporal, coffee-numeric.  Sized worlds (--size): blocksworld, logistics,
    gripper, ferry, grid, miconic (each also as NAME-typed), driverlog-temporal,
    zenotravel-numeric, scenegraph, logistics-manygoals and miconic-manygoals (each
    also as NAME-typed)."""
    from relevance_plan.cli.display import progress_bar
    from relevance_plan.generators.worlds import Settings, find_world

    chosen = find_world(world)
    if chosen.sized and distractors is not None:
        raise UsageError("--distractors applies to the kitchen worlds; classic and sized worlds take --size")
    if not chosen.sized and size is not None:
        raise UsageError(
            "--size applies to the classic worlds and the other sized worlds; kitchen worlds take --distractors"
        )
    settings = Settings(difficulty, distractors, size)
    chosen.check(count, seed, settings)
    label = world if chosen.sized else f"{world}-{difficulty}"
    with progress_bar(f"generate {label}", count) as bar:
        paths = chosen.suite(count, seed, Path(out_dir), settings, progress=bar, force=force)
    click.echo(f"wrote {counted(len(paths), 'problem')} to {out_dir}")


# --------------------------------------------------------------------------- score / prune


@main.command()
@task_arguments
@scoring_options
@click.option("--inquiries", is_flag=True, help="List what the robot would ask the human.")
@click.option(
    "--why",
    "why_object",
    metavar="OBJECT",
    default=None,
    help="Explain one object: its scores, the step that kept or dropped it, and what brought it back.",
)
@json_option("Machine-readable output.")
@handle_errors
def score(domain_path, problem_path, inquiries, why_object, as_json, **values):
    """Print the class and element relevance table for PROBLEM, each object with the step that kept or dropped it."""
    from relevance_plan.cli.explain import print_score_table, print_why, selection_json, why_json

    scoring, result = _score_and_prune(domain_path, problem_path, take_scoring(values))
    scores = scoring.scores
    if why_object is not None:
        if as_json:
            click.echo(json_text(why_json(result, why_object)))
        elif scores.sufficient:  # else there is nothing to explain but the error below, said once
            print_why(result, why_object)
        if not scores.sufficient:
            fail(f"insufficient cues: {scores.insufficiency}", ExitCode.INSUFFICIENT_CUES)
        return
    inquiry = _inquiries(scoring, result) if inquiries and scores.sufficient else None
    if as_json:
        data = selection_json(result)
        if inquiry is not None:
            data["inquiries"] = inquiry
        click.echo(json_text(data))
    else:
        print_score_table(result)
        if inquiry is not None:
            click.echo("")
            click.echo(f"served without asking: {', '.join(inquiry['necessary']) or '-'}")
            click.echo(f"questions ({inquiry['with_necessity']}): {', '.join(inquiry['questions']) or '-'}")
            click.echo(
                f"questions: {inquiry['with_necessity']} with relevance and necessity,"
                f" {inquiry['relevance_only']} with relevance alone, {inquiry['no_relevance']} without relevance"
                f" ({inquiry['reduction'] * 100:.1f} % fewer)"
            )
    if not scores.sufficient:
        fail(f"insufficient cues: {scores.insufficiency}", ExitCode.INSUFFICIENT_CUES)


def _pass_through(problem_path, output, refused: UnsupportedFeatureError, as_json: bool) -> None:
    """``prune --pass-through`` on input that cannot be pruned: the problem, unchanged, and why."""
    from relevance_plan.cli.files import write_output
    from relevance_plan.io import STDOUT, read_text

    reason = f"cannot be pruned: {refused}"
    written = write_output(output, read_text(problem_path, "problem file"))
    if as_json:
        click.echo(json_text({"pruned": False, "unpruned_reason": reason, "output": str(output)}))
    else:
        where = written if output == STDOUT else output
        click.echo(f"pruned: no ({reason}); wrote the problem unchanged to {where}", err=output == STDOUT)


def _inquiries(scoring: Scoring, result: Selection) -> dict:
    from relevance_plan.relevance.scoring.metrics import plan_inquiries
    from relevance_plan.relevance.scoring.scene import kind_of
    from relevance_plan.relevance.selection.prune import select_relevant

    task, model, scores = scoring.task, scoring.knowledge_model, scoring.scores
    structural = set()
    if model is not None:
        structural = {c.name for c in model.classes.values() if c.fixed_relevance is not None or c.from_contents}
    kinds = {name: kind_of(name) for name in task.problem.objects}
    # what the human may want is what relevance selects, before planning narrows it (goal filter, set-aside)
    relevant = select_relevant(task, scores, result.thresholds)
    found = plan_inquiries(scores, relevant, kinds, structural)
    return {
        "necessary": list(found.necessary),
        "questions": list(found.optional),
        "with_necessity": found.with_necessity,
        "relevance_only": found.relevance_only,
        "no_relevance": found.objects,
        "reduction": round(found.reduction, 4),
    }


@main.command()
@task_arguments
@file_option("-o", "--output", "output", required=True, help="Pruned problem file ('-': standard output).")
@scoring_options
@click.option(
    "--pass-through",
    is_flag=True,
    help="When the input cannot be pruned (a construct the reader or the analysis does not take),"
    " write PROBLEM unchanged, say why, and exit 0.",
)
@json_option("Machine-readable report on stdout.")
@handle_errors
def prune(domain_path, problem_path, output, pass_through, as_json, **values):
    """Write PROBLEM without the objects that do not matter (a drop-in filter for any planner).

    "-o -" writes the pruned problem to standard output (the summary goes to stderr).
    """
    from relevance_plan.cli.files import names_stdout, write_output

    to_stdout = names_stdout(output)  # never with --json (cli.arguments.paths refuses both on standard output)
    try:
        scoring, result = _score_and_prune(domain_path, problem_path, take_scoring(values))
    except UnsupportedFeatureError as refused:
        if not pass_through:
            raise
        _pass_through(problem_path, output, refused, as_json)
        return
    from relevance_plan.cli.explain import scores_header, selection_json, understood_lines
    from relevance_plan.relevance.selection.decisions import kept_summary

    scores = scoring.scores
    if not scores.sufficient:
        if as_json:
            click.echo(json_text(selection_json(result)))
        else:
            for line in understood_lines(scores.understood, resolved_only=True):
                click.echo(line, err=True)
        fail(f"insufficient cues: {scores.insufficiency}", ExitCode.INSUFFICIENT_CUES)
    written = write_output(output, result.text)
    if as_json:
        data = selection_json(result)
        data["output"] = str(output)
        click.echo(json_text(data))
    else:
        for line in scores_header(scores)[1:]:  # what free text was understood as
            click.echo(line, err=to_stdout)
        click.echo(f"{kept_summary(result)}; wrote {written if to_stdout else output}", err=to_stdout)
        if result.unpruned_reason:
            click.echo(f"pruned: no ({result.unpruned_reason})", err=to_stdout)


# --------------------------------------------------------------------------- plan


@main.command()
@task_arguments
@method_option
@scoring_options
@planning_options()
@file_option("--plan-file", default="sas_plan", show_default=True, help="Where the plan goes ('-': standard output).")
@keep_work_option
@race_option
@json_option("Print one JSON object.")
@quiet_option()
@handle_errors
def plan(domain_path, problem_path, plan_file, keep_work, as_json, quiet, **values):
    """Prune, plan, validate on the original problem, widen until solved."""
    from relevance_plan.cli.files import names_stdout
    from relevance_plan.planning.planners.preparation import check_keep_directory
    from relevance_plan.planning.planners.registry import make_planner

    to_stdout = names_stdout(plan_file)  # never with --json (cli.arguments.paths refuses both on standard output)

    from dataclasses import replace

    from relevance_plan.planning.race import race_by_default

    method, race = values.pop("method"), values.pop("race")  # plan options that depend on each other
    options = take_plan_options(values, method)
    options = replace(options, race=race_by_default(method) if race is None else race)
    make_planner(options.planner, options.planner_config, check=True)
    if keep_work is not None:
        check_keep_directory(keep_work, (domain_path, problem_path, plan_file))
    result = _plan_within_timeout(domain_path, problem_path, options, quiet or as_json, keep_work)
    numbered = write_plan_files(result, plan_file) if result.status is PlanStatus.SOLVED else []
    nodes = _plan_nodes(problem_path, result, plan_file, to_stdout)
    if as_json:
        data = result.to_json()
        if nodes is not None:
            data["plan_nodes"] = nodes
        data["plan_file"] = str(plan_file) if result.status is PlanStatus.SOLVED else None
        data["plan_files"] = numbered
        click.echo(json_text(data))
    else:
        # With the plan on stdout, the summary goes to stderr.
        _print_plan_summary(result, plan_file, err=to_stdout)
        if nodes is not None and not to_stdout:
            click.echo(f"graph nodes: {plan_file}.nodes.json (each step's arguments as scene-graph nodes)")
    code = exit_code_for_status(result.status.value)
    if code is not ExitCode.SUCCESS:
        if not as_json:
            click.echo(f"relevance-plan: {result.status.value}: {result.message}", err=True)
        sys.exit(int(code))


def _plan_nodes(problem_path, result: PlanResult, plan_file, to_stdout: bool) -> list | None:
    """For a problem imported from a scene graph (its sidecar maps names to graph nodes), the plan in
    node ids, also written to PLAN_FILE.nodes.json; None for any other problem."""
    from relevance_plan.scene_graphs.sidecar import plan_in_nodes, read_node_map

    node_map = read_node_map(problem_path) if result.status is PlanStatus.SOLVED else None
    if node_map is None:
        return None
    nodes = plan_in_nodes(node_map, result.plan)
    if not to_stdout:
        from relevance_plan.cli.files import write_output

        write_output(Path(f"{plan_file}.nodes.json"), json_text(nodes) + "\n")
    return nodes


# The backstop past --timeout, counted from the tool's start: the loop holds the limit itself; this
# stops whatever step overruns it, leaving time to stop the planners and say so within a second.
DEADLINE_SLACK = 0.6
# click's context object when the console script (``launch``) runs the commands: the process is the tool's
# own, so its age is the time the tool has spent (run inside another program, a command counts from its start).
LAUNCHED = "launched"


def _time_spent() -> float:
    """Seconds since the tool started: the process's age when it is the tool's own, else none."""
    from relevance_plan.signals import process_age

    context = click.get_current_context(silent=True)
    return process_age() if context is not None and context.find_root().obj == LAUNCHED else 0.0


def _plan_within_timeout(domain_path, problem_path, options, quiet: bool, keep_work=None) -> PlanResult:
    """``plan_task``, or, if it runs past ``--timeout``, an out-of-time result naming the step it
    was in and what the run had established by then (reported as any other result: exit 20, and
    one JSON object with ``--json``)."""
    from relevance_plan.planning.results import RunRecord
    from relevance_plan.signals import DEADLINE_SIGNAL, Interrupted, deadline_alarm

    def progress(event) -> None:
        if not quiet:
            click.echo(f"... {event.message}", err=True)

    record = RunRecord(options.method, progress)
    timeout = options.timeout
    try:
        with deadline_alarm(None if timeout is None else timeout + DEADLINE_SLACK - _time_spent()):
            return plan_task(domain_path, problem_path, options, keep_work=keep_work, record=record)
    except Interrupted as error:
        if error.signum != DEADLINE_SIGNAL:
            raise
        return record.stopped(f"out of time {record.where()}: the {timeout:g} s --timeout ran out")


def _attempt_label(attempt) -> str:
    """ "attempt 2 (23 objects)" or "attempt 3 (the full problem)"."""
    what = "the full problem" if attempt.selection is None else f"{attempt.objects_kept} objects"
    return f"attempt {attempt.number} ({what})"


def _objects_line(result: PlanResult) -> str:
    """ "9 kept of 54", or what is not known: the problem not read, no selection made."""
    total, kept = result.objects_total, result.objects_kept
    if total is None:
        return "all" if result.refusal else "not counted (the run ended before the problem was read)"
    if kept is None:
        return f"{total} in the problem, none selected (the run ended before the selection was made)"
    won = " (the full problem, which won the race)" if result.deciding_side == "full" else ""
    return f"{kept} kept of {total}{won}"


def _race_line(result: PlanResult) -> str:
    """Which side won the race, or that neither did and how each side ended."""
    from relevance_plan.planning.results import race_sides

    stopped = [a for a in result.attempts if a.stopped]
    also = f"; stopped: {', '.join(_attempt_label(a) for a in stopped)}" if stopped else ""
    if result.deciding_side:
        side = "the full problem, planned from the start," if result.deciding_side == "full" else "the pruned side"
        return f"{side} won{also}"
    sides = race_sides(result)
    names = (("pruned", "pruned side"), ("full", "full problem"))
    ended = ", ".join(f"{name}: {sides.get(key, 'no attempt ended')}" for key, name in names)
    return f"no side won ({ended}){also}"


def _print_plan_summary(result: PlanResult, plan_file, err: bool = False) -> None:
    echo = functools.partial(click.echo, err=err)
    echo(f"method:      {result.method}")
    echo(f"planner:     {result.planner}" + (f" (auto: {result.planner_choice})" if result.planner_choice else ""))
    echo(f"status:      {result.status.value}")
    from relevance_plan.cli.explain import understood_lines

    for line in understood_lines(result.understood):  # free text, and what it was taken for (or asked)
        label, said = line.split(":", 1)
        echo(f"{label + ':':<12} {said.strip()}")
    unpruned = result.unpruned_reason
    echo(f"objects:     {_objects_line(result)}" + (f" (pruned: no, {unpruned})" if unpruned else ""))
    if result.selection is not None:
        from relevance_plan.relevance.selection.decisions import kept_summary

        echo(f"pruning:     {kept_summary(result.selection)} first")
    echo(f"attempts:    {len(result.attempts)} (first: {result.first_attempt_status})")
    if result.race:
        echo(f"race:        {_race_line(result)}")
    echo(
        f"time:        {result.wall_time:.2f} s total, {result.relevance_time:.2f} s relevance,"
        f" {result.planner_time:.2f} s planner, {result.validation_time:.2f} s validation"
    )
    if result.status is PlanStatus.SOLVED:
        size = counted(len(result.plan), "step") + (
            f", cost {format_number(result.plan_cost)}" if result.plan_cost is not None else ""
        )
        if result.validation is not None and result.valid:
            echo(f"plan:        {size}, valid on the original problem ({result.validation.validator})")
        else:
            echo(f"plan:        {size}, NOT validated (--validator none)")
        echo(f"plan file:   {plan_file}")


# --------------------------------------------------------------------------- examples


@main.command()
@click.argument("folder", metavar="DIR", type=click.Path(file_okay=False))
@handle_errors
def examples(folder):
    """Copy the shipped worlds into DIR (DIR/domains, DIR/problems, DIR/examples), as in a clone's root.

    After a regular install, `relevance-plan examples kitchen && cd kitchen`
    makes the README's first-look commands work as written.  A file that
    already exists is never replaced: the copy is refused before anything
    is written.
    """
    from relevance_plan.generators.examples import write_examples

    written = write_examples(folder)
    tops = sorted({path.relative_to(folder).parts[0] + "/" for path in written})
    click.echo(f"wrote {counted(len(written), 'file')} to {folder} ({', '.join(tops)})")


# --------------------------------------------------------------------------- planners


@main.command()
@handle_errors
def planners():
    """Say where the planners are: the bundled Fast Downward, LPG, and how to name the others."""
    from relevance_plan.planning.planners.fast_downward.command_line import FAST_DOWNWARD_ENV, driver_location
    from relevance_plan.planning.planners.lpg import lpg_binary

    try:
        found = f"{driver_location()} (the up-fast-downward wheel; ${FAST_DOWNWARD_ENV} names another)"
    except RelevancePlanError as error:
        found = f"not found: {error.message}"
    lpg = lpg_binary()
    rows = [
        ("auto", "the default: Fast Downward for classical problems, a temporal or numeric planner otherwise"),
        ("fast-downward", found),
        ("lpg", str(lpg) if lpg is not None else "not installed: pip install 'relevance-plan[planners]'"),
        ("up:NAME", "a unified-planning engine: aries, tamer, enhsp, kairos, pyperplan, symk (the planners extra)"),
        ("cmd:'TEMPLATE'", "any planner binary, run without a shell: {domain} {problem} [{plan}]"),
    ]
    for name, where in rows:
        click.echo(f"{name:<15} {where}")


# --------------------------------------------------------------------------- exit codes


@main.command("exit-codes")
@handle_errors
def exit_codes():
    """Print the table of exit codes."""
    for code in ExitCode:
        click.echo(f"{int(code):>4}  {code.name:<18} {EXIT_CODE_DESCRIPTIONS[code]}")


from relevance_plan.cli.arguments.paths import own_path_checks  # noqa: E402

own_path_checks(main)
