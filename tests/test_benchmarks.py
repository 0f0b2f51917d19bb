"""The benchmarks' shared module: its statistics, and runs stored as rows ``report`` reads."""

from __future__ import annotations

import math

import base
import pytest

from relevance_plan.batch.report import build_report
from relevance_plan.batch.store import read_rows
from relevance_plan.planning.options import PlanOptions
from relevance_plan.planning.run import plan_task


def test_the_statistics_leave_missing_values_out_and_say_when_there_are_none():
    assert base.median([3.0, None, 1.0, 2.0]) == 2.0 and base.median([None]) is None
    assert base.mean([1.0, None, 2.0]) == 1.5 and base.mean([]) is None
    assert base.geometric_mean([2.0, 8.0, None]) == pytest.approx(4.0)
    assert math.isnan(base.geometric_mean([]))
    assert base.percentile([5.0, 1.0, 3.0, 2.0, 4.0], 0.95) == 5.0 and base.percentile([5.0, 1.0, 3.0], 0.0) == 1.0
    assert math.isnan(base.percentile([], 0.5))


def test_ratios_print_as_the_tables_show_them():
    assert base.ratio(6.0, 2.0) == 3.0 and base.ratio(None, 2.0) is None and base.ratio(1.0, 0.0) is None
    assert base.show_ratio(12.34) == "12.3x" and base.show_ratio(2.0, ">") == ">2.0x"
    assert base.show_ratio(None) == base.MISSING and base.show_ratio(math.nan) == base.MISSING


def test_a_table_header_has_one_rule_cell_per_column(capsys):
    base.table_header("a | b | c")
    base.table_row("x", 1, 2.5)
    assert capsys.readouterr().out == "| a | b | c |\n|---|---|---|\n| x | 1 | 2.5 |\n"


def test_the_default_store_is_a_new_file_of_its_own(tmp_path, monkeypatch):
    monkeypatch.setattr(base, "OUT", tmp_path / "out")
    with base.Store(None, "bench_x") as first, base.Store(None, "bench_x") as second:
        assert first.path != second.path  # the same second: the second store gets a number
    assert {first.path.parent, second.path.parent} == {tmp_path / "out"}
    assert first.path.name.startswith("bench_x-") and first.path.suffix == ".sqlite"


@pytest.mark.planner
def test_a_benchmark_s_runs_are_store_rows_that_report_compares(tmp_path, coffee_files):
    domain, problem = coffee_files
    path = tmp_path / "bench.sqlite"
    with base.Store(path, "bench_x") as store:
        runs = {
            method: base.run_method(domain, problem, PlanOptions(method=method, timeout=60), store, "coffee")[1]
            for method in ("pure", "relevance")
        }
        again = PlanOptions(method="pure", timeout=60)
        store.add("coffee", domain, problem, again, plan_task(domain, problem, again))
    assert store.stored == 2  # the second pure run is the same job: stored once
    assert all(run.solved and run.valid for run in runs.values())
    rows = read_rows(path)
    assert sorted(row["method"] for row in rows) == ["pure", "relevance"]
    (relevance,) = [record for record in build_report(rows) if record.method == "relevance"]
    assert relevance.pure_over_method == pytest.approx(runs["pure"].time / runs["relevance"].time)
    assert relevance.mean_objects_kept == runs["relevance"].kept < runs["relevance"].total


# --------------------------------------------------------------------------- bench_linked


def linked_run(status: str, wall: float, builtin: bool | None = True, val: bool | None = True):
    import bench_linked

    solved = status == "solved"
    return bench_linked.Run(status, wall, 3 if solved else None, 1 if solved else None, builtin, val)


def test_linked_budgets_are_flax_s_by_grid_size_and_a_minute_for_the_hard_to_ground_sets():
    from bench_linked import budget_of

    assert [budget_of("mazenamo", cell) for cell in ("10x10_easy", "12x12_hard", "15x15_expert")] == [5.0, 20.0, 40.0]
    assert budget_of("sokomindplus", "test_20x20") == 60.0 and budget_of("difficultlogistics", "test") == 30.0
    assert budget_of("rovers", "goal-8") == budget_of("gnad", "satellite-large") == 60.0


def test_linked_weighted_time_counts_a_failure_or_a_plan_a_validator_refuses_as_the_whole_budget():
    from bench_linked import weighted_time

    refused = linked_run("solved", 1.0, True, False)
    runs = [linked_run("solved", 2.0), linked_run("out-of-time", 7.5, None, None), refused]
    assert [run.solved for run in runs] == [True, False, False]
    assert weighted_time(runs, 5.0) == pytest.approx((2.0 + 5.0 + 5.0) / 3)
    assert linked_run("solved", 1.0, True, None).solved  # VAL not installed: the builtin validator's word
    assert not linked_run("solved", 1.0, False, True).solved


