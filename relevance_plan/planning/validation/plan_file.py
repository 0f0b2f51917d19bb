"""A plan file judged on its own, by one validator: the ``validate`` command's answer.

Files are read as the attempt loop reads them; the CLI command only shows the
:class:`PlanCheck` and sets the exit code.
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from typing import Any

from relevance_plan.errors import UsageError
from relevance_plan.pddl.model import Problem
from relevance_plan.planning.validation.registry import VALIDATORS, validate_unread
from relevance_plan.planning.validation.verdicts import ValidationResult, ValidationStatus


@dataclass(frozen=True)
class PlanCheck:
    """One plan file judged on its problem by one validator (the ``validate`` command's answer)."""

    result: ValidationResult
    steps: int
    timed: bool
    metric: float | None  # the problem's metric, or without one its total-cost, at the end of a valid plan

    def to_json(self) -> dict[str, Any]:
        result = self.result
        return {
            "valid": result.valid,
            "validator": result.validator,
            "steps": self.steps,
            "metric": self.metric,
            "failed_step": result.failed_step,
            "reason": result.message,
        }


def check_plan_file(
    domain_path: str, problem_path: str, plan_path: str, validator: str = "builtin", timeout: float | None = None
) -> PlanCheck:
    """Judge the plan in ``plan_path`` with ``validator`` (``builtin``, ``val`` or ``up``) within ``timeout``
    seconds of the judging (None: VAL's 60 s, no limit for the others).

    Files are read as the attempt loop reads them; an unreadable file, malformed PDDL or a
    malformed plan raise the library's errors (the plan's naming the file and line).  Input our
    reader refuses (an unsupported feature) can still be judged by ``val`` or ``up``, which read
    the files themselves; ``ValidatorUnavailableError`` when the validator cannot run.
    """
    from relevance_plan.errors import PlanFormatError, UnsupportedFeatureError, ValidatorUnavailableError
    from relevance_plan.io import load_task, read_text
    from relevance_plan.pddl.plans import read_plan

    if validator not in VALIDATORS:
        raise UsageError(f"unknown validator '{validator}' (choose from: {', '.join(VALIDATORS)})")
    text = read_text(plan_path, "plan file")
    try:
        plan = read_plan(text)
    except PlanFormatError as error:
        raise PlanFormatError(error.message, path=plan_path, line=error.line) from None
    problem: Problem | None = None
    try:
        domain, problem = load_task(domain_path, problem_path)
    except UnsupportedFeatureError as error:
        if validator == "builtin":
            raise
        deadline = None if timeout is None else time.monotonic() + timeout
        result = validate_unread(domain_path, problem_path, plan, error.message, (validator,), deadline)
    else:
        result = VALIDATORS[validator](domain, problem, plan, None if timeout is None else time.monotonic() + timeout)
    if result.status is ValidationStatus.UNAVAILABLE:
        raise ValidatorUnavailableError(f"validator {validator} cannot judge this plan: {result.message}")
    if result.status is ValidationStatus.OUT_OF_TIME:
        raise ValidatorUnavailableError(f"validator {validator} ran out of time: {result.message}")
    metric = None
    if result.valid and problem is not None:
        metric = result.metric if problem.metric is not None else result.cost
    return PlanCheck(result, len(plan), plan.timed, metric)
