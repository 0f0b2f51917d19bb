"""The report's numbers come from stored rows: a hand-made store gives a known table."""

from __future__ import annotations

import csv
import io
import json
import sys

import pytest
from support import TIMEOUT, invoke, make_row, write_store

from relevance_plan.batch.plots import write_plots
from relevance_plan.batch.report import JOB_FIELDS, build_report, format_report, job_time
from relevance_plan.batch.store import COLUMNS, ResultStore
from relevance_plan.errors import UsageError
from relevance_plan.exitcodes import ExitCode


def known_rows():
    """Suite 'alpha' with all four methods, 4 problems each; suite 'beta' with relevance only."""
    rows = []
    # pure: 10, 20, 30 s and one time-out (wall time 103 s, counted at 100 s).
    for problem, wall in zip("abc", (10.0, 20.0, 30.0)):
        rows.append(make_row("alpha", problem, "pure", wall=wall, kept=20, total=20))
    rows.append(make_row("alpha", "d", "pure", status="out-of-time", wall=103.0, kept=20, total=20, exit_code=23))
    # relevance: all solved; problem b needed a second attempt.
    for problem, wall, first in zip("abcd", (1.0, 2.0, 3.0, 4.0), ("solved", "unsolvable", "solved", "solved")):
        rows.append(make_row("alpha", problem, "relevance", wall=wall, relevance=0.5, first=first, kept=5, total=20))
    # random: one planner crash (final failure), one time-out, two solved.
    rows.append(make_row("alpha", "a", "random", wall=6.0, relevance=0.25, kept=10, total=20))
    rows.append(make_row("alpha", "b", "random", wall=8.0, relevance=0.25, kept=10, total=20))
    rows.append(
        make_row(
            "alpha", "c", "random", status="planner-error", wall=2.0, relevance=0.25, kept=10, total=20, exit_code=35
        )
    )
    rows.append(
        make_row(
            "alpha",
            "d",
            "random",
            status="out-of-time",
            wall=100.5,
            relevance=0.25,
            first="out-of-time",
            kept=10,
            total=20,
            exit_code=-9,
        )
    )
    # oracle: 0.5 s everywhere, 4 of 20 kept.
    for problem in "abcd":
        rows.append(make_row("alpha", problem, "oracle", wall=0.5, relevance=0.1, kept=4, total=20))
    rows.append(make_row("beta", "a", "relevance", wall=7.0, relevance=1.0, kept=3, total=12))
    return rows


@pytest.fixture
def known_store(tmp_path):
    return write_store(tmp_path / "known.sqlite", known_rows())


def stored_rows(path):
    with ResultStore(path, create=False) as store:
        return store.rows()


def test_job_time_counts_timeouts_at_the_timeout():
    assert job_time(make_row("s", "a", "pure", wall=3.5)) == 3.5
    assert job_time(make_row("s", "a", "pure", status="out-of-time", wall=131.0)) == TIMEOUT


def test_report_numbers_from_a_known_store(known_store):
    records = build_report(stored_rows(known_store))
    by_key = {(r.suite, r.method): r for r in records}
    assert [(r.suite, r.method) for r in records] == [
        ("alpha", "relevance"),
        ("alpha", "pure"),
        ("alpha", "random"),
        ("alpha", "oracle"),
        ("beta", "relevance"),
    ]

    pure = by_key[("alpha", "pure")]
    assert pure.n == 4 and pure.solved == 3
    assert pure.mean_time == pytest.approx((10 + 20 + 30 + 100) / 4)  # the time-out counts at 100 s, not 103 s
    assert pure.median_time == pytest.approx(25.0)
    assert pure.timeout_rate == pytest.approx(0.25)
    assert pure.first_failure_rate is None and pure.failure_rate is None  # not applicable to pure
    # One direction everywhere: pure / method, how many times faster than pure.
    assert pure.pure_over_method == pytest.approx(1.0)
    assert pure.oracle_over_method == pytest.approx(0.5 / 25.0)
    assert pure.mean_kept_fraction == pytest.approx(1.0)

    relevance = by_key[("alpha", "relevance")]
    assert relevance.mean_time == pytest.approx(2.5)
    assert relevance.median_time == pytest.approx(2.5)
    assert relevance.timeout_rate == 0.0
    assert relevance.first_failure_rate == pytest.approx(0.25)  # problem b's first attempt
    assert relevance.failure_rate == 0.0  # relaxation recovered it
    assert relevance.pure_over_method == pytest.approx(10.0)
    assert relevance.oracle_over_method == pytest.approx(0.2)
    assert relevance.mean_objects_kept == pytest.approx(5.0)
    assert relevance.mean_objects_total == pytest.approx(20.0)
    assert relevance.mean_kept_fraction == pytest.approx(0.25)
    assert relevance.mean_relevance_time == pytest.approx(0.5)

    random = by_key[("alpha", "random")]
    assert random.mean_time == pytest.approx((6 + 8 + 2 + 100) / 4)
    assert random.median_time == pytest.approx(7.0)
    assert random.timeout_rate == pytest.approx(0.25)
    assert random.first_failure_rate == pytest.approx(0.5)  # the crash and the time-out
    assert random.failure_rate == pytest.approx(0.25)  # only the crash: time-outs are not failures
    assert random.pure_over_method == pytest.approx(25.0 / 7.0)
    assert random.oracle_over_method == pytest.approx(0.5 / 7.0)
    assert random.mean_relevance_time == pytest.approx(0.25)

    oracle = by_key[("alpha", "oracle")]
    assert oracle.oracle_over_method == pytest.approx(1.0)
    assert oracle.pure_over_method == pytest.approx(50.0)
    assert oracle.mean_kept_fraction == pytest.approx(0.2)

    beta = by_key[("beta", "relevance")]
    assert beta.n == 1 and beta.median_time == pytest.approx(7.0)
    assert beta.pure_over_method is None and beta.oracle_over_method is None  # no pure/oracle on beta
    assert beta.mean_kept_fraction == pytest.approx(0.25)
    assert all(r.configs == 1 for r in records)


