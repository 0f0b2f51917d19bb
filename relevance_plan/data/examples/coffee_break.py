"""The paper's coffee-break demonstration (Section VI) replayed through the live session.

    python examples/coffee_break.py            # needs Fast Downward (the up-fast-downward wheel)

The same run from the command line, one JSON line per event:

    relevance-plan watch domains/coffee/domain.pddl examples/coffee-break/scene.pddl \\
        --events examples/coffee-break/events.jsonl --objective drink-at-break --plan
"""

from __future__ import annotations

import json
import tempfile
from pathlib import Path

from relevance_plan.data import DOMAINS_DIR
from relevance_plan.io import load_task
from relevance_plan.planning.options import PlanOptions
from relevance_plan.planning.planners.registry import make_planner
from relevance_plan.relevance.setup import ScoringOptions
from relevance_plan.session import Session

HERE = Path(__file__).resolve().parent / "coffee-break"
DOMAIN = DOMAINS_DIR / "coffee" / "domain.pddl"


def main() -> None:
    domain, problem = load_task(DOMAIN, HERE / "scene.pddl")
    planner = make_planner("fast-downward", "lama-first", check=True)
    with tempfile.TemporaryDirectory() as scratch:

        def run_planner(text: str, limit):
            path = Path(scratch) / "problem.pddl"
            path.write_text(text)
            return planner.run(str(DOMAIN), str(path), time_limit=limit, memory_limit_mb=None)

        # The context of the scene: a conference break.  Who is served, and what they want, comes as events.
        options = ScoringOptions(objective="drink-at-break")
        session = Session(
            domain,
            problem,
            options,
            domain_path=str(DOMAIN),
            plan_options=PlanOptions(timeout=60),
            run_planner=run_planner,
            plan_in_loop=True,
        )
        show = session.scene.display.get
        for line in (HERE / "events.jsonl").read_text().splitlines():
            event = json.loads(line)
            report = session.handle(event)
            if "fact" in event:
                what = "(" + " ".join(event["fact"]) + ")"
            else:
                what = " ".join(
                    str(v) for k, v in event.items() if k not in ("event", "facts", "note") and v is not None
                )
            print(f"{report.seq:>2} {report.event:<6} {what:<24} ", end="")
            if not report.triggered and report.plan is None:
                print("-  nothing triggered" + (f" (error: {report.error})" if report.error else ""))
                continue
            if report.triggered:
                print(f"TRIGGERED: {report.reason}")
            else:
                print("plan requested")
            if report.triggered and not report.sufficient:
                print(f"{'':34}insufficient cues: {report.insufficiency.split(' — ')[0]}")
            elif report.triggered and report.selection is not None:
                kept = sorted(show(n, n) for n in report.selection.kept)
                relevant = report.relevant
                print(f"{'':34}relevant {len(relevant)}: {', '.join(relevant)}")
                print(f"{'':34}kept {len(kept)} of {len(session.scene.objects)}: {', '.join(kept)}")
                if report.added or report.dropped:
                    print(
                        f"{'':34}added: {', '.join(show(n, n) for n in report.added) or '-'}"
                        f"   dropped: {', '.join(show(n, n) for n in report.dropped) or '-'}"
                    )
            if report.ask is not None:
                print(f"{'':34}ask: {report.ask.question}")
            if report.plan is not None:
                plan = report.plan
                source = "still valid, planner not called" if plan.source == "previous" else "planned"
                steps = f"{len(plan.steps)} step" + ("" if len(plan.steps) == 1 else "s")
                print(f"{'':34}plan: {plan.status.value}, {steps} ({source})")
                for step in plan.steps if plan.source == "planner" else ():
                    print(f"{'':36}(" + " ".join([step.action] + [show(a, a) for a in step.args]) + ")")


if __name__ == "__main__":
    main()
