"""The client through the real openai package against a scripted server on 127.0.0.1."""

from __future__ import annotations

import json
import logging
from dataclasses import replace
from pathlib import Path

import pytest

from apbot.llm.client import LLMClient, LLMError
from apbot.llm.config import LLMConfig
from apbot.llm.limits import Budget, BudgetSpent
from tests.llm.conftest import SECRET
from tests.llm.scripted import Reply, Script

HELLO = [{"role": "user", "content": "hello"}]


def test_an_answer_and_its_usage(script: Script, config: LLMConfig) -> None:
    script.replies = [Reply("hi there", prompt_tokens=5, completion_tokens=3)]
    answer = LLMClient(config).complete(HELLO)
    assert answer.text == "hi there"
    assert (answer.usage.prompt_tokens, answer.usage.completion_tokens) == (5, 3)
    assert script.count == 1
    sent = script.requests[0]
    assert sent["model"] == "scripted-model"
    assert sent["messages"] == HELLO
    assert sent["temperature"] == 0


def test_a_cached_rerun_makes_no_request(script: Script, config: LLMConfig) -> None:
    script.replies = [Reply("one"), Reply("two")]
    first = LLMClient(config).complete(HELLO)
    again = LLMClient(config).complete(HELLO)  # a new client: a new process, same cache
    assert script.count == 1
    assert again.text == first.text == "one"
    assert again.usage.record() == first.usage.record()  # the records stay identical
    assert again.usage.cached == 1 and again.usage.requests == 0


def test_the_repeat_index_and_the_settings_are_in_the_key(
    script: Script, config: LLMConfig
) -> None:
    script.replies = [Reply("a"), Reply("b"), Reply("c")]
    client = LLMClient(config)
    assert client.complete(HELLO, repeat=0).text == "a"
    assert client.complete(HELLO, repeat=1).text == "b"
    assert client.complete(HELLO, max_tokens=7).text == "c"
    assert client.complete(HELLO, repeat=1).text == "b"
    assert script.count == 3


def test_what_does_not_change_the_answer_is_not_in_the_key(
    script: Script, config: LLMConfig
) -> None:
    script.replies = [Reply("a")]
    LLMClient(config).complete(HELLO)
    other = replace(config, timeout=9.0, retries=0, concurrency=1, backoff=3.0)
    assert LLMClient(other).complete(HELLO).text == "a"
    assert script.count == 1


def test_cache_modes(script: Script, config: LLMConfig) -> None:
    script.replies = [Reply("a"), Reply("b"), Reply("c")]
    assert LLMClient(replace(config, cache="read")).complete(HELLO).text == "a"  # not stored
    assert LLMClient(config).complete(HELLO).text == "b"  # stored
    assert LLMClient(replace(config, cache="read")).complete(HELLO).text == "b"
    assert LLMClient(replace(config, cache="off")).complete(HELLO).text == "c"
    assert script.count == 3


def test_429_and_500_are_retried(script: Script, config: LLMConfig) -> None:
    script.replies = [Reply(status=429), Reply(status=500), Reply(status=503), Reply("done")]
    answer = LLMClient(replace(config, retries=3)).complete(HELLO)
    assert answer.text == "done"
    assert script.count == 4


def test_a_timeout_is_retried_then_reported(script: Script, config: LLMConfig) -> None:
    script.replies = [Reply("late", delay=1.0)] * 3
    with pytest.raises(LLMError, match="timed out after 3 attempt"):
        LLMClient(replace(config, timeout=0.2)).complete(HELLO)
    assert script.count == 3


def test_a_timeout_then_an_answer(script: Script, config: LLMConfig) -> None:
    script.replies = [Reply("late", delay=1.0), Reply("in time")]
    assert LLMClient(replace(config, timeout=0.2)).complete(HELLO).text == "in time"
    assert script.count == 2


def test_a_bad_request_is_not_retried(script: Script, config: LLMConfig) -> None:
    script.replies = [Reply(status=400, error="unknown model"), Reply("never")]
    with pytest.raises(LLMError, match="HTTP 400: unknown model"):
        LLMClient(config).complete(HELLO)
    assert script.count == 1


def test_the_budget_stops_cleanly(script: Script, config: LLMConfig, tmp_path: Path) -> None:
    script.replies = [Reply("a"), Reply("b"), Reply("c")]
    budget = Budget(max_requests=2, path=tmp_path / "budget.json")
    client = LLMClient(config, budget)
    client.complete([{"role": "user", "content": "1"}])
    client.complete([{"role": "user", "content": "1"}])  # cached: costs nothing
    client.complete([{"role": "user", "content": "2"}])
    with pytest.raises(BudgetSpent, match="2 of 2 requests"):
        client.complete([{"role": "user", "content": "3"}])
    assert script.count == 2
    # another process sharing the budget file sees the same spending
    assert Budget(max_requests=2, path=tmp_path / "budget.json").spent()["requests"] == 2


def test_the_key_is_never_in_a_log_the_cache_or_an_error(
    script: Script, config: LLMConfig, caplog: pytest.LogCaptureFixture
) -> None:
    caplog.set_level(logging.DEBUG)  # every logger, the openai and http ones included
    script.replies = [Reply(status=429), Reply("ok"), Reply(status=401, error="bad key")]
    client = LLMClient(config)
    client.complete(HELLO)
    with pytest.raises(LLMError) as failure:
        client.complete([{"role": "user", "content": "again"}])
    assert script.headers[0]["authorization"] == f"Bearer {SECRET}"  # it was sent, there only
    assert caplog.records  # the retry was logged
    assert SECRET not in caplog.text
    assert SECRET not in str(failure.value)
    assert SECRET not in repr(config) and SECRET not in repr(client.__dict__)
    for path in config.cache_dir.rglob("*"):
        if path.is_file():
            assert SECRET not in path.read_text(encoding="utf-8", errors="replace")
    assert all(SECRET not in json.dumps(body) for body in script.requests)


def test_a_missing_key_is_named(config: LLMConfig, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("APBOT_TEST_KEY")
    with pytest.raises(ValueError, match="set APBOT_TEST_KEY"):
        LLMClient(config).complete(HELLO)
