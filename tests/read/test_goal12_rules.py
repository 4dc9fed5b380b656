"""Rules of how people phrase requests, checked on models written for these tests (a floor
scrubber and a dog-grooming dryer no suite has).

Said to a phone or typed in a hurry, an order loses its commas: "… without the presoak and get
it started", "presoak brush 4", "power on use the deep programme". The joining word and the
order of the words are then all that mark where one order ends and the next begins."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction

SCRUBBER = """
appliance: {id: scrubber_1, category: floor_scrubber, name: "Glanz FS-2 floor scrubber", brand: G}
controls:
  - {id: power_key, kind: button, label: "POWER"}
  - {id: prog_key, kind: button, label: "PROGRAM"}
  - {id: brush_key, kind: button, label: "BRUSH"}
  - {id: soak_key, kind: button, label: "PRESOAK"}
  - {id: dry_key, kind: button, label: "DRY"}
  - {id: lock_key, kind: button, label: "LOCK"}
  - {id: gloss_key, kind: button, label: "GLOSS"}
  - {id: start_key, kind: button, label: "START"}
  - {id: pad_key, kind: button, label: "PAD"}
variables:
  pad: {type: discrete, values: [soft, firm]}
  power: {type: discrete, values: ["off", "on"]}
  program:
    type: discrete
    values: [daily, deep, tiles, tiles and grout]
  brush: {type: numeric, ranges: [[1, 5, 1]], initial: 3, wrap: true}
  gloss: {type: numeric, ranges: [[1, 3, 1]], initial: 2, wrap: true}
  presoak: {type: discrete, values: ["off", "on"]}
  dry: {type: discrete, values: ["off", "on"]}
  child_lock: {type: discrete, values: ["off", "on"]}
  running: {type: discrete, values: ["off", "on"]}
actions:
  press_power: {control: power_key}
  press_prog: {control: prog_key}
  press_brush: {control: brush_key}
  press_gloss: {control: gloss_key}
  press_soak: {control: soak_key}
  press_dry: {control: dry_key}
  press_lock: {control: lock_key}
  press_start: {control: start_key}
  press_pad: {control: pad_key}
features:
  pad:
    - {actions: [press_pad], variable: pad, effect: next}
  power:
    - {actions: [press_power], variable: power, effect: toggle}
  program:
    - {actions: [press_prog], variable: program, effect: next}
  brush:
    - {actions: [press_brush], variable: brush, effect: next}
  gloss:
    - {actions: [press_gloss], variable: gloss, effect: next}
  presoak:
    - {actions: [press_soak], variable: presoak, effect: toggle}
  dry:
    - {actions: [press_dry], variable: dry, effect: toggle}
  child_lock:
    - {actions: [press_lock], variable: child_lock, effect: toggle}
  start:
    - {actions: [press_start], variable: running, effect: toggle}
