"""The learned scorer by PLOI's protocol: learn on pddlgym's small training problems, plan its large test ones.

For each domain, ``relevance-plan learn``'s library call trains a model on the
training problems (``manyX/problem0..39``), timed.  Then on each test problem
(``manyX_test/``) four runs, one after the other, without the race (one core
each): pure Fast Downward, ``plan --scorer goal`` (the default), ``plan
--scorer learned:MODEL`` and ``--method random``.  Every plan is validated on
the original problem by the attempt loop.  Times are in-process: the attempt
loop's wall time (reading, scoring, pruning, planner processes, validation),
without interpreter start-up.  An unsolved run counts at the time limit in
the geometric means (so a speed-up over an unsolved pure run is a lower bound).

Scoring cost: on each test problem, ``score_problem`` with the goal and with
the learned scorer (in-process CPU seconds, median of 5); the difference is
what applying the model adds.  The same on a problem of at least
``--scale`` objects (default 1,000) made of renamed copies of the first test
problem side by side.

The problems come from the pddlgym wheel's files, without its dependencies:

    pip install --no-deps pddlgym==0.0.7

Takes 10-40 minutes on 2 cores with the defaults; for a short run:

    python benchmarks/bench_learned.py --per-domain 2 --timeout 60 --domains manylogistics,manyferry
"""

from __future__ import annotations

import argparse
import importlib.util
import math
import statistics
import sys
import tempfile
import time
from collections import Counter
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(REPO))

from relevance_plan.batch.learn import learn, plan_objects  # noqa: E402
from relevance_plan.io import load_domain, load_problem, write_text_atomic  # noqa: E402
from relevance_plan.pddl.formulas import literals  # noqa: E402
from relevance_plan.pddl.model import Problem  # noqa: E402
from relevance_plan.planning.loop import PlanOptions, PlanStatus, plan_task  # noqa: E402
from relevance_plan.relevance.learning.model import model_text  # noqa: E402
from relevance_plan.relevance.scorers import PlanningTask  # noqa: E402
from relevance_plan.relevance.setup import ScoringOptions, score_problem  # noqa: E402

DOMAINS = "manylogistics,manymiconic,manyblockssmallpiles,manyferry"
RUNS = ("pure", "goal", "learned", "random")


def pddlgym_folder() -> Path:
    spec = importlib.util.find_spec("pddlgym")  # finds the files without importing pddlgym (and gym)
    if spec is None or spec.origin is None:
        sys.exit("pddlgym's files are not installed: pip install --no-deps pddlgym==0.0.7")
    return Path(spec.origin).parent / "pddl"


def numbered(folder: Path) -> list[Path]:
    return sorted(folder.glob("problem*.pddl"), key=lambda p: int(p.stem[len("problem") :]))


def options_for(run: str, model: str, timeout: float) -> PlanOptions:
    common = {"timeout": timeout, "race": False, "validators": ("builtin",)}
    if run == "pure":
        return PlanOptions(method="pure", **common)
    if run == "random":
        return PlanOptions(method="random", **common)
    return PlanOptions(scorer="goal" if run == "goal" else f"learned:{model}", **common)


def scoring_seconds(domain_path: Path, problem_path: Path, scorer: str) -> float:
    """CPU seconds of scoring the problem in this process (median of 5): other processes' load on a
    shared machine stretches wall time, not this."""
    times = []
    for _ in range(5):
        domain = load_domain(domain_path)
        task = PlanningTask(domain, load_problem(problem_path, domain))
        started = time.process_time()
        score_problem(task, ScoringOptions(scorer=scorer))
        times.append(time.process_time() - started)
    return statistics.median(times)


