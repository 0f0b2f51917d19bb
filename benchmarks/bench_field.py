"""The field's own problems: does `prune` accept them, and is relevance ever slower than the planner?

Walks one or more corpus folders (any layout `compare` reads: IPC folders with
``domain.pddl``, per-problem domain files, potassco's ``domains/`` +
``instances/``, pddlgym's ``NAME.pddl`` + ``NAME/``), one entry per folder.

``accept`` (the default) reads each folder's domain and first problem and
prunes it with the goal scorer (no planner), then prints per track
(classical, adl, numeric, temporal, pddl3; from the requirements and the
model; FOND/PPDDL, PDDL+ and malformed files apart) how many folders were
accepted, and every refusal with its one line.
A traceback is a failure of the tool, never a refusal.  Target: at least
95 % of the folders of every track except PDDL+ accepted.  Takes about a
second per folder.

``speed`` runs, for every classical problem Fast Downward reads (up to
``--per-folder`` problems per folder), pure Fast Downward (`lama-first`) and
`relevance-plan plan` (the goal scorer, every plan validated on the
original), one after the other in one run, and prints pure / relevance per
problem, the geometric mean (target >= 0.95) and every problem slower than
pure x 1.25 + 0.5 s (target: none).  Both count the whole process, start-up
included (`--in-process` measures the library call instead): the tool runs
from this checkout with its bytecode compiled, or with `--installed` as a
user has it (a wheel of the checkout in a new virtual environment; see
``installed.py``).  `--repeat N` times each problem N times, pure and
relevance in turn, and takes the medians (a single run of a 0.2 s problem
varies by a few hundredths on a shared machine).  Takes a few minutes per
50 problems and repetition on 2 cores.

The folders default to the repository's corpus, ``benchmarks/corpus``
(``benchmarks/corpus/README.md``).  ``--pddlgym`` adds PLOI's many-object
problems (pddlgym's ``manyX/`` and ``manyX_test/`` folders beside their
``manyX.pddl``), which come from the ``pddlgym`` wheel rather than the
corpus: ``pip install --no-deps pddlgym==0.0.7`` (its files only are read,
the package is never imported); ``--pddlgym-only`` reads those alone.
Without the wheel, either option says so (and ``--pddlgym`` runs the other
folders).  Output names files relative to the repository
(pddlgym's as ``pddlgym/...``).

    python benchmarks/bench_field.py accept
    python benchmarks/bench_field.py accept --pddlgym
    python benchmarks/bench_field.py speed benchmarks/corpus/potassco --per-folder 2 --timeout 60
    python benchmarks/bench_field.py speed --pddlgym-only --installed --repeat 3
    python benchmarks/bench_field.py selections --pddlgym --per-folder 2 --against before.jsonl

``selections`` prints, as JSON lines, each problem's first selection (the
goal scorer, no planner; up to ``--per-folder`` problems per folder): the
kept objects and why each one not selected came back.  With ``--against``
(the lines of another version), it also says on stderr which problems keep
another set now: what a change to the pruning core changed across the field
(a file that is not such output stops it at once, exit 1, with one line).
"""

from __future__ import annotations

import argparse
import importlib.util
import json
import math
import os
import statistics
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

from base import REPO, Laps, geometric_mean, run_timed, suite_entries
from corpus import folders as corpus_folders
from installed import compiled_checkout, installed_environment, installed_tool

from relevance_plan.batch.suites import SuiteProblem
from relevance_plan.errors import PDDLParseError, RelevancePlanError
from relevance_plan.io import load_domain, load_problem
from relevance_plan.pddl.model import Domain
from relevance_plan.planning.planners.requirements import NUMERIC_FLUENTS, domain_features

DEFAULT_CORPUS = REPO / "benchmarks" / "corpus"
PDDLGYM_DOMAINS = (
    "manyblocksnopiles",
    "manyblockssmallpiles",
    "manyexplodingblockssmallpiles",
    "manyferry",
    "manygrid",
    "manygripper",
    "manylogistics",
    "manymiconic",
    "manytireworld",
)


