"""The live session's speed: per event at building scale (scene graphs), and on the coffee scene.

Scene graphs (``scenegraph``): for each size, a scene from ``relevance-plan
generate scenegraph --size N`` is read from its file and a session started on
it (timed: what ``watch`` does before the first event), then ``--changes``
seeded changes (``generators.scenegraph.SceneGraphEvents``) in this mix, in a
seeded order, out of 100: 40 items the goal does not name moved (two events each: out of one
receptacle, into another), 20 receptacles and doors not kept opened or
closed, 10 relevant fact changes (a kept receptacle or door, a goal item),
15 items added, 10 removed, 3 new goals and 2 plan requests (when Fast
Downward is installed).  Each size runs in a process of its own, so its peak
memory is the session's (read before the checks).  Every ``--check-every``
changes, the state is written out and determined from scratch as ``prune``
would (read, score, prune): timed, and compared with the session's report
(kept, relevant, restored with reasons, removed).  Printed per size: the
latency per event by kind (median, p95, max, and how often the first
selection was made again rather than kept), the issue's figures over fact
changes and additions, the load, the peak memory and the checks.

Targets at 50,000 objects: fact changes and additions median <= 20 ms and
p95 <= 100 ms; a goal change <= 1 s; peak memory <= 500 MB; every check
identical.  At 2,000 objects nothing slower than the session before.

Move orders (``orders``): one scene (10,000 objects by default) and one
session, ``--moves`` moves of items the goal does not name, every other one
reported as "unset the old receptacle, then set the new" and the others as
"set the new, then unset the old" (``SceneGraphEvents(new_place_first=...)``),
so both orders share the machine's load.  Printed: the latency per event of
each order (median, p95, max, how many triggered), the ratios of the new-place-first
order's to the old-place-first order's, and, every ``--check-every`` moves, whether
the report after the pair is what a determination from scratch says.  Target:
ratios near 1 (before the fix, about 160 at 10,000 objects), every check identical.

Loading (``load``): ``relevance-plan watch`` on a generated scene (100,000
objects by default) with ten item moves, under ``/usr/bin/time -v`` when
present: wall time and peak memory of the whole command.

The coffee scene (``coffee``): coffee-simple grown to 1,000 objects by
``add`` events, then 1,000 mixed events (moves among distractors, plates
put on kept objects and taken off, removals, additions, two goal changes),
every state determined from scratch too.  Targets: an untriggered event
under 1 ms; an element event at most a tenth of determining from scratch;
identical results.

Wall-clock times suffer first when other jobs share the CPUs.  ``scenegraph``
takes about 5 minutes at the default sizes (most of it the determinations from
scratch at 50,000 objects), ``load`` about 10 seconds, ``coffee`` 1-2 minutes.

    python benchmarks/bench_session.py scenegraph [--sizes 2000 10000 50000] [--changes 200] [--check-every 20]
    python benchmarks/bench_session.py orders [--size 10000] [--moves 200] [--check-every 20]
    python benchmarks/bench_session.py load [--size 100000]
    python benchmarks/bench_session.py coffee [--seed 0]
"""

from __future__ import annotations

import argparse
import json
import os
import random
import resource
import shutil
import statistics
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

from base import REPO, Laps, percentile, progress, run_timed, table_header, table_row

from relevance_plan.data import DOMAINS_DIR, PROBLEMS_DIR
from relevance_plan.generators import WORLDS, Settings
from relevance_plan.generators.scenegraph import SceneGraphEvents
from relevance_plan.io import load_task
from relevance_plan.pddl.formulas import literals
from relevance_plan.pddl.parser import read_problem
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.setup import ScoringOptions, score_problem
from relevance_plan.session import EventReport, Session

SCENEGRAPH_DOMAIN = DOMAINS_DIR / "scenegraph" / "domain.pddl"
# (label, kind of change, chosen among the kept objects or outside them): out of 100 changes
SCENE_MIX = (
    [("fact changes, irrelevant", "move", None)] * 40
    + [("fact changes, irrelevant", "receptacle", False)] * 10
    + [("fact changes, irrelevant", "door", False)] * 10
    + [("fact changes, relevant", "receptacle", True)] * 4
    + [("fact changes, relevant", "door", True)] * 4
    + [("fact changes, relevant", "move-goal", None)] * 2
    + [("additions", "add", None)] * 15
    + [("removals", "remove", None)] * 10
    + [("goal changes", "goal", None)] * 3
    + [("plan requests", "plan", None)] * 2
)
LABELS = (
    "fact changes, irrelevant",
    "fact changes, relevant",
    "additions",
    "removals",
    "goal changes",
    "plan requests",
)


