"""The traces section: grouped by appliance, failures first, every task's data once, whole."""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

import pytest

from apbot.bench.report import load_run
from apbot.bench.report.traces import DATA_ID, grouped
from apbot.bench.report.viewer import decode
from tests.bench.report.rundir import (
    EVIL,
    LONG_TRACE,
    record,
    render,
    standard_records,
    write_run,
)


def _data(page: str) -> Any:
    match = re.search(rf'<script type="text/plain" id="{DATA_ID}">([A-Za-z0-9+/=]*)</script>', page)
    assert match, "the viewer's data block"
    return decode(match.group(1))


@pytest.fixture
def page(report: dict[str, Any]) -> str:
    return str(report["html"])


def test_groups_by_appliance_with_failures_first(tmp_path: Path) -> None:
    records = [
        record("apbot", "kettle_1", "t01", True),
        record("apbot", "kettle_1", "t02", True),
        record("apbot", "microwave_1", "t02", True),
        record("apbot", "microwave_1", "t03", False),
        record("apbot", "microwave_1", "t01", False),
        record("apbot", "air_fryer_1", "t01", False),
        record("apbot", "air_fryer_1", "t02", True),
    ]
    data = load_run(write_run(tmp_path, records, run=None))
    groups = grouped(data)["apbot"]
    assert [appliance for appliance, _ in groups] == ["microwave_1", "air_fryer_1", "kettle_1"]
    assert [r.task for r in groups[0][1]] == ["t01", "t03", "t02"]  # failures, then successes


def test_every_task_line_points_at_its_own_data(page: str) -> None:
    data = _data(page)
    lines = re.findall(r'<details class="t (s|f)" data-i="(\d+)"><summary>([^<]*)', page)
    assert len(lines) == len(data["tasks"]) == 4
    for css, index, summary in lines:
        task = data["tasks"][int(index)]
        assert summary.startswith(task["t"] + " · R ")
        assert (css == "s") == task["ok"]
    # per method in the run's order (oracle first), apbot's failing dehumidifier first
    order = [(t["m"], t["a"]) for t in data["tasks"]]
    assert order[2:] == [("apbot", "dehumidifier_1"), ("apbot", "kettle_1")]
    assert order[:2] == [("oracle", "dehumidifier_1"), ("oracle", "kettle_1")]
    assert '<b>dehumidifier_1</b> <span class="muted">Dehumidifier</span> — 1 failed' in page


def test_the_details_are_the_records(page: str) -> None:
    failed = next(t for t in _data(page)["tasks"] if not t["ok"])
    assert failed["ins"] == EVIL  # text, drawn with textContent: never parsed as HTML
    assert failed["goal"] == [["mode", "<img src=x onerror=alert(1)>", None]]
    assert failed["why"] == "gave up | <b>bold</b>"
    assert failed["repairs"] == ["temperature: allow 40..90 in steps of 10"]
    assert EVIL not in page and "<img src=x" not in page


def test_traces_are_whole_and_marked(page: str) -> None:
    data = _data(page)
    failed = next(t for t in data["tasks"] if not t["ok"])
    rows = data["traces"][failed["tr"]]
    # 30 exploration presses share a row; nothing else is merged and nothing is cut
    assert len(rows) == len(LONG_TRACE) - 29
    assert rows[0] == ["m", 1, "macro", "set_temperature", "expect temperature=60"]
    assert rows[2] == [
        "c",
        1,
        "check",
        [["bad", "mismatch"]],
        [["mark", "temperature: expected 60, observed 50"]],
    ]
    assert rows[3] == ["x", 1, "explore", "press_up ×30", " → ".join(f"T{i}" for i in range(30))]
    assert rows[5] == ["r", 1, "repair", "model repaired: temperature: allow 40..90 in steps of 10"]
    assert rows[-2] == ["", 301, "", "press_299", "299"]
    assert rows[-1] == ["s", 25, "stop", "reached the limit of 25 reasoning steps"]


def test_each_distinct_trace_is_stored_once(page: str) -> None:
    data = _data(page)
    assert len(data["traces"]) == 2  # three tasks share the short trace
    assert len({t["tr"] for t in data["tasks"]}) == 2


def test_refusals_blank_displays_and_mismatched_values_are_marked(tmp_path: Path) -> None:
    trace = [
        {"kind": "action", "step": 1, "action": "press_a", "display": "", "accepted": False},
        *(
            {"kind": "action", "step": 2, "action": "press_b", "display": d, "exploring": True}
            | ({"accepted": False} if d == "" else {})
            for d in ("1", "", "3")
        ),
        {"kind": "check", "step": 2, "text": "mismatch", "expected": {"a": 1}, "values": {"b": 2}},
    ]
    records = [record("apbot", "kettle_1", "t01", False, trace=trace)]
    rows = _data(render(write_run(tmp_path, records, run=None))[1])["traces"][0]
    assert rows[0] == ["", 1, "", "press_a", [["muted", "(blank)"], " ", ["bad", "refused"]]]
    assert rows[1] == ["x", 2, "explore", "press_b ×3", ["1 → (blank) → 3 ", ["bad", "1 refused"]]]
    assert rows[2][4] == ["a=1; ", ["mark", "b: observed 2"]]


def test_a_partial_run_says_what_is_not_run_yet(tmp_path: Path) -> None:
    records = [r for r in standard_records() if (r.method, r.appliance) != ("apbot", "kettle_1")]
    _, page = render(write_run(tmp_path, records))
    section = page[page.index('<section class="method" id="m-apbot">') :]
    assert '<p class="muted">1 failed, 0 succeeded, 1 not run yet</p>' in section
