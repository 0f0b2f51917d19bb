"""A lean stand-in for Fast Downward's driver, for the plain case: translate, then search.

Run under the guard as ``python -I -S -c "...import fd_driver; fd_driver.main()"
DRIVER ARGUMENTS...`` (:data:`LAUNCH`), where DRIVER is ``fast-downward.py``
and ARGUMENTS are what that driver would get.  Fast Downward's own driver
imports its interpreter's ``site``, argparse, logging and its alias table
before the translator starts; on the small problems that are most of the
field's benchmarks, that is a noticeable share of the planner's time
(docs/how-it-works.md has the figures).  This one starts the translator at
once and reads the alias table while the translator runs.

It takes the arguments ``command.build_command`` writes: ``--plan-file``,
``--overall-time-limit``, ``--overall-memory-limit``, ``--keep-sas-file``,
one ``--alias`` or the search's own options after the two input files.
Anything else (a portfolio, an alias that the driver itself must read such
as ``--if-unit-cost``, the driver's component options, a build other than
``release``) goes to the real driver, with the same arguments (``exec``).
What it does is what the driver does for those arguments: the same
components with the same command lines, the time limit of each component
set as the remaining CPU time (``RLIMIT_CPU``) and the memory limit as its
address space (``RLIMIT_AS``), ``output.sas`` removed unless kept, the same
``<component> exit code: N`` lines and the same exit code (a translator
crash without an exit code of its own is 30, as the driver reports it).

Standard library only, and little of it: its start delays the translator.
``$RELEVANCE_PLAN_FULL_DRIVER=1`` makes the tool run the real driver instead.
"""

from __future__ import annotations

import os
import sys

TYPE_CHECKING = False  # typing's own flag would import typing
if TYPE_CHECKING:
    from typing import TypedDict

    class _DriverRun(TypedDict):
        inputs: list[str]
        search: list[str]
        alias: str | None
        plan_file: str
        time_limit: int | None
        memory_limit: int | None
        keep_sas_file: bool


LAUNCH = "import sys; sys.path.append({folder!r}); import fd_driver; fd_driver.main()"
SAS_FILE = "output.sas"
TRANSLATE_CRITICAL_ERROR = 30  # the driver's code for a translator that crashed with exit code 1
_DRIVER_FLAGS = frozenset({"--keep-sas-file"})
_DRIVER_VALUES = frozenset({"--plan-file", "--overall-time-limit", "--overall-memory-limit", "--alias"})
# What the search binary takes after the inputs, in pairs; anything else is the driver's to read.
_SEARCH_OPTIONS = frozenset({"--search", "--evaluator", "--heuristic", "--landmarks"})
_TIME_UNITS = {"s": 1, "m": 60, "h": 3600}
_MEMORY_UNITS = {"k": 2**10, "m": 2**20, "g": 2**30}


class _NotThisDriver(Exception):
    """The arguments ask for something only the real driver does."""


def _read(arguments: list[str]) -> _DriverRun:
    """The run the arguments describe; ``_NotThisDriver`` when this driver does not do it."""
    options: dict[str, str] = {}
    flags: set[str] = set()
    index = 0
    while index < len(arguments) and arguments[index].startswith("--"):
        name = arguments[index]
        if name in _DRIVER_FLAGS:
            flags.add(name)
            index += 1
        elif name in _DRIVER_VALUES and index + 1 < len(arguments) and name not in options:
            options[name] = arguments[index + 1]
            index += 2
        else:
            raise _NotThisDriver(name)
    inputs = arguments[index : index + 2]
    search = arguments[index + 2 :]
    if len(inputs) != 2 or any(item.startswith("-") or not os.path.isfile(item) for item in inputs):
        raise _NotThisDriver("inputs")
    if len(search) % 2 or not set(search[::2]) <= _SEARCH_OPTIONS:
        raise _NotThisDriver("search options")
    if ("--alias" in options) == bool(search):
        raise _NotThisDriver("one of --alias or search options")
    return {
        "inputs": inputs,
        "search": search,
        "alias": options.get("--alias"),
        "plan_file": options.get("--plan-file", "sas_plan"),
        "time_limit": _amount(options.get("--overall-time-limit"), _TIME_UNITS, "s"),
        "memory_limit": _amount(options.get("--overall-memory-limit"), _MEMORY_UNITS, "m"),
        "keep_sas_file": "--keep-sas-file" in flags,
    }


def _amount(text: str | None, units: dict[str, int], default: str) -> int | None:
    """``120s`` -> 120, ``2000M`` -> bytes, as the driver reads its limits."""
    if text is None:
        return None
    number, unit = (text[:-1], text[-1].lower()) if text[-1:].isalpha() else (text, default)
    if not number.isdigit() or unit not in units:
        raise _NotThisDriver("limit")
    return int(number) * units[unit]


