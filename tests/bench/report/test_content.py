"""The tables and facts: numbers computed from the records, the best in bold."""

from __future__ import annotations

from pathlib import Path

from apbot.bench.report import load_run, progress
from apbot.bench.report.content import SR_TABLE, fault_rows, header_facts, pvalue_rows, table
from tests.bench.report.rundir import RUN, record, standard_records, write_run


def test_tables_hold_the_records_figures_with_the_best_in_bold(tmp_path: Path) -> None:
    data = load_run(write_run(tmp_path))
    header, rows = table(data, SR_TABLE)
    # run.json order (oracle first); categories by goal variables: dehumidifier (1), kettle (2)
    assert header == ["Method", "Dehumidifier", "Kettle", "Overall"]
    # the oracle is a reference (given the truth), so apbot is the best ranked method
    assert rows == [
        [
            ("oracle †", False),
            ("1.00 / 2.00", False),
            ("1.00 / 3.00", False),
            ("1.00 / 2.50", False),
        ],
        [("apbot", False), ("0.00 / 25.00", True), ("1.00 / 2.00", True), ("0.50 / 13.50", True)],
    ]


def test_significant_differences_are_starred_and_bold(tmp_path: Path) -> None:
    tasks = [f"t{i:02d}" for i in range(1, 11)]
    records = [record("oracle", "kettle_1", t, True) for t in tasks]
    records += [record("apbot", "kettle_1", t, False) for t in tasks]
    run = {**RUN, "selection": {"appliances": ["kettle_1"]}, "tasks": 20}
    data = load_run(write_run(tmp_path, records, run=run))
    header, rows = pvalue_rows(data)
    assert header == ["", "oracle", "apbot"]
    assert rows[0][0] == ("oracle", False) and rows[0][1] == ("—", False)
    text, bold = rows[0][2]
    assert text.endswith("*") and bold and float(text[:-1]) < 0.05
    assert rows[1][1] == rows[0][2]


def test_fault_study_rows_show_missing_figures_as_a_dash(tmp_path: Path) -> None:
    data = load_run(write_run(tmp_path))
    assert data.fault_study is not None
    header, rows = fault_rows(data.fault_study)
    assert header == ["Method", "rate 0", "rate 0.25", "rate 0.5"]
    assert rows == [
        [("apbot", False), ("1.00 / 1.00", False), ("0.75 / 0.50", False), ("— / —", False)]
    ]


def test_header_facts_name_the_run(tmp_path: Path) -> None:
    facts = dict(header_facts(load_run(write_run(tmp_path)), "2026-01-02 03:04 UTC"))
    assert facts["Suite"] == "bundled" and facts["Belief"] == "true" and facts["Seed"] == "7"
    assert facts["Methods"] == "oracle, apbot"
    assert facts["Finished"] == "all 2 tasks finished per method"
    assert facts["Records"] == "4" and facts["Run"] == "2026-01-02 03:00 UTC"
    assert "Left out" not in facts


def test_more_records_than_the_count_allows_is_not_called_complete(tmp_path: Path) -> None:
    """Without the suite to replay the selection, an earlier bench's records look alike."""
    extra = record("apbot", "kettle_1", "t02", True)
    run = {**RUN, "suite": "/no/such/suite"}
    data = load_run(write_run(tmp_path, [*standard_records(), extra], run=run))
    state = progress(data)
    assert state.state == "unknown"
    assert state.text.startswith(
        "3 records for a method that selected 2 tasks: results.jsonl holds records outside "
        "the selection (the selection could not be replayed on suite '/no/such/suite'"
    )
