"""The benchmarks' shared module: its statistics, and runs stored as rows ``report`` reads."""

from __future__ import annotations

import math

import base
import pytest

from relevance_plan.batch.report import build_report
from relevance_plan.batch.store import read_rows
from relevance_plan.planning.loop import PlanOptions, plan_task


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
