"""Tiny kitchen problems built in code for the tests, and edits of their goal."""

from __future__ import annotations

from relevance_plan.pddl.formatter import format_problem_parts

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
