"""A beeper is the buzzer: "switch the beeper off", "the door beeper off" (a word real users
and manuals use for the sound switch). Checked on a toaster-like grill written for these tests."""

from __future__ import annotations

import pytest

from apbot.model.load import loads_model
from apbot.model.schema import ApplianceModel
from apbot.read.goal import parse_instruction

GRILL = """
appliance: {id: grill_1, category: sandwich_grill, name: "Crisp G2 sandwich grill", brand: C}
controls:
  - {id: shade_button, kind: button, label: "SHADE"}
  - {id: sound_button, kind: button, label: "SOUND"}
variables:
  shade:
    type: discrete
    values: ["1", "2", "3"]
  sound:
    type: discrete
    values: ["on", "off"]
actions:
  press_shade: {control: shade_button}
  press_sound: {control: sound_button}
features:
  shade:
    - {actions: [press_shade], variable: shade, effect: next}
  sound:
    - {actions: [press_sound], variable: sound, effect: toggle}
display:
  idle: ""
"""


@pytest.fixture(scope="module")
def grill() -> ApplianceModel:
    return loads_model(GRILL)


@pytest.mark.parametrize(
    "text", ["Shade 2 and switch the beeper off.", "Shade 3, with the end beeper off please"]
)
def test_the_beeper_is_the_sound_switch(grill: ApplianceModel, text: str) -> None:
    assert parse_instruction(grill, text)["sound"] == "off"
