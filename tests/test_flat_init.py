"""A big :init of plain atoms is read with string methods: the same problem as the full reading
(facts, their order, spans for the writer), and the same one-line error, naming the same line."""

from __future__ import annotations

import dataclasses

import pytest

from relevance_plan.data import DOMAINS_DIR
from relevance_plan.errors import RelevancePlanError
from relevance_plan.generators import WORLDS, Settings
from relevance_plan.pddl import parser
from relevance_plan.pddl.parser import read_domain, read_problem

FIELDS = [f.name for f in dataclasses.fields(parser.Problem) if f.name not in ("text", "path")]


def both(monkeypatch, text: str, domain) -> tuple[object, object]:
    """(string-method reading, full reading) of ``text``; each an exception when it raises."""
    results = []
    for threshold in (1, 10**9):
        monkeypatch.setattr(parser, "FLAT_INIT_FROM", threshold)
        try:
            results.append(read_problem(text, domain, path="p.pddl"))
        except RelevancePlanError as error:
            results.append(error)
    return results[0], results[1]


def same(fast, full) -> None:
    if isinstance(full, Exception):
        assert type(fast) is type(full) and str(fast) == str(full) and fast.line == full.line
        return
    for name in FIELDS:
        if name == "init_spans":  # the objects each entry names, in any order
            assert [(a, b, set(m)) for a, b, m in fast.init_spans] == [(a, b, set(m)) for a, b, m in full.init_spans]
        else:
            assert getattr(fast, name) == getattr(full, name), name


@pytest.mark.parametrize("world", ["miconic-manygoals", "logistics-manygoals-typed", "scenegraph"])
def test_generated_problems_read_the_same(monkeypatch, world):
    problem = WORLDS[world].problem(3, 1, Settings(size=300))
    folder = problem.sidecar["domain"]
    if problem.sidecar.get("form") == "typed" and (DOMAINS_DIR / f"{folder}-typed").exists():
        folder += "-typed"
    domain = read_domain((DOMAINS_DIR / folder / "domain.pddl").read_text())
    fast, full = both(monkeypatch, problem.pddl_text, domain)
    assert not isinstance(full, Exception)
    same(fast, full)
    monkeypatch.setattr(parser, "FLAT_INIT_FROM", 1)
    text = problem.pddl_text
    assert parser._one_stretch(text, parser._init_body(text)) is not None  # the string-method reading was used


DOMAIN = """(define (domain d) (:requirements :strips :typing) (:types thing)
  (:constants home - thing)
  (:predicates (at ?x - thing ?y - thing) (free ?x - thing) (ready))
  (:action go :parameters (?x - thing ?y - thing) :precondition (free ?x) :effect (at ?x ?y)))"""


def problem(init: str, line_break: str = "\n") -> str:
    lines = ["(define (problem p) (:domain d)", "  (:objects a b c - thing)", "  (:init", init, "  )"]
    return line_break.join([*lines, "  (:goal (at a b)))"])


@pytest.mark.parametrize(
    "init",
    [
        "    (at a b) (FREE C)\n    (at b home) (ready)\n    (at a b)",  # duplicates, case, a constant, no argument
        "    (at a b)\n    ; a comment (with parentheses)\n    (free c)",  # a comment: read in full
        "    (at a b)\n    (= (total-cost) 0)\n    (free c)",  # a nested list: read in full
        "    (at a b)\n    (not (free c))",
        "    (at a b)\n\n\n    (free d)",  # an unknown object, line 8
        "    (at a b)\n    (free a b)",  # the wrong arity
        "    (at a b)\n    (gone a)",  # an unknown predicate
        "    (at a b)\n    (= a b)",  # an equality
        "    (at a b)\n    ()",
        "    (at a b) stray (free c)",  # a symbol between atoms
        "    (at a b) (free (c))\n    (ready)",  # a list inside an atom
        "    (at a b) (free c)\n    (ready) (= (cost a) 1)",  # a nested list after plain atoms
        "    (at a ?x)",
        "    (at a b",  # no closing parenthesis
    ],
)
def test_small_inits_read_the_same(monkeypatch, init):
    domain = read_domain(DOMAIN)
    for line_break in ("\n", "\r\n"):
        fast, full = both(monkeypatch, problem(init.replace("\n", line_break), line_break), domain)
        same(fast, full)


