"""What the human says, mapped to a knowledge model's vocabulary by meaning.

Three vocabularies: the model's objectives, its activities, and its classes (for an
object kind the model does not list).  Each entry is embedded as a few short
phrases taken from what the model already says about it; a text is matched to
the entry with the most similar phrase (cosine similarity of the text model's
unit vectors).

A match is a decision only when it is clear: a nearest entry below the
vocabulary's floor, or within its margin of the runner-up, is reported as
insufficient cues with the candidates, so the caller asks instead of
guessing.  A text that spells an entry's name (``drink-at-break``,
``drink at break``) is that entry, without the text model.

Names come before words.  For objectives and activities, a text of one token (no
space: ``drink-at-brek``, ``nosuch``) is read as a name, never as words: a
name one or two typing slips from some of the model's names is a question
naming them (``near-name``), and one near none is a name the model does not
have (``unknown-name``, which the scoring set-up refuses as a model error).
Words of one's own take more than one word.
"""

from __future__ import annotations

import dataclasses
import functools
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from enum import Enum
from types import MappingProxyType
from typing import TYPE_CHECKING, Any

from relevance_plan.errors import printable
from relevance_plan.relevance.scoring.knowledge import KnowledgeModel, ModelClass
from relevance_plan.text.cache import cache_key, read_cached, write_cached
from relevance_plan.text.installed import TextModel, load_text_model

if TYPE_CHECKING:
    from relevance_plan.text.encoder import FloatArray


class ModelVocabulary(str, Enum):
    OBJECTIVE = "objective"
    ACTIVITY = "activity"
    CLASS = "class"

    @property
    def plural(self) -> str:
        return (
            "activities"
            if self is ModelVocabulary.ACTIVITY
            else "classes"
            if self is ModelVocabulary.CLASS
            else "objectives"
        )


class MatchStatus(str, Enum):
    RESOLVED = "resolved"
    BELOW_FLOOR = "below-floor"  # nothing is similar enough: ask
    TOO_CLOSE = "too-close"  # two entries are about as similar: ask which
    NEAR_NAME = "near-name"  # one token a typing slip away from some names: ask which
    UNKNOWN_NAME = "unknown-name"  # one token near no name of the vocabulary: not the model's


# Vocabularies whose entries a one-token text is taken to name (an object kind is always words).
NAMED_VOCABULARIES = frozenset({"objective", "activity"})
# A name is near when this share of its letters (at least one) covers the edits between them.
TYPING_SLIPS = 0.2


@dataclass(frozen=True)
class MatchRule:
    """A match stands when its similarity is at least ``floor`` and ``margin`` above the runner-up's."""

    floor: float
    margin: float


# Chosen on the tuning half of the paraphrases in tests/data/paraphrases.yaml (docs/knowledge-model.md,
# "Free text"): sentences against sentences score lower than a kind against single words, so kinds
# have the higher floor.
DEFAULT_RULES: Mapping[ModelVocabulary, MatchRule] = MappingProxyType(
    {
        ModelVocabulary.OBJECTIVE: MatchRule(floor=0.35, margin=0.03),
        ModelVocabulary.ACTIVITY: MatchRule(floor=0.35, margin=0.03),
        ModelVocabulary.CLASS: MatchRule(floor=0.55, margin=0.05),
    }
)
# Candidates a match reports (the nearest and its runners-up).
SHOWN_CANDIDATES = 3
# A class an activity needs with at least this probability is named in the activity's phrases.
NEEDED_CLASS = 0.5


@dataclass(frozen=True)
class MatchCandidate:
    name: str
    similarity: float


