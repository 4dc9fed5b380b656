"""Sentences new to the parser in the twenty-seventh set's shapes, said of small models written
for these tests: a flash's power in fractions and its compensation in stops, a one-letter mode
code named in brackets by its heading, a place counted back from an end of a scale, the middle
of an odd number of levels, an ordinal before a noun whose values are numbered but for one,
and a minutes-and-seconds clock that holds a span of time."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction

FLASH = """
appliance: {id: flash_1, category: camera_flash, name: "Strobo 40 speedlight", brand: S}
controls:
  - {id: mode_key, kind: button, label: "MODE"}
  - {id: dial, kind: dial, label: "DIAL"}
variables:
  mode: {type: discrete, values: [auto, m], show: {auto: "AUTO", m: "M"}}
  level:
    type: discrete
    depends_on: mode
    wrap: false
    cases:
      auto:
        values: ["-2.0", "-1.7", "-1.3", "-1.0", "-0.7", "-0.3", "0.0",
                 "+0.3", "+0.7", "+1.0", "+1.3", "+1.7", "+2.0"]
        initial: "0.0"
      m:
        values: ["1/32", "1/32+0.3", "1/32+0.7", "1/16", "1/16+0.3", "1/16+0.7", "1/8",
                 "1/8+0.3", "1/8+0.7", "1/4", "1/4+0.3", "1/4+0.7", "1/2", "1/2+0.3",
                 "1/2+0.7", "1/1"]
        initial: "1/1"
actions:
  press_mode: {control: mode_key}
  turn_up: {control: dial, skill: turn_cw}
  turn_down: {control: dial, skill: turn_ccw}
features:
  mode:
    - {actions: [press_mode], variable: mode, effect: next}
  level:
    - {actions: [turn_up, turn_down], variable: level, effect: {turn_up: next, turn_down: prev}}
"""

FLASH_MANUAL = """
Modes

   AUTO (metered flash)
     The camera meters the light. Turn the dial to add or take away light in
     1/3 stop steps.

   M (manual flash)
     You choose the power, from 1/1 (full) down to 1/32.
"""


def _flash(sentence: str) -> dict[str, object]:
    return parse_instruction(loads_model(FLASH), sentence, FLASH_MANUAL)


def test_power_said_as_a_fraction_in_words() -> None:
    assert _flash("manual, an eighth of full power") == {"mode": "m", "level": "1/8"}
    assert _flash("manual at one-sixteenth power plus two thirds of a stop") == {
        "mode": "m",
        "level": "1/16+0.7",
    }
    assert _flash("M mode, one thirty-second power") == {"mode": "m", "level": "1/32"}


def test_compensation_said_in_stops() -> None:
    assert _flash("auto, minus one and a third stops") == {"mode": "auto", "level": "-1.3"}
    assert _flash("auto, and bring it down by two-thirds of a stop") == {
        "mode": "auto",
        "level": "-0.7",
    }
    assert _flash("auto with a full stop more light") == {"mode": "auto", "level": "+1.0"}


CHAIR = """
appliance: {id: scooter_1, category: mobility_scooter, name: "Rova mobility scooter", brand: R}
controls:
  - {id: up_key, kind: button, label: "SPEED +"}
  - {id: down_key, kind: button, label: "SPEED -"}
  - {id: period_key, kind: button, label: "ROUND"}
variables:
  speed: {type: discrete, values: ["1", "2", "3", "4", "5"], wrap: false}
  round: {type: discrete, values: ["1", "2", "3", "4", "X"]}
actions:
  press_up: {control: up_key}
  press_down: {control: down_key}
  press_round: {control: period_key}
features:
  speed:
    - actions: [press_up, press_down]
      variable: speed
      effect: {press_up: next, press_down: prev}
  round:
    - {actions: [press_round], variable: round, effect: next}
"""


def test_a_place_counted_back_from_an_end() -> None:
    model = loads_model(CHAIR)
    assert parse_instruction(model, "one below the top speed") == {"speed": "4"}
    assert parse_instruction(model, "the second fastest speed") == {"speed": "4"}
    assert parse_instruction(model, "speed: second from the bottom") == {"speed": "2"}
    assert parse_instruction(model, "one above the slowest speed") == {"speed": "2"}


def test_the_middle_of_five_levels() -> None:
    assert parse_instruction(loads_model(CHAIR), "the middle speed") == {"speed": "3"}


def test_an_ordinal_before_a_noun_numbered_but_for_one_value() -> None:
    assert parse_instruction(loads_model(CHAIR), "the third round, speed 2") == {
        "round": "3",
        "speed": "2",
    }


TIMER = """
appliance: {id: board_1, category: scoreboard, name: "Tally scoreboard", brand: T}
controls:
  - {id: set_key, kind: button, label: "CLOCK"}
variables:
  game_clock:
    type: time
    ranges: [["00:00:00", "00:59:00", 60]]
    initial: "00:10:00"
    format: "mm:ss"
    label: "CLOCK"
actions:
  press_set: {control: set_key}
  press_back: {control: set_key, skill: hold, seconds: 2}
features:
  game_clock:
    - actions: [press_set, press_back]
      variable: game_clock
      effect: {press_set: next, press_back: prev}
"""


def test_a_minutes_and_seconds_clock_holds_a_span() -> None:
    model = loads_model(TIMER)
    assert parse_instruction(model, "put twelve minutes on the game clock") == {
        "game_clock": "00:12:00"
    }


SCOOTER = """
appliance: {id: scooter_2, category: mobility_scooter, name: "Rova wheelchair", brand: R}
controls:
  - {id: power_key, kind: button, label: "POWER"}
  - {id: light_key, kind: button, label: "LIGHTS"}
  - {id: hazard_key, kind: button, label: "HAZARD"}
variables:
  power: {type: discrete, values: ["off", "on"]}
  lights: {type: discrete, values: ["off", "on"]}
  hazard: {type: discrete, values: ["off", "on"]}
actions:
  press_power: {control: power_key}
  press_light: {control: light_key}
  press_hazard: {control: hazard_key}
features:
  power:
    - {actions: [press_power], variable: power, effect: toggle}
  lights:
    - {actions: [press_light], variable: lights, effect: toggle}
  hazard:
    - {actions: [press_hazard], variable: hazard, effect: toggle}
"""

SCOOTER_MANUAL = "The LIGHTS key switches the lights; HAZARD the hazard lights (all four blink).\n"


def test_the_chair_of_a_wheelchair_and_its_headlights() -> None:
    model = loads_model(SCOOTER)
    assert parse_instruction(model, "switch the chair on with the headlights on", "") == {
        "power": "on",
        "lights": "on",
    }


def test_the_hazard_lights_are_the_hazard_switch() -> None:
    model = loads_model(SCOOTER)
    assert parse_instruction(model, "the hazard lights on", SCOOTER_MANUAL) == {"hazard": "on"}
