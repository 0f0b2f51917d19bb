"""The learned scorer by PLOI's protocol: learn on small training problems, plan the large test ones.

For each domain, ``relevance-plan learn``'s library call trains a model on the
training problems (``NAME/problem0..39`` in pddlgym's layout), timed.  Then
on each test problem (``NAME_test/``) these runs, one after the other, without
the race (one core each): pure Fast Downward, ``plan --scorer goal`` (the
default), ``plan --scorer learned:MODEL`` and ``--method random``.  Every plan
is validated on the original problem by the attempt loop.  Times are
in-process: the attempt loop's wall time (reading, scoring, pruning, planner
processes, validation), without interpreter start-up.  An unsolved run counts
at the time limit in the geometric means (so a speed-up over an unsolved pure
run is a lower bound).

Domains (``--domains``) are pddlgym's by default, read from the pddlgym
wheel's files; ``--folder`` reads another folder of the same layout
(``NAME.pddl`` beside ``NAME/`` and ``NAME_test/``), such as the corpus's
Taskography scene graphs.  ``NAME:K`` trains on the first K problems only.

``--labels plan,minimal`` trains one model per label kind on the same
problems and plans each test problem with each model (runs ``learned-plan``
and ``learned-minimal``); training time and planner runs are printed per
model.

``--oracle N``: on the first N test problems of each domain (but those of
``--oracle-skip``), the greedy minimal sufficient set (the machinery of
``--labels minimal``, on the test problem, started from the objects of the
goal run's plan with their closure), its size beside each first selection,
how long finding it took, and the planner alone on it and on the goal
scorer's first selection (``--repeat`` times each, in turns, median): how
much faster a perfect first selection could have made the goal run's
planner.

``--repeat N``: a goal or learned run under 10 s runs N times in all, in
turns, median time (at a second or less, other work on a shared machine
moves a single run's time by half).

Every run is stored in a results store (``--store``; one suite per domain;
the goal scorer's runs under the method ``relevance``, the learned model's
under ``learned`` (``learned-plan``, ``learned-minimal`` with several
label kinds), of repeated runs the one of median time), which
``relevance-plan report`` shows.

Scoring cost: on each test problem, ``score_problem`` with the goal and with
the learned scorer (in-process CPU seconds, median of 5); the difference is
what applying the model adds.  The same on a problem of at least
``--scale`` objects (default 1,000) made of renamed copies of the first test
problem side by side.

The pddlgym problems come from the wheel's files, without its dependencies:

    pip install --no-deps pddlgym==0.0.7

With the defaults (seven domains, all ten test problems, 120 s) it takes
hours; docs/results.md's run (three test problems, 60 s, grid trained on 8
problems, each of which pure Fast Downward takes about 20 s to solve) took
30 minutes on a loaded 2-core machine:

    python benchmarks/bench_learned.py --per-domain 3 --timeout 60 --repeat 3 --oracle 2 \\
        --oracle-skip manymiconic --domains manyblockssmallpiles,manyblocksnopiles,manylogistics,\\
manymiconic,manyferry,manygripper,manygrid:8

For a short run:

    python benchmarks/bench_learned.py --per-domain 2 --timeout 60 --domains manylogistics,manyferry

Taskography's medium scenes (twelve training problems each in the corpus;
30 s as in the Taskography paper's setting; 11 minutes):

    python benchmarks/bench_learned.py --folder benchmarks/corpus/taskography/scene-graph \\
        --domains taskographyv2medium10,taskographyv3medium10bagslots10 --per-domain 2 --timeout 30 \\
        --repeat 3 --oracle 2
"""

from __future__ import annotations

import argparse
import importlib.util
import statistics
import sys
import tempfile
import time
from collections import Counter
from pathlib import Path

from base import Store, add_store_option, median_run
from base import geometric_mean as geomean

from relevance_plan.batch.learn import LABEL_KINDS, Solver, learn, minimal_objects, plan_objects
from relevance_plan.io import load_domain, load_problem, write_text_atomic
from relevance_plan.pddl.formulas import literals
from relevance_plan.pddl.model import Problem
from relevance_plan.pddl.plans import Plan
from relevance_plan.pddl.writer import write_pruned_problem
from relevance_plan.planning.options import PlanOptions
from relevance_plan.planning.planners.base import PlannerStatus
from relevance_plan.planning.planners.registry import DEFAULT_PLANNER_CONFIG
from relevance_plan.planning.results import PlanResult, PlanStatus
from relevance_plan.planning.run import plan_task
from relevance_plan.relevance.analysis.task import PlanningTask
from relevance_plan.relevance.scoring.learning.learned_model import learned_model_text
from relevance_plan.relevance.setup import ScoringOptions, score_problem

