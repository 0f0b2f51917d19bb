"""What every command shares: error handling and the option groups that build the options objects.

An option group is a decorator that adds its options to a command; its
builder turns the parsed values into the library's options object
(:class:`ScoringOptions`, :class:`PlanOptions`).  Each option is declared
here once, so ``score``, ``prune``, ``plan``, ``sweep``, ``compare`` and
``watch`` cannot drift apart.
"""

from __future__ import annotations

import contextlib
import errno
import functools
import json
import math
import shlex
import sys
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import click

from relevance_plan.cli.arguments.choices import CheckedName, NamedChoice, NamedChoices
from relevance_plan.cli.arguments.numbers import MEGABYTES, SEED, THRESHOLD, seconds
from relevance_plan.errors import InputFileError, RelevancePlanError, UsageError, ValidatorUnavailableError
from relevance_plan.exitcodes import ExitCode, exit_code_for_error
from relevance_plan.limits import DEFAULT_TIMEOUT
from relevance_plan.planning.options import METHODS, Method, PlanOptions
from relevance_plan.planning.planners.registry import DEFAULT_PLANNER, DEFAULT_PLANNER_CONFIG
from relevance_plan.planning.results import PlanResult
from relevance_plan.planning.validation import VALIDATOR_CHOICES
from relevance_plan.relevance.scoring.scorers import SCORERS
from relevance_plan.relevance.selection.prune import DEFAULT_TAU, Thresholds
from relevance_plan.relevance.setup import ScoringOptions, check_scorer, given_cues


def fail(message: str, code: ExitCode) -> None:
    click.echo(f"relevance-plan: error: {message}", err=True)
    sys.exit(int(code))


# Errors of writing standard output (a full disk, /dev/full, an I/O error): they name no file.
_OUTPUT_ERRNOS = (errno.ENOSPC, errno.EIO, errno.EFBIG, errno.EDQUOT)


def handle_errors(command):
    """A command's callback, its errors handled (:func:`handled`) and its ``--verbose`` option added: the
    warnings and log lines of the packages the tool imports reach stderr only with ``--verbose``."""

    @functools.wraps(command)
    def wrapper(*args, verbose: bool = False, **kwargs):
        with third_parties_heard(verbose):
            return command(*args, **kwargs)

    return click.option(
        "--verbose", is_flag=True, help="Also show the warnings and log lines of the packages the tool uses."
    )(handled(wrapper))


@contextlib.contextmanager
def third_parties_heard(heard: bool) -> Iterator[None]:
    """Unless ``heard``, the warnings and log lines of other packages (a planner package's warning on
    import, Dask's reconnection messages) stay off stderr while the block runs: the tool's own
    messages are its lines there.  The tool itself neither warns nor logs."""
    if heard:
        yield
        return
    import logging
    import warnings

    disabled = logging.root.manager.disable
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        logging.disable(logging.CRITICAL)
        try:
            yield
        finally:
            logging.disable(disabled)


def handled(function):
    """Every library error of ``function`` becomes one line on stderr and its documented exit code."""

    @functools.wraps(function)
    def wrapper(*args, **kwargs):
        from relevance_plan.cli.exits import (
            quit_if_memory_ran_out,
            quit_on_broken_pipe,
            quit_on_output_error,
        )
        from relevance_plan.signals import DEADLINE_SIGNAL, interrupt_on_signals

        try:
            with interrupt_on_signals():
                return function(*args, **kwargs)
        except RelevancePlanError as error:
            fail(str(error), exit_code_for_error(error))
        except BrokenPipeError:
            quit_on_broken_pipe()  # the reader of our output went away
        except OSError as error:
            if error.filename is None and error.errno in _OUTPUT_ERRNOS:
                quit_on_output_error(error)
            # A file-system error the library did not anticipate (a name too
            # long, a full disk) is still a file problem: one line, exit 31.
            where = InputFileError(error.strerror or str(error), path=error.filename)
            fail(str(where), ExitCode.INPUT_FILE)
        except (MemoryError, SystemError) as error:
            quit_if_memory_ran_out(error)
            raise
        except KeyboardInterrupt as error:
            if getattr(error, "signum", None) == DEADLINE_SIGNAL:
                fail("out of time: the run went past its --timeout", ExitCode.OUT_OF_TIME)
            by = f" by {error}" if str(error) else ""
            click.echo(f"relevance-plan: interrupted{by}", err=True)
            sys.exit(int(ExitCode.INTERRUPTED))

    return wrapper


def _apply(command, decorators):
    for decorator in reversed(decorators):
        command = decorator(command)
    return command


# --------------------------------------------------------------------------- files and output


def task_arguments(command):
    """DOMAIN PROBLEM: the two files a command on one problem reads."""
    return _apply(
        command,
        [
            click.argument("domain_path", metavar="DOMAIN", type=click.Path(dir_okay=False)),
            click.argument("problem_path", metavar="PROBLEM", type=click.Path(dir_okay=False)),
        ],
    )


