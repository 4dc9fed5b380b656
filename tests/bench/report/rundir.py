"""Run directories for the report's tests: records written by hand, and run.json to match."""

from __future__ import annotations

import json
from datetime import UTC, datetime
from pathlib import Path
from typing import Any

from apbot.bench.records import TaskRecord, record_key

EVIL = '<script>alert("pwned")</script>'

# run.json of a bench of two methods on the first task of two bundled appliances
RUN: dict[str, Any] = {
    "suite": "bundled",
    "belief": "true",
    "seed": 7,
    "methods": ["oracle", "apbot"],
    "selection": {"categories": None, "appliances": ["kettle_1", "dehumidifier_1"], "sample": 1},
    "tasks": 4,
    "started": "2026-01-02T03:00:00+00:00",
    "updated": "2026-01-02T03:00:00+00:00",
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


def render(directory: Path) -> tuple[str, str]:
    """The Markdown and HTML of a run directory without drawing figures (fast)."""
    from apbot.bench.report import load_run, render_html, render_markdown

    data = load_run(directory)
    generated = clock().strftime("%Y-%m-%d %H:%M UTC")
    return render_markdown(data, {}, generated), render_html(data, {}, generated)


def clock() -> datetime:
    return datetime(2026, 1, 2, 3, 4, tzinfo=UTC)


def record(method: str, appliance: str, task: str, success: bool, **extra: Any) -> TaskRecord:
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


def standard_records() -> list[TaskRecord]:
    """The run of :data:`RUN`: apbot fails on the dehumidifier (hostile text, a long trace)."""
    return [
        record("apbot", "kettle_1", "t01", True),
        record(
            "apbot",
            "dehumidifier_1",
            "t01",
            False,
            instruction=EVIL,
            goal={"mode": "<img src=x onerror=alert(1)>"},
            failure="gave up | <b>bold</b>",
            repairs=["temperature: allow 40..90 in steps of 10"],
            reasoning_steps=25,
            execution_steps=330,
            trace=LONG_TRACE,
        ),
        record("oracle", "kettle_1", "t01", True, reasoning_steps=3, execution_steps=4),
        record("oracle", "dehumidifier_1", "t01", True),
    ]


def write_run(
    directory: Path,
    records: list[TaskRecord] | None = None,
    run: dict[str, Any] | None = RUN,
    fault_study: bool = True,
) -> Path:
    """A run directory: results.jsonl, run.json (None: none) and optionally a fault study."""
    directory.mkdir(parents=True, exist_ok=True)
    rows = standard_records() if records is None else records
    (directory / "results.jsonl").write_text(
        "".join(r.model_dump_json() + "\n" for r in rows), encoding="utf-8"
    )
    if run is not None:
        (directory / "run.json").write_text(json.dumps(run), encoding="utf-8")
    if fault_study:
        (directory / "fault_study.json").write_text(
            json.dumps(
                {
                    "rates": [0.0, 0.25, 0.5],
                    "seeds": [0],
                    "methods": {"apbot": {"sr": [1.0, 0.75, None], "spl": [1.0, 0.5, None]}},
                }
            )
        )
    return directory
