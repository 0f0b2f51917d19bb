"""Prune, plan, validate on the original problem, and widen until solved.

Methods: ``pure`` (the planner on the original problem), ``relevance``
(knowledge-model scorer when a model applies, else the goal scorer),
``random`` (the paper's baseline) and ``oracle`` (the generator's necessary
set).  Every plan is checked against the ORIGINAL problem before it is
reported.  When a pruned problem turns out unsolvable, gives an invalid plan
or uses up its share of the time, the thresholds are lowered geometrically
and the best-scored removed objects are added back, closure is applied again,
and the planner retries; the last attempt is the full problem, so every
solvable problem is solved given time (PLOI's incremental loop).
"""

from __future__ import annotations

import enum
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable, Sequence

from relevance_plan.errors import InputFileError, UsageError
from relevance_plan.io import load_domain, load_problem, read_text, scratch_directory, write_text_atomic
from relevance_plan.relevance.knowledge import KnowledgeModel, check_model_applies, find_model, load_model
from relevance_plan.relevance.prune import PruneResult, Thresholds, prune_with_scores, score_task, widen
from relevance_plan.planning.runner import PlannerStatus, RunOutcome, check_planner_names, run_fast_downward
from relevance_plan.relevance.scorers import ScoreRequest, Task
from relevance_plan.planning.validate import ValidationResult, ValidationStatus, validate_plan

METHODS = ("relevance", "pure", "random", "oracle")
# Limits beyond these are typos: the watchdog's timer cannot even hold much more.
MAX_TIMEOUT = 1e6
# Below 16 MB Python cannot start the planner at all; above 1 PB is absurd.
MIN_MEMORY_MB = 16
MAX_MEMORY_MB = 1 << 30


class PlanStatus(enum.Enum):
    SOLVED = "solved"
    UNSOLVABLE = "unsolvable"
    NO_VALID_PLAN = "no-valid-plan"
    OUT_OF_TIME = "out-of-time"
    OUT_OF_MEMORY = "out-of-memory"
    INSUFFICIENT_CUES = "insufficient-cues"
    INPUT_ERROR = "input-error"
    PLANNER_CONFIG_ERROR = "planner-config-error"
    PLANNER_ERROR = "planner-error"
    VALIDATOR_UNAVAILABLE = "validator-unavailable"


@dataclass(frozen=True)
class PlanOptions:
    method: str = "relevance"
    planner_config: str = "lama-first"
    timeout: float = 120.0
    memory_limit_mb: int | None = None
    thresholds: Thresholds = field(default_factory=Thresholds)
    relax: bool = True
    relax_factor: float = 0.5  # thresholds shrink by this factor at each widening
    first_share: float = 0.5  # share of the remaining time a pruned attempt may use
    scorer: str | None = None  # overrides the method's scorer
    goal_filter: bool = True  # for 'relevance': drop relevant objects no goal-directed action can use
    prefer_free: bool = True  # for 'relevance' with a model: first try without blocked alternatives
    model_path: str | None = None
    objective: str | None = None
    task: str | None = None
    human: str | None = None
    seed: int = 0
    validators: tuple | None = None

    def __post_init__(self):
        if self.method not in METHODS:
            raise UsageError(f"unknown method '{self.method}' (choose from: {', '.join(METHODS)})")
        if not self.timeout > 0:
            raise UsageError(f"--timeout must be positive, got {self.timeout}")
        if not self.timeout <= MAX_TIMEOUT:
            raise UsageError(f"--timeout must be at most {MAX_TIMEOUT:g} s (about 11 days), got {self.timeout}")
        if self.memory_limit_mb is not None and self.memory_limit_mb < MIN_MEMORY_MB:
            raise UsageError(f"--memory-limit must be at least {MIN_MEMORY_MB} MB, got {self.memory_limit_mb}")
        if self.memory_limit_mb is not None and self.memory_limit_mb > MAX_MEMORY_MB:
            raise UsageError(f"--memory-limit must be at most {MAX_MEMORY_MB} MB (1 PB), got {self.memory_limit_mb}")
        if not 0.0 < self.relax_factor < 1.0:
            raise UsageError(f"relax factor must be in (0, 1), got {self.relax_factor}")


