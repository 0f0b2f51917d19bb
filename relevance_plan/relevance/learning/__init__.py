"""Relevance learned from solved problems: per-object features and the model that weighs them.

``features`` describes each object of a problem by its place in the graph of
initial and goal facts (Weisfeiler-Leman colours, type, goal distance, the
goal scorer's verdict); ``model`` holds a fitted logistic model in a portable
JSON file and applies it.  Training needs a planner and so lives above
(``relevance_plan.batch.learn``); scoring with a model is the ``learned``
scorer (``relevance.scorers.learned``).
"""
