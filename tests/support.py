"""Helpers shared by the test modules: paths, running the CLI, files, processes and store rows.

Fixtures live in ``conftest.py``; the padded classic worlds in the package
(``relevance_plan.generators.padded``).  Here too: the coffee problems built in code, the
small worlds whose quantifiers make pruning delicate, tiny Fast Downward problems and
stand-in planner scripts.  Nothing here imports the package at import time.
"""

from __future__ import annotations

import json
import os
import random
import stat
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parent.parent
DOMAINS = REPO / "domains"
PROBLEMS = REPO / "problems"
COFFEE_DOMAIN = DOMAINS / "coffee" / "domain.pddl"
COFFEE_MODEL = DOMAINS / "coffee" / "relevance.yaml"

# The tool as a separate process.
TOOL = [sys.executable, "-m", "relevance_plan"]


# --------------------------------------------------------------------------- the command line, in-process


def invoke(*args, input=None):
    """The click result of ``relevance-plan ARGS`` run in-process; a traceback fails the test."""
    from click.testing import CliRunner

    from relevance_plan.cli import main

    result = CliRunner().invoke(main, [str(a) for a in args], input=input)
    if result.exception is not None and not isinstance(result.exception, SystemExit):
        raise result.exception
    return result


def run(*args, input=None):
    """(exit code, stdout, stderr) of the command run in-process; a traceback fails the test."""
    result = invoke(*args, input=input)
    return result.exit_code, result.stdout, result.stderr


def one_line_error(stderr: str) -> str:
    lines = stderr.splitlines()
    assert len(lines) == 1, stderr
    assert lines[0].startswith("relevance-plan:") and "Traceback" not in stderr
    return lines[0]


# --------------------------------------------------------------------------- files


def modules_after(*lines: str, then: str = "") -> list[str]:
    """The modules a fresh interpreter has imported once it ran ``lines`` (then ``then``)."""
    script = "import sys\n" + "".join(line + "\n" for line in lines) + "print(' '.join(sorted(sys.modules)))\n" + then
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=60, cwd=REPO)
    assert done.returncode == 0, done.stderr
    return done.stdout.split()


def write_file(directory: Path, name: str, data: str | bytes) -> Path:
    """``directory / name`` holding ``data`` (text or bytes)."""
    path = directory / name
    if isinstance(data, bytes):
        path.write_bytes(data)
    else:
        path.write_text(data)
    return path


def write_task(directory: Path, name: str, domain: str, problem: str) -> tuple[Path, Path]:
    """(``NAME.pddl``, ``NAME-1.pddl``) in ``directory``, holding the domain and the problem text."""
    return write_file(directory, f"{name}.pddl", domain), write_file(directory, f"{name}-1.pddl", problem)


def task_fixture(name: str, domain: str, problem: str):
    """A fixture giving ``write_task``'s two files in the test's ``tmp_path``."""

    @pytest.fixture
    def files(tmp_path: Path) -> tuple[Path, Path]:
        return write_task(tmp_path, name, domain, problem)

    return files


def alias_bomb(levels: int = 9) -> bytes:
    """A YAML document whose aliases expand to 9**levels strings."""
    lines = ['a0: &a0 ["lol", "lol", "lol", "lol", "lol", "lol", "lol", "lol", "lol"]']
    for level in range(1, levels):
        lines.append(f"a{level}: &a{level} [" + ", ".join([f"*a{level - 1}"] * 9) + "]")
    return ("\n".join(lines) + "\n").encode()


# --------------------------------------------------------------------------- processes


def process_state(pid: int) -> str | None:
    """The state letter of ``pid`` in /proc (R, S, Z, ...), or None if it is gone."""
    try:
        return Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except OSError:
        return None


def running(pid: int) -> bool:
    """Alive and not a zombie waiting to be reaped by whoever adopted it (nor dead, X)."""
    return process_state(pid) not in (None, "Z", "X")


def process_gone(pid: int) -> bool:
    """Exited: no longer in /proc, or a zombie."""
    return not running(pid)


# --------------------------------------------------------------------------- results-store rows

TIMEOUT = 100.0


