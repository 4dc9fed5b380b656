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


# a dehumidifier whose legend letters its keys (U1) and whose last level has a gloss (U2)
DRYER = """
Arid D-9 dehumidifier

Keys
(A) ⏻ Power
(B) LEVEL — target: 45 %, 55 % or CON (non-stop)
(C) SLEEP — quiet fan

Use
Press ⏻ to begin. LEVEL is CON when new.
"""


def test_a_lettered_legend_keeps_each_key_on_its_own_line() -> None:
    model = _read(DRYER, ["press_power", "press_level", "press_sleep"])
    assert model["variables"]["level"]["values"] == ["45 %", "55 %", "con"]


def test_a_small_letter_in_brackets_inside_prose_is_no_item() -> None:
    from apbot.read.text import parse_manual

    manual = parse_manual("Fill the tank.\n(a) the lid must click shut before use.\n")
    assert not any(u.bullet for u in manual.units)


# a lamp whose keys are printed as icons only, each explained by a line it leads
LAMP = """
Glow L-3 bedside lamp

The keys carry symbols only.

✺  — brightness. Each touch: LOW → MID → HIGH → LOW.
☾  — nightlight on / off.
"""


def test_an_icon_leading_a_legend_line_is_the_key_its_words_name() -> None:
    model = _read(LAMP, ["touch_brightness", "touch_nightlight"])
    assert model["variables"]["brightness"]["values"] == ["low", "mid", "high"]


# a table of display symbols: each line says what the symbol looks like, then what it shows
DRYER_SYMBOLS = """
Boot dryer BD-2

Each press of MODE: ☀ HOT → ◐ WARM → ❄ COOL → ☀ HOT.
Each press of TIME: 30 → 60 → 90 → ∞ (minutes).

Display symbols
   ◐      half-moon symbol    WARM mode, about 40 °C
   ∞      infinity sign       continuous running, no time limit
"""


def test_a_display_symbol_line_naming_a_key_later_is_no_key() -> None:
    model = _read(DRYER_SYMBOLS, ["press_mode", "press_time"])
    assert model["variables"]["mode"]["values"] == ["hot", "warm", "cool"]
    assert "time" not in [str(v) for v in model["variables"]["time"].get("values", [])]


def test_a_single_guillemet_separates_a_cycle_and_a_start_beside_a_degree_sign() -> None:
    card = """
Tea maker T-1 quick card

| # | Key  | Use                                  | Note            |
|---|------|--------------------------------------|-----------------|
| 1 | HEAT | Tap: 70° › 80° › 90° › BOIL › 70° …  | (starts at 80°) |
"""
    model = _read(card, ["press_heat"])
    var = model["variables"]["heat"]
    assert var["values"] == ["70°", "80°", "90°", "boil"] and var["initial"] == "80°"


# a mode's sentence holding a setting at one value (C4)
PURIFIER = """
Whisper AP-2 air purifier

MODE - press to choose Auto, Turbo or Quiet.
SPEED - sets the fan speed from 1 to 6.
In Quiet mode the fan speed stays at 2.
"""


def test_a_setting_a_mode_holds_fixed_depends_on_that_mode() -> None:
    model = _read(PURIFIER, ["press_mode", "press_speed"])
    speed = model["variables"]["speed"]
    assert speed["depends_on"] == "mode"
    assert speed["cases"]["quiet"]["ranges"] == [[2, 2, 1]]
    assert speed["cases"]["auto"]["ranges"] == [[1, 6, 1]]


def test_a_toggle_named_as_the_mode_holds_the_setting_when_on() -> None:
    heater = """
Patio heater PH-3

POWER - on / off.
BOOST - switches boost mode on or off.
LEVEL - sets the heat level from 1 to 5.
While in boost mode the level is locked at 5.
"""
    model = _read(heater, ["press_power", "press_boost", "press_level"])
    level = model["variables"]["level"]
    assert level["depends_on"] == "boost"
    assert level["cases"]["on"]["ranges"] == [[5, 5, 1]]


def test_a_key_that_starts_or_stops_a_moving_part_is_no_running_key() -> None:
    heater = """
Fan heater FH-2

| Key   | Use                                 |
|-------|-------------------------------------|
| POWER | on / off                            |
| TURN  | Start or stop the rotating base     |
"""
    model = _read(heater, ["press_power", "press_turn"])
    assert "running" not in model["variables"]
