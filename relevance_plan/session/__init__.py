"""Event-based relevance: a live scene session (see ``session.py``)."""

from relevance_plan.session.events import EVENT_KINDS, Event, EventError
from relevance_plan.session.session import Ask, EventReport, PlanReport, Session
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
