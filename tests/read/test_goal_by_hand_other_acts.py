""" "Myself" on a read belief (no ``depends_on``) means the MANUAL case only when the user sets
or picks something by hand: checking, cleaning or topping up a part of the appliance oneself
is not choosing its setting. The same holds where the model says the mister depends on the
mode. Checked on a small plant-lamp model written for these tests."""

from __future__ import annotations

import pytest

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction

LAMP = """
appliance: {id: lamp_1, category: grow_lamp, name: "Sprout GL-2 grow lamp", brand: S}
controls:
  - {id: mode_button, kind: button, label: "MODE"}
  - {id: glow_button, kind: button, label: "GLOW"}
  - {id: mister_button, kind: button, label: "MISTER"}
variables:
  mode:
    type: discrete
    values: [herbs, flowers, manual]
  glow:
    type: numeric
    ranges: [[1, 5, 1]]
  mister:
    type: numeric
    ranges: [[0, 3, 1]]
actions:
  press_mode: {control: mode_button}
  press_glow: {control: glow_button}
  press_mister: {control: mister_button}
features:
  mode:
    - {actions: [press_mode], variable: mode, effect: next}
  glow:
    - {actions: [press_glow], variable: glow, effect: next}
  mister:
    - {actions: [press_mister], variable: mister, effect: next}
"""


@pytest.mark.parametrize(
    "text",
    [
        "I'll refill the mister myself.",
        "I'll wipe the glow panel myself.",
        "I'll check the mister myself.",
    ],
)
def test_doing_something_else_by_hand_is_no_manual_mode(text: str) -> None:
    assert parse_instruction(loads_model(LAMP), text).get("mode") is None


@pytest.mark.parametrize(
    "text", ["I'll adjust the glow myself - glow 4", "My own mister level of 2, please"]
)
def test_setting_it_by_hand_is_still_manual(text: str) -> None:
    assert parse_instruction(loads_model(LAMP), text).get("mode") == "manual"


LINKED = LAMP.replace(
    "  mister:\n    type: numeric\n    ranges: [[0, 3, 1]]",
    "  mister:\n    type: numeric\n    depends_on: mode\n    cases:\n"
    "      manual: {ranges: [[1, 3, 1]], initial: 1}",
)


def test_refilling_a_linked_setting_is_no_manual_mode() -> None:
    model = loads_model(LINKED)
    assert parse_instruction(model, "I'll refill the mister myself.").get("mode") is None
    assert parse_instruction(model, "I'll pick the mister myself - 2").get("mode") == "manual"
