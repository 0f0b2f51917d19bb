"""The planning methods, one spelling each: what ``--method`` takes, what results and stores say.

A :class:`Method` is a ``str``: it equals, hashes, prints and serialises as its
value (``Method.PURE == "pure"``), so a method read back from a results store
or a JSON file compares with it directly.  What a method does is asked of it
(:attr:`Method.prunes`, :attr:`Method.narrows_first`), never of its spelling.

This module imports only ``enum``: the launcher's head start reads the method
before the rest of the tool is imported.
"""

from __future__ import annotations

import enum


class Method(str, enum.Enum):
    """How one problem is planned.  These values are stored in results stores: never respell them."""

    RELEVANCE = "relevance"  # the knowledge-model scorer when a model applies, else the goal scorer
    PURE = "pure"  # the planner on the original problem
    RANDOM = "random"  # the paper's baseline: a random selection of the relevance method's size
    ORACLE = "oracle"  # the generator's necessary set

    def __str__(self) -> str:
        return self.value

    def __format__(self, spec: str) -> str:
        return format(self.value, spec)

    @property
    def prunes(self) -> bool:
        """Whether the method chooses objects at all (every method but ``pure``)."""
        return self is not Method.PURE

    @property
    def narrows_first(self) -> bool:
        """Whether the first selection is narrowed (goal filter, blocked alternatives set aside),
        and the tool's own verdicts (a proof that no plan exists) are given: ``relevance`` only;
        the baselines plan as the paper's did."""
        return self is Method.RELEVANCE


# The --method choices, in the order reports list them.
METHODS: tuple[str, ...] = tuple(method.value for method in Method)
