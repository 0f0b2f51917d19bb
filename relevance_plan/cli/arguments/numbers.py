"""The numeric options of every command, checked in one place while the command line is read.

Each numeric option is a :class:`NumberOption` (or a :class:`NumbersOption`, a comma-separated
list): text that is not a number at all is click's usage error (exit 2, as a
misspelt option is); a number that is not finite or falls outside its range
is a bad argument value (exit 30), said in one line naming the option,
before the command does anything.  ``tests/test_options.py`` checks that no
command has a numeric option of another type.
"""

from __future__ import annotations

import math

import click

from relevance_plan.exitcodes import ExitCode
from relevance_plan.limits import MAX_COUNT, MAX_DISTRACTORS, MAX_TIMEOUT
from relevance_plan.planning.options import MAX_MEMORY_MB, MIN_MEMORY_MB

# Seeds within this size either way: the generators' floor, and what a results store's INTEGER column holds.
_SEED_SIZE = 1 << 62


class OutOfRange(click.BadParameter):
    """A number the option does not take: exit 30, one line saying what it takes."""

    exit_code = int(ExitCode.USAGE)

    def format_message(self) -> str:
        names = self.param.opts if self.param is not None else []
        option = max(names, key=len) if names else "the value"
        return f"{option} {self.message}"


class NumberOption(click.ParamType):
    """An int or a float, finite, within ``[low, high]`` (``low`` excluded when ``above``; no ``high``:
    no upper bound)."""

    def __init__(self, kind: type, low: float, high: float | None, *, above: bool = False, what: str = "a number"):
        self.kind = kind
        self.low, self.high, self.above = low, high, above
        self.what = what
        self.name = "integer" if kind is int else "float"

    def describe(self) -> str:
        shown = str if self.kind is int else "{:g}".format
        lower = f"above {shown(self.low)}" if self.above else f"at least {shown(self.low)}"
        upper = "" if self.high is None else f" and at most {shown(self.high)}"
        return f"{lower}{upper} ({self.what})"

    def parse(self, value, param, ctx):
        """The number in ``value`` (click's own error, exit 2, for text that is not one)."""
        if isinstance(value, self.kind) and not isinstance(value, bool):
            return value
        return (click.INT if self.kind is int else click.FLOAT).convert(value, param, ctx)

    def check(self, number, shown, param, ctx):
        low_ok = number > self.low if self.above else number >= self.low
        finite = self.kind is int or math.isfinite(number)  # an int of any size is finite
        if not (finite and low_ok and (self.high is None or number <= self.high)):
            raise OutOfRange(f"must be {self.describe()}, got {shown}", ctx, param)
        return number

    def convert(self, value, param, ctx):
        return self.check(self.parse(value, param, ctx), value, param, ctx)


class NumbersOption(NumberOption):
    """A comma-separated list of :class:`NumberOption` values, as a tuple (duplicates dropped, order kept)."""

    def convert(self, value, param, ctx):
        if isinstance(value, tuple):
            return value
        parts = [part.strip() for part in str(value).split(",")]
        if not any(parts):
            raise OutOfRange(f"must be {self.describe()}, got '{value}'", ctx, param)
        try:
            numbers = [self.parse(part, param, ctx) for part in parts if part]
        except click.BadParameter:  # a list is read by the option itself: a bad value in it is a bad value
            raise OutOfRange(f"must be {self.describe()}, got '{value}'", ctx, param) from None
        return tuple(dict.fromkeys(self.check(number, number, param, ctx) for number in numbers))

    def describe(self) -> str:
        return "comma-separated values, each " + super().describe()


def seconds(what: str = "a number of seconds") -> NumberOption:
    """A time limit: above 0, at most ``MAX_TIMEOUT``."""
    return NumberOption(float, 0.0, MAX_TIMEOUT, above=True, what=what)


def count(low: int, high: int | None, what: str = "an integer") -> NumberOption:
    return NumberOption(int, low, high, what=what)


THRESHOLD = NumberOption(float, 0.0, 1.0, what="a threshold")
THRESHOLDS = NumbersOption(float, 0.0, 1.0, what="a threshold")
SEED = NumberOption(int, -_SEED_SIZE, None, what="an integer seed")  # hashed or given to random.Random: any size
SEEDS = NumbersOption(int, -_SEED_SIZE, _SEED_SIZE, what="an integer seed")  # each in a stored row
JOBS = count(1, None, "a number of jobs")  # threads start as jobs do: more than the jobs cost nothing
DPI = count(1, 2400, "a number of dots per inch")
SUITE_SIZE = count(1, MAX_COUNT, "a number of problems")
DISTRACTORS = count(0, MAX_DISTRACTORS, "a number of distractors")
# The generated worlds' sizes: what they make in seconds, not what would fill the memory.
OBJECTS = count(10, 1_000_000, "a number of objects")
MEGABYTES = count(MIN_MEMORY_MB, MAX_MEMORY_MB, "a number of megabytes")
