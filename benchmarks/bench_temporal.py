#!/usr/bin/env python
"""Pure vs relevance with temporal and numeric planners: on the IPC corpus, and on generated worlds.

``corpus``: the IPC's own temporal, numeric and timed-literals domains in
``benchmarks/corpus/`` (121 folders; ``--one-per-family`` keeps the newest
competition's folder of each track and domain: 66).  For each folder, its
smallest problem (``--per-folder K``: the K smallest), and for each
installed planner (``--planners``, default LPG and the unified-planning
engines Aries, Tamer, ENHSP and Kairos) whose declared features accept it
(the registry decides; a refusal gets no row and is counted), this process
runs ``plan_task`` twice, one after the other: ``method="pure"``, then
relevance with the tool's defaults as users get them (the race on when two
cores are there; ``--no-race`` for one core).  ``--extra N`` plans instead
the problem padded with N clones of objects the goal does not need
(``relevance_plan.generators.padded.pad_with_clones``, seeded by
``--seed``), written to a temporary folder; ``--pure-solved-in JSON`` keeps
the pairs whose pure run solved in an earlier ``--json`` output.  Every
solved plan was validated on the (padded) original; a row solved without a
valid plan is flagged and the script exits 1.  One row per (folder,
planner); an unsolved run counts as the ``--timeout``; a row solved by
neither is listed but left out of the means.  At the end, per planner: the
geometric mean of pure/relevance, the rows where relevance was more than
1.25x + 0.5 s slower than pure, the rows solved by one side only.  With
``--extra N --oracle``, each row also plans the problem as published (the
padding removed exactly, a perfect pruning of it) with ``method="pure"``,
and the summary gives pure/oracle over the same rows: what planning on a
perfectly pruned problem gives that planner, measured in the same run.

``worlds`` (the default): for each generated world and size, one problem
(``relevance-plan generate``, seeded), planned pure and with relevance (no
race), with the same planner and time limit; pure/relevance per planner as
a geometric mean over the sizes.  Worlds: driverlog-temporal (LPG, Tamer,
Aries), coffee-temporal with distractors (LPG, Aries, Tamer),
zenotravel-numeric (LPG, ENHSP when Java is there, Tamer).

    python benchmarks/bench_temporal.py corpus --one-per-family --timeout 20 --json rows.json   # about an hour
    python benchmarks/bench_temporal.py corpus --one-per-family --extra 40 --pure-solved-in rows.json  # 30 minutes
    python benchmarks/bench_temporal.py corpus --folders driverlog --planners lpg,up:aries --extra 60
    python benchmarks/bench_temporal.py                  # the generated grid: takes about 30 minutes
    python benchmarks/bench_temporal.py --quick          # the smallest sizes only: takes about 4 minutes

Progress lines go to stderr; rows and the summary to stdout.
"""

from __future__ import annotations

import argparse
import json
import shutil
import subprocess
import sys
import tempfile
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

import corpus
from base import Laps, Store, add_store_option, geometric_mean, smallest_problems

from relevance_plan.batch.suites import SuiteProblem
from relevance_plan.errors import RelevancePlanError
from relevance_plan.generators.padded import pad_with_clones
from relevance_plan.io import load_domain, load_problem, write_text_atomic
from relevance_plan.pddl.formatter import format_problem
from relevance_plan.pddl.model import Domain, Problem
from relevance_plan.planning.options import PlanOptions
from relevance_plan.planning.planners.preparation import prepare_planner
from relevance_plan.planning.planners.registry import make_planner
from relevance_plan.planning.race import race_by_default
from relevance_plan.planning.results import PlanResult, PlanStatus
from relevance_plan.planning.run import plan_task

# (world, how its size is given, sizes, planners)
GRID = (
    ("driverlog-temporal", "--size", (20, 60, 120), ("lpg", "up:tamer", "up:aries")),
    ("coffee-temporal", "--distractors", (10, 50, 100), ("lpg", "up:aries", "up:tamer")),
    ("zenotravel-numeric", "--size", (20, 60, 120), ("lpg", "up:enhsp", "up:tamer")),
)