def test_markdown_has_the_papers_shape(known_store):
    text = format_report(build_report(stored_rows(known_store)), "markdown")
    lines = text.splitlines()
    assert lines[0] == "| suite | metric | relevance | pure | random | oracle |"
    assert "| alpha | time (s) | 2.50 | 40.00 | 29.00 | 0.50 |" in lines
    assert "|  | timeout | 0.00 | 0.25 | 0.25 | 0.00 |" in lines
    assert "|  | fail (first attempt) | 0.25 | – | 0.50 | 0.00 |" in lines
    assert "|  | fail (final) | 0.00 | – | 0.25 | 0.00 |" in lines
    assert "|  | pure / method (median) | 10.00 | 1.00 | 3.57 | 50.00 |" in lines
    assert "|  | oracle / method (median) | 0.20 | 0.02 | 0.07 | 1.00 |" in lines
    assert "|  | objects kept | 5/20 | 20/20 | 10/20 | 4/20 |" in lines
    assert "|  | n | 4 | 4 | 4 | 4 |" in lines
    # beta has no pure or oracle: no ratio rows, missing methods shown as '–'.
    assert "| beta | time (s) | 7.00 | – | – | – |" in lines
    beta = lines[lines.index("| beta | time (s) | 7.00 | – | – | – |") :]
    assert not any("/ method" in line for line in beta if line.startswith("|"))
    assert any("counted at the timeout (100 s)" in line for line in lines)


def test_csv_has_one_line_per_suite_and_method(known_store):
    text = format_report(build_report(stored_rows(known_store)), "csv")
    table = list(csv.DictReader(io.StringIO(text)))
    assert len(table) == 5
    pure = next(r for r in table if r["suite"] == "alpha" and r["method"] == "pure")
    assert pure["failure_rate"] == "" and pure["first_failure_rate"] == ""
    assert float(pure["mean_time"]) == pytest.approx(40.0)
    random = next(r for r in table if r["method"] == "random")
    assert float(random["failure_rate"]) == pytest.approx(0.25)
    assert float(random["pure_over_method"]) == pytest.approx(25.0 / 7.0, rel=1e-5)


def test_latex_table(known_store):
    text = format_report(build_report(stored_rows(known_store)), "latex")
    assert "\\begin{tabular}{llrrrr}" in text
    assert "alpha & time (s) & 2.50 & 40.00 & 29.00 & 0.50 \\\\" in text
    assert " & fail (final) & 0.00 & -- & 0.25 & 0.00 \\\\" in text
    assert "pure / method (median)" in text
    assert text.rstrip().endswith("\\end{tabular}")


def test_pooled_option_sets_are_flagged():
    rows = [make_row("s", "a", "pure", config="x"), make_row("s", "b", "pure", config="y")]
    records = build_report(rows)
    assert records[0].configs == 2
    assert "pools 2 different option sets" in format_report(records, "markdown")


def test_empty_and_unknown_format():
    assert format_report([], "markdown") == "no results\n"
    with pytest.raises(UsageError):
        format_report([], "html")


PNG_PLOTS = ["cactus.png", "relevance-vs-pure.png", "cactus-alpha.png", "cactus-beta.png"]