# --------------------------------------------------------------------------- scene graphs


def scene_session(size: int, seed: int, folder: Path, plans: bool) -> tuple[Session, SceneGraphEvents, dict]:
    """The scene's file written and read back, a session started on it (as ``watch`` does), timed."""
    problem_path = folder / "scene.pddl"
    problem_path.write_text(WORLDS["scenegraph"].problem(seed, 1, Settings(size=size)).pddl_text)
    laps = Laps()
    domain, problem = load_task(SCENEGRAPH_DOMAIN, problem_path)
    laps.lap("read")
    session = Session(domain, problem, ScoringOptions(), domain_path=str(SCENEGRAPH_DOMAIN))
    laps.lap("start")
    goal = [(atom.predicate, *atom.args) for atom, _ in literals(problem.goal)]
    stream = SceneGraphEvents(dict(problem.objects), problem.init, goal, random.Random(seed))
    if not plans:
        session.run_planner = None
    return session, stream, {"objects": len(problem.objects), **laps.end()}


def change_events(stream: SceneGraphEvents, session: Session, kind: str, kept: bool | None) -> list[dict]:
    """The events of one change; a toggle chosen among the kept objects (``kept``) or outside them."""
    if kept is None:
        return stream.make(kind)
    pool = stream.openable if kind == "receptacle" else set(stream.doors)
    return stream.make(kind, [name for name in pool if (name in session.kept) == kept] or pool)


def fresh_determination(session: Session, text: str) -> tuple[float, dict]:
    """Determining from scratch what the written state ``text`` keeps, as ``prune`` does: timed."""
    laps = Laps()
    problem = read_problem(text, session.domain)
    scoring = score_problem(PlanningTask(session.domain, problem), session.options)
    first, relevance = scoring.first_selection(), scoring.prune(session.options.thresholds)
    seconds = laps.end()["total"]
    shown = {
        "kept": sorted(problem.display(n) for n in first.kept),
        "relevant": sorted(problem.display(n) for n in relevance.selected),
        "restored": [{"object": problem.display(r.name), "reason": _reason(r, problem)} for r in first.restored],
        "removed": len(first.removed),
    }
    return seconds, shown


def _reason(restored, shown_by) -> str:
    """Why closure put an object back, in the spelling of ``shown_by`` (a problem or a report); an
    older checkout's ``reason``, which had none."""
    describe = getattr(restored, "describe", None)
    return describe(shown_by.spelling) if describe is not None else restored.reason


def shown_by(report: EventReport) -> dict:
    """What the report says is in force (``made``, ``removed``: what older sessions lack)."""
    selection = report.selection
    restored = selection.restored if selection is not None else ()
    removed = len(selection.removed) if selection is not None else None
    return {
        "kept": report.kept,
        "relevant": report.relevant,
        "restored": [{"object": report.show(r.name), "reason": _reason(r, report)} for r in restored],
        "removed": getattr(report, "removed", removed),
    }


