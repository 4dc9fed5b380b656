"""Progress when nobody watches a terminal: a line of counts every few seconds."""

from __future__ import annotations

import io
from pathlib import Path

from typer.testing import CliRunner

from apbot.bench.progress import Counts, LineReporter
from apbot.bench.records import TaskRecord, record_key
from apbot.cli import app


def record(task: str, success: bool, failure: str = "") -> TaskRecord:
    return TaskRecord(
        key=record_key("oracle", "true", "kettle_1", task),
        method="oracle",
        belief="true",
        appliance="kettle_1",
        category="kettle",
        task=task,
        instruction="Heat the water, please.",
        goal={"heating": "on"},
        goal_variables=1,
        success=success,
        claimed_success=success,
        reasoning_steps=1,
        execution_steps=1,
        optimal_steps=1,
        spl=float(success),
        failure=failure,
    )


class Clock:
    def __init__(self) -> None:
        self.now = 100.0

    def __call__(self) -> float:
        return self.now


def test_a_line_every_few_seconds_with_successes_failures_and_errors() -> None:
    stream, clock = io.StringIO(), Clock()
    lines = LineReporter(stream, Counts(total=5), every=5.0, clock=clock)
    lines.begin(resumed=0)
    lines(record("t01", True))
    clock.now += 2
    lines(record("t02", False, "goal not met: heating='off' (want 'on')"))  # too soon: no line
    clock.now += 4
    lines(record("t03", False, "error: RuntimeError: boom"))
    clock.now += 65
    lines.line()
    lines.line()  # nothing new: no line
    assert stream.getvalue().splitlines() == [
        "bench: 5 task(s), 0 already finished, 5 to run",
        "bench: 3/5 finished (0:06): 1 ✓, 1 ✗, 1 error(s)",
    ]
    lines(record("t04", True))
    lines.line()
    assert stream.getvalue().splitlines()[-1] == "bench: 4/5 finished (1:11): 2 ✓, 1 ✗, 1 error(s)"


def test_resumed_records_count_from_the_start() -> None:
    stream = io.StringIO()
    counts = Counts(total=3)
    counts.add(record("t01", True))
    lines = LineReporter(stream, counts, every=0.0)
    lines.begin(resumed=1)
    lines(record("t02", True))
    assert stream.getvalue().splitlines() == [
        "bench: 3 task(s), 1 already finished, 2 to run",
        "bench: 2/3 finished (0:00): 2 ✓, 0 ✗, 0 error(s)",
    ]


def test_a_stream_that_cannot_show_the_marks_gets_words() -> None:
    stream = io.TextIOWrapper(io.BytesIO(), encoding="ascii")
    lines = LineReporter(stream, Counts(total=1), every=0.0)
    lines(record("t01", False))
    stream.seek(0)
    assert (
        stream.buffer.getvalue().decode()
        == "bench: 1/1 finished (0:00): 0 ok, 1 failed, 0 error(s)\n"
    )


def test_a_piped_bench_prints_progress_lines(tmp_path: Path) -> None:
    command = ["bench", "--methods", "oracle", "--appliances", "kettle_1,kettle_2", "--sample", "1"]
    result = CliRunner().invoke(
        app, [*command, "--workers", "1", "--no-report", "--out", str(tmp_path / "run")]
    )
    assert result.exit_code == 0, result.output
    lines = result.output.splitlines()
    assert lines[0] == "bench: 2 task(s), 0 already finished, 2 to run"
    assert any(line.startswith("bench: 2/2 finished (") for line in lines)
    assert "2 ✓, 0 ✗, 0 error(s)" in result.output
