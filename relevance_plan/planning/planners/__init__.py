"""Planner adapters behind one protocol, the choice of a planner, and a run's planner obtained once.

- ``supply``: what the attempt loop imports: ``open_planners`` around a run
  (the planner made, warmed, the head start taken) and the ``SuppliedPlanner``
  for the problem read (chosen, prepared, with the race's handles);
- ``base``: the :class:`Planner` protocol, :class:`PlannerStatus` and
  :class:`RunOutcome` (one run: status, plan, cost, the planner's own words);
- ``requirements``: the PDDL features a problem uses and a planner takes;
- ``registry``: ``PLANNERS`` (kind -> adapter, what ``--planner`` offers)
  and ``make_planner``;
- ``auto``: the installed planner that takes what the problem uses, with
  its family's others in reserve;
- ``preparation``: compiling a problem down to what the chosen planner
  takes, and mapping its plan back;
- one adapter per family: ``fast_downward/`` (adapter, command line, lean
  driver, head start), ``up/`` (unified-planning engines: adapter, child
  process, warm workers, fitting), ``lpg`` (LPG-td), ``command`` (any
  planner binary, ``cmd:TEMPLATE``).

This package's ``__init__`` imports nothing: the launcher's head start
imports ``fast_downward.head_start`` before anything else.
"""
