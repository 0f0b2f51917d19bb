"""Events: one JSON object each, checked against the current scene before anything changes.

    {"event": "add", "object": NAME, "type": TYPE, "facts": [[PRED, ARG, ...], ...]}
    {"event": "remove", "object": NAME}
    {"event": "set", "fact": [PRED, ARG, ...]}      {"event": "unset", "fact": [...]}
    {"event": "set", "fluent": [FUNCTION, ARG, ...], "value": NUMBER}   (a numeric fluent's new value)
    {"event": "goal", "goal": "(and ...)"}
    {"event": "human", "name": NAME, "preferences": PROFILE}   (PROFILE may be null: none recorded)
    {"event": "cue", "activity": NAME}   or   {"event": "cue", "objective": NAME}   or   {"event": "cue", "text": WORDS}
    ("task" for "activity": its name until 0.12, read for one more release)
    {"event": "plan"}

Extra fields are allowed and ignored.  A malformed or impossible event
raises :class:`EventError` with a one-line reason; the session stays as it was.
Every limit on a line (its size, its nesting, an integer's digits, a name's
length, a cue's words) is a constant here, but the goal's nesting (the PDDL
reader's); docs/live-session.md lists them all.
Nothing an event brings in can change the PDDL around it: a new object's
name must be a PDDL name (a letter, then letters, digits, ``-`` and ``_``),
every other name must already be in the scene, and a goal must be exactly
one balanced list.
"""

from __future__ import annotations

import json
import math
import re
from collections.abc import Callable, Mapping
from collections.abc import Set as AbstractSet
from dataclasses import dataclass
from typing import TYPE_CHECKING

from relevance_plan.errors import MAX_MESSAGE, RelevancePlanError, printable
from relevance_plan.pddl.formulas import Formula, names_in
from relevance_plan.pddl.parser import read_problem
from relevance_plan.pddl.sexpr import parse_sexpr
from relevance_plan.relevance.scoring.knowledge import KnowledgeModel
from relevance_plan.session.state import LiveScene

if TYPE_CHECKING:  # the text package is imported only for a cue in words
    from relevance_plan.relevance.scoring.word_matching import WordMatch

EVENT_KINDS = ("add", "remove", "set", "unset", "goal", "human", "cue", "plan")
# An event line holds at most this many bytes of UTF-8, its line ending not counted; a longer one is
# refused and the stream carries on.  Room for what perception attaches in fields the session ignores
# (a 1080p camera frame, raw, is about 8.3 MB in base64), while a line read, decoded and parsed takes
# about three times its size in memory (up to ten with characters past U+FFFF: about 150 MB).
MAX_EVENT_BYTES = 16 << 20
# JSON objects and lists nested deeper than this are refused (an event needs three levels: the event,
# its facts, a fact), well before the parser's own recursion limit (about 1,000 levels, fewer when the
# session is called from deep in a program).
MAX_EVENT_NESTING = 100
# A JSON integer of more digits is refused: Python's default limit, held whatever PYTHONINTMAXSTRDIGITS
# says (reading a longer one takes time quadratic in its length).
MAX_INTEGER_DIGITS = 4300
# A cue in words holds at most this many characters: the text model reads its first 256 word pieces
# (a thousand characters or so), and the words are split before that cut.
MAX_CUE_CHARACTERS = 10_000
# A PDDL name: a letter, then letters, digits, '-' and '_' (of any script).
_PDDL_NAME = re.compile(r"[^\W\d_][\w-]*")
MAX_NAME_LENGTH = 1000
# A fluent's value beyond this is a typo, and planners read it as a float anyway.
MAX_VALUE = 1e15


class EventError(RelevancePlanError):
    """An event the session rejects (bad JSON, unknown object, wrong arity, ...)."""

    def __init__(self, message: str, **where):
        # Messages quote the event: one visible line of bounded length, whatever it held.
        super().__init__(printable(message, MAX_MESSAGE), **where)


