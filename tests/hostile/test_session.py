"""The live session fed bad events: each refused in one answer, the next event taken, nothing injected;
lines at each limit on an event line, just under it and just over it; item moves reported in the order
that once made every event a full determination."""

from __future__ import annotations

import functools
import json
import random
import re

from hostile.inputs import files, says
from hostile.scenario import Result, Scenario, scenario_test
from relevance_plan.data import DOMAINS_DIR
from relevance_plan.session.events import MAX_EVENT_BYTES, MAX_EVENT_NESTING

GOOD_EVENT = {"event": "set", "fact": ["hand-empty"]}
INJECTED = "x ) (:init (coffee-served person_1)) (:metric"


def hostile_events() -> dict[str, bytes]:
    """A bad event line each (bytes: some are not UTF-8)."""

    def add(name) -> bytes:
        return json.dumps({"event": "add", "object": name, "type": "cup", "facts": [["empty", name]]}).encode()

    events = {f"add-named-{label}": add(name) for label, name in _BAD_NAMES.items()}
    events.update(
        {
            "deep-json-array": b"[" * 100_000 + b"]" * 100_000,
            "deep-json-object": b'{"a":' * 100_000 + b"1" + b"}" * 100_000,
            "invalid-utf8-name": b'{"event": "add", "object": "cup\xff", "type": "cup"}',
            "invalid-utf8-outside-strings": b'{"event": "add"\xfe\xff}',
            "lone-surrogate-name": b'{"event": "add", "object": "cup\\ud800", "type": "cup"}',
            "injection-in-type": json.dumps({"event": "add", "object": "cup9", "type": INJECTED}).encode(),
            "injection-in-a-fact": json.dumps({"event": "set", "fact": ["empty", INJECTED]}).encode(),
            "injection-in-a-predicate": json.dumps({"event": "set", "fact": [INJECTED]}).encode(),
            "injection-in-the-goal": json.dumps(
                {"event": "goal", "goal": "(and) ) (:init (coffee-served alice)"}
            ).encode(),
            "comment-in-the-goal": json.dumps({"event": "goal", "goal": "(and) ; )) (:init (x"}).encode(),
            "goal-two-lists": json.dumps({"event": "goal", "goal": "(and) (and)"}).encode(),
            "goal-unknown-object": json.dumps({"event": "goal", "goal": "(coffee-served nobody)"}).encode(),
            "human-injection": json.dumps({"event": "human", "name": INJECTED, "preferences": None}).encode(),
            "cue-list": json.dumps({"event": "cue", "activity": ["tea"]}).encode(),
            "remove-a-goal-object": json.dumps({"event": "remove", "object": "alice"}).encode(),
            "unknown-kind": json.dumps({"event": "explode"}).encode(),
            "json-array": b"[1, 2, 3]",
            "json-null": b"null",
            "json-number-name": json.dumps({"event": "add", "object": 7, "type": "cup"}).encode(),
            "facts-not-a-list": json.dumps({"event": "add", "object": "cup9", "type": "cup", "facts": "x"}).encode(),
            "fact-with-a-number": json.dumps({"event": "set", "fact": ["empty", 3]}).encode(),
            "huge-line": b'{"event": "add", "object": "' + b"a" * 2_000_000 + b'", "type": "cup"}',
            "nul-byte": b'{"event": "add", "object": "cup\\u0000x", "type": "cup"}',
            "not-json": b"this is not json",
            "huge-integer": b'{"event": "add", "object": "cup9", "type": "cup", "n": ' + b"9" * 5000 + b"}",
        }
    )
    return events


_BAD_NAMES = {
    "two-words": "two words",
    "semicolon": "cup;9",
    "dash": "-",
    "variable": "?x",
    "keyword": ":init",
    "open-paren": "(",
    "close-paren": ")",
    "digit-first": "9cup",
    "newline": "cup\nnine",
    "tab": "cup\t9",
    "injection": INJECTED,
    "empty": "",
    "spaces": "   ",
    "control": "cup\x1b[31m",
}


def _session_survives(result: Result) -> str | None:
    """Two answers: the bad event refused, the good one after it taken; the snapshot re-reads, nothing injected."""
    from relevance_plan.io import load_domain
    from relevance_plan.pddl.parser import read_problem

    answers = [json.loads(line) for line in result.stdout.splitlines() if line.strip()]
    if len(answers) != 2 or "error" not in answers[0] or "error" in answers[1]:
        return f"expected the bad event refused and the good one taken: {result.stdout[:300]!r}"
    snapshot = read_problem((result.work / "W" / "current.pddl").read_text(), load_domain(result.work / "D.pddl"))
    if any(fact[0] == "coffee-served" for fact in snapshot.init) or snapshot.metric is not None:
        return "the snapshot holds what the event injected"
    return None


