"""A power key whose hold has a job of its own in its legend (a setting it switches, a unit it
flips) rather than switching off: each rule on a small manual of our own words."""

from __future__ import annotations

from apbot.model.validate import check_model
from apbot.read import read_manual

# a patio heater: the power key held switches a setting of its own
HEATER = """
Solara PH-2 patio heater

Keys

  ⏻        touch: on / off
           hold 3 s: flame guard on / off

  ▲        warmer
  ▼        cooler

The heat goes from 1 to 5.
"""
HEATER_ACTIONS = ["press_power", "hold_power", "press_up", "press_down"]

# a seed germinator: the power key held while off flips the temperature unit
GERMINATOR = """
Sprouta SG-1 seed germinator

| No. | Key | What it does |
|---|---|---|
| 1 | ⏻ | Touch: on / off. Hold 3 seconds while OFF: °C / °F. |
| 2 | ▲ / ▼ | Temperature up / down. |

The temperature goes from 18 °C to 35 °C in steps of 1 °C.
"""
GERMINATOR_ACTIONS = ["press_power", "hold_power", "press_up", "press_down"]

# a fan whose power key is held to switch off: still the power
FAN = """
Breeza DF-1 desk fan

  ⏻        touch: on
           hold 2 s: off
  SPEED    next speed: LOW → MID → HIGH → LOW
"""
FAN_ACTIONS = ["press_power", "hold_power", "press_speed"]


def _feature_of(model, action: str):  # type: ignore[no-untyped-def]
    return next(
        (step for steps in model.features.values() for step in steps if action in step.actions),
        None,
    )


def test_a_power_hold_that_switches_a_setting_toggles_that_setting() -> None:
    model = read_manual(HEATER, HEATER_ACTIONS).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    step = _feature_of(model, "hold_power")
    assert step is not None and step.variable == "flame_guard"
    assert model.variables["flame_guard"].values == ["off", "on"]


def test_a_power_hold_that_flips_the_unit_while_off_is_the_unit() -> None:
    model = read_manual(GERMINATOR, GERMINATOR_ACTIONS).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    step = _feature_of(model, "hold_power")
    assert step is not None and step.variable == "unit"
    assert model.variables["unit"].values == ["°c", "°f"]
    off = next(g for g in model.guards if g.name == "power off")
    assert "hold_power" in off.only  # "while OFF": the one key besides power that works then


def test_a_power_hold_that_switches_off_stays_the_power() -> None:
    model = read_manual(FAN, FAN_ACTIONS).model
    step = _feature_of(model, "hold_power")
    assert step is not None and step.variable == "power"


def test_a_power_hold_that_switches_on_and_off_by_a_verb_or_a_lock_stays_the_power() -> None:
    # "switch on / off" names no setting, "childlock" is the lock: both leave the power its hold
    for job in ("switch on / off", "turn on / off", "childlock on / off"):
        manual = HEATER.replace("flame guard on / off", job)
        step = _feature_of(read_manual(manual, HEATER_ACTIONS).model, "hold_power")
        assert step is not None and step.variable == "power", job


# a fan whose legend holds ⏻ to switch off, and a sentence elsewhere holds ⏻ with ▲ for the sound
TWO_KEY_FAN = """
Breeza DF-2 desk fan

  ⏻        touch: on
           hold 3 s: off
  ▲        faster
  ▼        slower

Hold ⏻ and ▲ together for 3 seconds: sound on / off.
The speed goes from 1 to 5.
"""


def test_a_two_key_hold_elsewhere_does_not_take_the_power_keys_own_hold() -> None:
    model = read_manual(TWO_KEY_FAN, ["press_power", "hold_power", "press_up", "press_down"]).model
    step = _feature_of(model, "hold_power")
    assert step is not None and step.variable == "power"
    assert "sound" not in model.variables


def test_a_power_hold_flipping_words_that_are_no_units_names_no_setting() -> None:
    for job in ("I / O", "1 / 2 / 3", "reset / clear"):
        manual = GERMINATOR.replace("°C / °F", job)
        model = read_manual(manual, GERMINATOR_ACTIONS).model
        assert "setting" not in model.variables, job
        assert "unit" not in model.variables, job


def test_a_power_hold_for_the_child_safety_or_for_everything_names_no_setting() -> None:
    for job in ("child safety on / off", "all on / off"):
        model = read_manual(HEATER.replace("flame guard on / off", job), HEATER_ACTIONS).model
        assert set(model.variables) == {"power", "heat"}, job
