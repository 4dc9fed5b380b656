"""The LLM goal reader through the real client against a scripted server."""

from __future__ import annotations

import json

import pytest

from apbot.bench.suite import SuiteAppliance, bundled_suite_dir, load_appliance
from apbot.llm.client import LLMClient
from apbot.llm.config import LLMConfig
from apbot.llm.structured import StructuredError
from apbot.read.llm_goal import goal_schema, llm_parse_instruction, offline_hint
from tests.llm.scripted import Reply, Script


@pytest.fixture(scope="module")
def kettle() -> SuiteAppliance:
    return load_appliance(bundled_suite_dir() / "kettle_1")


def test_the_schema_holds_the_beliefs_values(kettle: SuiteAppliance) -> None:
    schema = goal_schema(kettle.model).model_json_schema()
    temperature = schema["properties"]["temperature"]["anyOf"]
    assert {"type": "null"} in temperature
    assert "80" in temperature[0]["enum"] and "81" not in temperature[0]["enum"]
    assert schema["properties"]["heating"]["anyOf"][0]["enum"] == ["off", "on"]


def test_a_value_outside_the_domain_is_fed_back(
    script: Script, config: LLMConfig, kettle: SuiteAppliance
) -> None:
    script.replies = [
        Reply('{"temperature": "120", "keep_warm": null, "heating": "on"}'),
        Reply('{"temperature": "80", "keep_warm": null, "heating": "on"}'),
    ]
    read = llm_parse_instruction(
        kettle.model, "Heat the water to 80 degrees for my green tea.", LLMClient(config)
    )
    assert read.goal == {"temperature": 80, "heating": "on"}
    assert read.attempts == 2
    user = script.requests[0]["messages"][1]["content"]
    assert "request: Heat the water to 80 degrees" in user
    assert "A rule-based parser read" in user and '"temperature": "80"' in user
    assert "temperature" in script.requests[1]["messages"][-1]["content"]  # the error went back


def test_nothing_chosen_is_an_error_fed_back(
    script: Script, config: LLMConfig, kettle: SuiteAppliance
) -> None:
    empty = json.dumps({"temperature": None, "keep_warm": None, "heating": None})
    script.replies = [Reply(empty)] * 4
    with pytest.raises(StructuredError, match="no setting is set"):
        llm_parse_instruction(kettle.model, "Make tea", LLMClient(config), use_hint=False)
    assert script.count == 4


def test_the_hint_reads_with_the_manual(script: Script, config: LLMConfig) -> None:
    """The offline parser names coded values from the manual (menu 3 is whole wheat); the
    hint the LLM gets must be that reading, not a weaker one without the manual."""
    bread = load_appliance(bundled_suite_dir() / "bread_maker_1")
    instruction = bread.tasks[1].instruction  # a whole wheat loaf: menu 3 in this manual
    script.replies = [
        Reply(
            '{"power": null, "menu": "3", "loaf_size": "1000", "crust": "light", '
            '"delay": "08:00:00", "running": "on"}'
        )
    ]
    read = llm_parse_instruction(bread.model, instruction, LLMClient(config), manual=bread.manual)
    assert '"menu": "3"' in read.hint
    assert '"menu": "3"' in script.requests[0]["messages"][1]["content"]
    # without the manual the parser cannot name the menu: the case this guards
    assert '"menu"' not in offline_hint(bread.model, instruction)
