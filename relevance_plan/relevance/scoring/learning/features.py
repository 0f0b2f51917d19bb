"""Per-object relational features, identical for a problem whatever the order of its objects.

The graph: objects (and the domain's constants) are nodes; every initial fact
and every goal literal of two or more arguments links each pair of its
arguments, the link labelled with its kind (init, goal, goal-negated), the
predicate and both argument positions.  Unary facts are part of a node's
first colour, with its type and whether the goal names it.  Weisfeiler-Leman
refinement then gives each object, at each round, a colour that sums up its
neighbourhood that many links deep; a round's colour is the old one with the
*set* of (link label, neighbour colour) pairs, so that a location with forty
packages and one with four look alike, as they should to a model learned on
small problems and applied to large ones.

An object's features are sparse: a few named ones (goal-named, the goal
scorer's score, hops from the goal's objects) and hashed ones (its type and
its ancestors, its colour at each round, and the colours of its neighbours by
link label), each hashed with BLAKE2b of its text into ``buckets`` slots.
Nothing depends on Python's per-process ``hash()`` or on the order of sets.
"""

from __future__ import annotations

import hashlib
import math
from collections import Counter, defaultdict
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass

from relevance_plan.pddl.formulas import literals
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.scoring.scorers.base import ScoreRequest
from relevance_plan.relevance.scoring.scorers.goal import score_by_goal

Features = dict[int, float]  # feature index -> value (absent: 0)

# The named features, then the hashed ones from NAMED on.
BIAS, GOAL_NAMED, GOAL_SCORE, GOAL_ZERO, PINNED = 0, 1, 2, 3, 4
DISTANCE = 5  # one-hot: 0, 1, 2, 3, 4 or more hops, unreached (DISTANCE .. DISTANCE + 5)
NAMED = DISTANCE + 6
# A predicate with more initial facts than this many per object links nearly every pair of its
# objects: it marks the positions each object fills instead of linking pairs, which would cost the
# square of the objects and tell the model nothing a marker does not.
HUB = 4
NAMED_FEATURES = (
    "bias",
    "goal-named",
    "goal-score",
    "goal-score-zero",
    "pinned",
    "hops-0",
    "hops-1",
    "hops-2",
    "hops-3",
    "hops-4+",
    "unreached",
)


@dataclass(frozen=True)
class FeatureConfig:
    iterations: int = 3
    buckets: int = 4096
    hubs: frozenset[str] = frozenset()  # predicates marked, not linked, on every problem (see HUB)

    def to_json(self) -> dict[str, object]:
        return {
            "kind": "wl-objects",
            "iterations": self.iterations,
            "buckets": self.buckets,
            "hash": "blake2b-64",
            "hubs": sorted(self.hubs),
        }


@dataclass(frozen=True)
class ObjectFeatures:
    """Every object's features, and what the scorer needs besides."""

    vectors: Mapping[str, Features]
    goal_scores: Mapping[str, float]
    alternatives: frozenset[str]  # the goal scorer's: candidates of a populous role (ScoreResult.alternatives)
    types: Mapping[str, tuple[str, ...]]  # each object's type and its ancestors
    predicates: Mapping[str, frozenset[str]]  # the predicates of the facts naming each object


def stable_hash(text: str) -> int:
    return int.from_bytes(hashlib.blake2b(text.encode("utf-8"), digest_size=8).digest(), "big")


def _bucket(text: str, config: FeatureConfig) -> int:
    return NAMED + stable_hash(text) % config.buckets


def goal_facts(task: PlanningTask) -> list[tuple[str, tuple[str, ...]]]:
    """(kind, atom) of each goal literal naming objects only: kind 'goal' or 'goal-not'."""
    known = task.problem.objects.keys() | task.domain.constants.keys()
    found = []
    for atom, positive in literals(task.problem.goal):
        if all(arg in known for arg in atom.args):
            found.append(("goal" if positive else "goal-not", (atom.predicate, *atom.args)))
    return found


def hub_predicates(task: PlanningTask) -> frozenset[str]:
    """Initial-state predicates of two or more arguments with more than ``HUB`` facts per object
    (``not-eq`` between every two locations, ``above`` between every two floors)."""
    nodes = len(task.problem.objects) + len(task.domain.constants)
    return frozenset(
        predicate
        for predicate, atoms in task.init_index.by_predicate.items()
        if atoms and len(atoms) > HUB * max(nodes, 1) and len(next(iter(atoms))) > 2
    )


