"""Turn problem data into PDDL text (the generator's writer).

The pruning path never re-formats a user's file (see ``writer.py``); this
formatter is for problems we create ourselves, so every suite we write has
one layout.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence

Atom = Sequence[str]


def format_atom(atom: Atom) -> str:
    return "(" + " ".join(atom) + ")"


def format_problem(
    name: str,
    domain: str,
    objects: Mapping[str, Sequence[str]],
    init: Iterable[Atom],
    goal: Iterable[Atom],
    comment: str | None = None,
) -> str:
    """Return a typed PDDL problem; ``objects`` maps a type to its object names."""
    lines: list[str] = []
    if comment:
        lines.extend("; " + line if line else ";" for line in comment.splitlines())
    lines.append(f"(define (problem {name})")
    lines.append(f"  (:domain {domain})")
    lines.append("  (:objects")
    for type_name, names in objects.items():
        if names:
            lines.append("    " + " ".join(names) + f" - {type_name}")
    lines.append("  )")
    lines.append("  (:init")
    lines.extend("    " + format_atom(atom) for atom in init)
    lines.append("  )")
    goal_atoms = [format_atom(atom) for atom in goal]
    lines.append("  (:goal (and")
    lines.extend("    " + text for text in goal_atoms)
    lines.append("  ))")
    lines.append(")")
    return "\n".join(lines) + "\n"
