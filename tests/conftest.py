"""Shared fixtures: the bundled example models; a guard against methods left registered."""

from __future__ import annotations

from collections.abc import Iterator

import pytest
from hypothesis import settings

import apbot.bench.runner  # noqa: F401  registers every real method (llm-policy-image too) first
from apbot.agent.registry import methods
from apbot.examples import load_example
from apbot.model.schema import ApplianceModel


@pytest.fixture(scope="module", autouse=True)
def registry_unchanged() -> Iterator[None]:
    """A test module that registers fake methods must remove them: left behind, they would run
    under every later default ``--methods`` in the same process."""
    before = sorted(methods())
    yield
    after = sorted(methods())
    assert after == before, f"methods left registered by this module: {set(after) - set(before)}"


@pytest.fixture(scope="session", autouse=True)
def read_cache(tmp_path_factory: pytest.TempPathFactory) -> Iterator[None]:
    """Read beliefs are cached in a directory of the test session's, not the user's."""
    import os

    before = os.environ.get("APBOT_CACHE_DIR")
    os.environ["APBOT_CACHE_DIR"] = str(tmp_path_factory.mktemp("apbot-cache"))
    yield
    if before is None:
        os.environ.pop("APBOT_CACHE_DIR", None)
    else:
        os.environ["APBOT_CACHE_DIR"] = before


LLM_VARIABLES = (
    "APBOT_LLM",
    "APBOT_LLM_CACHE",
    "APBOT_LLM_KEY_ENV",
    "APBOT_LLM_BUDGET_FILE",
    "APBOT_LLM_MAX_REQUESTS",
    "APBOT_LLM_MAX_TOKENS_TOTAL",
)


@pytest.fixture(autouse=True)
def no_llm_configured(monkeypatch: pytest.MonkeyPatch) -> None:
    """Tests run offline whatever the developer's shell says, and a test whose command sets
    ``APBOT_LLM`` (``--llm`` writes it for the workers) leaves it unset for the next."""
    for name in LLM_VARIABLES:
        monkeypatch.setenv(name, "")


@pytest.fixture(scope="session")
def microwave() -> ApplianceModel:
    return load_example("microwave_keypad")


@pytest.fixture(scope="session")
def washer() -> ApplianceModel:
    return load_example("washing_machine")


@pytest.fixture(scope="session")
def toaster() -> ApplianceModel:
    return load_example("toaster_oven_dial")


# `pytest --hypothesis-profile=long` (or APBOT_FUZZ=long): the fuzzers try many more inputs
# (see tests/fuzz.py); every other test keeps its own settings.
settings.register_profile("long", deadline=None)
