"""Suites written by users: every broken file is one line naming the file, the line or the task,
found when the suite is loaded (or validated), before any benchmark work starts."""

from __future__ import annotations

import shutil
from pathlib import Path
from typing import Any

import pytest
import yaml
from typer.testing import CliRunner

from apbot.bench.suite import SuiteError, bundled_suite_dir, load_suite, validate_suite
from apbot.cli import app
from apbot.model.problems import Problem


def make_suite(root: Path, *ids: str) -> Path:
    for appliance_id in ids:
        shutil.copytree(bundled_suite_dir() / appliance_id, root / appliance_id)
    return root


def edit_tasks(directory: Path, change: Any) -> None:
    path = directory / "tasks.yaml"
    data = yaml.safe_load(path.read_text(encoding="utf-8"))
    change(data)
    path.write_text(yaml.safe_dump(data, sort_keys=False), encoding="utf-8")


def load_errors(root: Path) -> list[Problem]:
    with pytest.raises(SuiteError) as caught:
        load_suite(root)
    return [p for p in caught.value.problems if p.severity == "error"]


def test_a_yaml_error_in_tasks_names_the_file_and_line(tmp_path: Path) -> None:
    suite = make_suite(tmp_path, "kettle_1", "dehumidifier_1")
    (suite / "kettle_1" / "tasks.yaml").write_text(
        "appliance: kettle_1\ntasks:\n- id: t01\n  instruction: [unclosed\n", encoding="utf-8"
    )
    [problem] = load_errors(suite)
    assert problem.source == str(suite / "kettle_1" / "tasks.yaml")
    assert problem.line == 5 and problem.message.startswith("YAML syntax")


def test_a_missing_tasks_file_and_an_empty_task_list(tmp_path: Path) -> None:
    suite = make_suite(tmp_path, "kettle_1", "dehumidifier_1")
    (suite / "kettle_1" / "tasks.yaml").unlink()
    (suite / "dehumidifier_1" / "tasks.yaml").write_text(
        "appliance: dehumidifier_1\ntasks: []\n", encoding="utf-8"
    )
    problems = load_errors(suite)
    assert [(Path(p.source or "").parent.name, p.line, p.message) for p in problems] == [
        ("dehumidifier_1", 2, "is empty; give at least 1"),
        ("kettle_1", None, "missing tasks.yaml"),
    ]


def test_repeated_task_ids_are_errors_not_silently_merged_records(tmp_path: Path) -> None:
    suite = make_suite(tmp_path, "kettle_1")

    def repeat(data: dict[str, Any]) -> None:
        data["tasks"][3]["id"] = "t01"

    edit_tasks(suite / "kettle_1", repeat)
    [problem] = load_errors(suite)
    assert problem.where == "tasks[3].id" and "'t01' repeats (it is also task 1)" in problem.message
    assert problem.line is not None and problem.line > 1


def test_two_directories_with_one_appliance_id(tmp_path: Path) -> None:
    suite = make_suite(tmp_path, "kettle_1")
    shutil.copytree(suite / "kettle_1", suite / "kettle_copy")
    [problem] = load_errors(suite)
    assert "appliance id 'kettle_1' is also the id of" in problem.message
    assert problem.source == str(suite / "kettle_copy" / "model.yaml")


def test_a_directory_without_appliances(tmp_path: Path) -> None:
    (tmp_path / "notes").mkdir()
    [problem] = load_errors(tmp_path)
    assert "no appliance directories here" in problem.message


def test_tasks_copied_from_another_appliance(tmp_path: Path) -> None:
    suite = make_suite(tmp_path, "kettle_1")
    edit_tasks(suite / "kettle_1", lambda data: data.update(appliance="kettle_2"))
    [problem] = load_errors(suite)
    assert "the tasks are for 'kettle_2' but the model beside them is 'kettle_1'" in problem.message


def test_validate_names_the_task_whose_goal_is_invalid_or_unreachable(tmp_path: Path) -> None:
    suite = make_suite(tmp_path, "kettle_1", "air_fryer_2")

    def bad_value(data: dict[str, Any]) -> None:
        data["tasks"][2]["goal"] = {"temperature": 81, "heating": "on"}

    def unreachable(data: dict[str, Any]) -> None:  # the fryer cannot be off on a preset
        task = data["tasks"][4]
        task["goal"] = {"power": "off", "preset": "fries", "temperature": 170, "running": "off"}
        del task["optimal_steps"]

    edit_tasks(suite / "kettle_1", bad_value)
    edit_tasks(suite / "air_fryer_2", unreachable)
    loaded = load_suite(suite)  # the files are fine; the goals are not
    problems = validate_suite(loaded)
    rendered = sorted(p.render() for p in problems)
    assert len(rendered) == 2
    assert "air_fryer_2/tasks.yaml:" in rendered[0] and "task t05: unreachable" in rendered[0]
    assert "kettle_1/tasks.yaml:" in rendered[1] and "task t03: 81°C is not one of" in rendered[1]
    assert all(p.line is not None for p in problems)


def test_the_bundled_suite_validates_clean() -> None:
    assert validate_suite(load_suite(), plan_missing_optimum=False) == []


def test_bench_refuses_a_broken_suite_in_one_line_per_problem(tmp_path: Path) -> None:
    suite = make_suite(tmp_path / "suite", "kettle_1")
    edit_tasks(suite / "kettle_1", lambda data: data["tasks"][1].update(id="t01"))
    out = tmp_path / "run"
    result = CliRunner().invoke(
        app, ["bench", "--suite", str(suite), "--out", str(out), "--workers", "1"]
    )
    assert result.exit_code == 2
    lines = result.output.strip().splitlines()
    assert len(lines) == 2 and "Traceback" not in result.output
    assert "kettle_1/tasks.yaml:" in lines[0] and "'t01' repeats" in lines[0]
    assert not (out / "results.jsonl").exists()


def test_bench_refuses_an_unreachable_task_before_any_worker_starts(tmp_path: Path) -> None:
    suite = make_suite(tmp_path / "suite", "kettle_1")
    edit_tasks(suite / "kettle_1", lambda data: data["tasks"][0].update(goal={"temperature": 81}))
    out = tmp_path / "run"
    result = CliRunner().invoke(
        app, ["bench", "--suite", str(suite), "--out", str(out), "--workers", "2"]
    )
    assert result.exit_code == 2 and "task t01: 81°C is not one of its values" in result.output
    assert "nothing was run" in result.output and not out.exists()
