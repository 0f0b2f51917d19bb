#!/usr/bin/env python
"""Differential validation: does the builtin simulator agree with VAL on real plans and their mutations?

For every domain folder found under the given roots (read the way
``relevance_plan.io.find_suite_problems`` reads a suite folder: a domain file
beside its problems, or problems in ``instances/`` or ``problems/``), the
first problem (or the one ``--problem`` names) is solved by a planner chosen by
what the domain uses: Fast Downward (lama-first) for classical, ADL and
action-cost domains, LPG then Aries then Tamer for temporal ones, LPG then
ENHSP for numeric ones.  The planner runs through the project's own adapter
(``make_planner``), so its plan is not filtered by any validator.  The plan and
seeded mutations of it — one step dropped, the last step dropped, two
adjacent steps swapped, one argument replaced by another object of the
problem (of the parameter's type when there is one) — are judged by the
builtin simulator, VAL (``pip install 'relevance-plan[val]'``) and, where its
reader reads the problem, unified-planning's validator.

A case agrees when every validator that gave a verdict gave the same one; a
validator that could not judge a case (VAL or UP refusing the files) is
counted apart, never as agreement.  On valid plans of a problem with a
metric, the builtin metric value is compared with VAL's final value too.
Prints agreement counts per track (the corpus manifest's, else the folder above the domain folder) and
every disagreement with each verdict and VAL's reason.

    python benchmarks/bench_validate.py                          # benchmarks/corpus of the repository
    python benchmarks/bench_validate.py ROOT... --time-limit 30 --seed 1 --json

A domain takes from a second to about two minutes (the planner's time limit,
once per planner tried, then VAL and UP on five plans).
"""

from __future__ import annotations

import argparse
import json
import random
import sys
from dataclasses import dataclass, field, replace
from pathlib import Path

import corpus
from base import Laps, suite_entries

from relevance_plan.errors import RelevancePlanError
from relevance_plan.io import load_task
from relevance_plan.pddl.model import Domain, Problem, all_objects
from relevance_plan.pddl.plans import Plan, format_plan
from relevance_plan.planning.planners.registry import make_planner
from relevance_plan.planning.validation import (
    ValidationResult,
    ValidationStatus,
    up_validator,
    val_available,
    validate_builtin,
    validate_with_val,
)

DEFAULT_ROOT = corpus.corpus_root()
# Fast Downward first for numeric domains too: it takes action costs read from static functions.
PLANNERS = {
    "classical": ("fast-downward",),
    "temporal": ("lpg", "up:aries", "up:tamer"),
    "numeric": ("fast-downward", "lpg", "up:enhsp"),
}
MEMORY_LIMIT_MB = 3000
METRIC_TOLERANCE = 1e-6


@dataclass
class Case:
    track: str
    domain: str
    name: str  # "plan" or the mutation
    verdicts: dict[str, ValidationResult] = field(default_factory=dict)

    def judged(self) -> dict[str, bool]:
        return {
            name: result.valid
            for name, result in self.verdicts.items()
            if result.status in (ValidationStatus.VALID, ValidationStatus.INVALID)
        }

    def agrees(self) -> bool | None:
        """True or False when two or more validators judged the case; None when fewer did."""
        judged = self.judged()
        if len(judged) < 2:
            return None
        if len(set(judged.values())) > 1:
            return False
        return self.metric_agrees()

    def metric_agrees(self) -> bool:
        builtin, val = self.verdicts.get("builtin"), self.verdicts.get("val")
        if builtin is None or val is None or not (builtin.valid and val.valid):
            return True
        if builtin.metric is None or val.metric is None:
            return builtin.metric is None and val.metric is None
        return abs(builtin.metric - val.metric) <= METRIC_TOLERANCE * max(1.0, abs(val.metric))

    def to_json(self) -> dict:
        return {
            "track": self.track,
            "domain": self.domain,
            "case": self.name,
            "agrees": self.agrees(),
            "verdicts": {
                name: {"status": r.status.value, "metric": r.metric, "step": r.failed_step, "reason": r.message}
                for name, r in self.verdicts.items()
            },
        }


def manifest_tracks(root: Path) -> dict[Path, str]:
    """Folder -> track, from the corpus manifest when ``root`` has one (``benchmarks/corpus``)."""
    return corpus.tracks(root) if (root / corpus.MANIFEST).is_file() else {}


def domain_folders(roots: list[Path]) -> list[tuple[str, str, list]]:
    """(track, domain name, its problems) of every suite folder under ``roots``; the track is the
    corpus manifest's where there is one, else the name of the folder above."""
    found = []
    for root in roots:
        tracks = manifest_tracks(root)
        for folder in sorted([root, *(p for p in root.rglob("*") if p.is_dir())]):
            if folder.name in ("instances", "problems", "domains"):
                continue
            try:
                problems = suite_entries(folder)
            except RelevancePlanError:
                continue
            if problems:
                found.append((tracks.get(folder.resolve(), folder.parent.name), folder.name, problems))
    return found


