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
    # no race: the full problem planned beside could answer before the first pruned attempt starts
    code, out, err = run(
        "plan", domain, problem, "--json", "--plan-file", tmp_path / "plan", "--timeout", "60", "--no-race"
    )
    assert code == 0, err
    first = json.loads(out)["attempt_log"][0]
    assert first["kept"] == pruned["kept"] and first["removed"] == pruned["removed"]
    assert [r["object"] for r in first["restored"]] == [r["object"] for r in pruned["restored"]]
    assert all(r["reason"] and r["rule"] for r in first["restored"])
    assert pruned["pruned"] and pruned["unpruned_reason"] is None


@pytest.mark.planner
def test_the_readme_python_snippets_run(monkeypatch, capsys):
    from support import REPO

    readme = (REPO / "README.md").read_text()
    blocks = [block.split("```")[0] for block in readme.split("```python")[1:]]
    assert len(blocks) >= 2
    monkeypatch.chdir(REPO)
    for block in blocks:
        namespace: dict = {}
        exec(block, namespace)
    printed = capsys.readouterr().out
    assert "PlanStatus.SOLVED True" in printed and "(unit cost)" not in printed.split("steps")[0]


def test_the_api_takes_text_and_keeps_the_users_spelling(tmp_path):
    import relevance_plan as rp

    text = (PROBLEMS / "coffee-simple.pddl").read_text().replace("paper_cup_1", "Paper_Cup_1")
    selection = rp.prune(DOMAINS / "coffee" / "domain.pddl", text)
    described = selection.describe()
    assert "Paper_Cup_1" in described["kept"] + described["removed"]
    assert "Paper_Cup_1" in selection.text and selection.task.problem.path == "<problem text>"