def pddlgym_folder() -> Path | None:
    """pddlgym's ``pddl`` folder in the installed wheel, found without importing the package
    (its dependencies are heavy and none of its code is needed); None when it is not installed."""
    spec = importlib.util.find_spec("pddlgym")
    if spec is None or not spec.submodule_search_locations:
        return None
    folder = Path(next(iter(spec.submodule_search_locations))) / "pddl"
    return folder if folder.is_dir() else None


def pddlgym_roots() -> list[str]:
    """PLOI's many-object folders of the installed pddlgym (``manyX/`` and ``manyX_test/``)."""
    folder = pddlgym_folder()
    if folder is None:
        return []
    return [
        str(folder / f"{name}{tail}")
        for name in PDDLGYM_DOMAINS
        for tail in ("", "_test")
        if (folder / f"{name}{tail}").is_dir()
    ]


def shown(text: str | Path) -> str:
    """``text`` with the repository's and pddlgym's absolute folders made relative, so that
    saved outputs name no folder of one machine."""
    text = str(text)
    folder = pddlgym_folder()
    if folder is not None:  # first: the wheel may be installed in a virtual environment inside the checkout
        text = text.replace(f"{folder}{os.sep}", "pddlgym/")
    return text.replace(f"{REPO}{os.sep}", "")


@dataclass
class Folder:
    path: Path
    entries: list[SuiteProblem]


def folders(roots: list[str]) -> list[Folder]:
    """Every folder under ``roots`` that holds a problem with a domain (its first problems)."""
    found: list[Folder] = []
    for root in roots:
        for directory in _directories(Path(root)):
            try:
                entries = suite_entries(Path(directory))
            except RelevancePlanError:
                continue
            if entries:
                found.append(Folder(Path(directory), entries))
    seen: set[tuple] = set()
    unique = []
    for folder in found:  # a domain file shared by nested folders counts once
        key = (str(folder.entries[0].domain), str(folder.entries[0].problem))
        if key not in seen:
            seen.add(key)
            unique.append(folder)
    return unique


def _directories(root: Path) -> list[Path]:
    """The folders under ``root`` to read: the corpus's domain folders from its manifest when
    ``root`` lies in the corpus, else every folder that holds a PDDL file."""
    resolved, corpus = root.resolve(), DEFAULT_CORPUS.resolve()
    if resolved == corpus or corpus in resolved.parents:
        listed = [folder for folder in corpus_folders(root=corpus) if folder == resolved or resolved in folder.parents]
        if listed:
            return listed
    found = []
    for directory, subdirectories, files in sorted(os.walk(root)):
        subdirectories.sort()
        if any(name.endswith(".pddl") for name in files):
            found.append(Path(directory))
    return found


def track(domain: Domain) -> str:
    """The competition track a domain belongs to; action costs, even from a cost function such as
    ``(road-length ?a ?b)``, are classical planning since 2008."""
    requirements = domain.requirements
    if {":processes", ":events", ":time"} & requirements:
        return "pddl+"
    if domain.temporal or ":durative-actions" in requirements:
        return "temporal"
    if NUMERIC_FLUENTS in domain_features(domain) or {":fluents", ":numeric-fluents"} & requirements:
        return "numeric"
    if domain.constraints is not None or {":preferences", ":constraints"} & requirements:
        return "pddl3"
    if domain.derived or {":adl", ":conditional-effects", ":derived-predicates"} & requirements:
        return "adl"
    return "classical"


