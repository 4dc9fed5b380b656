"""Narrowings of the set27a / set27b reader rules, each on a small manual of our own words where
the rule, as merged, turned something else into a setting or its values."""

from __future__ import annotations

from apbot.model.domain import all_values
from apbot.read import read_manual

DIGITS = [f"press_{d}" for d in range(10)]

# a microwave: the clock's own steps say "time of day"; the next section types cook times
MICROWAVE = """
QUIKWAVE MW-20 microwave oven

SETTING THE CLOCK
1. Press CLOCK.
2. Enter the time of day with the number keys, e.g. 1 0 3 0 for 10:30.
3. Press CLOCK again.
COOKING BY TIME
1. Enter the cooking time in minutes and seconds with the number keys.
2. You can set up to 99 minutes 59 seconds.
3. Press START.
Press STOP/CLEAR to cancel.
"""


def test_a_time_of_day_clock_stays_hours_and_minutes_beside_a_typed_cook_time() -> None:
    actions = ["press_clock", *DIGITS, "press_start", "press_stop_clear"]
    model = read_manual(MICROWAVE, actions).model
    clock = model.variables["clock"]
    assert clock.format != "mm:ss"
    assert "23:59" in str(list(all_values(clock))[-1])


# a coffee maker whose key list runs its labels together on one line
COFFEE = """
BREWMATE coffee maker

Keys on the panel: POWER START/STOP TIMER STRENGTH
Press START/STOP to brew. Press it again to stop brewing.
Press TIMER repeatedly: 1 h, 2 h, 4 h, 8 h, off.
STRENGTH: mild, medium, strong.
"""


def test_a_key_after_the_panels_own_start_stop_key_is_not_a_start() -> None:
    actions = ["press_power", "press_start_stop", "press_timer", "press_strength"]
    model = read_manual(COFFEE, actions).model
    ran = [
        st.variable for f in model.features.values() for st in f if st.actions == ["press_timer"]
    ]
    assert ran and "running" not in ran


# a heater whose modes each give a range in °C in their own subsections
HEATER = """
CLIMA H-5 heater

MODE key: each press COMFORT → ECO → FROST → COMFORT.
TEMP dial. Turn it to change the target temperature.

4.1 COMFORT - heating for rooms in use
    The target is set from 16.0 to 26.0 °C in steps of 0.5 °C.
4.2 ECO - saving
    The target is set from 12.0 to 20.0 °C in steps of 0.5 °C.
4.3 FROST - protection
    The target is set from 5.0 to 10.0 °C in steps of 0.5 °C.
"""


def test_a_range_in_steps_per_mode_is_not_read_as_three_values() -> None:
    model = read_manual(HEATER, ["press_mode", "turn_temp_cw", "turn_temp_ccw"]).model
    for var in model.variables.values():
        for case in (var.cases or {}).values():
            assert "0.5" not in [str(v) for v in case.values or []]


# two seat heaters that may both be on
SEATS = """
WARMRIDE seat heater

LEFT key: switches the left seat on or off.
RIGHT key: switches the right seat on or off.
The left seat and the right seat heat on their own; both seats may be on together.
Only one heat level is set for the two seats: each side uses it.
"""


def test_side_keys_where_both_sides_may_be_on_are_not_one_setting() -> None:
    model = read_manual(SEATS, ["press_left", "press_right"]).model
    assert not any(
        {"left", "right"} <= {str(v) for v in getattr(var, "values", None) or []}
        for var in model.variables.values()
    )


# a fan whose modes are words the user says, each with a bracketed description
FAN = """
FANNY tower fan

MODE key: each press selects the next mode - ECO, NORMAL or BOOST.
The modes in turn:
   ECO (saves energy) → NORMAL (steady wind) → BOOST (full power)
"""


def test_a_cycle_of_named_modes_keeps_their_names_over_their_descriptions() -> None:
    model = read_manual(FAN, ["press_mode"]).model
    assert model.variables["mode"].values == ["eco", "normal", "boost"]


# the legend's next line is another key's, its hold after a semicolon
LAMP = """
LUMA desk lamp

  OK    confirms the value shown.
  MODE  Press briefly to change the colour; press and hold for 3 seconds to switch the night
        light on or off.
  OK and MODE are on the base.
"""


def test_a_hold_in_the_next_keys_legend_line_is_not_this_keys() -> None:
    model = read_manual(LAMP, ["press_ok", "hold_ok", "press_mode", "hold_mode"]).model
    held = {
        a: st.variable
        for f in model.features.values()
        for st in f
        for a in st.actions
        if a.startswith("hold_")
    }
    assert held.get("hold_mode") == "night_light"
    assert held.get("hold_ok") != held.get("hold_mode") and "night" not in str(held.get("hold_ok"))


# a safe: the clock's entry ends with CLOCK, the code's with ENTER
SAFE = """
STRONGBOX safe

SETTING THE CLOCK
1. Press CLOCK.
2. Type the hours and minutes on the number keys.
3. Press CLOCK again to store the time.

CHANGING THE CODE
1. Press CODE.
2. Type the new four-digit code.
3. Press ENTER to finish.
"""


def test_a_finishing_key_closes_only_the_entry_whose_steps_name_it() -> None:
    actions = ["press_clock", "press_code", *DIGITS, "press_enter"]
    model = read_manual(SAFE, actions).model
    closed = [
        n for n, f in model.features.items() if any(st.actions == ["press_enter"] for st in f)
    ]
    assert closed == ["set_code"]


# an oven whose table of contents leads its sections' titles with the functions' names
OVEN = """
COOKMASTER oven

CONTENTS
Safety ............ 2
Grill ............. Grilling meat 5
Fan ............... Fan baking 7
Defrost ........... Thawing food 9

Turn the FUNCTION knob: GRILL, FAN, DEFROST.
"""


def test_a_table_of_contents_line_is_no_gloss_of_a_value() -> None:
    model = read_manual(OVEN, ["turn_function_cw", "turn_function_ccw"]).model
    assert model.variables["function"].values == ["grill", "fan", "defrost"]


# a menu whose names are words, described in a dotted legend (the styled rice cooker's shape)
MENU_LEGEND = """
## Menus

Press MENU to step through the menus:

  WHITE → BROWN → PORRIDGE → STEAM

  WHITE ........ everyday white rice
  BROWN ........ whole-grain rice
  PORRIDGE ..... rice porridge
  STEAM ........ vegetables and dumplings
"""


def test_menu_words_described_in_a_dotted_legend_keep_their_names() -> None:
    model = read_manual(MENU_LEGEND, ["press_menu", "press_start"]).model
    values = [v for var in model.variables.values() for v in (getattr(var, "values", None) or [])]
    assert "white" in values and "porridge" in values
    assert "everyday white rice" not in values