def _facts(task: PlanningTask, hubs: frozenset[str] = frozenset()) -> Iterable[tuple[str, tuple[str, ...]]]:
    for predicate, atoms in task.init_index.by_predicate.items():
        if predicate in hubs:
            continue
        for atom in atoms:
            if atom[0] == predicate:
                yield "init", atom
    yield from goal_facts(task)


@dataclass(frozen=True)
class _FactGraph:
    """Objects and constants as nodes, linked by the facts that name two of them (see the module's docstring)."""

    nodes: frozenset[str]
    unary: Mapping[str, set[str]]  # node -> the labels of its unary facts and of the hub positions it fills
    links: Mapping[str, set[tuple[int, str]]]  # node -> {(link label, neighbour)}
    predicates: Mapping[str, set[str]]  # node -> the predicates of the facts naming it


def object_features(task: PlanningTask, config: FeatureConfig, only_judged: bool = False) -> ObjectFeatures:
    """The features of every object of ``task`` (``FeatureConfig`` says how many rounds and slots).

    With ``only_judged``, the objects a model never judges (the goal's, and those the goal scorer
    rules out) get their named features only: the scorer decides them without the model.
    """
    objects = task.typing.problem.objects
    graph = _fact_graph(task, config.hubs | hub_predicates(task))
    task.check_time("describing the objects")
    types = _types_and_ancestors(task, graph.nodes)
    goal_result = score_by_goal(task, ScoreRequest())
    goal_scores = goal_result.element_scores
    described = [
        name
        for name in objects
        if not only_judged or (name not in task.goal_objects and goal_scores.get(name, 0.0) != 0.0)
    ]
    vectors: dict[str, Features] = {name: {} for name in objects}
    _add_type_features(vectors, described, types, config)
    _add_colour_features(task, vectors, described, graph, _first_colours(task, graph, types), config)
    _add_named_features(task, vectors, goal_scores)
    return ObjectFeatures(
        vectors,
        goal_scores,
        goal_result.alternatives,
        {name: types[name] for name in objects},
        {name: frozenset(graph.predicates.get(name, ())) for name in objects},
    )


def _fact_graph(task: PlanningTask, hubs: frozenset[str]) -> _FactGraph:
    """The graph of initial and goal facts; a hub predicate marks the positions each object fills."""
    nodes = frozenset(task.typing.problem.objects) | frozenset(task.typing.domain.constants)
    unary: dict[str, set[str]] = defaultdict(set)
    links: dict[str, set[tuple[int, str]]] = defaultdict(set)
    predicates: dict[str, set[str]] = defaultdict(set)
    labels: dict[tuple[str, str, int, int], int] = {}
    for predicate in sorted(hubs & task.init_index.by_predicate.keys()):
        # a hub's facts link (nearly) every pair: which positions an object fills says all they say
        atoms = task.init_index.by_predicate[predicate]
        if not atoms:
            continue
        for position in range(1, len(next(iter(atoms)))):
            for arg in {atom[position] for atom in atoms}:
                predicates[arg].add(predicate)
                unary[arg].add(f"init:{predicate}@{position - 1}")
    for kind, atom in _facts(task, hubs):
        args = atom[1:]
        for arg in args:
            predicates[arg].add(atom[0])
        if len(args) == 1:
            unary[args[0]].add(f"{kind}:{atom[0]}")
            continue
        for i, here in enumerate(args):
            for j, there in enumerate(args):
                if i != j and here in nodes and there in nodes:
                    key = (kind, atom[0], i, j)
                    label = labels.get(key)
                    if label is None:
                        label = labels[key] = stable_hash(f"{kind}:{atom[0]}:{i}:{j}")
                    links[here].add((label, there))
    return _FactGraph(nodes, unary, links, predicates)


def _types_and_ancestors(task: PlanningTask, nodes: Iterable[str]) -> dict[str, tuple[str, ...]]:
    """Each node's declared type and its ancestors."""
    domain, objects = task.typing.domain, task.typing.problem.objects
    ancestors: dict[str, tuple[str, ...]] = {}
    types = {}
    for name in nodes:
        declared = objects[name] if name in objects else domain.constants[name]
        types[name] = ancestors.get(declared) or ancestors.setdefault(declared, domain.ancestors(declared))
    return types


def _first_colours(task: PlanningTask, graph: _FactGraph, types: Mapping[str, tuple[str, ...]]) -> dict[str, int]:
    """Each node's colour before any round: its type, its unary facts, whether the goal names it."""
    goal_named, constants = task.goal_objects, task.typing.domain.constants
    # a constant is the same object in every problem of the domain: its name is part of its colour
    return {
        name: stable_hash(
            f"{types[name][0]}|{','.join(sorted(graph.unary.get(name, ())))}|{'goal' if name in goal_named else ''}"
            + (f"|{name}" if name in constants else "")
        )
        for name in graph.nodes
    }


