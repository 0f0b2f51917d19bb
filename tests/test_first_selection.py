"""One first selection: what `prune` writes is what `plan` tries first, on every shipped problem,
and `plan --json` says per attempt what it kept, removed and restored, with reasons."""

from __future__ import annotations

import json

import pytest
from support import DOMAINS, PROBLEMS, run

SHIPPED = sorted(PROBLEMS.glob("*.pddl"))


@pytest.mark.planner
@pytest.mark.parametrize("problem", SHIPPED, ids=lambda p: p.stem)
def test_prune_and_the_first_attempt_of_plan_keep_the_same_objects(problem, tmp_path):
    domain = DOMAINS / problem.stem.split("-")[0] / "domain.pddl"
    code, out, err = run("prune", domain, problem, "-o", tmp_path / "small.pddl", "--json")
    assert code == 0, err
    pruned = json.loads(out)
    code, out, err = run("plan", domain, problem, "--json", "--plan-file", tmp_path / "plan", "--timeout", "60")
    assert code == 0, err
    first = json.loads(out)["attempt_log"][0]
    assert first["kept"] == pruned["kept"] and first["removed"] == pruned["removed"]
    assert [r["object"] for r in first["restored"]] == [r["object"] for r in pruned["restored"]]
    assert all(r["reason"] and r["rule"] for r in first["restored"])
    assert pruned["pruned"] and pruned["unpruned_reason"] is None
