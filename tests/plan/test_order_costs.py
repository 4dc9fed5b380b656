"""Among plans of the same length, the one in the order people operate an appliance — the run
started last, the clock set before a finish time — whatever order the actions are listed in
(apbot.plan.order_costs, apbot.sim.action_order)."""

from __future__ import annotations

from typing import Any

import yaml

from apbot.model.load import loads_model
from apbot.plan.plan import plan

HOB = """
appliance: {id: hob_9, category: hot_plate, name: "Plato HP-9", brand: P}
controls:
  - {id: start_button, kind: button, label: "START"}
  - {id: temp_button, kind: button, label: "TEMP"}
  - {id: clock_button, kind: button, label: "CLOCK"}
  - {id: ready_button, kind: button, label: "READY AT"}
  - {id: up_button, kind: button, label: "+"}
variables:
  running:
    type: discrete
    values: ["off", "on"]
  temp:
    type: numeric
    unit: "°C"
    ranges: [[60, 100, 20]]
    initial: 60
  clock:
    type: time
    ranges: [["00:00:00", "23:00:00", 3600]]
    wrap: true
  ready_at:
    type: time
    ranges: [["00:00:00", "23:00:00", 3600]]
    wrap: true
actions:
  press_start: {control: start_button}
  press_temp: {control: temp_button}
  press_clock: {control: clock_button}
  press_ready: {control: ready_button}
  press_up: {control: up_button}
features:
  start:
    - {actions: [press_start], variable: running, effect: toggle}
  set_temp:
    - {actions: [press_temp]}
    - {actions: [press_up], variable: temp, effect: next}
  set_clock:
    - {actions: [press_clock]}
    - {actions: [press_up], variable: clock, effect: next}
  set_ready_at:
    - {actions: [press_ready]}
    - {actions: [press_up], variable: ready_at, effect: next}
display:
  idle: "{temp}"
"""


def _listed(order: list[str]) -> Any:
    """The model with its actions (and features) listed in ``order`` of the action names."""
    data = yaml.safe_load(HOB)
    data["actions"] = {name: data["actions"][name] for name in order}
    by_action = {steps[0]["actions"][0]: f for f, steps in data["features"].items()}
    data["features"] = {
        by_action[a]: data["features"][by_action[a]] for a in order if a in by_action
    }
    return loads_model(yaml.safe_dump(data, sort_keys=False))


ORDERS = [
    ["press_start", "press_temp", "press_clock", "press_ready", "press_up"],
    ["press_up", "press_ready", "press_clock", "press_temp", "press_start"],
]


def test_the_run_is_started_after_the_settings_in_any_listing() -> None:
    for order in ORDERS:
        found = plan(_listed(order), None, {"temp": 100, "running": "on"})
        assert [m.feature for m in found.macro_actions] == ["set_temp", "start"]


def test_the_clock_is_set_before_a_finish_time_in_any_listing() -> None:
    for order in ORDERS:
        found = plan(_listed(order), None, {"ready_at": "07:00", "clock": "02:00"})
        assert [m.feature for m in found.macro_actions] == ["set_clock", "set_ready_at"]
