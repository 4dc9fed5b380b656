"""Helpers for tests: small models written inline."""

from __future__ import annotations

import textwrap

from apbot.model.load import loads_model
from apbot.model.schema import ApplianceModel


def model_from(yaml_text: str, check: bool = True) -> ApplianceModel:
    """A model from an indented YAML snippet (the appliance header is added if missing)."""
    text = textwrap.dedent(yaml_text)
    if "appliance:" not in text:
        text = "appliance: {id: test_unit, category: test}\n" + text
    return loads_model(text, check=check)
