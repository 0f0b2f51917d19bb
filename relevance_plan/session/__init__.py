"""Event-based relevance: a live scene session.

- ``session``: :class:`Session`, events in, the determination kept current, plans kept valid:
  a thin front over its three collaborators,
- ``updates``: applying events (the scene, the options they set, the scores, what passes the thresholds),
- ``determination``: determining relevance (the selection in force, what it read, what to ask),
- ``planning``: planning the current state with the one attempt loop;
- ``events``: one event, checked against the current scene;
- ``state``: the live scene (objects, facts, goal) and its index;
- ``triggers``: when relevance must be determined again;
- ``rescoring``: the scores kept current event by event;
- ``reuse``: what the first selection read, and whether an event changed any of it;
- ``reports``: what the session says of each event (``watch``'s JSON lines).
"""

from relevance_plan.session.events import EVENT_KINDS, Event, EventError
from relevance_plan.session.reports import Ask, EventReport, PlanReport
from relevance_plan.session.session import Session
from relevance_plan.session.triggers import TRIGGERS, Change

__all__ = [
    "EVENT_KINDS",
    "TRIGGERS",
    "Ask",
    "Change",
    "Event",
    "EventError",
    "EventReport",
    "PlanReport",
    "Session",
]
