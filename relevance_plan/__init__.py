"""relevance-plan: prune what does not matter, then plan."""

__version__ = "0.3.0"
