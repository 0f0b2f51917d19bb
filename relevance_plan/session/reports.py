"""What the session says about each event: :class:`EventReport` (``watch`` prints its JSON),
:class:`Ask` (the question for the human) and :class:`PlanReport` (a plan kept current)."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from relevance_plan.pddl.model import UNSPELLED, Spelling
from relevance_plan.pddl.plans import Plan, format_plan_step
from relevance_plan.planning.results import PlanResult, PlanStatus
from relevance_plan.relevance.selection.prune import Selection

if TYPE_CHECKING:  # the text package is imported only when free text is given
    from relevance_plan.relevance.scoring.word_matching import WordMatch


@dataclass(frozen=True)
class Ask:
    """What to ask the human: the missing cue, the question, the choices."""

    cue: str  # "objective", "activity", "model" (insufficient cues) or "preference" (which kind)
    question: str
    options: tuple = ()


@dataclass(frozen=True)
class PlanReport:
    status: PlanStatus
    steps: Plan = Plan()
    source: str = "planner"  # "planner" or "previous" (still valid: the planner was not called)
    message: str = ""
    result: PlanResult | None = None


@dataclass(frozen=True)
class EventReport:
    seq: int
    event: str
    triggered: bool = False
    reasons: tuple = ()
    error: str | None = None
    sufficient: bool = True
    insufficiency: str = ""
    stale: bool = False  # the selection in force predates insufficient cues
    selection: Selection | None = None  # the first selection in force (after the event), as ``prune`` writes it
    relevant_objects: frozenset = frozenset()  # the paper's relevant set in force (names; see Session.relevant)
    added: tuple = ()  # kept now, not before (names)
    dropped: tuple = ()
    ask: Ask | None = None
    seconds: float = 0.0  # trigger check + determination
    made: bool | None = None  # when triggered: whether the first selection was made again (or the one in force held)
    plan: PlanReport | None = None
    spelling: Spelling = field(default=UNSPELLED, repr=False)  # the user's spelling of the names shown
    understood: tuple[WordMatch, ...] = ()  # free text (a cue in words, --objective TEXT) and what it was taken for

    @property
    def reason(self) -> str:
        return "; ".join(self.reasons)

    def show(self, name: str) -> str:
        """An object's name in the user's spelling (a name that left the scene as given)."""
        return self.spelling.object(name)

    @property
    def kept(self) -> list[str]:
        """The objects the selection in force keeps, in the user's spelling, sorted."""
        return sorted(self.show(n) for n in (self.selection.kept if self.selection is not None else ()))

    @property
    def relevant(self) -> list[str]:
        """The paper's relevant set in force (above the thresholds, before the goal filter), in the
        user's spelling, sorted: every kept object is in it or was put back (``selection.restored``)."""
        return sorted(self.show(n) for n in self.relevant_objects)

    @property
    def removed(self) -> int | None:
        """How many objects the selection in force leaves out (None: no selection yet)."""
        if self.selection is None:
            return None
        objects = self.selection.task.problem.objects
        return len(objects) - sum(1 for name in self.selection.kept if name in objects)

    def to_json(self) -> dict[str, Any]:
        """The event's report as ``watch`` prints it (names in the user's spelling)."""
        data: dict[str, Any] = {
            "seq": self.seq,
            "event": self.event,
            "triggered": self.triggered,
            "reason": self.reason,
            "sufficient": self.sufficient,
            "stale": self.stale,
        }
        if self.error is not None:
            data["error"] = self.error
        if not self.sufficient:
            data["insufficiency"] = self.insufficiency
        if self.triggered:
            data["kept"] = self.kept
            data["relevant"] = self.relevant
            restored = self.selection.restored if self.selection is not None else ()
            data["restored"] = [{"object": self.show(r.name), "reason": r.describe(self.spelling)} for r in restored]
            data["removed"] = self.removed
            if self.made is not None:
                data["selection"] = "made" if self.made else "kept"
        data["added"] = [self.show(n) for n in self.added]
        data["dropped"] = [self.show(n) for n in self.dropped]
        ask = self.ask
        data["ask"] = None if ask is None else {"cue": ask.cue, "question": ask.question, "options": list(ask.options)}
        if self.understood:
            data["understood"] = [match.as_json() for match in self.understood]
        data["determination_ms"] = round(self.seconds * 1000, 3)
        if self.plan is not None:
            data["plan_status"] = self.plan.status.value
            data["plan"] = [format_plan_step(step, self.spelling) for step in self.plan.steps]
            data["plan_source"] = self.plan.source
            data["plan_message"] = self.plan.message
        return data
