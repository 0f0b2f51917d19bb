"""Classic benchmark domains padded with objects the goal does not need.

Used to show that pruning without a knowledge model (the goal scorer) pays
off on domains we did not design: blocksworld with extra towers and blocks
stacked on the goal's blocks, gripper with extra balls.  The worlds live in
the package (``relevance_plan.generators.padded``); this script prints them.

Run as a script, it prints one padded problem (or its domain) as PDDL, to
look at or to hand to a planner; it measures nothing and takes no time.

    python benchmarks/padded_worlds.py blocksworld 60 > blocks-60.pddl
    python benchmarks/padded_worlds.py blocksworld --domain > blocksworld.pddl
"""

from __future__ import annotations

import argparse

from relevance_plan.generators.padded import (
    BLOCKSWORLD_DOMAIN,
    GRIPPER_DOMAIN,
    blocksworld_problem,
    gripper_problem,
)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("world", choices=("blocksworld", "gripper"))
    parser.add_argument("extra", nargs="?", type=int, default=60, help="objects the goal does not need (default: 60)")
    parser.add_argument("--seed", type=int, default=1, help="seed of the blocksworld towers (default: 1)")
    parser.add_argument("--domain", action="store_true", help="print the domain instead of a problem")
    args = parser.parse_args(argv)
    if args.world == "blocksworld":
        print(BLOCKSWORLD_DOMAIN if args.domain else blocksworld_problem(args.extra, seed=args.seed, in_the_way=3))
    else:
        print(GRIPPER_DOMAIN if args.domain else gripper_problem(args.extra))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
