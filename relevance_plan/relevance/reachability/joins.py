"""The facts an exploration has processed, indexed for its joins."""

from __future__ import annotations

from collections import defaultdict
from collections.abc import Iterable, Mapping, Sequence

from relevance_plan.pddl.formulas import GroundAtom
from relevance_plan.pddl.model import Domain
from relevance_plan.relevance.reachability.schemas import Binding, TypedCondition


class JoinIndex:
    """Processed facts by (predicate, signature) and (predicate, position, value, signature), where
    the signature is the classes of the fact's objects: a condition on a truck's place looks only
    at the facts that place a truck, not at the hundred packages that may be there too."""

    def __init__(self, domain: Domain, types_of: Mapping[str, str]):
        self.domain = domain
        self.types_of = types_of
        self.processed: dict[tuple[str | int | tuple[str, ...], ...], list[GroundAtom]] = defaultdict(list)
        self.signatures: dict[str, list[tuple[str, ...]]] = defaultdict(list)
        self.compatible_cache: dict[tuple[str, tuple[str | None, ...]], tuple[int, list[tuple[str, ...]]]] = {}

    def index(self, facts: Iterable[GroundAtom]) -> None:
        """Make ``facts`` visible to the joins, in their order (a floor's 600 ``above`` facts at once)."""
        processed, signatures, types = self.processed, self.signatures, self.types_of
        for fact in facts:
            predicate = fact[0]
            if len(fact) == 3 and fact[1] in types and fact[2] in types:  # most facts: no loop
                signature: tuple[str, ...] = (types[fact[1]], types[fact[2]])
                processed[(predicate, 0, fact[1], signature)].append(fact)
                processed[(predicate, 1, fact[2], signature)].append(fact)
            else:
                signature = tuple([types.get(arg, "object") for arg in fact[1:]])
                for position, value in enumerate(fact[1:]):
                    processed[(predicate, position, value, signature)].append(fact)
            known = signatures[predicate]
            if signature not in known:
                known.append(signature)
            processed[(predicate, signature)].append(fact)

    def compatible(self, predicate: str, types: tuple[str | None, ...]) -> list[tuple[str, ...]]:
        """The signatures of processed ``predicate`` facts whose objects fit ``types`` (None: any)."""
        seen = self.signatures.get(predicate, ())
        cached = self.compatible_cache.get((predicate, types))
        if cached is not None and cached[0] == len(seen):
            return cached[1]
        fitting = [
            signature
            for signature in seen
            if all(t is None or t == "object" or self.domain.is_subtype(c, t) for c, t in zip(signature, types))
        ]
        self.compatible_cache[(predicate, types)] = (len(seen), fitting)
        return fitting

    def smallest(self, pre: list[TypedCondition], binding: Binding) -> tuple[int, list[Sequence[GroundAtom]]]:
        """The condition whose bound arguments leave the fewest processed facts, and those facts."""
        processed = self.processed
        best = 0
        best_buckets: list[Sequence[GroundAtom]] = []
        best_size: int | None = None
        buckets: list[Sequence[GroundAtom]]
        cache, seen = self.compatible_cache, self.signatures
        for j, (predicate, args, types) in enumerate(pre):
            cached = cache.get((predicate, types))
            if cached is not None and cached[0] == len(seen.get(predicate, ())):
                signatures = cached[1]  # compatible()'s answer, without the call
            else:
                signatures = self.compatible(predicate, types)
            if len(signatures) == 1:  # the common case (typed objects), without the lists of lists
                signature = signatures[0]
                bucket: Sequence[GroundAtom] = processed.get((predicate, signature), ())
                size = len(bucket)
                for position, arg in enumerate(args):
                    if not size:
                        break
                    value = binding.get(arg, arg) if arg[0] == "?" else arg
                    if value[0] != "?":
                        fewer: Sequence[GroundAtom] = processed.get((predicate, position, value, signature), ())
                        if len(fewer) < size:
                            bucket, size = fewer, len(fewer)
                buckets = [bucket]
            else:
                buckets = [processed.get((predicate, signature), []) for signature in signatures]
                size = sum(len(bucket) for bucket in buckets)
                for position, arg in enumerate(args):
                    value = binding.get(arg, arg) if arg[0] == "?" else arg
                    if value[0] != "?" and size:
                        narrower: list[Sequence[GroundAtom]] = [
                            processed.get((predicate, position, value, sig), []) for sig in signatures
                        ]
                        narrower_size = sum(len(bucket) for bucket in narrower)
                        if narrower_size < size:
                            buckets, size = narrower, narrower_size
            if best_size is None or size < best_size:
                best, best_buckets, best_size = j, buckets, size
                if size == 0 or len(pre) == 1:
                    break
        return best, best_buckets
