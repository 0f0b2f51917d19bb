"""`report --html`: one self-contained page with each suite's table and the plots as inline SVG,
read by a plain HTML parser and rendered by a headless browser."""

from __future__ import annotations

import re
import shutil
import subprocess
import sys
from html.parser import HTMLParser

import pytest
from support import invoke, make_row, write_store

from relevance_plan.batch.html_report import format_html
from relevance_plan.exitcodes import ExitCode

HOSTILE = "<script>alert('x')</script> & co"


def page_rows():
    return [
        make_row("alpha", "a", "pure", wall=10.0, cost=10.0),
        make_row("alpha", "b", "pure", wall=20.0, cost=20.0),
        make_row("alpha", "a", "relevance", wall=1.0, cost=12.0),
        make_row("alpha", "b", "relevance", status="out-of-time", wall=100.0),
        make_row(HOSTILE, "a", "random", wall=3.0, cost=5.0),
    ]


class Page(HTMLParser):
    """Tags, the text of each heading and table cell, and attributes that could fetch something."""

    def __init__(self) -> None:
        super().__init__()
        self.tags: list[str] = []
        self.open: list[str] = []
        self.texts: dict[str, list[str]] = {}
        self.fetching: list[tuple[str, str]] = []

    def handle_starttag(self, tag, attrs):
        self.tags.append(tag)
        self.open.append(tag)
        for name, value in attrs:
            if name in ("src", "href", "xlink:href") and value and not value.startswith("#"):
                self.fetching.append((tag, value))

    def handle_endtag(self, tag):
        while self.open and self.open.pop() != tag:
            pass

    def handle_data(self, data):
        if self.open and data.strip():
            self.texts.setdefault(self.open[-1], []).append(data.strip())


def parsed(text: str) -> Page:
    page = Page()
    page.feed(text)
    page.close()
    return page


@pytest.fixture
def page_store(tmp_path):
    return write_store(tmp_path / "results.sqlite", page_rows())


def test_the_page_holds_a_table_per_suite_with_escaped_text_and_no_outside_reference():
    page = parsed(format_html(page_rows()))
    assert {"alpha", HOSTILE} <= set(page.texts["h2"])
    assert page.tags.count("table") == 2
    assert {"relevance", "pure", "random"} <= set(page.texts["th"])
    assert "cost / pure (geo. mean)" in page.texts["th"] and "solved" in page.texts["th"]
    assert "1/2" in page.texts["td"]  # relevance solved one of alpha's two
    assert "script" not in page.tags and "link" not in page.tags and "img" not in page.tags
    assert page.fetching == []


def test_figures_are_inline_svg_with_distinct_ids():
    pytest.importorskip("matplotlib")
    text = format_html(page_rows())
    page = parsed(text)
    assert page.tags.count("svg") == 4  # all suites, the scatter, one cactus per suite
    ids = re.findall(r'\bid="([^"]+)"', text)
    assert len(ids) == len(set(ids))


def test_without_matplotlib_the_page_says_how_to_get_figures(monkeypatch):
    monkeypatch.setitem(sys.modules, "matplotlib.figure", None)
    page = parsed(format_html(page_rows()))
    assert "svg" not in page.tags and page.tags.count("table") == 2
    assert any("relevance-plan[plots]" in text for text in page.texts["p"])


def test_report_html_command_writes_the_page_and_keeps_the_store(page_store, tmp_path):
    before = page_store.read_bytes()
    out = tmp_path / "report.html"
    result = invoke("report", page_store, "--html", out)
    assert result.exit_code == 0, result.output
    assert parsed(out.read_text()).tags.count("table") == 2
    assert page_store.read_bytes() == before
    refused = invoke("report", page_store, "--html", page_store)
    assert refused.exit_code == int(ExitCode.USAGE), refused.output
    assert page_store.read_bytes() == before


def chromium() -> str | None:
    return shutil.which("chromium") or shutil.which("chromium-browser")


@pytest.mark.skipif(chromium() is None, reason="no chromium to render the page (apt-get install chromium)")
def test_the_page_renders_in_a_headless_browser(page_store, tmp_path):
    out = tmp_path / "report.html"
    assert invoke("report", page_store, "--html", out).exit_code == 0
    command = [
        chromium(),
        "--headless",
        "--no-sandbox",
        "--disable-gpu",
        "--disable-background-networking",
        "--disable-component-update",
        "--disable-sync",
        "--no-first-run",
        f"--user-data-dir={tmp_path / 'profile'}",
        "--dump-dom",
        out.as_uri(),
    ]
    rendered = subprocess.run(command, capture_output=True, text=True, timeout=120, check=False)
    dom = rendered.stdout
    assert rendered.returncode == 0 and "<table" in dom, rendered.stderr[-2000:]
    page = parsed(dom)
    assert {"alpha", HOSTILE} <= set(page.texts["h2"])
    assert {"relevance", "pure", "random"} <= set(page.texts["th"])
    assert "script" not in page.tags  # the hostile suite name stayed text
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        return
    assert "<svg" in dom