@dataclass(frozen=True)
class Event:
    """A checked event: names lower-cased, facts as tuples, the goal parsed."""

    kind: str
    name: str | None = None  # object of add/remove, human of 'human'
    display: str | None = None  # the user's spelling of ``name``
    type: str | None = None
    facts: tuple = ()  # add: its facts; set/unset: one fact
    fluent: tuple | None = None  # set of a numeric value: (function, args...)
    value: float | None = None  # ... and its new value
    goal: Formula | None = None
    profile: str | None = None  # human: the model's profile
    activity: str | None = None  # cue
    objective: str | None = None  # cue
    understood: WordMatch | None = None  # cue in words: what it was understood as (or the question)


def parse_event_line(line: str) -> dict:
    """One JSON line (its line ending included or not) -> a dict (raises EventError)."""
    if line_bytes(line) > MAX_EVENT_BYTES:
        raise EventError(f"an event line holds at most {MAX_EVENT_BYTES:,} bytes (16 MiB); this one holds more")
    try:
        data = json.loads(line, parse_int=_integer)
    except ValueError as error:
        raise EventError(f"not a JSON object: {error}") from None
    except RecursionError:
        data = None  # deeper than the parser goes: deeper than the limit
    if data is None or _nesting(data) > MAX_EVENT_NESTING:
        raise EventError(f"not an event: JSON nested more than {MAX_EVENT_NESTING} levels deep")
    if not isinstance(data, dict):
        raise EventError("an event must be a JSON object")
    return data


def line_bytes(line: str) -> int:
    """The bytes of UTF-8 ``line`` holds without its line ending (a byte that was not UTF-8, read as
    a lone surrogate, counts one)."""
    ending = 2 if line.endswith("\r\n") else 1 if line.endswith("\n") else 0
    if line.isascii():
        return len(line) - ending
    try:
        return len(line.encode("utf-8", "surrogateescape")) - ending
    except UnicodeEncodeError:  # a lone surrogate written as such (from Python, not read from bytes)
        return len(line.encode("utf-8", "surrogatepass")) - ending


def _integer(digits: str) -> int:
    if len(digits) > MAX_INTEGER_DIGITS + digits.startswith("-"):
        raise EventError(f"not an event: an integer of more than {MAX_INTEGER_DIGITS:,} digits")
    return int(digits)


def _nesting(data: object) -> int:
    """How deep JSON objects and lists nest in ``data`` (an object of scalars: 1), counted up to
    one past :data:`MAX_EVENT_NESTING`."""
    deepest = 0
    stack = [(data, 1)]
    while stack and deepest <= MAX_EVENT_NESTING:
        value, depth = stack.pop()
        items = value.values() if isinstance(value, dict) else value if isinstance(value, list) else None
        if items is None:
            continue
        deepest = max(deepest, depth)
        stack.extend((item, depth + 1) for item in items if isinstance(item, (dict, list)))
    return deepest


def check_event(data: dict, scene: LiveScene, model: KnowledgeModel | None) -> Event:
    """Validate ``data`` against the current scene and model; nothing is changed."""
    kind = data.get("event")
    if kind not in EVENT_KINDS:
        raise EventError(f"unknown event {kind!r} (expected one of: {', '.join(EVENT_KINDS)})")
    return CHECKS[kind](data, scene, model)


def _check_add(data: dict, scene: LiveScene, model: KnowledgeModel | None) -> Event:
    display = check_name(_text(data, "object"), "object name")
    name = display.lower()
    if name in scene.objects or name in scene.domain.constants:
        raise EventError(f"object '{display}' is already in the scene")
    type_name = _text(data, "type").lower()
    if type_name not in scene.domain.types:
        raise EventError(f"unknown type '{data['type']}'")
    facts = data.get("facts", [])
    if not isinstance(facts, list):
        raise EventError("'facts' must be a list of facts")
    known = {name}
    checked = tuple(_fact(item, scene, known) for item in facts)
    return Event("add", name=name, display=display, type=type_name, facts=checked)