def accept(roots: list[str]) -> int:
    from relevance_plan.relevance.analysis.task import PlanningTask
    from relevance_plan.relevance.setup import ScoringOptions, score_problem

    totals: dict[str, list[int]] = {}
    failures = 0
    for folder in folders(roots):
        entry = folder.entries[0]
        name = shown(folder.path)
        kind, verdict = "?", "ok"
        try:
            domain = load_domain(entry.domain)
            kind = track(domain)
            problem = load_problem(entry.problem, domain)
            selection = score_problem(PlanningTask(domain, problem), ScoringOptions(scorer="goal")).first_selection()
            verdict = f"ok, kept {len(selection.kept)}/{len(problem.objects)}"
        except PDDLParseError as error:
            verdict, kind = f"refused: {error}", "malformed"
        except RelevancePlanError as error:
            verdict = f"refused: {error}"
            kind = kind if kind != "?" else _guess_track(entry.domain)
        except Exception as error:  # a traceback is the tool's failure, counted apart
            verdict = f"FAILURE {type(error).__name__}: {error}"
            failures += 1
        counts = totals.setdefault(kind, [0, 0])
        counts[1] += 1
        counts[0] += verdict.startswith("ok")
        if not verdict.startswith("ok"):
            print(f"{kind:<10} {name}: {shown(verdict)[:200]}")
    print()
    print("| track | folders | accepted | share | target |")
    print("|---|---|---|---|---|")
    for kind, (ok, total) in sorted(totals.items()):
        target = "-" if kind in ("pddl+", "fond/ppddl", "malformed") else ">= 95 %"
        print(f"| {kind} | {total} | {ok} | {100 * ok / total:.0f} % | {target} |")
    print(f"\ntracebacks: {failures}")
    return 1 if failures else 0


def _guess_track(domain_path: Path) -> str:
    """The track of a domain our reader refused: from its text."""
    text = domain_path.read_text(errors="replace").lower()
    words = (
        (":non-deterministic", "fond/ppddl"),
        ("(oneof", "fond/ppddl"),
        (":probabilistic-effects", "fond/ppddl"),
        ("(probabilistic", "fond/ppddl"),
        (":durative-action", "temporal"),
        (":process", "pddl+"),
        (":functions", "numeric"),
    )
    for word, kind in words:
        if word in text:
            return kind
    return "classical"


def speed(roots: list[str], per_folder: int, timeout: float, in_process: bool, installed: bool, repeat: int) -> int:
    from relevance_plan.planning.planners.fast_downward.adapter import find_fast_downward

    driver = str(find_fast_downward())
    rows = []
    with tempfile.TemporaryDirectory(prefix="bench-field-") as folder:
        scratch = Path(folder)
        if installed:
            tool, env = installed_tool(scratch), installed_environment()
            print(f"relevance-plan as installed from a wheel of this checkout; medians of {repeat} run(s)\n")
        else:
            tool, env = compiled_checkout()
            print(f"relevance-plan from this checkout, bytecode compiled; medians of {repeat} run(s)\n")
        print("| problem | objects | pure (s) | relevance (s) | pure/relevance | kept | attempts |")
        print("|---|---|---|---|---|---|---|")
        for folder in folders(roots):
            for entry in folder.entries[:per_folder]:
                try:
                    domain = load_domain(entry.domain)
                    if track(domain) not in ("classical", "adl"):
                        continue
                    total = len(load_problem(entry.problem, domain).objects)
                except RelevancePlanError:
                    continue
                plan_file = scratch / "sas_plan"
                pure_command = [
                    sys.executable,
                    driver,
                    "--plan-file",
                    str(plan_file),
                    "--overall-time-limit",
                    f"{int(timeout)}s",
                    "--alias",
                    "lama-first",
                    str(entry.domain.resolve()),
                    str(entry.problem.resolve()),
                ]
                pure_times: list[float] = []
                relevance_times: list[float] = []
                for _ in range(repeat):
                    # in the scratch folder: Fast Downward's translator writes output.sas where it runs
                    pure_run = run_timed(pure_command, cwd=scratch, timeout=timeout + 30)
                    if pure_run.code != 0:
                        break
                    pure_times.append(pure_run.seconds)
                    kept, attempts, relevance = _relevance(entry, timeout, scratch, in_process, tool, env)
                    if relevance is None:
                        break
                    relevance_times.append(relevance)
                if len(pure_times) < repeat and len(pure_times) == len(relevance_times):
                    continue  # pure failed: the benchmark compares problems the planner alone solves
                pure = statistics.median(pure_times)
                relevance = statistics.median(relevance_times) if len(relevance_times) == repeat else None
                label = f"{_domain_name(entry.problem)}/{entry.problem.name}"
                if relevance is None:
                    print(f"| {label} | {total} | {pure:.2f} | FAILED | - | - | - |")
                    rows.append((entry.problem, pure, math.inf))
                    continue
                rows.append((entry.problem, pure, relevance))
                print(
                    f"| {label} | {total} | {pure:.2f} | {relevance:.2f}"
                    f" | {pure / relevance:.2f} | {kept}/{total} | {attempts} |",
                    flush=True,
                )
    return _speed_summary(rows)


