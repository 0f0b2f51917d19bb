"""The drafted model as YAML a person can review: every entry with a comment saying where it came from."""

from __future__ import annotations

import json
import re
from collections.abc import Sequence

from relevance_plan.relevance.drafting.draft import UNSEEN_KIND, Draft
from relevance_plan.relevance.drafting.structure import DraftedDependency
from relevance_plan.relevance.scoring.knowledge import NO_PREDICATE, SCHEMA_VERSION

# Plain YAML scalars that read back as the same string; anything else is written quoted.
_PLAIN = re.compile(r"[a-z_][a-z0-9_\-]*")
_YAML_WORDS = frozenset({"y", "n", "yes", "no", "true", "false", "on", "off", "null"})

PLACEMENT = (
    ("reachable", 1.0, "lies where the robot can take it"),
    ("in-closed-container", 0.9, "shut away until something is opened: a little less likely wanted"),
    ("covered", 0.9, "something stands on it"),
    ("stacked", 0.95, "it stands on something"),
    ("near-human", 1.0, "where the human is"),
)


def name(text: str) -> str:
    """``text`` as a YAML key or scalar that reads back as itself."""
    if _PLAIN.fullmatch(text) and text not in _YAML_WORDS:
        return text
    return json.dumps(text)


def draft_text(draft: Draft, problems: Sequence[str], notes: Sequence[str] = ()) -> str:
    """The YAML text of ``draft`` (``notes``: what the check changed or could not match, as comments)."""
    lines = _header(draft, problems, notes)
    lines += _scene(draft)
    lines += _objectives(draft)
    lines += _activities(draft)
    lines += _classes(draft)
    lines += ["", "# P(e | h, C, O): factors from where an element is; a condition not listed counts 1.", "placement:"]
    lines += [f"  {condition}: {value:g}  # {why}" for condition, value, why in PLACEMENT]
    lines += _dependencies(draft)
    return "\n".join(lines) + "\n"


def _header(draft: Draft, problems: Sequence[str], notes: Sequence[str]) -> list[str]:
    shown = ", ".join(problems[:6]) + (f" and {len(problems) - 6} more" if len(problems) > 6 else "")
    lines = [
        f"# Knowledge model drafted by 'relevance-plan draft-model' from domain '{draft.domain.name}'",
        f"# and {len(problems)} problem(s): {shown}.",
        "# A draft for a person to review: each entry says where it came from.  Rename the objectives",
        "# and describe them in your own words (free text is matched against the descriptions), and",
        "# weigh the classes as your robot's users would (schema: docs/knowledge-model.md).",
    ]
    lines += [f"# {note}" for note in notes]
    return [
        *lines,
        f"version: {SCHEMA_VERSION}",
        f"domain: {name(draft.domain.name)}",
        f"description: {json.dumps(f'drafted from the action schemas of {draft.domain.name} and its problems')}",
        "entropy_bound: 1.0",
        "# The first selection is checked for relaxed reachability and completed, as without a model:",
        "# what the robot must pass through (doors, rooms) is found there, not in the priors.",
        "reachability_check: true",
        "",
        "defaults:",
        "  unknown_class_relevance: 0.05  # an object whose class the model does not know",
        f"  kind_relevance: {UNSEEN_KIND:g}  # a kind a known class does not list",
    ]


def _scene(draft: Draft) -> list[str]:
    lines = [
        "",
        "# The predicates that say where things are, found in the action schemas ('none': the domain has none).",
        "scene:",
    ]
    for role, finding in draft.structure.roles.items():
        value = name(finding.predicate) if finding.predicate is not None else NO_PREDICATE
        lines.append(f"  {role}: {value}  # {finding.why}")
    return lines


def _objectives(draft: Draft) -> list[str]:
    lines = ["", "# One objective per set of goal predicates of the given problems, one activity each.", "objectives:"]
    for objective in draft.objectives.values():
        lines += [
            f"  {name(objective.name)}:",
            f"    # from {', '.join(objective.problems)}",
            f"    description: {json.dumps(objective.description)}",
            f"    goal_predicates: [{', '.join(name(p) for p in objective.goal_predicates)}]",
            f"    activities: {{{name(objective.name)}: 1.0}}",
        ]
    return lines


def _activities(draft: Draft) -> list[str]:
    lines = [
        "",
        "# P(class | activity, objective): high for what the goal names or a role the goal scorer filled.",
        "activities:",
    ]
    for objective in draft.objectives:
        lines.append(f"  {name(objective)}:")
        priors = sorted(
            ((c, p) for (o, c), p in draft.priors.items() if o == objective), key=lambda item: (-item[1].value, item[0])
        )
        lines += [f"    {name(c)}: {p.value:g}  # {p.why}" for c, p in priors]
        if not priors:
            lines[-1] += " {}"
    return lines


def _classes(draft: Draft) -> list[str]:
    lines = ["", "# A class per type of the problems' objects; kinds from their names.", "classes:"]
    for class_draft in draft.classes.values():
        lines += [f"  {name(class_draft.name)}:", f"    # {class_draft.why}"]
        if class_draft.types:
            lines.append(f"    types: [{', '.join(name(t) for t in class_draft.types)}]")
        if class_draft.kinds:
            lines.append(f"    kinds: [{', '.join(name(k) for k in class_draft.kinds)}]")
        if class_draft.role == "place":
            lines.append("    relevance_from: contents")
        elif class_draft.role == "person":
            lines.append("    relevance: 1.0")
        weighed = [
            (k, draft.kinds[(class_draft.name, k)]) for k in class_draft.kinds if (class_draft.name, k) in draft.kinds
        ]
        if weighed:
            lines += ["    kind_relevance:", f"      default: {UNSEEN_KIND:g}  # a kind the problems do not show"]
            lines += [f"      {name(k)}: {p.value:g}  # {p.why}" for k, p in weighed]
    return lines


def _dependencies(draft: Draft) -> list[str]:
    lines = ["", "# Keeping the object at when_kept of an initial fact keeps the one at restore (1-based)."]
    if draft.left_out:
        lines.append("# Found in the schemas, left out by the check (to use one, write it under 'dependencies:'):")
        for dependency, why in draft.left_out:
            lines += [f"#  - {line}" if i == 0 else f"#    {line}" for i, line in enumerate(_entry(dependency))]
            lines.append(f"#    ({why})")
    if not draft.dependencies:
        none = "the check needs none" if draft.left_out else "no action needs a static relation to something held"
        return [*lines, f"dependencies: []  # {none}"]
    lines.append("dependencies:")
    for dependency in draft.dependencies:
        entry = _entry(dependency)
        lines += [f"  - {entry[0]}  # {dependency.why}", *(f"    {line}" for line in entry[1:])]
    return lines


def _entry(dependency: DraftedDependency) -> list[str]:
    return [
        f"predicate: {name(dependency.predicate)}",
        f"when_kept: {dependency.when_kept + 1}",
        f"restore: {dependency.restore + 1}",
        f"reason: {json.dumps(dependency.reason)}",
    ]
