"""Parse + score + closure + write time at 500 and 2,000 objects.

A coffee problem with 500 and one with 2,000 objects, pruned with the
knowledge-model scorer and with the goal scorer.  Targets: <= 0.3 s at 500
objects, <= 1.5 s at 2,000.  Measured two ways in one run: in-process stages
(median of 5), and the whole `relevance-plan prune` command as a fresh
process (interpreter start-up and imports included, median of 3).  No
planner is started.

Takes 10-15 seconds on 2 cores.  No options besides --help.

    python benchmarks/bench_prune.py
"""

from __future__ import annotations

import argparse
import statistics
import sys
import tempfile
from pathlib import Path

from base import REPO, Laps, median, run_timed

from relevance_plan.generators import WORLDS, Settings
from relevance_plan.io import load_domain, load_problem, write_text_atomic
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.scoring.knowledge import load_knowledge_model
from relevance_plan.relevance.setup import ScoringOptions, score_problem

TARGETS = {500: 0.3, 2000: 1.5}
STAGES = ("parse", "score", "closure", "write", "total")


def stages(domain_path: Path, problem_path: Path, out: Path, scorer: str) -> dict:
    laps = Laps()
    domain = load_domain(domain_path)
    problem = load_problem(problem_path, domain)
    laps.lap("parse")
    model = load_knowledge_model(REPO / "domains" / "coffee" / "relevance.yaml") if scorer == "model" else None
    task = PlanningTask(domain, problem)
    scoring = score_problem(task, ScoringOptions(scorer=scorer), knowledge_model=model)
    laps.lap("score")
    result = scoring.prune(ScoringOptions().thresholds)
    laps.lap("closure")
    write_text_atomic(out, result.text)
    laps.lap("write")
    return {**laps.end(), "kept": len(result.kept), "objects": len(problem.objects)}


def parse_args(argv: list[str] | None = None) -> argparse.Namespace:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    return parser.parse_args(argv)


def whole_command(domain_path: Path, problem_path: Path, out: Path, scorer: str) -> float:
    """`relevance-plan prune` as a fresh process, median of 3 runs."""
    command = [sys.executable, "-m", "relevance_plan", "prune", str(domain_path), str(problem_path)]
    command += ["-o", str(out), "--scorer", scorer]
    runs = [run_timed(command) for _ in range(3)]
    failed = [run.code for run in runs if run.code != 0]
    if failed:
        raise SystemExit(f"bench_prune: `{' '.join(command)}` exited {failed[0]}")
    return statistics.median(run.seconds for run in runs)


def main(argv: list[str] | None = None) -> int:
    parse_args(argv)
    domain_path = REPO / "domains" / "coffee" / "domain.pddl"
    print("| objects | scorer | parse | score | closure | write | total (in-process) | whole command | target | kept |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory(prefix="bench-prune-") as scratch:
        for objects, target in TARGETS.items():
            generated = WORLDS["coffee"].problem(1, 0, Settings("simple", distractors=objects - 19))
            problem_path = Path(scratch) / f"coffee-{objects}.pddl"
            problem_path.write_text(generated.pddl_text)
            out = Path(scratch) / "pruned.pddl"
            for scorer in ("model", "goal"):
                runs = [stages(domain_path, problem_path, out, scorer) for _ in range(5)]
                times = {stage: median(r[stage] for r in runs) for stage in STAGES}
                command = whole_command(domain_path, problem_path, out, scorer)
                print(
                    f"| {runs[0]['objects']} | {scorer} | {times['parse']:.3f} | {times['score']:.3f} |"
                    f" {times['closure']:.3f} | {times['write']:.3f} | {times['total']:.3f} s |"
                    f" {command:.2f} s | {target} s | {runs[0]['kept']} |"
                )
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
