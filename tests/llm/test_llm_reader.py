"""The staged LLM reader through the real client against a scripted server."""

from __future__ import annotations

import json
from typing import Any

import pytest

from apbot.bench.suite import SuiteAppliance, bundled_suite_dir, load_appliance
from apbot.llm.client import LLMClient
from apbot.llm.config import LLMConfig
from apbot.read import read_manual
from apbot.read.llm_reader import llm_read_manual
from apbot.sim.checks import check_model
from tests.llm.scripted import Reply, Script

CONTROLS = {
    "controls": [
        {"action": "press_temp", "label": "TEMP", "does": "chooses the temperature"},
        {"action": "press_warm", "label": "KEEP WARM", "does": "keeps the water warm"},
        {"action": "press_start", "label": "START/STOP", "does": "starts or stops heating"},
    ]
}
VARIABLES = {
    "variables": [
        {"name": "temperature", "kind": "number", "low": "40", "high": "100", "step": "10"},
        {"name": "keep_warm", "kind": "switch"},
        {"name": "heating", "kind": "switch"},
    ]
}


def _feature(name: str, variable: str, action: str, effect: str) -> dict[str, Any]:
    presses = [{"action": action, "effect": effect}]
    return {"name": name, "steps": [{"variable": variable, "presses": presses}]}


WRONG = {
    "features": [
        _feature("set_temperature", "temp", "press_temp", "next"),  # no such variable
        _feature("keep_warm", "keep_warm", "press_warm", "toggle"),
        _feature("start", "heating", "press_start", "toggle"),
    ]
}
RIGHT = {
    "features": [
        _feature("set_temperature", "temperature", "press_temp", "next"),
        *WRONG["features"][1:],
    ]
}


@pytest.fixture(scope="module")
def kettle() -> SuiteAppliance:
    return load_appliance(bundled_suite_dir() / "kettle_1")


def _stage(body: dict[str, Any]) -> str:
    text = body["messages"][1]["content"]
    return next(s for s in ("Stage 1", "Stage 2", "Stage 3") if s in text)


def test_from_scratch_each_stage_checked_and_errors_fed_back(
    script: Script, config: LLMConfig, kettle: SuiteAppliance
) -> None:
    answers = {
        "Stage 1": [CONTROLS],
        "Stage 2": [{"variables": [{"name": "temperature", "kind": "number"}]}, VARIABLES],
        "Stage 3": [WRONG, RIGHT],
    }

    def route(body: dict[str, Any]) -> Reply:
        return Reply(json.dumps(answers[_stage(body)].pop(0)))

    script.router = route
    reading = llm_read_manual(
        kettle.manual, list(kettle.model.actions), LLMClient(config), seeded=False
    )
    model = reading.model
    assert reading.fallbacks == []
    assert set(model.variables) == {"temperature", "keep_warm", "heating"}
    assert model.features["set_temperature"][0].variable == "temperature"
    assert [c.label for c in model.controls if c.label == "KEEP WARM"]
    assert not [p for p in check_model(model) if p.severity == "error"]
    assert script.count == 5 and reading.usage.calls == 5
    feedback = [r["messages"][-1]["content"] for r in script.requests if len(r["messages"]) > 2]
    assert any("low is missing" in text for text in feedback)
    assert any("temp" in text and "features" in text for text in feedback)
    # the manual is the start of every request: one prefix for the server's prompt cache
    firsts = {r["messages"][1]["content"][:2000] for r in script.requests}
    assert len(firsts) == 1 and kettle.manual[:200] in next(iter(firsts))
    assert "draft" not in script.requests[0]["messages"][1]["content"]


def test_seeded_an_unchanged_draft_keeps_the_offline_model(
    script: Script, config: LLMConfig, kettle: SuiteAppliance
) -> None:
    def echo(body: dict[str, Any]) -> Reply:
        text = body["messages"][1]["content"]
        return Reply(text.split("Correct and complete it:\n", 1)[1].split("\n\nReply with")[0])

    script.router = echo
    actions = list(kettle.model.actions)
    reading = llm_read_manual(kettle.manual, actions, LLMClient(config))
    offline = read_manual(kettle.manual, actions).model
    assert reading.model.variables == offline.variables
    assert reading.model.features == offline.features
    assert script.count == 3


def test_a_stage_without_a_valid_answer_falls_back(
    script: Script, config: LLMConfig, kettle: SuiteAppliance
) -> None:
    script.router = lambda body: Reply("not json")
    actions = list(kettle.model.actions)
    reading = llm_read_manual(kettle.manual, actions, LLMClient(config), seeded=False)
    assert reading.fallbacks == ["controls", "variables", "features"]
    assert reading.model.variables == read_manual(kettle.manual, actions).model.variables
    assert "no valid answer" in reading.report.render()
    assert reading.variables_read is None  # no variables answer: nothing of the LLM's to score


def test_the_variables_stage_is_kept_for_scoring_when_the_model_falls_back(
    script: Script, config: LLMConfig, kettle: SuiteAppliance
) -> None:
    """Features that never fit: the model is the offline one (its scores are the offline
    reader's), and the LLM's own variables stay available to be scored alone."""
    answers = {"Stage 1": [CONTROLS], "Stage 2": [VARIABLES], "Stage 3": [WRONG] * 4}

    def route(body: dict[str, Any]) -> Reply:
        return Reply(json.dumps(answers[_stage(body)].pop(0)))

    script.router = route
    actions = list(kettle.model.actions)
    reading = llm_read_manual(kettle.manual, actions, LLMClient(config), seeded=False)
    assert "features" in reading.fallbacks
    assert reading.variables_read is not None
    assert set(reading.variables_read.variables) == {"temperature", "keep_warm", "heating"}
    assert reading.variables_read.variables["temperature"].type == "numeric"


def test_eval_reader_scores_the_variables_stage_apart(
    script: Script, config: LLMConfig, kettle: SuiteAppliance
) -> None:
    from apbot.cli_llm import evaluate_reader

    answers = {"Stage 1": [CONTROLS], "Stage 2": [VARIABLES], "Stage 3": [WRONG] * 4}
    script.router = lambda body: Reply(json.dumps(answers[_stage(body)].pop(0)))
    result, extra = evaluate_reader(config, [kettle], from_scratch=True)
    assert result.appliances == 1
    assert "features" in extra["fallbacks"]["kettle_1"]
    stage = extra["variables_stage"]
    assert stage["appliances"] == 1
    assert set(stage) == {"appliances", "variables", "discrete_values", "numeric_ranges"}
    assert stage["variables"] == {"precision": 1.0, "recall": 1.0}  # the three, named right