def choose_problem(problems, wanted: str | None):
    if wanted:
        for item in problems:
            if item.problem.stem == wanted or item.problem.name == wanted:
                return item
    return problems[0]


def kind_of(domain: Domain, problem: Problem) -> str:
    if domain.temporal or problem.timed_literals:
        return "temporal"
    return "numeric" if domain.numeric else "classical"


def solve(kind: str, domain_path: Path, problem_path: Path, time_limit: float) -> tuple[Plan | None, str]:
    notes = []
    for name in PLANNERS[kind]:
        try:
            planner = make_planner(name, check=True)
        except RelevancePlanError as error:
            notes.append(f"{name}: {error.message}")
            continue
        try:
            outcome = planner.run(
                str(domain_path), str(problem_path), time_limit=time_limit, memory_limit_mb=MEMORY_LIMIT_MB
            )
        except RelevancePlanError as error:
            notes.append(f"{name}: {error.message}")
            continue
        if outcome.solved and len(outcome.plan):
            return outcome.plan, name
        notes.append(f"{name}: {outcome.status.value}")
    return None, "; ".join(notes)


def mutations(plan: Plan, domain: Domain, problem: Problem, rng: random.Random) -> list[tuple[str, Plan]]:
    steps = list(plan.steps)
    found: list[tuple[str, Plan]] = []
    if len(steps) >= 2:
        drop = rng.randrange(len(steps) - 1)
        found.append((f"drop step {drop + 1}", replace(plan, steps=tuple(steps[:drop] + steps[drop + 1 :]))))
    found.append(("drop the last step", replace(plan, steps=tuple(steps[:-1]))))
    if len(steps) >= 2:
        i = rng.randrange(len(steps) - 1)
        swapped = list(steps)
        if plan.timed:  # the actions change places; the times stay where they were
            first, second = steps[i], steps[i + 1]
            swapped[i] = replace(second, time=first.time)
            swapped[i + 1] = replace(first, time=second.time)
        else:
            swapped[i], swapped[i + 1] = steps[i + 1], steps[i]
        found.append((f"swap steps {i + 1} and {i + 2}", replace(plan, steps=tuple(swapped))))
    replaced = _replace_argument(plan, domain, problem, rng)
    if replaced is not None:
        found.append(replaced)
    return found


def _replace_argument(plan: Plan, domain: Domain, problem: Problem, rng: random.Random) -> tuple[str, Plan] | None:
    objects = all_objects(domain, problem)
    with_args = [i for i, step in enumerate(plan.steps) if step.args]
    rng.shuffle(with_args)
    for index in with_args:
        step = plan.steps[index]
        action = domain.action(step.action)
        position = rng.randrange(len(step.args))
        old = step.args[position]
        wanted = action.parameters[position][1] if action is not None and position < len(action.parameters) else None
        pool = [o for o, t in objects.items() if o != old and (wanted is None or domain.is_subtype(t, wanted))]
        if not pool:
            continue
        new = rng.choice(sorted(pool))
        args = step.args[:position] + (new,) + step.args[position + 1 :]
        steps = plan.steps[:index] + (replace(step, args=args),) + plan.steps[index + 1 :]
        return f"step {index + 1}: {old} -> {new}", replace(plan, steps=steps)
    return None


def run(args) -> dict:
    roots = [Path(r) for r in args.roots] or [DEFAULT_ROOT]
    missing = [str(r) for r in roots if not r.is_dir()]
    if missing:
        raise SystemExit(f"bench_validate: no such folder: {', '.join(missing)}")
    if not val_available():
        raise SystemExit("bench_validate: VAL is not installed (pip install 'relevance-plan[val]')")
    cases: list[Case] = []
    skipped: list[dict] = []
    plans: list[dict] = []
    folders = domain_folders(roots)
    if args.limit:
        folders = folders[: args.limit]
    for track, name, problems in folders:
        item = choose_problem(problems, args.problem)
        laps = Laps()
        try:
            domain, problem = load_task(item.domain, item.problem)
        except RelevancePlanError as error:
            skipped.append({"track": track, "domain": name, "why": f"our reader: {error}"})
            print(f"[{track}] {name}: skipped, our reader: {error}", file=sys.stderr)
            continue
        kind = kind_of(domain, problem)
        plan, planner = solve(kind, Path(item.domain), Path(item.problem), args.time_limit)
        if plan is None:
            skipped.append({"track": track, "domain": name, "why": f"no plan ({planner})"})
            print(f"[{track}] {name}: skipped, no plan ({planner})", file=sys.stderr)
            continue
        rng = random.Random(f"{args.seed}:{name}")
        judge_up = up_validator(str(item.domain), str(item.problem)) if args.up else None
        for case_name, candidate in [("plan", plan), *mutations(plan, domain, problem, rng)]:
            case = Case(track, name, case_name)
            case.verdicts["builtin"] = validate_builtin(domain, problem, candidate)
            case.verdicts["val"] = validate_with_val(domain, problem, candidate)
            if judge_up is not None:
                case.verdicts["up"] = judge_up(candidate)
            cases.append(case)
            if args.plans_dir:
                write_case(Path(args.plans_dir), name, case_name, candidate, item)
        mine = [c for c in cases if c.domain == name and c.track == track]
        found = mine[0].verdicts
        plans.append(
            {
                "track": track,
                "domain": name,
                "problem": item.problem.name,
                "planner": planner,
                "steps": len(plan),
                "metric": {name: verdict.metric for name, verdict in found.items() if verdict.metric is not None},
            }
        )
        print(
            f"[{track}] {name} ({item.problem.name}, {planner}, {len(plan)} steps):"
            f" {sum(c.agrees() is True for c in mine)} of {len(mine)} cases agree"
            f" ({laps.end()['total']:.1f} s)",
            file=sys.stderr,
        )
    return summarize(cases, skipped, plans)