@dataclass(frozen=True)
class Attempt:
    number: int
    objects_kept: int
    thresholds: Thresholds | None  # None for the full problem
    added_back: int  # removed objects put back by rank at this widening
    outcome: RunOutcome
    validation: ValidationResult | None
    time_limit: float
    validation_time: float = 0.0

    @property
    def status(self) -> str:
        if self.outcome.status is PlannerStatus.SOLVED and self.validation is not None:
            return "solved" if self.validation.valid else f"plan-{self.validation.status.value}"
        return self.outcome.status.value


@dataclass(frozen=True)
class PlanResult:
    method: str
    status: PlanStatus
    plan: tuple = ()
    plan_cost: int | None = None
    validation: ValidationResult | None = None
    attempts: tuple = ()
    wall_time: float = 0.0
    relevance_time: float = 0.0
    planner_time: float = 0.0
    validation_time: float = 0.0
    objects_total: int = 0
    objects_kept: int = 0
    prune: PruneResult | None = None
    message: str = ""
    peak_memory_mb: float = 0.0

    @property
    def valid(self) -> bool:
        return self.validation is not None and self.validation.valid

    @property
    def first_attempt_status(self) -> str:
        if self.attempts:
            return self.attempts[0].status
        return self.status.value

    def to_json(self) -> dict:
        return {
            "method": self.method,
            "status": self.status.value,
            "valid": self.valid,
            "validator": self.validation.validator if self.validation else None,
            "plan_length": len(self.plan) if self.status is PlanStatus.SOLVED else None,
            "plan_cost": self.plan_cost,
            "wall_time": round(self.wall_time, 4),
            "relevance_time": round(self.relevance_time, 4),
            "planner_time": round(self.planner_time, 4),
            "validation_time": round(self.validation_time, 4),
            "objects_total": self.objects_total,
            "objects_kept": self.objects_kept,
            "attempts": len(self.attempts),
            "first_attempt_status": self.first_attempt_status,
            "attempt_log": [
                {
                    "attempt": a.number,
                    "objects_kept": a.objects_kept,
                    "tau_class": a.thresholds.tau_class if a.thresholds else None,
                    "tau_element": a.thresholds.tau_element if a.thresholds else None,
                    "added_back": a.added_back,
                    "time_limit": round(a.time_limit, 3),
                    "planner_status": a.outcome.status.value,
                    "planner_exit_code": a.outcome.exit_code,
                    "status": a.status,
                    "wall_time": round(a.outcome.wall_time, 4),
                }
                for a in self.attempts
            ],
            "peak_memory_mb": round(self.peak_memory_mb, 1),
            "message": self.message,
            "plan": [" ".join(step) for step in self.plan] if self.status is PlanStatus.SOLVED else [],
        }


_PLANNER_TO_PLAN_STATUS = {
    PlannerStatus.UNSOLVABLE: PlanStatus.UNSOLVABLE,
    PlannerStatus.SEARCH_INCOMPLETE: PlanStatus.NO_VALID_PLAN,
    PlannerStatus.OUT_OF_TIME: PlanStatus.OUT_OF_TIME,
    PlannerStatus.OUT_OF_MEMORY: PlanStatus.OUT_OF_MEMORY,
    PlannerStatus.INPUT_ERROR: PlanStatus.INPUT_ERROR,
    PlannerStatus.UNSUPPORTED: PlanStatus.INPUT_ERROR,
    PlannerStatus.PLANNER_CRASH: PlanStatus.PLANNER_ERROR,
}


def scorer_for(method: str, model: KnowledgeModel | None, override: str | None) -> str:
    if override:
        return override
    if method == "relevance":
        return "model" if model is not None else "goal"
    return method


def resolve_model(domain_name: str, domain_path: str | None, model_path: str | None) -> KnowledgeModel | None:
    """The explicit ``--model``, else one found next to the domain or under domains/<name>/."""
    if model_path is not None:
        model = load_model(model_path)
        check_model_applies(model, domain_name)
        return model
    found = find_model(domain_name, domain_path)
    if found is None:
        return None
    model = load_model(found)
    return model if model.domain == domain_name else None


def read_sidecar_necessary(problem_path: str) -> frozenset | None:
    """The sidecar's ``necessary`` set, None without a sidecar (``InputFileError`` if it is bad)."""
    from relevance_plan.relevance.sidecar import read_sidecar_fields

    sidecar = Path(problem_path).with_suffix(".json")
    if not sidecar.exists():
        return None
    necessary = read_sidecar_fields(sidecar).necessary
    if necessary is None:
        raise InputFileError("sidecar has no 'necessary' list", path=str(sidecar))
    return necessary


