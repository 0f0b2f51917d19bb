"""The command line as click reads it: every numeric option checked in one place, usage errors in one
line, --verbose, the validators as a comma list, learn's --timeout and its old name."""

from __future__ import annotations

import logging
import warnings

import click
import pytest
from click.testing import CliRunner
from support import COFFEE_DOMAIN, coffee_problem, invoke, one_line_error, run, write_file

from relevance_plan.cli import main
from relevance_plan.cli.arguments.choices import CheckedName, NamedChoice, NamedChoices
from relevance_plan.cli.arguments.numbers import NumberOption
from relevance_plan.cli.common import handle_errors
from relevance_plan.exitcodes import ExitCode


def _commands() -> dict[str, click.Command]:
    """Every command the user runs: a group's (``scene-graph``) as ``group sub``."""
    context = click.Context(main)
    found = {}
    for name in main.list_commands(context):
        command = main.get_command(context, name)
        if isinstance(command, click.Group):
            found.update({f"{name} {sub}": command.commands[sub] for sub in command.commands})
        else:
            found[name] = command
    return found


def _numeric_options() -> list[tuple[str, click.Parameter]]:
    return [
        (name, param)
        for name, command in _commands().items()
        for param in command.params
        if isinstance(param.type, (click.types.IntParamType, click.types.FloatParamType, NumberOption))
    ]


@pytest.fixture
def arguments(tmp_path):
    """The positional arguments that let each command read its options (nothing runs: the option fails)."""
    problem = write_file(tmp_path, "p.pddl", coffee_problem())
    return {
        "generate": ["coffee", "--out", tmp_path / "suite"],
        "score": [COFFEE_DOMAIN, problem],
        "prune": [COFFEE_DOMAIN, problem, "-o", tmp_path / "small.pddl"],
        "plan": [COFFEE_DOMAIN, problem, "--plan-file", tmp_path / "plan"],
        "watch": [COFFEE_DOMAIN, problem, "--events", problem],
        "compare": [tmp_path, "--store", tmp_path / "s.sqlite"],
        "report": [tmp_path / "s.sqlite"],
        "sweep": [tmp_path],
        "demo": ["--workdir", tmp_path / "demo"],
        "learn": [COFFEE_DOMAIN, problem, "-o", tmp_path / "m.json"],
        "validate": [COFFEE_DOMAIN, problem, problem],
        "scene-graph import": [problem, "-o", tmp_path / "out", "--goal", "(x)"],
        "scene-graph watch": [problem, "--goal", "(x)"],
    }


def test_every_numeric_option_is_checked_in_one_place():
    found = _numeric_options()
    assert {name for name, _ in found} >= {"plan", "learn", "compare", "report", "generate", "demo", "sweep"}
    unchecked = [f"{name} {param.opts[0]}" for name, param in found if not isinstance(param.type, NumberOption)]
    assert not unchecked


@pytest.mark.parametrize("name, param", _numeric_options(), ids=lambda p: getattr(p, "name", p))
def test_no_numeric_option_takes_a_number_out_of_its_range(name, param, arguments, tmp_path):
    """nan, infinities and numbers past either end: exit 30 in one line naming the option, nothing written."""
    kind = param.type
    if kind.kind is float:
        values = ["nan", "inf", "-inf", "1e999", "-1e999", str(kind.low - 1.0)]
    else:
        values = [str(-(10**30))] + ([] if kind.high is None else [str(10**30)])
    option = max(param.opts, key=len)
    before = sorted(tmp_path.rglob("*"))
    for value in values:
        code, _, stderr = run(*name.split(), *arguments[name], option, value)
        assert code == ExitCode.USAGE, f"{name} {option} {value}: {stderr}"
        assert option in one_line_error(stderr)
    assert sorted(tmp_path.rglob("*")) == before


# Options whose names the library checks (a planner template, a world's difficulty): plain text to click.
CHECKED_BY_THE_LIBRARY = {"planner", "planners", "methods", "difficulty"}
NAMED_TYPES = (NamedChoice, CheckedName, NamedChoices)