def test_an_init_in_a_comment_is_not_taken(monkeypatch):
    domain = read_domain(DOMAIN)
    text = problem("    (at a b)").replace("(define", "; (:init (free a))\n(define")
    fast, full = both(monkeypatch, text, domain)
    same(fast, full)
    assert ("free", "a") not in fast.init


def test_a_deadline_stops_the_string_method_reading(monkeypatch):
    import time

    from relevance_plan.errors import OutOfTimeError

    domain = read_domain(DOMAIN)
    atoms = "\n".join("    (at a b) (free c)" for _ in range(5000))
    monkeypatch.setattr(parser, "FLAT_INIT_FROM", 1)
    text = problem(atoms)
    stretches = parser._one_stretch(text, parser._init_body(text))
    assert stretches is not None
    known = {"home": "thing", "a": "thing", "b": "thing", "c": "thing"}
    scope = parser._Scope(domain.types, domain.predicates, domain.functions, known, {}, in_problem=True)
    with pytest.raises(OutOfTimeError):  # while reading the atoms
        plain = parser._plain_atoms(text, stretches)
        parser._read_flat_init(plain, scope, {"a": "thing", "b": "thing", "c": "thing"}, "p.pddl", 0.0)
    with pytest.raises(OutOfTimeError):  # and through the whole reading: not read again in full
        read_problem(problem(atoms), domain, path="p.pddl", deadline=time.monotonic() - 1)


def test_a_skipped_part_leaves_the_offsets_and_lines_after_it(monkeypatch):
    from relevance_plan.pddl.sexpr import Node, parse_sexpr

    def walk(item):
        yield type(item).__name__, item.start, item.end, item.line, getattr(item, "text", None)
        for inner in getattr(item, "items", ()):
            yield from walk(inner)

    for line_break in ("\n", "\r\n", "\r"):
        lines = [
            "(define (problem p)",
            "  (:init",
            "    (at a b)",
            "",
            "    (free c)",
            "  )",
            "  (:goal",
            "   (at a b)))",
        ]
        text = line_break.join(lines)
        start, end = text.index("(at"), text.index("(free c)") + len("(free c)")
        full, skipped = parse_sexpr(text), parse_sexpr(text, skip=[(start, end)])
        init = skipped.items[2]
        assert isinstance(init, Node) and [getattr(i, "text", None) for i in init.items] == [":init"]
        assert list(walk(skipped.items[3])) == list(walk(full.items[3]))  # the goal, on line 7
        assert skipped.items[3].line == 7
        two = [(start, start + len("(at a b)")), (text.index("(free c)"), end)]  # two parts, a blank line kept
        assert list(walk(parse_sexpr(text, skip=two).items[3])) == list(walk(full.items[3]))


def test_cutting_most_of_a_big_init_keeps_the_rest_and_its_layout():
    """200 facts on lines of their own, a pair on one line, blank lines between runs: the cut facts'
    lines go in runs, the blank lines and the kept facts stay as they were."""
    from relevance_plan.pddl.writer import write_pruned_problem

    domain = read_domain(DOMAIN)
    names = [f"o{i}" for i in range(200)]
    body = []
    for i, name in enumerate(names):
        body.append(f"    (free {name})" if i % 50 else "")
        if i == 120:
            body.append(f"    (at {name} o7) (free {names[i + 1]})")  # kept beside cut
    text = "\n".join(
        ["(define (problem p) (:domain d)", f"  (:objects {' '.join(names)} - thing)", "  (:init", *body, "  )"]
        + ["  (:goal (at o7 o7)))"]
    )
    problem = read_problem(text, domain)
    kept = {"o7", "o120", "o199"}
    pruned = write_pruned_problem(problem, kept)
    again = read_problem(pruned, domain)
    assert again.init == {atom for atom in problem.init if set(atom[1:]) <= kept}
    init_lines = pruned[pruned.index("(:init") : pruned.index("(:goal")].splitlines()[1:-2]
    assert init_lines.count("") == 4  # the user's blank lines (where o0, o50, o100, o150 would be)
    assert [line for line in init_lines if line] == [
        "    (free o7)",
        "    (free o120)",
        "    (at o120 o7)",
        "    (free o199)",
    ]


