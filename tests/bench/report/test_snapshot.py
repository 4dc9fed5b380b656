"""One read of a run directory: the figures come from the records read, never a stale summary."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

from apbot.bench.report import ReportError, load_run, progress, write_report
from apbot.bench.runner import BenchOptions, run_benchmark
from tests.bench.report.rundir import RUN, clock, record, render, standard_records, write_run


@pytest.fixture(scope="module")
def finished_run(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A real bench: two methods on the first two tasks of two appliances (8 records)."""
    out = tmp_path_factory.mktemp("bench") / "run"
    options = BenchOptions(
        methods=["oracle", "apbot"],
        appliances=["kettle_1", "dehumidifier_1"],
        sample=2,
        workers=1,
        out=out,
    )
    run_benchmark(options, progress=False)
    return out


def test_a_strict_prefix_of_the_work_says_how_far_each_method_got(
    finished_run: Path, tmp_path: Path
) -> None:
    """What `apbot report` sees while a bench is running: run.json and summary.json of the
    whole run (the summary is stale), and only the first records, the last one half written."""
    partial = tmp_path / "partial"
    partial.mkdir()
    for name in ("run.json", "summary.json"):
        shutil.copy(finished_run / name, partial / name)
    lines = (finished_run / "results.jsonl").read_text(encoding="utf-8").splitlines(True)
    assert len(lines) == 8
    (partial / "results.jsonl").write_text("".join(lines[:5]) + lines[5][:40], encoding="utf-8")

    data = load_run(partial)
    counts = {
        m: sum(json.loads(line)["method"] == m for line in lines[:5]) for m in ("oracle", "apbot")
    }
    assert counts["oracle"] != counts["apbot"]  # the work is interleaved, oracle first
    assert data.finished() == counts
    assert {m: data.summary.methods[m].overall.n for m in counts} == counts  # not the stale 4
    expected = f"oracle {counts['oracle']} of 4 tasks finished, apbot {counts['apbot']} of 4"
    assert progress(data).state == "partial" and progress(data).text == expected

    md, page = render(partial)
    assert f"Partial run: {expected}." in md and f"Partial run: {expected}." in page
    assert f"- **Finished:** {expected}" in md


def test_the_finished_run_says_so(finished_run: Path) -> None:
    data = load_run(finished_run)
    assert progress(data).state == "complete"
    assert progress(data).text == "all 4 tasks finished per method"
    assert data.outside == 0 and len(data.records) == 8


def test_a_run_with_nothing_finished_yet(finished_run: Path, tmp_path: Path) -> None:
    shutil.copy(finished_run / "run.json", tmp_path / "run.json")
    data = load_run(tmp_path)
    assert progress(data).text == "0 of 4 tasks finished per method"
    paths = write_report(tmp_path, clock=clock)  # nothing to draw, nothing to fail on
    assert "Partial run: 0 of 4 tasks finished per method." in paths[0].read_text()


def test_records_outside_the_selection_are_left_out_and_counted(tmp_path: Path) -> None:
    """An earlier bench into the same directory ran more tasks, and another method."""
    extra = [
        record("apbot", "kettle_1", "t02", False),
        record("apbot-open-loop", "kettle_1", "t01", False),
    ]
    write_run(tmp_path, standard_records() + extra)
    data = load_run(tmp_path)
    assert data.outside == 2 and len(data.records) == 4
    assert data.methods == ["oracle", "apbot"]
    assert data.summary.methods["apbot"].overall.n == 2
    assert progress(data).text == "all 2 tasks finished per method"
    md, _ = render(tmp_path)
    assert "- **Left out:** 2 record(s) in results.jsonl outside this run's selection" in md


def test_without_run_json_every_record_counts_and_completeness_is_unknown(
    tmp_path: Path,
) -> None:
    write_run(tmp_path, run=None)
    data = load_run(tmp_path)
    assert len(data.records) == 4 and data.outside == 0
    state = progress(data)
    assert state.state == "unknown"
    assert state.text == (
        "4 records; run.json is missing or lists no methods, so whether the run is complete "
        "is unknown"
    )


def test_a_directory_without_a_run_is_a_clear_error(tmp_path: Path) -> None:
    with pytest.raises(ReportError, match=r"no such run directory"):
        load_run(tmp_path / "nowhere")
    with pytest.raises(ReportError, match=r"no benchmark run here .*run `apbot bench --out"):
        load_run(tmp_path)


def test_damaged_files_name_the_file_and_line(tmp_path: Path) -> None:
    write_run(tmp_path, fault_study=False)
    results = tmp_path / "results.jsonl"
    lines = results.read_text(encoding="utf-8").splitlines(True)
    results.write_text(lines[0] + "garbage\n" + "".join(lines[1:]), encoding="utf-8")
    with pytest.raises(ReportError, match=r"results\.jsonl:2: not a valid result record"):
        load_run(tmp_path)
    (tmp_path / "results.jsonl").unlink()
    (tmp_path / "results.jsonl").mkdir()  # unreadable as a file (root reads anything else)
    with pytest.raises(ReportError, match=r"results\.jsonl: cannot be read \(Is a directory\)"):
        load_run(tmp_path)
    (tmp_path / "results.jsonl").rmdir()
    write_run(tmp_path, fault_study=False)
    (tmp_path / "run.json").write_text("{not json")
    with pytest.raises(ReportError, match=r"run\.json:1:2: not valid JSON"):
        load_run(tmp_path)


def test_fault_study_with_a_missing_value_is_a_clear_error(tmp_path: Path) -> None:
    write_run(tmp_path)
    (tmp_path / "fault_study.json").write_text(
        json.dumps({"rates": [0.0, 0.5], "methods": {"apbot": {"sr": [1.0], "spl": [1.0, 0.5]}}})
    )
    with pytest.raises(
        ReportError, match=r"fault_study\.json: .*methods\.apbot\.sr has 1 values for 2 rates"
    ):
        load_run(tmp_path)


def test_the_run_date_comes_from_run_json(tmp_path: Path) -> None:
    write_run(tmp_path, run={**RUN, "updated": "2026-01-02T05:30:00+00:00"})
    assert load_run(tmp_path).run_date == "2026-01-02 03:00 UTC (last updated 2026-01-02 05:30 UTC)"