def _named_options() -> list[tuple[str, click.Parameter]]:
    """Every command's option that takes one of a set of names: a choice of click's or ours, or one the
    library checks."""
    return [
        (name, param)
        for name, command in _commands().items()
        for param in command.params
        if isinstance(param, click.Option)
        and (isinstance(param.type, (click.Choice, *NAMED_TYPES)) or param.name in CHECKED_BY_THE_LIBRARY)
    ]


def test_every_option_of_names_is_checked_in_one_place():
    found = _named_options()
    kinds = {param.name for _, param in found}
    assert kinds >= {"method", "methods", "scorer", "planner", "planners", "validators", "validator", "labels", "fmt"}
    unchecked = [
        f"{name} {param.opts[0]}"
        for name, param in found
        if param.name not in CHECKED_BY_THE_LIBRARY and not isinstance(param.type, NAMED_TYPES)
    ]
    assert not unchecked


@pytest.mark.parametrize("name, param", _named_options(), ids=lambda p: getattr(p, "name", p))
def test_a_name_an_option_does_not_know_is_exit_30_in_every_command(name, param, arguments, tmp_path):
    """The same mistake, the same code, whichever command reads it and whoever finds it: one line naming
    the value, nothing written."""
    option = max(param.opts, key=len)
    value = "relevance,no-such-name" if param.name == "methods" else "no-such-name"
    before = sorted(tmp_path.rglob("*"))
    code, _, stderr = run(*name.split(), *arguments[name], option, value)
    assert code == ExitCode.USAGE, f"{name} {option} {value}: {stderr}"
    assert "'no-such-name'" in one_line_error(stderr)
    assert sorted(tmp_path.rglob("*")) == before


@pytest.mark.parametrize(
    "args, needle",
    [
        (["plan", COFFEE_DOMAIN, COFFEE_DOMAIN, "--no-such-option"], "--no-such-option"),
        (["plan", COFFEE_DOMAIN], "PROBLEM"),
        (["plan", COFFEE_DOMAIN, COFFEE_DOMAIN, "--method"], "--method"),
        (["plan", COFFEE_DOMAIN, COFFEE_DOMAIN, "--timeout", "soon"], "--timeout"),
        (["plan", COFFEE_DOMAIN, COFFEE_DOMAIN, "--timeout"], "--timeout"),
        (["no-such-command"], "no-such-command"),
        (["report"], "STORE"),
        ([], "no command"),
        (["prune", COFFEE_DOMAIN, COFFEE_DOMAIN], "--output"),
        (["learn", COFFEE_DOMAIN, COFFEE_DOMAIN], "--output"),
        (["generate", "coffee"], "--out"),
    ],
)
def test_usage_errors_are_one_line_naming_what_is_wrong(args, needle):
    result = CliRunner().invoke(main, [str(a) for a in args])
    assert result.exit_code == ExitCode.COMMAND_LINE
    line = one_line_error(result.stderr)
    assert needle in line and "Usage:" not in line


def test_other_packages_warnings_and_log_lines_need_verbose():
    @click.command()
    @handle_errors
    def noisy():
        warnings.warn("a package's warning on import", UserWarning, stacklevel=1)
        logging.getLogger("distributed.client").error("Failed to reconnect to scheduler")
        click.echo("done")

    quiet = CliRunner().invoke(noisy, [])
    assert quiet.exit_code == 0 and quiet.stdout == "done\n" and quiet.stderr == ""
    logging.getLogger("distributed.client").addHandler(handler := logging.StreamHandler())
    try:
        with warnings.catch_warnings(record=True) as heard:
            warnings.simplefilter("always")
            loud = CliRunner().invoke(noisy, ["--verbose"])
    finally:
        logging.getLogger("distributed.client").removeHandler(handler)
    assert loud.exit_code == 0 and [str(w.message) for w in heard] == ["a package's warning on import"]
    assert logging.root.manager.disable == logging.NOTSET  # the quiet ends with the command


