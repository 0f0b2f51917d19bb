"""unified-planning engines (``up:NAME``), run outside the tool's process under the time limit.

- ``adapter``: :class:`UnifiedPlanningPlanner`, the engines' features and statuses;
- ``child``: the one-shot child process that reads, fits and solves (``python -m``);
- ``worker``: the warm worker process that imports an engine once and solves every attempt;
- ``pool``: the tool's side of the workers: one per engine and run, started early, killed with the run;
- ``fitting``: rewriting a read problem into the shape an engine takes;
- ``deferred``: ConfigSpace imported on first use in the child and the worker.
"""
