"""The HTML page: self-contained, one script allowed by its hash, escaped, fits 800 px."""

from __future__ import annotations

import base64
import hashlib
import re
from pathlib import Path
from typing import Any

from apbot.bench.report.page import CSS, SCRIPT
from tests.bench.report.rundir import EVIL, render, write_run


def test_html_is_self_contained(report: dict[str, Any]) -> None:
    page = report["html"]
    assert not re.search(r'(src|href)\s*=\s*"?(https?:|//)', page)
    assert "<link" not in page and "@import" not in page and "url(" not in page
    images = re.findall(r'<img [^>]*src="([^"]*)"', page)
    assert len(images) == 4 and all(src.startswith("data:image/") for src in images)


def test_the_only_script_is_the_viewer_allowed_by_its_hash(report: dict[str, Any]) -> None:
    page = report["html"]
    scripts = re.findall(r"<script([^>]*)>(.*?)</script>", page, re.S)
    executable = [body for attributes, body in scripts if "type=" not in attributes]
    assert executable == [SCRIPT]
    data_blocks = [a for a, body in scripts if re.fullmatch(r"[A-Za-z0-9+/=]+", body)]
    assert data_blocks == [' type="text/plain" id="viewer-data"']
    policy = re.search(r'http-equiv="Content-Security-Policy" content="([^"]*)"', page)
    assert policy
    digest = base64.b64encode(hashlib.sha256(SCRIPT.encode()).digest()).decode()
    directives = {d.split()[0]: d.split()[1:] for d in policy.group(1).split(";") if d.strip()}
    assert directives["script-src"] == [f"'sha256-{digest}'"]  # no 'unsafe-inline'
    assert directives["default-src"] == ["'none'"]
    assert "</script" not in SCRIPT.lower()


def test_untrusted_text_is_escaped(report: dict[str, Any]) -> None:
    page, md = report["html"], report["md"]
    assert EVIL not in page and "<img src=x" not in page and "<b>bold" not in page
    assert "gave up | &lt;b&gt;bold&lt;/b&gt;" in page  # the task line's reason
    assert "<script" not in md and "<b>" not in md


def test_tables_scroll_inside_their_own_box(report: dict[str, Any]) -> None:
    """At 800 px the category tables are wider than the page: each scrolls in a box."""
    page = report["html"]
    tables = [m.start() for m in re.finditer(r"<table", page)]
    assert tables and all(page[:t].endswith('<div class="wide">') for t in tables)
    assert ".wide{overflow-x:auto;max-width:100%}" in CSS
    assert "viewer.js" not in page and 'node("div", null, "wide")' in SCRIPT  # drawn tables too


def test_a_partial_run_says_so_before_anything_else(tmp_path: Path) -> None:
    _, page = render(write_run(tmp_path, []))
    banner = '<p class="partial"><b>Partial run: 0 of 2 tasks finished per method.</b>'
    assert banner in page and page.index(banner) < page.index("<dl")