PLOI_DOMAINS = (
    "manyblockssmallpiles",
    "manyblocksnopiles",
    "manylogistics",
    "manymiconic",
    "manyferry",
    "manygripper",
    "manygrid",
)
DOMAINS = ",".join(PLOI_DOMAINS)
RUNS = ("pure", "goal", "learned", "random")
STORED_AS = {"goal": "relevance"}  # the method column of a run's store row (the others: the run's name)
SHORT = 10.0  # seconds: a pruned run shorter than this is repeated with --repeat


def pddlgym_folder() -> Path:
    spec = importlib.util.find_spec("pddlgym")  # finds the files without importing pddlgym (and gym)
    if spec is None or spec.origin is None:
        sys.exit("pddlgym's files are not installed: pip install --no-deps pddlgym==0.0.7")
    return Path(spec.origin).parent / "pddl"


def numbered(folder: Path) -> list[Path]:
    return sorted(folder.glob("problem*.pddl"), key=lambda p: int(p.stem[len("problem") :]))


def run_names(runs: list[str], labels: list[str]) -> list[str]:
    """The runs of each test problem: ``learned`` becomes one run per label kind when there are several."""
    names = []
    for run in runs:
        if run == "learned" and len(labels) > 1:
            names += [f"learned-{kind}" for kind in labels]
        else:
            names.append(run)
    return names


def options_for(run: str, models: dict[str, Path], timeout: float) -> PlanOptions:
    common = {"timeout": timeout, "race": False, "validators": ("builtin",)}
    if run == "pure":
        return PlanOptions(method="pure", **common)
    if run == "random":
        return PlanOptions(method="random", **common)
    if run == "goal":
        return PlanOptions(scorer="goal", **common)
    return PlanOptions(scorer=f"learned:{models[run]}", **common)


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


def train(
    domain_path: Path, training: list[Path], args: argparse.Namespace, scratch: Path, name: str
) -> tuple[dict[str, Path], dict[str, dict]]:
    """One model per label kind, written under ``scratch``; each kind's training figures."""
    models, training_figures = {}, {}
    for kind in args.labels:
        started = time.perf_counter()
        report = learn(domain_path, training, time_limit=args.train_limit, labels=kind, seed=args.seed)
        seconds = time.perf_counter() - started
        run = "learned" if len(args.labels) == 1 else f"learned-{kind}"
        models[run] = write_text_atomic(scratch / f"{name}-{kind}.json", learned_model_text(report.model))
        runs = sum(p.planner_runs for p in report.problems)
        needed = statistics.mean(len(p.positives) for p in report.problems)
        size = statistics.mean(p.objects for p in report.problems)
        training_figures[run] = {"seconds": seconds, "problems": len(report.problems), "planner_runs": runs}
        print(
            f"\n{name}: learned ({kind} labels) from {len(report.problems)} of {len(training)} training problems"
            f" in {seconds:.1f} s, {runs} planner runs, {needed:.1f} needed objects a problem"
            f" (of {size:.1f}), threshold P > {report.model.threshold:.3f}",
            flush=True,
        )
    return models, training_figures


