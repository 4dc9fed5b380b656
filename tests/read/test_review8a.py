"""Round-8 reader rules that fired on ordinary manual text (fresh-eyes review), each on a
small manual of our own words."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.text import parse_manual

# a cooking-time chart with dot leaders and bare minutes: no table of contents
CHART = """Quickboil Rice Cooker RC-7

PROGRAMMES

Press MENU to choose a programme. Cooking times (minutes):

White rice ........ 35
Brown rice ........ 50
Porridge .......... 90
Steam ............. 120

Press START to begin cooking.
"""


def test_a_dot_leader_chart_of_minutes_is_no_table_of_contents() -> None:
    text = " ".join(u.text for u in parse_manual(CHART).units)
    assert "Porridge" in text and "120" in text


def test_a_table_of_contents_without_a_heading_still_goes() -> None:
    toc = "".join(
        f"{t} .......... {p}\n"
        for t, p in [
            ("Safety", 2),
            ("The keys", 3),
            ("Programmes", 5),
            ("Cleaning", 8),
            ("Warranty", 9),
        ]
    )
    text = " ".join(u.text for u in parse_manual("Tower fan\n\n" + toc + "\nPress SPEED.\n").units)
    assert "Warranty" not in text and "SPEED" in text


# a fan always on while plugged in, whose LOCK key is held to lock the keys
FAN = """Breeze Tower Fan TF-3

The fan runs as soon as it is plugged in.

KEYS

SPEED     Press to go from speed 1 to 2 and 3.
LOCK      Hold for 3 seconds: on/off.
TIMER     Press to set the timer from 1 to 8 hours.
"""
FAN_ACTIONS = ["press_speed", "hold_lock", "press_timer"]


def test_a_lock_key_held_on_off_is_no_power_key() -> None:
    model = read_manual(FAN, FAN_ACTIONS).model
    assert "power" not in model.variables


def test_holding_a_key_to_switch_on_or_off_the_child_lock_is_no_power() -> None:
    text = FAN.replace("Hold for 3 seconds: on/off.", "Locks the keys.") + (
        "\nHold TIMER for 3 seconds to switch on or off the child lock.\n"
    )
    model = read_manual(text, ["press_speed", "hold_timer", "press_timer"]).model
    assert "power" not in model.variables


# a microwave whose keypad types the time; its zero key has a name of its own
OVEN = """Speedy Microwave MW-30

Press TIME, then type the cooking time with the number keys 1 to 9 and 0.
Press START to begin.
"""
OVEN_ACTIONS = ["press_time", "press_start", *[f"press_{d}" for d in range(1, 10)], "press_zero"]


def test_number_keys_that_type_a_time_stay_a_keypad() -> None:
    model = read_manual(OVEN, OVEN_ACTIONS).model
    assert "level" not in model.variables
    said = OVEN.replace("then type the cooking time", "then set the cooking time")
    assert "level" not in read_manual(said, OVEN_ACTIONS).model.variables


def test_a_time_out_after_minutes_names_no_wrap() -> None:
    from apbot.read.values_wraps import find_wrap

    assert find_wrap("After 10 minutes without a key press the display goes back to 0.") is None
    assert find_wrap("After 2 hours of keep warm the cooker returns to 1.") is None
    assert find_wrap("After 10 minutes the power level falls back to 9.") is None
    assert find_wrap("One more press after 15 h sets the timer back to 0.") is not None


# a diffuser with no power key whose title names its display, said more often than the product
DIFFUSER = """Aroma Diffuser AD-5 with LED display

Plug in the diffuser. The mist starts at once.

KEYS

MIST      Press to choose the mist: LOW or HIGH.
LIGHT     Press to choose the colour: WARM, COOL or RAINBOW.
          Hold for 2 seconds: switch the display on or off.

The display shows the mist level. When the display is off, the light stays on.
"""


def test_switching_the_display_a_title_names_is_no_power() -> None:
    model = read_manual(DIFFUSER, ["press_mist", "press_light", "hold_light"]).model
    assert "power" not in model.variables


# a heater whose mode change both clears the timer and names the fan's value
HEATER = """Cosy Heater H-6

