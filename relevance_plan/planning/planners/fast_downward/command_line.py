"""Fast Downward's driver and its command line, with the standard library only.

Separate from :mod:`adapter` (which reads what a run leaves behind) so
that the command can be built, and the driver started, before the rest of
the tool is imported (:mod:`head_start`).
"""

from __future__ import annotations

import math
import os
import sys

from relevance_plan import errors
from relevance_plan.planning.planners.fast_downward import fd_driver

TYPE_CHECKING = False  # typing's own flag would import typing
if TYPE_CHECKING:
    from collections.abc import Sequence
    from pathlib import Path

FAST_DOWNWARD_ENV = "RELEVANCE_PLAN_FAST_DOWNWARD"
FULL_DRIVER_ENV = "RELEVANCE_PLAN_FULL_DRIVER"
_LEAN_LAUNCH = fd_driver.LAUNCH.format(folder=os.path.dirname(os.path.abspath(__file__)))
DEFAULT_CONFIG = "lama-first"

# Named configurations -> driver arguments.  Options the driver itself parses
# (``--alias``) must precede the input files, while component options
# (``--evaluator``, ``--search``) must follow them: ``--search`` before the
# files would be read as the driver's "run search component" flag.
# ``_split_driver_options`` puts each part in its place.
PLANNER_CONFIGS: dict[str, tuple[str, ...]] = {
    "lama-first": ("--alias", "lama-first"),
    # Anytime: writes sas_plan.1, sas_plan.2, ... with decreasing cost.
    "lama": ("--alias", "seq-sat-lama-2011"),
    "ff-gbfs": ("--evaluator", "h=ff()", "--search", "lazy_greedy([h],preferred=[h])"),
    "astar-lmcut": ("--search", "astar(lmcut())"),
    "astar-blind": ("--search", "astar(blind())"),
}

# Driver options that take one value and belong before the input files.
_DRIVER_OPTIONS = frozenset({"--alias", "--portfolio"})

PLAN_FILE = "sas_plan"


_LOCATED: dict[str | None, str] = {}  # override -> driver path, found once each


def _locate_driver(override: str | None) -> str:
    if override:
        path = os.path.expanduser(override)
        if not os.path.isfile(path):
            raise errors.PlannerError(f"Fast Downward driver not found at {path} (from ${FAST_DOWNWARD_ENV})")
        return os.path.realpath(path)
    # The package is located without importing it (its __init__ pulls in
    # unified_planning, which is slow), and without importlib.util (itself a costly import).
    spec = None
    for finder in sys.meta_path:
        find_spec = getattr(finder, "find_spec", None)
        spec = find_spec("up_fast_downward", None) if find_spec is not None else None
        if spec is not None:
            break
    if spec is None or not spec.submodule_search_locations:
        raise errors.PlannerError(f"up-fast-downward is not installed; install it or set ${FAST_DOWNWARD_ENV}")
    for location in spec.submodule_search_locations:
        path = os.path.join(location, "downward", "fast-downward.py")
        if os.path.isfile(path):
            return os.path.realpath(path)
    raise errors.PlannerError(
        f"up-fast-downward has no downward/fast-downward.py; reinstall it or set ${FAST_DOWNWARD_ENV}"
    )


def driver_location() -> str:
    """Path of ``fast-downward.py`` as a string; ``$RELEVANCE_PLAN_FAST_DOWNWARD`` overrides it."""
    # Cached per override value, so changing the variable takes effect.
    override = os.environ.get(FAST_DOWNWARD_ENV) or None
    if override not in _LOCATED:
        _LOCATED[override] = _locate_driver(override)
    return _LOCATED[override]


def find_fast_downward() -> Path:
    """Path of ``fast-downward.py``; ``$RELEVANCE_PLAN_FAST_DOWNWARD`` overrides it."""
    from pathlib import Path

    return Path(driver_location())


def planner_arguments(config: str) -> tuple[str, ...]:
    """Driver arguments for a named config, a raw search string or an alias.

    An alias is checked against the driver's list by :func:`check_config`;
    a search string is left to the planner, which rejects a bad one (exit 33).
    """
    if config in PLANNER_CONFIGS:
        return PLANNER_CONFIGS[config]
    if not config.strip():
        raise errors.UsageError("empty planner configuration")
    if "(" in config:
        return ("--search", config)
    return ("--alias", config)


def _split_driver_options(arguments: tuple[str, ...]) -> tuple[list[str], list[str]]:
    """(options before the input files, component options after them)."""
    before: list[str] = []
    index = 0
    while index + 1 < len(arguments) and arguments[index] in _DRIVER_OPTIONS:
        before.extend(arguments[index : index + 2])
        index += 2
    return before, list(arguments[index:])


def build_command(
    launcher: tuple[str, str],
    domain: str | Path,
    problem: str | Path,
    config: str,
    time_limit: float | None,
    memory_limit_mb: int | None,
    extra_arguments: Sequence[str] = (),
    keep_sas_file: bool = False,
) -> list[str]:
    """The driver's command line (``launcher``: the interpreter and the driver script).  ``extra_arguments``
    (``--planner-args``) come last, after the inputs and the configuration's component options
    (e.g. ``--translate-options --invariant-generation-max-candidates 0``)."""
    limits: list[str] = []
    if time_limit is not None:
        limits += ["--overall-time-limit", f"{math.ceil(time_limit)}s"]
    if memory_limit_mb is not None:
        limits += ["--overall-memory-limit", f"{memory_limit_mb}M"]
    before, after = _split_driver_options(planner_arguments(config))
    if keep_sas_file:
        before.append("--keep-sas-file")
    python, driver = launcher
    return [
        python,
        driver,
        "--plan-file",
        PLAN_FILE,
        *limits,
        *before,
        str(domain),
        str(problem),
        *after,
        *extra_arguments,
    ]


def through_lean_driver(command: list[str]) -> list[str]:
    """The driver's ``command`` (from :func:`build_command`) run by the lean stand-in
    (:mod:`fd_driver`), which hands anything but translate-then-search to the real driver;
    ``command`` itself where ``$RELEVANCE_PLAN_FULL_DRIVER`` is set."""
    if os.environ.get(FULL_DRIVER_ENV):
        return command
    return [command[0], "-I", "-S", "-c", _LEAN_LAUNCH, *command[1:]]
