"""The work a relaxed check may do: bindings tried against a budget and a deadline.

Every check of this package gives up past its budget rather than cost more than the planner
would; :class:`OutOfBudget` ends it, and the check's entry point turns it into "nothing is known".
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass


class OutOfBudget(Exception):
    """A relaxed check spent its budget of bindings or passed its deadline."""


@dataclass
class Work:
    """Bindings tried by one check, against its budget and its deadline (``time.monotonic()``)."""

    limit: int
    deadline: float = math.inf
    done: int = 0

    def spend(self) -> None:
        self.done += 1
        # the clock is read once every 4,096 bindings: cheap, and still within milliseconds
        if self.done > self.limit or (not self.done & 4095 and time.monotonic() > self.deadline):
            raise OutOfBudget
