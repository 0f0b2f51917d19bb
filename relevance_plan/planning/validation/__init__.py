"""Plan validation against the ORIGINAL problem: every validator in one place.

The validators are engines behind one signature (as unified-planning keeps its
``PlanValidator`` engines), registered by name:

- ``verdicts``: what a validator says (``ValidationResult`` with a
  ``ValidationStatus``; ``none``'s NOT VALIDATED), and several verdicts combined;
- ``builtin``: the builtin simulator's entry point (``simulate``; its core,
  the semantics of formulas and happenings, is ``pddl/simulator.py``);
- ``up``: unified-planning's validators, reading the original files;
- ``val``: VAL's adapter (its report read), ``val_program``: finding and
  running VAL's ``Validate`` under the guard;
- ``registry``: ``VALIDATORS`` (the ``--validator`` choices) and
  ``validate_plan``, which runs those asked for;
- ``plan_file``: a plan file judged on its own (the ``validate`` command).

The names below are the ones the rest of the package uses.
"""

from relevance_plan.planning.validation.builtin import simulate, validate_builtin
from relevance_plan.planning.validation.plan_file import PlanCheck, check_plan_file
from relevance_plan.planning.validation.registry import (
    VALIDATOR_CHOICES,
    VALIDATORS,
    Validator,
    check_validators,
    default_validators,
    validate_plan,
    validate_unread,
)
from relevance_plan.planning.validation.up import up_validator, validate_files_with_up, validate_with_up
from relevance_plan.planning.validation.val import (
    read_val_report,
    val_available,
    validate_files_with_val,
    validate_with_val,
)
from relevance_plan.planning.validation.verdicts import NONE, ValidationResult, ValidationStatus

__all__ = [
    "NONE",
    "VALIDATORS",
    "VALIDATOR_CHOICES",
    "PlanCheck",
    "ValidationResult",
    "ValidationStatus",
    "Validator",
    "check_plan_file",
    "check_validators",
    "default_validators",
    "read_val_report",
    "simulate",
    "up_validator",
    "val_available",
    "validate_builtin",
    "validate_files_with_up",
    "validate_files_with_val",
    "validate_plan",
    "validate_unread",
    "validate_with_up",
    "validate_with_val",
]
