"""The benchmark report: numbers in the tables, a self-contained and escaped HTML page."""

from __future__ import annotations

import json
import re
import shutil
from datetime import UTC, datetime
from pathlib import Path
from typing import Any

import pytest

from apbot.bench.records import TaskRecord, record_key
from apbot.bench.report import ReportError, write_report

EVIL = '<script>alert("pwned")</script>'


def _clock() -> datetime:
    return datetime(2026, 1, 2, 3, 4, tzinfo=UTC)


def _record(method: str, appliance: str, task: str, success: bool, **extra: Any) -> TaskRecord:
    fields: dict[str, Any] = {
        "key": record_key(method, "true", appliance, task),
        "method": method,
        "belief": "true",
        "appliance": appliance,
        "category": appliance.rsplit("_", 1)[0],
        "task": task,
        "instruction": f"Set {appliance} for {task}.",
        "goal": {"power": "on"},
        "goal_variables": 1,
        "success": success,
        "claimed_success": success,
        "reasoning_steps": 2,
        "execution_steps": 3,
        "optimal_steps": 3,
        "spl": 1.0 if success else 0.0,
        "final_values": {"power": "on" if success else "off"},
        "trace": [
            {"kind": "macro", "step": 1, "text": "power", "expected": {"power": "on"}},
            {"kind": "action", "step": 1, "action": "press_power", "display": "ON"},
            {"kind": "stop", "step": 1, "text": "the goal holds"},
        ],
    }
    fields.update(extra)
    return TaskRecord(**fields)


def _figures(sr: float, spl: float, reasoning: float, execution: float, n: int) -> dict:
    return {
        "sr": sr,
        "spl": spl,
        "reasoning_steps": reasoning,
        "execution_steps": execution,
        "n": n,
    }


LONG_TRACE = [
    {"kind": "macro", "step": 1, "text": "set_temperature", "expected": {"temperature": 60}},
    {"kind": "action", "step": 1, "action": "press_up", "display": "50"},
    {
        "kind": "check",
        "step": 1,
        "text": "mismatch",
        "expected": {"temperature": 60},
        "values": {"temperature": 50},
    },
    *(
        {"kind": "action", "step": 1, "action": "press_up", "display": f"T{i}", "exploring": True}
        for i in range(30)
    ),
    {"kind": "explore", "step": 1, "text": "temperature under press_up: 40..90 by 10"},
    {"kind": "repair", "step": 1, "text": "temperature: allow 40..90 in steps of 10"},
    *(
        {"kind": "action", "step": 2 + i, "action": f"press_{i}", "display": str(i)}
        for i in range(300)
    ),
    {"kind": "stop", "step": 25, "text": "reached the limit of 25 reasoning steps"},
]


def _write_run(directory: Path, fault_study: bool = True) -> Path:
    directory.mkdir(parents=True, exist_ok=True)
    records = [
        _record("apbot", "kettle_1", "t01", True),
        _record(
            "apbot",
            "dehumidifier_1",
            "t01",
            False,
            instruction=EVIL,
            goal={"mode": "<img src=x onerror=alert(1)>"},
            failure="gave up | <b>bold</b>",
            repairs=["temperature: allow 40..90 in steps of 10"],
            trace=LONG_TRACE,
        ),
        _record("oracle", "kettle_1", "t01", True),
        _record("oracle", "dehumidifier_1", "t01", True),
    ]
    (directory / "results.jsonl").write_text(
        "".join(r.model_dump_json() + "\n" for r in records), encoding="utf-8"
    )
    summary = {
        "belief": "true",
        "methods": {
            "apbot": {
                "overall": _figures(0.5, 0.5, 2.0, 3.0, 2),
                "categories": {
                    "dehumidifier": _figures(0.0, 0.0, 25.0, 330.0, 1),
                    "kettle": _figures(1.0, 1.0, 2.0, 3.0, 1),
                },
            },
            "oracle": {
                "overall": _figures(1.0, 1.0, 2.5, 3.5, 2),
                "categories": {
                    "dehumidifier": _figures(1.0, 1.0, 2.0, 3.0, 1),
                    "kettle": _figures(1.0, 1.0, 3.0, 4.0, 1),
                },
            },
        },
        "pvalues": {
            "apbot": {"apbot": 1.0, "oracle": 0.0123},
            "oracle": {"apbot": 0.0123, "oracle": 1.0},
        },
        "goal_variables": {
            "apbot": {"1": {"sr": 0.5, "n": 2}},
            "oracle": {"1": {"sr": 1.0, "n": 2}},
        },
    }
    (directory / "summary.json").write_text(json.dumps(summary), encoding="utf-8")
    (directory / "run.json").write_text(
        json.dumps(
            {"suite": "bundled", "belief": "true", "seed": 7, "methods": ["oracle", "apbot"]}
        )
    )
    if fault_study:
        (directory / "fault_study.json").write_text(
            json.dumps(
                {
                    "rates": [0.0, 0.25],
                    "seeds": [0],
                    "methods": {"apbot": {"sr": [1.0, 0.75], "spl": [1.0, 0.5]}},
                }
            )
        )
    return directory


