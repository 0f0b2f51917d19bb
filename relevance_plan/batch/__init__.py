"""Batch runs over suites, in three steps: run (``compare``) → store → report.

``suites`` (a suite folder's problems and their domains), ``keys`` (what
makes two jobs the same), ``jobs`` (one job and how it runs), ``rows`` (a
finished job as a store row), ``executors`` (local threads, Dask),
``compare`` (the run step), ``store`` (SQLite), ``report`` (tables),
``html_report`` (the report as one page), ``plots`` (figures from the
tables), ``sweep`` (relevance quality over a threshold grid), ``learn``
(the learned scorer's training runs) and ``demo`` (all of it on two small
generated suites).
"""
