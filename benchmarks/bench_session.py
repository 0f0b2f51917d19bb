"""The live session at 1,000 objects: trigger check and incremental determination vs from scratch.

A coffee scene (problems/coffee-simple.pddl) is grown to 1,000 objects by
``add`` events, then 1,000 mixed events follow: moves among distractors,
moves onto kept objects (a plate put on a kept cup, and taken off again),
removals and additions of elements, and two goal changes.  After every mixed
event the same state is determined from scratch (the current scene written
as PDDL, read, scored with ``score_problem``, pruned) and compared with the
session's determination: kept, selected and restored sets and every score.

Targets: an untriggered event costs under 1 ms; an incremental
determination after one element event costs at most a tenth of determining
from scratch at 1,000 objects; identical results.  Everything is measured in
one run.  No planner is started.

Takes 1-2 minutes on 2 cores (the 1,000 determinations from scratch, 45-100 ms
each, are most of it).  Wall-clock times per event suffer first
when other jobs share the CPUs; the CPU-time line does not.

    python benchmarks/bench_session.py [--seed 0]
"""

from __future__ import annotations

import argparse
import os
import random
import statistics
import time
from dataclasses import dataclass

from base import Laps, percentile

from relevance_plan.data import DOMAINS_DIR, PROBLEMS_DIR
from relevance_plan.io import load_task
from relevance_plan.pddl.parser import read_problem
from relevance_plan.relevance.setup import ScoringOptions, score_problem
from relevance_plan.relevance.task import PlanningTask
from relevance_plan.session import Session

TARGET_OBJECTS = 1000
MIXED_EVENTS = 1000
# Mostly distractors, a few things a coffee drinker could use.
DISTRACTORS = [
    ("plate", "dinner_plate"),
    ("bowl", "cereal_bowl"),
    ("cookware", "frying_pan"),
    ("utensil", "ladle"),
    ("cutlery", "fork"),
    ("glassware", "wine_glass"),
    ("board", "cutting_board"),
    ("tray", "baking_tray"),
    ("jar", "pickle_jar"),
    ("linen", "tablecloth"),
    ("food", "bagel"),
    ("cleaning", "sponge"),
]
USEFUL = [
    ("cup", "paper_cup"),
    ("whitener", "oat_milk"),
    ("stirrer", "teaspoon"),
    ("napkin", "napkin"),
    ("sweetener", "sugar_packet"),
]


