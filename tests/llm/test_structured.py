"""Structured answers through the real client: re-asks with the error, refusals, length stops."""

from __future__ import annotations

import json
from dataclasses import replace
from typing import Literal

import pytest
from pydantic import BaseModel

from apbot.llm.client import LLMClient
from apbot.llm.config import LLMConfig
from apbot.llm.structured import StructuredError, ask, repeated_tail
from tests.llm.scripted import Reply, Script


class Setting(BaseModel):
    name: str
    value: int
    unit: Literal["min", "h"] = "min"


MESSAGES = [{"role": "system", "content": "You read settings."}, {"role": "user", "content": "x"}]


def test_a_malformed_answer_is_reasked_with_its_error_then_accepted(
    script: Script, config: LLMConfig
) -> None:
    script.replies = [
        Reply('{"name": "timer", "value": "ten"}'),  # not an integer
        Reply('{"name": "timer", "value": 10}'),
    ]
    answer = ask(LLMClient(config), MESSAGES, Setting)
    assert answer.value == Setting(name="timer", value=10)
    assert answer.attempts == 2 and script.count == 2
    assert answer.usage.prompt_tokens == 22 and answer.usage.calls == 2
    second = script.requests[1]["messages"]
    assert second[-2] == {"role": "assistant", "content": '{"name": "timer", "value": "ten"}'}
    assert "value: Input should be a valid integer" in second[-1]["content"]
    # the strict schema went along
    sent = script.requests[0]["response_format"]
    assert sent["type"] == "json_schema" and sent["json_schema"]["strict"] is True
    assert sent["json_schema"]["schema"]["required"] == ["name", "value", "unit"]


def test_not_json_and_a_semantic_error_are_fed_back(script: Script, config: LLMConfig) -> None:
    script.replies = [
        Reply("the timer is ten minutes"),
        Reply('```json\n{"name": "timer", "value": 900}\n```'),
        Reply('{"name": "timer", "value": 90}'),
    ]

    def check(setting: Setting) -> list[str]:
        return [f"value {setting.value} is over 120"] if setting.value > 120 else []

    answer = ask(LLMClient(config), MESSAGES, Setting, check=check)
    assert answer.value.value == 90
    assert answer.feedback[0][0].startswith("the answer is not valid JSON")
    assert answer.feedback[1] == ["value 900 is over 120"]


def test_at_most_three_rounds_of_feedback(script: Script, config: LLMConfig) -> None:
    script.replies = [Reply("{}")] * 6
    with pytest.raises(StructuredError, match="after 4 attempt") as failure:
        ask(LLMClient(config), MESSAGES, Setting)
    assert script.count == 4
    assert failure.value.usage.calls == 4


def test_a_refusal_ends_the_question(script: Script, config: LLMConfig) -> None:
    script.replies = [Reply(refusal="I cannot help with that")]
    with pytest.raises(StructuredError, match="refused: I cannot help"):
        ask(LLMClient(config), MESSAGES, Setting)
    assert script.count == 1


def test_a_length_stop_is_asked_again_with_more_room(script: Script, config: LLMConfig) -> None:
    script.replies = [Reply('{"name": "tim', finish="length"), Reply('{"name": "t", "value": 1}')]
    answer = ask(LLMClient(config), MESSAGES, Setting, max_tokens=50)
    assert answer.value.value == 1
    assert [r["max_tokens"] for r in script.requests] == [50, 100]
    assert "cut off at 50 tokens" in script.requests[1]["messages"][-1]["content"]


def test_a_loop_cut_off_is_named_and_asked_again_with_the_same_room(
    script: Script, config: LLMConfig
) -> None:
    looping = '{"name": "timer", "values": [' + '"," , ' * 200
    script.replies = [
        Reply(looping, finish="length"),
        Reply(looping, finish="length"),
        Reply('{"name": "t", "value": 1}'),
    ]
    answer = ask(LLMClient(config), MESSAGES, Setting, max_tokens=50)
    assert answer.value.value == 1
    assert [r["max_tokens"] for r in script.requests] == [50, 50, 50]  # no longer loops
    said = script.requests[1]["messages"]
    assert "repeated" in said[-1]["content"] and "cut off at 50 tokens" in said[-1]["content"]
    shown = said[-2]["content"]
    assert shown.startswith('{"name": "timer", "values": [') and len(shown) < 80


def test_repeated_tail_finds_a_loop_and_only_a_loop() -> None:
    text = '{"a": "FRONT", "b": [' + '"," , ' * 60
    start, unit = repeated_tail(text)  # type: ignore[misc]
    assert text[start:].startswith(unit) and len(unit) == 6
    assert text[:start].startswith('{"a": "FRONT", "b": [')
    counting = '{"values": [' + ", ".join(f'"{i}"' for i in range(200))
    assert repeated_tail(counting) is None
    assert repeated_tail('{"name": "tim') is None
    assert repeated_tail("x" * 100) is None  # too short a span to call a loop


def test_a_server_without_json_schema_gets_json_object(script: Script, config: LLMConfig) -> None:
    script.replies = [
        Reply(status=500, error="response_format type json_schema is not supported"),
        Reply('{"name": "timer", "value": 5}'),
    ]
    answer = ask(LLMClient(config), MESSAGES, Setting)
    assert answer.value.value == 5
    assert script.count == 2
    second = script.requests[1]["response_format"]
    assert second["type"] == "json_object" and "properties" in second["schema"]
    assert second["schema"]["required"] == ["name", "value", "unit"]  # one order for a grammar


def test_schema_in_the_prompt_mode(script: Script, config: LLMConfig) -> None:
    script.replies = [Reply('Sure: {"name": "timer", "value": 5}')]
    answer = ask(LLMClient(replace(config, schema_mode="prompt")), MESSAGES, Setting)
    assert answer.value.value == 5
    sent = script.requests[0]
    assert "response_format" not in sent
    schema = json.dumps(Setting.model_json_schema(), separators=(",", ":"))
    assert schema in sent["messages"][-1]["content"]
    assert sent["messages"][0] == MESSAGES[0]  # the shared prefix is left as it was
