"""Narrowings found reviewing this session's reader and goal-parser rules, each on our own
words: a drawing's legend of circled callouts ("① PROGRAM key · ② TIMER key") shows no value
circled (``circled_shows``); "a" / "an" are no figure of a spoken number ("twelve hundred a
minute", "one point five A"), and a military time keeps its minutes ("nineteen hundred thirty
hours") (``goal_spoken_numbers``); a direction word after the number is its own only when it
follows the number and its unit, never a word of a later phrase or after "up" (``goal_signed``);
a pronoun's "one's" is no number (``numbers_owning``); a chart's Range column makes an amount
only of the setting the chart already reads per choice, not of a setting of its own whose
values a column pairs with each row (``cases_lines.table_choice_ranges``)."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read import read_manual
from apbot.read.goal import parse_instruction
from apbot.read.goal_spoken_numbers import numbers_owning, said_hundreds_past_ten, said_points

# a slow cooker (our own words) whose panel legend numbers its keys with circled figures
COOKER = """
Simmo SC-3 slow cooker

 PANEL

 ① PROGRAM key · ② TIMER key · ③ START key

 PROGRAMS

 Press PROGRAM to choose a program, 1 to 3. The display shows the program number.

 TIMER

 Press TIMER to set the cooking time from 1 to 12 hours in 1 hour steps.
"""
COOKER_ACTIONS = ["press_program", "press_timer", "press_start"]


def test_circled_callouts_of_a_panel_legend_show_no_value() -> None:
    model = read_manual(COOKER, COOKER_ACTIONS).model
    program = model.variables["program"]  # (on main: shown as ① ② ③, the keys' callouts)
    assert not getattr(program, "show", None)


def test_a_callout_after_a_keys_name_shows_no_value() -> None:
    text = COOKER.replace(
        "① PROGRAM key · ② TIMER key · ③ START key", "PROGRAM ①  TIMER ②  START ③"
    )
    model = read_manual(text, COOKER_ACTIONS).model
    assert not getattr(model.variables["program"], "show", None)


def test_an_article_is_no_figure_of_a_spoken_number() -> None:
    assert said_hundreds_past_ten(None, "spin at twelve hundred a minute") == (  # type: ignore[arg-type]
        "spin at 1200 a minute"
    )
    assert said_points(None, "charge at one point five A") == "charge at 1.5 A"  # type: ignore[arg-type]
    assert said_points(None, "three point three volts") == "3.3 volts"  # type: ignore[arg-type]


def test_a_military_time_keeps_its_minutes() -> None:
    said = "start at nineteen hundred thirty hours"
    assert said_hundreds_past_ten(None, said) == said  # type: ignore[arg-type]
    assert said_hundreds_past_ten(None, "nineteen hundred and thirty hours").endswith("hours")  # type: ignore[arg-type]
    assert said_hundreds_past_ten(None, "fifteen hundred and fifteen") == "1515"  # type: ignore[arg-type]


# a keyboard (our own words) whose transpose runs either side of zero
KEYBOARD = """
appliance: {id: keyboard_9, category: keyboard, name: "Keys K-9", brand: K}
controls:
  - {id: tr_key, kind: button, label: "TRANSPOSE"}
variables:
  transpose: {type: numeric, ranges: [[-6, 6, 1]], initial: 0, wrap: true, show: "{value}"}
actions:
  press_tr: {control: tr_key}
features:
  transpose:
    - {actions: [press_tr], variable: transpose, effect: next}
"""


def test_a_direction_of_a_later_phrase_keeps_the_number_as_said() -> None:
    model = loads_model(KEYBOARD)
    assert parse_instruction(model, "Transpose up two for the lower voice.") == {"transpose": 2}
    assert parse_instruction(model, "Transpose up 2 so the back row can sing.") == {"transpose": 2}
    assert parse_instruction(model, "Transpose two semitones lower.") == {"transpose": -2}
    assert parse_instruction(model, "Transpose three notches back.") == {"transpose": -3}


def test_a_pronouns_possessive_is_no_number() -> None:
    model = loads_model(KEYBOARD)
    # (on main: "no one's" read as "no one", a transpose of 1)
    assert parse_instruction(model, "Play the keyboard when no one's at home.") == {}
    assert parse_instruction(model, "Set the transpose for each one's part.") == {}
    assert numbers_owning(None, "set dog one's level to 5") == "set dog one level to 5"  # type: ignore[arg-type]


# a food dehydrator (our own words): the chart pairs a fan speed and a temperature range per mode
DRYER = """
Dryo D-5 food dehydrator

 CONTROLS

 Press MODE to step FRUIT → MEAT → HERBS → FRUIT.
 Press FAN to switch the fan between LOW and HIGH.
 Press ▲ or ▼ to change the temperature by 5 °C.

 MODES

 | Mode  | Fan   | Range       | Starts at |
 |-------|-------|-------------|-----------|
 | FRUIT | LOW   | 50 - 70 °C  | 60        |
 | MEAT  | HIGH  | 60 - 75 °C  | 70        |
 | HERBS | LOW   | 35 - 50 °C  | 40        |
"""
DRYER_ACTIONS = ["press_mode", "press_fan", "press_up", "press_down"]


def test_a_range_column_leaves_a_setting_of_its_own_named() -> None:
    model = read_manual(DRYER, DRYER_ACTIONS).model
    fan = model.variables["fan"]  # (on main: an amount 50-70 per mode, then a bare toggle)
    assert fan.type == "discrete" and list(getattr(fan, "values", [])) == ["low", "high"]
