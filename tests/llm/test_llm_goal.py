"""The LLM goal reader through the real client against a scripted server."""

from __future__ import annotations

import json
from dataclasses import replace

import pytest

from apbot.bench.suite import SuiteAppliance, bundled_suite_dir, load_appliance
from apbot.llm.adapter import grammar_schema, strict_schema
from apbot.llm.client import LLMClient
from apbot.llm.config import LLMConfig
from apbot.llm.structured import StructuredError
from apbot.read.llm_goal import goal_list_schema, goal_schema, llm_parse_instruction, offline_hint
from tests.llm.scripted import Reply, Script


def pairs(**goal: str) -> str:
    """A list-form answer naming ``goal``'s settings."""
    return json.dumps({"settings": [{"setting": k, "value": v} for k, v in goal.items()]})


@pytest.fixture(scope="module")
def kettle() -> SuiteAppliance:
    return load_appliance(bundled_suite_dir() / "kettle_1")


def test_the_schema_holds_the_beliefs_values(kettle: SuiteAppliance) -> None:
    schema = goal_schema(kettle.model).model_json_schema()
    temperature = schema["properties"]["temperature"]["anyOf"]
    assert {"type": "null"} in temperature
    assert "80" in temperature[0]["enum"] and "81" not in temperature[0]["enum"]
    assert schema["properties"]["heating"]["anyOf"][0]["enum"] == ["off", "on"]


def test_the_list_schema_ties_each_value_to_its_setting(kettle: SuiteAppliance) -> None:
    schema = goal_list_schema(kettle.model).model_json_schema()
    items = schema["properties"]["settings"]
    assert items["maxItems"] == 3
    temperature = schema["$defs"]["Setting0"]["properties"]
    assert temperature["setting"]["const"] == "temperature"
    assert "80" in temperature["value"]["enum"] and "on" not in temperature["value"]["enum"]
    assert schema["$defs"]["Setting2"]["properties"]["value"]["enum"] == ["off", "on"]
    for sent in (strict_schema(schema), grammar_schema(schema)):  # strict mode takes anyOf only
        union = sent["properties"]["settings"]["items"]
        assert "oneOf" not in union and "discriminator" not in union
        assert len(union["anyOf"]) == 3
        assert sent["$defs"]["Setting0"]["required"] == ["setting", "value"]


def test_a_list_answer_names_only_what_the_request_asks(
    script: Script, config: LLMConfig, kettle: SuiteAppliance
) -> None:
    script.replies = [Reply(pairs(temperature="80", heating="on"))]
    read = llm_parse_instruction(
        kettle.model, "Heat the water to 80 degrees for my green tea.", LLMClient(config)
    )
    assert read.goal == {"temperature": 80, "heating": "on"}
    sent = script.requests[0]
    assert sent["response_format"]["json_schema"]["schema"]["properties"]["settings"]
    assert "leave the others out" in sent["messages"][1]["content"]
    assert '{"setting": "mode", "value": "eco"}' in sent["messages"][1]["content"]


def test_a_list_value_outside_its_settings_domain_is_fed_back(
    script: Script, config: LLMConfig, kettle: SuiteAppliance
) -> None:
    script.replies = [
        Reply(pairs(temperature="80", heating="80")),
        Reply(pairs(temperature="80", heating="on")),
    ]
    read = llm_parse_instruction(kettle.model, "Heat it to 80 degrees.", LLMClient(config))
    assert read.goal == {"temperature": 80, "heating": "on"} and read.attempts == 2
    fed_back = script.requests[1]["messages"][-1]["content"]
    assert "settings.0.heating.value" in fed_back.replace("settings.1", "settings.0")
    assert "'off' or 'on'" in fed_back
    assert "Setting0" not in fed_back  # the error names its own setting, not every alternative


def test_a_setting_listed_twice_is_fed_back(
    script: Script, config: LLMConfig, kettle: SuiteAppliance
) -> None:
    twice = {
        "settings": [
            {"setting": "temperature", "value": "80"},
            {"setting": "temperature", "value": "90"},
        ]
    }
    script.replies = [Reply(json.dumps(twice)), Reply(pairs(temperature="90"))]
    read = llm_parse_instruction(kettle.model, "90 degrees please", LLMClient(config))
    assert read.goal == {"temperature": 90}
    assert "temperature is listed more than once" in script.requests[1]["messages"][-1]["content"]


def test_the_list_form_goes_to_a_grammar_server_as_anyof(
    script: Script, config: LLMConfig, kettle: SuiteAppliance
) -> None:
    script.replies = [Reply(pairs(keep_warm="on"))]
    grammar = replace(config, schema_mode="json_object")
    read = llm_parse_instruction(kettle.model, "Keep it warm", LLMClient(grammar))
    assert read.goal == {"keep_warm": "on"}
    sent = script.requests[0]["response_format"]
    assert sent["type"] == "json_object"
    assert "anyOf" in sent["schema"]["properties"]["settings"]["items"]


def test_an_unknown_form_is_refused(config: LLMConfig, kettle: SuiteAppliance) -> None:
    with pytest.raises(ValueError, match="goal form 'table'"):
        llm_parse_instruction(kettle.model, "Tea", LLMClient(config), form="table")  # type: ignore[arg-type]


def test_a_value_outside_the_domain_is_fed_back(
    script: Script, config: LLMConfig, kettle: SuiteAppliance
) -> None:
    script.replies = [
        Reply('{"temperature": "120", "keep_warm": null, "heating": "on"}'),
        Reply('{"temperature": "80", "keep_warm": null, "heating": "on"}'),
    ]
    read = llm_parse_instruction(
        kettle.model,
        "Heat the water to 80 degrees for my green tea.",
        LLMClient(config),
        form="object",
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
        llm_parse_instruction(
            kettle.model, "Make tea", LLMClient(config), use_hint=False, form="object"
        )
    assert script.count == 4
    script.replies = [Reply('{"settings": []}')] * 4
    with pytest.raises(StructuredError, match="no setting is set"):
        llm_parse_instruction(kettle.model, "Make tea", LLMClient(config), use_hint=False)
    assert script.count == 8


def test_the_hint_reads_with_the_manual(script: Script, config: LLMConfig) -> None:
    """The offline parser names coded values from the manual (menu 3 is whole wheat); the
    hint the LLM gets must be that reading, not a weaker one without the manual."""
    bread = load_appliance(bundled_suite_dir() / "bread_maker_1")
    instruction = bread.tasks[1].instruction  # a whole wheat loaf: menu 3 in this manual
    script.replies = [
        Reply(pairs(menu="3", loaf_size="1000", crust="light", delay="08:00:00", running="on"))
    ]
    read = llm_parse_instruction(bread.model, instruction, LLMClient(config), manual=bread.manual)
    assert '"menu": "3"' in read.hint
    assert '"menu": "3"' in script.requests[0]["messages"][1]["content"]
    # without the manual the parser cannot name the menu: the case this guards
    assert '"menu"' not in offline_hint(bread.model, instruction)