def selections(roots: list[str], per_folder: int, timeout: float, against: Path | None) -> int:
    """Each problem's first selection as a JSON line; with ``against``, the problems that keep
    another set than those lines say (on stderr)."""
    before = _selections_file(against) if against is not None else {}
    rows, changed, unmatched = 0, [], 0
    for folder in folders(roots):
        for entry in folder.entries[:per_folder]:
            row = {"problem": shown(entry.problem), **_first_selection(entry, timeout)}
            print(json.dumps(row), flush=True)
            rows += 1
            old = before.get(row["problem"])
            unmatched += old is None
            if old is not None and (old.get("kept"), old.get("error")) != (row.get("kept"), row.get("error")):
                changed.append((row, old))
    if against is not None:
        print(f"{len(changed)} of {rows} problems keep another set than {against}", file=sys.stderr)
        if unmatched:
            print(f"  ({unmatched} of them have no line there: not compared)", file=sys.stderr)
        for row, old in changed:
            now, then = row.get("kept", row.get("error")), old.get("kept", old.get("error"))
            shown_now = f"{len(now)} objects" if isinstance(now, list) else now
            shown_then = f"{len(then)} objects" if isinstance(then, list) else then
            print(f"  {row['problem']}: {shown_then} -> {shown_now}", file=sys.stderr)
    return 0


def _selections_file(path: Path) -> dict[str, dict]:
    """Problem -> its line in ``path`` (the output of ``selections``); exits with a one-line reason
    when the file cannot be read or is not that output."""
    try:
        rows = [json.loads(line) for line in path.read_text(encoding="utf-8").splitlines() if line.strip()]
        return {row["problem"]: row for row in rows}
    except (OSError, UnicodeDecodeError, ValueError, KeyError, TypeError) as error:
        sys.exit(f"{path}: not the output of 'bench_field.py selections' ({type(error).__name__}: {error})")


def _first_selection(entry: SuiteProblem, timeout: float) -> dict:
    """The kept objects of ``entry``'s first selection and why each came back, or the error's kind."""
    from relevance_plan.relevance.analysis.task import PlanningTask
    from relevance_plan.relevance.setup import ScoringOptions, score_problem

    started = time.monotonic()
    try:
        domain = load_domain(entry.domain)
        task = PlanningTask(domain, load_problem(entry.problem, domain), deadline=started + timeout)
        selection = score_problem(task, ScoringOptions()).first_selection()
    except RelevancePlanError as error:
        return {"error": type(error).__name__}
    return {
        "kept": sorted(selection.kept),
        # ``describe``, or an older checkout's ``reason``: the fact, spelled as the problem writes it
        "restored": [
            [item.name, item.describe(task.problem.spelling) if hasattr(item, "describe") else item.reason]
            for item in selection.restored
        ],
        "seconds": round(time.monotonic() - started, 2),
    }


def _domain_name(problem: Path) -> str:
    """The folder that names a problem's domain (``tetris/instances/instance-1.pddl``: tetris)."""
    folder = problem.parent
    return folder.parent.name if folder.name in ("instances", "problems") else folder.name


