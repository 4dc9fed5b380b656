"""The HTML page: self-contained, every untrusted text escaped, a partial run said first."""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

import pytest

from apbot.bench.report import write_report
from tests.bench.report.rundir import EVIL, clock, write_run


@pytest.fixture(scope="module")
def report(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Any]:
    directory = write_run(tmp_path_factory.mktemp("run"))
    write_report(directory, clock=clock)
    return {
        "md": (directory / "report.md").read_text(encoding="utf-8"),
        "html": (directory / "report.html").read_text(encoding="utf-8"),
    }


def test_html_is_self_contained(report: dict[str, Any]) -> None:
    page = report["html"]
    assert not re.search(r'(src|href)\s*=\s*"?(https?:|//)', page)
    assert "<script" not in page and "<link" not in page and "@import" not in page
    images = re.findall(r'<img [^>]*src="([^"]*)"', page)
    assert len(images) == 4 and all(src.startswith("data:image/png;base64,") for src in images)


def test_untrusted_text_is_escaped(report: dict[str, Any]) -> None:
    page, md = report["html"], report["md"]
    assert EVIL not in page and "<img src=x" not in page and "<b>bold" not in page
    assert "&lt;script&gt;alert(&quot;pwned&quot;)&lt;/script&gt;" in page
    assert "&lt;img src=x onerror=alert(1)&gt;" in page
    assert "<script" not in md and "<b>" not in md


def test_a_partial_run_says_so_before_anything_else(tmp_path: Path) -> None:
    write_run(tmp_path, [])
    write_report(tmp_path, clock=clock)
    page = (tmp_path / "report.html").read_text(encoding="utf-8")
    banner = '<p class="partial"><b>Partial run: 0 of 2 tasks finished per method.</b>'
    assert banner in page and page.index(banner) < page.index("<dl")
