"""The human's words where the model expects a name: ``--objective TEXT``, ``--task TEXT``, a cue, an unknown kind.

A value that names an entry of the model is that entry, with no text model
at all.  Anything else is free text: mapped to the nearest entry
(:mod:`.word_matching`), or, when the mapping is not clear, a question.  Without
the ``text`` extra, free text is refused in one line that names what was not
understood and what to install.
"""

from __future__ import annotations

from collections.abc import Mapping

from relevance_plan.errors import MissingExtraError, printable
from relevance_plan.relevance.scoring.knowledge import KnowledgeModel
from relevance_plan.relevance.scoring.word_matching import ModelVocabulary, WordMatch, match_text, place_kinds

# The option each vocabulary's free text comes from, for messages.
OPTIONS = {ModelVocabulary.OBJECTIVE: "--objective", ModelVocabulary.TASK: "--task"}


def entries(model: KnowledgeModel, vocabulary: ModelVocabulary) -> Mapping[str, object]:
    if vocabulary is ModelVocabulary.OBJECTIVE:
        return model.objectives
    if vocabulary is ModelVocabulary.TASK:
        return model.task_classes
    return model.classes


def understand(text: str, model: KnowledgeModel, vocabulary: ModelVocabulary) -> WordMatch:
    """``text`` as an entry of ``vocabulary``: resolved, or a question (``WordMatch.insufficiency``).

    :class:`MissingExtraError` when the text needs the text model and it is not installed."""
    try:
        return match_text(text, model, vocabulary)
    except MissingExtraError as error:
        known = ", ".join(entries(model, vocabulary)) or "none"
        raise MissingExtraError(
            f"unknown {vocabulary.value} '{printable(text, 80)}' (the model has: {known}); to understand it as"
            f" free text, {error.message}",
            path=model.path,
        ) from None


def understand_kinds(kinds: list[str], model: KnowledgeModel) -> tuple[WordMatch, ...]:
    """Each object kind (or type) the model does not list, as the class it most resembles or a question."""
    try:
        return place_kinds(kinds, model)
    except MissingExtraError as error:
        raise MissingExtraError(f"placing the kinds the model does not list: {error.message}") from None
