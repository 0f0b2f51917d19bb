"""The one options object every front end builds: how one problem is planned.

``plan``, ``compare``, ``watch``, the library's ``plan()`` and the
unified-planning engine all describe a run with a :class:`PlanOptions`; the
attempt loop (``attempts``), the run (``run``) and the summary (``summary``)
read it.  Its values are checked once, here, when it is made: a bad value is
a :class:`~relevance_plan.errors.UsageError` naming the option.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field, fields
from typing import Any

from relevance_plan.errors import UsageError
from relevance_plan.limits import DEFAULT_TIMEOUT, MAX_TIMEOUT
from relevance_plan.planning.methods import METHODS, Method
from relevance_plan.planning.planners.supply import DEFAULT_PLANNER, DEFAULT_PLANNER_CONFIG, PlannerRequest
from relevance_plan.planning.validation import check_validators
from relevance_plan.relevance.selection.prune import Thresholds
from relevance_plan.relevance.setup import ScoringOptions

__all__ = ["METHODS", "MAX_MEMORY_MB", "MIN_MEMORY_MB", "PLAN_OPTION_FIELDS", "SCORING_FIELDS", "Method", "PlanOptions"]

# Below 16 MB Python cannot start the planner at all; above 1 PB is absurd.
MIN_MEMORY_MB = 16
MAX_MEMORY_MB = 1 << 30


@dataclass(frozen=True)
class PlanOptions:
    """Everything that decides how one problem is planned; every front end builds one.

    ``method`` may be given by its spelling (``"pure"``); it is held as a :class:`Method`.
    """

    method: Method = Method.RELEVANCE
    planner: str = DEFAULT_PLANNER  # a planner name as planners.registry.make_planner takes it
    planner_config: str = DEFAULT_PLANNER_CONFIG
    timeout: float | None = DEFAULT_TIMEOUT  # None: no limit (the UP engine without a timeout)
    memory_limit_mb: int | None = None
    thresholds: Thresholds = field(default_factory=Thresholds)
    widen: bool = True  # after a failed attempt, widen the selection and try again
    widen_factor: float = 0.5  # thresholds shrink by this factor at each widening
    first_share: float = 0.5  # share of the remaining time a pruned attempt may use
    scorer: str | None = None  # overrides the method's scorer
    goal_filter: bool = True  # for 'relevance': drop relevant objects no goal-directed action can use
    prefer_free: bool = True  # for 'relevance' with a model: first try without blocked alternatives
    economical: bool = True  # for 'relevance': first try, of many candidates for a role, those a relaxed plan needs
    model_path: str | None = None
    objective: str | None = None
    activity: str | None = None
    human: str | None = None
    place_kinds: bool = False
    seed: int = 0
    validators: tuple[str, ...] | None = None
    planner_args: tuple[str, ...] = ()  # appended to the planner's command line (--planner-args)
    race: bool = False  # plan the full problem beside the pruned attempts (planning.race); takes a second core

    def __post_init__(self) -> None:
        object.__setattr__(self, "method", _method(self.method))
        if self.timeout is not None and not 0 < self.timeout < float("inf"):
            raise UsageError(f"--timeout must be a positive number of seconds, got {self.timeout}")
        if self.timeout is not None and self.timeout > MAX_TIMEOUT:
            raise UsageError(f"--timeout must be at most {MAX_TIMEOUT:g} s (about 11 days), got {self.timeout}")
        if self.memory_limit_mb is not None and self.memory_limit_mb < MIN_MEMORY_MB:
            raise UsageError(f"--memory-limit must be at least {MIN_MEMORY_MB} MB, got {self.memory_limit_mb}")
        if self.memory_limit_mb is not None and self.memory_limit_mb > MAX_MEMORY_MB:
            raise UsageError(f"--memory-limit must be at most {MAX_MEMORY_MB} MB (1 PB), got {self.memory_limit_mb}")
        if not 0.0 < self.widen_factor < 1.0:
            raise UsageError(f"widen factor must be in (0, 1), got {self.widen_factor}")
        if not 0.0 < self.first_share <= 1.0:
            raise UsageError(f"first share must be in (0, 1], got {self.first_share}")
        if self.validators:
            check_validators(self.validators)

    @property
    def scoring(self) -> ScoringOptions:
        """The scoring part of these options (the fields share their names)."""
        return ScoringOptions(**{name: getattr(self, name) for name in SCORING_FIELDS})

    @classmethod
    def from_scoring(cls, scoring: ScoringOptions, **planning: Any) -> PlanOptions:
        return cls(**{name: getattr(scoring, name) for name in SCORING_FIELDS}, **planning)

    def planner_request(self, keep_work: str | os.PathLike[str] | None = None) -> PlannerRequest:
        """What these options ask of the run's planner (``planners.supply``), with ``--keep-work``."""
        return PlannerRequest(self.planner, self.planner_config, self.planner_args, self.memory_limit_mb, keep_work)

    @property
    def narrows_first(self) -> bool:
        """Whether the first selection is narrowed (goal filter, blocked alternatives set aside)."""
        return self.method.narrows_first


def _method(value: object) -> Method:
    """``value`` as a :class:`Method`; a spelling no method has is the user's mistake."""
    try:
        return Method(value)
    except ValueError:
        raise UsageError(f"unknown method '{value}' (choose from: {', '.join(METHODS)})") from None


PLAN_OPTION_FIELDS = tuple(f.name for f in fields(PlanOptions))
SCORING_FIELDS = tuple(f.name for f in fields(ScoringOptions))
assert set(SCORING_FIELDS) <= set(PLAN_OPTION_FIELDS), "PlanOptions must carry every scoring option"
