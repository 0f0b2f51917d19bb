"""Plans in the IPC format: one reader and one writer, sequential and timed.

Sequential::

    (pick cup1 counter)
    ; cost = 1 (unit cost)

Timed (PDDL 2.1; LPG, POPF, OPTIC, TFD and Aries write these)::

    0.000: (drive truck1 depot market) [10.000]

Names are lower-cased when read (PDDL compares them without case, and Fast
Downward writes them lower-cased); the writer shows every name as the user's
domain and problem spell it (``Spelling``), the plan a planner found
included.  The reader is linear in the text (no backtracking pattern), refuses lines
that are neither a step nor a comment, and stops at ``max_steps``.
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Sequence
from dataclasses import dataclass

from relevance_plan.errors import PlanFormatError
from relevance_plan.pddl.formatter import format_number, format_step
from relevance_plan.pddl.model import UNSPELLED, Spelling

MAX_STEPS = 1_000_000


@dataclass(frozen=True, slots=True)
class PlanStep:
    action: str
    args: tuple[str, ...] = ()
    time: float | None = None  # start time of a timed step
    duration: float | None = None

    @property
    def ground(self) -> tuple[str, ...]:
        return (self.action, *self.args)

    def __str__(self) -> str:
        return "(" + " ".join(self.ground) + ")"


@dataclass(frozen=True, slots=True)
class Plan:
    steps: tuple[PlanStep, ...] = ()
    cost: float | None = None  # what the planner reported, if it did

    @property
    def timed(self) -> bool:
        return any(step.time is not None for step in self.steps)

    def __len__(self) -> int:
        return len(self.steps)

    def __iter__(self) -> Iterator[PlanStep]:
        return iter(self.steps)

    @property
    def makespan(self) -> float:
        return max(((s.time or 0.0) + (s.duration or 0.0) for s in self.steps), default=0.0)


def read_plan(text: str, *, max_steps: int = MAX_STEPS) -> Plan:
    """Read a plan; ``PlanFormatError`` names the first line that is neither a step nor a comment."""
    steps: list[PlanStep] = []
    cost: float | None = None
    for number, raw in enumerate(text.splitlines(), start=1):
        line = raw.strip()
        if not line:
            continue
        if line.startswith(";"):
            found = _comment_cost(line)
            if found is not None:
                cost = found
            continue
        steps.append(_read_step(line, number))
        if len(steps) > max_steps:
            raise PlanFormatError(f"more than {max_steps} plan steps", line=number)
    return Plan(tuple(steps), cost)


def _comment_cost(line: str) -> float | None:
    body = line.lstrip(";").strip().lower()
    if not body.startswith("cost"):
        return None
    rest = body[4:].lstrip()
    if not rest.startswith("="):
        return None
    token = rest[1:].split(maxsplit=1)
    return _float(token[0]) if token else None


def _float(text: str) -> float | None:
    try:
        value = float(text)
    except ValueError:
        return None
    return value if math.isfinite(value) else None


def _read_step(line: str, number: int) -> PlanStep:
    time = None
    open_at = line.find("(")
    if open_at < 0:
        raise PlanFormatError(f"not a plan step: {line[:60]!r}", line=number)
    if open_at > 0:
        prefix = line[:open_at].strip()
        if not prefix.endswith(":") or (time := _float(prefix[:-1].strip())) is None or time < 0:
            raise PlanFormatError(f"not a plan step: {line[:60]!r}", line=number)
    close_at = line.find(")", open_at)
    if close_at < 0 or "(" in line[open_at + 1 : close_at]:
        raise PlanFormatError(f"not a plan step: {line[:60]!r}", line=number)
    names = line[open_at + 1 : close_at].lower().split()
    if not names:
        raise PlanFormatError("an empty step '()'", line=number)
    rest = line[close_at + 1 :].split(";", 1)[0].strip()
    duration = None
    if rest:
        if not (rest.startswith("[") and rest.endswith("]")) or (duration := _float(rest[1:-1].strip())) is None:
            raise PlanFormatError(f"unexpected text after the step: {rest[:60]!r}", line=number)
    return PlanStep(names[0], tuple(names[1:]), time, duration)


def format_plan(plan: Plan | Sequence[PlanStep], spelling: Spelling = UNSPELLED) -> str:
    """The IPC format, names in ``spelling`` (a problem's: ``Problem.spelling``); a sequential plan ends
    with its cost line."""
    steps = plan.steps if isinstance(plan, Plan) else tuple(plan)
    lines = [format_plan_step(step, spelling) for step in steps]
    cost = plan.cost if isinstance(plan, Plan) else None
    if not any(step.time is not None for step in steps):
        lines.append(f"; cost = {len(steps)} (unit cost)" if cost is None else f"; cost = {format_number(cost)}")
    return "\n".join(lines) + "\n"


def format_plan_step(step: PlanStep, spelling: Spelling = UNSPELLED) -> str:
    """One step's IPC line: ``(action arg ...)``, a timed one with its start and duration."""
    text = format_step(step.action, step.args, spelling)
    if step.time is not None:
        text = f"{_decimals(step.time)}: {text}"
        if step.duration is not None:
            text += f" [{_decimals(step.duration)}]"
    return text


def _decimals(value: float) -> str:
    """Three decimals, as planners print them, unless that would change the value (LPG separates
    happenings by fractions of a millisecond): the plan written is the plan validated."""
    short = f"{value:.3f}"
    return short if float(short) == value else repr(float(value))
