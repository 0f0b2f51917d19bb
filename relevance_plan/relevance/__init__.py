"""Relevance: which objects of a planning task an attempt keeps, and why.

Its modules from the bottom up (each imports only modules listed before it):

    analysis.py          the initial facts' index, constraint rules, the goal's roles, distances
    types.py             classes inferred for untyped domains; static predicates
    witnesses.py         class goals: the objects a goal atom or an existential is met through
    object_states.py     the states one object of a type can be in (a sound over-approximation)
    witness_proof.py     the proof that a goal needs more witnesses than the problem has
    soundness.py         the objects a quantifier ranges over, which pruning must keep
    task.py              PlanningTask: a domain and problem with the analyses every stage shares
    scene.py             the scene a knowledge model scores: elements, kinds, places
    knowledge.py         the knowledge model (YAML): classes, tasks, objectives, humans, dependencies
    text/                free text mapped to a knowledge model's names (the ``text`` extra, loaded on use)
    scorers/             one function per scorer (goal, model, random, oracle), in SCORERS
    learning/            the learned scorer: features, the learned model, its fit
    sidecar.py           the generator's ground truth for a problem (the oracle's answer)
    metrics.py           relevance quality against that ground truth
    closure.py           constraint closure: what the kept objects depend on, and why
    exploration.py       relaxed reachability on a kept set: the sufficiency check
    timed_relaxation.py  the sharper check for temporal and numeric problems
    repair.py            the repair: what a failing selection lacks, found by growing it
    prune.py             select -> close -> set aside -> repair -> finish; widening
    decisions.py         each object's decision, named by the step that made it
    completion.py        a first selection completed for the negative preconditions the check passes over
    setup.py             one scoring set-up for every front end
    drafting/            a knowledge model drafted from a domain's schemas and problems, checked on them
"""
