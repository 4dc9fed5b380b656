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


WELDER = """
appliance: {id: arc_welder_1, category: arc_welder, name: "Fuse W-1 welder", brand: F}
controls:
  - {id: trig_key, kind: button, label: "TRIGGER"}
  - {id: up_key, kind: button, label: "+"}
variables:
  trigger: {type: discrete, values: [2t, 4t], show: {2t: "2T", 4t: "4T"}}
  current: {type: numeric, unit: A, ranges: [[10, 150, 5]], initial: 80, wrap: true}
actions:
  press_trigger: {control: trig_key}
  press_up: {control: up_key}
features:
  trigger:
    - {actions: [press_trigger], variable: trigger, effect: next}
  current:
    - {actions: [press_up], variable: current, effect: next}
"""

WELDER_MANUAL = """
TRIGGER MODES
  2T (two-stroke): hold the torch trigger to weld.
  4T (four-stroke / latching): press once to start, once to stop.
"""

TUNER = """
appliance: {id: pocket_tuner_1, category: pocket_tuner, name: "Pitchy T-3 tuner", brand: P}
controls:
  - {id: down_key, kind: button, label: "DROP"}
variables:
  drop: {type: numeric, ranges: [[0, 4, 1]], initial: 0, wrap: true, show: "b{value}"}
actions:
  press_down: {control: down_key}
features:
  drop:
    - {actions: [press_down], variable: drop, effect: next}
"""

TUNER_MANUAL = "DROP lowers the tuning of every string by one semitone per press (b0 to b4)."


def test_a_hyphenated_name_in_brackets_names_the_value() -> None:
    model = loads_model(WELDER)
    goal = parse_instruction(model, "Ninety amps with the four-stroke trigger.", WELDER_MANUAL)
    assert goal == {"current": 90, "trigger": "4t"}
    goal = parse_instruction(model, "Two-stroke, sixty amps.", WELDER_MANUAL)
    assert goal == {"trigger": "2t", "current": 60}


def test_steps_are_counted_in_semitones() -> None:
    model = loads_model(TUNER)
    assert parse_instruction(model, "Drop it a whole step.", TUNER_MANUAL) == {"drop": 2}
    assert parse_instruction(model, "Drop it half a step.", TUNER_MANUAL) == {"drop": 1}


FAN = """
appliance: {id: twin_fan_1, category: twin_fan, name: "Breeze D-2 twin fan", brand: B}
controls:
  - {id: head_switch, kind: switch, label: "HEAD"}
  - {id: move_key, kind: button, label: "MOVE"}
  - {id: speed_key, kind: button, label: "SPEED"}
variables:
  head: {type: discrete, values: ["1", "2"], show: {"1": "H1", "2": "H2"}}
  movement: {type: discrete, values: [fixed, oscillation], show: {fixed: "", oscillation: "OSC"}}
  speed: {type: numeric, ranges: [[1, 5, 1]], initial: 1, wrap: true, show: "S{value}"}
actions:
  slide_head: {control: head_switch}
  press_move: {control: move_key}
  press_speed: {control: speed_key}
features:
  head:
    - {actions: [slide_head], variable: head, effect: next}
  movement:
    - {actions: [press_move], variable: movement, effect: next}
  speed:
    - {actions: [press_speed], variable: speed, effect: next}
"""


def test_a_numbered_things_possessive_keeps_its_number() -> None:
    goal = parse_instruction(loads_model(FAN), "Put head two's speed on 4.")
    assert goal == {"head": "2", "speed": 4}


def test_a_verb_names_its_value_in_ation() -> None:
    goal = parse_instruction(loads_model(FAN), "Let it oscillate at speed 3.")
    assert goal == {"movement": "oscillation", "speed": 3}


GENERATOR = """
appliance: {id: inverter_gen_1, category: inverter_generator, name: "Volta G-2", brand: V}
controls:
  - {id: avr_key, kind: button, label: "AVR"}
  - {id: eco_key, kind: button, label: "ECO"}
variables:
  avr: {type: discrete, values: ["off", "on"], show: {"off": "", "on": "AVR"}}
  eco: {type: discrete, values: ["off", "on"], show: {"off": "", "on": "ECO"}}
actions:
  press_avr: {control: avr_key}
  press_eco: {control: eco_key}
features:
  avr:
    - {actions: [press_avr], variable: avr, effect: toggle}
  eco:
    - {actions: [press_eco], variable: eco, effect: toggle}
"""

GENERATOR_MANUAL = "Press AVR (Automatic Voltage Regulation) to steady the output for tools."


def test_initials_said_as_the_words_the_manual_spells_out() -> None:
    model = loads_model(GENERATOR)
    goal = parse_instruction(model, "Switch on the automatic voltage regulation.", GENERATOR_MANUAL)
    assert goal == {"avr": "on"}
    goal = parse_instruction(model, "Turn the automatic voltage on, eco off.", GENERATOR_MANUAL)
    assert goal == {"avr": "on", "eco": "off"}


MASSAGER = """
appliance: {id: neck_massager_1, category: neck_massager, name: "Knead N-4", brand: K}
controls:
  - {id: power_key, kind: button, label: "⏻"}
  - {id: level_key, kind: button, label: "LEVEL"}
variables:
  power: {type: discrete, values: ["off", "on"], show: {"off": "", "on": "ON"}}
  intensity: {type: discrete, values: ["1", "2", "3", "4", "5"], show: {"1": "L1", "2": "L2",
    "3": "L3", "4": "L4", "5": "L5"}}
actions:
  press_power: {control: power_key}
  press_level: {control: level_key}
features:
  power:
    - {actions: [press_power], variable: power, effect: toggle}
  intensity:
    - {actions: [press_level], variable: intensity, effect: next}
"""


def test_full_power_is_the_top_of_the_one_strength_in_levels() -> None:
    model = loads_model(MASSAGER)
    assert parse_instruction(model, "Give me the massage at full power.")["intensity"] == "5"
    assert parse_instruction(model, "Minimum strength please.")["intensity"] == "1"


RADIO_CLOCK = """
appliance: {id: radio_clock_9, category: radio_clock, name: "Tick R-9", brand: T}
controls:
  - {id: zone_key, kind: button, label: "ZONE"}
variables:
  zone: {type: numeric, unit: h, ranges: [[-6, 6, 1]], initial: 0, wrap: true, show: "{value}"}
actions:
  press_zone: {control: zone_key}
features:
  zone:
    - {actions: [press_zone], variable: zone, effect: next}
"""


def test_a_direction_said_after_the_number_counts_down() -> None:
    model = loads_model(RADIO_CLOCK)
    assert parse_instruction(model, "Set the zone three hours behind.") == {"zone": -3}
    assert parse_instruction(model, "Set the zone three hours ahead.") == {"zone": 3}