def run_domain(folder: Path, spec: str, args: argparse.Namespace, scratch: Path, store: Store) -> dict:
    name, _, count = spec.partition(":")
    domain_path = folder / f"{name}.pddl"
    training = numbered(folder / name)[: int(count) if count else args.train]
    tests = numbered(folder / f"{name}_test")[: args.per_domain]
    models, training_figures = train(domain_path, training, args, scratch, name)
    runs = run_names(args.runs, args.labels)
    print(f"{'problem':<16}{'objects':>8}  " + "  ".join(f"{run:>24}" for run in runs) + f"  {'+scoring':>9}")
    rows = []
    for number, problem in enumerate(tests):
        row: dict = {"problem": problem.name}
        results = {run: [plan_task(domain_path, problem, options_for(run, models, args.timeout))] for run in runs}
        repeat_short_runs(results, domain_path, problem, models, args)
        for run, each in results.items():
            options = options_for(run, models, args.timeout)
            store.add(name, domain_path, problem, options, median_run(each), STORED_AS.get(run, run))
            row[run] = measured(each)
            row["objects"] = each[0].objects_total
        first_kept = {run: each[0].selection.kept for run, each in results.items() if each[0].selection is not None}
        plans = {run: each[0].plan for run, each in results.items() if measured(each[:1])[0]}
        row["first"] = {run: len(kept) for run, kept in first_kept.items()}
        domain = load_domain(domain_path)
        task = PlanningTask(domain, load_problem(problem, domain))
        learned = [run for run in runs if run.startswith("learned")]
        goal_scoring = scoring_seconds(domain_path, problem, "goal")
        row["added"] = {
            run: scoring_seconds(domain_path, problem, f"learned:{models[run]}") - goal_scoring for run in learned
        }
        rows.append(row)
        cells = []
        for run in runs:
            solved, seconds, kept, attempts, _ = row[run]
            cells.append(f"{'ok' if solved else 'FAIL':>4} {seconds:7.2f}s {kept:>5} kept {attempts}att")
        added = " ".join(f"{value:+8.3f}s" for value in row["added"].values())
        print(f"{problem.name:<16}{row['objects']:>8}  " + "  ".join(f"{c:>24}" for c in cells) + f"  {added}")
        if first_kept:
            print(f"{'':<16}first selections: " + ", ".join(f"{run} {len(kept)}" for run, kept in first_kept.items()))
        if "pure" in plans:
            needed = plan_objects(task, plans["pure"])
            # the objects pure Fast Downward's plan names, with their closure, against each first selection
            print(
                f"{'':<16}the full problem's plan uses {len(needed)} objects (with closure); first selections: "
                + ", ".join(
                    f"{run} keeps {len(kept & needed)} of them and {len(kept - needed)} others"
                    + missed(task, needed - kept)
                    for run, kept in first_kept.items()
                ),
                flush=True,
            )
        start_plan = plans.get("goal") or plans.get("pure")
        if number < args.oracle and name not in args.oracle_skip and start_plan is not None:
            row["oracle"] = oracle(domain_path, problem, task, start_plan, first_kept, args, scratch)
    scale = None
    if tests and args.scale:
        scale = scaled_scoring(domain_path, tests[0], str(next(iter(models.values()))), args.scale, scratch)
    if scale is not None:
        objects, goal_seconds, learned_seconds = scale
        print(
            f"scoring {objects} objects (copies of {tests[0].name}): goal {goal_seconds:.3f} s,"
            f" learned {learned_seconds:.3f} s, the model added {learned_seconds - goal_seconds:+.3f} s (CPU)"
        )
    return {"name": name, "training": training_figures, "rows": rows, "scale": scale, "runs": runs}


def measured(results: list[PlanResult]) -> tuple[bool, float, int, int, float]:
    """(solved with a valid plan every time, median wall seconds, objects kept and attempts of the first run,
    median planner seconds)."""
    solved = all(result.status is PlanStatus.SOLVED and result.valid for result in results)
    first = results[0]
    wall = statistics.median(result.wall_time for result in results)
    planner = statistics.median(result.planner_time for result in results)
    return solved, wall, first.objects_kept, len(first.attempts), planner


def repeat_short_runs(
    results: dict[str, list[PlanResult]], domain_path: Path, problem: Path, models: dict[str, Path], args
) -> None:
    """With ``--repeat N``, the goal and learned runs that took under ``SHORT`` seconds run N times in
    all, in turns (their medians count): at a second or less, other work on the machine moves one
    run's time by half."""
    short = [run for run, each in results.items() if run not in ("pure", "random") and each[0].wall_time < SHORT]
    for _ in range(args.repeat - 1):
        for run in short:
            results[run].append(plan_task(domain_path, problem, options_for(run, models, args.timeout)))


