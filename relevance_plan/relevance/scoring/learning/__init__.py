"""Relevance learned from solved problems: per-object features, the learned model, its fit, its scorer.

``features`` describes each object of a problem by its place in the graph of
initial and goal facts (Weisfeiler-Leman colours, type, goal distance, the
goal scorer's verdict); ``fit`` fits a logistic model on labelled problems
(with numpy); ``learned_model`` holds a fitted model in a portable JSON file
and applies it; ``scorer`` is the ``learned:MODEL`` scorer.  Labelling the
training problems needs a planner and so lives above
(``relevance_plan.batch.learn``).
"""
