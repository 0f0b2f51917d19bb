"""Relaxed reachability: whether a kept set of objects can reach the goal, deletes ignored.

The cheap reachability check every selection passes before a planner runs ("unreachable" is a
proof: no plan exists on those objects).  From the bottom up (each module imports only modules
listed before it)::

    budget.py            the work a check may do, and the one exception that ends it
    schemas.py           the task's relaxed actions compiled to join schemas (once per task):
                         disjunctive ways, the shared class, dominated and saturable schemas
    relaxed_plan.py      each fact's first achiever, walked back from the goal
    joins.py             the processed facts, indexed for the joins
    members.py           a shared class's members following the placeholder's steps
    exploration.py       the exploration itself: relaxed_reachability, and Exploration on a set
                         that grows
    timed_relaxation.py  the sharper check for temporal and numeric problems

What uses the check to grow a selection (the repair, the completion) is selection's.
"""
