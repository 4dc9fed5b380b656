"""Fixtures: a scripted server and a client configured for it (fast timeouts and backoff)."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest

from apbot.llm.config import LLMConfig
from tests.llm.scripted import Script, serving

SECRET = "sk-test-DO-NOT-LEAK-7f3a9c"


@pytest.fixture
def script() -> Script:
    return Script()


@pytest.fixture
def base_url(script: Script) -> Iterator[str]:
    with serving(script) as url:
        yield url


@pytest.fixture
def config(base_url: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> LLMConfig:
    monkeypatch.setenv("APBOT_TEST_KEY", SECRET)
    return LLMConfig(
        "server",
        "scripted-model",
        base_url,
        key_env="APBOT_TEST_KEY",
        timeout=0.5,
        retries=2,
        backoff=0.01,
        cache_dir=tmp_path / "cache",
        schema_mode="json_schema",
    )
