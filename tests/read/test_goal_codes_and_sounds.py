"""A lock's code said digit by digit, its sound said loud or denied, and an automatic
relock switched off. Small models written for these tests."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction

LOCK = """
appliance: {id: lock_9, category: smart_lock, name: "Bolt L-9", brand: B}
controls:
  - {id: code_key, kind: button, label: "CODE"}
  - {id: up_key, kind: button, label: "▲"}
  - {id: auto_key, kind: button, label: "AUTO"}
  - {id: vol_key, kind: button, label: "VOL"}
variables:
  code:
    type: numeric
    ranges: [[1000, 9999, 1]]
    initial: 1234
    wrap: true
    label: "CODE"
  relock:
    type: numeric
    unit: s
    ranges: [[0, 60, 30], [60, 180, 120]]
    initial: 30
    wrap: true
    label: "AUTO"
  volume:
    type: discrete
    values: [mute, low, high]
    initial: low
actions:
  press_code: {control: code_key}
  press_up: {control: up_key}
  press_auto: {control: auto_key}
  press_vol: {control: vol_key}
features:
  code:
    - {actions: [press_code]}
    - {actions: [press_up], variable: code, effect: next}
  relock:
    - {actions: [press_auto], variable: relock, effect: next}
  volume:
    - {actions: [press_vol], variable: volume, effect: next}
"""


def test_a_code_said_digit_by_digit() -> None:
    model = loads_model(LOCK)
    assert parse_instruction(model, "new code 5 2 0 7") == {"code": 5207}
    assert parse_instruction(model, "code two-nine-zero-one") == {"code": 2901}


def test_loud_and_denied_sound() -> None:
    model = loads_model(LOCK)
    assert parse_instruction(model, "loud beeps please") == {"volume": "high"}
    assert parse_instruction(model, "no beeping at night") == {"volume": "mute"}
    assert parse_instruction(model, "sound off") == {"volume": "mute"}


def test_an_automatic_setting_switched_off_is_zero() -> None:
    model = loads_model(LOCK)
    assert parse_instruction(model, "relock off") == {"relock": 0}
    assert parse_instruction(model, "turn off the relock") == {"relock": 0}
    assert parse_instruction(model, "relock after a minute") == {"relock": 60}
