"""unified-planning engines (``up:NAME``), each run in a child process under the time limit.

- ``adapter``: :class:`UnifiedPlanningPlanner`, the engines' features and statuses;
- ``child``: the child process that reads, fits and solves (``python -m``);
- ``fitting``: rewriting a read problem into the shape an engine takes.
"""