def test_a_run_of_cuts_that_starts_and_ends_on_kept_lines_takes_only_the_lines_it_fills():
    """The first fact shares its line with '(:init', the last with the list's ')': those lines keep
    what is not cut, the lines between go whole."""
    from relevance_plan.pddl.writer import apply_cuts

    facts = [f"(free o{i})" for i in range(6)]
    text = "(:init " + facts[0] + "\n" + "\n".join("  " + f for f in facts[1:5]) + "\n  " + facts[5] + ")\n"
    cuts = [(text.index(f), text.index(f) + len(f)) for f in facts]
    assert apply_cuts(text, cuts) == "(:init\n  )\n"
    keep_last = apply_cuts(text, cuts[:-1])
    assert keep_last == "(:init\n  (free o5))\n"


def test_the_facts_come_in_the_files_order_or_sorted_once_changed(monkeypatch):
    """What the fact index, the scene and the exploration iterate: never a set's order."""
    domain = read_domain(DOMAIN)
    for threshold in (1, 10**9):  # the string-method reading and the full one
        monkeypatch.setattr(parser, "FLAT_INIT_FROM", threshold)
        read = read_problem(problem("    (free c) (at b a)\n    (at a b) (free c) (ready)"), domain)
        assert list(read.facts_in_order()) == [("free", "c"), ("at", "b", "a"), ("at", "a", "b"), ("ready",)]
    changed = dataclasses.replace(read, init=read.init | {("free", "a")})
    assert list(changed.facts_in_order()) == sorted(changed.init)


COST_DOMAIN = """(define (domain d) (:requirements :strips :typing :action-costs :timed-initial-literals)
  (:types thing)
  (:predicates (at ?x - thing ?y - thing) (free ?x - thing))
  (:functions (total-cost) - number (cost ?x - thing) - number)
  (:action go :parameters (?x - thing ?y - thing) :precondition (free ?x)
    :effect (and (at ?x ?y) (increase (total-cost) (cost ?x)))))"""


@pytest.mark.parametrize(
    "entries",
    [
        ["(= (total-cost) 0)", "", ""],  # the usual action-cost start
        ["", "(not (free c))", ""],
        ["(= (cost a) 2)", "(= (cost b) 3) (not (at a a))", "(at 10 (free b))\n(= (cost c) 1)"],
        ["", "", "(not (free a))"],  # an entry ends the body
        ["(not (free c))", "", ""],  # its '))' before any atom
        ["", "(= (cost a) 2) (gone a)", ""],  # an unknown predicate: the full reading's error
        ["", "(= (cost a) two)", ""],
        ["", "(not (free a)", ""],  # never closed
    ],
)
def test_entries_between_plain_atoms_read_the_same(monkeypatch, entries):
    """A big :init with numeric values, negative and timed literals among its plain atoms: the atoms
    between them are read as stretches, to the same problem (or the same error) as the full reading."""
    domain = read_domain(COST_DOMAIN)
    atoms = "\n".join(f"    (at a b) (free c)\n    (at b {name})" for name in ("a", "b", "c") * 400)
    init = "\n".join([f"    {entries[0]}", atoms, f"    {entries[1]}", atoms, f"    {entries[2]}"])
    text = problem(init)
    fast, full = both(monkeypatch, text, domain)
    same(fast, full)
    if isinstance(full, Exception):
        return
    from relevance_plan.pddl.sexpr import parse_sexpr

    read: list[list[tuple[int, int]]] = []
    plain_atoms = parser._plain_atoms
    monkeypatch.setattr(
        parser, "_plain_atoms", lambda text, stretches: read.append(stretches) or plain_atoms(text, stretches)
    )
    monkeypatch.setattr(parser, "FLAT_INIT_FROM", 2000)
    same(read_problem(text, domain, path="p.pddl"), full)
    between = len(parse_sexpr("(" + " ".join(entries) + ")").items)  # the entries holding a list
    assert len(read[-1]) == 1 + between  # read as the stretches between them


@pytest.mark.parametrize("atoms, entries, by_stretches", [(6000, 2500, True), (2500, 6000, False)])
def test_entries_outnumbering_the_atoms_are_read_in_full(atoms, entries, by_stretches):
    """Finding and reading an entry between stretches costs more than in the full reading, an atom
    less: with more than one entry for two atoms, the whole :init goes to the full reading."""
    init = "\n".join(["    (at a b)"] * atoms + ["    (not (free c))"] * entries)
    text = problem(init)
    stretches = parser._stretches_between_entries(text, parser._init_body(text))
    assert (stretches is not None) is by_stretches
    domain = read_domain(COST_DOMAIN)
    assert read_problem(text, domain, path="p.pddl").init == {("at", "a", "b")}
