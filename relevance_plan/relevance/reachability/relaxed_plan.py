"""The relaxed plan: the steps that reach the goal, walked back from it through each fact's first achiever."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

from relevance_plan.pddl.formulas import GroundAtom
from relevance_plan.relevance.reachability.schemas import Binding, JoinSchema, Step


@dataclass(frozen=True)
class Achiever:
    """The ground step that first reached a fact, with its schema and binding (to walk back from)."""

    step: Step
    schema: JoinSchema
    binding: Binding


def relaxed_plan(
    facts: Mapping[GroundAtom, Achiever | None], goal: Sequence[GroundAtom]
) -> tuple[list[Step], set[str]]:
    """The steps that first reached ``goal``'s facts and the conditions they need, back to the initial
    facts (those without an achiever), in the order a plan takes them; and the objects they name."""
    plan: list[Step] = []
    objects: set[str] = set()
    done: set[GroundAtom] = set()
    stack = list(goal)
    seen_steps: set[Step] = set()
    while stack:
        fact = stack.pop()
        if fact in done:
            continue
        done.add(fact)
        objects.update(fact[1:])
        achiever = facts.get(fact)
        if achiever is None:
            continue
        step, schema, binding = achiever.step, achiever.schema, achiever.binding
        if step in seen_steps:
            continue
        seen_steps.add(step)
        plan.append(step)
        objects.update(a for a in step[1:] if a != "?")
        for predicate, args in schema.pre:
            stack.append((predicate,) + tuple(binding.get(a, a) for a in args))
    plan.reverse()
    return plan, objects