def _bad_event(label: str, line: bytes) -> Scenario:
    """The bad event, then a good one: the session refuses the first and takes the second."""
    return Scenario(
        f"session/{label}",
        args=("watch", "D.pddl", "P.pddl", "--events", "ev.jsonl", "--snapshot", "W"),
        setup=files(ev_dot_jsonl=line + b"\n" + json.dumps(GOOD_EVENT).encode() + b"\n"),
        writes=("W/*", "W"),
        check=_session_survives,
        quick=label in ("deep-json-array", "add-named-injection", "invalid-utf8-name"),
    )


EVENTS = [_bad_event(label, line) for label, line in hostile_events().items()]
stdin_events = hostile_events()["add-named-two-words"] + b"\n" + json.dumps(GOOD_EVENT).encode() + b"\n"
SCENARIOS = EVENTS + [
    Scenario(
        "session/events-on-stdin",
        args=("watch", "D.pddl", "P.pddl", "--snapshot", "W"),
        stdin=stdin_events,
        writes=("W/*", "W"),
        check=_session_survives,
    ),
    Scenario(
        "session/sigterm-exits-130-with-a-snapshot",
        shell="mkfifo ev; $TOOL watch D.pddl P.pddl --events ev --snapshot W & tool=$!; exec 3> ev; "
        "echo '" + json.dumps(GOOD_EVENT) + "' >&3; sleep 3; kill -TERM $tool; wait $tool; echo exit=$?; "
        "exec 3>&-; test -s W/current.pddl",
        writes=("W/*", "W", "ev"),
        budget=25,
        check=says("exit=130", where="stdout"),
    ),
    Scenario(
        "session/answers-a-live-pipe-at-once",
        shell="mkfifo ev; { echo '" + json.dumps(GOOD_EVENT) + "'; sleep 6; } > ev & "
        "$TOOL watch D.pddl P.pddl --events ev > answers & sleep 4; wc -l < answers; wait",
        writes=("ev", "answers"),
        check=lambda r: None if r.stdout.split()[:1] == ["1"] else f"no answer before the end: {r.stdout!r}",
    ),
    Scenario(
        "session/piped-into-head",
        shell="yes '" + json.dumps(GOOD_EVENT) + "' | head -5000 | $TOOL watch D.pddl P.pddl | head -1; "
        "echo exit=${PIPESTATUS[2]}",
        check=lambda r: (
            None
            if re.search(r"exit=(0|141)\b", r.stdout) and not r.stderr.strip()
            else f"not a quiet end: {r.stdout[-30:]!r} {r.stderr[-200:]!r}"
        ),
    ),
]


# --------------------------------------------------------------------------- the limits on an event line