def make_row(
    suite,
    problem,
    method,
    status="solved",
    wall=1.0,
    relevance=0.0,
    first=None,
    kept=10,
    total=20,
    seed=0,
    config="c",
    exit_code=0,
    cost=None,
):
    """A complete results-store row, made by hand."""
    config_json = json.dumps({"method": method, "timeout": TIMEOUT, "config": config}, sort_keys=True)
    return {
        "problem_hash": f"hash-{suite}-{problem}",
        "method": method,
        "config_hash": f"{config}-{seed}",
        "planner_version": "1.0.0",
        "suite": suite,
        "problem": f"{problem}.pddl",
        "world": "coffee",
        "difficulty": "simple",
        "seed": seed,
        "status": status,
        "valid": int(status == "solved"),
        "exit_code": exit_code,
        "wall_time": wall,
        "relevance_time": relevance,
        "planner_time": max(wall - relevance, 0.0),
        "objects_total": total,
        "objects_kept": kept,
        "attempts": 1,
        "first_attempt_status": first or status,
        "plan_length": 10 if status == "solved" else None,
        "plan_cost": (10.0 if cost is None else cost) if status == "solved" else None,
        "timeout": TIMEOUT,
        "message": "",
        "config_json": config_json,
        "finished_at": "2026-11-22T00:00:00.000+00:00",
        "result_json": "{}",
    }


def write_store(path: Path, rows) -> Path:
    """A new results store at ``path`` holding ``rows`` (each stored: no two share a key)."""
    from relevance_plan.batch.store import ResultStore

    with ResultStore(path) as store:
        for row in rows:
            assert store.add(row)
    return path


# --------------------------------------------------------------------------- other processes


def outputs_under_hash_seeds(script: str, seeds: tuple[str, ...] = ("1", "2"), *args: str) -> list[str]:
    """What ``python -c script args`` prints in a new process under each hash seed: sets and
    dicts of strings iterate in another order in each."""
    return [
        subprocess.run(
            [sys.executable, "-c", script, *args],
            env=dict(os.environ, PYTHONHASHSEED=seed),
            capture_output=True,
            text=True,
            check=True,
        ).stdout
        for seed in seeds
    ]


# --------------------------------------------------------------------------- tiny kitchen problems built in code


COFFEE_OBJECTS = {
    "surface": ["counter_1", "table_1"],
    "container": ["fridge_1"],
    "human": ["alice"],
    "cup": ["plastic_cup_1", "paper_cup_1"],
    "coffee-source": ["cold_brew_1"],
    "whitener": ["creamer_1"],
    "stirrer": ["stir_stick_1"],
    "plate": ["dinner_plate_1", "dinner_plate_2"],
}


def coffee_problem(extra_plates: int = 0, plate_on_cup: bool = True, name: str = "coffee-tiny") -> str:
    from relevance_plan.pddl.formatter import format_problem_parts

    objects = {k: list(v) for k, v in COFFEE_OBJECTS.items()}
    objects["plate"] += [f"side_plate_{i}" for i in range(1, extra_plates + 1)]
    init = [
        ("robot-at", "counter_1"),
        ("hand-empty",),
        ("accessible", "counter_1"),
        ("accessible", "table_1"),
        ("human-at", "alice", "table_1"),
        ("empty", "plastic_cup_1"),
        ("empty", "paper_cup_1"),
    ]

    def stand(item, place):
        init.extend([("at", item, place), ("on-base", item), ("clear", item)])

    init.extend([("at", "plastic_cup_1", "counter_1"), ("on-base", "plastic_cup_1")])
    if plate_on_cup:
        init.extend(
            [
                ("at", "dinner_plate_1", "counter_1"),
                ("on", "dinner_plate_1", "plastic_cup_1"),
                ("clear", "dinner_plate_1"),
            ]
        )
    else:
        init.append(("clear", "plastic_cup_1"))
        stand("dinner_plate_1", "counter_1")
    stand("paper_cup_1", "table_1")
    stand("cold_brew_1", "counter_1")
    stand("creamer_1", "fridge_1")
    stand("stir_stick_1", "counter_1")
    stand("dinner_plate_2", "table_1")
    for i in range(1, extra_plates + 1):
        stand(f"side_plate_{i}", "counter_1" if i % 2 else "table_1")
    return format_problem_parts(name, "coffee", objects, init, [("coffee-served", "alice")])


def goal_of(text: str) -> str:
    """The goal formula of a problem's text (without the ``(:goal`` around it)."""
    start = text.index("(:goal") + len("(:goal")
    end = text.rindex(")", 0, text.rindex(")"))
    return text[start:end].strip()


