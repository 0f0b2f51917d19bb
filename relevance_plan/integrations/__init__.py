"""Front ends for other tools: ``up_engine``, the unified-planning meta-engine ``relevance[<planner>]``
that prunes in front of any one-shot planner, through the same attempt loop as ``plan``."""
