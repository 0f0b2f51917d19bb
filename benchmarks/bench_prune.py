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
import subprocess
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(REPO))

from relevance_plan.generators.generate import generate_problem  # noqa: E402
from relevance_plan.io import load_domain, load_problem, write_text_atomic  # noqa: E402
from relevance_plan.relevance.knowledge import load_knowledge_model  # noqa: E402
from relevance_plan.relevance.setup import ScoringOptions, score_problem  # noqa: E402
from relevance_plan.relevance.task import PlanningTask  # noqa: E402

TARGETS = {500: 0.3, 2000: 1.5}


def stages(domain_path: Path, problem_path: Path, out: Path, scorer: str) -> dict:
    times = {}
    start = time.perf_counter()
    domain = load_domain(domain_path)
    problem = load_problem(problem_path, domain)
    times["parse"] = time.perf_counter() - start
    mark = time.perf_counter()
    model = load_knowledge_model(REPO / "domains" / "coffee" / "relevance.yaml") if scorer == "model" else None
    task = PlanningTask(domain, problem)
    scoring = score_problem(task, ScoringOptions(scorer=scorer), knowledge_model=model)
    times["score"] = time.perf_counter() - mark
    mark = time.perf_counter()
    result = scoring.prune(ScoringOptions().thresholds)
    times["closure"] = time.perf_counter() - mark
    mark = time.perf_counter()
    write_text_atomic(out, result.text)
    times["write"] = time.perf_counter() - mark
    times["total"] = time.perf_counter() - start
    times["kept"] = len(result.kept)
    times["objects"] = len(problem.objects)
    return times


def parse_args(argv: list[str] | None = None) -> argparse.Namespace:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    return parser.parse_args(argv)


def main() -> int:
    parse_args()
    domain_path = REPO / "domains" / "coffee" / "domain.pddl"
    print("| objects | scorer | parse | score | closure | write | total (in-process) | whole command | target | kept |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory(prefix="bench-prune-") as scratch:
        for objects, target in TARGETS.items():
            generated = generate_problem("coffee", "simple", 1, 0, distractors=objects - 19)
            problem_path = Path(scratch) / f"coffee-{objects}.pddl"
            problem_path.write_text(generated.pddl_text)
            out = Path(scratch) / "pruned.pddl"
            for scorer in ("model", "goal"):
                runs = [stages(domain_path, problem_path, out, scorer) for _ in range(5)]
                median = {
                    k: statistics.median(r[k] for r in runs) for k in ("parse", "score", "closure", "write", "total")
                }
                commands = []
                for _ in range(3):
                    started = time.perf_counter()
                    subprocess.run(
                        [
                            sys.executable,
                            "-m",
                            "relevance_plan",
                            "prune",
                            str(domain_path),
                            str(problem_path),
                            "-o",
                            str(out),
                            "--scorer",
                            scorer,
                        ],
                        check=True,
                        capture_output=True,
                    )
                    commands.append(time.perf_counter() - started)
                print(
                    f"| {runs[0]['objects']} | {scorer} | {median['parse']:.3f} | {median['score']:.3f} |"
                    f" {median['closure']:.3f} | {median['write']:.3f} | {median['total']:.3f} s |"
                    f" {statistics.median(commands):.2f} s | {target} s | {runs[0]['kept']} |"
                )
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