def oracle(
    domain_path: Path,
    problem_path: Path,
    task: PlanningTask,
    plan: Plan,
    first_kept: dict[str, frozenset[str]],
    args: argparse.Namespace,
    scratch: Path,
) -> dict:
    """The greedy minimal sufficient set from ``plan``'s objects, against each first selection; the
    planner alone on it and on the goal run's first selection (``--repeat`` times each, in turns,
    median): how much faster a perfect first selection would have made the goal run's planner."""
    started = time.perf_counter()
    solver = Solver(str(domain_path), "fast-downward", DEFAULT_PLANNER_CONFIG, args.oracle_limit, str(scratch))
    start = plan_objects(task, plan)
    minimal = minimal_objects(task, str(problem_path), start, solver, args.seed)
    finding = time.perf_counter() - started
    sets = {"minimal": minimal}
    if "goal" in first_kept and first_kept["goal"] != minimal:
        sets["goal"] = first_kept["goal"]
    paths = {
        which: write_text_atomic(scratch / f"oracle-{which}.pddl", write_pruned_problem(task.problem, kept))
        for which, kept in sets.items()
    }
    times: dict[str, list[float]] = {which: [] for which in sets}
    solved = True
    for _ in range(args.repeat):
        for which, path in paths.items():
            outcome = solver.planner.run(str(domain_path), str(path), time_limit=args.timeout, memory_limit_mb=None)
            solved = solved and (which != "minimal" or outcome.status is PlannerStatus.SOLVED)
            times[which].append(outcome.wall_time)
    seconds = statistics.median(times["minimal"])
    goal_seconds = statistics.median(times["goal"]) if "goal" in times else None
    print(
        f"{'':<16}oracle: {len(minimal)} objects (from the goal run's plan's {len(start)}; found in {finding:.1f} s,"
        f" {solver.runs} planner runs); the planner alone on them: {seconds:.2f} s"
        f"{'' if solved else ' (not solved)'}; first selections: "
        + ", ".join(f"{run} {len(kept)} ({len(kept & minimal)} of its objects)" for run, kept in first_kept.items()),
        flush=True,
    )
    if "goal" in first_kept:
        bound = 1.0 if goal_seconds is None else goal_seconds / seconds
        print(
            f"{'':<16}"
            + (
                "the goal scorer's first selection is this set: no first selection could make its planner faster"
                if goal_seconds is None
                else f"the planner alone on the goal scorer's first selection: {goal_seconds:.2f} s; a perfect first"
                f" selection could make it at most {bound:.2f}x faster"
            ),
            flush=True,
        )
    else:
        bound = float("nan")
    return {"size": len(minimal), "seconds": seconds, "solved": solved, "finding": finding, "bound": bound}


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
    solved, seconds = row[run][:2]
    return seconds if solved else max(seconds, limit)


def ratios(rows: list[dict], top: str, bottom: str, limit: float) -> list[float]:
    """top's seconds over bottom's, per problem (empty when either run was not made)."""
    if not rows or top not in rows[0] or bottom not in rows[0]:
        return []
    return [seconds_of(r, top, limit) / seconds_of(r, bottom, limit) for r in rows]


def summary(results: list[dict], limit: float) -> None:
    print("\nper domain and run (geometric-mean seconds, an unsolved run counting at the time limit;")
    print("mean objects kept in the end and in the first selection; mean attempts; mean planner seconds):")
    print(f"{'domain':<32}{'run':<17}{'solved':>7}{'time s':>9}{'kept':>8}{'first':>8}{'attempts':>9}{'planner s':>10}")
    for result in results:
        rows = result["rows"]
        for run in result["runs"]:
            solved = sum(row[run][0] for row in rows)
            firsts = [row["first"][run] for row in rows if run in row["first"]]
            print(
                f"{result['name']:<32}{run:<17}{solved:>4}/{len(rows):<2}"
                f"{geomean([seconds_of(row, run, limit) for row in rows]):>9.2f}"
                f"{statistics.mean(row[run][2] for row in rows):>8.0f}"
                f"{statistics.mean(firsts) if firsts else float('nan'):>8.0f}"
                f"{statistics.mean(row[run][3] for row in rows):>9.1f}"
                f"{statistics.mean(row[run][4] for row in rows):>10.2f}"
            )
        measured = [row["oracle"] for row in rows if "oracle" in row]
        if measured:
            print(
                f"{result['name']:<32}{'oracle':<17}{sum(o['solved'] for o in measured):>4}/{len(measured):<2}"
                f"{geomean([o['seconds'] for o in measured]):>9.2f}{statistics.mean(o['size'] for o in measured):>8.0f}"
                f"{'':>8}{'':>9}{geomean([o['seconds'] for o in measured]):>10.2f}"
                f"  (the planner alone on the minimal set; {len(measured)} problems;"
                f" a perfect first selection: at most {geomean([o['bound'] for o in measured]):.2f}x over goal's)"
            )
    print("\nspeed-ups (geometric means over the domain's test problems):")
    print(f"{'domain':<32}{'run':<17}{'training s':>11}{'runs':>6}{'over pure':>10}{'over goal':>10}{'goal/pure':>10}")
    over_pure: dict[str, list[float]] = {}
    over_goal: dict[str, list[float]] = {}
    for result in results:
        rows = result["rows"]
        goal_over_pure = geomean(ratios(rows, "pure", "goal", limit))
        for run in [r for r in result["runs"] if r.startswith("learned")]:
            lp, lg = ratios(rows, "pure", run, limit), ratios(rows, "goal", run, limit)
            over_pure.setdefault(run, []).extend(lp)
            over_goal.setdefault(run, []).extend(lg)
            figures = result["training"][run]
            print(
                f"{result['name']:<32}{run:<17}{figures['seconds']:>11.1f}{figures['planner_runs']:>6}"
                f"{geomean(lp):>10.2f}{geomean(lg):>10.2f}{goal_over_pure:>10.2f}"
            )
    for run in over_pure:
        print(f"{'all':<32}{run:<17}{'':>11}{'':>6}{geomean(over_pure[run]):>10.2f}{geomean(over_goal[run]):>10.2f}")
    added = [value for result in results for row in result["rows"] for value in row["added"].values()]
    if added:
        print(f"applying the model added {statistics.median(added):+.3f} s (median), {max(added):+.3f} s (most) of CPU")


