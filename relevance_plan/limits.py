"""The limits every front end shares: the default ``--timeout``, the largest one taken, and the largest suites.

Nothing is imported here: the launcher's head start reads these before the
rest of the tool is imported, and ``plan``, ``compare``, ``watch``, the
Fast Downward adapter and the head start must agree on them; the command
line checks its numeric options against them (``cli.arguments.numbers``) without
importing the generators.
"""

DEFAULT_TIMEOUT = 120.0  # seconds for a run (a batch job) when no --timeout is given
# Limits beyond this are typos: the watchdog's timer cannot even hold much more.
MAX_TIMEOUT = 1e6
# Far above any benchmark; beyond, a typo would run for hours and fill the disk.
MAX_COUNT = 100_000  # problems in one generated suite
MAX_DISTRACTORS = 100_000  # distractors in one kitchen problem