def replace_goal(text: str, goal: str) -> str:
    """The problem's text with ``goal`` in place of its goal formula."""
    start = text.index("(:goal") + len("(:goal")
    end = text.rindex(")", 0, text.rindex(")"))
    return text[:start] + " " + goal + text[end:]


def nested_goal(depth: int) -> str:
    """The tiny coffee problem with its goal wrapped in ``depth`` levels of ``(and ...)``."""
    text = coffee_problem()
    return replace_goal(text, "(and " * depth + goal_of(text) + ")" * depth)


# ------------------------------------------------------------------ worlds whose quantifiers make pruning delicate

LIFT = """(define (domain lift-adl)
  (:requirements :adl)
  (:types passenger floor)
  (:predicates (origin ?p - passenger ?f - floor) (destin ?p - passenger ?f - floor)
               (boarded ?p - passenger) (served ?p - passenger) (lift-at ?f - floor))
  (:action move :parameters (?f1 ?f2 - floor)
    :precondition (lift-at ?f1)
    :effect (and (not (lift-at ?f1)) (lift-at ?f2)))
  (:action stop :parameters (?f - floor)
    :precondition (lift-at ?f)
    :effect (and (forall (?p - passenger) (when (and (boarded ?p) (destin ?p ?f))
                                                (and (not (boarded ?p)) (served ?p))))
                 (forall (?p - passenger) (when (and (origin ?p ?f) (not (served ?p))) (boarded ?p))))))
"""

UNTYPED_LIFT = LIFT.replace("(:types passenger floor)", "").replace(" - passenger", "").replace(" - floor", "")
UNTYPED_LIFT = UNTYPED_LIFT.replace("(lift-at ?f))", "(lift-at ?f) (passenger ?p) (floor ?f) (junk ?j))", 1)
UNTYPED_LIFT = UNTYPED_LIFT.replace(
    "(forall (?p) (when (and (boarded ?p)", "(forall (?p) (when (and (passenger ?p) (boarded ?p)"
)

ROOMS = """(define (domain rooms)
  (:requirements :adl)
  (:types robot room item)
  (:predicates (at ?r - robot ?x - room) (in ?i - item ?x - room) (door ?a - room ?b - room)
               (sealed ?x - room))
  (:action go :parameters (?r - robot ?a - room ?b - room)
    :precondition (and (at ?r ?a) (door ?a ?b))
    :effect (and (not (at ?r ?a)) (at ?r ?b)))
  (:action seal :parameters (?r - robot ?x - room)
    :precondition (and (at ?r ?x) (forall (?i - item) (not (in ?i ?x))))
    :effect (sealed ?x))
  (:action carry :parameters (?r - robot ?i - item ?a - room ?b - room)
    :precondition (and (at ?r ?a) (in ?i ?a) (door ?a ?b))
    :effect (and (not (in ?i ?a)) (in ?i ?b) (not (at ?r ?a)) (at ?r ?b))))
"""

GUARDED = """(define (domain guarded)
  (:requirements :adl :derived-predicates)
  (:types agent cell guard)
  (:predicates (at ?a - agent ?c - cell) (adj ?c ?d - cell) (watch ?g - guard ?c - cell) (seen ?c - cell))
  (:derived (seen ?c - cell) (exists (?g - guard) (watch ?g ?c)))
  (:action step :parameters (?a - agent ?c ?d - cell)
    :precondition (and (at ?a ?c) (adj ?c ?d) (not (seen ?d)))
    :effect (and (not (at ?a ?c)) (at ?a ?d))))
"""

ALARM = """(define (domain alarm)
  (:requirements :adl)
  (:types thief spot alarm)
  (:predicates (at ?t - thief ?s - spot) (link ?s ?u - spot) (armed ?a - alarm) (covers ?a - alarm ?s - spot)
               (caught ?t - thief) (took ?t - thief))
  (:action go :parameters (?t - thief ?s ?u - spot)
    :precondition (and (at ?t ?s) (link ?s ?u))
    :effect (and (not (at ?t ?s)) (at ?t ?u)
                 (when (exists (?a - alarm) (and (armed ?a) (covers ?a ?u))) (caught ?t))))
  (:action grab :parameters (?t - thief ?s - spot)
    :precondition (and (at ?t ?s) (not (caught ?t)))
    :effect (took ?t)))
"""

