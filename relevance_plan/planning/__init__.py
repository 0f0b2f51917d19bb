"""Planning: the attempt loop over object selections, with every plan validated on the original problem.

- ``loop``: the one attempt loop every front end calls (``plan_task``,
  ``run_attempts``), its options (``PlanOptions``) and result records
  (``PlanResult``, ``Attempt``, ``PlanStatus``);
- ``race``: the full problem planned beside the pruned attempts, first valid
  answer wins;
- ``validate``: the plan validators (the builtin simulator, VAL,
  unified-planning's) that check a plan on the original problem;
- ``planners/``: the planner adapters behind one protocol, the registry the
  CLI reads, and the choice of a planner by the problem's features.

Process supervision (the guard, spawning, process groups) lives below, in
:mod:`relevance_plan.supervision`, which ``batch`` uses too.
"""
