"""Process supervision: planners and workers run contained, and nothing is left behind.

- ``guard``: the small guard process that leads a planner's session, keeps
  its memory limit and cgroup, and kills the group when the tool's pipe closes;
- ``spawn``: starting a command under the guard, and usable cores;
- ``process``: one planner run as a process group (watchdog, wait, reap,
  logs), scratch directories and cancel scopes.

Used by ``planning`` (its planners, and VAL's ``Validate`` in
``planning/validation``) and ``batch`` alike; imports nothing of the pipeline.
"""
