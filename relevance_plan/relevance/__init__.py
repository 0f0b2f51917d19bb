"""Relevance: which objects of a planning task an attempt keeps, and why.

Its folders are the stage's pipeline, from the bottom up (each imports only those listed before it;
``pyproject.toml``'s import contract checks it):

    analysis/       the task's analyses: PlanningTask, the facts' index, distances, constraint
                    rules, the goal's regression, types, witnesses and their proof, soundness
    reachability/   relaxed reachability on a kept set: the join schemas, the exploration, its
                    relaxed plan, and the sharper check for temporal and numeric problems
    scoring/        the scene, the knowledge model, words mapped to its names, the scorers, the
                    learned scorer, relevance quality
    selection/      from scores to kept objects: closure, the repair, the prune stages, each
                    object's decision, the completion for negative preconditions
    setup.py        one scoring set-up for every front end: a scorer, then the selection
    drafting/       a knowledge model drafted from a domain's schemas and problems, checked on them

Reachability and scoring do not import each other.  Selection reads both: it keeps objects by
their scores (``ScoreResult``, the knowledge model's dependencies and classes) and repairs a kept
set the relaxed check refutes.  The set-up wires a scorer to the selection, and drafting checks
its drafts through the set-up, so both sit on top.
"""
