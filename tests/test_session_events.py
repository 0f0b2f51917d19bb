"""Event lines at each documented limit: taken just under it, refused one step over it, with a reason
the line's answer carries while the session carries on."""

from __future__ import annotations

import io
import json
import sys

import pytest
from click.testing import CliRunner

from relevance_plan.cli import main
from relevance_plan.cli.watch import read_event_lines
from relevance_plan.data import DOMAINS_DIR, PROBLEMS_DIR
from relevance_plan.io import load_domain
from relevance_plan.pddl.parser import read_problem
from relevance_plan.session import Session
from relevance_plan.session.events import (
    MAX_CUE_CHARACTERS,
    MAX_EVENT_BYTES,
    MAX_EVENT_NESTING,
    MAX_INTEGER_DIGITS,
)

COFFEE_DOMAIN = DOMAINS_DIR / "coffee" / "domain.pddl"
COFFEE_SIMPLE = PROBLEMS_DIR / "coffee-simple.pddl"
GOOD = {"event": "set", "fact": ["clear", "dinner_plate_1"]}


def coffee_session() -> Session:
    domain = load_domain(COFFEE_DOMAIN)
    return Session(domain, read_problem(COFFEE_SIMPLE.read_text(), domain), domain_path=str(COFFEE_DOMAIN))


def padded(size: int, character: str = "a") -> str:
    """A good event whose ignored ``note`` makes the line ``size`` bytes of UTF-8 long."""
    bare = len(json.dumps({**GOOD, "note": ""}).encode())
    width = len(character.encode())
    assert (size - bare) % width == 0
    line = json.dumps({**GOOD, "note": character * ((size - bare) // width)}, ensure_ascii=False)
    assert len(line.encode()) == size
    return line


def assert_taken_then_carries_on(session: Session, line: str) -> None:
    report = session.handle_line(line)
    assert report.error is None, report.error
    assert session.handle(GOOD).error is None


def assert_refused_then_carries_on(session: Session, line: str, reason: str) -> None:
    facts = set(session.scene.facts)
    report = session.handle_line(line)
    assert report.error is not None and reason in report.error, report.error
    assert not report.triggered and session.scene.facts == facts
    report = session.handle({"event": "unset", "fact": ["clear", "dinner_plate_1"]})
    assert report.error is None and report.seq == session.seq


@pytest.mark.parametrize("ending", ["", "\n", "\r\n"], ids=["no-ending", "newline", "crlf"])
def test_a_line_of_the_limit_is_taken_and_one_byte_more_is_refused(ending):
    session = coffee_session()
    assert_taken_then_carries_on(session, padded(MAX_EVENT_BYTES) + ending)
    assert_refused_then_carries_on(session, padded(MAX_EVENT_BYTES + 1) + ending, "at most 16,777,216 bytes")


def test_the_limit_counts_the_bytes_of_utf8_not_characters():
    bare = len(json.dumps({**GOOD, "note": ""}))
    line = padded(MAX_EVENT_BYTES + 100 + (MAX_EVENT_BYTES + 100 - bare) % 2, "é")
    assert len(line) < MAX_EVENT_BYTES
    assert_refused_then_carries_on(coffee_session(), line, "at most 16,777,216 bytes")


def test_the_reader_hands_over_a_line_of_the_limit_whole_and_cuts_a_longer_one():
    lines = [b"a" * 10 + b"\n", b"b" * 10 + b"\r\n", b"c" * 11 + b"\n", b"d" * 50 + b"\n", b"e" * 12]
    read = list(read_event_lines(io.BytesIO(b"".join(lines)), limit=10))
    assert read == ["a" * 10 + "\n", "b" * 10 + "\r\n", "c" * 11 + "\n", "d" * 12, "e" * 12]


def test_watch_takes_a_line_of_the_limit_and_refuses_a_longer_one_by_its_size(tmp_path):
    events = tmp_path / "events.jsonl"
    good = json.dumps(GOOD)
    bare = len(json.dumps({**GOOD, "note": ""}))
    over = padded(MAX_EVENT_BYTES + 100 + (MAX_EVENT_BYTES + 100 - bare) % 2, "é")  # fewer characters than the limit
    events.write_text("\n".join([padded(MAX_EVENT_BYTES), good, over, good]) + "\n", encoding="utf-8")
    result = CliRunner().invoke(main, ["watch", str(COFFEE_DOMAIN), str(COFFEE_SIMPLE), "--events", str(events)])
    assert result.exit_code == 0, result.stderr
    answers = [json.loads(line) for line in result.stdout.splitlines()]
    assert [answer.get("error") is None for answer in answers] == [True, True, False, True]
    assert "at most 16,777,216 bytes" in answers[2]["error"]


def nested(levels: int) -> str:
    """A good event with an ignored field of lists nested so that the line nests ``levels`` deep."""
    return json.dumps(GOOD)[:-1] + ', "note": ' + "[" * (levels - 1) + "]" * (levels - 1) + "}"


def test_nesting_up_to_the_limit_is_taken_and_deeper_refused_however_deep():
    session = coffee_session()
    assert_taken_then_carries_on(session, nested(MAX_EVENT_NESTING))
    for levels in (MAX_EVENT_NESTING + 1, 100_000):
        assert_refused_then_carries_on(session, nested(levels), f"nested more than {MAX_EVENT_NESTING} levels")


def test_an_integer_of_the_limits_digits_is_taken_and_a_longer_one_refused_whatever_python_allows():
    session = coffee_session()
    for sign in ("", "-"):
        line = json.dumps(GOOD)[:-1] + ', "n": ' + sign + "9" * MAX_INTEGER_DIGITS + "}"
        assert_taken_then_carries_on(session, line)
    if hasattr(sys, "set_int_max_str_digits"):  # no limit of Python's own: the session's holds
        previous = sys.get_int_max_str_digits()
        sys.set_int_max_str_digits(0)
    try:
        line = json.dumps(GOOD)[:-1] + ', "n": ' + "9" * (MAX_INTEGER_DIGITS + 1) + "}"
        assert_refused_then_carries_on(session, line, f"more than {MAX_INTEGER_DIGITS:,} digits")
    finally:
        if hasattr(sys, "set_int_max_str_digits"):
            sys.set_int_max_str_digits(previous)


def test_a_cue_in_more_words_than_the_limit_is_refused_before_they_are_read():
    session = coffee_session()
    words = ("cold brew please " * MAX_CUE_CHARACTERS)[:MAX_CUE_CHARACTERS]
    report = session.handle({"event": "cue", "text": words + "x"})
    assert report.error is not None and f"at most {MAX_CUE_CHARACTERS:,} characters" in report.error
    report = session.handle({"event": "cue", "text": words})  # understood, or the text extra named
    assert report.error is None or "at most" not in report.error, report.error