def _search_options(driver: str, alias: str) -> list[str]:
    """The search options of ``alias``, from the driver's own table; ``_NotThisDriver`` for a portfolio or
    an alias whose options the driver itself reads."""
    sys.path.insert(0, os.path.dirname(driver))
    try:
        from driver import aliases

        options = aliases.ALIASES.get(alias)
    except Exception as error:  # noqa: BLE001 - a driver laid out otherwise: it reads its aliases itself
        raise _NotThisDriver(f"alias table: {error}") from None
    finally:
        del sys.path[0]
    if options is None or any(option.startswith(("--if-", "--always")) for option in options):
        raise _NotThisDriver(f"alias {alias}")
    return list(options)


def _remaining_cpu(limit: int | None) -> int | None:
    """The component's time limit: what is left of ``limit`` after the CPU time used so far (as the driver
    counts it: this process and its children), rounded down unless within 1 ms of the next second."""
    if limit is None:
        return None
    used = sum(os.times()[:4])
    return int(max(0.0, limit - used) + 0.001)


def _start(
    nick: str, command: list[str], *, env: dict[str, str], stdin: str | None, time_limit: int | None, memory: int | None
) -> int:
    """Start one component with its limits; its pid."""
    print(f"{nick} command line: {' '.join(command)}{' < ' + stdin if stdin else ''}", flush=True)
    pid = os.fork()
    if pid == 0:
        try:
            import resource

            if time_limit is not None:
                try:
                    resource.setrlimit(resource.RLIMIT_CPU, (time_limit, time_limit + 1))
                except ValueError:
                    resource.setrlimit(resource.RLIMIT_CPU, (time_limit, time_limit))
            if memory is not None:
                resource.setrlimit(resource.RLIMIT_AS, (memory, memory))
            if stdin is not None:
                handle = os.open(stdin, os.O_RDONLY)
                os.dup2(handle, 0)
                os.close(handle)
            os.execve(command[0], command, env)
        except BaseException as error:  # noqa: BLE001 - the child must never return into the parent's code
            print(f"{nick}: cannot start {command[0]}: {error}", file=sys.stderr, flush=True)
        os._exit(127)
    return pid


def _wait(pid: int) -> int:
    """The exit code of the component ``pid`` (-N: killed by signal N)."""
    _, status = os.waitpid(pid, 0)
    return os.waitstatus_to_exitcode(status)


def _plan(driver: str, run: _DriverRun) -> int:
    """Translate, then search: the driver's exit code.  ``_NotThisDriver`` (before anything is left
    behind) when the alias turns out to be one only the driver reads."""
    root = os.path.dirname(os.path.abspath(driver))
    binaries = os.path.join(root, "builds", "release", "bin")
    search_binary = os.path.join(binaries, "downward")
    if not (os.path.isdir(os.path.join(binaries, "fast_downward")) and os.access(search_binary, os.X_OK)):
        raise _NotThisDriver("build")
    time_limit, memory = run["time_limit"], run["memory_limit"]
    python_path = os.pathsep.join(filter(None, [binaries, os.environ.get("PYTHONPATH")]))
    translate = [sys.executable, "-m", "fast_downward.translate", *run["inputs"], "--sas-file", SAS_FILE]
    translator = _start(
        "translate",
        translate,
        env={**os.environ, "PYTHONPATH": python_path},
        stdin=None,
        time_limit=_remaining_cpu(time_limit),
        memory=memory,
    )
    # the alias is read while the translator runs: only the search needs it
    try:
        search = run["search"]
        if not search:
            assert run["alias"] is not None  # _read takes an alias when no search options are given
            search = _search_options(driver, run["alias"])
    except _NotThisDriver:
        os.kill(translator, 9)  # SIGKILL: the real driver translates again
        _wait(translator)
        _remove(SAS_FILE)
        raise
    code = _wait(translator)
    if code == 1:
        code = TRANSLATE_CRITICAL_ERROR
    print(f"translate exit code: {code}\n", flush=True)
    if code != 0:
        print("Driver aborting after translate", flush=True)
        return code
    command = [search_binary, *search, "--internal-plan-file", run["plan_file"]]
    searcher = _start(
        "search", command, env=dict(os.environ), stdin=SAS_FILE, time_limit=_remaining_cpu(time_limit), memory=memory
    )
    code = _wait(searcher)
    if not run["keep_sas_file"]:
        _remove(SAS_FILE)
    print(f"search exit code: {code}\n", flush=True)
    return code


def _remove(path: str) -> None:
    try:
        os.remove(path)
    except OSError:
        pass


def main() -> None:
    driver, arguments = sys.argv[1], sys.argv[2:]
    try:
        code = _plan(driver, _read(arguments))
    except _NotThisDriver:
        sys.stdout.flush()
        os.execv(sys.executable, [sys.executable, driver, *arguments])
    # as the driver exits: a death by signal N as -N, which the exit status carries as 256 - N
    sys.exit(code)
