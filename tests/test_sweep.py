"""The sweep and its heatmap: readable colour scales and text, N defined, where it wrote, and a
missing matplotlib named as the extra to install before any work."""

from __future__ import annotations

import sys

import pytest
from support import invoke, one_line_error

from relevance_plan.batch.plots import heatmap_figure, text_colour
from relevance_plan.batch.sweep import SweepResult
from relevance_plan.exitcodes import ExitCode
from relevance_plan.relevance.scoring.metrics import SetMetrics

TAUS = (0.2, 0.4)


def constant_result(value: float = 1.0, with_truth: bool = True) -> SweepResult:
    """Every cell and metric at ``value``: the panels a colour scale must not stretch to 0.90-1.10."""
    cells = [(c, e) for c in TAUS for e in TAUS]
    table = {cell: SetMetrics(value, value, value, value) for cell in cells} if with_truth else {}
    return SweepResult(
        suite="s",
        scorer="goal",
        problems=3,
        taus=TAUS,
        relevant=table,
        necessary=table,
        insufficient=0,
        with_truth=3 if with_truth else 0,
        kept={cell: 7.0 for cell in cells},
        objects_total=12.0,
    )


def images_and_texts(figure):
    for axis in figure.axes:
        if axis.images:
            yield axis.images[0], axis.texts


@pytest.mark.parametrize("value", [1.0, 0.0, 0.5])
def test_a_constant_panel_keeps_a_real_colour_scale(value):
    pytest.importorskip("matplotlib")
    panels = list(images_and_texts(heatmap_figure(constant_result(value))))
    assert len(panels) == 8
    for image, _ in panels:
        low, high = image.get_clim()
        assert (low, high) == (0.0, 1.0), (low, high)


def test_without_ground_truth_the_heatmap_shows_objects_kept_from_zero():
    pytest.importorskip("matplotlib")
    ((image, texts),) = images_and_texts(heatmap_figure(constant_result(with_truth=False)))
    assert image.get_clim() == (0.0, 7.0)
    assert {t.get_text() for t in texts} == {"7.00"}


def test_cell_text_is_dark_on_light_cells_and_light_on_dark_ones():
    pytest.importorskip("matplotlib")
    assert text_colour(1.0) == "black" and text_colour(0.0) == "white"
    for value, colour in ((1.0, "black"), (0.0, "white")):
        for _, texts in images_and_texts(heatmap_figure(constant_result(value))):
            assert {t.get_color() for t in texts} == {colour}


def test_the_heatmap_says_what_n_is():
    pytest.importorskip("matplotlib")
    title = heatmap_figure(constant_result()).get_suptitle()
    assert "N = objects chosen / objects in the ground truth" in title


@pytest.fixture
def coffee_suite(tmp_path):
    suite = tmp_path / "suite"
    assert invoke("generate", "coffee", "--count", "1", "--distractors", "2", "--out", suite).exit_code == 0
    return suite


def test_sweep_heatmap_says_where_it_wrote(coffee_suite, tmp_path):
    pytest.importorskip("matplotlib")
    target = tmp_path / "heat.png"
    result = invoke("sweep", coffee_suite, "--taus", "0.2,0.4", "--heatmap", target)
    assert result.exit_code == 0, result.output
    assert f"wrote {target}" in result.stderr
    assert target.read_bytes().startswith(b"\x89PNG")
    assert "N = objects chosen / objects in the ground truth" in result.stdout


@pytest.mark.parametrize(
    "command",
    [
        lambda suite, out: ["sweep", suite, "--heatmap", out / "heat.png"],
        lambda suite, out: ["report", out / "results.sqlite", "--plots", out / "plots"],
    ],
    ids=["sweep-heatmap", "report-plots"],
)
def test_a_missing_matplotlib_names_the_extra_before_any_work(coffee_suite, tmp_path, monkeypatch, command):
    from support import make_row

    from relevance_plan.batch.store import ResultStore

    out = tmp_path / "out"
    out.mkdir()
    with ResultStore(out / "results.sqlite") as store:
        store.add(make_row("s", "a", "pure"))
    before = sorted(p.name for p in out.iterdir())
    monkeypatch.setitem(sys.modules, "matplotlib.figure", None)
    result = invoke(*command(coffee_suite, out))
    assert result.exit_code == ExitCode.USAGE
    line = one_line_error(result.stderr)
    assert "matplotlib" in line and "pip install 'relevance-plan[plots]'" in line
    assert sorted(p.name for p in out.iterdir()) == before
    assert result.stdout == ""  # refused before the sweep or the report ran
