"""Path arguments are checked by the project, not by click.

click's own checks end with its four-line usage block and exit 2; a bad file
is exit 31 with one line, and an output that is also an input is exit 30
(``io.check_input_file`` / ``cli.files.check_output_file``).  ``own_path_checks``
is applied once to the command group: it makes every ``click.Path`` accept
any string and checks the values itself before the command runs.
"""

from __future__ import annotations

import functools
import os
from pathlib import Path

import click

# Parameter name -> what the file is, for the messages.
INPUT_FILES = {
    "domain_path": "domain file",
    "problem_path": "problem file",
    "problem_paths": "problem file",
    "model_path": "knowledge model",
    "plan_path": "plan file",
}
OUTPUT_FILES = {
    "output": "output file",
    "output_path": "model file",
    "plan_file": "plan file",
    "heatmap": "heatmap file",
    "html_path": "HTML report",
}
# Outputs ``-`` (standard output) may not name, and why: ``-`` is standard output for every other
# output (``prune -o``, ``learn -o``, ``plan --plan-file``, ``report --html``).
NOT_STDOUT = {
    "out_dir": "it names a folder",
    "keep_work": "it names a folder",
    "folder": "it names a folder",
    "plots_dir": "it names a folder",
    "workdir": "it names a folder",
    "snapshot_dir": "it names a folder",
    "heatmap": "the table goes there",
    "store_path": "it names a results store",
}
# Flags that put a command's own output on standard output: beside an output file naming standard
# output (``-o -``, ``--plan-file -``, ``--html -``), one of the two would be lost in the other.
STDOUT_FLAGS = {"as_json": "--json", "as_csv": "--csv", "fmt": "--format"}
# Read, never created, by these commands.
INPUT_STORES = {"report", "learn"}
# Inputs these commands hand to a planner, which reads them again: a pipe (``<(...)``, /dev/stdin) gives its text once.
REREAD = {"plan": ("domain_path", "problem_path"), "watch": ("domain_path",), "learn": ("domain_path", "problem_paths")}


class _UncheckedPath(click.Path):
    """Shows the same metavar as the original, checks nothing."""

    def convert(self, value, param, ctx):
        return value


def _as_list(value) -> list:
    if value is None:
        return []
    return list(value) if isinstance(value, (list, tuple)) else [value]


def _check_not_stdout(command: click.Command, values: dict) -> None:
    """``UsageError`` for ``-`` naming an output that standard output cannot take (see ``NOT_STDOUT``)."""
    from relevance_plan.errors import UsageError
    from relevance_plan.io import STDOUT

    for param in command.params:
        why = NOT_STDOUT.get(param.name or "")
        if why is None or (param.name == "store_path" and command.name in INPUT_STORES):
            continue
        if STDOUT in _as_list(values.get(param.name or "")):
            option = max(param.opts, key=len) if isinstance(param, click.Option) else param.human_readable_name
            raise UsageError(f"{option} cannot be '-' (standard output): {why}; give a name")


def _check_one_on_stdout(command: click.Command, values: dict) -> None:
    """``UsageError`` when an output naming standard output (``-o -``, a link to it) and a flag that
    prints there (``--json``) are both given, whichever the command: one would be lost in the other."""
    from relevance_plan.cli.files import names_stdout
    from relevance_plan.errors import UsageError

    flags = [flag for name, flag in STDOUT_FLAGS.items() if values.get(name) not in (None, False)]
    for param in command.params:
        if param.name not in OUTPUT_FILES or not flags:
            continue
        value = values.get(param.name)
        if value is not None and names_stdout(value):
            option = min(param.opts, key=len)
            raise UsageError(
                f"{flags[0]} and '{option} {value}' would both write to standard output; give {option} a file name"
            )


def _check(command: click.Command, values: dict) -> None:
    from relevance_plan.cli.files import check_output_file, check_regular_file
    from relevance_plan.io import check_input_file

    command_name = command.name or ""
    _check_not_stdout(command, values)
    _check_one_on_stdout(command, values)
    inputs = []
    for name, what in INPUT_FILES.items():
        for path in _as_list(values.get(name)):
            check_input_file(path, what)
            if name in REREAD.get(command_name, ()):
                check_regular_file(path, what, f"{command_name} gives it to the planner")
            inputs.append(path)
    if values.get("domain_path") is not None and values.get("model_path") is None:
        # The model found next to the domain is an input too.
        found = Path(values["domain_path"]).parent / "relevance.yaml"
        if found.is_file():
            inputs.append(str(found))
    if values.get("store_path") is not None:
        if command_name in INPUT_STORES:
            check_input_file(values["store_path"], "results store")
        inputs.append(values["store_path"])
    # A suite's files are inputs too (``sweep --heatmap SUITE/domain.pddl``).
    for suite in _as_list(values.get("suite_dir")) + _as_list(values.get("suite_dirs")):
        if os.path.isdir(suite):
            inputs += [str(path) for path in Path(suite).iterdir() if path.suffix in (".pddl", ".json")]
    for name, what in OUTPUT_FILES.items():
        if values.get(name) is not None:
            check_output_file(values[name], what, inputs)


def _checked(command: click.Command):
    callback = command.callback
    assert callback is not None  # every command of the CLI has one

    @functools.wraps(callback)
    def wrapper(*args, **kwargs):
        from relevance_plan.cli.common import handled

        handled(_check)(command, kwargs)
        return callback(*args, **kwargs)

    return wrapper


def own_path_checks(group: click.Group) -> None:
    """Take the path checks of every command of ``group`` away from click."""
    for command in group.commands.values():
        own_command_path_checks(command)


def own_command_path_checks(command: click.Command) -> None:
    """Take the path checks of ``command`` away from click (once: a second call changes nothing)."""
    changed = False
    for param in command.params:
        if isinstance(param.type, click.Path) and not isinstance(param.type, _UncheckedPath):
            original = param.type
            param.type = _UncheckedPath(
                file_okay=original.file_okay, dir_okay=original.dir_okay, allow_dash=original.allow_dash
            )
            changed = True
    if changed and command.callback is not None:
        command.callback = _checked(command)