"""


def test_a_negation_ends_where_and_opens_a_new_order() -> None:
    model = loads_model(SCRUBBER)
    goal = parse_instruction(model, "Scrub the tiles without drying and get it started")
    assert goal["dry"] == "off" and goal["running"] == "on"
    goal = parse_instruction(model, "Deep program without starting it then lock the panel")
    assert goal["running"] == "off" and goal["child_lock"] == "on"


def test_a_negation_still_covers_a_gerund_joined_by_and() -> None:
    goal = parse_instruction(loads_model(SCRUBBER), "Deep program, without drying and starting.")
    assert goal["running"] == "off"


def test_a_switch_said_on_before_the_next_verb_is_on() -> None:
    goal = parse_instruction(
        loads_model(SCRUBBER), "Daily program with no drying and presoak on start it"
    )
    assert goal["dry"] == "off" and goal["presoak"] == "on" and goal["running"] == "on"


def test_a_switch_listed_before_another_settings_value_is_on() -> None:
    model = loads_model(SCRUBBER)
    assert parse_instruction(model, "Deep program with presoak brush 4")["presoak"] == "on"
    assert parse_instruction(model, "Deep program brush 4 presoak")["presoak"] == "on"
    assert parse_instruction(model, "Deep program firm pad presoak")["presoak"] == "on"


def test_power_said_on_right_before_the_next_verb() -> None:
    model = loads_model(SCRUBBER)
    goal = parse_instruction(model, "Power on use the deep program and lock the panel")
    assert goal["power"] == "on" and goal["program"] == "deep"
    goal = parse_instruction(model, "Switch it on set the brush to 2")
    assert goal["power"] == "on" and goal["brush"] == 2


def test_a_superlative_before_a_setting_word_is_that_settings() -> None:
    model = loads_model(SCRUBBER)
    goal = parse_instruction(model, "Deep program with the highest gloss brush 4")
    assert goal == {"program": "deep", "brush": 4, "gloss": 3}


DRYER = """
appliance: {id: groomer_1, category: dog_dryer, name: "Fluff D1 dog-grooming dryer", brand: F}
controls:
  - {id: eye_key, kind: button, label: "EYE"}
  - {id: time_key, kind: button, label: "TIME"}
  - {id: cool_key, kind: button, label: "COOL+"}
variables:
  eye_range: {type: discrete, values: [near, mid, far], initial: mid}
  blow_time: {type: numeric, unit: min, ranges: [[10, 60, 10]], initial: 20, wrap: true}
  extra_cool: {type: numeric, unit: min, ranges: [[0, 120, 30]], initial: 0, wrap: true}
actions:
  press_eye: {control: eye_key}
  press_time: {control: time_key}
  press_cool: {control: cool_key}
features:
  eye_range:
    - {actions: [press_eye], variable: eye_range, effect: next}
  blow_time:
    - {actions: [press_time], variable: blow_time, effect: next}
  extra_cool:
    - {actions: [press_cool], variable: extra_cool, effect: next}
"""


def test_a_reach_said_as_a_length_names_near_or_far() -> None:
    model = loads_model(DRYER)
    assert parse_instruction(model, "Use the long eye range.") == {"eye_range": "far"}
    assert parse_instruction(model, "The eye range at its shortest.") == {"eye_range": "near"}
    assert parse_instruction(model, "Let the eye sense the dog from further away.") == {
        "eye_range": "far"
    }


def test_an_extra_hour_is_an_hour() -> None:
    goal = parse_instruction(
        loads_model(DRYER), "Blow for 30 minutes with an extra hour of cooling."
    )
    assert goal == {"blow_time": 30, "extra_cool": 60}


def test_a_value_of_two_things_said_with_the_article_repeated() -> None:
    goal = parse_instruction(loads_model(SCRUBBER), "Clean the tiles and the grout.")
    assert goal["program"] == "tiles and grout"


WEATHER = """
appliance: {id: station_1, category: weather_station, name: "Nimbus W4 weather station", brand: N}
controls:
  - {id: set_key, kind: button, label: "SET"}
  - {id: up_key, kind: button, label: "UP"}
variables:
  month: {type: discrete, values: ["1", "2", "3", "4", "5", "6", "7", "8", "9", "10", "11", "12"]}
  day: {type: numeric, ranges: [[1, 31, 1]], initial: 1, wrap: true}
actions:
  press_set: {control: set_key}
  press_up: {control: up_key}
features:
  date:
    - {actions: [press_set]}
    - {actions: [press_up], variable: month, effect: next}
    - {actions: [press_set]}
    - {actions: [press_up], variable: day, effect: next}
"""


def test_a_date_said_in_words_sets_the_day_and_the_month() -> None:
    model = loads_model(WEATHER)
    assert parse_instruction(model, "Set the date to the twenty-second of October.") == {
        "month": "10",
        "day": 22,
    }
    assert parse_instruction(model, "It's the 5th of June.") == {"month": "6", "day": 5}
    assert parse_instruction(model, "Make it September 30th.") == {"month": "9", "day": 30}
