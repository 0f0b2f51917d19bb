"""The ``relevance-plan`` command: the only place that prints for the user and exits."""

from relevance_plan.cli.app import main

__all__ = ["main"]
