"""Rules from probing the reader with short manuals of our own (probe14): each rule on a small
manual written in different words from the probe that found it."""

from __future__ import annotations

from typing import Any

from apbot.read import read_manual


def _read(text: str, actions: list[str]) -> dict[str, Any]:
    """The model read, as the YAML a reading writes (the lists and maps a test can compare)."""
    return read_manual(text, actions).model.model_dump(mode="json", exclude_defaults=True)


# a radiator whose power selector is named only in lower-case prose (H1, H3)
RADIATOR = """
WarmWall OR-9 oil radiator

Parts
- Power switch (0/I)
- Output selector: 800 W / 1200 W / 2000 W
- Thermostat wheel

Using it
Switch on with the 0/I switch. The output selector chooses between three outputs; it leaves
the factory set to 1200 W. Turn the thermostat wheel to hold the room warm.
"""


def test_a_control_named_in_lower_case_prose_takes_its_list_of_amounts() -> None:
    model = _read(RADIATOR, ["press_power_switch", "press_output_selector", "turn_wheel_cw"])
    var = model["variables"]["output_selector"]
    assert var["type"] == "numeric" and var["unit"] == "W"
    assert var["ranges"][0][0] == 800 and var["ranges"][-1][1] == 2000
    assert var["initial"] == 1200


PANEL_HEATER = """
Panel heater PH-2

Press the I/O switch to switch on.
The heat selector selects between 1000 W and 2000 W. As supplied it is set to 2000 W.
"""


def test_a_selector_that_selects_between_two_amounts_has_those_two() -> None:
    model = _read(PANEL_HEATER, ["press_io_switch", "press_heat_selector"])
    var = model["variables"]["heat_selector"]
    assert var["ranges"] == [[1000, 2000, 1000]] and var["initial"] == 2000


# a grill whose dial a key points at the heat or at the timer (V1), whose start key is PLAY-like
GRILL = """
EmberTop CG-4 contact grill

Controls
* KNOB - turn it to change the figure shown.
* SEL - switches the knob between temperature and time.
* GO - starts or stops grilling.

Temperature
The temperature can be set from 150 to 230 °C. Each click of the knob changes it by 10 °C.

Time
The time can be set up to 30 minutes, in 1-minute steps.
"""


def test_a_key_that_switches_the_dial_between_two_settings_shares_it() -> None:
    model = _read(GRILL, ["turn_knob_cw", "turn_knob_ccw", "press_sel", "press_go"])
    variables = model["variables"]
    assert {"temperature", "time"} <= set(variables)
    assert variables["temperature"]["ranges"] == [[150, 230, 10]]
    shared = [f for f in model["features"].values() if f[0]["actions"] == ["press_sel"]]
    assert shared and shared[0][1]["actions"] == ["turn_knob_cw", "turn_knob_ccw"]
    assert model["features"]["go"][0] == {
        "actions": ["press_go"], "variable": "running", "effect": "toggle"
    }  # fmt: skip


def test_starting_or_stopping_a_feature_is_no_running_key() -> None:
    fan = """
Desk fan DF-1

POWER - switches the fan on or off.
SWING - starts or stops oscillation.
"""
    model = _read(fan, ["press_power", "press_swing"])
    assert "running" not in model["variables"]


# a cooler whose start speed is said once, of switching on (F1)
COOLER = """
Polar AC-3 evaporative cooler

Keys
1. ON/OFF - switches the cooler on or off.
2. FLOW - sets the air flow from 1 to 5.

Operation
After switching on, the cooler blows at flow 2 until you change it.
"""


def test_a_start_said_of_switching_on_names_the_setting_and_its_figure() -> None:
    model = _read(COOLER, ["press_on_off", "press_flow"])
    assert model["variables"]["flow"]["initial"] == 2


# a pasta maker whose values are marked as preselected after them (B2)
PASTA = """
PastaPro PM-2

THICKNESS toggles between 1 mm and 2 mm (1 mm is preselected).
SHAPE picks the die: Spaghetti, Penne, Fusilli. Penne comes preset.
"""


def test_a_value_said_to_be_preselected_is_the_start() -> None:
    model = _read(PASTA, ["press_thickness", "press_shape"])
    assert model["variables"]["shape"]["initial"] == "penne"
    assert model["variables"]["thickness"]["initial"] == 1