def test_plots_are_written_atomically_as_png(known_store, tmp_path):
    written = write_plots(stored_rows(known_store), tmp_path / "plots")
    assert [p.name for p in written] == PNG_PLOTS
    for path in written:
        assert path.read_bytes().startswith(b"\x89PNG\r\n\x1a\n")
    assert sorted(p.name for p in (tmp_path / "plots").iterdir()) == sorted(PNG_PLOTS)


@pytest.mark.parametrize("fmt, start", [("svg", b"<?xml"), ("pdf", b"%PDF")])
def test_plots_in_a_paper_format_one_cactus_per_suite(known_store, tmp_path, fmt, start):
    rows = stored_rows(known_store)
    written = write_plots(rows, tmp_path / "plots", fmt=fmt)
    assert [p.name for p in written] == [name.replace(".png", f".{fmt}") for name in PNG_PLOTS]
    assert all(path.read_bytes().startswith(start) for path in written)
    again = write_plots(rows, tmp_path / "plots", fmt=fmt)  # our own plots are replaced
    assert again == written and sorted(p.name for p in (tmp_path / "plots").iterdir()) == sorted(
        p.name for p in written
    )


def test_png_resolution_follows_dpi(known_store, tmp_path):
    import struct

    rows = stored_rows(known_store)
    sizes = []
    for dpi in (50, 100):
        (cactus, *_) = write_plots(rows, tmp_path / f"dpi-{dpi}", dpi=dpi)
        sizes.append(struct.unpack(">II", cactus.read_bytes()[16:24]))  # the IHDR width and height
    assert sizes[1][0] == pytest.approx(2 * sizes[0][0], abs=2) and sizes[1][1] == pytest.approx(2 * sizes[0][1], abs=2)


def test_a_users_file_with_a_per_suite_plot_name_stops_before_any_plot_is_written(known_store, tmp_path):
    folder = tmp_path / "plots"
    folder.mkdir()
    (folder / "cactus-beta.svg").write_text("<svg>my own drawing</svg>")
    with pytest.raises(UsageError, match="cactus-beta.svg exists and is not a plot"):
        write_plots(stored_rows(known_store), folder, fmt="svg")
    assert [p.name for p in folder.iterdir()] == ["cactus-beta.svg"]


def test_a_drawing_error_leaves_no_plot_behind(known_store, tmp_path, monkeypatch):
    from relevance_plan.batch import plots

    def broken(rows, suite=None):
        if suite == "beta":
            raise RuntimeError("drawing failed")
        return real(rows, suite)

    real = plots._cactus
    monkeypatch.setattr(plots, "_cactus", broken)
    with pytest.raises(RuntimeError):
        write_plots(stored_rows(known_store), tmp_path / "plots")
    assert not (tmp_path / "plots").exists() or not list((tmp_path / "plots").iterdir())


def test_suite_names_become_safe_distinct_file_names():
    from relevance_plan.batch.plots import plot_names

    names = plot_names(["a/b", "a b", "../x", "ok"], "png")
    assert names["ok"] == "cactus-ok.png" and names["../x"] == "cactus-x.png"
    assert len(set(names.values())) == len(names)
    assert all("/" not in name and " " not in name for name in names.values())


def test_plots_without_matplotlib_say_how_to_install(known_store, tmp_path, monkeypatch):
    monkeypatch.setitem(sys.modules, "matplotlib.figure", None)
    with pytest.raises(UsageError, match=r"relevance-plan\[plots\]"):
        write_plots(stored_rows(known_store), tmp_path / "plots")
    assert not (tmp_path / "plots").exists()


# --------------------------------------------------------------------------- CLI


def test_report_command(known_store, tmp_path):
    before = known_store.read_bytes()
    result = invoke("report", known_store)
    assert result.exit_code == 0, result.output
    assert result.stdout == format_report(build_report(known_rows()), "markdown")
    result = invoke("report", known_store, "--format", "csv", "--plots", tmp_path / "p")
    assert result.exit_code == 0, result.output
    assert result.stdout.startswith("suite,method,n,")
    assert (tmp_path / "p" / "cactus.png").is_file()
    assert known_store.read_bytes() == before


def test_report_on_a_missing_store_creates_nothing(tmp_path):
    missing = tmp_path / "nothing.sqlite"
    result = invoke("report", missing)
    assert result.exit_code == ExitCode.INPUT_FILE
    assert result.stderr.count("\n") == 1 and "results store not found" in result.stderr
    assert not missing.exists()


def test_store_columns_cover_every_row_field():
    assert set(make_row("s", "a", "pure")) == set(COLUMNS)


# --------------------------------------------------------------------------- one row per job


def per_job_store(tmp_path):
    """The known rows, one with a validation time in its result and one from another planner."""
    rows = known_rows()
    rows[0] = {**rows[0], "result_json": json.dumps({"validation_time": 0.125})}
    config = json.loads(rows[1]["config_json"])
    rows[1] = {**rows[1], "config_json": json.dumps({**config, "planner": "up:pyperplan"}, sort_keys=True)}
    return write_store(tmp_path / "jobs.sqlite", rows)


