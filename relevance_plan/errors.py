"""One exception hierarchy for the whole package.

Library code raises these; only the CLI (``relevance_plan.cli``) turns them into exit codes.
Each error carries the offending file and, where known, the line, so the
CLI can print one precise line.
"""

from __future__ import annotations


class RelevancePlanError(Exception):
    """Root of every error this package raises on purpose."""

    def __init__(self, message: str, *, path: str | None = None, line: int | None = None):
        super().__init__(message)
        self.message = message
        self.path = str(path) if path is not None else None
        self.line = line

    def __reduce__(self):
        # Errors cross process boundaries (Dask workers); keep the path and line.
        return (_rebuild_error, (type(self), self.message, self.path, self.line))

    def __str__(self) -> str:
        where = ""
        if self.path:
            where = printable(self.path, MAX_PATH) + (f":{self.line}" if self.line else "") + ": "
        return where + printable(self.message, MAX_MESSAGE)


# A message quotes names from the user's files; a 1 MB name must not become a 1 MB line.
MAX_MESSAGE = 400
MAX_PATH = 1000


def printable(text: str, limit: int | None = None) -> str:
    """``text`` on one visible line: control and invisible characters (NUL,
    newline, a byte-order mark, ...) as escapes, cut to ``limit`` characters."""
    if not text.isprintable():
        text = "".join(c if c.isprintable() else ascii(c)[1:-1] for c in text)
    if limit is not None and len(text) > limit:
        text = text[: limit - 1] + "…"
    return text


def counted(count: int, noun: str, plural: str | None = None) -> str:
    """``1 step``, ``2 steps``: a count with its noun in the right number (``plural`` when not noun + s)."""
    return f"{count} {noun if count == 1 else plural or noun + 's'}"


def _rebuild_error(cls, message, path, line):
    return cls(message, path=path, line=line)


class UsageError(RelevancePlanError):
    """A bad argument value: threshold outside [0, 1], negative count, unknown name."""


class MissingExtraError(UsageError):
    """An optional extra that is not installed; the message says what to install."""


class InputFileError(RelevancePlanError):
    """A file or directory that is missing, unreadable or unwritable."""


class PDDLParseError(RelevancePlanError):
    """Malformed PDDL text."""


class UnsupportedFeatureError(RelevancePlanError):
    """Legal PDDL that this tool does not handle (durative actions, fluents, ...)."""


class DomainMismatchError(RelevancePlanError):
    """A problem that does not belong to the given domain."""


class ModelError(RelevancePlanError):
    """An invalid knowledge-model file (bad YAML, probability outside [0, 1], ...)."""


class PlanFormatError(RelevancePlanError):
    """A plan file that is not in the IPC format (a planner wrote something else)."""


class OutOfTimeError(RelevancePlanError):
    """A step (reading, scoring, writing) ran past the run's ``--timeout``."""


class SimulationTimeout(OutOfTimeError):
    """The builtin simulator ran past its deadline."""


class PlannerError(RelevancePlanError):
    """The planner cannot be found or started."""


class ValidatorUnavailableError(RelevancePlanError):
    """No plan validator could run."""


class StoreError(RelevancePlanError):
    """A results store that cannot be opened or belongs to an incompatible version."""


class SchedulerError(RelevancePlanError):
    """A Dask scheduler that cannot be reached."""


class SceneGraphError(InputFileError):
    """A scene graph (Hydra JSON, a binary update, a Matterport3D house) that cannot be read or imported."""
