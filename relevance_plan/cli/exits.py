"""How a run ends when its surroundings fail: the output closed or full, memory exhausted.

Library errors become one line and an exit code in ``common.handle_errors``;
this module covers what is not the library's doing, so that no traceback
ever reaches the user:

* the reader of standard output went away (``relevance-plan score | head -1``):
  stop at once and quietly with exit 141, as a filter killed by SIGPIPE does;
* standard output is closed (``>&-``): refused before any work (exit 31),
  rather than running with every line thrown away;
* standard output cannot take the text (``> /dev/full``): one line, exit 31;
* the tool itself runs out of memory (``ulimit -v``), however the interpreter says so: one line, exit 21;
* click refuses the command line (an unknown option, a missing argument, a
  number out of its range): one line naming what is wrong, not click's
  four, exit 2 (30 for a number out of range, ``cli.arguments.numbers``).
"""

from __future__ import annotations

import contextlib
import errno
import os
import sys
from typing import NoReturn

import click

from relevance_plan.errors import MAX_MESSAGE, printable
from relevance_plan.exitcodes import ExitCode

# What a shell reports for a process killed by SIGPIPE (128 + 13); Python ignores SIGPIPE, so we exit so.
OUTPUT_CLOSED = 141
_PREFIX = "relevance-plan: error: "


def _say(message: str) -> None:
    """One line on stderr with as little work as possible (memory may be exhausted)."""
    with contextlib.suppress(OSError, ValueError):
        os.write(2, (_PREFIX + message + "\n").encode("utf-8", errors="replace"))


def _drop_stdout() -> None:
    """Point standard output at /dev/null, so that the interpreter's last flush cannot fail again."""
    with contextlib.suppress(OSError, ValueError, AttributeError):
        fd = sys.stdout.fileno()
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, fd)
        os.close(devnull)


def quit_on_broken_pipe() -> NoReturn:
    """The reader of our output left: say nothing, exit 141."""
    _drop_stdout()
    sys.exit(OUTPUT_CLOSED)


_said_out_of_memory = False


def quit_out_of_memory() -> NoReturn:
    """One line, exit 21; the line said once, though memory may run out again on the way out."""
    global _said_out_of_memory
    if not _said_out_of_memory:
        _say("out of memory (raise the memory limit, or give the tool a smaller problem)")
        _said_out_of_memory = True
    _drop_stdout()
    sys.exit(int(ExitCode.OUT_OF_MEMORY))


# How the interpreter reports a C function that failed an allocation and did not say so: the same
# out of memory, in other words ("<function score> returned NULL without setting an exception").
_SILENT_FAILURES = ("without setting an exception", "without exception set")


def quit_if_memory_ran_out(error: MemoryError | SystemError) -> None:
    """One line and exit 21 when ``error`` is how memory running out surfaced; else return."""
    if isinstance(error, MemoryError) or any(words in str(error) for words in _SILENT_FAILURES):
        error.__traceback__ = None  # its frames hold what filled the memory: free it before saying anything
        quit_out_of_memory()


def quit_on_output_error(error: OSError) -> NoReturn:
    """Standard output refused the text (a full disk, /dev/full, an I/O error)."""
    if error.errno == errno.EPIPE:
        quit_on_broken_pipe()
    _say(f"cannot write standard output: {error.strerror or error}")
    _drop_stdout()
    sys.exit(int(ExitCode.INPUT_FILE))


def stdout_is_closed() -> bool:
    """Standard output is not open at all (``>&-``); a captured stream (tests) counts as open."""
    if sys.stdout is None:
        return True
    try:
        fd = sys.stdout.fileno()
    except (OSError, ValueError, AttributeError):
        return False  # not backed by a descriptor: an in-memory stream
    try:
        os.fstat(fd)
    except OSError:
        return True
    return False


def quit_on_usage_error(error: click.ClickException) -> NoReturn:
    """click refused the command line: one line naming what is wrong (click's own block is four),
    and its exit code (2 for a malformed command line, 30 for a number out of range)."""
    context = getattr(error, "ctx", None)
    if isinstance(error, click.exceptions.NoArgsIsHelpError) and context is not None:
        click.echo(context.get_help())  # no command at all: the help, then the line
        message = f"no command given; the commands are listed above ('{context.command_path} COMMAND --help')"
        click.echo(_PREFIX + message, err=True)
        sys.exit(int(ExitCode.COMMAND_LINE))
    message = printable(" ".join(error.format_message().split()), MAX_MESSAGE)
    if isinstance(error, click.UsageError) and context is not None:
        message += f" (see '{context.command_path} --help')"
    click.echo(_PREFIX + message, err=True)
    if isinstance(error, click.FileError):
        sys.exit(int(ExitCode.INPUT_FILE))
    sys.exit(error.exit_code if error.exit_code in _CLICK_CODES else int(ExitCode.USAGE))


_CLICK_CODES = (int(ExitCode.COMMAND_LINE), int(ExitCode.USAGE))


class ToolGroup(click.Group):
    """The command group, with the endings above around every command (click's own included).

    click runs it outside its standalone mode, so that its usage errors and what
    ends a run while the command line is read come here and end in one line.
    """

    def main(self, args=None, prog_name=None, complete_var=None, standalone_mode: bool = True, **extra):
        if not standalone_mode:  # a caller that handles click's exceptions itself
            return super().main(args, prog_name, complete_var, standalone_mode=False, **extra)
        if stdout_is_closed():
            _say("standard output is closed; give the command somewhere to write (e.g. > /dev/null)")
            sys.exit(int(ExitCode.INPUT_FILE))
        try:
            result = super().main(args, prog_name, complete_var, standalone_mode=False, **extra)
        except click.ClickException as error:
            _flush_stdout()
            quit_on_usage_error(error)
        except (click.Abort, KeyboardInterrupt):  # Ctrl-C while click read the command line
            _say("interrupted")
            sys.exit(int(ExitCode.INTERRUPTED))
        except SystemExit:
            _flush_stdout()
            raise
        except (MemoryError, SystemError) as error:
            quit_if_memory_ran_out(error)
            raise
        except OSError as error:  # outside any command's own handling (click's help, its usage lines)
            if error.filename is None:
                quit_on_output_error(error)
            _say(f"{error.filename}: {error.strerror or error}")
            sys.exit(int(ExitCode.INPUT_FILE))
        _flush_stdout()
        # click's --help and --version end with their code; a command that returns has succeeded
        sys.exit(result if isinstance(result, int) else int(ExitCode.SUCCESS))


def _flush_stdout() -> None:
    try:
        if sys.stdout is not None:
            sys.stdout.flush()
    except OSError as error:
        quit_on_output_error(error)
