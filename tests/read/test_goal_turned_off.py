""" "Turn off" said of a setting with one OFF value: "turn off the automatic watering" (an
adjective between) sets its OFF level, and a value said right after "turn off" ("turn off
automatic watering" where the schedule is AUTO / OFF) names what is switched off. A small
garden-timer model written for these tests."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction

TIMER = """
appliance: {id: tap_1, category: garden_timer, name: "Drip T-1 tap timer", brand: D}
controls:
  - {id: water_key, kind: button, label: "WATERING"}
  - {id: plan_key, kind: button, label: "PLAN"}
variables:
  watering:
    type: discrete
    values: ["off", "1", "2", "3"]
    show: {"off": "W OFF", "1": "W 1", "2": "W 2", "3": "W 3"}
  plan:
    type: discrete
    values: [auto, "off"]
    show: {auto: "AUTO", "off": "OFF"}
actions:
  press_water: {control: water_key}
  press_plan: {control: plan_key}
features:
  watering:
    - {actions: [press_water], variable: watering, effect: next}
  plan:
    - {actions: [press_plan], variable: plan, effect: toggle}
"""


def _goal(text: str) -> dict[str, object]:
    return parse_instruction(loads_model(TIMER), text)


def test_turn_off_the_adjective_setting_is_its_off_level() -> None:
    assert _goal("turn off the daily watering")["watering"] == "off"


def test_a_value_said_right_after_turn_off_is_switched_off() -> None:
    assert _goal("turn off auto, please") == {"plan": "off"}
    assert _goal("put the plan on auto") == {"plan": "auto"}