def run_scene(size: int, changes: int, seed: int, check_every: int, plans: bool) -> dict:
    """One size: the session's latency per event, its peak memory, and the checks from scratch."""
    rng = random.Random(seed)
    with tempfile.TemporaryDirectory() as folder:
        session, stream, start = scene_session(size, seed, Path(folder), plans)
    events: list[tuple[str, float, bool, bool | None]] = []
    checks: list[tuple[str, dict]] = []
    mix = [entry for entry in SCENE_MIX if plans or entry[1] != "plan"]
    schedule = (mix * (changes // len(mix) + 1))[:changes]  # the mix's shares exactly, in a seeded order
    rng.shuffle(schedule)
    for number, (label, kind, kept) in enumerate(schedule):
        for event in change_events(stream, session, kind, kept):
            started = time.perf_counter()
            report = session.handle(event)
            events.append((label, time.perf_counter() - started, report.triggered, getattr(report, "made", None)))
            assert report.error is None, (event, report.error)
        if number % check_every == check_every - 1:
            checks.append((session.scene.problem_text(), shown_by(report)))
    memory = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    compared = []
    for text, shown in checks:
        seconds, fresh = fresh_determination(session, text)
        compared.append((seconds, fresh == shown))
    return {"size": size, "start": start, "events": events, "memory_mb": memory, "checks": compared}


def print_scene(result: dict) -> None:
    start, events = result["start"], result["events"]
    print(f"\n### {start['objects']:,} objects, {len(events)} events\n")
    print(
        f"load: read {start['read']:.2f} s + session start {start['start']:.2f} s;"
        f" peak memory {result['memory_mb']:.0f} MB"
    )
    table_header("events | count | median | p95 | max | selection made again")
    rows = [(label, [e for e in events if e[0] == label]) for label in LABELS]
    rows.append(("fact changes and additions", [e for e in events if e[0].startswith(("fact", "additions"))]))
    quiet = ("fact changes, irrelevant", "additions")
    rows.append(("the same, relevant fact changes left out", [e for e in events if e[0] in quiet]))
    for label, chosen in rows:
        if not chosen:
            continue
        times = [e[1] for e in chosen]
        made = sum(e[3] is True for e in chosen)
        table_row(
            label,
            len(chosen),
            millis(statistics.median(times)),
            millis(percentile(times, 0.95)),
            millis(max(times)),
            f"{made} of {sum(e[2] for e in chosen)} triggered",
        )
    checks = result["checks"]
    if checks:
        fresh = [seconds for seconds, _ in checks]
        print(
            f"\ndetermined from scratch at {len(checks)} states: median {millis(statistics.median(fresh))},"
            f" max {millis(max(fresh))}; identical to the session's report: {sum(same for _, same in checks)}"
            f" of {len(checks)}"
        )


def scenegraph(args: argparse.Namespace) -> None:
    """Each size in a process of its own (its peak memory is its own), printed as it finishes."""
    plans = args.plans and planner_installed()
    if args.plans and not plans:
        progress("Fast Downward is not installed: no plan requests")
    print(f"scene graphs, seed {args.seed}, {args.changes} changes each; load average {os.getloadavg()[0]:.2f}")
    for size in args.sizes:
        progress(f"{size:,} objects")
        command = [sys.executable, __file__, "one-scene", "--size", str(size), "--changes", str(args.changes)]
        command += ["--seed", str(args.seed), "--check-every", str(args.check_every)]
        command += [] if plans else ["--no-plans"]
        run = run_timed(command, cwd=REPO)
        if run.code != 0:
            print(f"\n### {size:,} objects: the run failed (exit {run.code})")
            continue
        print_scene(json.loads(run.stdout.splitlines()[-1]))


def planner_installed() -> bool:
    from relevance_plan.errors import RelevancePlanError
    from relevance_plan.planning.planners.registry import make_planner

    try:
        make_planner("fast-downward", check=True)
    except RelevancePlanError:
        return False
    return True


def one_scene(args: argparse.Namespace) -> None:
    print(json.dumps(run_scene(args.size, args.changes, args.seed, args.check_every, args.plans)))


ORDERS = ("old place first", "new place first")


def move_orders(args: argparse.Namespace) -> None:
    """Moves reported in either order on one session, alternating: each order's latency, their ratio."""
    with tempfile.TemporaryDirectory() as folder:
        session, stream, start = scene_session(args.size, args.seed, Path(folder), plans=False)
    times: dict[str, list[float]] = {order: [] for order in ORDERS}
    triggered = dict.fromkeys(ORDERS, 0)
    checks: list[bool] = []
    for number in range(args.moves):
        order = ORDERS[number % 2]
        stream.new_place_first = order == ORDERS[1]
        for event in stream.make("move"):
            started = time.perf_counter()
            report = session.handle(event)
            times[order].append(time.perf_counter() - started)
            triggered[order] += report.triggered
            assert report.error is None, (event, report.error)
        if number % args.check_every == args.check_every - 1:
            checks.append(fresh_determination(session, session.scene.problem_text())[1] == shown_by(report))
    print(
        f"move orders on {start['objects']:,} objects, seed {args.seed}: {args.moves} moves, {len(checks)} checks;"
        f" load average {os.getloadavg()[0]:.2f}"
    )
    table_header("order | events | median | p95 | max | triggered")
    for order in ORDERS:
        chosen = times[order]
        row = (millis(statistics.median(chosen)), millis(percentile(chosen, 0.95)), millis(max(chosen)))
        table_row(order, len(chosen), *row, triggered[order])
    first, second = (times[order] for order in ORDERS)
    print(
        f"\nnew place first / old place first: median {statistics.median(second) / statistics.median(first):.2f},"
        f" p95 {percentile(second, 0.95) / percentile(first, 0.95):.2f}, total {sum(second) / sum(first):.2f}"
    )
    print(f"reports after a move identical to a determination from scratch: {sum(checks)} of {len(checks)}")


def load(args: argparse.Namespace) -> None:
    """``watch`` on a generated scene with ten item moves: wall time and peak memory of the command."""
    with tempfile.TemporaryDirectory() as folder:
        problem_path = Path(folder) / "scene.pddl"
        problem_path.write_text(WORLDS["scenegraph"].problem(args.seed, 1, Settings(size=args.size)).pddl_text)
        domain, problem = load_task(SCENEGRAPH_DOMAIN, problem_path)
        goal = [(atom.predicate, *atom.args) for atom, _ in literals(problem.goal)]
        stream = SceneGraphEvents(dict(problem.objects), problem.init, goal, random.Random(args.seed))
        lines = [json.dumps(event) for _ in range(10) for event in stream.make("move")]
        del domain, problem, stream
        events = Path(folder) / "events.jsonl"
        events.write_text("\n".join(lines) + "\n")
        command = [sys.executable, "-m", "relevance_plan", "watch", str(SCENEGRAPH_DOMAIN), str(problem_path)]
        command += ["--events", str(events)]
        timer = shutil.which("time") or ("/usr/bin/time" if Path("/usr/bin/time").exists() else None)
        run = run_timed(([timer, "-v"] if timer else []) + command, cwd=REPO)
    peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024
    print(
        f"watch on {args.size:,} objects with {len(lines)} events: exit {run.code}, wall {run.seconds:.2f} s,"
        f" peak memory {peak:.0f} MB" + (" (/usr/bin/time -v)" if timer else "")
    )


def millis(seconds: float) -> str:
    return f"{seconds * 1000:.1f} ms"


# --------------------------------------------------------------------------- the coffee scene

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


def coffee(args: argparse.Namespace) -> None:
    """The coffee scene at 1,000 objects: every mixed event, every state determined from scratch too."""
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


def parse_args(argv: list[str] | None = None) -> argparse.Namespace:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    which = parser.add_subparsers(dest="which", required=True)
    scene = which.add_parser("scenegraph", help="per-event latency and memory on generated scene graphs")
    scene.add_argument("--sizes", type=int, nargs="+", default=[2000, 10000, 50000], metavar="N")
    one = which.add_parser("one-scene", help="one size, printed as JSON (what 'scenegraph' runs per size)")
    one.add_argument("--size", type=int, required=True)
    for sub in (scene, one):
        sub.add_argument("--changes", type=int, default=200, help="seeded changes per size (default: 200)")
        sub.add_argument("--check-every", type=int, default=20, help="determine from scratch every N changes")
        sub.add_argument("--no-plans", dest="plans", action="store_false", help="leave the plan requests out")
    orders = which.add_parser("orders", help="item moves reported in either order: each one's latency, the ratio")
    orders.add_argument("--size", type=int, default=10_000)
    orders.add_argument("--moves", type=int, default=200, help="moves, half in each order (default: 200)")
    orders.add_argument("--check-every", type=int, default=20, help="determine from scratch every N moves")
    loading = which.add_parser("load", help="watch on one big scene: wall time and peak memory")
    loading.add_argument("--size", type=int, default=100_000)
    coffee_scene = which.add_parser("coffee", help="the coffee scene at 1,000 objects")
    for sub in (scene, one, orders, loading, coffee_scene):
        sub.add_argument("--seed", type=int, default=0, help="seed of the scene and the events (default: 0)")
    return parser.parse_args(argv)


def main(argv: list[str] | None = None) -> None:
    args = parse_args(argv)
    commands = {"scenegraph": scenegraph, "one-scene": one_scene, "orders": move_orders, "load": load, "coffee": coffee}
    commands[args.which](args)


if __name__ == "__main__":
    main()