def _padded(size: int, character: str = "a") -> bytes:
    """The good event with an ignored ``note`` that makes its line ``size`` bytes (``size`` minus one
    or so for a character of several bytes)."""
    bare = len(json.dumps({**GOOD_EVENT, "note": ""}).encode())
    note = character * ((size - bare) // len(character.encode()))
    return json.dumps({**GOOD_EVENT, "note": note}, ensure_ascii=False).encode()


def _nested(levels: int) -> bytes:
    return (json.dumps(GOOD_EVENT)[:-1] + ', "note": ' + "[" * (levels - 1) + "]" * (levels - 1) + "}").encode()


def _both_taken(result: Result) -> str | None:
    answers = [json.loads(line) for line in result.stdout.splitlines() if line.strip()]
    if len(answers) != 2 or any("error" in answer for answer in answers):
        return f"expected both events taken: {result.stdout[:300]!r}"
    return None


def _refused_for(reason: str):
    def check(result: Result) -> str | None:
        answers = [json.loads(line) for line in result.stdout.splitlines() if line.strip()]
        if answers and reason not in answers[0].get("error", ""):
            return f"not refused for {reason!r}: {answers[0].get('error')!r}"
        return _session_survives(result)

    return check


def _limit_line(label: str, line, taken: bool, reason: str = "", **more) -> Scenario:
    """``line`` (bytes, or made when the scenario runs), then the good event: both taken, or the first
    refused for ``reason`` and the second taken."""
    text = (lambda: line() + b"\n" + json.dumps(GOOD_EVENT).encode() + b"\n") if callable(line) else None
    return Scenario(
        f"session/{label}",
        args=("watch", "D.pddl", "P.pddl", "--events", "ev.jsonl", "--snapshot", "W"),
        setup=files(ev_dot_jsonl=text or line + b"\n" + json.dumps(GOOD_EVENT).encode() + b"\n"),
        writes=("W/*", "W"),
        check=_both_taken if taken else _refused_for(reason),
        **more,
    )


SIZE = f"at most {MAX_EVENT_BYTES:,} bytes"
DEEP = f"nested more than {MAX_EVENT_NESTING} levels"
LIMITS = [
    _limit_line("line-of-the-limit-is-taken", lambda: _padded(MAX_EVENT_BYTES), True, quick=True),
    _limit_line("line-a-byte-over-the-limit", lambda: _padded(MAX_EVENT_BYTES + 1), False, SIZE, quick=True),
    _limit_line("line-over-the-limit-in-bytes-not-characters", lambda: _padded(MAX_EVENT_BYTES + 9, "é"), False, SIZE),
    _limit_line("line-far-over-the-limit", lambda: _padded(3 * MAX_EVENT_BYTES), False, SIZE, budget=20),
    _limit_line("nested-to-the-limit-is-taken", _nested(MAX_EVENT_NESTING), True, quick=True),
    _limit_line("nested-a-level-past-the-limit", _nested(MAX_EVENT_NESTING + 1), False, DEEP),
    _limit_line(
        "integer-of-a-million-digits-where-python-sets-no-limit",
        json.dumps(GOOD_EVENT)[:-1].encode() + b', "n": ' + b"9" * 1_000_000 + b"}",
        False,
        "more than 4,300 digits",
        env=(("PYTHONINTMAXSTRDIGITS", "0"),),
        budget=10,
    ),
]


# --------------------------------------------------------------------------- item moves in either order

SCENE_SIZE = 20_000
MOVES = 100


@functools.lru_cache(maxsize=1)
def _scene_and_moves() -> tuple[str, bytes]:
    """A generated scene graph and its item moves, each seen in the new receptacle first (made once)."""
    from relevance_plan.generators import WORLDS, Settings
    from relevance_plan.generators.scenegraph import SceneGraphEvents
    from relevance_plan.io import load_domain
    from relevance_plan.pddl.formulas import literals
    from relevance_plan.pddl.parser import read_problem

    text = WORLDS["scenegraph"].problem(3, 1, Settings(size=SCENE_SIZE)).pddl_text
    problem = read_problem(text, load_domain(DOMAINS_DIR / "scenegraph" / "domain.pddl"))
    goal = [(atom.predicate, *atom.args) for atom, _ in literals(problem.goal)]
    stream = SceneGraphEvents(dict(problem.objects), problem.init, goal, random.Random(3), new_place_first=True)
    events = [event for _ in range(MOVES) for event in stream.make("move")]
    return text, "".join(json.dumps(event) + "\n" for event in events).encode()


def _moves_answered_as_prune_decides(result: Result) -> str | None:
    """Every move taken, and the snapshot's pruned problem what ``prune`` keeps of its current one."""
    import relevance_plan as rp
    from relevance_plan.io import load_domain
    from relevance_plan.pddl.parser import read_problem

    answers = [json.loads(line) for line in result.stdout.splitlines() if line.strip()]
    if len(answers) != 2 * MOVES or any("error" in answer for answer in answers):
        return f"expected {2 * MOVES} answers without an error: {result.stdout[-300:]!r}"
    domain = load_domain(result.work / "SG.pddl")
    pruned = read_problem((result.work / "W" / "pruned.pddl").read_text(), domain)
    fresh = rp.prune(result.work / "SG.pddl", (result.work / "W" / "current.pddl").read_text())
    if set(pruned.objects) != set(fresh.kept):
        return f"the session keeps {len(pruned.objects)} objects, prune {len(fresh.kept)}"
    return None


MOVE_ORDERS = [
    Scenario(
        "session/moves-seen-in-the-new-place-before-they-leave-the-old",
        args=("watch", "SG.pddl", "S.pddl", "--events", "moves.jsonl", "--snapshot", "W"),
        setup=files(
            SG_dot_pddl=(DOMAINS_DIR / "scenegraph" / "domain.pddl").read_text(),
            S_dot_pddl=lambda: _scene_and_moves()[0],
            moves_dot_jsonl=lambda: _scene_and_moves()[1],
        ),
        writes=("W/*", "W"),
        budget=30,  # 200 events that each cost what the other order's do; a full determination each took minutes
        check=_moves_answered_as_prune_decides,
    )
]

SCENARIOS += LIMITS + MOVE_ORDERS

test_session = scenario_test(SCENARIOS)