def generate(world: str, flag: str, size: int, seed: int, folder: Path) -> tuple[Path, Path]:
    """One generated problem of ``world`` and its domain file."""
    out = folder / f"{world}-{size}"
    command = [sys.executable, "-m", "relevance_plan", "generate", world, "--count", "1", "--seed", str(seed)]
    command += ["--out", str(out), flag, str(size)]
    if flag == "--distractors":
        command += ["--difficulty", "simple"]
    subprocess.run(command, check=True, capture_output=True)
    problems = sorted(p for p in out.glob("*.pddl") if p.name != "domain.pddl")
    return out / "domain.pddl", problems[0]


def planner_available(name: str) -> str | None:
    """Why ``name`` cannot run here, or None."""
    if name == "up:enhsp" and shutil.which("java") is None:
        return "no Java runtime"
    try:
        make_planner(name, check=True)
    except Exception as error:  # a missing engine: the row says why
        return str(error)
    return None


def timed_plan(
    domain: Path, problem: Path, options: PlanOptions, store: Store, suite: str, method: str = ""
) -> tuple[PlanResult, float]:
    """``plan_task`` timed from outside, the run stored under ``suite`` (and ``method`` when given)."""
    laps = Laps()
    result = plan_task(domain, problem, options)
    seconds = laps.end()["total"]
    store.add(suite, domain, problem, options, result, method)
    return result, seconds


