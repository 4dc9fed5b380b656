"""Small models the fault-kind tests mutate, and helpers to run presses on them."""

from __future__ import annotations

import random
from collections.abc import Callable
from typing import Any

from apbot.bench.faults import Fault, Kind
from apbot.bench.faults.common import valid
from apbot.model.schema import ApplianceModel
from apbot.model.validate import check_model
from apbot.sim.simulator import Observation, Simulator
from tests.helpers import model_from

OVEN = """
controls:
  - {id: power_button, label: POWER}
  - {id: mode_button, label: MODE}
  - {id: temp_button, label: TEMP}
  - {id: up_button, label: "▲"}
  - {id: down_button, label: "▼"}
  - {id: timer_button, label: TIMER}
  - {id: start_button, label: START}
  - {id: stop_button, label: STOP}
variables:
  power: {type: discrete, values: ["off", "on"]}
  mode: {type: discrete, values: [bake, grill, defrost, steam]}
  temperature:
    type: numeric
    unit: "°C"
    depends_on: mode
    label: TEMPERATURE
    cases:
      bake: {ranges: [[100, 200, 20]], initial: 180}
      grill: {ranges: [[150, 250, 50]], initial: 200}
  delay: {type: numeric, unit: h, ranges: [[0, 6, 1]], show: "DL{value}"}
  running: {type: discrete, values: ["off", "on"]}
actions:
  press_power: {control: power_button}
  press_mode: {control: mode_button}
  press_temp: {control: temp_button}
  press_up: {control: up_button}
  press_down: {control: down_button}
  press_timer: {control: timer_button}
  press_start: {control: start_button}
  press_stop: {control: stop_button}
features:
  power:
    - {actions: [press_power], variable: power, effect: toggle, set: {running: "off"},
       reset: [mode, delay]}
  set_mode:
    - {actions: [press_mode], variable: mode, effect: next}
  set_temperature:
    - {actions: [press_temp]}
    - actions: [press_up, press_down]
      variable: temperature
      effect: {press_up: next, press_down: prev}
  set_delay:
    - {actions: [press_timer], variable: delay, effect: next}
  start:
    - {actions: [press_start], variable: running, effect: {to: "on"}}
  stop:
    - {actions: [press_stop], variable: running, effect: {to: "off"}, reset: [delay]}
guards:
  - {name: power off, when: {power: "off"}, only: [press_power], display: "", hide: true}
  - {name: running, when: {running: "on"}, only: [press_stop, press_power], display: "RUN"}
display:
  idle: "{mode}"
"""

KEYPAD = """
controls:
  - {id: time_pad, label: TIME}
  - {id: start_pad, label: START}
  - {id: key_0, kind: key, label: "0"}
  - {id: key_1, kind: key, label: "1"}
  - {id: key_2, kind: key, label: "2"}
  - {id: key_3, kind: key, label: "3"}
  - {id: key_4, kind: key, label: "4"}
  - {id: key_5, kind: key, label: "5"}
  - {id: key_6, kind: key, label: "6"}
  - {id: key_7, kind: key, label: "7"}
  - {id: key_8, kind: key, label: "8"}
  - {id: key_9, kind: key, label: "9"}
variables:
  cook_time:
    type: time
    ranges: [["00:00:00", "01:00:00", 60]]
    format: "mm:ss"
    entry: {format: "mm:ss"}
    label: COOK
  running: {type: discrete, values: ["off", "on"]}
actions:
  press_time: {control: time_pad}
  press_start: {control: start_pad}
  press_0: {control: key_0, digit: 0}
  press_1: {control: key_1, digit: 1}
  press_2: {control: key_2, digit: 2}
  press_3: {control: key_3, digit: 3}
  press_4: {control: key_4, digit: 4}
  press_5: {control: key_5, digit: 5}
  press_6: {control: key_6, digit: 6}
  press_7: {control: key_7, digit: 7}
  press_8: {control: key_8, digit: 8}
  press_9: {control: key_9, digit: 9}
features:
  set_time:
    - {actions: [press_time]}
    - actions: [press_0, press_1, press_2, press_3, press_4, press_5, press_6, press_7, press_8,
                press_9]
      variable: cook_time
    - {actions: [press_start], variable: running, effect: {to: "on"}}
display:
  idle: "{cook_time}"
"""


def oven() -> ApplianceModel:
    return model_from(OVEN)


def keypad() -> ApplianceModel:
    return model_from(KEYPAD)


def every_candidate(
    kind: Kind, model: ApplianceModel, name: str, seeds: int = 4
) -> list[tuple[ApplianceModel, Fault]]:
    """Every valid candidate the kind offers at a site, over a few generator seeds (each one
    passes the checker: a kind never offers an invalid model the injector would keep)."""
    found: dict[str, tuple[ApplianceModel, Fault]] = {}
    for seed in range(seeds):
        for data, fault in kind(model, name, random.Random(seed)):
            faulty = valid(data)
            if faulty is not None:
                found.setdefault(str(fault), (faulty, fault))
    return list(found.values())


def only(
    candidates: list[tuple[ApplianceModel, Fault]], test: Callable[[Fault], bool]
) -> tuple[ApplianceModel, Fault]:
    """The one candidate whose fault passes ``test`` (the test names which candidate)."""
    chosen = [c for c in candidates if test(c[1])]
    assert chosen, [str(f) for _, f in candidates]
    return chosen[0]


def errors(model: ApplianceModel) -> list[str]:
    return [p.render() for p in check_model(model) if p.severity == "error"]


def press(model: ApplianceModel, actions: list[str]) -> tuple[Simulator, Observation]:
    """The simulator after the presses, and the last observation."""
    sim = Simulator(model)
    seen = sim.observe()
    for action in actions:
        seen = sim.step(action)
    return sim, seen


def value(model: ApplianceModel, actions: list[str], name: str) -> Any:
    return press(model, actions)[0].value(name)


def shown(model: ApplianceModel, actions: list[str]) -> str:
    return press(model, actions)[1].text
