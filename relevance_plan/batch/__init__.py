"""Batch runs over suites, in three steps: run (``compare``) → store → report.

``keys`` (what makes two jobs the same), ``jobs`` (one job and how it runs),
``rows`` (a finished job as a store row), ``executors`` (local threads, Dask),
``compare`` (the run step), ``store`` (SQLite), ``report`` (tables),
``plots`` (figures from the tables), ``sweep`` (relevance quality over a
threshold grid) and ``demo`` (all of it on two small generated suites).
"""
