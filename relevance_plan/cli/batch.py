"""The batch commands of ``relevance-plan``: ``compare``, ``report``, ``sweep``, ``demo`` and ``learn``."""

from __future__ import annotations

from pathlib import Path

import click

from relevance_plan.cli.arguments.choices import NamedChoice
from relevance_plan.cli.arguments.numbers import DISTRACTORS, DPI, JOBS, SEED, SEEDS, SUITE_SIZE, THRESHOLDS, seconds
from relevance_plan.cli.common import (
    file_option,
    handle_errors,
    json_option,
    json_text,
    planning_options,
    quiet_option,
    scoring_options,
    take_plan_options,
    take_scoring,
    timeout_option,
)
from relevance_plan.cli.display import progress_bar
from relevance_plan.errors import UsageError, counted
from relevance_plan.planning.options import METHODS, Method

DEFAULT_METHODS = ",".join(method.value for method in (Method.RELEVANCE, Method.PURE, Method.RANDOM))
LEARN_TIMEOUT = 60.0  # seconds for each planner run of learn


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
    type=JOBS,
    default=1,
    show_default=True,
    help="Jobs run at once locally (each drives one planner process).",
)
@file_option(
    "--store",
    "store_path",
    default="results.sqlite",
    show_default=True,
    help="SQLite results store; jobs already in it are skipped (resume).",
)
@click.option("--scheduler", default=None, metavar="tcp://HOST:PORT", help="Run the jobs on this Dask scheduler.")
@click.option(
    "--scheduler-timeout",
    type=seconds(),
    default=10.0,
    show_default=True,
    help="Seconds to wait for the Dask scheduler.",
)
@click.option("--seeds", type=SEEDS, default="0", show_default=True, help="Comma-separated seeds; one job per seed.")
@quiet_option("No progress display.")
@handle_errors
def compare(suite_dirs, methods, planners, store_path, seeds, quiet, **values):
    """Run each method on every problem of the SUITE_DIRs and store the results.

    Rerunning the same command resumes: stored jobs are not run again.
    """
    from relevance_plan.batch.compare import compare as run_compare
    from relevance_plan.batch.executors import Workers
    from relevance_plan.planning.planners.registry import split_planner_names

    workers = Workers(values.pop("jobs"), values.pop("scheduler"), values.pop("scheduler_timeout"))
    options = take_plan_options(values)
    with progress_bar("compare", live=None if not quiet else False) as bar:
        summary = run_compare(
            list(suite_dirs),
            methods,
            options,
            planners=split_planner_names(planners) if planners else (),
            seeds=seeds,
            store_path=store_path,
            workers=workers,
            progress=None if quiet else bar,
        )
    click.echo(summary.describe())
    click.echo(f"report: relevance-plan report {store_path}")


