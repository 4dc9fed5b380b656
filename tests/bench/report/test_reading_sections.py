"""The report on a read run: per task the read goal beside the stored one; read beliefs."""

from __future__ import annotations

from pathlib import Path

from apbot.bench.report import load_run, write_files
from apbot.bench.report.viewer import task_entry
from apbot.bench.runner import BenchOptions, run_benchmark


def test_a_read_run_reports_goals_and_beliefs(tmp_path: Path) -> None:
    options = BenchOptions(
        methods=["apbot", "oracle"],
        appliances=["blender_1"],
        sample=2,
        workers=1,
        out=tmp_path / "run",
    )
    outcome = run_benchmark(options, progress=False)
    write_files(load_run(tmp_path / "run"))
    text = (tmp_path / "run" / "report.md").read_text()
    assert "## Goals read from the instructions" in text and "## Read beliefs" in text
    assert "blender\\_1/t01" in text and "blender\\_1/t02" in text
    assert "of 2 tasks: the goal read from the instruction is the stored goal" in text
    record = next(r for r in outcome.records if r.method == "apbot")
    entry = task_entry(record, 0)
    assert entry["gm"] == "read" and entry["pg"] is not None and entry["bd"]
    assert entry["bh"] == record.belief_hash
    html = (tmp_path / "run" / "report.html").read_text()
    assert "Goal read from the instruction" in html  # the viewer draws it