def _relevance(entry: SuiteProblem, timeout: float, scratch: Path, in_process: bool, tool: list[str], env: dict):
    if in_process:
        from relevance_plan.planning.options import PlanOptions
        from relevance_plan.planning.results import PlanStatus
        from relevance_plan.planning.run import plan_task

        laps = Laps()
        result = plan_task(entry.domain, entry.problem, PlanOptions(timeout=timeout, scorer="goal"))
        elapsed = laps.end()["total"]
        solved = result.status is PlanStatus.SOLVED
        return result.objects_kept, len(result.attempts), elapsed if solved else None
    command = [
        *tool,
        "plan",
        str(entry.domain.resolve()),
        str(entry.problem.resolve()),
        "--json",
        "--scorer",
        "goal",
        "--timeout",
        str(timeout),
        "--plan-file",
        str(scratch / "plan"),
    ]
    run = run_timed(command, cwd=scratch, env=env, timeout=timeout + 60)
    if run.code != 0:
        return None, None, None
    data = json.loads(run.stdout)
    return data["objects_kept"], data["attempts"], run.seconds


def _speed_summary(rows: list) -> int:
    ratios = [pure / relevance for _, pure, relevance in rows if relevance not in (None, math.inf)]
    if not rows:
        print("no classical problem that Fast Downward solves was found")
        return 1
    gmean = geometric_mean(ratios) if ratios else 0.0
    slow = [(p, pure, rel) for p, pure, rel in rows if rel > pure * 1.25 + 0.5]
    print(f"\n{len(rows)} problems; geometric mean pure/relevance {gmean:.2f} (target >= 0.95)")
    longer = [pure / rel for _, pure, rel in rows if pure >= 1.0 and rel not in (None, math.inf)]
    if longer:
        print(f"where pure takes >= 1 s: {len(longer)} problems, geometric mean {geometric_mean(longer):.2f}")
    extra = sorted(rel - pure for _, pure, rel in rows if rel not in (None, math.inf))
    print(f"median extra time of relevance over pure: {statistics.median(extra):+.2f} s")
    print(f"slower than pure x 1.25 + 0.5 s: {len(slow)} (target 0)")
    for problem, pure, rel in slow:
        print(f"  {shown(problem)}: pure {pure:.2f} s, relevance {rel:.2f} s")
    return 0


def main() -> int:
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0],
        epilog=__doc__.split("\n\n", 1)[1],
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument("mode", choices=("accept", "speed", "selections"), nargs="?", default="accept")
    parser.add_argument("roots", nargs="*", help="corpus folders (default: benchmarks/corpus)")
    parser.add_argument(
        "--pddlgym", action="store_true", help="add PLOI's many-object folders of the installed pddlgym wheel"
    )
    parser.add_argument("--pddlgym-only", action="store_true", help="read only those pddlgym folders")
    parser.add_argument("--per-folder", type=int, default=1, help="problems per folder in speed mode")
    parser.add_argument("--timeout", type=float, default=60.0)
    parser.add_argument("--in-process", action="store_true", help="time the library call, not the command")
    parser.add_argument("--installed", action="store_true", help="run a wheel of the checkout in a new venv")
    parser.add_argument("--repeat", type=int, default=1, help="runs of each command per problem (medians)")
    parser.add_argument("--against", type=Path, help="selections mode: the JSON lines of another version")
    args = parser.parse_args()
    if args.pddlgym_only and args.roots:
        parser.error("--pddlgym-only takes no folders")
    args.roots = [] if args.pddlgym_only else args.roots or [str(DEFAULT_CORPUS)]
    for root in args.roots:
        if not Path(root).is_dir():
            parser.error(f"not a folder: {root}")
    if args.pddlgym or args.pddlgym_only:
        more = pddlgym_roots()
        if not more:
            print(
                "pddlgym is not installed (pip install --no-deps pddlgym==0.0.7): its many-object folders are left out"
            )
        args.roots += more
    if not args.roots:
        return 1
    if args.mode == "accept":
        return accept(args.roots)
    if args.mode == "selections":
        return selections(args.roots, args.per_folder, args.timeout, args.against)
    return speed(args.roots, args.per_folder, args.timeout, args.in_process, args.installed, max(1, args.repeat))


if __name__ == "__main__":
    sys.exit(main())