SCENE = """(define (domain scene)
  (:requirements :adl)
  (:types agent place receptacle item)
  (:predicates (at ?a - agent ?p - place) (link ?p ?q - place) (item-at ?i - item ?p - place)
               (rec-at ?r - receptacle ?p - place) (inside ?i - item ?r - receptacle)
               (opened ?r - receptacle) (holding ?a - agent ?i - item) (free ?a - agent))
  (:action go :parameters (?a - agent ?p ?q - place)
    :precondition (and (at ?a ?p) (link ?p ?q))
    :effect (and (not (at ?a ?p)) (at ?a ?q)))
  (:action open :parameters (?a - agent ?r - receptacle ?p - place)
    :precondition (and (at ?a ?p) (rec-at ?r ?p))
    :effect (opened ?r))
  (:action pick-loose :parameters (?a - agent ?i - item ?p - place)
    :precondition (and (at ?a ?p) (item-at ?i ?p) (free ?a) (forall (?r - receptacle) (not (inside ?i ?r))))
    :effect (and (holding ?a ?i) (not (free ?a)) (not (item-at ?i ?p))))
  (:action pick-from :parameters (?a - agent ?i - item ?r - receptacle ?p - place)
    :precondition (and (at ?a ?p) (rec-at ?r ?p) (inside ?i ?r) (opened ?r) (free ?a))
    :effect (and (holding ?a ?i) (not (free ?a)) (not (inside ?i ?r)) (not (item-at ?i ?p))))
  (:action put :parameters (?a - agent ?i - item ?r - receptacle ?p - place)
    :precondition (and (at ?a ?p) (rec-at ?r ?p) (holding ?a ?i))
    :effect (and (inside ?i ?r) (item-at ?i ?p) (free ?a) (not (holding ?a ?i)))))
"""

NOISE = """(define (domain noise)
  (:requirements :adl)
  (:types agent cell sleeper)
  (:predicates (at ?a - agent ?c - cell) (adj ?c ?d - cell) (near ?s - sleeper ?c - cell) (woken))
  (:action step :parameters (?a - agent ?c ?d - cell)
    :precondition (and (at ?a ?c) (adj ?c ?d))
    :effect (and (not (at ?a ?c)) (at ?a ?d) (forall (?s - sleeper) (when (near ?s ?d) (woken))))))
"""


def define_problem(name: str, domain: str, objects: str, init: str, goal: str) -> str:
    """A problem's text on one line, from its parts' texts."""
    return f"(define (problem {name}) (:domain {domain}) (:objects {objects}) (:init {init}) (:goal {goal}))"


def lift_problem(seed: int, untyped: bool = False) -> str:
    rng = random.Random(seed)
    passengers, floors = 12, 24
    init = ["(lift-at f0)"]
    for i in range(passengers):
        a, b = rng.sample(range(floors), 2)
        init += [f"(origin p{i} f{a})", f"(destin p{i} f{b})"]
        if rng.random() < 0.5:
            init.append(f"(served p{i})")
    if untyped:
        init += [f"(passenger p{i})" for i in range(passengers)] + [f"(floor f{i})" for i in range(floors)]
        init += [f"(junk j{i})" for i in range(30)]
        objects = " ".join([f"p{i}" for i in range(passengers)] + [f"f{i}" for i in range(floors)])
        objects += " " + " ".join(f"j{i}" for i in range(30))
        goal = "(forall (?p) (imply (passenger ?p) (served ?p)))"
    else:
        objects = " ".join(f"p{i}" for i in range(passengers)) + " - passenger "
        objects += " ".join(f"f{i}" for i in range(floors)) + " - floor"
        goal = "(forall (?p - passenger) (served ?p))"
    return define_problem(f"lift-{seed}", "lift-adl", objects, " ".join(init), goal)


def rooms_problem(seed: int) -> str:
    rng = random.Random(seed)
    rooms = [f"r{i}" for i in range(8)]
    doors = [f"(door r{i} r{i + 1}) (door r{i + 1} r{i})" for i in range(7)]
    items = [f"(in i{k} r{rng.randrange(8)})" for k in range(6)]
    objects = f"bot - robot {' '.join(rooms)} - room {' '.join(f'i{k}' for k in range(6))} - item"
    init = f"(at bot r0) {' '.join(doors)} {' '.join(items)}"
    return define_problem(f"rooms-{seed}", "rooms", objects, init, f"(sealed r{rng.randrange(2, 8)})")