ProgressCallback = Callable[[str], None]


def plan_task(
    domain_path: str | Path,
    problem_path: str | Path,
    options: PlanOptions = PlanOptions(),
    progress: ProgressCallback | None = None,
) -> PlanResult:
    """Run one method on one problem; the plan returned is always validated on the original."""
    say = progress or (lambda message: None)
    started = time.perf_counter()
    domain_path, problem_path = str(domain_path), str(problem_path)
    domain = load_domain(domain_path)
    problem = load_problem(problem_path, domain)
    task = Task(domain, problem)
    check_planner_names(domain, problem)
    total = len(problem.objects)
    deadline = started + options.timeout
    overran = _overran("reading the domain and problem", started, options, total)
    if overran is not None:
        return overran

    if options.method == "pure":
        say("planning on the full problem")
        attempt = _attempt(1, task, domain_path, problem_path, options, deadline, None, 0, total, final=True)
        return _finish(task, options, [attempt], started, 0.0, None)

    model = resolve_model(domain.name, domain_path, options.model_path)
    scorer = scorer_for(options.method, model, options.scorer)
    request = ScoreRequest(
        model=model,
        objective=options.objective,
        task=options.task,
        human=options.human,
        seed=options.seed,
        necessary=read_sidecar_necessary(problem_path) if scorer == "oracle" else None,
    )
    say(f"scoring {total} objects with the {scorer} scorer")
    scores = score_task(task, scorer, request)
    overran = _overran("scoring", started, options, total)
    if overran is not None:
        return overran
    if not scores.sufficient:
        elapsed = time.perf_counter() - started
        return PlanResult(
            method=options.method,
            status=PlanStatus.INSUFFICIENT_CUES,
            wall_time=elapsed,
            relevance_time=elapsed,
            objects_total=total,
            message=scores.insufficiency,
        )
    goal_filter = options.goal_filter and options.method == "relevance"
    # Setting blocked alternatives aside is a bet on the first attempt only: widening
    # (which never sets aside) brings them back if the bet was wrong.
    prefer_free = options.prefer_free and options.method == "relevance"
    pruned = prune_with_scores(task, scores, options.thresholds, model, goal_filter=goal_filter,
                               prefer_free=prefer_free)
    relevance_time = time.perf_counter() - started
    overran = _overran("pruning and closure", started, options, total)
    if overran is not None:
        return overran
    say(f"kept {len(pruned.kept)} of {total} objects ({len(pruned.restored)} restored by closure"
        + (f", {len(pruned.set_aside)} blocked alternatives set aside)" if pruned.set_aside else ")"))

    attempts: list[Attempt] = []
    thresholds = options.thresholds
    extra: frozenset = frozenset()
    current = pruned
    with scratch_directory() as scratch:
        while time.perf_counter() < deadline:
            number = len(attempts) + 1
            full = len(current.kept) >= total
            if full:
                say(f"attempt {number}: the full problem")
                target = problem_path
            else:
                say(f"attempt {number}: {len(current.kept)} of {total} objects")
                target = str(write_text_atomic(Path(scratch) / f"pruned-{number}.pddl", current.text))
            attempt = _attempt(
                number, task, domain_path, target, options, deadline,
                None if full else thresholds, len(extra), len(current.kept), final=full or not options.relax,
            )
            attempts.append(attempt)
            if attempt.validation is not None and attempt.validation.status is not ValidationStatus.INVALID:
                break  # valid, or no validator could run: report it, never retry blindly
            if not options.relax or full or attempt.outcome.status in _PLANNER_FAULTS:
                break
            # Widen: lower the thresholds and put back the best-ranked removed objects.
            widen_started = time.perf_counter()
            current, extra = widen(current, options.relax_factor, extra, model, goal_filter)
            thresholds = current.thresholds
            relevance_time += time.perf_counter() - widen_started
    return _finish(task, options, attempts, started, relevance_time, pruned)


def _overran(step: str, started: float, options: PlanOptions, total: int) -> PlanResult | None:
    """An out-of-time result naming ``step`` when ``--timeout`` ran out during it."""
    elapsed = time.perf_counter() - started
    if elapsed < options.timeout:
        return None
    return PlanResult(
        method=options.method,
        status=PlanStatus.OUT_OF_TIME,
        wall_time=elapsed,
        relevance_time=elapsed,
        objects_total=total,
        message=f"out of time while {step}: {elapsed:.1f} s of the {options.timeout:g} s --timeout",
    )


