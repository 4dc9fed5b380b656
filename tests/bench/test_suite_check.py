"""The suite checker: goal findings are errors unless a task allows them, with a reason."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from apbot.bench.suite import SuiteAppliance, Task, bundled_suite_dir, load_appliance
from apbot.bench.suite_check import FillError, check_appliance, fill_optimal
from apbot.model.yaml_text import read_yaml


def _appliance() -> SuiteAppliance:
    return load_appliance(bundled_suite_dir() / "bottle_washer_1")


def _with(appliance: SuiteAppliance, task_id: str, **update: object) -> SuiteAppliance:
    appliance.tasks = [
        t.model_copy(update=update) if t.id == task_id else t for t in appliance.tasks
    ]
    return appliance


def _errors(appliance: SuiteAppliance) -> list[str]:
    return [
        f"{p.where} [{p.check}] {p.message}"
        for p in check_appliance(appliance)
        if p.severity == "error"
    ]


def test_the_bundled_exception_is_needed_and_enough() -> None:
    appliance = _appliance()
    assert _errors(appliance) == []
    errors = _errors(_with(appliance, "t06", allow={}))
    assert [e.split(" ")[1] for e in errors] == ["[start-only]", "[free:mode]"]
    assert all("t06" in e for e in errors)


def test_allow_entries_that_do_not_apply_are_reported() -> None:
    appliance = _with(
        _appliance(),
        "t01",
        allow={"quick-start": "stale", "free:power": "x", "whatever": "y", "free:mode": " "},
    )
    errors = _errors(appliance)
    assert any("nothing to allow any more (quick-start" in e for e in errors)
    assert any("'power' is not in the goal" in e for e in errors)
    assert any("unknown finding 'whatever'" in e for e in errors)
    assert any("free:mode" in e and "say why" in e for e in errors)


def test_a_goal_met_by_its_start_alone_is_an_error() -> None:
    appliance = _appliance()
    appliance.tasks.append(
        Task(id="t11", instruction="Start the default one.", goal={"mode": "auto", "running": "on"})
    )
    errors = [e for e in _errors(appliance) if "t11" in e]
    assert any("[start-only]" in e for e in errors)


def test_fill_optimal_keeps_the_allow_entries(tmp_path: Path) -> None:
    directory = tmp_path / "bottle_washer_1"
    shutil.copytree(bundled_suite_dir() / "bottle_washer_1", directory)
    tasks_file = directory / "tasks.yaml"
    text = tasks_file.read_text(encoding="utf-8")
    tasks_file.write_text(text.replace("optimal_steps: 2\n", "optimal_steps: 99\n", 1))
    appliance = load_appliance(directory)
    assert fill_optimal(appliance) == 1
    data = read_yaml(tasks_file.read_text(encoding="utf-8"), str(tasks_file))
    by_id = {t["id"]: t for t in data["tasks"]}
    assert by_id["t06"]["optimal_steps"] == 2
    assert set(by_id["t06"]["allow"]) == {"start-only", "free:mode"}
    assert "allow" not in by_id["t01"]
    assert _errors(load_appliance(directory)) == []


def test_fill_optimal_names_a_task_whose_goal_value_is_invalid_and_writes_nothing(
    tmp_path: Path,
) -> None:
    directory = tmp_path / "bottle_washer_1"
    shutil.copytree(bundled_suite_dir() / "bottle_washer_1", directory)
    tasks_file = directory / "tasks.yaml"
    before = tasks_file.read_text(encoding="utf-8").replace(
        "goal: {mode: sterilise, running: 'on'}", "goal: {mode: no such mode, running: 'on'}"
    )
    tasks_file.write_text(before, encoding="utf-8")
    appliance = load_appliance(directory)
    with pytest.raises(FillError, match=r"bottle_washer_1 t03: .*no such mode"):
        fill_optimal(appliance)
    assert tasks_file.read_text(encoding="utf-8") == before


def test_a_development_category_is_checked_with_its_goal_size() -> None:
    from dataclasses import replace

    appliance = _appliance()  # bottle washer tasks have two goal settings, as ice cream makers
    assert _errors(replace(appliance, category="ice_cream_maker")) == []
    errors = _errors(replace(appliance, category="sous_vide_cooker"))
    assert errors and all("sous_vide_cooker tasks have 3" in e for e in errors)
    unknown = _errors(replace(appliance, category="hovercraft"))
    assert len(unknown) == 1 and "unknown category 'hovercraft'" in unknown[0]
