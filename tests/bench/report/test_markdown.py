"""The Markdown report: tables, figure links, failures with their reasons, nothing unescaped."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

from tests.bench.report.rundir import render, write_run


@pytest.fixture
def md(report: dict[str, Any]) -> str:
    return str(report["md"])


def test_tables_and_facts(md: str) -> None:
    assert "| Method | Dehumidifier | Kettle | Overall |" in md
    assert "| oracle † | 1.00 / 2.00 | 1.00 / 3.00 | 1.00 / 2.50 |" in md
    assert "| apbot | **0.00 / 25.00** | **1.00 / 2.00** | **0.50 / 13.50** |" in md
    assert "| apbot | **0.00 / 330.00** | **1.00 / 3.00** | **0.50 / 166.50** |" in md
    assert "| apbot | 1.00 / 1.00 | 0.75 / 0.50 | — / — |" in md  # fault study: SR / SPL
    assert "- **Seed:** 7" in md and "- **Report generated:** 2026-01-02 03:04 UTC" in md
    assert "Partial run" not in md


def test_failures_with_their_reasons(md: str) -> None:
    assert "## Failures (1 of 1)" in md
    assert (
        "### apbot: 1 failed\n\n- dehumidifier\\_1/t01: gave up \\| &lt;b&gt;bold&lt;/b&gt;" in md
    )


def test_untrusted_text_is_escaped(md: str) -> None:
    assert "<script" not in md and "<b>" not in md


def test_a_partial_run_says_so_first(tmp_path: Path) -> None:
    md, _ = render(write_run(tmp_path, []))
    assert md.startswith("# apbot benchmark report\n\n> **Partial run: 0 of 2 tasks finished")
