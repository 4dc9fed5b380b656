"""One-touch positions named for all they set, a schedule armed by its closing OK, an hour
written on a 12-hour clock, and times said as two numbers in words — on models written for
these tests (a recliner armchair and a pool-cleaning robot no suite has)."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction
from apbot.read.goal_text import Text
from apbot.read.numbers import find_mentions

RECLINER = """
appliance: {id: recliner_1, category: recliner, name: "Restwell R2 power recliner", brand: R}
controls:
  - {id: back_up, kind: button, label: "BACK +"}
  - {id: back_down, kind: button, label: "BACK -"}
  - {id: rest_up, kind: button, label: "REST +"}
  - {id: rest_down, kind: button, label: "REST -"}
  - {id: nap_key, kind: button, label: "NAP"}
  - {id: home_key, kind: button, label: "UPRIGHT"}
  - {id: heat_key, kind: button, label: "HEAT"}
variables:
  back: {type: numeric, unit: "°", ranges: [[0, 50, 5]]}
  footrest: {type: numeric, unit: "°", ranges: [[0, 30, 5]]}
  heat: {type: discrete, values: ["off", "on"]}
actions:
  press_back_up: {control: back_up}
  press_back_down: {control: back_down}
  press_rest_up: {control: rest_up}
  press_rest_down: {control: rest_down}
  press_nap: {control: nap_key}
  press_home: {control: home_key}
  press_heat: {control: heat_key}
features:
  back:
    - actions: [press_back_up, press_back_down]
      variable: back
      effect: {press_back_up: next, press_back_down: prev}
  footrest:
    - actions: [press_rest_up, press_rest_down]
      variable: footrest
      effect: {press_rest_up: next, press_rest_down: prev}
  nap:
    - {actions: [press_nap], variable: back, effect: {to: 40}, set: {footrest: 25}}
  upright:
    - {actions: [press_home], variable: back, effect: {to: 0}}
  heat:
    - {actions: [press_heat], variable: heat, effect: toggle}
"""

POOL_ROBOT = """
appliance: {id: pool_bot_1, category: pool_robot, name: "AquaSweep 3 pool robot", brand: A}
controls:
  - {id: go_key, kind: button, label: "GO"}
  - {id: timer_key, kind: button, label: "TIMER"}
  - {id: plus_key, kind: button, label: "+"}
  - {id: minus_key, kind: button, label: "-"}
  - {id: ok_key, kind: button, label: "OK"}
variables:
  status: {type: discrete, values: [idle, cleaning]}
  timer_hour:
    type: discrete
    values: ["12 AM", "1 AM", "2 AM", "3 AM", "4 AM", "5 AM", "6 AM", "7 AM", "8 AM", "9 AM",
             "10 AM", "11 AM", "12 PM", "1 PM", "2 PM", "3 PM", "4 PM", "5 PM", "6 PM", "7 PM",
             "8 PM", "9 PM", "10 PM", "11 PM"]
    initial: "8 AM"
  timer_minute: {type: numeric, ranges: [[0, 45, 15]], unit: min}
  timer: {type: discrete, values: ["off", "on"]}
actions:
  press_go: {control: go_key}
  press_timer: {control: timer_key}
  hold_timer: {control: timer_key, skill: hold, seconds: 3}
  press_plus: {control: plus_key}
  press_minus: {control: minus_key}
  press_ok: {control: ok_key}
features:
  go:
    - {actions: [press_go], variable: status, effect: {to: cleaning}}
  timer:
    - {actions: [press_timer]}
    - actions: [press_plus, press_minus]
      variable: timer_hour
      effect: {press_plus: next, press_minus: prev}
    - {actions: [press_ok]}
    - actions: [press_plus, press_minus]
      variable: timer_minute
      effect: {press_plus: next, press_minus: prev}
    - {actions: [press_ok], variable: timer, effect: {to: "on"}}
  timer_off:
    - {actions: [hold_timer], variable: timer, effect: {to: "off"}}
"""


def test_a_named_position_asks_for_all_it_sets() -> None:
    model = loads_model(RECLINER)
    goal = parse_instruction(model, "Put me in the nap position and warm the seat.")
    assert goal["back"] == 40 and goal["footrest"] == 25


def test_a_position_key_said_with_its_own_value_keeps_the_value_said() -> None:
    model = loads_model(RECLINER)
    goal = parse_instruction(model, "Nap, but the footrest at 10 degrees.")
    assert goal["back"] == 40 and goal["footrest"] == 10


def test_a_key_without_companions_adds_nothing() -> None:
    model = loads_model(RECLINER)
    assert parse_instruction(model, "Upright please.") == {"back": 0}


def test_a_last_word_cut_to_its_initial_names_the_key() -> None:
    model = loads_model(RECLINER.replace('"NAP"', '"NAP P"'))
    goal = parse_instruction(model, "The nap position, please.")
    assert goal["back"] == 40 and goal["footrest"] == 25


def test_a_twelve_hour_clock_hour_and_its_arming_ok() -> None:
    model = loads_model(POOL_ROBOT)
    goal = parse_instruction(model, "Have it sweep the pool each afternoon at 3:45 pm.")
    assert goal == {"timer_hour": "3 PM", "timer_minute": 45, "timer": "on"}


def test_the_key_that_cancels_a_schedule_is_not_named_by_its_label() -> None:
    model = loads_model(POOL_ROBOT)
    goal = parse_instruction(model, "Timer for six fifteen in the evening.")
    assert goal == {"timer_hour": "6 PM", "timer_minute": 15, "timer": "on"}


def test_times_said_in_words() -> None:
    def clocks(sentence: str) -> list[float]:
        text = Text.of(sentence)
        return [m.value for m in find_mentions(text.tokens) if m.kind == "clock"]

    assert clocks("wake me at six forty-five") == [6 * 3600 + 45 * 60]
    assert clocks("a quarter past midnight") == [15 * 60]
    assert clocks("eight twenty in the evening") == [20 * 3600 + 20 * 60]
    assert clocks("cook it for two fifteen minutes") == []


def test_a_name_then_at_binds_the_number_after_it() -> None:
    model = loads_model(RECLINER)
    goal = parse_instruction(model, "Footrest raised to twenty degrees, back at forty-five.")
    assert goal == {"back": 45, "footrest": 20}
    goal = parse_instruction(model, "Put up to 25 degrees, back at 10, the footrest.")
    assert goal["back"] == 10


POOL_LEVELS = POOL_ROBOT.replace(
    "  status: {type: discrete, values: [idle, cleaning]}",
    "  status: {type: discrete, values: [idle, cleaning]}\n"
    '  brush: {type: discrete, values: ["off", low, medium, high]}',
).replace(
    "  go:\n",
    "  brush:\n    - {actions: [press_minus], variable: brush, effect: next}\n  go:\n",
)


def test_a_little_of_a_setting_is_its_least_working_level() -> None:
    model = loads_model(POOL_LEVELS)
    assert parse_instruction(model, "Sweep with a little brush.")["brush"] == "low"
    assert parse_instruction(model, "Sweep with a bit of brush.")["brush"] == "low"
