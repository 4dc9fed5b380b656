"""Rules of the goal parser checked on small models written for these tests: a setting that
only a switch lets the user set implies that switch on; "every other day" and its kin are a
number of days or hours; an end of a scale is taken in the unit the panel shows, and the unit
it starts in, said beside it, is no request; "the slowest setting" is the first step of a
setting named for its speed."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction
from apbot.read.goal_error import GoalParseError

CLEANER = """
appliance: {id: cleaner_1, category: cleaner, name: "Sonix C-1 cleaner", brand: S}
controls:
  - {id: heat_button, kind: button, label: "HEAT"}
  - {id: up_button, kind: button, label: "▲"}
  - {id: sweep_button, kind: button, label: "SWEEP"}
variables:
  heater:
    type: discrete
    values: ["off", "on"]
    show: {"off": "", "on": "HEAT"}
  temperature:
    type: numeric
    unit: "°C"
    depends_on: heater
    wrap: true
    cases:
      "on": {ranges: [[30, 80, 5]], initial: 50}
  sweep:
    type: discrete
    values: ["off", "on"]
    show: {"off": "", "on": "SWEEP"}
actions:
  press_heat: {control: heat_button}
  press_up: {control: up_button}
  press_sweep: {control: sweep_button}
features:
  heater:
    - {actions: [press_heat], variable: heater, effect: toggle}
  temperature:
    - {actions: [press_up], variable: temperature, effect: next}
  sweep:
    - {actions: [press_sweep], variable: sweep, effect: toggle}
display:
  idle: "{temperature}"
"""

SPA = """
appliance: {id: spa_1, category: foot_spa, name: "Pedi S-2 foot spa", brand: P}
controls:
  - {id: heat_key, kind: touch, label: "HEAT"}
  - {id: up_key, kind: touch, label: "▲"}
  - {id: jet_key, kind: touch, label: "JETS"}
variables:
  heat:
    type: discrete
    values: ["off", "on"]
    show: {"off": "", "on": "HEAT"}
  unit:
    type: discrete
    values: [celsius, fahrenheit]
    show: {celsius: "°C", fahrenheit: "°F"}
  temperature:
    type: numeric
    depends_on: unit
    wrap: true
    cases:
      celsius: {ranges: [[35, 48, 1]], initial: 40}
      fahrenheit: {ranges: [[95, 118, 1]], initial: 104}
  jets:
    type: discrete
    values: ["off", "on"]
    show: {"off": "", "on": "JETS"}
actions:
  press_heat: {control: heat_key}
  hold_heat: {control: heat_key, skill: hold, seconds: 3}
  press_up: {control: up_key}
  press_jets: {control: jet_key}
features:
  heat:
    - {actions: [press_heat], variable: heat, effect: toggle}
  unit:
    - {actions: [hold_heat], variable: unit, effect: toggle}
  temperature:
    - {actions: [press_up], variable: temperature, effect: next}
  jets:
    - {actions: [press_jets], variable: jets, effect: toggle}
guards:
  - name: heating off
    when: {heat: "off"}
    only: [press_heat, hold_heat, press_jets]
    display: "HEAT"
display:
  idle: "{temperature}"
"""

SPRINKLER = """
appliance: {id: sprinkler_1, category: sprinkler, name: "Rainy R-1 sprinkler timer", brand: R}
controls:
  - {id: often_button, kind: button, label: "HOW OFTEN"}
variables:
  interval:
    type: discrete
    values: [every day, every 2 days, every 3 days, every 7 days]
    show: {every day: "24H", every 2 days: "2D", every 3 days: "3D", every 7 days: "7D"}
actions:
  press_often: {control: often_button}
features:
  interval:
    - {actions: [press_often], variable: interval, effect: next}
display:
  idle: "{interval}"
"""

MISTER = """
appliance: {id: mister_1, category: mister, name: "Nebbi M-1 greenhouse mister", brand: N}
controls:
  - {id: mist_button, kind: button, label: "MIST"}
variables:
  mist:
    type: discrete
    values: ["off", "1 d", "2 d", "4 d"]
    show: {"off": "M OFF", "1 d": "M 1d", "2 d": "M 2d", "4 d": "M 4d"}
actions:
  press_mist: {control: mist_button}
features:
  mist:
    - {actions: [press_mist], variable: mist, effect: next}
display:
  idle: "{mist}"
"""

HATCHER = """
appliance: {id: hatcher_1, category: incubator, name: "Brood B-1 incubator", brand: B}
controls:
  - {id: turn_button, kind: button, label: "TURN"}
variables:
  turn_interval:
    type: numeric
    unit: h
    ranges: [[1, 12, 1]]
    initial: 2
    wrap: true
actions:
  press_turn: {control: turn_button}
features:
  turn_interval:
    - {actions: [press_turn], variable: turn_interval, effect: next}
display:
  idle: "{turn_interval}"
"""

MIXER = """
appliance: {id: mixer_1, category: mixer, name: "Kneady K-1 mixer", brand: K}
controls:
  - {id: minus_key, kind: touch, label: "-"}
  - {id: soft_key, kind: touch, label: "SOFT"}