class Stream:
    def __init__(self, session: Session, rng: random.Random):
        self.session = session
        self.rng = rng
        self.count = 0
        self.places = ["kitchen_counter_1", "serving_table_1", "cabinet_1"]
        self.stacked: list[tuple[str, str]] = []  # (plate, kept item it was put on)
        self.goals = 0

    def add(self, useful_share: float = 0.05) -> dict:
        self.count += 1
        type_name, kind = self.rng.choice(USEFUL if self.rng.random() < useful_share else DISTRACTORS)
        name = f"{kind}_{1000 + self.count}"
        place = self.rng.choice(self.places)
        facts = [["at", name, place], ["on-base", name], ["clear", name]]
        if type_name == "cup":
            facts.append(["empty", name])
        return {"event": "add", "object": name, "type": type_name, "facts": facts}

    def distractors(self) -> list[str]:
        scene, kept = self.session.scene, self.session.kept
        return [
            n
            for n, t in scene.objects.items()
            if n not in kept
            and t not in ("surface", "container", "human")
            and any(f[0] == "at" for f in scene.index.facts_of(n, "at"))
        ]

    def mixed(self, done: int) -> list[dict]:
        """The next mixed event(s) after ``done`` events (a move is two: off the old place, onto the new)."""
        rng, scene = self.rng, self.session.scene
        for number, at in enumerate((MIXED_EVENTS // 3, 2 * MIXED_EVENTS // 3)):
            if done >= at and self.goals == number:
                self.goals += 1
                cups = sorted(n for n in self.session.kept if scene.objects[n] == "cup")
                goal = (
                    f"(and (coffee-served person_1) (stirred {cups[0]}))" if number == 0 else "(coffee-served person_1)"
                )
                return [{"event": "goal", "goal": goal}]
        roll = rng.random()
        if roll < 0.6:
            item = rng.choice(self.distractors())
            here = next(f[2] for f in scene.index.facts_of(item, "at") if f[1] == item)
            there = rng.choice([p for p in self.places if p != here])
            return [{"event": "unset", "fact": ["at", item, here]}, {"event": "set", "fact": ["at", item, there]}]
        if roll < 0.75:
            if self.stacked and rng.random() < 0.5:
                plate, below = self.stacked.pop()
                if plate in scene.objects and below in scene.objects:
                    return [{"event": "unset", "fact": ["on", plate, below]}]
            kept_items = sorted(n for n in self.session.kept if scene.objects[n] in ("cup", "whitener", "stirrer"))
            plate = rng.choice(self.distractors())
            below = rng.choice(kept_items)
            self.stacked.append((plate, below))
            return [{"event": "set", "fact": ["on", plate, below]}]
        if roll < 0.88:
            return [{"event": "remove", "object": rng.choice(self.distractors())}]
        return [self.add()]


def from_scratch(session: Session):
    text = session.scene.problem_text()
    laps = Laps()
    problem = read_problem(text, session.domain)
    scoring = score_problem(PlanningTask(session.domain, problem), session.options, knowledge_model=session.model)
    result = scoring.prune(session.options.thresholds), scoring.first_selection()
    return laps.end()["total"], scoring.scores, result


def same(session: Session, scores, result) -> bool:
    current = session.current_scores()
    if current.sufficient != scores.sufficient:
        return False
    if not scores.sufficient:
        return current.insufficiency == scores.insufficiency
    relevance, first = result
    determination = session.determination
    return (
        current.element_scores == scores.element_scores
        and current.class_scores == scores.class_scores
        and determination.kept == relevance.kept
        and determination.selected == relevance.selected
        and {r.name for r in determination.restored} == {r.name for r in relevance.restored}
        and session.kept == first.kept
    )


def parse_args(argv: list[str] | None = None) -> argparse.Namespace:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--seed", type=int, default=0, help="seed of the event stream (default: 0)")
    return parser.parse_args(argv)


@dataclass(frozen=True)
class Event:
    """One mixed event: its kind, whether it triggered, the session's and the from-scratch seconds."""

    kind: str
    triggered: bool
    incremental: float
    scratch: float
    same: bool
    cpu: float  # the session's CPU seconds for it


def grow(session: Session, stream: Stream) -> tuple[int, float]:
    """Add events until the scene has ``TARGET_OBJECTS`` objects: (events, seconds)."""
    laps = Laps()
    grown = 0
    while len(session.scene.objects) < TARGET_OBJECTS:
        session.handle(stream.add())
        grown += 1
    return grown, laps.end()["total"]


def mixed_events(session: Session, stream: Stream) -> list[Event]:
    """``MIXED_EVENTS`` mixed events, each state determined from scratch too."""
    events: list[Event] = []
    while len(events) < MIXED_EVENTS:
        for event in stream.mixed(len(events)):
            cpu = time.process_time()
            report = session.handle(event)
            cpu = time.process_time() - cpu
            assert report.error is None, (event, report.error)
            scratch_time, scores, result = from_scratch(session)
            events.append(
                Event(
                    event["event"], report.triggered, report.seconds, scratch_time, same(session, scores, result), cpu
                )
            )
    return events[:MIXED_EVENTS]


def ms(seconds: float) -> str:
    return f"{seconds * 1000:7.3f} ms"


def line(label: str, values: list[float]) -> None:
    print(f"{label:<34}{ms(statistics.median(values))} {ms(percentile(values, 0.95))} {ms(max(values))}")


def print_times(events: list[Event]) -> None:
    triggered = [e for e in events if e.triggered]
    untriggered = [e for e in events if not e.triggered]
    element = [e for e in triggered if e.kind in ("add", "remove")]
    print("")
    print(f"{'':34}{'median':>10} {'p95':>10} {'max':>10}")
    line(f"untriggered events ({len(untriggered)})", [e.incremental for e in untriggered])
    line(f"triggered, incremental ({len(triggered)})", [e.incremental for e in triggered])
    line("triggered, from scratch", [e.scratch for e in triggered])
    line(f"element events, incremental ({len(element)})", [e.incremental for e in element])
    line("element events, from scratch", [e.scratch for e in element])
    line("all events, from scratch", [e.scratch for e in events])
    ratio_median = statistics.median(e.incremental for e in element) / statistics.median(e.scratch for e in element)
    ratio_p95 = percentile([e.incremental for e in element], 0.95) / percentile([e.scratch for e in element], 0.95)
    print("")
    quick = [e.incremental for e in untriggered]
    print(
        f"untriggered under 1 ms: {sum(t < 0.001 for t in quick)} of {len(untriggered)}"
        f" (p95 {ms(percentile(quick, 0.95)).strip()}, max {ms(max(quick)).strip()})"
        f"  target: every one under 1 ms"
    )
    print(
        f"element event, incremental / from scratch: {ratio_median:.3f} (median), {ratio_p95:.3f} (p95)  target: <= 0.1"
    )
    cpu = [e.cpu for e in untriggered]
    print(
        "untriggered, CPU time of the process (no preemption):"
        f" median {ms(statistics.median(cpu)).strip()},"
        f" p95 {ms(percentile(cpu, 0.95)).strip()}, max {ms(max(cpu)).strip()};"
        f" load average {os.getloadavg()[0]:.2f} on {os.cpu_count()} CPUs"
    )


def main(argv: list[str] | None = None) -> None:
    args = parse_args(argv)
    rng = random.Random(args.seed)
    domain_path = DOMAINS_DIR / "coffee" / "domain.pddl"
    domain, problem = load_task(domain_path, PROBLEMS_DIR / "coffee-simple.pddl")
    session = Session(domain, problem, ScoringOptions(), domain_path=str(domain_path))
    stream = Stream(session, rng)
    grown, grow_time = grow(session, stream)
    events = mixed_events(session, stream)
    triggered = sum(e.triggered for e in events)
    print(
        f"grew the scene from {len(problem.objects)} to {TARGET_OBJECTS} objects with {grown} add events"
        f" in {grow_time:.2f} s ({grown / grow_time:,.0f} events/s)"
    )
    handled = sum(e.incremental for e in events)
    print(
        f"mixed events: {len(events)} at {len(session.scene.objects)} objects at the end; kept {len(session.kept)};"
        f" {handled:.3f} s in the session = {len(events) / handled:,.0f} events/s"
    )
    kinds = sorted({e.kind for e in events})
    print(
        "events by kind: "
        + ", ".join(
            f"{k} {sum(e.kind == k for e in events)} ({sum(e.kind == k and e.triggered for e in events)} triggered)"
            for k in kinds
        )
    )
    print(f"triggered: {triggered} of {len(events)} ({triggered / len(events):.1%})")
    print_times(events)
    print(f"identical to from scratch: {sum(e.same for e in events)} of {len(events)} states")


if __name__ == "__main__":
    main()
