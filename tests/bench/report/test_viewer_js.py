"""viewer.js in a real browser: the page at 800 px, a task drawn on opening, the filter.

Needs a headless Chromium (Debian: ``apt-get install chromium``); skipped without one. The
page keeps its Content-Security-Policy: the probe script is allowed by its own hash, next
to the viewer's, so the test also shows that the policy lets the viewer run.
"""

from __future__ import annotations

import base64
import hashlib
import html
import json
import re
import shutil
import subprocess
from pathlib import Path
from typing import Any

import pytest

from apbot.bench.report import write_report
from apbot.bench.suite import CATEGORIES
from tests.bench.report.rundir import EVIL, LONG_TRACE, clock, record, write_run

BROWSER = next(
    (
        path
        for name in ("chromium", "chromium-browser", "google-chrome")
        if (path := shutil.which(name))
    ),
    None,
)
pytestmark = pytest.mark.skipif(BROWSER is None, reason="needs a headless Chromium")

PROBE = """
(async () => {
  const out = {};
  const ready = () => document.body.dataset.viewer;
  for (let i = 0; i < 200 && !ready(); i++) await new Promise((r) => setTimeout(r, 25));
  out.viewer = ready() || "never";
  const page = document.documentElement;
  out.pageFits = page.scrollWidth <= page.clientWidth;
  const boxes = [...document.querySelectorAll(".wide")];
  out.boxesScroll = boxes.some((b) => b.scrollWidth > b.clientWidth);
  const failed = document.querySelector("details.t.f");
  failed.open = true;
  await new Promise((r) => setTimeout(r, 50));
  out.rows = failed.querySelectorAll("table.tr tbody tr").length;
  out.marked = [...failed.querySelectorAll("mark")].map((m) => m.textContent);
  out.instruction = failed.querySelector("p").textContent;
  out.scripts = document.scripts.length;
  out.pageFitsOpen = page.scrollWidth <= page.clientWidth;
  const text = document.getElementById("filter-text");
  const failures = document.getElementById("filter-failures");
  const count = () => document.getElementById("filter-count").textContent;
  const filter = (value, only) => {
    text.value = value;
    failures.checked = only;
    text.dispatchEvent(new Event("input"));
    return count();
  };
  out.kettle = filter("kettle_1", false);
  out.byInstruction = filter("pwned", false);
  out.failuresOnly = filter("", true);
  out.nothing = filter("no such thing", false);
  out.noneShown = [...document.querySelectorAll(".none")].filter((n) => !n.hidden).length;
  out.cleared = filter("", false);
  document.getElementById("probe").textContent = JSON.stringify(out);
})();
"""


def _render(page: str, directory: Path) -> dict[str, Any]:
    digest = base64.b64encode(hashlib.sha256(PROBE.encode()).digest()).decode()
    page = page.replace("script-src '", f"script-src 'sha256-{digest}' '", 1)
    page = page.replace("</body>", f'<script>{PROBE}</script><pre id="probe"></pre></body>')
    probe = directory / "probe.html"
    probe.write_text(page, encoding="utf-8")
    assert BROWSER is not None
    result = subprocess.run(
        [
            BROWSER,
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--window-size=800,900",
            "--virtual-time-budget=20000",
            "--dump-dom",
            probe.as_uri(),
        ],
        capture_output=True,
        text=True,
        timeout=120,
    )
    found = re.search(r'<pre id="probe">(.*?)</pre>', result.stdout, re.S)
    assert found and found.group(1), result.stderr[-2000:]
    return json.loads(html.unescape(found.group(1)))


@pytest.fixture(scope="module")
def seen(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Any]:
    """A run over every category (wide tables), one failure with a long, wide trace."""
    directory = tmp_path_factory.mktemp("run")
    wide = [*LONG_TRACE[:-1], {"kind": "action", "step": 25, "action": "p", "display": "W" * 400}]
    records = [record(m, f"{c}_1", "t01", True) for m in ("oracle", "apbot") for c in CATEGORIES]
    records[-1] = record(
        "apbot", "kettle_1", "t02", False, instruction=EVIL, trace=wide, failure="gave up"
    )
    write_run(directory, records, run=None)
    write_report(directory, clock=clock)
    return _render((directory / "report.html").read_text(encoding="utf-8"), directory)


def test_the_viewer_runs_under_the_pages_policy(seen: dict[str, Any]) -> None:
    assert seen["viewer"] == "ready"
    assert seen["scripts"] == 3  # the viewer, its data block and the probe: nothing injected


def test_the_page_fits_800_pixels_and_wide_tables_scroll_in_their_box(seen: dict[str, Any]) -> None:
    assert seen["boxesScroll"]  # the category tables are wider than the page ...
    assert seen["pageFits"] and seen["pageFitsOpen"]  # ... and the page does not scroll


def test_opening_a_task_draws_its_details_and_whole_trace(seen: dict[str, Any]) -> None:
    assert seen["rows"] == len(LONG_TRACE) - 29
    assert seen["marked"] == ["temperature: expected 60, observed 50"]
    assert seen["instruction"] == f"Instruction: {EVIL}"  # shown as text, not run


def test_the_filter_matches_words_and_narrows_to_failures(seen: dict[str, Any]) -> None:
    assert seen["kettle"] == "3 of 30 tasks shown"  # oracle's kettle_1/t01, apbot's t01 and t02
    assert seen["byInstruction"] == "1 of 30 tasks shown"
    assert seen["failuresOnly"] == "1 of 30 tasks shown"
    assert seen["nothing"] == "0 of 30 tasks shown" and seen["noneShown"] == 2
    assert seen["cleared"] == ""