def parse_args(argv: list[str] | None = None) -> argparse.Namespace:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument(
        "--domains",
        default=DOMAINS,
        help=f"Comma-separated domains, NAME or NAME:K to train on K problems (default: {DOMAINS}).",
    )
    parser.add_argument(
        "--folder",
        type=Path,
        default=None,
        help="Folder of NAME.pddl, NAME/ and NAME_test/ (default: the pddlgym wheel's pddl folder).",
    )
    parser.add_argument("--per-domain", type=int, default=10, help="Test problems per domain (default: all 10).")
    parser.add_argument("--train", type=int, default=40, help="Training problems per domain (default: 40).")
    parser.add_argument("--timeout", type=float, default=120.0, help="Seconds for each test run (default: 120).")
    parser.add_argument("--train-limit", type=float, default=30.0, help="Seconds for each training planner run.")
    parser.add_argument(
        "--labels", default="plan", help="Label kinds, comma-separated: plan, minimal or both (default: plan)."
    )
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument(
        "--runs", default=",".join(RUNS), help=f"Comma-separated runs of each test problem (default: {','.join(RUNS)})."
    )
    parser.add_argument(
        "--repeat",
        type=int,
        default=1,
        help=f"Run goal and learned runs shorter than {SHORT:g} s this many times, median time (default: 1).",
    )
    parser.add_argument(
        "--oracle", type=int, default=0, help="Find the minimal sufficient set on this many test problems (default: 0)."
    )
    parser.add_argument(
        "--oracle-limit", type=float, default=30.0, help="Seconds for each planner run while finding it (default: 30)."
    )
    parser.add_argument(
        "--oracle-skip", default="", help="Comma-separated domains not to find it on (too many planner runs)."
    )
    parser.add_argument(
        "--scale",
        type=int,
        default=1000,
        help="Also time scoring on copies of a test problem, this many objects (0: not).",
    )
    add_store_option(parser)
    args = parser.parse_args(argv)
    args.runs = [run for run in RUNS if run in args.runs.split(",")]
    args.oracle_skip = set(filter(None, args.oracle_skip.split(",")))
    args.labels = [kind for kind in args.labels.split(",") if kind]
    unknown = [kind for kind in args.labels if kind not in LABEL_KINDS]
    if unknown or not args.labels:
        parser.error(f"--labels takes {', '.join(LABEL_KINDS)} (comma-separated)")
    return args


def main(argv: list[str] | None = None) -> None:
    args = parse_args(argv)
    folder = args.folder or pddlgym_folder()
    results = []
    with tempfile.TemporaryDirectory(prefix="bench-learned-") as scratch, Store(args.store, "bench_learned") as store:
        for spec in args.domains.split(","):
            results.append(run_domain(folder, spec, args, Path(scratch), store))
    summary(results, args.timeout)


if __name__ == "__main__":
    main()