def _check_remove(data: dict, scene: LiveScene, model: KnowledgeModel | None) -> Event:
    display = _text(data, "object")
    name = _object(display, scene)
    if name in _goal_names(scene.goal):
        raise EventError(f"object '{display}' is named in the goal: change the goal first")
    return Event("remove", name=name, display=display)


def _check_fact(data: dict, scene: LiveScene, model: KnowledgeModel | None) -> Event:
    kind = data["event"]
    if kind == "set" and "fluent" in data:
        return Event("set", fluent=_fluent(data["fluent"], scene), value=_number(data.get("value")))
    if "fact" not in data:
        hint = " (a numeric fluent is set, never unset)" if "fluent" in data else ""
        raise EventError(f"'{kind}' needs a 'fact'{hint}")
    return Event(kind, facts=(_fact(data["fact"], scene),))


def _check_goal(data: dict, scene: LiveScene, model: KnowledgeModel | None) -> Event:
    return Event("goal", goal=parse_goal(_text(data, "goal"), scene))


def _check_human(data: dict, scene: LiveScene, model: KnowledgeModel | None) -> Event:
    display = _text(data, "name")
    name = _object(display, scene)
    profile = data.get("preferences")
    if profile is not None:
        if not isinstance(profile, str):
            raise EventError("'preferences' must be a profile name or null")
        if model is None or profile not in model.humans:
            profiles = ", ".join(model.humans) if model is not None and model.humans else "none"
            raise EventError(f"unknown preference profile '{profile}' (the model has: {profiles})")
    return Event("human", name=name, display=display, profile=profile)


def _check_cue(data: dict, scene: LiveScene, model: KnowledgeModel | None) -> Event:
    """A cue names the model's activity or objective, or gives the human's words (one field per way)."""
    if "task" in data and "activity" in data:
        raise EventError("give 'activity' only ('task' is its name until 0.12)")
    activity, objective, text = data.get("activity", data.get("task")), data.get("objective"), data.get("text")
    if sum(value is not None for value in (activity, objective, text)) != 1:
        raise EventError("a cue gives either 'activity' or 'objective', or 'text' (the human's words)")
    if model is None:
        raise EventError("cues need a knowledge model (this session has none)")
    if text is not None:
        words = _text(data, "text")
        if len(words) > MAX_CUE_CHARACTERS:
            raise EventError(
                f"a cue's 'text' holds at most {MAX_CUE_CHARACTERS:,} characters (the text model reads the first"
                f" thousand or so); this one holds {len(words):,}"
            )
        return _understood_cue(words, model)
    if activity is not None and (not isinstance(activity, str) or activity not in model.activity_classes):
        raise EventError(f"unknown activity {activity!r} (the model has: {', '.join(model.activity_classes)})")
    if objective is not None and (not isinstance(objective, str) or objective not in model.objectives):
        raise EventError(f"unknown objective {objective!r} (the model has: {', '.join(model.objectives)})")
    return Event("cue", activity=activity, objective=objective)


def _understood_cue(text: str, model: KnowledgeModel) -> Event:
    """A cue in words, as the model's nearest activity, else its nearest objective, else a question
    (``understanding.understand_cue``); one token that names nothing of the model is refused."""
    from relevance_plan.errors import MissingExtraError, ModelError
    from relevance_plan.relevance.scoring.word_matching import ModelVocabulary
    from relevance_plan.relevance.scoring.word_understanding import understand_cue

    try:
        match = understand_cue(text, model)
    except MissingExtraError as error:
        raise EventError(f"a cue in words needs the 'text' extra: {error.message}") from None
    except ModelError as error:
        raise EventError(error.message) from None
    if match.chosen is None:
        return Event("cue", understood=match)
    if match.vocabulary is ModelVocabulary.ACTIVITY:
        return Event("cue", activity=match.chosen, understood=match)
    return Event("cue", objective=match.chosen, understood=match)


def _check_plan(data: dict, scene: LiveScene, model: KnowledgeModel | None) -> Event:
    return Event("plan")


