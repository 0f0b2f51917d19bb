"""Fast Downward, from the up-fast-downward wheel.

- ``adapter``: :class:`FastDownwardPlanner`, its exit codes and plan files;
- ``command_line``: the command line for one run (the lean driver or the real one);
- ``fd_driver``: a lean stand-in for Fast Downward's driver in the plain
  translate-then-search case (imported by name in the planner's process);
- ``head_start``: the full problem's run started by the launcher before the
  tool is imported, taken over by the loop.
"""