def file_option(*names: str, help: str, folder: bool = False, default: str | None = None, **more):
    """An option naming a file (``folder``: a directory); ``paths`` checks it before the command runs."""
    kind = click.Path(file_okay=False) if folder else click.Path(dir_okay=False)
    if default is not None:  # click counts an explicit default of None as given: a required option would pass
        more["default"] = default
    return click.option(*names, type=kind, help=help, **more)


def json_option(help: str | None = None):
    return click.option("--json", "as_json", is_flag=True, help=help)


def json_text(data: Any, indent: int | None = 2) -> str:
    """``data`` as strict JSON (what ``--json`` prints): a number JSON cannot hold, an infinite
    metric or a NaN, is null there."""
    return json.dumps(_finite(data), indent=indent, allow_nan=False)


def _finite(data: Any) -> Any:
    if isinstance(data, float):
        return data if math.isfinite(data) else None
    if isinstance(data, dict):
        return {key: _finite(value) for key, value in data.items()}
    if isinstance(data, (list, tuple)):
        return [_finite(value) for value in data]
    return data


def timeout_option(default: float, help: str):
    """``--timeout`` in seconds: every command's time limit has this one name, and one check (``seconds``)."""
    return click.option("--timeout", type=seconds(), default=default, show_default=True, help=help)


def quiet_option(help: str = "No progress messages."):
    return click.option("--quiet", "-q", is_flag=True, help=help)


# --------------------------------------------------------------------------- scoring

SCORING_KEYS = (
    "scorer",
    "model_path",
    "objective",
    "activity",
    "human",
    "place_kinds",
    "tau_class",
    "tau_element",
    "seed",
)


def scoring_options(command=None, *, with_seed: bool = True):
    """--scorer --model --objective --activity --human --place-kinds --tau-class --tau-element [--seed]."""
    if command is None:
        return functools.partial(scoring_options, with_seed=with_seed)
    seed = [click.option("--seed", type=SEED, default=0, show_default=True, help="Seed of the random scorer.")]
    return _apply(
        command,
        [
            click.option(
                "--scorer",
                type=CheckedName(check_scorer, "[" + "|".join(sorted(SCORERS)) + "|learned:MODEL]"),
                default=None,
                help="Scorer: " + ", ".join(sorted(SCORERS)) + " or learned:MODEL (a model made by 'relevance-plan"
                " learn'); default: 'model' when a knowledge model applies, else 'goal'.",
            ),
            file_option(
                "--model",
                "model_path",
                help="Knowledge-model YAML (default: found next to the domain or among the shipped worlds).",
            ),
            click.option(
                "--objective",
                default=None,
                help="Objective from the model, or what the human wants in their own words (with the 'text' extra);"
                " default: matched from the goal.",
            ),
            click.option(
                "--activity",
                "--task",
                "activity",
                default=None,
                help="Fix the model's activity, P(activity | objective) = 1: its name, or a cue in words (the 'text'"
                " extra).  --task is its name until 0.12.",
            ),
            click.option("--human", default=None, help="Apply this human's recorded preferences."),
            click.option(
                "--place-kinds",
                is_flag=True,
                help="Place object kinds and types the model does not list under their nearest class (the 'text'"
                " extra); one that resembles no class stays unknown, and is asked about.",
            ),
            click.option(
                "--tau-class",
                type=THRESHOLD,
                default=DEFAULT_TAU,
                show_default=True,
                help="Class threshold tau_c in [0, 1].",
            ),
            click.option(
                "--tau-element",
                type=THRESHOLD,
                default=DEFAULT_TAU,
                show_default=True,
                help="Element threshold tau_e in [0, 1].",
            ),
        ]
        + (seed if with_seed else []),
    )


def take_scoring(values: dict) -> ScoringOptions:
    """ScoringOptions from a command's parsed values (the scoring keys are removed from ``values``)."""
    taken = {key: values.pop(key, 0 if key == "seed" else None) for key in SCORING_KEYS}
    taken["place_kinds"] = bool(taken["place_kinds"])
    thresholds = Thresholds(taken.pop("tau_class"), taken.pop("tau_element"))
    options = ScoringOptions(thresholds=thresholds, **taken)
    if options.learned_model_path is not None:
        from relevance_plan.relevance.scoring.learning.learned_model import load_learned_model

        load_learned_model(options.learned_model_path)  # a damaged file stops the command before any planning
    return options


# --------------------------------------------------------------------------- planning

PLANNING_KEYS = ("planner", "planner_config", "planner_args", "timeout", "memory_limit", "no_widen", "validators")


