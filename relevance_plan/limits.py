"""The time limits every front end shares: the default ``--timeout`` and the largest one taken.

Nothing is imported here: the launcher's head start reads these before the
rest of the tool is imported, and ``plan``, ``compare``, ``watch``, the
Fast Downward adapter and the head start must agree on them.
"""

DEFAULT_TIMEOUT = 120.0  # seconds for a run (a batch job) when no --timeout is given
# Limits beyond this are typos: the watchdog's timer cannot even hold much more.
MAX_TIMEOUT = 1e6
