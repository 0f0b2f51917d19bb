"""Planning: the attempt loop over object selections, with every plan validated on the original problem.

- ``methods``: the planning methods (``Method``: relevance, pure, random,
  oracle), one spelling each;
- ``options``: the one options object every front end builds (``PlanOptions``);
- ``attempts``: the one attempt loop every front end calls (``run_attempts``):
  one attempt, its plan validated, widening between attempts, budgets;
- ``run``: one problem from its files to its result (``plan_task``);
- ``summary``: a run's attempts summed up as one result (``summarise`` of a
  run's ``RunFacts``);
- ``results``: the records of a run (``PlanResult``, ``Attempt``) and the
  chain of statuses from a planner's run to the problem's verdict;
- ``race``: the full problem planned beside the pruned attempts, first valid
  answer wins;
- ``validation/``: the plan validators (the builtin simulator's entry point,
  VAL's adapter, unified-planning's) that check a plan on the original
  problem, and their registry;
- ``planners/``: the planner adapters behind one protocol, the registry the
  CLI reads, the choice of a planner by the problem's features, and
  ``supply``, where a run obtains its planner once.

Process supervision (the guard, spawning, process groups) lives below, in
:mod:`relevance_plan.supervision`, which ``batch`` uses too.
"""
