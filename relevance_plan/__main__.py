"""``python -m relevance_plan``: the ``relevance-plan`` command."""

from relevance_plan.cli.launch import main

main()