def planning_options(per_job: bool = False):
    """--planner --planner-config --planner-args --timeout --memory-limit --no-widen --validator."""
    per = "each job (relevance + planning)" if per_job else "the whole run"

    def group(command):
        return _apply(
            command,
            [
                click.option(
                    "--planner",
                    default=DEFAULT_PLANNER,
                    show_default=True,
                    help="auto (chosen by the problem's features: Fast Downward for classical problems, a temporal"
                    " or numeric planner otherwise), fast-downward, lpg, up:NAME (a unified-planning engine:"
                    " aries, tamer, enhsp, ...) or cmd:'TEMPLATE' (an external planner; {domain} {problem} [{plan}]).",
                ),
                click.option(
                    "--planner-config",
                    default=DEFAULT_PLANNER_CONFIG,
                    show_default=True,
                    help="Fast Downward alias, registered name, or search string.",
                ),
                click.option(
                    "--planner-args",
                    "planner_args",
                    default=None,
                    metavar="'ARGS'",
                    help="Arguments appended to the planner's command line, split as a shell would (never run by "
                    "one); Fast Downward: after the inputs, e.g. '--translate-options "
                    "--invariant-generation-max-candidates 1000'.",
                ),
                timeout_option(DEFAULT_TIMEOUT, f"Seconds for {per}."),
                click.option(
                    "--memory-limit",
                    "memory_limit",
                    type=MEGABYTES,
                    default=None,
                    help="Planner memory limit in MB.",
                ),
                click.option(
                    "--no-widen",
                    "--no-relax",
                    "no_widen",
                    is_flag=True,
                    help="One attempt only (the paper's behaviour).",
                ),
                click.option(
                    "--validator",
                    "validators",
                    multiple=True,
                    type=NamedChoices(VALIDATOR_CHOICES, "validator"),
                    help="Validator(s) to use, repeated or comma-separated (--validator builtin,val; default:"
                    " builtin); 'none': report the plan NOT validated.",
                ),
            ],
        )

    return group


def take_plan_options(values: dict, method: str = Method.RELEVANCE) -> PlanOptions:
    """PlanOptions from a command's parsed values (scoring and planning keys are removed).

    What can be checked before planning is checked here: the pass-through
    arguments split, and a validator asked for by name can run.
    """
    scoring = take_scoring(values)
    given = given_cues(scoring)
    if given and method != Method.RELEVANCE:
        verb = "applies" if len(given) == 1 else "apply"
        raise UsageError(f"{' and '.join(given)} {verb} to --method relevance only, not to --method {method}")
    taken = {key: values.pop(key) for key in PLANNING_KEYS}
    # --validator builtin,val --validator val: each named once, in the order first named
    taken["validators"] = tuple(dict.fromkeys(name for names in taken["validators"] for name in names))
    require_installed_validators(taken["validators"])
    return PlanOptions.from_scoring(
        scoring,
        method=method,
        planner=taken["planner"],
        planner_config=taken["planner_config"],
        timeout=taken["timeout"],
        memory_limit_mb=taken["memory_limit"],
        widen=not taken["no_widen"],
        validators=tuple(taken["validators"]) or None,
        planner_args=split_planner_args(taken["planner_args"]),
    )


def split_planner_args(text: str | None) -> tuple[str, ...]:
    """``--planner-args`` as an argument list (shell quoting rules, no shell)."""
    if not text:
        return ()
    try:
        return tuple(shlex.split(text))
    except ValueError as error:
        raise UsageError(f"--planner-args cannot be split: {error}") from None


def require_installed_validators(names) -> None:
    """A validator asked for by name must be able to run; found before planning, not after."""
    from relevance_plan.planning.validation import val_available

    if "val" in (names or ()) and not val_available():
        raise ValidatorUnavailableError(
            "--validator val: VAL is not installed (pip install 'relevance-plan[val]', or put Validate on PATH)"
        )


keep_work_option = file_option(
    "--keep-work",
    "keep_work",
    folder=True,
    metavar="DIR",
    help="Keep each attempt's planner files in DIR/attempt-N (Fast Downward's output.sas, sas_plan* and log; "
    "a command's plan file and log; compiled PDDL); never overwrites.",
)


def write_plan_files(result: PlanResult, plan_file: str) -> list[str]:
    """The plan in ``plan_file``; an anytime planner's plans also in ``plan_file.1``, ``.2``, ... in the
    order found, like Fast Downward's driver (the last is the plan).  Returns the numbered files."""
    from relevance_plan.cli.files import names_stdout, write_output
    from relevance_plan.pddl.plans import format_plan

    write_output(plan_file, result.plan_text())
    if names_stdout(plan_file):
        return []
    written = []
    for number, plan in enumerate(result.plans, start=1):
        written.append(write_output(Path(f"{plan_file}.{number}"), format_plan(plan, result.spelling)))
    return written


race_option = click.option(
    "--race/--no-race",
    default=None,
    help="Plan the full problem beside the pruned attempts and take the first valid plan"
    " (default: on for relevance with two or more usable cores).",
)

method_option = click.option(
    "--method", type=NamedChoice(METHODS, "method"), default=Method.RELEVANCE.value, show_default=True
)
