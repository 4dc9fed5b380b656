"""Shared fixtures: small models written inline, and the bundled examples."""

from __future__ import annotations

import textwrap

import pytest

from apbot.examples import load_example
from apbot.model.load import loads_model
from apbot.model.schema import ApplianceModel


def model_from(yaml_text: str, check: bool = True) -> ApplianceModel:
    """A model from an indented YAML snippet (the appliance header is added if missing)."""
    text = textwrap.dedent(yaml_text)
    if "appliance:" not in text:
        text = "appliance: {id: test_unit, category: test}\n" + text
    return loads_model(text, check=check)


@pytest.fixture(scope="session")
def microwave() -> ApplianceModel:
    return load_example("microwave_keypad")


@pytest.fixture(scope="session")
def washer() -> ApplianceModel:
    return load_example("washing_machine")


@pytest.fixture(scope="session")
def toaster() -> ApplianceModel:
    return load_example("toaster_oven_dial")
