"""The human's words where the model expects a name: ``--objective TEXT``, ``--activity TEXT``, a cue, an unknown kind.

A value that names an entry of the model is that entry, with no text model
at all.  One token that names none is a name still: a question naming the
names it nearly spells, or, near none, a model error (exit 35) listing the
model's names.  Anything else is free text: mapped to the nearest entry
(:mod:`.word_matching`), or, when the mapping is not clear, a question.  Without
the ``text`` extra, free text is refused in one line that names what was not
understood and what to install.
"""

from __future__ import annotations

from collections.abc import Mapping

from relevance_plan.errors import MissingExtraError, ModelError, printable
from relevance_plan.relevance.scoring.knowledge import KnowledgeModel
from relevance_plan.relevance.scoring.word_matching import (
    MatchStatus,
    ModelVocabulary,
    WordMatch,
    match_text,
    place_kinds,
)

# The option each vocabulary's free text comes from, for messages.
OPTIONS = {ModelVocabulary.OBJECTIVE: "--objective", ModelVocabulary.ACTIVITY: "--activity"}


def entries(model: KnowledgeModel, vocabulary: ModelVocabulary) -> Mapping[str, object]:
    if vocabulary is ModelVocabulary.OBJECTIVE:
        return model.objectives
    if vocabulary is ModelVocabulary.ACTIVITY:
        return model.activity_classes
    return model.classes


def understand(text: str, model: KnowledgeModel, vocabulary: ModelVocabulary) -> WordMatch:
    """``text`` as an entry of ``vocabulary``: resolved, or a question (``WordMatch.insufficiency``).

    :class:`ModelError` for one token that is no name of the vocabulary nor near one;
    :class:`MissingExtraError` when the text needs the text model and it is not installed."""
    match = _matched(text, model, vocabulary)
    if match.status is MatchStatus.UNKNOWN_NAME:
        raise ModelError(_unknown_name(text, model, (vocabulary,)), path=model.path)
    return match


def understand_cue(text: str, model: KnowledgeModel) -> WordMatch:
    """A cue in the human's words, as the model's activity it names or means (a cue is about what to
    make, as an activity cue is), else its objective; else the question, about the activity.

    One token is a name of either vocabulary: near some, the question names them; near none,
    :class:`ModelError` listing both."""
    activity = _matched(text, model, ModelVocabulary.ACTIVITY)
    if activity.chosen is not None:
        return activity
    objective = _matched(text, model, ModelVocabulary.OBJECTIVE)
    if objective.chosen is not None:
        return objective
    if activity.status is MatchStatus.UNKNOWN_NAME and objective.status is MatchStatus.UNKNOWN_NAME:
        raise ModelError(
            _unknown_name(text, model, (ModelVocabulary.ACTIVITY, ModelVocabulary.OBJECTIVE)), path=model.path
        )
    if activity.status is not MatchStatus.NEAR_NAME and objective.status is MatchStatus.NEAR_NAME:
        return objective
    return activity


def _unknown_name(text: str, model: KnowledgeModel, vocabularies: tuple[ModelVocabulary, ...]) -> str:
    """ "unknown objective 'nosuch' (the model's objectives: ...)", for each vocabulary."""
    what = " or ".join(vocabulary.value for vocabulary in vocabularies)
    known = "; ".join(
        f"the model's {vocabulary.plural}: {', '.join(entries(model, vocabulary)) or 'none'}"
        for vocabulary in vocabularies
    )
    return f"unknown {what} '{printable(text, 80)}' ({known}; words of your own take more than one word)"


def _matched(text: str, model: KnowledgeModel, vocabulary: ModelVocabulary) -> WordMatch:
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