def scaled_text(problem: Problem, least: int) -> str:
    """Copies of ``problem`` side by side (objects renamed, goals conjoined), at least ``least`` objects."""
    copies = max(1, -(-least // max(len(problem.objects), 1)))
    objects, facts, goal = [], set(), []

    def atom_text(atom: tuple[str, ...], suffix: str) -> str:
        args = [f"{arg}{suffix}" if arg in problem.objects else arg for arg in atom[1:]]
        return "(" + " ".join([atom[0], *args]) + ")"

    for copy in range(copies):
        suffix = f"_c{copy}"
        objects += [f"{name}{suffix} - {kind}" for name, kind in problem.objects.items()]
        facts |= {atom_text(atom, suffix) for atom in problem.init}
        for atom, positive in literals(problem.goal):
            goal.append(
                atom_text((atom.predicate, *atom.args), suffix)
                if positive
                else f"(not {atom_text((atom.predicate, *atom.args), suffix)})"
            )
    return (
        f"(define (problem scaled) (:domain {problem.domain_name})\n(:objects\n"
        + "\n".join(objects)
        + ")\n(:init\n"
        + "\n".join(sorted(facts))
        + ")\n(:goal (and\n"
        + "\n".join(goal)
        + ")))\n"
    )


def geomean(values: list[float]) -> float:
    return math.exp(sum(math.log(v) for v in values) / len(values)) if values else float("nan")


def run_domain(folder: Path, name: str, args: argparse.Namespace, scratch: Path) -> dict:
    domain_path = folder / f"{name}.pddl"
    training = numbered(folder / name)[: args.train]
    tests = numbered(folder / f"{name}_test")[: args.per_domain]
    started = time.perf_counter()
    report = learn(domain_path, training, time_limit=args.train_limit, labels=args.labels, seed=args.seed)
    learning = time.perf_counter() - started
    model = scratch / f"{name}.json"
    write_text_atomic(model, model_text(report.model))
    print(
        f"\n{name}: learned from {len(report.problems)} of {len(training)} training problems in {learning:.1f} s"
        f" ({args.labels} labels, threshold P > {report.model.threshold:.3f})",
        flush=True,
    )
    runs = args.runs
    print(f"{'problem':<16}{'objects':>8}  " + "  ".join(f"{run:>24}" for run in runs) + f"  {'+scoring':>9}")
    rows = []
    for problem in tests:
        row: dict = {"problem": problem.name}
        first_kept: dict[str, frozenset[str]] = {}
        needed: frozenset[str] | None = None
        for run in runs:
            result = plan_task(domain_path, problem, options_for(run, str(model), args.timeout))
            solved = result.status is PlanStatus.SOLVED and result.valid
            row[run] = (solved, result.wall_time, result.objects_kept, len(result.attempts))
            row["objects"] = result.objects_total
            if result.selection is not None:
                first_kept[run] = result.selection.kept
            if run == "pure" and solved:
                domain = load_domain(domain_path)
                pure_task = PlanningTask(domain, load_problem(problem, domain))
                needed = plan_objects(pure_task, result.plan)
        goal_scoring = scoring_seconds(domain_path, problem, "goal")
        learned_scoring = scoring_seconds(domain_path, problem, f"learned:{model}")
        row["added"] = learned_scoring - goal_scoring
        rows.append(row)
        cells = []
        for run in runs:
            solved, seconds, kept, attempts = row[run]
            cells.append(f"{'ok' if solved else 'FAIL':>4} {seconds:7.2f}s {kept:>5} kept {attempts}att")
        print(
            f"{problem.name:<16}{row['objects']:>8}  "
            + "  ".join(f"{c:>24}" for c in cells)
            + f"  {row['added']:+8.3f}s"
        )
        if needed is not None:
            # the objects pure Fast Downward's plan names, with their closure, against each first selection
            print(
                f"{'':<16}the full problem's plan uses {len(needed)} objects (with closure); first selections: "
                + ", ".join(
                    f"{run} keeps {len(kept & needed)} of them and {len(kept - needed)} others"
                    + missed(pure_task, needed - kept)
                    for run, kept in first_kept.items()
                )
            )
    scale = scaled_scoring(domain_path, tests[0], str(model), args.scale, scratch) if tests and args.scale else None
    if scale is not None:
        objects, goal_seconds, learned_seconds = scale
        print(
            f"scoring {objects} objects (copies of {tests[0].name}): goal {goal_seconds:.3f} s,"
            f" learned {learned_seconds:.3f} s, the model added {learned_seconds - goal_seconds:+.3f} s (CPU)"
        )
    return {"name": name, "learning": learning, "rows": rows, "threshold": report.model.threshold, "scale": scale}


def missed(task: PlanningTask, names: frozenset[str]) -> str:
    """' (not: 13 airplane)': the types of the plan's objects a first selection left out."""
    if not names:
        return ""
    kinds = Counter(task.typing.problem.objects[name] for name in names)
    return " (not: " + ", ".join(f"{count} {kind}" for kind, count in sorted(kinds.items())) + ")"


def scaled_scoring(
    domain_path: Path, problem_path: Path, model: str, least: int, scratch: Path
) -> tuple[int, float, float]:
    """Objects, goal and learned scoring seconds on copies of ``problem_path`` (``scaled_text``)."""
    domain = load_domain(domain_path)
    path = write_text_atomic(scratch / "scaled.pddl", scaled_text(load_problem(problem_path, domain), least))
    objects = len(load_problem(path, domain).objects)
    return objects, scoring_seconds(domain_path, path, "goal"), scoring_seconds(domain_path, path, f"learned:{model}")


def seconds_of(row: dict, run: str, limit: float) -> float:
    solved, seconds, _, _ = row[run]
    return seconds if solved else max(seconds, limit)


def ratios(rows: list[dict], top: str, bottom: str, limit: float) -> list[float]:
    """top's seconds over bottom's, per problem (empty when either run was not made)."""
    if not rows or top not in rows[0] or bottom not in rows[0]:
        return []
    return [seconds_of(r, top, limit) / seconds_of(r, bottom, limit) for r in rows]


def summary(results: list[dict], limit: float, runs: list[str]) -> None:
    print("\nper domain (geometric means; an unsolved run counts at the time limit):")
    print(
        f"{'domain':<24}{'learn s':>8}{'solved ' + '/'.join(r[0] for r in runs):>16}"
        f"{'l over pure':>12}{'l over goal':>12}{'g over pure':>12}{'kept g/l':>14}{'attempts g/l':>14}"
    )
    over_pure, over_goal = [], []
    for result in results:
        rows = result["rows"]
        solved = "/".join(str(sum(row[run][0] for row in rows)) for run in runs)
        lp, lg, gp = (
            ratios(rows, "pure", "learned", limit),
            ratios(rows, "goal", "learned", limit),
            ratios(rows, "pure", "goal", limit),
        )
        over_pure += lp
        over_goal += lg
        kept = "/".join(
            f"{statistics.mean(r[run][2] for r in rows):.0f}" if run in runs else "-" for run in ("goal", "learned")
        )
        tries = "/".join(
            f"{statistics.mean(r[run][3] for r in rows):.1f}" if run in runs else "-" for run in ("goal", "learned")
        )
        print(
            f"{result['name']:<24}{result['learning']:>8.1f}{solved:>16}"
            f"{geomean(lp):>12.2f}{geomean(lg):>12.2f}{geomean(gp):>12.2f}{kept:>14}{tries:>14}"
        )
    print(f"{'all':<24}{'':>8}{'':>16}{geomean(over_pure):>12.2f}{geomean(over_goal):>12.2f}")
    added = [row["added"] for result in results for row in result["rows"]]
    if added:
        print(f"applying the model added {statistics.median(added):+.3f} s (median), {max(added):+.3f} s (most) of CPU")


def parse_args(argv: list[str] | None = None) -> argparse.Namespace:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--domains", default=DOMAINS, help=f"Comma-separated pddlgym domains (default: {DOMAINS}).")
    parser.add_argument("--per-domain", type=int, default=10, help="Test problems per domain (default: all 10).")
    parser.add_argument("--train", type=int, default=40, help="Training problems per domain (default: 40).")
    parser.add_argument("--timeout", type=float, default=120.0, help="Seconds for each test run (default: 120).")
    parser.add_argument("--train-limit", type=float, default=30.0, help="Seconds for each training planner run.")
    parser.add_argument("--labels", choices=("plan", "minimal"), default="plan")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument(
        "--runs", default=",".join(RUNS), help=f"Comma-separated runs of each test problem (default: {','.join(RUNS)})."
    )
    parser.add_argument(
        "--scale",
        type=int,
        default=1000,
        help="Also time scoring on copies of a test problem, this many objects (0: not).",
    )
    args = parser.parse_args(argv)
    args.runs = [run for run in RUNS if run in args.runs.split(",")]
    return args


def main(argv: list[str] | None = None) -> None:
    args = parse_args(argv)
    folder = pddlgym_folder()
    results = []
    with tempfile.TemporaryDirectory(prefix="bench-learned-") as scratch:
        for name in args.domains.split(","):
            results.append(run_domain(folder, name, args, Path(scratch)))
    summary(results, args.timeout, args.runs)


if __name__ == "__main__":
    main()