@pytest.fixture(scope="module")
def report(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Any]:
    directory = _write_run(tmp_path_factory.mktemp("run"))
    paths = write_report(directory, clock=_clock)
    return {
        "dir": directory,
        "paths": paths,
        "md": (directory / "report.md").read_text(encoding="utf-8"),
        "html": (directory / "report.html").read_text(encoding="utf-8"),
    }


def test_writes_markdown_html_and_figures(report: dict[str, Any]) -> None:
    directory = report["dir"]
    names = {p.relative_to(directory).as_posix() for p in report["paths"]}
    assert {
        "report.md",
        "report.html",
        "figures/pvalues.png",
        "figures/goal_variables.png",
        "figures/fault_study.png",
        "figures/overview.png",
    } <= names
    for path in report["paths"]:
        assert path.exists()
        if path.suffix == ".png":
            assert path.read_bytes().startswith(b"\x89PNG")
            assert f"(figures/{path.name})" in report["md"]


def test_tables_show_the_summary_numbers_with_the_best_in_bold(report: dict[str, Any]) -> None:
    md = report["md"]
    # run.json order (oracle first); categories by goal variables: dehumidifier (1), kettle (2)
    assert "| Method | Dehumidifier | Kettle | Overall |" in md
    assert "| oracle † | 1.00 / 2.00 | 1.00 / 3.00 | 1.00 / 2.50 |" in md
    # the oracle is a reference (given the truth), so apbot is the best ranked method
    assert "| apbot | **0.00 / 25.00** | **1.00 / 2.00** | **0.50 / 2.00** |" in md
    assert "| apbot | **0.00 / 330.00** | **1.00 / 3.00** | **0.50 / 3.00** |" in md
    assert "| oracle | — | **0.012\\*** |" in md  # p < 0.05 is marked
    assert "| apbot | 1.00 / 1.00 | 0.75 / 0.50 |" in md  # fault study: SR / SPL per rate
    assert "- **Seed:** 7" in md
    assert "## Failures (1 of 1)" in md
    assert (
        "### apbot: 1 failed\n\n- dehumidifier\\_1/t01: gave up \\| &lt;b&gt;bold&lt;/b&gt;" in md
    )


def test_html_is_self_contained(report: dict[str, Any]) -> None:
    page = report["html"]
    assert not re.search(r'(src|href)\s*=\s*"?(https?:|//)', page)
    assert "<script" not in page and "<link" not in page and "@import" not in page
    images = re.findall(r'<img [^>]*src="([^"]*)"', page)
    assert len(images) == 4 and all(src.startswith("data:image/png;base64,") for src in images)


def test_untrusted_text_is_escaped(report: dict[str, Any]) -> None:
    page, md = report["html"], report["md"]
    assert EVIL not in page and "<img src=x" not in page and "<b>bold" not in page
    assert "&lt;script&gt;alert(&quot;pwned&quot;)&lt;/script&gt;" in page
    assert "&lt;img src=x onerror=alert(1)&gt;" in page
    assert "<script" not in md and "<b>" not in md


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


def test_same_inputs_give_the_same_report(report: dict[str, Any], tmp_path: Path) -> None:
    copy = tmp_path / "again"
    shutil.copytree(report["dir"], copy)
    for path in write_report(copy, clock=_clock):
        original = report["dir"] / path.relative_to(copy)
        assert path.read_bytes() == original.read_bytes(), path.name


def test_missing_summary_is_a_clear_error(tmp_path: Path) -> None:
    with pytest.raises(ReportError, match=r"summary\.json: not found; run `apbot bench"):
        write_report(tmp_path)


def test_malformed_summary_names_the_place(tmp_path: Path) -> None:
    _write_run(tmp_path, fault_study=False)
    summary = json.loads((tmp_path / "summary.json").read_text())
    del summary["methods"]["apbot"]["overall"]["sr"]
    (tmp_path / "summary.json").write_text(json.dumps(summary))
    with pytest.raises(
        ReportError,
        match=r"summary\.json: methods\.apbot\.overall\.sr: Field "
        "required",
    ):
        write_report(tmp_path)
    (tmp_path / "summary.json").write_text("{not json")
    with pytest.raises(ReportError, match=r"summary\.json:1:2: not valid JSON"):
        write_report(tmp_path)


def test_fault_study_with_a_missing_value_is_a_clear_error(tmp_path: Path) -> None:
    _write_run(tmp_path)
    (tmp_path / "fault_study.json").write_text(
        json.dumps({"rates": [0.0, 0.5], "methods": {"apbot": {"sr": [1.0], "spl": [1.0, 0.5]}}})
    )
    with pytest.raises(
        ReportError,
        match=r"fault_study\.json: .*methods\.apbot\.sr has 1 "
        "values for 2 rates",
    ):
        write_report(tmp_path)