def test_linked_sample_is_the_first_n_or_a_seeded_choice_of_each_cell_in_natural_order():
    from bench_linked import sample

    problems = list(range(20))
    assert sample(problems, 5, None, "mazenamo/10x10_hard") == [0, 1, 2, 3, 4]
    assert sample(problems, None, 1, "mazenamo/10x10_hard") == sample(problems, 30, 1, "x") == problems
    chosen = sample(problems, 5, 1, "mazenamo/10x10_hard")
    assert chosen == sample(problems, 5, 1, "mazenamo/10x10_hard") == sorted(set(chosen)) and len(chosen) == 5
    assert chosen != [0, 1, 2, 3, 4] and chosen != sample(problems, 5, 1, "mazenamo/10x10_expert")


def test_linked_methods_name_the_tool_s_options_and_refuse_a_missing_model(tmp_path):
    import argparse

    from bench_linked import method_of

    assert (method_of("pure").method, method_of("pure").options().race) == ("pure", False)
    assert method_of("no-race").arguments == ("--no-race",) and not method_of("no-race").options().race
    assert method_of("relevance").options().race
    model = tmp_path / "model.json"
    model.write_text("{}")
    learned = method_of(f"learned:{model}")
    assert learned.arguments == ("--scorer", f"learned:{model.resolve()}") and learned.scorer == learned.arguments[1]
    for wrong in (f"learned:{tmp_path / 'none.json'}", "learned:", "ploi"):
        with pytest.raises(argparse.ArgumentTypeError):
            method_of(wrong)


def test_linked_prints_flax_s_published_rates_beside_ours_for_the_maze_cells_run(capsys):
    from bench_linked import flax_table, method_of

    results = {
        ("mazenamo", "15x15_expert"): {
            "pure": [linked_run("out-of-time", 41.0, None, None)] * 2,
            "relevance": [linked_run("solved", 3.0), linked_run("out-of-time", 40.5, None, None)],
        },
        ("difficultlogistics", "test"): {"pure": [linked_run("solved", 1.0)], "relevance": [linked_run("solved", 1.0)]},
    }
    flax_table(results, [method_of("pure"), method_of("relevance")])
    out = capsys.readouterr().out
    assert "| 15x15_expert (2) | 0.000 | 0.500 | 0.000 | 0.502 | 0.707 |" in out
    assert "average here over 1 cell(s): pure 0.000, relevance 0.500" in out
    assert "pure FD 0.578, PLOI 0.716, PLOI + complementary rules 0.761, PLOI + relaxation 0.770, Flax 0.866" in out
    assert "difficultlogistics" not in out and "arXiv 2507.15975" in out
    flax_table({("difficultlogistics", "test"): results[("difficultlogistics", "test")]}, [method_of("pure")])
    assert capsys.readouterr().out == ""


@pytest.mark.planner
@pytest.mark.slow  # 15 to 30 s: pure may take its whole budget, which leaves the tool room on a busy machine
def test_bench_linked_plans_a_cell_with_pure_and_the_tool_and_checks_each_plan_on_the_original(tmp_path):
    import json
    import subprocess
    import sys

    from support import REPO

    from relevance_plan.planning.validation.val_program import find_validate

    raw = tmp_path / "raw.jsonl"
    command = [sys.executable, str(REPO / "benchmarks" / "bench_linked.py"), "--sets", "blocksworld"]
    command += ["--cells", "goal-2", "--per-cell", "1", "--timeout", "10", "--out", str(raw)]
    command += ["--store", str(tmp_path / "runs.sqlite")]
    done = subprocess.run(command, capture_output=True, text=True, timeout=180, cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    lines = [json.loads(line) for line in raw.read_text().splitlines()]
    assert [(line["method"], line["problem"], line["budget"]) for line in lines] == [
        ("pure", "p-100-2.pddl", 10.0),
        ("relevance", "p-100-2.pddl", 10.0),
    ]
    pure, ours = lines
    assert pure["first_selection"] == pure["objects_total"] == ours["objects_total"] == 100
    assert ours["first_selection"] < 10 and ours["report"]["status"] == ours["status"]
    # two goal atoms among 100 blocks: the tool plans a handful of them, its plan checked by both validators
    assert ours["solved"] and ours["valid_builtin"] is True and ours["valid_val"] is (True if find_validate() else None)
    for line in lines:
        assert not line["solved"] or line["valid_builtin"] is True
        weighted = line["wall"] if line["solved"] else 10.0  # a failure counts the whole budget
        solved = int(line["solved"])
        assert f"| {line['method']} | {solved}/1 ({solved}.000) | {weighted:.2f} s |" in done.stdout


def test_linked_summary_counts_what_each_validator_accepted_and_notes_a_first_attempt_of_another_size(capsys):
    from bench_linked import Cell, Run, summarise

    runs = {
        "relevance": [
            Run("solved", 2.0, 60, 1, True, True, first_attempt=68),
            Run("solved", 3.0, 62, 2, True, False, first_attempt=62),
            Run("out-of-time", 31.0, None, None, None, None),
        ]
    }
    summarise(Cell("difficultlogistics", "test", 30.0, ()), runs, {"relevance": [62, 62, 64]}, [100, 105, 102])
    out = capsys.readouterr().out
    weighted = (2.0 + 30.0 + 30.0) / 3
    assert f"| relevance | 1/3 (0.333) | {weighted:.2f} s | 62 / 102 | 61 | 2 | 2/2 | 1/2 |" in out
    assert "the run's own first attempt kept another number of objects (68 against 62)" in out
