"""How people name moving air: circulation and ventilation are the fan (a FAN mode, an AIR
switch), checked on a cheese-ripening cabinet written for these tests."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.model.schema import ApplianceModel
from apbot.read.goal import parse_instruction
from tests.helpers import model_from

CABINET = """
appliance: {id: cave_1, category: cheese_cabinet, name: "Affine CC-2 ripening cabinet", brand: A}
controls:
  - {id: mode_button, kind: button, label: "MODE"}
  - {id: air_button, kind: button, label: "AIR"}
  - {id: up_button, kind: button, label: "+"}
  - {id: down_button, kind: button, label: "-"}
variables:
  mode:
    type: discrete
    values: [chill, fan, mist]
  air:
    type: discrete
    values: ["off", "on"]
    show: {"off": "", "on": "AIR"}
  temperature:
    type: numeric
    unit: "°C"
    ranges: [[6, 16, 1]]
    initial: 12
actions:
  press_mode: {control: mode_button}
  press_air: {control: air_button}
  press_up: {control: up_button}
  press_down: {control: down_button}
features:
  mode:
    - {actions: [press_mode], variable: mode, effect: next}
  air:
    - {actions: [press_air], variable: air, effect: toggle}
  temperature:
    - actions: [press_up, press_down]
      variable: temperature
      effect: {press_up: next, press_down: prev}
display:
  idle: "{temperature}"
"""


def _model(modes: str = "chill, dry, mist") -> ApplianceModel:
    return loads_model(CABINET.replace("chill, fan, mist", modes))


def test_ventilation_names_the_air_switch() -> None:
    goal = parse_instruction(_model(), "10 degrees, and switch the ventilation on")
    assert goal == {"temperature": 10, "air": "on"}


def test_circulation_names_the_air_switch() -> None:
    goal = parse_instruction(_model(), "Keep the air circulation off and hold it at 8 °C")
    assert goal == {"air": "off", "temperature": 8}


def test_circulating_names_the_fan_mode() -> None:
    goal = parse_instruction(_model("chill, fan, mist"), "Only circulate, no chilling")
    assert goal == {"mode": "fan"}


FOUNTAIN = """
appliance: {id: fountain_1, category: chocolate_fountain, name: "Cascade CF-1 fountain", brand: C}
controls:
  - {id: start_button, kind: button, label: "START"}
  - {id: flow_button, kind: button, label: "FLOW"}
variables:
  flow:
    type: discrete
    values: [gentle, strong]
  running:
    type: discrete
    values: ["off", "on"]
    show: {"off": "", "on": "RUN"}
actions:
  press_start: {control: start_button}
  press_flow: {control: flow_button}
features:
  flow:
    - {actions: [press_flow], variable: flow, effect: next}
  start:
    - {actions: [press_start], variable: running, effect: toggle}
display:
  idle: "{flow}"
"""


def test_get_it_moving_starts_it() -> None:
    fountain = loads_model(FOUNTAIN)
    assert parse_instruction(fountain, "Strong flow, and get it moving") == {
        "flow": "strong",
        "running": "on",
    }
    assert parse_instruction(fountain, "Gentle flow; get the tower turning now.") == {
        "flow": "gentle",
        "running": "on",
    }


def test_let_it_run_starts_it() -> None:
    fountain = loads_model(FOUNTAIN)
    goal = parse_instruction(fountain, "Let it run until the guests leave, strong flow")
    assert goal == {"flow": "strong", "running": "on"}


def test_other_gets_and_lets_start_nothing() -> None:
    fountain = loads_model(FOUNTAIN)
    goal = parse_instruction(fountain, "Strong flow, then get the setting saved")
    assert goal == {"flow": "strong"}
    assert parse_instruction(fountain, "Let the kids run around, gentle flow") == {"flow": "gentle"}


def test_letting_water_run_until_clear_is_a_rinse_not_a_start() -> None:
    fountain = loads_model(FOUNTAIN)
    goal = parse_instruction(fountain, "Let the water run until it comes out clear, gentle flow")
    assert goal == {"flow": "gentle"}


def test_a_fan_word_naming_an_opening_of_the_body_sets_no_switch() -> None:
    """'Ventilation' and 'circulation' name the fan switch, but "the ventilation slots" or
    "the air circulation vents" in a cleaning remark are openings of the body: no switch."""
    cooler = model_from(
        """
        controls: [{id: fan, label: FAN}, {id: up, label: "+"}, {id: down, label: "-"}]
        variables:
          fan: {type: discrete, values: ["off", "on"], label: FAN}
          cold: {type: numeric, ranges: [[1, 7, 1]], initial: 4, label: COLD}
        actions:
          press_fan: {control: fan}
          press_up: {control: up}
          press_down: {control: down}
        features:
          fan:
            - {actions: [press_fan], variable: fan, effect: next}
          cold:
            - actions: [press_up, press_down]
              variable: cold
              effect: {press_up: next, press_down: prev}
        """
    )
    for said in (
        "Don't block the ventilation slots. Cold at 3",
        "Cold at 3, then dust the air circulation vents",
    ):
        assert "fan" not in parse_instruction(cooler, said), said
    assert parse_instruction(cooler, "Cold at 3 with the ventilation on")["fan"] == "on"
