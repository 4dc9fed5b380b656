"""Writing a report: every file, atomically, the same bytes for the same run."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from apbot.bench.report import ReportError, write_report
from tests.bench.report.rundir import clock, write_run


def test_writes_markdown_html_and_figures(tmp_path: Path) -> None:
    paths = write_report(write_run(tmp_path), clock=clock)
    names = {p.relative_to(tmp_path).as_posix() for p in paths}
    figures = {
        f"figures/{name}" for name in ("overview", "pvalues", "goal_variables", "fault_study")
    }
    assert names == {"report.md", "report.html"} | {f + ".svg" for f in figures}
    md = (tmp_path / "report.md").read_text(encoding="utf-8")
    for path in paths[2:]:
        assert path.read_bytes().startswith(b"<?xml")
        assert f"(figures/{path.name})" in md
    assert not list(tmp_path.rglob("*.tmp"))


def test_same_inputs_give_the_same_report(tmp_path: Path) -> None:
    first = write_run(tmp_path / "first")
    paths = write_report(first, clock=clock)
    copy = tmp_path / "again"
    shutil.copytree(first, copy)
    for path in write_report(copy, clock=clock):
        original = first / path.relative_to(copy)
        assert path.read_bytes() == original.read_bytes(), path.name
    assert len(paths) == 6


def test_a_file_that_cannot_be_written_is_named(tmp_path: Path) -> None:
    write_run(tmp_path)
    (tmp_path / "report.html").mkdir()  # in the way (a read-only directory fails the same way)
    with pytest.raises(ReportError, match=r"report\.html: cannot be written \(Is a directory\)"):
        write_report(tmp_path, clock=clock)
