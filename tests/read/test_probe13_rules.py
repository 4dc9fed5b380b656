"""Rules found by probing the reader with short manuals written unlike our data (probe13)."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.actions import action_info

BOTTLE_WARMER = """# Tepida Bottle Warmer

## Keys
- POWER: on and off.
- TIME + / TIME −: the warming time.

Warming time: adjustable from 2 to 20 minutes in steps of 1 minute.
The default is 6 minutes.
"""


def test_number_keys_spelled_with_their_kind_are_digits() -> None:
    for name in ("key_4", "press_key_4", "digit_4", "press_number_4_button", "4_key"):
        info = action_info(name)
        assert info.digit == 4 and info.controls == ("key_4",), name
    assert action_info("press_menu1").digit is None
    assert action_info("wait_10s").digit is None


def test_a_start_time_goes_to_the_time_not_to_a_temperature() -> None:
    manual = """# Brewa Tea Maker

## Panel
1. POWER – on or off
2. TEMP ▲ / TEMP ▼ – the brewing temperature
3. STEEP ▲ / STEEP ▼ – the steeping time

## Use
The brewing temperature is chosen between 70 °C and 95 °C. Pressing TEMP ▲ or TEMP ▼ moves
it by 5 °C.
Steeping time: adjustable from 1 to 10 minutes in steps of 1 minute. The default is 4 minutes.
"""
    actions = [
        "press_power_button",
        "press_temp_up_button",
        "press_temp_down_button",
        "press_steep_up_button",
        "press_steep_down_button",
    ]
    variables = read_manual(manual, actions).model.variables
    temp = variables["temp"]
    assert temp.ranges is not None and [list(r) for r in temp.ranges] == [[70, 95, 5]]
    assert temp.initial is None or temp.initial != 4
    steep = variables["steep"]
    assert str(steep.initial) in ("00:04:00", "4", "4.0")


def test_a_start_value_said_after_the_range_as_it_leaves_the_box() -> None:
    manual = """# Sproutly Seed Warmer

## Keys
- ON/OFF switches the mat on or off.
- WARM + and WARM − set the mat temperature.

## Warmth
Use WARM + and WARM − to set the mat temperature; it goes from 20 °C to 40 °C, 2 degrees at
a time. Out of the box it is set to 26 °C.
"""
    actions = ["press_on_off", "press_warm_plus", "press_warm_minus"]
    warm = read_manual(manual, actions).model.variables["warm"]
    assert warm.ranges is not None and [list(r) for r in warm.ranges] == [[20, 40, 2]]
    assert warm.initial == 26


def test_a_step_is_said_as_what_each_press_adds_or_removes() -> None:
    from apbot.read.value_steps import find_step

    assert find_step("Every tap adds or removes two minutes.") == (2.0, "min")
    assert find_step("It climbs from 40 to 80 °C, 10 °C at a time.") == (10.0, "°C")
    # a hold's fast steps are no step of a press
    assert find_step("Hold ▲ for 2 seconds to move 10 minutes at a time.") is None


def test_choices_said_after_the_sentence_naming_the_key_are_its_values() -> None:
    manual = """# Lumo Night Light

## Keys
GLOW: picks the colour of the light. The choices are: warm white, amber, soft blue, rose.
POWER: switches the light on or off.
"""
    glow = read_manual(manual, ["glow_key", "power_key"]).model.variables["glow"]
    assert glow.values == ["warm white", "amber", "soft blue", "rose"]


def test_two_amounts_a_key_switches_between_are_its_two_choices() -> None:
    manual = """# Crispa Waffle Iron

## Keys
- POWER: on or off.
- BATTER: switches the batter dose between 150 ml and 250 ml.
"""
    model = read_manual(manual, ["power_key", "batter_key"]).model
    batter = model.variables["batter"]
    assert batter.type == "numeric" and batter.ranges is not None
    assert [list(r) for r in batter.ranges] == [[150, 250, 100]]
    # a range said with "between" stays a range
    from apbot.read.two_choices import two_choices

    assert not two_choices("The batter can be set between 100 ml and 300 ml.")