def write_case(folder: Path, domain_name: str, case_name: str, plan: Plan, item) -> None:
    """Write one case's plan (and where its domain and problem are) so both validators can be rerun on it."""
    target = folder / domain_name
    target.mkdir(parents=True, exist_ok=True)
    (target / (case_name.replace(" ", "-") + ".plan")).write_text(format_plan(plan))
    (target / "task.txt").write_text(f"{item.domain}\n{item.problem}\n")


def summarize(cases: list[Case], skipped: list[dict], plans: list[dict]) -> dict:
    tracks: dict[str, dict[str, int]] = {}
    for case in cases:
        row = tracks.setdefault(case.track, {"domains": 0, "cases": 0, "agree": 0, "disagree": 0, "one_verdict": 0})
        row["cases"] += 1
        verdict = case.agrees()
        row["agree" if verdict else "disagree" if verdict is False else "one_verdict"] += 1
    for track in tracks:
        tracks[track]["domains"] = len({c.domain for c in cases if c.track == track})
    unjudged = {name: sum(1 for c in cases if name in c.verdicts and name not in c.judged()) for name in ("val", "up")}
    return {
        "tracks": tracks,
        "cases": len(cases),
        "domains": len({(c.track, c.domain) for c in cases}),
        "agree": sum(c.agrees() is True for c in cases),
        "disagreements": [c.to_json() for c in cases if c.agrees() is False],
        "no_verdict": unjudged,
        "val_no_verdict_cases": [
            {"track": c.track, "domain": c.domain, "case": c.name, "reason": c.verdicts["val"].message}
            for c in cases
            if "val" in c.verdicts and "val" not in c.judged()
        ],
        "skipped": skipped,
        "plans": plans,
    }


def print_report(summary: dict) -> None:
    print(f"{'track':<14} {'domains':>7} {'cases':>6} {'agree':>6} {'disagree':>8} {'one verdict':>11}")
    for track, row in sorted(summary["tracks"].items()):
        print(
            f"{track:<14} {row['domains']:>7} {row['cases']:>6} {row['agree']:>6} {row['disagree']:>8}"
            f" {row['one_verdict']:>11}"
        )
    print(f"all: {summary['agree']} of {summary['cases']} cases agree on {summary['domains']} domains")
    print(f"cases a validator could not judge: VAL {summary['no_verdict']['val']}, UP {summary['no_verdict']['up']}")
    for item in summary["val_no_verdict_cases"]:
        print(f"  VAL no verdict: [{item['track']}] {item['domain']} / {item['case']}: {item['reason']}")
    for item in summary["disagreements"]:
        print(f"DISAGREE [{item['track']}] {item['domain']} / {item['case']}")
        for name, verdict in item["verdicts"].items():
            metric = "" if verdict["metric"] is None else f" metric {verdict['metric']:g}"
            print(f"    {name:<8} {verdict['status']}{metric}: {verdict['reason']}")
    for item in summary["skipped"]:
        print(f"skipped [{item['track']}] {item['domain']}: {item['why']}")
    for item in summary["plans"]:
        values = ", ".join(f"{name} {value:g}" for name, value in item["metric"].items()) or "no metric"
        where = f"[{item['track']}] {item['domain']} {item['problem']}"
        print(f"plan {where} ({item['planner']}, {item['steps']} steps): {values}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("roots", nargs="*", help="folders holding domain folders (default: benchmarks/corpus)")
    parser.add_argument("--time-limit", type=float, default=30.0, help="seconds per planner run")
    parser.add_argument("--seed", type=int, default=1, help="seed of the mutations")
    parser.add_argument("--problem", help="the problem to solve in each folder, by name (default: the first)")
    parser.add_argument("--limit", type=int, default=0, help="at most this many domain folders")
    parser.add_argument("--no-up", dest="up", action="store_false", help="leave unified-planning's validator out")
    parser.add_argument("--plans-dir", help="write each case's plan under this folder, one subfolder per domain")
    parser.add_argument("--json", action="store_true", help="print one JSON object")
    args = parser.parse_args()
    summary = run(args)
    if args.json:
        print(json.dumps(summary, indent=2))
    else:
        print_report(summary)


if __name__ == "__main__":
    main()