variables:
  speed:
    type: numeric
    ranges: [[1, 10, 1]]
    initial: 4
    wrap: true
  soft_start:
    type: numeric
    ranges: [[1, 2, 1]]
    initial: 1
    wrap: true
actions:
  press_minus: {control: minus_key}
  press_soft: {control: soft_key}
features:
  speed:
    - {actions: [press_minus], variable: speed, effect: prev}
  soft_start:
    - {actions: [press_soft], variable: soft_start, effect: next}
display:
  idle: "{speed}"
"""


def _goal(model: str, text: str) -> dict[str, object]:
    return parse_instruction(loads_model(model), text)


def test_a_setting_kept_only_while_a_switch_is_on_implies_the_switch() -> None:
    assert _goal(CLEANER, "Heat the bath to 60 degrees with the sweep on") == {
        "temperature": 60,
        "heater": "on",
        "sweep": "on",
    }
    assert _goal(CLEANER, "Sweep on") == {"sweep": "on"}


def test_a_setting_whose_keys_a_switch_refuses_implies_the_switch() -> None:
    assert _goal(SPA, "Water at 42 degrees with the jets") == {
        "temperature": 42,
        "heat": "on",
        "jets": "on",
    }
    assert _goal(SPA, "Jets on") == {"jets": "on"}


def test_how_often_said_in_words_is_a_number() -> None:
    assert _goal(SPRINKLER, "every other day") == {"interval": "every 2 days"}
    assert _goal(SPRINKLER, "every third day, please") == {"interval": "every 3 days"}
    assert _goal(SPRINKLER, "once a week") == {"interval": "every 7 days"}
    assert _goal(SPRINKLER, "every day") == {"interval": "every day"}  # its own name
    assert _goal(HATCHER, "turn the eggs every hour") == {"turn_interval": 1}


def test_choices_counted_in_days_are_how_often() -> None:
    assert _goal(MISTER, "mist the seedlings every day") == {"mist": "1 d"}
    assert _goal(MISTER, "mist every other day") == {"mist": "2 d"}
    assert _goal(MISTER, "mist every 4 days") == {"mist": "4 d"}


def test_an_end_of_the_scale_in_the_unit_the_panel_shows() -> None:
    assert _goal(SPA, "As hot as it goes")["temperature"] == 48
    goal = _goal(SPA, "As hot as it goes in Celsius")
    assert goal["temperature"] == 48 and "unit" not in goal


def test_the_slowest_setting_is_the_first_speed() -> None:
    assert _goal(MIXER, "Mix on the slowest setting") == {"speed": 1}


WASHER = """
appliance: {id: washer_1, category: washer, name: "Sudsy W-1 washer", brand: W}
controls:
  - {id: prog_button, kind: button, label: "PROGRAMME"}
  - {id: spin_button, kind: button, label: "SPIN"}
  - {id: delay_button, kind: button, label: "DELAY"}
variables:
  programme:
    type: discrete
    values: [cotton, synthetics, quick, wool]
  spin_speed:
    type: numeric
    unit: rpm
    ranges: [[400, 1400, 200]]
    initial: 1000
    wrap: true
  delay:
    type: time
    ranges: [["00:00:00", "24:00:00", 3600]]
    initial: "00:00:00"
    wrap: true
actions:
  press_prog: {control: prog_button}
  press_spin: {control: spin_button}
  press_delay: {control: delay_button}
features:
  programme:
    - {actions: [press_prog], variable: programme, effect: next}
  spin_speed:
    - {actions: [press_spin], variable: spin_speed, effect: next}
  delay:
    - {actions: [press_delay], variable: delay, effect: next}
display:
  idle: "{programme}"
"""


def test_a_switch_said_off_is_not_implied_on() -> None:
    # "heat" is too general a word for the switch reader; said off, it still is no "on"
    assert _goal(SPA, "Switch off the heat; 42 degrees is fine") == {"temperature": 42}
    assert _goal(CLEANER, "Without heating, sweep at 50 degrees") == {
        "temperature": 50,
        "sweep": "on",
    }


def test_how_often_is_a_habit_on_a_panel_with_no_interval() -> None:
    assert _goal(WASHER, "I wash every day, so cotton please") == {"programme": "cotton"}
    assert _goal(WASHER, "Cotton, it is the wash I do every other day") == {"programme": "cotton"}


def test_as_fast_as_possible_is_a_hurry_and_the_fastest_programme_no_speed() -> None:
    assert _goal(WASHER, "Cotton, as fast as possible") == {"programme": "cotton"}
    assert _goal(WASHER, "Quick wash at the slowest spin") == {
        "programme": "quick",
        "spin_speed": 400,
    }
    try:  # the programme has no fastest: an error asking which, never the spin's top speed
        goal = _goal(WASHER, "The fastest programme, with a 2 hour delay")
    except GoalParseError:
        goal = {}
    assert "spin_speed" not in goal
