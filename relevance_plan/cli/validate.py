"""The ``validate`` command: judge a plan file on a problem, as the attempt loop judges its plans."""

from __future__ import annotations

import sys

import click

from relevance_plan.cli.arguments.choices import NamedChoice
from relevance_plan.cli.common import handle_errors, json_option, json_text, task_arguments, timeout_option
from relevance_plan.errors import counted
from relevance_plan.exitcodes import ExitCode
from relevance_plan.pddl.formatter import format_number
from relevance_plan.planning.validation import VALIDATORS

# What VAL was always given to judge a plan; the builtin simulator takes milliseconds.
VALIDATE_TIMEOUT = 60.0


@click.command()
@task_arguments
@click.argument("plan_path", metavar="PLAN", type=click.Path(dir_okay=False))
@click.option(
    "--validator",
    type=NamedChoice(VALIDATORS, "validator"),
    default="builtin",
    show_default=True,
    help="builtin (the simulator the attempt loop uses), val (VAL's Validate: pip install"
    " 'relevance-plan[val]'), up (unified-planning's validators).",
)
@timeout_option(VALIDATE_TIMEOUT, "Seconds the validator may take to judge the plan.")
@json_option("Print one JSON object.")
@handle_errors
def validate(domain_path, problem_path, plan_path, validator, timeout, as_json):
    """Check that PLAN (sequential or timed, IPC format) solves PROBLEM.

    Exit 0 for a valid plan, 13 for an invalid one (with the first failing
    step and why), 41 when the validator cannot run or judge within --timeout.
    """
    from relevance_plan.cli.files import check_regular_file
    from relevance_plan.planning.validation import check_plan_file

    if validator != "builtin":  # VAL and unified-planning read the files again
        for path, what in ((domain_path, "domain file"), (problem_path, "problem file")):
            check_regular_file(path, what, f"--validator {validator} reads it again")
    check = check_plan_file(domain_path, problem_path, plan_path, validator, timeout)
    result = check.result
    if as_json:
        click.echo(json_text(check.to_json()))
    else:
        kind = "timed plan" if check.timed else "plan"
        metric = "" if check.metric is None else f", metric {format_number(check.metric)}"
        verdict = "valid" if result.valid else "INVALID"
        click.echo(f"{verdict}: {kind} of {counted(check.steps, 'step')}{metric} ({result.validator})")
        if result.failed_step is not None:
            click.echo(f"failed step: {result.failed_step}")
        click.echo(f"reason:      {result.message}")
    if not result.valid:
        sys.exit(int(ExitCode.PLAN_INVALID))
