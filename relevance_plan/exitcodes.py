"""Exit codes of the ``relevance-plan`` command, grouped by tens: the tool's one exit table.

Modelled on Fast Downward's ``driver/returncodes.py``: 0-9 success,
10-19 no plan, 20-29 resource limits, 30-39 bad input, 40-49 tool errors.
Both ways of ending are mapped here: a library error (:func:`exit_code_for_error`)
and a ``plan`` verdict (:func:`exit_code_for_status`).  The CLI
(``relevance_plan.cli``) is the only part of the package that calls ``sys.exit``.
A planner's own exit codes are its adapter's business and never appear here.
"""

from __future__ import annotations

from enum import IntEnum

from relevance_plan import errors


class ExitCode(IntEnum):
    SUCCESS = 0
    # 2 is click's own code for a malformed command line (unknown option, missing argument).
    COMMAND_LINE = 2
    UNSOLVABLE = 10
    NO_VALID_PLAN = 11
    INSUFFICIENT_CUES = 12
    PLAN_INVALID = 13
    OUT_OF_TIME = 20
    OUT_OF_MEMORY = 21
    USAGE = 30
    INPUT_FILE = 31
    PDDL_SYNTAX = 32
    UNSUPPORTED_PDDL = 33
    DOMAIN_MISMATCH = 34
    MODEL = 35
    STORE = 36
    SCHEDULER = 37
    PLANNER = 40
    VALIDATOR = 41
    INTERRUPTED = 130


EXIT_CODE_DESCRIPTIONS: dict[ExitCode, str] = {
    ExitCode.SUCCESS: "success: a plan was found and validated on the original problem (or the command finished)",
    ExitCode.COMMAND_LINE: "malformed command line (unknown option, missing argument, text where a number goes)",
    ExitCode.UNSOLVABLE: "the original problem is unsolvable",
    ExitCode.NO_VALID_PLAN: (
        "no valid plan: search ended without one (incomplete search, invalid plans, or --no-widen failure)"
    ),
    ExitCode.INSUFFICIENT_CUES: (
        "insufficient cues: relevance cannot be decided; give --activity, --objective or --human"
    ),
    ExitCode.PLAN_INVALID: "the plan is invalid on the problem (validate)",
    ExitCode.OUT_OF_TIME: "out of time",
    ExitCode.OUT_OF_MEMORY: "out of memory (the tool's, or a planner that died under --memory-limit)",
    ExitCode.USAGE: (
        "bad argument value (threshold outside [0, 1], a number not finite or out of its range, a name an option"
        " does not know: method, scorer, validator, ...) or an optional extra that is not installed"
    ),
    ExitCode.INPUT_FILE: "missing, unreadable or unwritable file or directory, whichever option names it",
    ExitCode.PDDL_SYNTAX: "malformed PDDL, or a malformed plan file",
    ExitCode.UNSUPPORTED_PDDL: "PDDL feature not supported (by the tool, or by the planner or its reader)",
    ExitCode.DOMAIN_MISMATCH: "problem does not belong to the domain",
    ExitCode.MODEL: (
        "invalid knowledge model (YAML, schema, probability; its file and line), or a human, objective or activity name"
        " it lacks"
    ),
    ExitCode.STORE: "results store unusable or from an incompatible version",
    ExitCode.SCHEDULER: "Dask scheduler unreachable or Dask not installed",
    ExitCode.PLANNER: "planner not found, failed to start, or crashed",
    ExitCode.VALIDATOR: "no plan validator could run (or judge the plan within --timeout)",
    ExitCode.INTERRUPTED: "interrupted (Ctrl-C); finished results are kept",
}

_ERROR_CODES: tuple[tuple[type[errors.RelevancePlanError], ExitCode], ...] = (
    (errors.UsageError, ExitCode.USAGE),
    (errors.OutOfTimeError, ExitCode.OUT_OF_TIME),
    (errors.InputFileError, ExitCode.INPUT_FILE),
    (errors.PDDLParseError, ExitCode.PDDL_SYNTAX),
    (errors.PlanFormatError, ExitCode.PDDL_SYNTAX),
    (errors.UnsupportedFeatureError, ExitCode.UNSUPPORTED_PDDL),
    (errors.DomainMismatchError, ExitCode.DOMAIN_MISMATCH),
    (errors.ModelError, ExitCode.MODEL),
    (errors.StoreError, ExitCode.STORE),
    (errors.SchedulerError, ExitCode.SCHEDULER),
    (errors.PlannerError, ExitCode.PLANNER),
    (errors.ValidatorUnavailableError, ExitCode.VALIDATOR),
)


def exit_code_for_error(error: errors.RelevancePlanError) -> ExitCode:
    for error_type, code in _ERROR_CODES:
        if isinstance(error, error_type):
            return code
    return ExitCode.USAGE


# A ``plan`` verdict (a ``planning.results.PlanStatus`` value; this module sits below
# the planning layer, so the table is keyed by the one spelling of each status).
PLAN_STATUS_EXIT: dict[str, ExitCode] = {
    "solved": ExitCode.SUCCESS,
    "unsolvable": ExitCode.UNSOLVABLE,
    "no-valid-plan": ExitCode.NO_VALID_PLAN,
    "out-of-time": ExitCode.OUT_OF_TIME,
    "out-of-memory": ExitCode.OUT_OF_MEMORY,
    "insufficient-cues": ExitCode.INSUFFICIENT_CUES,
    "input-error": ExitCode.PDDL_SYNTAX,
    "unsupported": ExitCode.UNSUPPORTED_PDDL,
    "planner-config-error": ExitCode.USAGE,
    "planner-error": ExitCode.PLANNER,
    "validator-unavailable": ExitCode.VALIDATOR,
}


def exit_code_for_status(status: str) -> ExitCode:
    """The exit code of a ``plan`` verdict, given as its status value."""
    return PLAN_STATUS_EXIT[status]
