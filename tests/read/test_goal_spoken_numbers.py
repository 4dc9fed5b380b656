"""Numbers and units the parser used to drop or misread (parse29, 7 December): hundreds counted
past ten ("twenty-seven hundred kelvin"), decimals read out digit by digit ("two point five
volts"), settings kept in volts and amps named by those units, a current said in milliamps,
and a switch whose whole name is a synonym of power ("the output on"). Small models written
for these tests."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction
from apbot.read.goal_spoken_numbers import said_hundreds_past_ten, said_points

LAMP = """
appliance: {id: panel_lamp_1, category: panel_lamp, name: "Lumo P-9 panel lamp", brand: L}
controls:
  - {id: cct_key, kind: button, label: "CCT"}
  - {id: dim_key, kind: button, label: "DIM"}
variables:
  colour_temperature:
    type: numeric
    unit: K
    ranges: [[2500, 6000, 100]]
    initial: 4000
    wrap: true
    show: "{value}K"
  brightness:
    type: numeric
    unit: "%"
    ranges: [[10, 100, 10]]
    initial: 50
    wrap: true
    show: "{value}%"
actions:
  press_cct: {control: cct_key}
  press_dim: {control: dim_key}
features:
  colour_temperature:
    - {actions: [press_cct], variable: colour_temperature, effect: next}
  brightness:
    - {actions: [press_dim], variable: brightness, effect: next}
"""

SUPPLY = """
appliance: {id: lab_supply_1, category: lab_supply, name: "Ohmic LS-20 supply", brand: O}
controls:
  - {id: v_knob, kind: knob, label: "V"}
  - {id: i_knob, kind: knob, label: "I"}
  - {id: out_key, kind: button, label: "OUTPUT"}
variables:
  output: {type: discrete, values: ["off", "on"], show: {"off": "", "on": "OUT"}}
  voltage: {type: numeric, unit: V, ranges: [[0, 20, 0.1]], initial: 5, show: "{value} V"}
  current: {type: numeric, unit: A, ranges: [[0, 3, 0.01]], initial: 1, show: "{value} A"}
actions:
  turn_v: {control: v_knob, skill: turn_cw}
  back_v: {control: v_knob, skill: turn_ccw}
  turn_i: {control: i_knob, skill: turn_cw}
  back_i: {control: i_knob, skill: turn_ccw}
  press_out: {control: out_key}
features:
  voltage:
    - actions: [turn_v, back_v]
      variable: voltage
      effect: {turn_v: {add: 0.1}, back_v: {add: -0.1}}
  current:
    - actions: [turn_i, back_i]
      variable: current
      effect: {turn_i: {add: 0.01}, back_i: {add: -0.01}}
  output:
    - {actions: [press_out], variable: output, effect: toggle}
"""


def test_hundreds_past_ten_are_one_number() -> None:
    assert said_hundreds_past_ten(None, "twenty-seven hundred kelvin") == "2700 kelvin"
    assert said_hundreds_past_ten(None, "nineteen hundred and six mm") == "1906 mm"
    assert said_hundreds_past_ten(None, "at eighteen hundred hours") == "at eighteen hundred hours"
    goal = parse_instruction(loads_model(LAMP), "Make it fifty-six hundred kelvin at 40 percent.")
    assert goal == {"colour_temperature": 5600, "brightness": 40}


def test_decimals_read_digit_by_digit() -> None:
    assert said_points(None, "two point five volts") == "2.5 volts"
    assert said_points(None, "nought point seven five") == "0.75"
    assert said_points(None, "at one point, stop") == "at one point, stop"


def test_volts_and_amps_name_their_settings() -> None:
    model = loads_model(SUPPLY)
    assert parse_instruction(model, "Six volts and one amp please.") == {
        "voltage": 6,
        "current": 1,
    }
    assert parse_instruction(model, "Two point five volts at four hundred milliamps.") == {
        "voltage": 2.5,
        "current": 0.4,
    }
    assert parse_instruction(model, "Limit it to 250 mA, nine volts.") == {
        "current": 0.25,
        "voltage": 9,
    }


def test_a_switch_named_by_a_synonym_of_power() -> None:
    model = loads_model(SUPPLY)
    assert parse_instruction(model, "Eight volts, then the output on.") == {
        "voltage": 8,
        "output": "on",
    }
