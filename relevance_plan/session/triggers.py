"""The trigger check (Section III of the paper): when must relevance be determined again?

Each trigger is a small named rule in :data:`TRIGGERS`: it looks at a
:class:`Change` (the event and what it did to the scene) and returns a
one-line reason, or None.  Relevance is determined again when any rule
fires.  While the session is idle (nobody to serve: no goal and no human),
element and fact events fire nothing.

A fact change among objects that stay irrelevant fires nothing, and that is
safe: such a change cannot alter the relevant set (no score crossed a
threshold) nor the first selection (closure follows a fact only from a
watched object in a rule's position, the rules did not change, and nothing
else the selection read changed: ``reuse.selection_read``), so the selection
in force is still the one a determination from scratch would give.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from relevance_plan.session.events import Event


@dataclass(frozen=True)
class Change:
    event: Event
    idle: bool  # nobody to serve: element and fact events fire nothing
    changed: bool  # the event changed the scene, goal, human or cues
    touched: frozenset  # objects the event names (fact arguments, the object added or removed)
    kept: frozenset  # watched before the event: the first selection's kept set and its closure
    linked: frozenset  # watched objects from which closure follows the changed fact
    crossed: frozenset  # elements whose score crossed the thresholds, either way
    rules_changed: bool  # the inferred closure rules (functional / single-valued predicates) changed
    read: str = ""  # what else the event changed that the first selection read ("" when nothing)
    show: Callable[[str], str] = str  # the user's spelling of a name


def _names(change: Change, names) -> str:
    shown = sorted(change.show(n) for n in names)
    return ", ".join(shown[:5]) + (f" and {len(shown) - 5} more" if len(shown) > 5 else "")


def element_added(change: Change) -> str | None:
    if change.event.kind == "add" and not change.idle:
        return f"element added: {change.event.display}"
    return None


def element_removed(change: Change) -> str | None:
    if change.event.kind == "remove" and not change.idle:
        return f"element removed: {change.event.display}"
    return None


def goal_changed(change: Change) -> str | None:
    if change.event.kind == "goal" and change.changed:
        return "goal changed"
    return None


def human_changed(change: Change) -> str | None:
    event = change.event
    if event.kind == "human" and change.changed:
        profile = f"recorded preferences '{event.profile}'" if event.profile else "no recorded preferences"
        return f"human changed: {event.display} ({profile})"
    return None


def cue_received(change: Change) -> str | None:
    event = change.event
    if event.kind == "cue" and change.changed:
        return f"cue: activity {event.activity}" if event.activity else f"cue: objective {event.objective}"
    return None


def kept_touched(change: Change) -> str | None:
    """A fact about a kept object (its first argument: the cup was filled, the fridge opened),
    or a closure link from one (a plate put on the kept cup).  A distractor put down on a
    kept table is neither: closure does not follow a table to what stands on it."""
    event = change.event
    if event.kind in ("set", "unset") and change.changed and not change.idle:
        fact = event.facts[0] if event.facts else event.fluent
        assert fact is not None  # a set event carries a fact or a fluent
        if len(fact) > 1 and fact[1] in change.kept:
            what = "value" if event.fluent is not None else "fact"
            return f"{what} {event.kind} on kept {change.show(fact[1])}"
        if change.linked:
            return f"closure link {event.kind} from kept {_names(change, change.linked)}"
    return None


def relevance_crossed(change: Change) -> str | None:
    if change.event.kind in ("set", "unset") and change.crossed and not change.idle:
        return f"relevance crossed the thresholds: {_names(change, change.crossed)}"
    return None


def closure_rules_changed(change: Change) -> str | None:
    if change.event.kind in ("set", "unset") and change.rules_changed and not change.idle:
        return "closure rules changed (a predicate stopped or started being functional or single-valued)"
    return None


def selection_read(change: Change) -> str | None:
    """A fact the first selection read besides closure's (the reachability repair explored the
    object, a link its rankings follow, a static fact): see ``reuse.selection_read``."""
    if change.event.kind in ("set", "unset") and change.read and not change.idle:
        return f"selection read: {change.read}"
    return None


Trigger = Callable[[Change], "str | None"]

TRIGGERS: dict[str, Trigger] = {
    "element-added": element_added,
    "element-removed": element_removed,
    "goal-changed": goal_changed,
    "human-changed": human_changed,
    "cue-received": cue_received,
    "kept-touched": kept_touched,
    "relevance-crossed": relevance_crossed,
    "closure-rules-changed": closure_rules_changed,
    "selection-read": selection_read,
}


def check_triggers(change: Change, triggers: dict[str, Trigger] = TRIGGERS) -> tuple[str, ...]:
    """The reasons of every trigger that fires ("name: reason")."""
    return tuple(reason for reason in (rule(change) for rule in triggers.values()) if reason)