@dataclass(frozen=True)
class WordMatch:
    """One text mapped to one vocabulary: the nearest entries, best first, and whether it stands."""

    text: str
    vocabulary: ModelVocabulary
    status: MatchStatus
    candidates: tuple[MatchCandidate, ...]
    rule: MatchRule

    @property
    def chosen(self) -> str | None:
        """The entry the text means, or None: the cues are insufficient and the caller should ask."""
        return self.candidates[0].name if self.status is MatchStatus.RESOLVED else None

    @property
    def similarity(self) -> float:
        """The nearest entry's cosine similarity (1.0 for a text that spells its name)."""
        return self.candidates[0].similarity if self.candidates else 0.0

    @property
    def runners_up(self) -> tuple[MatchCandidate, ...]:
        return self.candidates[1:]

    @property
    def insufficiency(self) -> str:
        """Why the text decides nothing ("" when it does), with the candidates to ask about."""
        said = printable(self.text, 80)
        shown = ", ".join(f"{c.name} {c.similarity:.2f}" for c in self.candidates)
        if self.status is MatchStatus.BELOW_FLOOR:
            return (
                f"'{said}' is like no {self.vocabulary.value} of the model"
                f" (nearest: {shown or 'none'}; floor {self.rule.floor:.2f})"
            )
        if self.status is MatchStatus.TOO_CLOSE:
            return (
                f"'{said}' fits several {self.vocabulary.plural} about equally ({shown};"
                f" margin {self.rule.margin:.2f}) — say which"
            )
        if self.status is MatchStatus.NEAR_NAME:
            names = ", ".join(c.name for c in self.candidates)
            return f"'{said}' is no {self.vocabulary.value} of the model; the names nearest it: {names}"
        if self.status is MatchStatus.UNKNOWN_NAME:
            vocabulary = self.vocabulary.value
            return f"'{said}' is no {vocabulary} of the model, nor near one (free text takes more than one word)"
        return ""

    def as_json(self) -> dict[str, Any]:
        return {
            "text": self.text,
            "vocabulary": self.vocabulary.value,
            "status": self.status.value,
            "chosen": self.chosen,
            "similarity": round(self.similarity, 4),
            "candidates": [{"name": c.name, "similarity": round(c.similarity, 4)} for c in self.candidates],
        }


def plain_words(name: str) -> str:
    """A model name as words: ``hot-coffee-with-creamer`` -> ``hot coffee with creamer``."""
    return " ".join(name.replace("_", " ").replace("-", " ").split()).lower()


def vocabulary_phrases(model: KnowledgeModel, vocabulary: ModelVocabulary) -> Mapping[str, tuple[str, ...]]:
    """Entry name -> the phrases embedded for it, all from the model's own words.

    - an objective: its name and its description (not its activities' names, which
      objectives share and which would blur them);
    - an activity: its name, and its name with the classes it most needs;
    - a class: its name, its PDDL types and its kinds, each a phrase.
    """
    phrases: dict[str, tuple[str, ...]] = {}
    if vocabulary is ModelVocabulary.OBJECTIVE:
        for name, objective in model.objectives.items():
            phrases[name] = _distinct(plain_words(name), objective.description)
    elif vocabulary is ModelVocabulary.ACTIVITY:
        for name, classes in model.activity_classes.items():
            ranked = sorted(classes.items(), key=lambda item: (-item[1], item[0]))
            needed = ", ".join(plain_words(c) for c, p in ranked if p >= NEEDED_CLASS)
            phrases[name] = _distinct(plain_words(name), f"{plain_words(name)}: {needed}" if needed else "")
    else:
        for name, model_class in model.classes.items():
            phrases[name] = _class_phrases(model_class)
    return MappingProxyType(phrases)


def _class_phrases(model_class: ModelClass) -> tuple[str, ...]:
    return _distinct(plain_words(model_class.name), *map(plain_words, model_class.types + model_class.kinds))


def _distinct(*phrases: str) -> tuple[str, ...]:
    return tuple(dict.fromkeys(p.strip() for p in phrases if p.strip()))


def match_text(
    text: str,
    model: KnowledgeModel,
    vocabulary: ModelVocabulary,
    rule: MatchRule | None = None,
    text_model: TextModel | None = None,
) -> WordMatch:
    """``text`` mapped to the nearest entry of ``vocabulary`` in ``model``.

    Loads the text model on first use unless the text spells an entry's name
    (:class:`~relevance_plan.errors.MissingExtraError` when it is not installed).
    """
    return match_texts([text], model, vocabulary, rule, text_model)[0]


