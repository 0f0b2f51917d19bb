"""The batch commands of ``relevance-plan``: ``compare``, ``report`` and ``demo``."""

from __future__ import annotations

from pathlib import Path

import click

from relevance_plan.cli.common import handle_errors, planning_options, scoring_options, take_plan_options
from relevance_plan.planning.loop import METHODS

DEFAULT_METHODS = "relevance,pure,random"


@click.command()
@click.argument("suite_dirs", metavar="SUITE_DIR...", nargs=-1, required=True, type=click.Path())
@click.option(
    "--methods", default=DEFAULT_METHODS, show_default=True, help=f"Comma-separated methods from: {', '.join(METHODS)}."
)
@click.option(
    "--planners",
    default=None,
    help="Comma-separated planners (fast-downward, up:NAME; a cmd:'TEMPLATE' last); default: --planner.",
)
@scoring_options(with_seed=False)
@planning_options(per_job=True)
@click.option(
    "--jobs",
    "-j",
    type=int,
    default=1,
    show_default=True,
    help="Jobs run at once locally (each drives one planner process).",
)
@click.option(
    "--store",
    "store_path",
    type=click.Path(dir_okay=False),
    default="results.sqlite",
    show_default=True,
    help="SQLite results store; jobs already in it are skipped (resume).",
)
@click.option("--scheduler", default=None, metavar="tcp://HOST:PORT", help="Run the jobs on this Dask scheduler.")
@click.option(
    "--scheduler-timeout", type=float, default=10.0, show_default=True, help="Seconds to wait for the Dask scheduler."
)
@click.option("--seeds", default="0", show_default=True, help="Comma-separated seeds; one job per seed.")
@click.option("--quiet", "-q", is_flag=True, help="No progress display.")
@handle_errors
def compare(suite_dirs, methods, planners, jobs, store_path, scheduler, scheduler_timeout, seeds, quiet, **values):
    """Run each method on every problem of the SUITE_DIRs and store the results.

    Rerunning the same command resumes: stored jobs are not run again.
    """
    from relevance_plan.batch.jobs import compare as run_compare
    from relevance_plan.planning.planners import split_planner_names

    options = take_plan_options(values)
    summary = run_compare(
        list(suite_dirs),
        methods,
        options,
        planners=split_planner_names(planners) if planners else (),
        seeds=seeds,
        jobs=jobs,
        store_path=store_path,
        scheduler=scheduler,
        scheduler_timeout=scheduler_timeout,
        progress=not quiet,
    )
    click.echo(summary.describe())
    click.echo(f"report: relevance-plan report {store_path}")


@click.command()
@click.argument("store_path", metavar="STORE", type=click.Path(dir_okay=False))
@click.option("--format", "fmt", type=click.Choice(["markdown", "csv", "latex"]), default="markdown", show_default=True)
@click.option("--suite", default=None, help="Only this suite.")
@click.option(
    "--plots",
    "plots_dir",
    type=click.Path(file_okay=False),
    default=None,
    help="Also write a cactus plot and a relevance-vs-pure scatter (PNG) here; needs matplotlib.",
)
@handle_errors
def report(store_path, fmt, suite, plots_dir):
    """Print the comparison table computed from the rows of STORE."""
    from relevance_plan.batch.report import build_report, format_report, write_plots
    from relevance_plan.batch.store import read_rows

    rows = read_rows(store_path, suite)
    if plots_dir is not None:
        written = write_plots(rows, plots_dir)
        click.echo("wrote " + ", ".join(str(path) for path in written), err=True)
    click.echo(format_report(build_report(rows), fmt), nl=False)


@click.command()
@click.option(
    "--workdir",
    type=click.Path(file_okay=False),
    default=None,
    help="Where suites and results go (default: a new temporary directory, kept).",
)
@click.option("--count", type=int, default=3, show_default=True, help="Problems per world.")
@click.option("--timeout", type=float, default=60.0, show_default=True, help="Seconds per job.")
@click.option("--jobs", "-j", type=int, default=2, show_default=True, help="Jobs run at once.")
@click.option("--distractors", type=int, default=None, help="Distractors per problem (default 30).")
@click.option("--tiny", is_flag=True, help="1 problem per world with 5 distractors (a quick check).")
@click.option("--quiet", "-q", is_flag=True, help="No progress display.")
@handle_errors
def demo(workdir, count, timeout, jobs, distractors, tiny, quiet):
    """Generate coffee and cereal suites, compare relevance, pure, random and oracle, print the table."""
    from relevance_plan.batch.demo import run_demo

    run = run_demo(workdir, count, timeout, jobs, distractors=distractors, tiny=tiny, progress=not quiet)
    workdir = run.workdir
    click.echo(run.table, nl=False)
    click.echo("")
    click.echo(f"suites: {', '.join(str(s) for s in run.suites)}")
    click.echo(f"results: {run.store_path} ({run.summary.ran} run now, {run.summary.already_stored} reused)")
    click.echo(f"more: relevance-plan report {run.store_path} --format latex --plots {Path(workdir) / 'plots'}")


COMMANDS = (compare, report, demo)
