"""The trace viewer: failures first, checks and repairs marked, long traces cut."""

from __future__ import annotations

from typing import Any

import pytest

from apbot.bench.report import write_report
from tests.bench.report.rundir import clock, write_run


@pytest.fixture(scope="module")
def report(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Any]:
    directory = write_run(tmp_path_factory.mktemp("run"))
    write_report(directory, clock=clock)
    return {"html": (directory / "report.html").read_text(encoding="utf-8")}


def test_trace_viewer_lists_failures_first_and_marks_checks_and_repairs(
    report: dict[str, Any],
) -> None:
    page = report["html"]
    section = page[page.index('<section id="m-apbot">') :]
    section = section[: section.index("</section>")]
    assert section.index("Failures (1)") < section.index("Successes (1)")
    assert "<mark>temperature: expected 60, observed 50</mark>" in section
    assert '<tr class="r"><td>1<td>repair<td colspan="2">model repaired: temperature' in section
    # 30 exploration presses of one action share one row, with the displays in order
    assert "press_up ×30<td>T0 → T1 → T2" in section
    assert "… 107 more rows not shown …" in section  # 307 rows cut to the limit of 200
    assert "reached the limit of 25 reasoning steps" in section.split("more rows not shown")[1]