def match_texts(
    texts: Sequence[str],
    model: KnowledgeModel,
    vocabulary: ModelVocabulary,
    rule: MatchRule | None = None,
    text_model: TextModel | None = None,
) -> tuple[WordMatch, ...]:
    """Each of ``texts`` mapped as :func:`match_text` does, embedded together."""
    rule = rule if rule is not None else DEFAULT_RULES[vocabulary]
    phrases = vocabulary_phrases(model, vocabulary)
    results: list[WordMatch | None] = [
        _spelled_entry(text, phrases, vocabulary, rule) or _named_entry(text, phrases, vocabulary, rule)
        for text in texts
    ]
    unspelled = [i for i, found in enumerate(results) if found is None]
    if unspelled:
        if not phrases:
            for i in unspelled:
                results[i] = WordMatch(texts[i], vocabulary, MatchStatus.BELOW_FLOOR, (), rule)
        else:
            encoder = text_model if text_model is not None else load_text_model()
            owners, table = _phrase_table(encoder, tuple((name, p) for name, group in phrases.items() for p in group))
            queries = encoder.embed([texts[i] for i in unspelled])
            for i, similarities in zip(unspelled, queries @ table.T):
                results[i] = _decide(texts[i], vocabulary, rule, owners, similarities)
    return tuple(found for found in results if found is not None)


def resolve_objective(text: str, model: KnowledgeModel, text_model: TextModel | None = None) -> WordMatch:
    """What the human wants, as one of the model's objectives (``--objective TEXT``)."""
    return match_text(text, model, ModelVocabulary.OBJECTIVE, text_model=text_model)


def resolve_activity(text: str, model: KnowledgeModel, text_model: TextModel | None = None) -> WordMatch:
    """A cue, as one of the model's activities (``--activity TEXT``, a ``cue`` event's text)."""
    return match_text(text, model, ModelVocabulary.ACTIVITY, text_model=text_model)


def place_kinds(
    kinds: Iterable[str], model: KnowledgeModel, text_model: TextModel | None = None
) -> tuple[WordMatch, ...]:
    """Each distinct object kind (``oat_milk_carton``), in order, as the model class it most resembles
    or a question."""
    kinds = list(dict.fromkeys(kinds))
    matches = match_texts([plain_words(kind) for kind in kinds], model, ModelVocabulary.CLASS, text_model=text_model)
    return tuple(dataclasses.replace(match, text=kind) for kind, match in zip(kinds, matches))


def with_placed_kinds(model: KnowledgeModel, matches: Iterable[WordMatch]) -> KnowledgeModel:
    """``model`` with each resolved kind listed under its class (a question leaves the model as it is).

    The kind gets its class's default kind relevance, as a kind the class does not weigh.
    """
    added: dict[str, list[str]] = {}
    for match in matches:
        if match.vocabulary is ModelVocabulary.CLASS and match.chosen is not None:
            added.setdefault(match.chosen, []).append(match.text.lower())
    if not added:
        return model
    classes = {
        name: dataclasses.replace(c, kinds=c.kinds + tuple(k for k in added[name] if k not in c.kinds))
        if name in added
        else c
        for name, c in model.classes.items()
    }
    return dataclasses.replace(model, classes=MappingProxyType(classes))


def _spelled_entry(
    text: str, phrases: Mapping[str, tuple[str, ...]], vocabulary: ModelVocabulary, rule: MatchRule
) -> WordMatch | None:
    """The entry ``text`` names outright (its name, or for a class a type or kind it lists)."""
    said = plain_words(text)
    for name, group in phrases.items():
        spelled = group if vocabulary is ModelVocabulary.CLASS else (plain_words(name),)
        if said in spelled:
            return WordMatch(text, vocabulary, MatchStatus.RESOLVED, (MatchCandidate(name, 1.0),), rule)
    return None


def names_one_entry(text: str) -> bool:
    """Whether ``text`` reads as a name rather than words: one token, no space."""
    return len(text.split()) == 1


