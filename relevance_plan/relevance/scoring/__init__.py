"""Scoring: how relevant each object of a planning task is, with the reason.

From the bottom up (each module imports only modules listed before it)::

    scene.py               the scene a knowledge model scores: elements, kinds, places
    knowledge.py           the knowledge model (YAML): classes, activities, objectives, humans,
                           dependencies
    word_matching.py       a person's words mapped to a knowledge model's names by meaning (the
                           sentence encoder is ``relevance_plan.text``, loaded on use)
    word_understanding.py  those words where the model expects a name, or a question
    scorers/               one function per scorer (goal, model, random, oracle), in SCORERS
    learning/              the learned scorer: features, the learned model, its fit
    metrics.py             relevance quality against the generator's ground truth

The scoring set-up a front end calls (``relevance.setup``) sits above the selection, which reads
the scores: it is not in this package.
"""