Press POWER to switch the heater on or off.
Press MODE to choose the mode: ECO, COMFORT or BOOST.
Press FAN to choose the fan: AUTO, LOW or HIGH.
Press TEMP to set the temperature from 5 to 30 °C.
Press TIMER to set the timer from 1 to 12 hours.

Each time you change the mode, the timer is cleared and the fan goes back to AUTO.
"""
HEATER_ACTIONS = ["press_power", "press_mode", "press_fan", "press_temp", "press_timer"]


def _mode_step(text: str):  # type: ignore[no-untyped-def]
    model = read_manual(text, HEATER_ACTIONS).model
    return next(s for f in model.features.values() for s in f if s.variable == "mode")


def test_a_named_value_beside_a_clear_keeps_the_reset() -> None:
    step = _mode_step(HEATER)
    assert step.set == {"fan": "auto"} and "timer" in step.reset


def test_a_named_value_alone_resets_nothing_else() -> None:
    text = HEATER.replace("the timer is cleared and the fan goes back to", "it resets the fan to")
    step = _mode_step(text)
    assert step.set == {"fan": "auto"} and not step.reset


# a foot spa whose one-letter key P starts a sentence that holds another key
SPA = """Calm Foot Spa FS-9

KEYS

P       Press briefly: next programme.
HEAT    Press to switch the heat on or off.

Programmes: CALM, PULSE or WAVE.
Press P to choose the programme; hold P for 2 seconds to save it as your favourite.
Press P, then hold HEAT for 3 seconds to switch the spa on or off.
"""


def test_a_sentence_starting_with_press_p_is_no_legend_line_of_p() -> None:
    model = read_manual(SPA, ["press_p", "hold_p", "press_heat", "hold_heat"]).model
    assert [s.actions for s in model.features["power"]] == [["hold_heat"]]


def test_dial_positions_with_dot_leaders_are_no_table_of_contents() -> None:
    dial = "".join(
        f"{t} .......... {p}\n"
        for p, t in enumerate(["Cotton", "Synthetics", "Wool", "Quick", "Rinse"], start=1)
    )
    text = " ".join(
        u.text
        for u in parse_manual("Washer\n\nDial positions:\n" + dial + "\nTurn the dial.\n").units
    )
    assert "Wool" in text and "Rinse" in text


# an air fryer whose programme, not the fryer, starts with a printed list of settings
FRYER = """Crispy Air Fryer AF-9

Press POWER to switch the fryer on or off. It starts at 200 °C and 15 min.
Press MENU to choose a programme: FRIES, CHICKEN or FISH.
Press TEMP to set the temperature from 80 to 200 °C.
Press TIME to set the time from 1 to 60 minutes.

The FISH programme starts with these settings: 160 °C, 12 min.
"""


def test_a_programmes_start_settings_are_not_the_appliances() -> None:
    actions = ["press_power", "press_menu", "press_temp", "press_time"]
    model = read_manual(FRYER, actions).model
    assert model.variables["temp"].initial != 160
    assert str(model.variables["time"].initial or "") != "00:12:00"


def test_a_return_to_the_defaults_after_a_mode_change_is_a_reset_not_a_wrap() -> None:
    text = HEATER.replace(
        "Each time you change the mode, the timer is cleared and the fan goes back to AUTO.",
        "After a mode change, it returns to the default temperature and timer of that mode.",
    )
    assert "timer" in _mode_step(text).reset


# a cushion with no power key, whose HEAT and SOUND keys are held to switch themselves
CUSHION = """Warm Seat Cushion SC-2

Plug the cushion in; it is ready at once.

KEYS

MODE      Press briefly: next massage mode (WAVE, KNEAD, TAP).
HEAT      Hold for 2 seconds: on/off.
SOUND     Hold for 2 seconds: on/off.
"""


def test_a_heat_key_held_on_off_switches_the_heat_not_the_appliance() -> None:
    model = read_manual(CUSHION, ["press_mode", "hold_heat", "hold_sound"]).model
    assert "power" not in model.variables
