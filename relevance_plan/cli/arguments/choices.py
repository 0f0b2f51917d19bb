"""The options that take one of a set of names (a method, a scorer, a validator, a format...), checked
in one place while the command line is read.

A name the option does not know is a bad argument value: exit 30 in one line
naming the option and its choices, the same code whichever command reads it
and whether click or the library finds it out (``plan --method fast`` as
``compare --methods relevance,fast``).  A misspelt option, a missing value or
text where a number goes stay click's usage errors (exit 2).
``tests/test_options.py`` walks every command's options of this kind.
"""

from __future__ import annotations

from collections.abc import Iterable

import click

from relevance_plan.errors import UsageError
from relevance_plan.exitcodes import ExitCode


class UnknownName(click.BadParameter):
    """A name the option does not take: exit 30, one line naming the option and its choices."""

    exit_code = int(ExitCode.USAGE)

    def format_message(self) -> str:
        names = self.param.opts if self.param is not None else []
        option = max(names, key=len) if names else "the value"
        return f"{option}: {self.message}"


def unknown(what: str, value: str, choices: Iterable[str]) -> str:
    """ "unknown method 'fast' (choose from: relevance, pure, ...)": every such message reads so."""
    return f"unknown {what} '{value}' (choose from: {', '.join(choices)})"


class NamedChoice(click.Choice):
    """One of ``choices`` (a registry's names), called ``what`` in messages."""

    def __init__(self, choices: Iterable[str], what: str):
        super().__init__(tuple(choices))
        self.what = what

    def convert(self, value, param, ctx):
        if value in self.choices:
            return value
        raise UnknownName(unknown(self.what, str(value), self.choices), ctx, param)


class CheckedName(click.ParamType):
    """A name the library checks (``check`` raises UsageError for one it does not know), as a
    :class:`NamedChoice` reports it: a scorer (``learned:MODEL`` among them)."""

    def __init__(self, check, metavar: str):
        self.check = check
        self.name = metavar

    def convert(self, value, param, ctx):
        try:
            self.check(value)
        except UsageError as error:
            raise UnknownName(error.message, ctx, param) from None
        return value


class NamedChoices(click.ParamType):
    """One or more of ``choices``, comma-separated (``builtin,val``); the option may be repeated too."""

    def __init__(self, choices: Iterable[str], what: str):
        self.choices = tuple(choices)
        self.what = what
        self.name = "[" + "|".join(self.choices) + "][,...]"

    def convert(self, value, param, ctx):
        if isinstance(value, tuple):
            return value
        names = tuple(part.strip() for part in str(value).split(","))
        strange = [name for name in names if name not in self.choices]
        if strange:
            raise UnknownName(unknown(self.what, strange[0], self.choices), ctx, param)
        return names
