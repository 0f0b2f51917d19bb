"""``relevance-plan draft-model``: a knowledge model drafted from a domain and its problems, for review."""

from __future__ import annotations

import click

from relevance_plan.cli.common import file_option, handle_errors, json_option, json_text, quiet_option
from relevance_plan.errors import counted


@click.command("draft-model")
@click.argument("domain_path", metavar="DOMAIN", type=click.Path(dir_okay=False))
@click.argument("problem_paths", metavar="PROBLEM...", nargs=-1, required=True, type=click.Path(dir_okay=False))
@file_option("-o", "--output", "output", required=True, help="Knowledge-model YAML to write ('-': standard output).")
@json_option("Print what the check found as one JSON object.")
@quiet_option("Print nothing but errors.")
@handle_errors
def draft_model(domain_path, problem_paths, output, as_json, quiet):
    """Draft a knowledge model for DOMAIN from its action schemas and PROBLEMs, for a person to review.

    Classes come from the types (kinds from the objects' names), the scene
    predicates from the action schemas, objectives from the problems' goals,
    priors from what goal regression says can play a role.  The draft is
    checked on every PROBLEM against the goal scorer (it must keep what a first
    attempt needs, and at most 1.2 times what the goal scorer needs) and
    adjusted; what it could not match is said, here and in the file.
    """
    from relevance_plan.cli.files import check_output_file, names_stdout, write_output
    from relevance_plan.io import check_input_file, load_domain, load_problem
    from relevance_plan.pddl.sexpr import collection_paused
    from relevance_plan.relevance.analysis.task import PlanningTask
    from relevance_plan.relevance.drafting import draft_model as draft

    for path in problem_paths:
        check_input_file(path, "problem file")
    check_output_file(output, "output file", [domain_path, *problem_paths])
    with collection_paused():
        domain = load_domain(domain_path)
        tasks = [PlanningTask(domain, load_problem(path, domain)) for path in problem_paths]
        drafted = draft(domain, tasks, str(output))
    where = write_output(output, drafted.text)
    to_stdout = names_stdout(output)
    if as_json:
        data = {
            "output": where,
            "matched": drafted.matched,
            "classes": len(drafted.model.classes),
            "objectives": list(drafted.model.objectives),
            "dependencies": len(drafted.model.dependencies),
            "adjustments": list(drafted.adjustments),
            "problems": [_check_json(check) for check in drafted.checks],
        }
        click.echo(json_text(data))  # never beside the model on stdout (cli.arguments.paths refuses both there)
    elif not quiet:
        for check in drafted.checks:
            click.echo(f"{'' if check.matched else 'not matched: '}{check.describe()}", err=to_stdout)
        click.echo(_summary(drafted, where), err=to_stdout)
    if not drafted.matched and (quiet or as_json):
        unmatched = ", ".join(check.problem for check in drafted.unmatched)
        click.echo(f"relevance-plan: draft-model: the draft does not match the goal scorer on {unmatched}", err=True)


def _summary(drafted, where: str) -> str:
    model = drafted.model
    count = len(model.dependencies)
    said = (
        f"wrote {where}: {counted(len(model.classes), 'class', 'classes')},"
        f" {counted(len(model.objectives), 'objective')}, {counted(count, 'dependency', 'dependencies')}"
    )
    if drafted.adjustments:
        said += f"; the check changed {counted(len(drafted.adjustments), 'entry', 'entries')} (see the file's header)"
    if not drafted.matched:
        said += f"; not matched on {len(drafted.unmatched)} of {len(drafted.checks)} problems: review it"
    return said


def _check_json(check) -> dict:
    return {
        "problem": check.problem,
        "objects": check.objects,
        "kept": check.kept,
        "goal_scorer_kept": check.goal_kept,
        "goal_scorer_lacks": list(check.goal_lacks),
        "lacks": list(check.lacks),
        "insufficiency": check.insufficiency or None,
        "matched": check.matched,
    }