# One check per kind of event: a new kind is a new entry (and its handling in the session).
CHECKS: dict[str, Callable[[dict, LiveScene, KnowledgeModel | None], Event]] = {
    "add": _check_add,
    "remove": _check_remove,
    "set": _check_fact,
    "unset": _check_fact,
    "goal": _check_goal,
    "human": _check_human,
    "cue": _check_cue,
    "plan": _check_plan,
}


def check_name(text: str, what: str) -> str:
    """``text`` if it is a PDDL name, else ``EventError`` (it would change the PDDL around it)."""
    if len(text) > MAX_NAME_LENGTH or not _PDDL_NAME.fullmatch(text):
        raise EventError(
            f"{what} '{printable(text, 80)}' is not a PDDL name (a letter, then letters, digits, '-' or '_')"
        )
    return text


def _text(data: dict, key: str) -> str:
    value = data.get(key)
    if not isinstance(value, str) or not value.strip():
        raise EventError(f"'{data.get('event')}' needs '{key}' (a non-empty string)")
    return value.strip()


def _object(display: str, scene: LiveScene) -> str:
    name = display.lower()
    if name not in scene.objects:
        raise EventError(f"unknown object '{display}'")
    return name


def _fact(item, scene: LiveScene, extra: AbstractSet[str] = frozenset()) -> tuple:
    return _ground(item, scene, "fact", "predicate", scene.domain.predicates, extra)


def _fluent(item, scene: LiveScene) -> tuple:
    return _ground(item, scene, "fluent", "function", scene.domain.functions, frozenset())


_SHOWN = {"predicate": "PRED", "function": "FUNCTION"}


def _ground(
    item, scene: LiveScene, what: str, head: str, declared: Mapping[str, tuple], extra: AbstractSet[str]
) -> tuple:
    """``[NAME, ARG, ...]`` of a fact or a fluent: a declared name with as many known objects as it takes."""
    if not isinstance(item, list) or not item or not all(isinstance(part, str) for part in item):
        raise EventError(f"a {what} is a list of names [{_SHOWN[head]}, ARG, ...], got {json.dumps(item)}")
    name = item[0].lower()
    parameters = declared.get(name)
    if parameters is None:
        raise EventError(f"unknown {head} '{item[0]}'")
    if len(parameters) != len(item) - 1:
        raise EventError(f"{head} '{item[0]}' takes {len(parameters)} arguments, got {len(item) - 1}")
    args = tuple(arg.lower() for arg in item[1:])
    for arg, shown in zip(args, item[1:]):
        if arg not in scene.objects and arg not in scene.domain.constants and arg not in extra:
            raise EventError(f"unknown object '{shown}' in ({' '.join(item)})")
    return (name,) + args


def _number(value) -> float:
    """A fluent's value: a finite JSON number (not a boolean, not a string)."""
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise EventError(f"'value' must be a finite number, got {json.dumps(value)[:80]}")
    if abs(value) > MAX_VALUE:
        raise EventError(f"'value' must be at most {MAX_VALUE:g} in size, got {json.dumps(value)[:80]}")
    return float(value)


_SYMBOL = re.compile(r"[^\s()]+")


def parse_goal(text: str, scene: LiveScene) -> Formula:
    """Parse a goal condition over the scene's objects with the problem reader itself."""
    try:
        parse_sexpr(text)  # exactly one balanced list, nothing after it
    except RelevancePlanError as error:
        raise EventError(f"goal does not parse: {error.message}") from None
    mentioned = {symbol.lower() for symbol in _SYMBOL.findall(text)} & scene.objects.keys()
    objects = " ".join(f"{name} - {scene.objects[name]}" for name in sorted(mentioned))
    wrapper = f"(define (problem goal) (:domain {scene.domain.name}) (:objects {objects}) (:init) (:goal {text}))"
    try:
        return read_problem(wrapper, scene.domain).goal
    except RelevancePlanError as error:
        raise EventError(f"goal does not parse: {error.message}") from None


def _goal_names(goal: Formula) -> set:
    return set(names_in(goal))
