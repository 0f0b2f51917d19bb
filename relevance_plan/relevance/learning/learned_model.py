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
from relevance_plan.pddl.model import Domain
from relevance_plan.relevance.learning.features import NAMED, NAMED_FEATURES, FeatureConfig, Features

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
    """The model in ``path``; ModelError naming the file when it is not one (corrupt, truncated,
    another format or version)."""
    shown = os.fspath(path)
    try:
        with open(shown, "rb") as stream:
            data = json.loads(stream.read().decode("utf-8"))
    except FileNotFoundError:
        raise ModelError("no such learned model file", path=shown) from None
    except IsADirectoryError:
        raise ModelError("the learned model is a directory, not a file", path=shown) from None
    except PermissionError:
        raise ModelError("the learned model file cannot be read (permission denied)", path=shown) from None
    except (UnicodeDecodeError, json.JSONDecodeError) as error:
        raise ModelError(f"not a learned model (corrupt or truncated JSON: {error})", path=shown) from None
    try:
        return _from_json(data, shown)
    except (KeyError, TypeError, ValueError, AttributeError) as error:
        raise ModelError(f"not a learned model (missing or malformed field: {error})", path=shown) from None


def _from_json(data: Any, path: str) -> LearnedModel:
    if not isinstance(data, dict) or data.get("format") != FORMAT:
        raise ModelError(f'not a learned model (no "format": "{FORMAT}")', path=path)
    if data.get("version") != VERSION:
        raise ModelError(
            f"learned model format version {data.get('version')!r}; this relevance-plan reads version {VERSION}",
            path=path,
        )
    features = data["features"]
    config = FeatureConfig(
        int(features["iterations"]), int(features["buckets"]), frozenset(str(h) for h in features.get("hubs", ()))
    )
    if not 0 <= config.iterations <= 8 or not 1 <= config.buckets <= 1 << 24:
        raise ValueError("feature configuration out of range")
    named = data["weights"]["named"]
    named_weights = tuple(float(named[name]) for name in NAMED_FEATURES)
    hashed: dict[int, float] = {}
    for slot, weight in data["weights"]["hashed"].items():
        index = int(slot)
        if not 0 <= index < config.buckets:
            raise ValueError(f"weight slot {index} outside 0..{config.buckets - 1}")
        hashed[NAMED + index] = float(weight)
    threshold = float(data["threshold"])
    if not 0.0 < threshold < 1.0:
        raise ValueError(f"threshold {threshold} outside (0, 1)")
    domain = data["domain"]
    if not isinstance(domain, dict) or not isinstance(domain.get("hash"), str):
        raise ValueError("no domain signature")
    if not all(math.isfinite(w) for w in (*named_weights, *hashed.values())):
        raise ValueError("a weight is not a finite number")
    return LearnedModel(
        domain=domain,
        config=config,
        named_weights=named_weights,
        hashed_weights=hashed,
        threshold=threshold,
        seen_types=frozenset(str(t) for t in data["seen_types"]),
        seen_predicates=frozenset(str(p) for p in data["seen_predicates"]),
        labels=str(data.get("labels", "plan")),
        respect_goal_zero=bool(data.get("respect_goal_zero", True)),
        training=dict(data.get("training", {})),
        path=path,
    )
