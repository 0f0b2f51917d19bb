"""Job keys: what makes two batch jobs the same job.

A job's key is ``(problem_hash, method, config_hash, planner_version)``
(``store.ResultKey``): the sha256 of the domain and problem texts, the
method, the sha256 of the canonical JSON of every option that can change
the result, and the version of the planner that runs it.  A job whose key is
already stored is not run again; anything that could change its result
changes its key.
"""

from __future__ import annotations

import hashlib
import json
import os
from pathlib import Path
from typing import Any

from relevance_plan import __version__
from relevance_plan.batch.store import ResultKey
from relevance_plan.errors import InputFileError, RelevancePlanError
from relevance_plan.io import load_domain, read_bytes
from relevance_plan.planning.options import PLAN_OPTION_FIELDS, Method, PlanOptions
from relevance_plan.planning.planners.registry import DEFAULT_PLANNER_CONFIG, make_planner
from relevance_plan.relevance.scoring.knowledge import find_knowledge_model
from relevance_plan.sidecar import sidecar_path


def _sha256(data: bytes) -> str:
    return hashlib.sha256(data).hexdigest()


def _file_hash(path: str | os.PathLike | None) -> str | None:
    """sha256 of a file's bytes, None when there is no such regular file (a FIFO is never read)."""
    if path is None or not os.path.isfile(path):
        return None
    try:
        return _sha256(read_bytes(path))
    except InputFileError:
        return None


def problem_hash(domain_path: str | os.PathLike, problem_path: str | os.PathLike) -> str:
    """sha256 of the domain text, a NUL byte, and the problem text."""
    domain = read_bytes(domain_path, "domain file")
    problem = read_bytes(problem_path, "problem file")
    return _sha256(domain + b"\0" + problem)


def unreadable_hash(problem_path: str | os.PathLike, reason: str) -> str:
    """The problem part of the key of a problem that cannot be read: its file name and why.

    The suite's location stays out of it (moving a suite keeps its keys); a
    problem that becomes readable gets its content's key and runs.
    """
    return _sha256(
        b"unreadable\0" + Path(problem_path).name.encode("utf-8", "surrogateescape") + b"\0" + reason.encode()
    )


def planner_version(planner: str = "fast-downward", config: str = DEFAULT_PLANNER_CONFIG) -> str:
    """The version of the planner a job runs (a changed planner must not reuse stored rows)."""
    return make_planner(planner, config).version()


def _model_file(options: PlanOptions, domain_path: str | None) -> str | None:
    """The knowledge-model file the run would use (as ``relevance.setup.resolve_knowledge_model`` finds it)."""
    if options.model_path is not None:
        return options.model_path
    if domain_path is None:
        return None
    try:
        name = load_domain(domain_path).name
    except RelevancePlanError:
        return None  # the job itself will report the bad domain
    found = find_knowledge_model(name, domain_path)
    return str(found) if found is not None else None


# How each PlanOptions field enters a job's configuration key.  Every field
# must be listed (a test checks it): a new option cannot silently reuse rows
# stored without it.
#   "always"  - part of every job's key;
#   "pruning" - part of the key of the methods that prune (not 'pure');
#   "derived" - enters through a derived value (below);
#   "method"  - the key has the method in its own column.
FINGERPRINT_RULES: dict[str, str] = {
    "method": "method",
    "planner": "always",
    "planner_config": "always",
    "planner_args": "derived",  # when given (keys of runs without any stay as they were)
    "race": "derived",  # when on: it changes times, not plans' validity
    "timeout": "always",
    "memory_limit_mb": "always",
    "validators": "derived",  # the validators that will actually run
    "seed": "always",
    "thresholds": "derived",  # as tau_class and tau_element
    "widen": "pruning",
    "widen_factor": "pruning",
    "first_share": "pruning",
    "scorer": "pruning",  # and, for learned:MODEL, the sha256 of the model file
    "goal_filter": "pruning",
    "prefer_free": "pruning",
    "economical": "pruning",
    "model_path": "derived",  # as the sha256 of the model file the run would use
    "objective": "pruning",
    "activity": "pruning",
    "human": "pruning",
    "place_kinds": "derived",  # when on (keys of runs without it stay as they were)
}


def _plain(value: Any) -> Any:
    return float(value) if isinstance(value, float) else value


def config_fingerprint(options: PlanOptions, domain_path: str | None, problem_path: str) -> dict[str, Any]:
    """The options that influence a job's result, as a JSON-ready dict (see ``FINGERPRINT_RULES``).

    Besides the options: the tool version (a new release may prune or
    validate differently), for pruning methods the sha256 of the knowledge
    model the run would use, for ``--scorer learned:MODEL`` the sha256 of
    MODEL (a model retrained at the same path must not reuse rows), and for
    the oracle the sha256 of the sidecar (its ground truth).
    """
    from relevance_plan.planning.validation import default_validators

    unlisted = set(PLAN_OPTION_FIELDS) - set(FINGERPRINT_RULES)
    if unlisted:
        raise AssertionError(f"PlanOptions fields without a fingerprint rule: {sorted(unlisted)}")
    pruning = options.method.prunes
    config: dict[str, Any] = {"tool_version": __version__, "method": options.method}
    for name, rule in FINGERPRINT_RULES.items():
        if rule == "always" or (rule == "pruning" and pruning):
            config[name] = _plain(getattr(options, name))
    config["validators"] = list(options.validators) if options.validators else list(default_validators())
    if options.planner_args:
        config["planner_args"] = list(options.planner_args)
    if options.race:
        config["race"] = True
    if options.place_kinds and pruning:
        config["place_kinds"] = True
    if pruning:
        config["tau_class"] = float(options.thresholds.tau_class)
        config["tau_element"] = float(options.thresholds.tau_element)
        config["model_hash"] = _file_hash(_model_file(options, domain_path))
        learned = options.scoring.learned_model_path
        if learned is not None:
            config["learned_model_hash"] = _file_hash(learned)
        if options.method is Method.ORACLE or options.scorer == "oracle":
            config["sidecar_hash"] = _file_hash(sidecar_path(problem_path))
    return config


def canonical_json(config: dict[str, Any]) -> str:
    """Sorted keys, no spaces: the same options always give the same text."""
    return json.dumps(config, sort_keys=True, separators=(",", ":"))


def config_hash(config: dict[str, Any]) -> str:
    """sha256 of the canonical JSON of ``config``."""
    return _sha256(canonical_json(config).encode("utf-8"))


def result_key(
    domain_path: str | None, problem_path: str, input_error: str | None, config: dict[str, Any], options: PlanOptions
) -> ResultKey:
    """The store key of one job; a problem that cannot be read is keyed by its name and the reason."""
    if input_error is None and domain_path is not None:
        try:
            digest = problem_hash(domain_path, problem_path)
        except InputFileError as error:
            digest = unreadable_hash(problem_path, error.message)
    else:
        digest = unreadable_hash(problem_path, input_error or "no domain file")
    return ResultKey(
        problem_hash=digest,
        method=options.method,
        config_hash=config_hash(config),
        planner_version=planner_version(options.planner, options.planner_config),
    )