@click.command()
@click.argument("store_path", metavar="STORE", type=click.Path(dir_okay=False))
@click.option(
    "--format",
    "fmt",
    type=NamedChoice(("markdown", "csv", "latex"), "format"),
    default=None,
    help="The table per suite and method  [default: markdown].",
)
@json_option("One JSON object per job instead of the table.")
@click.option("--csv", "as_csv", is_flag=True, help="One CSV line per job instead of the table.")
@click.option("--suite", default=None, help="Only this suite.")
@file_option(
    "--plots",
    "plots_dir",
    folder=True,
    help="Also write cactus plots (all suites and one per suite) and a relevance-vs-pure scatter here;"
    " needs matplotlib.",
)
@click.option(
    "--plot-format",
    type=NamedChoice(("png", "svg", "pdf"), "plot format"),
    default="png",
    show_default=True,
    help="File format of --plots.",
)
@click.option("--dpi", type=DPI, default=150, show_default=True, help="Resolution of PNG plots.")
@file_option(
    "--html",
    "html_path",
    help="Also write one self-contained HTML page: the tables and, with matplotlib, the plots as inline SVG"
    " ('-': the page on standard output, instead of the table).",
)
@handle_errors
def report(store_path, fmt, as_json, as_csv, suite, html_path, **plots):
    """Print the comparison table computed from the rows of STORE (or, with --json/--csv, every job)."""
    from relevance_plan.batch.report import build_report, format_jobs, format_report
    from relevance_plan.batch.store import read_rows
    from relevance_plan.cli.files import check_distinct_outputs, names_stdout, write_output

    per_job = [name for name, chosen in (("--json", as_json), ("--csv", as_csv)) if chosen]
    given = per_job + ([f"--format {fmt}"] if fmt is not None else [])
    if len(given) > 1:
        raise UsageError(f"choose one output: {' or '.join(given)}")
    page_on_stdout = html_path is not None and names_stdout(html_path)  # alone there (cli.arguments.paths)
    plots_dir, plot_format, dpi = plots["plots_dir"], plots["plot_format"], plots["dpi"]
    if plots_dir is not None:
        from relevance_plan.batch.plots import check_plot_targets, require_matplotlib

        require_matplotlib("--plots")
        check_plot_targets(plots_dir, store_path, plot_format)
    rows = read_rows(store_path, suite)
    if plots_dir is not None:
        from relevance_plan.batch.plots import unplotted_note, write_plots

        # no file this run writes may be the target of another (the page over a plot)
        suites = sorted({row["suite"] for row in rows})
        plots = [("plot", path) for path in check_plot_targets(plots_dir, store_path, plot_format, suites)]
        check_distinct_outputs(plots + ([] if html_path is None or page_on_stdout else [("HTML report", html_path)]))
        written = write_plots(rows, plots_dir, store=store_path, fmt=plot_format, dpi=dpi)
        unplotted = unplotted_note(suites)
        click.echo(
            "wrote " + ", ".join(str(path) for path in written) + (f" ({unplotted})" if unplotted else ""), err=True
        )
    if html_path is not None:
        from relevance_plan.batch.html_report import format_html

        page = format_html(rows, title=f"relevance-plan report: {Path(store_path).name}")
        where = write_output(html_path, page)
        if page_on_stdout:
            return  # the page holds the tables
        click.echo(f"wrote {where}", err=True)
    if per_job:
        click.echo(format_jobs(rows, "json" if as_json else "csv"), nl=False)
    else:
        click.echo(format_report(build_report(rows), fmt or "markdown"), nl=False)


@click.command()
@click.argument("suite_dir", metavar="SUITE_DIR", type=click.Path())
@scoring_options
@click.option(
    "--taus",
    type=THRESHOLDS,
    default="0.1,0.2,0.3,0.4,0.5",
    show_default=True,
    help="Threshold values for both axes.",
)
@file_option("--heatmap", help="Write a PNG heatmap (needs matplotlib).")
@json_option()
@handle_errors
def sweep(suite_dir, taus, heatmap, as_json, **values):
    """Objects kept, timing and (with the generator's sidecars) precision, recall, F1 and N
    over a tau_c x tau_e grid for a suite."""
    from relevance_plan.batch.suites import find_suite_problems
    from relevance_plan.batch.sweep import format_sweep, sweep_suite
    from relevance_plan.cli.files import check_output_file

    options = take_scoring(values)
    if heatmap:
        from relevance_plan.batch.plots import require_matplotlib

        require_matplotlib("--heatmap")
        # Every file the sweep reads is an input the heatmap must not replace (a domain may sit in a parent folder).
        inputs = [str(p) for e in find_suite_problems(suite_dir) for p in (e.problem, e.domain) if p is not None]
        check_output_file(heatmap, "heatmap file", inputs)
    result = sweep_suite(Path(suite_dir), taus, options)
    if heatmap:
        from relevance_plan.batch.plots import write_heatmap

        click.echo(f"wrote {write_heatmap(result, heatmap)}", err=True)
    click.echo(json_text(result.to_json()) if as_json else format_sweep(result))


