"""``python -m relevance_plan``: the ``relevance-plan`` command."""

from relevance_plan.cli import main

main(prog_name="relevance-plan")
