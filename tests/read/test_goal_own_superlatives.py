"""Superlatives made of a setting's own word ("the thickest setting" on THICK ▲ / ▼, "the
brightest" for BRIGHTNESS) pick the top of that setting; "the loudest" is the top of a volume
as "the quietest" is its bottom. A small model written for these tests."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction

FREEZER = """
appliance: {id: slusher_1, category: slush_maker, name: "Ice S-1 slusher", brand: I}
controls:
  - {id: thick_up, kind: button, label: "THICK ▲"}
  - {id: thick_down, kind: button, label: "THICK ▼"}
  - {id: vol_key, kind: button, label: "VOL"}
  - {id: glow_key, kind: button, label: "GLOW"}
variables:
  consistency:
    type: numeric
    ranges: [[1, 7, 1]]
    initial: 4
    show: "T{value}"
  volume:
    type: discrete
    values: ["0", "1", "2", "3"]
    show: {"0": "MUTE", "1": "▮▯▯", "2": "▮▮▯", "3": "▮▮▮"}
  brightness: {type: numeric, ranges: [[1, 5, 1]], initial: 3, wrap: true}
actions:
  press_up: {control: thick_up}
  press_down: {control: thick_down}
  press_vol: {control: vol_key}
  press_glow: {control: glow_key}
features:
  consistency:
    - actions: [press_up, press_down]
      variable: consistency
      effect: {press_up: next, press_down: prev}
  volume:
    - {actions: [press_vol], variable: volume, effect: next}
  brightness:
    - {actions: [press_glow], variable: brightness, effect: next}
"""


def _goal(text: str) -> dict[str, object]:
    return parse_instruction(loads_model(FREEZER), text)


def test_a_superlative_of_the_settings_own_word_is_its_top() -> None:
    assert _goal("the thickest setting") == {"consistency": 7}
    assert _goal("the brightest, please") == {"brightness": 5}


def test_the_loudest_volume_is_its_top() -> None:
    assert _goal("at the loudest volume") == {"volume": "3"}