def scene_problem(seed: int, timed: str = "") -> str:
    """Items in receptacles and loose; the goal holds an item that sits in a receptacle, which a
    pruned problem without that receptacle would let the agent pick up loose."""
    rng = random.Random(seed)
    places = [f"p{i}" for i in range(10)]
    links = [f"(link p{i} p{i + 1}) (link p{i + 1} p{i})" for i in range(9)]
    where = {f"r{k}": rng.randrange(10) for k in range(12)}
    init = ["(at bot p0)", "(free bot)", *links, *(f"(rec-at {r} p{p})" for r, p in where.items())]
    for k in range(8):
        if k % 2 == 0:  # in a box in a cabinet: inside both
            box, cabinet = rng.sample(sorted(where), 2)
            init += [f"(inside i{k} {box})", f"(inside i{k} {cabinet})", f"(item-at i{k} p{where[box]})"]
        else:
            init.append(f"(item-at i{k} p{rng.randrange(10)})")
    objects = f"bot - agent {' '.join(places)} - place {' '.join(where)} - receptacle"
    objects += " " + " ".join(f"i{k}" for k in range(8)) + " - item"
    goal = f"(holding bot i{2 * rng.randrange(4)})"
    return define_problem(f"scene-{seed}", "scene", objects, f"{' '.join(init)} {timed}", goal)


def noise_problem(seed: int) -> str:
    """A short way past sleepers and a long way round; the goal wakes no one.  The sleepers are
    named nowhere but in the quantified effect's condition; z0 sleeps near no cell."""
    rng = random.Random(seed)
    cells = [f"c{i}" for i in range(10)] + [f"d{i}" for i in range(1, 12)]
    way = ["c0", *(f"d{i}" for i in range(1, 12)), "c9"]
    links = [(f"c{i}", f"c{i + 1}") for i in range(9)] + list(zip(way, way[1:]))
    adj = " ".join(f"(adj {a} {b}) (adj {b} {a})" for a, b in links)
    near = " ".join(f"(near s{k} c{rng.randrange(2, 8)})" for k in range(3))
    objects = f"a - agent {' '.join(cells)} - cell s0 s1 s2 z0 - sleeper"
    return define_problem(f"noise-{seed}", "noise", objects, f"(at a c0) {adj} {near}", "(and (at a c9) (not (woken)))")


def guarded_problem(seed: int) -> str:
    rng = random.Random(seed)
    cells = [f"c{i}" for i in range(20)]
    adj = [f"(adj c{i} c{j})" for i in range(20) for j in (i + 1, i + 5) if j < 20]
    adj += [f"(adj c{j} c{i})" for i in range(20) for j in (i + 1, i + 5) if j < 20]
    guards = [f"(watch g{k} c{rng.randrange(1, 19)})" for k in range(6)]
    objects = f"a - agent {' '.join(cells)} - cell {' '.join(f'g{k}' for k in range(6))} - guard"
    return define_problem(
        f"guarded-{seed}", "guarded", objects, f"(at a c0) {' '.join(adj)} {' '.join(guards)}", "(at a c19)"
    )


def alarm_problem(seed: int) -> str:
    rng = random.Random(seed)
    spots = [f"s{i}" for i in range(10)]
    links = [f"(link s{i} s{i + 1})" for i in range(9)] + ["(link s0 s9)"]
    alarms = [f"(armed a{k}) (covers a{k} s{rng.randrange(1, 9)})" for k in range(5)]
    objects = f"t - thief {' '.join(spots)} - spot {' '.join(f'a{k}' for k in range(5))} - alarm"
    init = f"(at t s0) {' '.join(links)} {' '.join(alarms)}"
    return define_problem(f"alarm-{seed}", "alarm", objects, init, "(and (took t) (at t s9))")


WORLDS = {
    "lift": (LIFT, lift_problem),
    "untyped-lift": (UNTYPED_LIFT, lambda seed: lift_problem(seed, untyped=True)),
    "rooms": (ROOMS, rooms_problem),
    "guarded": (GUARDED, guarded_problem),
    "alarm": (ALARM, alarm_problem),
    "scene": (SCENE, scene_problem),
    "noise": (NOISE, noise_problem),
}


# ------------------------------------------------------------ stand-in planners and tiny Fast Downward problems


def planner_script(tmp_path: Path, name: str, body: str) -> str:
    """An executable Python script standing in for an external planner."""
    path = tmp_path / name
    path.write_text(f"#!{sys.executable}\n" + textwrap.dedent(body))
    path.chmod(path.stat().st_mode | stat.S_IXUSR)
    return str(path)


