"""The live session fed bad events: each refused in one answer, the next event taken, nothing injected."""

from __future__ import annotations

import json
import re

from hostile.inputs import files, says
from hostile.scenario import Result, Scenario, scenario_test

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
            "cue-list": json.dumps({"event": "cue", "task": ["tea"]}).encode(),
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


test_session = scenario_test(SCENARIOS)