def test_every_command_takes_verbose():
    assert [name for name, command in _commands().items() if "verbose" not in {p.name for p in command.params}] == []


def test_validators_as_a_comma_list_or_repeated(tmp_path):
    """The list is read as docs/validation.md writes it: 'none' beside a validator is refused either way,
    and so is an unknown name (exit 30, the options' own check)."""
    problem = write_file(tmp_path, "p.pddl", coffee_problem())
    plan = ["plan", COFFEE_DOMAIN, problem, "--plan-file", tmp_path / "plan", "-q"]
    for given in (["--validator", "builtin,none"], ["--validator", "builtin", "--validator", "none"]):
        code, _, stderr = run(*plan, *given)
        assert code == ExitCode.USAGE and "none" in one_line_error(stderr)
    code, _, stderr = run(*plan, "--validator", "builtin,magic")
    assert code == ExitCode.USAGE and "'magic'" in one_line_error(stderr)


@pytest.mark.planner
def test_plan_with_builtin_and_val_as_validation_md_writes_it(tmp_path):
    from relevance_plan.planning.validation import val_available

    if not val_available():
        pytest.skip("VAL is not installed")
    problem = write_file(tmp_path, "p.pddl", coffee_problem())
    result = invoke("plan", COFFEE_DOMAIN, problem, "--validator", "builtin,val", "--plan-file", tmp_path / "plan")
    assert result.exit_code == 0, result.stderr
    assert "valid on the original problem (builtin+val)" in result.stdout


def test_learns_old_time_limit_is_a_deprecated_name_for_timeout(tmp_path):
    problem = write_file(tmp_path, "p.pddl", coffee_problem())
    learn = ["learn", COFFEE_DOMAIN, problem, "-o", tmp_path / "m.json"]
    assert "--time-limit" not in invoke("learn", "--help").stdout and "--timeout" in invoke("learn", "--help").stdout
    code, _, stderr = run(*learn, "--time-limit", "nan")
    assert code == ExitCode.USAGE and "--time-limit" in one_line_error(stderr)
    code, _, stderr = run(*learn, "--time-limit", "5", "--timeout", "5")
    assert code == ExitCode.USAGE and "--timeout only" in one_line_error(stderr)
    assert not (tmp_path / "m.json").exists()


# --------------------------------------------------------------------------- the method, one spelling


def test_the_method_is_one_enum_spelled_one_way_everywhere():
    import json

    from relevance_plan.cli.common import method_option
    from relevance_plan.errors import UsageError
    from relevance_plan.planning.methods import METHODS, Method
    from relevance_plan.planning.options import PlanOptions
    from relevance_plan.planning.planners.fast_downward import head_start
    from relevance_plan.planning.results import PlanResult, PlanStatus

    options = PlanOptions(method="pure")
    assert options.method is Method.PURE and not options.method.prunes and not options.narrows_first
    assert PlanOptions().method is Method.RELEVANCE and PlanOptions().narrows_first
    assert METHODS == tuple(method.value for method in Method) == ("relevance", "pure", "random", "oracle")
    assert f"{Method.ORACLE}" == str(Method.ORACLE) == "oracle" == Method.ORACLE
    result = PlanResult(method=options.method, status=PlanStatus.SOLVED)
    assert json.loads(json.dumps(result.to_json()))["method"] == "pure"
    assert head_start.DEFAULT_METHOD is Method.RELEVANCE
    with pytest.raises(UsageError, match="unknown method 'puree' \\(choose from: relevance, pure, random, oracle\\)"):
        PlanOptions(method="puree")

    @method_option
    def command(method):
        pass

    (choice,) = [param for param in command.__click_params__ if param.name == "method"]
    assert tuple(choice.type.choices) == METHODS and choice.default == Method.RELEVANCE