def _named_entry(
    text: str, phrases: Mapping[str, tuple[str, ...]], vocabulary: ModelVocabulary, rule: MatchRule
) -> WordMatch | None:
    """For a one-token text of a named vocabulary (spelling no entry): the names it nearly spells (a
    question), or none (a name the model does not have); None for words, and for object kinds."""
    if vocabulary.value not in NAMED_VOCABULARIES or not names_one_entry(text):
        return None
    ranked = sorted(((name_similarity(text, name), name) for name in phrases), key=lambda item: (-item[0], item[1]))
    near = tuple(MatchCandidate(name, similarity) for similarity, name in ranked if _slips_apart(text, name))
    if near:
        return WordMatch(text, vocabulary, MatchStatus.NEAR_NAME, near[:SHOWN_CANDIDATES], rule)
    nearest = tuple(MatchCandidate(name, similarity) for similarity, name in ranked[:SHOWN_CANDIDATES])
    return WordMatch(text, vocabulary, MatchStatus.UNKNOWN_NAME, nearest, rule)


def _spelling(name: str) -> str:
    return plain_words(name).replace(" ", "-")


def name_similarity(text: str, name: str) -> float:
    """1 less the edits between two spellings (case, '-' and '_' aside) per letter of the longer."""
    a, b = _spelling(text), _spelling(name)
    return 1.0 - _edits(a, b) / max(len(a), len(b), 1)


def _slips_apart(text: str, name: str) -> bool:
    a, b = _spelling(text), _spelling(name)
    return _edits(a, b) <= max(1, int(TYPING_SLIPS * max(len(a), len(b))))


def _edits(a: str, b: str) -> int:
    """Insertions, deletions, substitutions and swaps of two neighbours turning ``a`` into ``b``."""
    previous2: list[int] = []
    previous = list(range(len(b) + 1))
    for i in range(1, len(a) + 1):
        current = [i] + [0] * len(b)
        for j in range(1, len(b) + 1):
            cost = 0 if a[i - 1] == b[j - 1] else 1
            current[j] = min(previous[j] + 1, current[j - 1] + 1, previous[j - 1] + cost)
            if i > 1 and j > 1 and a[i - 1] == b[j - 2] and a[i - 2] == b[j - 1]:
                current[j] = min(current[j], previous2[j - 2] + 1)
        previous2, previous = previous, current
    return previous[len(b)]


@functools.lru_cache(maxsize=16)
def _phrase_table(text_model: TextModel, entries: tuple[tuple[str, str], ...]) -> tuple[tuple[str, ...], FloatArray]:
    """The owners and unit vectors of a vocabulary's phrases: embedded once per text model and vocabulary
    (and kept on disk for the next run, see :mod:`relevance_plan.text.cache`)."""
    phrases = [phrase for _, phrase in entries]
    key = cache_key(text_model.fingerprint, phrases)
    table = read_cached(key, len(phrases), text_model.width)
    if table is None:
        table = text_model.embed(phrases)
        write_cached(key, table)
    table.setflags(write=False)
    return tuple(name for name, _ in entries), table


def _decide(
    text: str, vocabulary: ModelVocabulary, rule: MatchRule, owners: Sequence[str], similarities: FloatArray
) -> WordMatch:
    best: dict[str, float] = {}
    for name, similarity in zip(owners, similarities.tolist()):
        best[name] = max(best.get(name, -1.0), similarity)
    ranked = sorted(best.items(), key=lambda item: (-item[1], item[0]))
    candidates = tuple(MatchCandidate(name, similarity) for name, similarity in ranked[:SHOWN_CANDIDATES])
    nearest = candidates[0].similarity
    if nearest < rule.floor:
        status = MatchStatus.BELOW_FLOOR
    elif len(candidates) > 1 and nearest - candidates[1].similarity < rule.margin:
        status = MatchStatus.TOO_CLOSE
    else:
        status = MatchStatus.RESOLVED
    return WordMatch(text, vocabulary, status, candidates, rule)
