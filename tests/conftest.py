"""Shared fixtures: the bundled example models."""

from __future__ import annotations

import pytest
from hypothesis import settings

from apbot.examples import load_example
from apbot.model.schema import ApplianceModel


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
