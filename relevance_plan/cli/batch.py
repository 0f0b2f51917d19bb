"""The batch commands of ``relevance-plan``: ``compare``, ``report`` and ``demo``.

``cli.py`` registers them with ``main.add_command(...)``.  This module never
imports ``cli`` at import time (``cli`` imports it), so the error handling of
``cli.handle_errors`` is looked up when a command runs.  ``python -m
relevance_plan.cli.batch`` runs a small group holding only these commands.
"""

from __future__ import annotations

import functools
from pathlib import Path

import click

from relevance_plan.planning.loop import METHODS
from relevance_plan.relevance.prune import DEFAULT_TAU

DEFAULT_METHODS = "relevance,pure,random"


def _handled(command):
    """``cli.handle_errors`` around ``command``, imported when the command runs."""

    @functools.wraps(command)
    def wrapper(*args, **kwargs):
        from relevance_plan.cli.app import handle_errors

        return handle_errors(command)(*args, **kwargs)

    return wrapper


@click.command()
@click.argument("suite_dirs", metavar="SUITE_DIR...", nargs=-1, required=True, type=click.Path())
@click.option("--methods", default=DEFAULT_METHODS, show_default=True,
              help=f"Comma-separated methods from: {', '.join(METHODS)}.")
@click.option("--timeout", type=float, default=120.0, show_default=True, help="Seconds per job (relevance + planning).")
@click.option("--jobs", "-j", type=int, default=1, show_default=True,
              help="Jobs run at once locally (each drives one planner process).")
@click.option("--store", "store_path", type=click.Path(dir_okay=False), default="results.sqlite", show_default=True,
              help="SQLite results store; jobs already in it are skipped (resume).")
@click.option("--scheduler", default=None, metavar="tcp://HOST:PORT", help="Run the jobs on this Dask scheduler.")
@click.option("--scheduler-timeout", type=float, default=10.0, show_default=True,
              help="Seconds to wait for the Dask scheduler.")
@click.option("--seeds", default="0", show_default=True, help="Comma-separated seeds; one job per seed.")
@click.option("--no-relax", is_flag=True, help="One attempt per pruned problem (the paper's behaviour).")
@click.option("--planner-config", default="lama-first", show_default=True,
              help="Fast Downward alias, registered name, or search string.")
@click.option("--memory-limit", "memory_limit", type=int, default=None, help="Planner memory limit in MB.")
@click.option("--tau-class", type=float, default=DEFAULT_TAU, show_default=True, help="Class threshold tau_c.")
@click.option("--tau-element", type=float, default=DEFAULT_TAU, show_default=True, help="Element threshold tau_e.")
@click.option("--model", "model_path", type=click.Path(dir_okay=False), default=None,
              help="Knowledge-model YAML (default: found next to each domain).")
@click.option("--objective", default=None, help="Objective from the model.")
@click.option("--task", "task_name", default=None, help="Fix the task: P(task | objective) = 1.")
@click.option("--human", default=None, help="Apply this human's recorded preferences.")
@click.option("--quiet", "-q", is_flag=True, help="No progress display.")
@_handled
def compare(suite_dirs, methods, timeout, jobs, store_path, scheduler, scheduler_timeout, seeds, no_relax,
            planner_config, memory_limit, tau_class, tau_element, model_path, objective, task_name, human, quiet):
    """Run each method on every problem of the SUITE_DIRs and store the results.

    Rerunning the same command resumes: stored jobs are not run again.
    """
    from relevance_plan.batch.jobs import compare as run_compare

    summary = run_compare(
        list(suite_dirs),
        methods,
        timeout=timeout,
        jobs=jobs,
        store_path=store_path,
        seeds=seeds,
        scheduler=scheduler,
        scheduler_timeout=scheduler_timeout,
        planner_config=planner_config,
        memory_limit_mb=memory_limit,
        relax=not no_relax,
        tau_class=tau_class,
        tau_element=tau_element,
        model_path=model_path,
        objective=objective,
        task=task_name,
        human=human,
        progress=not quiet,
    )
    click.echo(summary.describe())
    click.echo(f"report: relevance-plan report {store_path}")


@click.command()
@click.argument("store_path", metavar="STORE", type=click.Path(dir_okay=False))
@click.option("--format", "fmt", type=click.Choice(["markdown", "csv", "latex"]), default="markdown", show_default=True)
@click.option("--suite", default=None, help="Only this suite.")
@click.option("--plots", "plots_dir", type=click.Path(file_okay=False), default=None,
              help="Also write a cactus plot and a relevance-vs-pure scatter (PNG) here; needs matplotlib.")
@_handled
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
@click.option("--workdir", type=click.Path(file_okay=False), default=None,
              help="Where suites and results go (default: a new temporary directory, kept).")
@click.option("--count", type=int, default=3, show_default=True, help="Problems per world.")
@click.option("--timeout", type=float, default=60.0, show_default=True, help="Seconds per job.")
@click.option("--jobs", "-j", type=int, default=2, show_default=True, help="Jobs run at once.")
@click.option("--distractors", type=int, default=None, help="Distractors per problem (default 30).")
@click.option("--tiny", is_flag=True, help="1 problem per world with 5 distractors (a quick check).")
@click.option("--quiet", "-q", is_flag=True, help="No progress display.")
@_handled
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


@click.group(context_settings={"help_option_names": ["-h", "--help"]})
def batch_main():
    """Batch commands of relevance-plan (also available as `relevance-plan compare|report|demo`)."""


for _command in COMMANDS:
    batch_main.add_command(_command)


if __name__ == "__main__":  # pragma: no cover
    batch_main()
