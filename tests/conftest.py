"""Shared fixtures: the bundled example models."""

from __future__ import annotations

import pytest

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
