"""The hostile sweep: the tool run as a separate process against hostile surroundings, by behaviour.

``scenario`` says what a scenario is, ``inputs`` holds the files and pieces
scenarios are built from, ``harness`` runs and judges one; each
``test_*.py`` module lists the scenarios of one behaviour (outputs,
processes, deadlines and floods, the live session, messages, temporal and
numeric inputs, stores and models, the other commands, supervision faults,
learn and its models, unified-planning's engines, Dask, hostile plans)
and ``test_inputs`` feeds hostile files to every command in this process.
The quick scenarios run by default; the others are marked ``slow``
(``python -m pytest tests/hostile --runslow`` runs all of them).
"""
