"""Settings the reader missed on new categories, each on a small manual written in our own words
the way a flattened commercial manual reads: a key table's column for holding whose cells name
the switched thing without repeating "hold" ("end signal on / off"), or under a heading such as
"Keep touching"; a time of day whose range is only said by where it wraps."""

from __future__ import annotations

from apbot.model.domain import all_values
from apbot.model.validate import check_model
from apbot.read import read_manual
from apbot.read.text import parse_manual
from apbot.read.values import Range, find_ranges

# a key table whose last column is for holding: the cells name what the hold switches
HOLD_COLUMN = """PRESSO CB-2 CLOTHES AIRER
Instructions

CONTROL PANEL

  No.  Key            Press briefly                     Press and hold (3 s)
  ---  -------------  --------------------------------  --------------------------
  1    POWER          switches the airer on or off      --
  2    HEAT           warm air on / off                 night quiet on / off
  3    FAN            fan speed LOW / HIGH              --

Switch on with POWER. Press FAN to change between LOW and HIGH.
"""
HOLD_COLUMN_ACTIONS = ["press_power", "press_heat", "hold_heat", "press_fan"]

# the same structure under another heading, each cell led by the time to hold
KEEP_TOUCHING = """GLACIA CHEST FREEZER CF-9
User guide

TOUCH FIELDS

  Field          Touch briefly                  Keep touching (printed below)
  -------------  -----------------------------  ------------------------------
  COLD           freezer one degree colder      -
  BOOST          quick freeze on / off          3 s: PARTY mode on / off
  BEEP           door alarm off / on            -

The freezer keeps -16 to -24 °C. Each touch of COLD makes it one degree colder.
"""
KEEP_TOUCHING_ACTIONS = ["press_cold", "press_boost", "hold_boost", "press_beep"]


def test_a_hold_column_cell_names_the_toggle_without_saying_hold() -> None:
    model = read_manual(HOLD_COLUMN, HOLD_COLUMN_ACTIONS).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    held = [f for f, steps in model.features.items() if steps[0].actions == ["hold_heat"]]
    assert held and model.features[held[0]][0].variable == "night_quiet"
    assert model.variables["night_quiet"].values == ["off", "on"]


def test_a_keep_touching_column_is_a_column_for_holding() -> None:
    model = read_manual(KEEP_TOUCHING, KEEP_TOUCHING_ACTIONS).model
    held = [f for f, steps in model.features.items() if steps[0].actions == ["hold_boost"]]
    assert held and model.features[held[0]][0].variable == "party"


def test_a_hold_cell_naming_the_key_lock_makes_that_hold_the_lock() -> None:
    manual = KEEP_TOUCHING.replace(
        "  BEEP           door alarm off / on            -",
        "  BEEP           door alarm off / on            5 s: key lock on / off",
    )
    model = read_manual(manual, [*KEEP_TOUCHING_ACTIONS, "hold_beep"]).model
    assert model.features["child_lock"][0].actions == ["hold_beep"]
    assert model.features["child_lock"][0].variable == "child_lock"


# a start time whose section gives only its step and where it goes round the clock
CLOCK_WRAP = """VERDA GARDEN PUMP TIMER GT-4
Operating instructions

KEYS

  Key        Function
  ---------  --------------------------------
  TIME       select the daily watering start
  ▲          value up
  ▼          value down
  RUN        water now

DAILY START

  1  Press TIME: the start time blinks on the display.
  2  Press ▲ or ▼. Each press moves the time by 15 minutes.
  3  The time goes round the clock: after 23:45 comes 00:00, and before 00:00 comes 23:45.

The factory setting is 06:00.
"""
CLOCK_WRAP_ACTIONS = ["press_time", "press_up", "press_down", "press_run"]


def test_a_wrap_between_clock_times_is_the_range_of_a_time_of_day() -> None:
    model = read_manual(CLOCK_WRAP, CLOCK_WRAP_ACTIONS).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    start = model.variables["time"]
    assert start.type == "time"
    assert [list(r) for r in start.ranges] == [["00:00:00", "23:45:00", 900]]
    steps = model.features["set_time"]
    assert steps[0].actions == ["press_time"]
    assert set(steps[1].actions) == {"press_up", "press_down"}


def test_a_range_in_ampere_hours_or_square_metres_is_a_rating_not_a_setting() -> None:
    # "4 - 14 Ah  1 A" in a capacity guide, "200 - 400 m²  4 h" in a lawn-area guide
    assert find_ranges("3 - 12 Ah (6 V)      1 A") == []
    assert find_ranges("up to 150 - 300 m²   3 h") == []
    assert find_ranges("set 1 - 9") != []