def _add_type_features(
    vectors: dict[str, Features], described: Iterable[str], types: Mapping[str, tuple[str, ...]], config: FeatureConfig
) -> None:
    """A slot for each described object's type and one for each of its ancestors."""
    type_slots: dict[tuple[str, ...], tuple[int, ...]] = {}
    for name in described:
        slots = type_slots.get(types[name])
        if slots is None:
            first, *rest = types[name]
            slots = type_slots[types[name]] = (
                _bucket(f"type:{first}", config),
                *(_bucket(f"ancestor:{ancestor}", config) for ancestor in rest),
            )
        vector = vectors[name]
        for slot in slots:
            _add(vector, slot, 1.0)


Neighbourhood = tuple[tuple[int, int], ...]  # sorted (link label, neighbour colour) pairs, repeats kept


def _add_colour_features(
    task: PlanningTask,
    vectors: dict[str, Features],
    described: Sequence[str],
    graph: _FactGraph,
    colour: dict[str, int],
    config: FeatureConfig,
) -> None:
    """The Weisfeiler-Leman rounds: each described object's colour at each round and, but in the last
    round, its neighbours' colours by link label."""
    adjacent = {name: sorted(graph.links.get(name, ())) for name in graph.nodes}
    refined: dict[tuple[int, Neighbourhood], int] = {}
    for round_number in range(config.iterations + 1):
        if round_number == config.iterations:
            _add_round(vectors, described, colour, {}, round_number, config)
            break
        seen = {
            name: tuple(sorted([(label, colour[other]) for label, other in adjacent[name]])) for name in graph.nodes
        }
        _add_round(vectors, described, colour, seen, round_number, config)
        colour = {name: _refined(colour[name], seen[name], refined) for name in graph.nodes}
        task.check_time("describing the objects")


def _add_round(
    vectors: dict[str, Features],
    described: Sequence[str],
    colour: Mapping[str, int],
    seen: Mapping[str, Neighbourhood],
    round_number: int,
    config: FeatureConfig,
) -> None:
    """One round's slots for each described object (``seen`` empty: its colour only)."""
    # Objects alike so far get the same features and the same next colour: each distinct
    # (colour, neighbourhood) is hashed once, which on large problems is most of the work saved.
    contributions: dict[tuple[int, Neighbourhood], tuple[tuple[int, float], ...]] = {}
    for name in described:
        seen_key = (colour[name], seen.get(name, ()))
        found = contributions.get(seen_key)
        if found is None:
            found = contributions[seen_key] = (
                (_bucket(f"wl{round_number}:{colour[name]}", config), 1.0),
                *(
                    (_bucket(f"nb{round_number}:{label}:{shade}", config), math.log1p(count))
                    for (label, shade), count in Counter(seen_key[1]).items()
                ),
            )
        vector = vectors[name]
        for slot, value in found:
            _add(vector, slot, value)


def _refined(colour: int, seen: Neighbourhood, refined: dict[tuple[int, Neighbourhood], int]) -> int:
    """The next colour of a node of ``colour`` whose neighbourhood is ``seen`` (``refined`` caches them)."""
    seen_key = (colour, seen)
    shade = refined.get(seen_key)
    if shade is None:
        # the set of pairs, not their counts: forty packages at a place look like four
        shade = refined[seen_key] = stable_hash(repr((colour, sorted(set(seen)))))
    return shade


def _add_named_features(task: PlanningTask, vectors: dict[str, Features], goal_scores: Mapping[str, float]) -> None:
    """The named features: bias, goal-named, the goal scorer's score (or its zero), pinned, hops."""
    goal_named, pinned, distance = task.goal_objects, task.pinned_objects, task.goal_distance
    for name in task.typing.problem.objects:
        vector = vectors[name]
        vector[BIAS] = 1.0
        if name in goal_named:
            vector[GOAL_NAMED] = 1.0
        score = goal_scores.get(name, 0.0)
        if score:
            vector[GOAL_SCORE] = score
        else:
            vector[GOAL_ZERO] = 1.0
        if name in pinned:
            vector[PINNED] = 1.0
        hops = distance.get(name)
        vector[DISTANCE + (5 if hops is None else min(hops, 4))] = 1.0


def _add(vector: Features, index: int, value: float) -> None:
    vector[index] = vector.get(index, 0.0) + value
