"""The validators by name, and a plan checked on the ORIGINAL problem by those asked for.

``VALIDATORS`` is the registry the CLI's ``--validator`` choices come from:
- ``builtin``: the simulator (``builtin``), milliseconds on any problem: the default;
- ``up``: unified-planning's validators (``up``);
- ``val``: VAL's ``Validate`` (``val``; ``val_program`` finds and runs it).
:func:`validate_plan` runs each one asked for; the plan is valid only if every
one that ran says so (``verdicts.combine``).  Input our reader refuses (PDDL+,
object fluents) is planned unpruned; only the validators that read the files
themselves can check its plans (:func:`validate_unread`).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import replace

from relevance_plan.errors import UsageError
from relevance_plan.pddl.model import Domain, Problem
from relevance_plan.pddl.plans import Plan
from relevance_plan.planning.validation.builtin import validate_builtin
from relevance_plan.planning.validation.up import validate_files_with_up, validate_with_up
from relevance_plan.planning.validation.val import validate_files_with_val, validate_with_val
from relevance_plan.planning.validation.verdicts import NONE, NOT_VALIDATED, ValidationResult, ValidationStatus, combine

# A validator judges a plan on the original problem, by a deadline (time.monotonic(); None: none).
Validator = Callable[[Domain, Problem, Plan, "float | None"], ValidationResult]

VALIDATORS: dict[str, Validator] = {
    "builtin": validate_builtin,
    "up": validate_with_up,
    "val": validate_with_val,
}
# Every --validator choice: the validators, and ``none`` (no validation, explicitly).
VALIDATOR_CHOICES = (*VALIDATORS, NONE)


def check_validators(names: Sequence[str]) -> None:
    """Refuse an unknown name, and ``none`` together with a validator."""
    unknown = [name for name in names if name not in VALIDATOR_CHOICES]
    if unknown:
        raise UsageError(f"unknown validator '{unknown[0]}' (choose from: {', '.join(VALIDATOR_CHOICES)})")
    if NONE in names and len(set(names)) > 1:
        raise UsageError("--validator none means no validation; it cannot be combined with a validator")


def default_validators() -> tuple[str, ...]:
    """The builtin simulator: milliseconds on any problem, so it checks every plan; VAL and
    unified-planning's validators join when asked for (``--validator builtin,val``), since each
    costs a process or a second reading of the problem on every plan."""
    return ("builtin",)


def validate_plan(
    domain: Domain,
    problem: Problem,
    plan: Plan,
    validators: Sequence[str] | None = None,
    deadline: float | None = None,
) -> ValidationResult:
    """Run each validator; the plan is valid only if every one that ran says so.

    If none could run, the result is UNAVAILABLE (the caller must say so loudly);
    past ``deadline`` (``time.monotonic()`` seconds) it is OUT_OF_TIME.
    """
    return _each_validator(validators, lambda name: VALIDATORS[name](domain, problem, plan, deadline))


def validate_unread(
    domain_path: str,
    problem_path: str,
    plan: Plan,
    refused: str,
    validators: Sequence[str] | None = None,
    deadline: float | None = None,
) -> ValidationResult:
    """Validate a plan of input our reader refuses (``refused`` says why): only the validators that
    read the files themselves can run; the builtin simulator cannot."""

    def run(name: str) -> ValidationResult:
        if name == "up":
            return validate_files_with_up(domain_path, problem_path, plan)
        if name == "val":
            # without the problem read, VAL's final value cannot be told from the plan's length
            return replace(validate_files_with_val(domain_path, problem_path, plan, deadline), metric=None)
        return ValidationResult(
            status=ValidationStatus.UNAVAILABLE, validator=name, message=f"our reader refuses the input ({refused})"
        )

    return _each_validator(validators, run)


def _each_validator(validators: Sequence[str] | None, run: Callable[[str], ValidationResult]) -> ValidationResult:
    """``run`` for each validator asked for (default: :func:`default_validators`), combined; not
    validated at all with ``none``."""
    names = tuple(validators) if validators else default_validators()
    if NONE in names:
        return NOT_VALIDATED
    return combine(names, (run(name) for name in names))