@click.command()
@file_option(
    "--workdir",
    folder=True,
    help="Where suites and results go, kept (default: a temporary folder, removed at the end).",
)
@click.option("--count", type=SUITE_SIZE, default=3, show_default=True, help="Problems per world.")
@timeout_option(60.0, "Seconds per job.")
@click.option("--jobs", "-j", type=JOBS, default=2, show_default=True, help="Jobs run at once.")
@click.option("--distractors", type=DISTRACTORS, default=None, help="Distractors per problem (default 30).")
@click.option("--tiny", is_flag=True, help="1 problem per world with 5 distractors (a quick check).")
@quiet_option("No progress display.")
@handle_errors
def demo(workdir, count, timeout, jobs, distractors, tiny, quiet):
    """Generate coffee and cereal suites, compare relevance, pure, random and oracle, print the table."""
    from relevance_plan.batch.demo import run_demo

    with progress_bar("compare", live=None if not quiet else False) as bar:
        run = run_demo(
            workdir, count, timeout, jobs, distractors=distractors, tiny=tiny, progress=None if quiet else bar
        )
    click.echo(run.table, nl=False)
    click.echo("")
    if run.workdir is None:
        click.echo(
            f"{counted(run.summary.ran, 'job')} run in a temporary folder, now removed; "
            "--workdir DIR keeps the suites and the results store"
        )
        return
    click.echo(f"suites: {', '.join(str(s) for s in run.suites)}")
    click.echo(f"results: {run.store_path} ({run.summary.ran} run now, {run.summary.already_stored} reused)")
    click.echo(f"more: relevance-plan report {run.store_path} --format latex --plots {run.workdir / 'plots'}")


_OLD_TIMEOUT = "learn: --time-limit"


def _old_timeout(context: click.Context, _parameter: click.Parameter, value: float | None) -> None:
    """Keeps ``--time-limit``'s value aside for the command, which says it is deprecated."""
    if value is not None:
        context.meta[_OLD_TIMEOUT] = value


@click.command()
@click.argument("domain_path", metavar="DOMAIN", type=click.Path(dir_okay=False))
@click.argument("problem_paths", metavar="PROBLEM...", nargs=-1, type=click.Path(dir_okay=False))
@file_option("-o", "--output", "output_path", required=True, help="Model file (JSON).")
@timeout_option(LEARN_TIMEOUT, "Seconds for each planner run on a problem.")
# The option's name until 0.12, kept for a release: hidden, said to be deprecated when used.
@click.option("--time-limit", type=seconds(), default=None, hidden=True, expose_value=False, callback=_old_timeout)
@click.option(
    "--labels",
    type=NamedChoice(("plan", "minimal"), "labelling"),
    default="plan",
    show_default=True,
    help="plan: the objects the plan uses, with their closure (one run a problem); minimal: PLOI's greedy minimal"
    " sufficient set (one run per object).",
)
@click.option("--seed", type=SEED, default=0, show_default=True, help="Seed of the order 'minimal' drops objects in.")
@file_option(
    "--store",
    "store_path",
    help="Learn from the solved runs of this results store (their plans) instead of planning again.",
)
@quiet_option()
@handle_errors
def learn(domain_path, problem_paths, output_path, timeout, labels, seed, store_path, quiet):
    """Learn which objects matter from solved PROBLEMs of DOMAIN; use the model with --scorer learned:MODEL.

    "-o -" writes the model to standard output (the summary goes to stderr).
    """
    from relevance_plan.batch.learn import learn as learn_model
    from relevance_plan.batch.learn import learn_from_store
    from relevance_plan.cli.files import names_stdout, write_output
    from relevance_plan.relevance.scoring.learning.learned_model import learned_model_text

    time_limit = click.get_current_context().meta.get(_OLD_TIMEOUT)
    if time_limit is not None:
        if click.get_current_context().get_parameter_source("timeout") is click.core.ParameterSource.COMMANDLINE:
            raise UsageError("give --timeout only (--time-limit is its old, deprecated name)")
        click.echo("relevance-plan: --time-limit is deprecated: use --timeout", err=True)
        timeout = time_limit

    def say(message: str) -> None:
        if not quiet:
            click.echo(f"... {message}", err=True)

    if store_path is not None:
        report = learn_from_store(domain_path, store_path, problem_paths, labels=labels, seed=seed, say=say)
    else:
        if not problem_paths:
            raise UsageError("give the training PROBLEMs (or --store STORE)")
        report = learn_model(domain_path, problem_paths, time_limit=timeout, labels=labels, seed=seed, say=say)
    where = write_output(output_path, learned_model_text(report.model))
    model = report.model
    click.echo(
        f"learned from {len(report.problems)} problems ({len(report.skipped)} skipped) in {report.seconds:.1f} s:"
        f" {model.training.get('needed')} of {model.training.get('objects')} objects needed ({labels} labels),"
        f" keeps above P = {model.threshold:.3f}; model written to {where}",
        err=names_stdout(output_path),  # with the model on stdout, the summary goes to stderr
    )
