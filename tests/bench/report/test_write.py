"""Writing a report: every file, atomically, the same bytes for the same run."""

from __future__ import annotations

import shutil
from pathlib import Path
from typing import Any

import pytest

from apbot.bench.report import ReportError, write_report
from tests.bench.report.rundir import clock, write_run


def test_writes_markdown_html_and_figures(report: dict[str, Any]) -> None:
    directory, paths = report["dir"], report["paths"]
    names = {p.relative_to(directory).as_posix() for p in paths}
    figures = {
        f"figures/{name}" for name in ("overview", "pvalues", "goal_variables", "fault_study")
    }
    assert names == {"report.md", "report.html"} | {f + ".svg" for f in figures}
    for path in paths[2:]:
        assert path.read_bytes().startswith(b"<?xml")
        assert f"(figures/{path.name})" in report["md"]
    assert not list(directory.rglob("*.tmp"))


def test_same_inputs_give_the_same_report(report: dict[str, Any], tmp_path: Path) -> None:
    copy = tmp_path / "again"
    shutil.copytree(report["dir"], copy)
    again = write_report(copy, clock=clock)
    assert len(again) == len(report["paths"]) == 6
    for path in again:
        original = report["dir"] / path.relative_to(copy)
        assert path.read_bytes() == original.read_bytes(), path.name


def test_a_file_that_cannot_be_written_is_named(tmp_path: Path) -> None:
    write_run(tmp_path, [])  # nothing finished: no figures to draw first
    (tmp_path / "report.html").mkdir()  # in the way (a read-only directory fails the same way)
    with pytest.raises(ReportError, match=r"report\.html: cannot be written \(Is a directory\)"):
        write_report(tmp_path, clock=clock)
