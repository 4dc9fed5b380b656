"""A setting named by a general word that only its own name has: a HEAT switch beside a
TEMPERATURE is named by "heating on" or "heat it to 30", and a WATER level beside a SEAT level
by "the water off" — though "heat" and "water" are words most settings could share. A negated
mention ("hold off the heating") names no switch. Checked on a pool-heater panel and a
two-level warmer written for these tests."""

from __future__ import annotations

import pytest

from apbot.model.load import loads_model
from apbot.model.schema import ApplianceModel
from apbot.read.goal import parse_instruction

POOL = """
appliance: {id: pool_1, category: pool_heater, name: "Lido P2 pool heater", brand: L}
controls:
  - {id: heat_button, kind: button, label: "HEAT"}
  - {id: up_button, kind: button, label: "▲"}
  - {id: pump_button, kind: button, label: "PUMP"}
variables:
  heat:
    type: discrete
    values: ["off", "on"]
  temperature:
    type: numeric
    ranges: [[20, 35, 1]]
    unit: "°C"
  pump:
    type: discrete
    values: ["off", "on"]
actions:
  press_heat: {control: heat_button}
  press_up: {control: up_button}
  press_pump: {control: pump_button}
features:
  heat:
    - {actions: [press_heat], variable: heat, effect: toggle}
  temperature:
    - {actions: [press_up], variable: temperature, effect: next}
  pump:
    - {actions: [press_pump], variable: pump, effect: toggle}
display:
  idle: ""
"""

WARMER = """
appliance: {id: warmer_1, category: seat_warmer, name: "Tepa W2 warmer", brand: T}
controls:
  - {id: water_button, kind: button, label: "WATER"}
  - {id: seat_button, kind: button, label: "SEAT"}
variables:
  water_level:
    type: discrete
    values: ["off", low, high]
  seat_level:
    type: discrete
    values: ["off", low, high]
actions:
  press_water: {control: water_button}
  press_seat: {control: seat_button}
features:
  water_level:
    - {actions: [press_water], variable: water_level, effect: next}
  seat_level:
    - {actions: [press_seat], variable: seat_level, effect: next}
display:
  idle: ""
"""


@pytest.fixture(scope="module")
def pool() -> ApplianceModel:
    return loads_model(POOL)


@pytest.mark.parametrize(
    "text",
    ["Heating on at 28 °C.", "Heat it to 30 degrees, please.", "Keep the pool heated at 27."],
)
def test_heat_names_the_heat_switch(pool: ApplianceModel, text: str) -> None:
    assert parse_instruction(pool, text).get("heat") == "on"


def test_a_negated_heating_names_no_switch(pool: ApplianceModel) -> None:
    assert "heat" not in parse_instruction(pool, "Hold off the heating for now, pump on.")


def test_the_water_off_is_the_water_level(pool: ApplianceModel) -> None:
    goal = parse_instruction(loads_model(WARMER), "Water off and the seat on high.")
    assert goal == {"water_level": "off", "seat_level": "high"}


LOAVES = """
appliance: {id: loaves_1, category: bread_maker, name: "Mika B1 bread maker", brand: M}
controls:
  - {id: loaf_button, kind: button, label: "LOAF"}
  - {id: menu_button, kind: button, label: "MENU"}
variables:
  loaf:
    type: discrete
    values: ["off", "on"]
  menu:
    type: discrete
    values: [basic, french]
actions:
  press_loaf: {control: loaf_button}
  press_menu: {control: menu_button}
features:
  loaf:
    - {actions: [press_loaf], variable: loaf, effect: toggle}
  menu:
    - {actions: [press_menu], variable: menu, effect: next}
display:
  idle: ""
"""


def test_a_word_of_a_kind_of_setting_names_no_switch() -> None:
    """ "a French loaf": the bread, not a LOAF switch (a loaf is a size, a word for a kind)."""
    assert parse_instruction(loads_model(LOAVES), "A French loaf, please.") == {"menu": "french"}


def test_a_label_worn_by_a_held_keys_second_function_does_not_count() -> None:
    """HEAT held 3 s switches °C / °F: a reader labels that switch HEAT too, yet "heating on"
    still names the HEAT switch, whose name it is."""
    held = (
        POOL.replace("  pump:\n    type", '  unit:\n    label: "HEAT"\n    type: discrete\n'
                     '    values: ["off", "on"]\n  pump:\n    type', 1)
        .replace("  press_pump:", "  hold_heat: {control: heat_button, skill: hold, seconds: 3}\n"
                 "  press_pump:", 1)
        .replace("  pump:\n    - {", "  unit:\n    - {actions: [hold_heat], variable: unit, "
                 "effect: toggle}\n  pump:\n    - {", 1)
    )  # fmt: skip
    goal = parse_instruction(loads_model(held), "Heating on at 28 °C.")
    assert goal.get("heat") == "on" and "unit" not in goal
