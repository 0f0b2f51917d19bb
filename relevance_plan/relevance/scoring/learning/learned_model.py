"""A learned model of per-object importance: its JSON file, its domain check, and applying it.

The file is plain JSON (never pickle), so it can be read, diffed and moved
between machines.  It records the format and its version, the domain's
signature (name, predicates with arities, types, action names: listed, and
hashed), the feature configuration, the logistic weights (named ones by
name, hashed ones by slot), the types and predicates seen in training, and
the probability ``threshold`` at which the first attempt keeps an object.
"""

from __future__ import annotations

import hashlib
import json
import math
import os
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

from relevance_plan.errors import ModelError
from relevance_plan.io import parse_json, read_bytes
from relevance_plan.pddl.model import Domain
from relevance_plan.relevance.scoring.learning.features import NAMED, NAMED_FEATURES, FeatureConfig, Features

FORMAT = "relevance-plan-learned-model"
VERSION = 1


def domain_signature(domain: Domain) -> dict[str, Any]:
    """What a model must share with a domain to apply to it, listed and hashed."""
    listed: dict[str, Any] = {
        "name": domain.name,
        "predicates": sorted([name, len(params)] for name, params in domain.predicates.items()),
        "types": sorted(domain.types),
        "actions": sorted(action.name for action in domain.actions),
    }
    text = json.dumps(listed, sort_keys=True, separators=(",", ":"))
    listed["hash"] = hashlib.sha256(text.encode("utf-8")).hexdigest()
    return listed


@dataclass(frozen=True)
class LearnedModel:
    domain: Mapping[str, Any]  # domain_signature() of the training domain
    config: FeatureConfig
    named_weights: tuple[float, ...]  # one per NAMED_FEATURES
    hashed_weights: Mapping[int, float]  # feature index (NAMED + slot) -> weight
    threshold: float  # keep an object whose probability exceeds this on the first attempt
    seen_types: frozenset[str]
    seen_predicates: frozenset[str]
    labels: str = "plan"
    respect_goal_zero: bool = True  # objects the goal scorer rules out (score 0) stay out
    training: Mapping[str, Any] = field(default_factory=dict)
    path: str | None = None

    def probability(self, vector: Features) -> float:
        total = 0.0
        for index, value in vector.items():
            if index < NAMED:
                total += self.named_weights[index] * value
            else:
                total += self.hashed_weights.get(index, 0.0) * value
        if total >= 0:
            return 1.0 / (1.0 + math.exp(-total))
        exp = math.exp(total)
        return exp / (1.0 + exp)

    def check_applies(self, domain: Domain) -> None:
        """ModelError (one line) when the model was learned for another domain."""
        signature = domain_signature(domain)
        if signature["hash"] == self.domain.get("hash"):
            return
        if signature["name"] != self.domain.get("name"):
            why = f"it was learned for domain '{self.domain.get('name')}', not '{domain.name}'"
        else:
            why = f"it was learned for another version of domain '{domain.name}' (predicates, types or actions differ)"
        raise ModelError(f"the learned model does not apply: {why}", path=self.path)

    def to_json(self) -> dict[str, Any]:
        return {
            "format": FORMAT,
            "version": VERSION,
            "domain": dict(self.domain),
            "features": self.config.to_json(),
            "labels": self.labels,
            "threshold": self.threshold,
            "respect_goal_zero": self.respect_goal_zero,
            "seen_types": sorted(self.seen_types),
            "seen_predicates": sorted(self.seen_predicates),
            "weights": {
                "named": dict(zip(NAMED_FEATURES, self.named_weights, strict=True)),
                "hashed": {str(index - NAMED): weight for index, weight in sorted(self.hashed_weights.items())},
            },
            "training": dict(self.training),
        }


def learned_model_text(learned_model: LearnedModel) -> str:
    return json.dumps(learned_model.to_json(), indent=1, sort_keys=False) + "\n"


def load_learned_model(path: str | os.PathLike[str]) -> LearnedModel:
    """The model in ``path``: ``InputFileError`` when the file is missing or unreadable (as for
    every file the tool reads), ``ModelError`` naming the file when it is not a model (corrupt,
    truncated, nested too deep, another format or version, a field of the wrong kind)."""
    shown = os.fspath(path)
    data = read_bytes(path, "learned model file")
    try:
        found = parse_json(data.decode("utf-8"))
    except (UnicodeDecodeError, ValueError) as error:
        raise ModelError(f"not a learned model (corrupt or truncated JSON: {error})", path=shown) from None
    try:
        return _from_json(found, shown)
    except (KeyError, TypeError, ValueError) as error:
        raise ModelError(f"not a learned model (missing or malformed field: {error})", path=shown) from None


_REQUIRED = object()


def _field(data: dict[str, Any], key: str, kind: type | tuple[type, ...], default: Any = _REQUIRED) -> Any:
    """``data[key]`` (``default`` when absent, if given), which must be of ``kind``: a number is finite
    and never a bool.  KeyError or TypeError naming the field if not."""
    if key not in data:
        if default is _REQUIRED:
            raise KeyError(key)
        return default
    value = data[key]
    kinds = kind if isinstance(kind, tuple) else (kind,)
    wrong = not isinstance(value, kind) or (isinstance(value, bool) and bool not in kinds)
    if wrong or (isinstance(value, float) and not math.isfinite(value)):
        raise TypeError(f'"{key}" is {json.dumps(value)[:40]}')
    return value


def _names(data: dict[str, Any], key: str, default: Any = _REQUIRED) -> frozenset[str]:
    names = _field(data, key, list, default)
    if not all(isinstance(name, str) for name in names):
        raise TypeError(f'"{key}" must list names')
    return frozenset(names)


def _from_json(data: Any, path: str) -> LearnedModel:
    if not isinstance(data, dict) or data.get("format") != FORMAT:
        raise ModelError(f'not a learned model (no "format": "{FORMAT}")', path=path)
    if data.get("version") != VERSION:
        raise ModelError(
            f"learned model format version {data.get('version')!r}; this relevance-plan reads version {VERSION}",
            path=path,
        )
    features = _field(data, "features", dict)
    config = FeatureConfig(
        _field(features, "iterations", int), _field(features, "buckets", int), _names(features, "hubs", [])
    )
    if not 0 <= config.iterations <= 8 or not 1 <= config.buckets <= 1 << 24:
        raise ValueError("feature configuration out of range")
    weights = _field(data, "weights", dict)
    named = _field(weights, "named", dict)
    named_weights = tuple(float(_field(named, name, (int, float))) for name in NAMED_FEATURES)
    hashed: dict[int, float] = {}
    for slot, weight in _field(weights, "hashed", dict).items():
        index = int(slot)
        if not 0 <= index < config.buckets:
            raise ValueError(f"weight slot {index} outside 0..{config.buckets - 1}")
        hashed[NAMED + index] = float(_field({slot: weight}, slot, (int, float)))
    threshold = float(_field(data, "threshold", (int, float)))
    if not 0.0 < threshold < 1.0:
        raise ValueError(f"threshold {threshold} outside (0, 1)")
    domain = _field(data, "domain", dict)
    _field(domain, "hash", str)
    return LearnedModel(
        domain=domain,
        config=config,
        named_weights=named_weights,
        hashed_weights=hashed,
        threshold=threshold,
        seen_types=_names(data, "seen_types"),
        seen_predicates=_names(data, "seen_predicates"),
        labels=_field(data, "labels", str, "plan"),
        respect_goal_zero=_field(data, "respect_goal_zero", bool, True),
        training=_field(data, "training", dict, {}),
        path=path,
    )
