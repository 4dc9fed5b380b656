"""llm-policy and apbot-no-model through the bench runner against a scripted server."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest
from typer.testing import CliRunner

from apbot.agent.registry import default_methods, methods
from apbot.bench.records import TaskRecord
from apbot.bench.runner import run_task
from apbot.bench.suite import SuiteAppliance, bundled_suite_dir, load_appliance
from apbot.cli import app
from tests.llm.conftest import SECRET
from tests.llm.scripted import Reply, Script

# kettle_1 t01 ("Heat the water to 80 degrees…"): start, then TEMP six times (100 -> 80)
PRESSES = ["press_start", *["press_temp"] * 6]


@pytest.fixture(scope="module")
def kettle() -> SuiteAppliance:
    return load_appliance(bundled_suite_dir() / "kettle_1")


@pytest.fixture
def llm_env(base_url: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> str:
    monkeypatch.setenv("APBOT_LLM", f"{base_url}:scripted-model")
    monkeypatch.setenv("APBOT_LLM_KEY_ENV", "APBOT_TEST_KEY")
    monkeypatch.setenv("APBOT_TEST_KEY", SECRET)
    monkeypatch.setenv("APBOT_LLM_CACHE_DIR", str(tmp_path / "cache"))
    monkeypatch.setenv("APBOT_LLM_BACKOFF", "0.01")
    return base_url


def _scripted(choices: list[dict[str, Any]]) -> Any:
    def route(body: dict[str, Any]) -> Reply:
        history = body["messages"][1]["content"].split("display showed after each:\n")[1]
        done = 0 if history.startswith("(nothing yet)") else history.count(" -> ")
        steps, index = 0, 0
        while index < len(choices) and steps < done:  # which choice comes next
            steps += choices[index].get("times", 1)
            index += 1
        answer = choices[index] if index < len(choices) else {"action": "done"}
        return Reply(json.dumps(answer))

    return route


def test_llm_methods_run_only_when_named() -> None:
    assert {"llm-policy", "apbot-no-model"} <= set(methods())
    assert not {"llm-policy", "apbot-no-model"} & set(default_methods())


def test_llm_policy_one_action_per_step(
    script: Script, llm_env: str, kettle: SuiteAppliance
) -> None:
    script.router = _scripted([{"action": a} for a in PRESSES])
    record = run_task(kettle, kettle.tasks[0], "llm-policy")
    assert record.success, record.failure
    assert record.reasoning_steps == 7 and record.execution_steps == 7
    assert record.claimed_success
    assert record.llm_usage == {"prompt_tokens": 88, "completion_tokens": 56, "calls": 8}
    first = script.requests[0]["messages"][1]["content"]
    assert first.startswith("User manual:\n# Ostara VT-17")
    assert "Actions: press_temp, press_warm, press_start" in first
    assert "Heat the water to 80 degrees" in first
    assert "temperature" not in first.split("User's request:")[1]  # no stored goal given
    assert "press_start -> " in script.requests[1]["messages"][1]["content"]
    assert SECRET not in json.dumps(record.model_dump())


def test_apbot_no_model_expands_repeats(
    script: Script, llm_env: str, kettle: SuiteAppliance
) -> None:
    script.router = _scripted([{"action": "press_start"}, {"action": "press_temp", "times": 6}])
    record = run_task(kettle, kettle.tasks[0], "apbot-no-model")
    assert record.success, record.failure
    assert record.reasoning_steps == 2 and record.execution_steps == 7
    assert script.count == 3


def test_an_action_outside_the_panel_is_refused_by_the_schema(
    script: Script, llm_env: str, kettle: SuiteAppliance
) -> None:
    script.router = lambda body: Reply('{"action": "rm -rf /"}')
    record = run_task(kettle, kettle.tasks[0], "llm-policy")
    assert not record.success and "no valid choice" in record.failure
    assert record.execution_steps == 0 and script.count == 4
    schema = script.requests[0]["response_format"]["json_schema"]["schema"]
    assert schema["properties"]["action"]["enum"][-1] == "done"


def test_a_cached_rerun_is_free_and_identical(
    script: Script, llm_env: str, kettle: SuiteAppliance
) -> None:
    script.router = _scripted([{"action": a} for a in PRESSES])
    first = run_task(kettle, kettle.tasks[0], "llm-policy")
    sent = script.count
    again = run_task(kettle, kettle.tasks[0], "llm-policy")
    assert script.count == sent

    def same(record: TaskRecord) -> dict[str, Any]:
        return record.model_dump(exclude={"timings"})

    assert same(again) == same(first)


def test_bench_stops_cleanly_when_the_budget_is_spent(
    script: Script, llm_env: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    script.router = _scripted([{"action": a} for a in PRESSES])
    out = tmp_path / "run"
    args = ["bench", "--methods", "llm-policy", "--appliances", "kettle_1", "--sample", "1"]
    args += ["--workers", "1", "--out", str(out), "--no-report", "--belief", "true"]
    args += ["--goal", "given"]  # the policy sees neither: no reading spends the budget
    stopped = CliRunner().invoke(app, [*args, "--llm-requests", "3"])
    assert stopped.exit_code == 1, stopped.output
    assert "LLM budget" in stopped.output
    results = out / "results.jsonl"
    assert not results.exists() or not results.read_text().strip()  # not a result
    monkeypatch.setenv("APBOT_LLM_MAX_REQUESTS", "")  # a new process: no budget given
    finished = CliRunner().invoke(app, args)
    assert finished.exit_code == 0, finished.output
    assert script.count == 8  # the three answers paid for are not asked again
    summary = json.loads((out / "summary.json").read_text())
    assert summary["methods"]["llm-policy"]["llm_usage"]["calls"] == 8
    for path in out.rglob("*"):
        if path.is_file():
            assert SECRET not in path.read_text(encoding="utf-8", errors="replace")


def test_run_and_bench_say_they_read_offline(tmp_path: Path) -> None:
    run = CliRunner().invoke(app, ["run", "kettle_1", "t01"])
    assert "offline reader" in run.output and "--llm" in run.output
    bench = CliRunner().invoke(
        app,
        [
            "bench",
            "--appliances",
            "kettle_1",
            "--sample",
            "1",
            "--methods",
            "oracle",
            "--workers",
            "1",
            "--out",
            str(tmp_path / "b"),
            "--no-report",
        ],
    )
    assert bench.exit_code == 0
    assert "offline reader" in bench.output and "APBOT_LLM" in bench.output
