"""Settings said by what their name says: a unitless count named DAYS counts days, and silence
said of an appliance with a volume but no sound switch mutes the volume. Models written for
these tests."""

from __future__ import annotations

import pytest

from apbot.model.load import loads_model
from apbot.model.schema import ApplianceModel
from apbot.read.goal import parse_instruction

CROCK = """
appliance: {id: crock_1, category: pickling_crock, name: "Sauer P2 pickling crock", brand: Sauer}
controls:
  - {id: days_key, kind: button, label: "DAYS"}
  - {id: light_key, kind: button, label: "BRIGHT"}
  - {id: vol_key, kind: button, label: "VOLUME"}
variables:
  days: {type: numeric, ranges: [[1, 14, 1], [14, 28, 14]], initial: 3, wrap: true}
  bright: {type: discrete, values: ["20", "60", "100"], label: BRIGHT}
  volume: {type: numeric, ranges: [[0, 5, 1]], initial: 3, label: VOLUME, wrap: true}
actions:
  press_days: {control: days_key}
  press_light: {control: light_key}
  press_vol: {control: vol_key}
features:
  days:
    - {actions: [press_days], variable: days, effect: next}
  bright:
    - {actions: [press_light], variable: bright, effect: next}
  volume:
    - {actions: [press_vol], variable: volume, effect: next}
display:
  idle: "d{days}"
"""


@pytest.fixture(scope="module")
def crock() -> ApplianceModel:
    return loads_model(CROCK)


@pytest.mark.parametrize(
    ("text", "days"),
    [("Ferment for 5 days", 5), ("Two weeks please", 14), ("every 3 days", 3), ("one day", 1)],
)
def test_a_count_named_days_takes_days(crock: ApplianceModel, text: str, days: int) -> None:
    assert parse_instruction(crock, text) == {"days": days}


@pytest.mark.parametrize("text", ["Mute it, 7 days", "7 days, silent please"])
def test_silence_mutes_the_only_volume(crock: ApplianceModel, text: str) -> None:
    assert parse_instruction(crock, text) == {"days": 7, "volume": 0}


BEEPER = """
appliance: {id: timer_1, category: kitchen_timer, name: "Tikk T1 timer", brand: Tikk}
controls:
  - {id: beep_key, kind: button, label: "BEEP"}
  - {id: vol_key, kind: button, label: "VOLUME"}
variables:
  beep: {type: discrete, values: ["off", "on"], label: BEEP}
  volume: {type: numeric, ranges: [[0, 5, 1]], initial: 3, label: VOLUME, wrap: true}
actions:
  press_beep: {control: beep_key}
  press_vol: {control: vol_key}
features:
  beep:
    - {actions: [press_beep], variable: beep, effect: toggle}
  volume:
    - {actions: [press_vol], variable: volume, effect: next}
display:
  idle: "{volume}"
"""


def test_silence_is_a_sound_switch_s_where_there_is_one() -> None:
    assert parse_instruction(loads_model(BEEPER), "Mute it") == {"beep": "off"}


CLOCK = """
appliance: {id: clock_1, category: bedside_clock, name: "Dorm C3 clock", brand: Dorm}
controls:
  - {id: alarm_key, kind: button, label: "ALARM"}
  - {id: vol_key, kind: button, label: "VOLUME"}
variables:
  alarm: {type: discrete, values: ["off", buzz, chime], label: ALARM}
  volume: {type: numeric, ranges: [[0, 9, 1]], initial: 4, label: VOLUME, wrap: true}
actions:
  press_alarm: {control: alarm_key}
  press_vol: {control: vol_key}
features:
  alarm:
    - {actions: [press_alarm], variable: alarm, effect: next}
  volume:
    - {actions: [press_vol], variable: volume, effect: next}
display:
  idle: "{volume}"
"""


def test_silence_of_another_setting_leaves_the_volume() -> None:
    """'silence the alarm' silences the alarm: the volume is not turned down to nothing."""
    clock = loads_model(CLOCK)
    assert "volume" not in parse_instruction(clock, "Silence the alarm")
    assert parse_instruction(clock, "Mute it") == {"volume": 0}