# Driver exit codes that reject the planner configuration, not the task:
# argparse usage error, search input error, unknown alias (driver input error).
_CONFIG_ERROR_CODES = (2, 33, 36)

_PLANNER_FAULTS = (PlannerStatus.INPUT_ERROR, PlannerStatus.UNSUPPORTED, PlannerStatus.PLANNER_CRASH)


def _attempt(number, task, domain_path, problem_path, options, deadline, thresholds, added_back, kept, final) -> Attempt:
    """One planner run on ``problem_path``; a found plan is validated on the original problem."""
    remaining = max(deadline - time.perf_counter(), 0.5)
    limit = remaining if final else max(1.0, remaining * options.first_share)
    outcome = run_fast_downward(
        domain_path,
        problem_path,
        config=options.planner_config,
        time_limit=limit,
        memory_limit_mb=options.memory_limit_mb,
    )
    validation = None
    validation_time = 0.0
    if outcome.status is PlannerStatus.SOLVED:
        validation_started = time.perf_counter()
        steps = tuple(tuple(step.lower().split()) for step in outcome.plan)
        validation = validate_plan(task.domain, task.problem, steps, options.validators)
        validation_time = time.perf_counter() - validation_started
    return Attempt(number, kept, thresholds, added_back, outcome, validation, limit, validation_time)


def _finish(task: Task, options: PlanOptions, attempts: Sequence[Attempt], started: float, relevance_time: float, pruned) -> PlanResult:
    planner_time = sum(a.outcome.wall_time for a in attempts)
    total = len(task.problem.objects)
    common = dict(
        method=options.method,
        attempts=tuple(attempts),
        wall_time=time.perf_counter() - started,
        relevance_time=relevance_time,
        planner_time=planner_time,
        validation_time=sum(a.validation_time for a in attempts),
        objects_total=total,
        prune=pruned,
        peak_memory_mb=max((a.outcome.peak_memory_mb for a in attempts), default=0.0),
    )
    if attempts and attempts[-1].outcome.status is PlannerStatus.SOLVED:
        last = attempts[-1]
        validation = last.validation
        if validation is not None and validation.valid:
            plan = tuple(tuple(step.lower().split()) for step in last.outcome.plan)
            return PlanResult(
                status=PlanStatus.SOLVED,
                plan=plan,
                plan_cost=last.outcome.plan_cost,
                validation=validation,
                objects_kept=last.objects_kept,
                message=f"plan of {len(plan)} steps validated on the original problem ({validation.validator})",
                **common,
            )
        if validation is not None and validation.status is ValidationStatus.UNAVAILABLE:
            return PlanResult(
                status=PlanStatus.VALIDATOR_UNAVAILABLE,
                validation=validation,
                objects_kept=last.objects_kept,
                message=f"a plan was found but NO VALIDATOR COULD RUN: {validation.message}",
                **common,
            )
        return PlanResult(
            status=PlanStatus.NO_VALID_PLAN,
            validation=validation,
            objects_kept=last.objects_kept,
            message=f"the plan failed validation on the original problem: {validation.message if validation else ''}",
            **common,
        )
    if not attempts:
        return PlanResult(status=PlanStatus.OUT_OF_TIME, message="no time left for planning", **common)
    last = attempts[-1]
    full = last.objects_kept >= total
    status = _PLANNER_TO_PLAN_STATUS.get(last.outcome.status, PlanStatus.PLANNER_ERROR)
    if status is PlanStatus.INPUT_ERROR and last.outcome.exit_code in _CONFIG_ERROR_CODES:
        status = PlanStatus.PLANNER_CONFIG_ERROR
    if status is PlanStatus.PLANNER_CONFIG_ERROR:
        message = (f"Fast Downward rejected --planner-config '{options.planner_config}'"
                   f" (unknown alias or bad search string; exit code {last.outcome.exit_code})")
    elif status is PlanStatus.UNSOLVABLE and not full:
        # Only the full problem's unsolvability says anything about the user's problem.
        status = PlanStatus.NO_VALID_PLAN
        message = "the pruned problem is unsolvable (pruning removed something needed; relaxation is off)"
    elif status is PlanStatus.UNSOLVABLE:
        message = "the problem is unsolvable"
    else:
        message = f"planner: {last.outcome.status.value} (exit code {last.outcome.exit_code})"
    return PlanResult(status=status, objects_kept=last.objects_kept, message=message, **common)