# numbered steps: press the key, then press the pair with the range (the pair's step is the key's)
PAIR_STEP = """FLORA DRIP CONTROLLER DC-3
Operating manual

   Key          Use
   -----------  ------------------------------------
   CYCLE        choose the watering cycle
   SOAK         choose the soak length
   ▲            up
   ▼            down
   RUN          water now

WATERING CYCLE

 1. Press CYCLE. The display shows C and the cycle.
 2. Press ▲ or ▼ to set 1 to 14 days. The value stops at both ends.

SOAK LENGTH

 1. Press SOAK. The display shows S and the length.
 2. Press ▲ or ▼ to set 2 to 20 minutes, in steps of 2 minutes.
"""
PAIR_STEP_ACTIONS = ["press_cycle", "press_soak", "press_up", "press_down", "press_run"]


def test_the_pair_step_after_a_key_step_gives_that_key_its_range() -> None:
    model = read_manual(PAIR_STEP, PAIR_STEP_ACTIONS).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    cycle = all_values(model.variables["cycle"])
    assert cycle[0] == 1 and cycle[-1] == 14 and len(cycle) == 14
    soak = all_values(model.variables["soak"])
    assert soak[0] == "00:02:00" and soak[-1] == "00:20:00" and len(soak) == 10
    assert set(model.features["set_cycle"][1].actions) == {"press_up", "press_down"}


def test_a_spec_table_whose_first_column_has_no_name_is_a_table() -> None:
    manual = parse_manual(
        "TECHNICAL DATA\n\n"
        "   -------------------------------------------------------------\n"
        "                          Model S-3            Model S-6\n"
        "   -------------------------------------------------------------\n"
        "   Power                  400 W                700 W\n"
        "   Bath temperature       40 - 60 °C           35 - 70 °C\n"
        "   Keys                   BATH TIME            as S-3, plus LIGHT\n"
    )
    rows = [u for u in manual.units if u.cells]
    assert rows and rows[-1].header == ("", "Model S-3", "Model S-6")
    assert rows[-1].cells[0] == "Keys"


def test_stops_at_two_values_and_a_chain_of_values_are_ranges() -> None:
    assert find_ranges("the value stops at 35 °C and at 50 °C") == [Range(35, 50, "°C")]
    assert find_ranges("in steps: 0.5 - 1 - 1.5 - 2 h.") == [Range(0.5, 2, "h", 0.5)]
    assert find_ranges("it stops at both ends") == []


# the key is printed HOLD and its setting is a "holding time": no hold of the key
HOLDING_TIME = """WARMA SAUCE STATION
Guide

  Key      Use
  -------  ------------------------------
  HOLD     select the holding time
  −        lower
  +        raise

HOLDING TIME

 1. Press HOLD. The holding time is shown.
 2. Press − or + in steps of half an hour: 0.5 - 1 - 1.5 - 2 - 2.5 - 3 h.
"""
HOLDING_TIME_ACTIONS = ["press_hold", "press_minus", "press_plus"]


def test_a_key_printed_hold_steps_its_holding_time_with_the_pair() -> None:
    model = read_manual(HOLDING_TIME, HOLDING_TIME_ACTIONS).model
    values = all_values(model.variables["hold"])
    assert values[0] in (0.5, "00:30:00") and values[-1] in (3, "03:00:00") and len(values) == 6


# the key's step runs over several sentences: the pair's step comes after them
LONG_STEP = """TERRA MOWER M-2
Guide

  Key      Use
  -------  ------------------------------
  HOURS    select the mowing hours
  ▲        up
  ▼        down
  GO       mow now

DAILY SCHEDULE

  1  Press HOURS. The display shows D and the hours. They blink.
  2  Press ▲ or ▼ to change the hours by 1 h, from 2 h to 10 h.
"""
LONG_STEP_ACTIONS = ["press_hours", "press_up", "press_down", "press_go"]


def test_the_pair_step_after_a_key_step_of_several_sentences_is_the_keys() -> None:
    model = read_manual(LONG_STEP, LONG_STEP_ACTIONS).model
    values = all_values(model.variables["hours"])
    assert values[0] == 2 and values[-1] == 10 and len(values) == 9
    assert set(model.features["set_hours"][1].actions) == {"press_up", "press_down"}