# Two coins at a price of 1e308 each: the plan's total cost is past the largest float.
PAYING_DOMAIN = """(define (domain pay)
  (:requirements :typing :action-costs)
  (:types coin)
  (:predicates (spent ?c - coin))
  (:functions (total-cost) - number (price) - number)
  (:action spend :parameters (?c - coin) :precondition (and)
    :effect (and (spent ?c) (increase (total-cost) (price)))))
"""
PAYING_PROBLEM = """(define (problem pay-1) (:domain pay)
  (:objects a b - coin)
  (:init (= (total-cost) 0) (= (price) 1e308))
  (:goal (and (spent a) (spent b)))
  (:metric minimize (total-cost)))
"""


SMALL_GRIPPER_DOMAIN = """
(define (domain gripper)
  (:requirements :strips :typing)
  (:types room ball gripper)
  (:predicates (at-robby ?r - room) (at ?b - ball ?r - room)
               (free ?g - gripper) (carry ?b - ball ?g - gripper))
  (:action move :parameters (?from ?to - room)
    :precondition (at-robby ?from)
    :effect (and (at-robby ?to) (not (at-robby ?from))))
  (:action pick :parameters (?b - ball ?r - room ?g - gripper)
    :precondition (and (at ?b ?r) (at-robby ?r) (free ?g))
    :effect (and (carry ?b ?g) (not (at ?b ?r)) (not (free ?g))))
  (:action drop :parameters (?b - ball ?r - room ?g - gripper)
    :precondition (and (carry ?b ?g) (at-robby ?r))
    :effect (and (at ?b ?r) (free ?g) (not (carry ?b ?g)))))
"""


def small_gripper_problem(target: str = "roomb", free_gripper: bool = True) -> str:
    free = "(free left)" if free_gripper else ""
    return f"""
(define (problem g) (:domain gripper)
  (:objects rooma roomb roomc - room ball1 - ball left - gripper)
  (:init (at-robby rooma) (at ball1 rooma) {free})
  (:goal (at ball1 {target})))
"""


# n objects give n^3 ground actions: at n=40 translation takes seconds while the search is trivial.
BIG_DOMAIN = """
(define (domain big)
  (:requirements :strips)
  (:predicates (p ?x) (q ?x ?y ?z) (done))
  (:action a :parameters (?x ?y ?z)
    :precondition (and (p ?x) (p ?y) (p ?z))
    :effect (q ?x ?y ?z))
  (:action fin :parameters (?x)
    :precondition (q ?x ?x ?x)
    :effect (done)))
"""


def big_problem(n: int) -> str:
    objects = " ".join(f"o{i}" for i in range(n))
    init = " ".join(f"(p o{i})" for i in range(n))
    return f"(define (problem big{n}) (:domain big) (:objects {objects}) (:init {init}) (:goal (done)))"


def live_session_members(session: int) -> list[int]:
    """Pids of processes in this session that are not zombies (from /proc)."""
    members = []
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        try:
            stat = (entry / "stat").read_text()
        except OSError:
            continue
        # Fields after "(comm)": state ppid pgrp session ...
        fields = stat[stat.rindex(")") + 2 :].split()
        if int(fields[3]) == session and fields[0] != "Z":
            members.append(int(entry.name))
    return members


def assert_session_gone(session: int) -> None:
    # SIGKILL is delivered at once, but exiting (freeing memory) takes a moment.
    deadline = time.monotonic() + 3.0
    while live_session_members(session) and time.monotonic() < deadline:
        time.sleep(0.05)
    assert live_session_members(session) == []


# --- without running the planner ---------------------------------------------


# --------------------------------------------------------------------------- a store written by several processes


def write_store_rounds(barrier, folder: str, rounds: int, writer: str, jobs: int) -> None:
    """In a child process: for each round, wait for the other writers, then create the round's store
    (the same new path for every writer) and add ``jobs`` rows of its own plus one row all share."""
    from relevance_plan.batch.store import ResultStore

    for number in range(rounds):
        barrier.wait(timeout=120)
        with ResultStore(Path(folder) / f"round-{number}.sqlite") as store:
            store.add(make_row("s", "shared", "pure"))
            for job in range(jobs):
                store.add(make_row("s", f"{writer}-{job}", "pure"))
