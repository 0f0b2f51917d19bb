"""What a validator says of a plan: a status enum, never a bare boolean, and the message why.

Every validator answers with a :class:`ValidationResult`.  A validator that
cannot run says so (``UNAVAILABLE``); that is never read as valid or invalid.
``none``, alone, is the user's explicit choice not to validate: the plan is
reported as NOT validated (:data:`NOT_VALIDATED`).  Several validators'
answers are combined by :func:`combine`: valid only if every one that ran
says so.
"""

from __future__ import annotations

import enum
from collections.abc import Iterable, Sequence
from dataclasses import dataclass


class ValidationStatus(enum.Enum):
    VALID = "valid"
    INVALID = "invalid"
    UNAVAILABLE = "unavailable"
    OUT_OF_TIME = "out-of-time"
    NOT_VALIDATED = "not-validated"  # --validator none: the user chose not to validate


NONE = "none"


@dataclass(frozen=True, kw_only=True)
class ValidationResult:
    status: ValidationStatus
    validator: str
    message: str = ""
    failed_step: int | None = None  # 1-based; None for a goal failure or success
    cost: float | None = None  # the plan's total-cost on the original problem, when it has one
    metric: float | None = None  # the value of the problem's :metric at the end of the plan, when it has one

    @property
    def valid(self) -> bool:
        return self.status is ValidationStatus.VALID

    @property
    def accepted(self) -> bool:
        """The plan may be reported: valid, or not validated at the user's request."""
        return self.status in (ValidationStatus.VALID, ValidationStatus.NOT_VALIDATED)


NOT_VALIDATED = ValidationResult(
    status=ValidationStatus.NOT_VALIDATED, validator=NONE, message="not validated (--validator none)"
)


def combine(names: Sequence[str], results: Iterable[ValidationResult]) -> ValidationResult:
    """Valid only if every validator that ran says so; the first invalid or out-of-time verdict stops."""
    ran: list[ValidationResult] = []
    unavailable: list[ValidationResult] = []
    for result in results:
        if result.status in (ValidationStatus.INVALID, ValidationStatus.OUT_OF_TIME):
            return result
        (ran if result.status is ValidationStatus.VALID else unavailable).append(result)
    if not ran:
        reasons = "; ".join(f"{r.validator}: {r.message}" for r in unavailable)
        return ValidationResult(status=ValidationStatus.UNAVAILABLE, validator="+".join(names), message=reasons)
    cost = next((r.cost for r in ran if r.cost is not None), None)
    metric = next((r.metric for r in ran if r.metric is not None), None)
    return ValidationResult(
        status=ValidationStatus.VALID,
        validator="+".join(r.validator for r in ran),
        message=ran[0].message,
        cost=cost,
        metric=metric,
    )