def run_worlds(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(
        prog="bench_temporal.py [worlds]",
        description="Pure vs relevance on generated temporal and numeric worlds at growing sizes.",
        epilog="The default grid takes about 30 minutes on 2 cores; --quick about 4 minutes.",
    )
    parser.add_argument("--timeout", type=float, default=60.0)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--quick", action="store_true", help="the smallest size of each world only")
    add_store_option(parser)
    args = parser.parse_args(argv)

    ratios: dict[str, list[float]] = {}
    print(f"{'world':20} {'planner':9} {'objects':>7} {'pure s':>8} {'relevance s':>11} {'kept':>9} {'pure/rel':>8}")
    with tempfile.TemporaryDirectory(prefix="bench-temporal-") as scratch, Store(args.store, "bench_temporal") as store:
        for world, flag, sizes, planners in GRID:
            for size in sizes[:1] if args.quick else sizes:
                domain, problem = generate(world, flag, size, args.seed, Path(scratch))
                for planner in planners:
                    ratio = world_row(world, f"{world}-{size}", domain, problem, planner, args.timeout, store)
                    if ratio is not None:
                        ratios.setdefault(planner, []).append(ratio)
    print()
    for planner, values in ratios.items():
        print(f"{planner}: pure / relevance geometric mean {geometric_mean(values):.2f} over {len(values)} problems")
    return 0


def world_row(
    world: str, suite: str, domain: Path, problem: Path, planner: str, timeout: float, store: Store
) -> float | None:
    """Pure and relevance (no race) on one generated problem, one row printed; pure/relevance when either solved."""
    missing = planner_available(planner)
    if missing:
        print(f"{world:20} {planner:9} skipped: {missing}")
        return None
    try:
        runs = [
            timed_plan(
                domain, problem, PlanOptions(method=method, planner=planner, timeout=timeout, race=False), store, suite
            )
            for method in ("pure", "relevance")
        ]
    except RelevancePlanError as error:
        print(f"{world:20} {planner:9} refused: {error}")
        return None
    (pure, pure_time), (rel, rel_time) = runs
    solved = (pure.status is PlanStatus.SOLVED, rel.status is PlanStatus.SOLVED)
    pure_cell = f"{pure_time:8.2f}" if solved[0] else f"{pure.status.value:>8}"
    rel_cell = f"{rel_time:11.2f}" if solved[1] else f"{rel.status.value:>11}"
    kept = f"{rel.objects_kept}/{rel.objects_total}"
    ratio = (pure_time if solved[0] else timeout) / (rel_time if solved[1] else timeout)
    valid = all(r.valid for r, ok in zip((pure, rel), solved) if ok)
    note = "" if valid else "  PLAN NOT VALIDATED"
    print(
        f"{world:20} {planner:9} {rel.objects_total:7} {pure_cell} {rel_cell} {kept:>9} {ratio:8.2f}{note}", flush=True
    )
    return ratio if any(solved) else None


# --------------------------------------------------------------------------- the IPC corpus

TRACKS = ("temporal", "numeric", "timed-literals")
CORPUS_PLANNERS = ("lpg", "up:aries", "up:tamer", "up:enhsp", "up:kairos")
# A row where relevance took longer than this many times pure, plus SLOWER_SLACK seconds, is a miss.
SLOWER_FACTOR = 1.25
SLOWER_SLACK = 0.5
LABEL = 52  # the width of the folder column: year/folder


def corpus_folders(filters: list[str], families: bool) -> list[Path]:
    """The corpus folders of the temporal, numeric and timed-literals tracks, in manifest order,
    whose path contains one of ``filters`` (all when none); ``families``: the newest of each domain."""
    chosen = [(track, folder) for track in TRACKS for folder in corpus.folders(track)]
    if families:
        chosen = corpus.newest_of_each_family(chosen)
    root = corpus.corpus_root()
    return [f for _, f in chosen if not filters or any(text in str(f.relative_to(root)) for text in filters)]


@dataclass
class Row:
    """One (problem, planner) pair: the two runs and what they say."""

    folder: str
    problem: str
    planner: str
    objects: int
    extra: int
    pure: dict[str, Any]
    relevance: dict[str, Any]
    pure_seconds: float
    relevance_seconds: float
    pure_solved: bool
    relevance_solved: bool
    unvalidated: list[str] = field(default_factory=list)
    oracle: dict[str, Any] | None = None  # --oracle: the unpadded problem planned pure
    oracle_seconds: float | None = None
    oracle_solved: bool = False

    @property
    def counted(self) -> bool:
        return self.pure_solved or self.relevance_solved

    def charged(self, timeout: float) -> tuple[float, float]:
        """The two times, an unsolved run counted as the timeout."""
        return (
            self.pure_seconds if self.pure_solved else timeout,
            self.relevance_seconds if self.relevance_solved else timeout,
        )

    def ratio(self, timeout: float) -> float:
        pure, relevance = self.charged(timeout)
        return pure / relevance

    def oracle_ratio(self, timeout: float) -> float:
        """pure/oracle, an unsolved oracle run counted as the timeout."""
        pure, _ = self.charged(timeout)
        assert self.oracle_seconds is not None
        return pure / (self.oracle_seconds if self.oracle_solved else timeout)

    def slower(self, timeout: float) -> bool:
        pure, relevance = self.charged(timeout)
        return self.counted and relevance > SLOWER_FACTOR * pure + SLOWER_SLACK


def compact(result: dict[str, Any]) -> dict[str, Any]:
    """A result's JSON without its plan's steps, each attempt's object lists as their lengths."""
    attempts = [
        {key: len(value) if isinstance(value, list) else value for key, value in attempt.items()}
        for attempt in result["attempt_log"]
    ]
    return {**{key: value for key, value in result.items() if key != "plan"}, "attempt_log": attempts}


def accepts(planner: str, domain: Domain, problem: Problem, path: Path) -> str | None:
    """Why ``planner`` refuses this problem (its declared features, through the registry), or None."""
    try:
        prepare_planner(make_planner(planner), domain, problem, str(path))
    except RelevancePlanError as error:
        return error.message
    return None


def note(message: str) -> None:
    print(message, file=sys.stderr, flush=True)


def corpus_arguments(argv: list[str]) -> argparse.Namespace:
    parser = argparse.ArgumentParser(
        prog="bench_temporal.py corpus",
        description="Pure vs relevance (as users get it) on the IPC temporal, numeric and timed-literals "
        "folders of benchmarks/corpus, unpadded or padded with clones of objects the goal does not need.",
        epilog="With --one-per-family on 2 cores: about an hour unpadded (--timeout 20); over the pairs pure"
        " solved (--pure-solved-in), about 10 minutes unpadded and 25 minutes padded with 120 clones (--timeout 15;"
        " --oracle: 27 minutes).",
    )
    parser.add_argument("--planners", default=",".join(CORPUS_PLANNERS), help="comma-separated planner names")
    parser.add_argument(
        "--folders", action="append", default=[], help="only folders whose path contains this text (repeatable)"
    )
    parser.add_argument("--one-per-family", action="store_true", help="the newest folder of each track and domain")
    parser.add_argument("--extra", type=int, default=0, help="pad each problem with this many clones")
    parser.add_argument("--seed", type=int, default=1, help="the padding's seed")
    parser.add_argument(
        "--oracle",
        action="store_true",
        help="with --extra: also plan each problem as published (the padding removed), pure, in the same run",
    )
    parser.add_argument("--timeout", type=float, default=30.0, help="per run, seconds")
    parser.add_argument("--per-folder", type=int, default=1, help="the K smallest problems of each folder")
    parser.add_argument("--no-race", action="store_true", help="relevance without the race (one core)")
    parser.add_argument("--json", type=Path, help="write the raw rows (both results' JSON) here")
    parser.add_argument(
        "--pure-solved-in",
        type=Path,
        metavar="JSON",
        help="only the (problem, planner) pairs whose pure run solved in this earlier --json output",
    )
    add_store_option(parser)
    args = parser.parse_args(argv)
    if args.oracle and not args.extra:
        parser.error("--oracle needs --extra: the oracle is the problem without its padding")
    args.wanted = None
    if args.pure_solved_in:
        earlier = json.loads(args.pure_solved_in.read_text(encoding="utf-8"))
        args.wanted = {(row["folder"], row["problem"], row["planner"]) for row in earlier if row["pure_solved"]}
    args.race = race_by_default("relevance") and not args.no_race
    return args


@dataclass
class Tally:
    """What the corpus run found besides its rows: refusals, unreadable and unpaddable problems."""

    refused: dict[str, int]
    unreadable: list[str] = field(default_factory=list)
    unpaddable: list[str] = field(default_factory=list)


def run_corpus(argv: list[str]) -> int:
    args = corpus_arguments(argv)
    usable = []
    for name in (name.strip() for name in args.planners.split(",") if name.strip()):
        missing = planner_available(name)
        if missing:
            print(f"# {name} skipped: {missing}")
        else:
            usable.append(name)
    folders = corpus_folders(args.folders, args.one_per_family)
    print(
        f"# {len(folders)} folders, planners {', '.join(usable)}; --extra {args.extra} (seed {args.seed}),"
        f" --timeout {args.timeout:g}, relevance {'with' if args.race else 'without'} the race"
    )
    header = (
        f"{'folder':58} {'planner':9} {'objects':>7} {'pure s':>8} {'relev. s':>8} {'kept':>7} {'att':>3} {'ratio':>6}"
    )
    print(header, flush=True)
    rows: list[Row] = []
    tally = Tally({name: 0 for name in usable})
    with (
        tempfile.TemporaryDirectory(prefix="bench-temporal-corpus-") as scratch,
        Store(args.store, "bench_temporal") as store,
    ):
        for folder in folders:
            label = f"{folder.parent.name}/{folder.name}"
            for entry in smallest_problems(folder, args.per_folder):
                if args.wanted is not None and not any(key[:2] == (label, entry.problem.name) for key in args.wanted):
                    continue
                read = read_corpus_problem(
                    entry, label, args, Path(scratch) / f"{len(rows)}-{entry.problem.name}", tally
                )
                if read is None:
                    continue
                for planner in usable:
                    if args.wanted is None or (label, entry.problem.name, planner) in args.wanted:
                        row = corpus_row(entry, label, read, planner, args, store, tally)
                        if row is not None:
                            rows.append(row)
                            print(format_row(row, args.timeout), flush=True)
    print_summary(rows, usable, tally, args.timeout)
    if args.json:
        lines = ",\n".join(json.dumps(asdict(row)) for row in rows)
        args.json.write_text(f"[\n{lines}\n]\n", encoding="utf-8")
    return 1 if any(row.unvalidated for row in rows) else 0


def read_corpus_problem(
    entry: SuiteProblem, label: str, args: argparse.Namespace, padded: Path, tally: Tally
) -> tuple[Domain, Problem, Path] | None:
    """(domain, problem, the file to plan): the problem as published, or padded into ``padded``; None
    (and a line saying why) when our reader refuses it or it has nothing to clone."""
    assert entry.domain is not None
    try:
        domain = load_domain(entry.domain)
        problem = load_problem(entry.problem, domain)
    except RelevancePlanError as error:
        tally.unreadable.append(label)
        print(f"{label:{LABEL}} our reader refuses it: {error.message[:80]}")
        return None
    if not args.extra:
        return domain, problem, entry.problem
    try:
        problem = pad_with_clones(domain, problem, args.extra, seed=args.seed)
    except RelevancePlanError as error:
        tally.unpaddable.append(label)
        print(f"{label:{LABEL}} not padded: {error.message[:80]}")
        return None
    return domain, problem, write_text_atomic(padded, format_problem(problem))


def corpus_row(
    entry: SuiteProblem,
    label: str,
    read: tuple[Domain, Problem, Path],
    planner: str,
    args: argparse.Namespace,
    store: Store,
    tally: Tally,
) -> Row | None:
    """Pure, then relevance (and with --oracle the problem as published) with one planner; None when its
    features refuse the problem."""
    assert entry.domain is not None
    domain, problem, path = read
    why = accepts(planner, domain, problem, path)
    if why is not None:
        tally.refused[planner] += 1
        note(f"{label} {planner}: refused ({why[:100]})")
        return None
    note(f"{label} {planner}: pure")
    pure_options = PlanOptions(method="pure", planner=planner, timeout=args.timeout)
    pure, pure_time = timed_plan(entry.domain, path, pure_options, store, label)
    note(f"{label} {planner}: relevance")
    relevance_options = PlanOptions(planner=planner, timeout=args.timeout, race=args.race)
    rel, rel_time = timed_plan(entry.domain, path, relevance_options, store, label)
    oracle = oracle_time = None
    if args.oracle:
        note(f"{label} {planner}: oracle (the problem as published)")
        oracle, oracle_time = timed_plan(entry.domain, entry.problem, pure_options, store, label, "oracle")
    return Row(
        folder=label,
        problem=entry.problem.name,
        planner=planner,
        objects=len(problem.objects),
        extra=args.extra,
        pure=compact(pure.to_json()),
        relevance=compact(rel.to_json()),
        pure_seconds=pure_time,
        relevance_seconds=rel_time,
        pure_solved=pure.status is PlanStatus.SOLVED,
        relevance_solved=rel.status is PlanStatus.SOLVED,
        unvalidated=[
            method
            for method, r in (("pure", pure), ("relevance", rel), ("oracle", oracle))
            if r is not None and r.status is PlanStatus.SOLVED and not r.valid
        ],
        oracle=None if oracle is None else compact(oracle.to_json()),
        oracle_seconds=oracle_time,
        oracle_solved=oracle is not None and oracle.status is PlanStatus.SOLVED,
    )


def format_row(row: Row, timeout: float) -> str:
    pure = f"{row.pure_seconds:8.2f}" if row.pure_solved else f"{_short(row.pure['status']):>8}"
    rel = f"{row.relevance_seconds:8.2f}" if row.relevance_solved else f"{_short(row.relevance['status']):>8}"
    kept = f"{_first_kept(row.relevance)}/{row.objects}"
    ratio = f"{row.ratio(timeout):6.2f}" if row.counted else f"{'-':>6}"
    attempts = row.relevance["attempts"]
    line = f"{row.folder:{LABEL}} {row.planner:9} {row.objects:7} {pure} {rel} {kept:>7} {attempts:3} {ratio}"
    if row.oracle is not None:
        oracle = f"{row.oracle_seconds:.2f}" if row.oracle_solved else _short(row.oracle["status"])
        line += f"  oracle {oracle}"
    if row.unvalidated:
        line += f"  !!! SOLVED BUT NOT VALIDATED: {', '.join(row.unvalidated)}"
    return line


def _short(status: str) -> str:
    return {"out-of-time": "timeout", "planner-error": "error", "unsupported": "unsupp."}.get(status, status[:8])


def _first_kept(result: dict[str, Any]) -> int:
    """How many objects the first pruned attempt kept (the full count when nothing was pruned)."""
    for attempt in result["attempt_log"]:
        if attempt["pruned"]:
            return int(attempt["objects_kept"])
    return int(result["objects_total"])


def print_summary(rows: list[Row], planners: list[str], tally: Tally, timeout: float) -> None:
    print()
    if tally.unreadable:
        print(f"# our reader refuses {len(tally.unreadable)} problems: {', '.join(tally.unreadable)}")
    if tally.unpaddable:
        print(f"# {len(tally.unpaddable)} problems have no object to clone: {', '.join(tally.unpaddable)}")
    for planner in planners:
        mine = [row for row in rows if row.planner == planner]
        counted = [row for row in mine if row.counted]
        mean = geometric_mean(row.ratio(timeout) for row in counted)
        slower = [row for row in counted if row.slower(timeout)]
        pure_only = sum(1 for row in counted if row.pure_solved and not row.relevance_solved)
        rel_only = sum(1 for row in counted if row.relevance_solved and not row.pure_solved)
        print(
            f"{planner}: {len(mine)} rows ({tally.refused[planner]} problems refused by its features),"
            f" {len(mine) - len(counted)} solved by neither; pure/relevance geometric mean {mean:.2f}"
            f" over {len(counted)}; relevance slower (> {SLOWER_FACTOR}x + {SLOWER_SLACK} s) on {len(slower)};"
            f" solved by pure only {pure_only}, by relevance only {rel_only}"
        )
        with_oracle = [row for row in counted if row.oracle is not None]
        if with_oracle:
            oracle_mean = geometric_mean([row.oracle_ratio(timeout) for row in with_oracle])
            print(
                f"    pure/oracle (the problem as published, planned pure) geometric mean {oracle_mean:.2f}"
                f" over the same {len(with_oracle)} rows; oracle unsolved on"
                f" {sum(1 for row in with_oracle if not row.oracle_solved)}"
            )
        missed = [row for row in mine if not row.counted and row.oracle_solved]
        if missed:
            print(f"    solved by the oracle but by neither side: {len(missed)} rows")
            for row in missed:
                print(f"        {row.folder} ({row.problem}): oracle {row.oracle_seconds:.2f} s")
        for row in slower:
            pure, rel = row.charged(timeout)
            print(f"    slower: {row.folder} ({row.problem}) pure {pure:.2f} s, relevance {rel:.2f} s")
    flagged = [row for row in rows if row.unvalidated]
    if flagged:
        print(f"!!! {len(flagged)} rows solved without a validated plan: " + ", ".join(r.folder for r in flagged))


USAGE = (
    "usage: bench_temporal.py [worlds] [--quick] [--timeout S] [--seed N]   (worlds --help: its options)\n"
    "       bench_temporal.py corpus [options]                              (corpus --help: its options)\n"
)


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    if argv and argv[0] == "corpus":
        return run_corpus(argv[1:])
    if argv and argv[0] == "worlds":
        return run_worlds(argv[1:])
    if argv and argv[0] in ("-h", "--help"):
        print(USAGE + "\n" + (__doc__ or ""))
        return 0
    return run_worlds(argv)


if __name__ == "__main__":
    sys.exit(main())
