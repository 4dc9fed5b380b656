"""Fixtures shared by the goal-parser tests of tests/read: the grow light and the rower models
(tests/read/goal_kind_models.py), each loaded once per module that asks for it."""

from __future__ import annotations

import pytest

from apbot.model.load import loads_model
from apbot.model.schema import ApplianceModel

from .goal_kind_models import GROW_LIGHT, ROWER


@pytest.fixture(scope="module")
def light() -> ApplianceModel:
    """The seedling grow light: ON TIME / OFF TIME, a percent level, a heat mat, a soak time."""
    return loads_model(GROW_LIGHT)


@pytest.fixture(scope="module")
def rower() -> ApplianceModel:
    """The rowing machine: one unitless goal figure whose meaning its GOAL kind gives, a drag."""
    return loads_model(ROWER)
