"""The tool's own cost on problems it cannot prune: the bare driver vs `relevance-plan plan`, in one run.

Generates small classic problems with every movable object in the goal (the
unpadded forms of bench_classic's worlds: nearly nothing can be pruned) and
runs each as a fresh process, one after the other, ``--repeat`` times:

- ``bare``: Fast Downward's driver (``fast-downward.py --alias lama-first``),
  nothing of ours;
- ``pure``: ``relevance-plan plan --method pure`` (read, plan, validate);
- ``relevance``: ``relevance-plan plan`` with its defaults (on two or more
  cores, the full problem raced beside the pruned attempts).

Prints, per problem, the median wall time of each, the tool's overhead over
the bare driver, and whether it meets the targets: overhead <= 0.05 s + 5 %
of the bare time, and relevance <= pure x 1.1 + 0.3 s.  Every plan of ours
is validated on the original problem (a failure is a row marked FAILED).

The tool runs from this checkout (``PYTHONPATH``), with its bytecode
compiled first (``compileall``), as an installed wheel has it: where
``PYTHONDONTWRITEBYTECODE`` is set, an uncompiled checkout would recompile
every module on every run (~0.1 s that no installed copy pays).  An
editable install still costs every start its import hook (~15 ms), so
``--installed`` measures what a user has instead: the checkout built as a
wheel and installed in a new virtual environment (its dependencies taken
from this one), run through its ``relevance-plan`` script.

Takes under a minute on 2 cores with the defaults (40 s with
``--repeat 5``; ``--installed`` adds ~15 s to build and install).  Run it
alone: it measures wall time.

    python benchmarks/bench_startup.py
    python benchmarks/bench_startup.py --repeat 5 --installed
    python benchmarks/bench_startup.py --repeat 5 --worlds gripper miconic
"""

from __future__ import annotations

import argparse
import json
import statistics
import sys
import tempfile
from pathlib import Path

from base import DOMAINS, geometric_mean, run_timed
from installed import compiled_checkout, installed_environment, installed_tool

from relevance_plan.generators.classic import generate_classic_problem
from relevance_plan.planning.planners.fast_downward.command_line import find_fast_downward

# Sizes where the bare driver takes from a few tenths of a second to a few seconds.
SIZES = {"blocksworld": 20, "logistics": 40, "gripper": 40, "ferry": 40, "grid": 40, "miconic": 40}


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--worlds", nargs="+", default=list(SIZES), choices=list(SIZES))
    parser.add_argument("--repeat", type=int, default=3, help="runs of each command per problem (median)")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--installed", action="store_true", help="run a wheel of the checkout in a new venv")
    args = parser.parse_args()
    driver = find_fast_downward()
    rows = []
    with tempfile.TemporaryDirectory(prefix="bench-startup-") as scratch:
        work = Path(scratch)
        if args.installed:
            tool = installed_tool(work)
            env = installed_environment()
            print("relevance-plan as installed from a wheel of this checkout, in a new virtual environment")
        else:
            tool, env = compiled_checkout()
            print("relevance-plan from this checkout, bytecode compiled beforehand (as installed)")
        print(f"{'problem':<24} {'bare':>7} {'pure':>7} {'relev.':>7} {'overhead':>9} {'target':>7}  rel<=pure*1.1+0.3")
        for world in args.worlds:
            problem = generate_classic_problem(world, args.seed, 1, SIZES[world], dense=True)
            domain_path = DOMAINS / world / "domain.pddl"
            problem_path = work / f"{problem.name}.pddl"
            problem_path.write_text(problem.pddl_text)
            commands = {
                "bare": [sys.executable, str(driver), "--alias", "lama-first", "--plan-file", "bare.plan"],
                "pure": [*tool, "plan", "--method", "pure", "--planner", "fast-downward", "-q", "--plan-file", "p1"],
                "relevance": [*tool, "plan", "--planner", "fast-downward", "-q", "--json", "--plan-file", "p2"],
            }
            times: dict[str, list[float]] = {name: [] for name in commands}
            failed = []
            kept = ""
            for _ in range(args.repeat):
                for name, command in commands.items():
                    run = run_timed([*command, str(domain_path), str(problem_path)], cwd=work, env=env, timeout=600)
                    times[name].append(run.seconds)
                    if run.code != 0:
                        failed.append(f"{name} exit {run.code}")
                    elif name == "relevance":
                        report = json.loads(run.stdout)
                        kept = f"{report['objects_kept']}/{report['objects_total']} {report.get('raced') or ''}"
            bare, pure, relevance = (statistics.median(times[name]) for name in commands)
            overhead = pure - bare
            target = 0.05 + 0.05 * bare
            bound = relevance <= pure * 1.1 + 0.3
            rows.append((problem.name, bare, pure, relevance, overhead, target, bound, failed))
            flag = "  FAILED: " + ", ".join(failed) if failed else ""
            print(
                f"{problem.name:<24} {bare:7.2f} {pure:7.2f} {relevance:7.2f} {overhead:+9.3f} {target:7.3f}"
                f"  {'yes' if bound else 'NO'}  (kept {kept}){flag}",
                flush=True,
            )
    overheads = [row[4] for row in rows]
    met = sum(row[4] <= row[5] for row in rows)
    print(
        f"\noverhead of `plan --method pure` over the bare driver: median {statistics.median(overheads):+.3f} s,"
        f" max {max(overheads):+.3f} s; within 0.05 s + 5 %: {met} of {len(rows)}"
    )
    print(f"relevance within pure x 1.1 + 0.3 s: {sum(row[6] for row in rows)} of {len(rows)}")
    ratios = [row[1] / row[3] for row in rows]
    print(f"bare / relevance, geometric mean: {geometric_mean(ratios):.2f}")
    return 1 if any(row[7] for row in rows) else 0


if __name__ == "__main__":
    sys.exit(main())