def test_report_json_rows_round_trip_to_the_store_rows(tmp_path):
    path = per_job_store(tmp_path)
    result = invoke("report", path, "--json")
    assert result.exit_code == 0, result.output
    jobs = json.loads(result.stdout)
    stored = stored_rows(path)
    assert len(jobs) == len(stored)
    for job, row in zip(jobs, stored):
        assert set(job) == {name for name, _ in JOB_FIELDS}
        for name in job:
            if name in row:
                assert job[name] == row[name], name
    assert jobs[0]["validation_time"] == 0.125 and jobs[2]["validation_time"] is None
    assert jobs[1]["planner"] == "up:pyperplan" and jobs[0]["planner"] == "fast-downward"


def test_report_csv_rows_read_back_as_the_json_rows(tmp_path):
    path = per_job_store(tmp_path)
    jobs = json.loads(invoke("report", path, "--json").stdout)
    result = invoke("report", path, "--csv")
    assert result.exit_code == 0, result.output
    types = dict(JOB_FIELDS)
    table = list(csv.DictReader(io.StringIO(result.stdout)))
    read_back = [{name: None if text == "" else types[name](text) for name, text in line.items()} for line in table]
    # An empty message and a missing one are the same field in CSV.
    assert read_back == [{**job, "message": job["message"] or None} for job in jobs]


@pytest.mark.parametrize(
    "options", [["--json", "--csv"], ["--json", "--format", "latex"], ["--csv", "--format", "csv"]]
)
def test_report_takes_one_output_format(known_store, options):
    result = invoke("report", known_store, *options)
    assert result.exit_code == ExitCode.USAGE and "choose one output" in result.stderr


# --------------------------------------------------------------------------- plan costs


def cost_rows():
    """Suite 'alpha': pure and relevance on a, b, c; relevance doubles a's cost and halves b's, c
    unsolved by pure; random solves only a, at four times pure's cost.  Suite 'beta' has no pure."""
    return [
        make_row("alpha", "a", "pure", cost=10.0),
        make_row("alpha", "b", "pure", cost=20.0),
        make_row("alpha", "c", "pure", status="out-of-time", wall=100.0),
        make_row("alpha", "a", "relevance", cost=20.0),
        make_row("alpha", "b", "relevance", cost=10.0),
        make_row("alpha", "c", "relevance", cost=99.0),
        make_row("alpha", "a", "random", cost=40.0),
        make_row("alpha", "b", "random", status="planner-error"),
        make_row("beta", "a", "relevance", cost=3.0),
    ]


def test_cost_ratio_is_the_geometric_mean_over_problems_both_solved():
    records = {(r.suite, r.method): r for r in build_report(cost_rows())}
    relevance, random, pure = records[("alpha", "relevance")], records[("alpha", "random")], records[("alpha", "pure")]
    # 20/10 and 10/20: a geometric mean of 1; c is left out (pure did not solve it)
    assert relevance.cost_over_pure == pytest.approx(1.0) and relevance.cost_pairs == 2
    assert random.cost_over_pure == pytest.approx(4.0) and random.cost_pairs == 1
    assert pure.cost_over_pure == pytest.approx(1.0)
    assert relevance.mean_plan_cost == pytest.approx((20 + 10 + 99) / 3)
    assert records[("beta", "relevance")].cost_over_pure is None


def test_cost_rows_in_the_text_table_and_the_csv(tmp_path):
    lines = format_report(build_report(cost_rows())).splitlines()
    assert "|  | cost / pure (geo. mean) | 1.00 | 1.00 | 4.00 |" in lines
    assert "|  | plan cost | 43.0 | 15.0 | 40.0 |" in lines
    assert "|  | solved | 3/3 | 2/3 | 1/2 |" in lines
    beta = lines[lines.index("| beta | time (s) | 1.00 | – | – |") :]
    assert not any("cost / pure" in line for line in beta[: beta.index("")])  # no pure in beta
    table = list(csv.DictReader(io.StringIO(format_report(build_report(cost_rows()), "csv"))))
    random = next(line for line in table if line["method"] == "random")
    assert float(random["cost_over_pure"]) == 4.0 and random["cost_pairs"] == "1"


def test_unknown_costs_show_as_unknown_not_as_zero():
    rows = [{**row, "plan_cost": None} for row in cost_rows()]
    records = build_report(rows)
    assert all(r.mean_plan_cost is None and r.cost_over_pure is None for r in records)
    text = format_report(records)
    assert "|  | plan cost | ? | ? | ? |" in text.splitlines()
    assert "plan cost unknown" in text
