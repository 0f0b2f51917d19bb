"""The task's analyses: what every stage reads of a domain and a problem, computed once per task.

Nothing here grounds an action or knows a score.  From the bottom up (each module imports only
modules listed before it)::

    facts.py             the facts indexed by predicate and by object; functional positions
    invariants.py        positions at which no action gives an object one more fact
    types.py             classes inferred for untyped domains; static predicates
    soundness.py         the objects a quantifier ranges over, which pruning must keep
    object_states.py     the states one object of a type can be in (a sound over-approximation)
    distances.py         the object graph: hops through linking facts, walks and their bounds
    constraint_rules.py  the facts that tie one object to another (what closure follows)
    goal_regression.py   the goal regressed through the schemas: the types that can play a role
    witnesses.py         class goals: the objects a goal atom or an existential is met through
    witness_proof.py     the proof that a goal needs more witnesses than the problem has
    task.py              PlanningTask: a domain and problem with the analyses every stage shares
"""
