"""Programme values that hold a quantity: "a 6-volt battery" for 6V STANDARD (a number glued
to its unit), "ninety minutes of timed drying" for TIMED 90. Checked on a charger and a dryer
written for these tests."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction

CHARGER = """
appliance: {id: charger_1, category: charger, name: "Voltix C-8 charger", brand: V}
controls:
  - {id: mode_button, kind: button, label: "MODE"}
  - {id: hours_button, kind: button, label: "HOURS"}
variables:
  mode:
    type: discrete
    values: [12v standard, 12v gel, 6v standard, recondition]
  hours:
    type: numeric
    unit: h
    ranges: [[0, 12, 1]]
actions:
  press_mode: {control: mode_button}
  press_hours: {control: hours_button}
features:
  mode:
    - {actions: [press_mode], variable: mode, effect: next}
  hours:
    - {actions: [press_hours], variable: hours, effect: next}
display:
  idle: ""
"""

DRYER = """
appliance: {id: dryer_9, category: tumble_dryer, name: "Dryo 9", brand: D}
controls:
  - {id: prog_knob, kind: knob, label: "PROGRAMME"}
  - {id: end_button, kind: button, label: "END IN"}
variables:
  programme:
    type: discrete
    values: [cottons, wool, timed 20, timed 40, timed 80]
  end_in:
    type: numeric
    unit: h
    ranges: [[0, 9, 1]]
    label: "END IN"
actions:
  turn_prog: {control: prog_knob}
  press_end: {control: end_button}
features:
  programme:
    - {actions: [turn_prog], variable: programme, effect: next}
  end_in:
    - {actions: [press_end], variable: end_in, effect: next}
display:
  idle: ""
"""


def test_a_number_glued_to_its_unit_is_said_in_words() -> None:
    charger = loads_model(CHARGER)
    assert parse_instruction(charger, "Charge my 6-volt battery for 5 hours") == {
        "mode": "6v standard",
        "hours": 5,
    }
    assert parse_instruction(charger, "six volts, 3 hours") == {"mode": "6v standard", "hours": 3}
    assert "mode" not in parse_instruction(charger, "a 12 volt battery for 4 hours")  # 2 values


def test_a_quantity_shared_by_several_values_is_no_timer() -> None:
    """ "a 12-volt gel battery": GEL picks among the 12 V values, and the 12 volts are never
    read as 12 hours (review2: the timer got 12 h)."""
    charger = loads_model(CHARGER)
    assert parse_instruction(charger, "charge my 12-volt car battery, it's a gel type") == {
        "mode": "12v gel"
    }
    assert parse_instruction(charger, "a 12-volt gel battery") == {"mode": "12v gel"}
    assert parse_instruction(charger, "a 12 volt battery for 4 hours") == {"hours": 4}


def test_a_programme_holding_minutes_is_named_by_a_duration_beside_its_word() -> None:
    dryer = loads_model(DRYER)
    assert parse_instruction(dryer, "Forty minutes of timed drying, done in 3 hours") == {
        "programme": "timed 40",
        "end_in": 3,
    }
    assert parse_instruction(dryer, "timed drying for an hour and 20 minutes")["programme"] == (
        "timed 80"
    )
