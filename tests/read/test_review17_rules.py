"""Misfires of this session's rules found in review (review17), each narrowed: checked on models
written for these tests (loaded unchecked: only the parts a rule reads are written), a tower fan
and a bedside lamp, neither of them in a suite. Each test fails without its narrowing."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read import read_manual
from apbot.read.goal import parse_instruction


def _goal(model_text: str, said: str) -> dict[str, object]:
    return dict(parse_instruction(loads_model(model_text, check=False), said))


FAN = """
appliance: {id: fan_x, category: tower_fan, name: "Breezo T3 tower fan", brand: B}
controls:
  - {id: power_key, kind: button, label: "POWER"}
  - {id: speed_key, kind: button, label: "SPEED"}
  - {id: sleep_key, kind: button, label: "SLEEP"}
variables:
  power: {type: discrete, values: ["off", "on"]}
  fan_speed: {type: discrete, values: ["auto", "1", "2", "3"]}
  sleep: {type: discrete, values: ["off", "on"]}
actions:
  press_power: {control: power_key}
  press_speed: {control: speed_key}
  press_sleep: {control: sleep_key}
features:
  power:
    - {actions: [press_power], variable: power, effect: toggle}
  fan_speed:
    - {actions: [press_speed], variable: fan_speed, effect: next}
  sleep:
    - {actions: [press_sleep], variable: sleep, effect: toggle}
"""


def test_letting_the_user_choose_is_no_auto() -> None:
    """ "let me pick the speed" keeps the choice with the user: no AUTO (goal_left_to_it)."""
    assert _goal(FAN, "Let me adjust the speed by hand.") == {}
    assert _goal(FAN, "Let me choose the speed myself, just switch it on.") == {"power": "on"}


def test_letting_the_appliance_choose_is_still_auto() -> None:
    """The rule kept: the appliance ("it", "the fan") is let choose."""
    assert _goal(FAN, "Let the fan pick the speed.") == {"fan_speed": "auto"}
    assert _goal(FAN, "Let it choose the speed.") == {"fan_speed": "auto"}


LAMP = """
appliance: {id: lamp_x, category: bedside_lamp, name: "Glowy B2 bedside lamp", brand: G}
controls:
  - {id: fan_key, kind: button, label: "FAN"}
  - {id: dim_key, kind: button, label: "DIM"}
variables:
  fan: {type: discrete, values: ["off", "low", "high"]}
  auto_dim: {type: discrete, values: ["off", "on"]}
actions:
  press_fan: {control: fan_key}
  press_dim: {control: dim_key}
features:
  fan:
    - {actions: [press_fan], variable: fan, effect: next}
  auto_dim:
    - {actions: [press_dim], variable: auto_dim, effect: toggle}
"""


def test_a_setting_not_let_stop_is_not_off() -> None:
    """ "never let the fan stop": the fan is the subject kept going, not refused (goal_offs)."""
    assert _goal(LAMP, "Never let the fan stop while I sleep.") == {}


def test_the_appliance_not_let_do_a_thing_is_still_off() -> None:
    """The rule kept: "don't let it dim" refuses what the appliance does by itself."""
    assert _goal(LAMP, "Don't let it dim.") == {"auto_dim": "off"}


WINE = """
appliance: {id: wine_x, category: wine_cooler, name: "Cava D2 dual-zone wine cooler", brand: C}
controls:
  - {id: up_key, kind: button, label: "▲"}
variables:
  upper_zone: {type: numeric, unit: "°C", ranges: [[5, 12, 1]]}
  lower_zone: {type: numeric, unit: "°C", ranges: [[10, 18, 1]]}
actions:
  press_up: {control: up_key}
features:
  upper_zone:
    - {actions: [press_up], variable: upper_zone, effect: next}
  lower_zone:
    - {actions: [press_up], variable: lower_zone, effect: next}
"""


def test_a_number_said_of_a_named_place_is_no_limit() -> None:
    """Upper and lower zones are places, not limits: "the upper zone just under 11" is the
    upper zone's, not the lower zone's low limit (goal_limits)."""
    said = "Put the upper zone just under 11 °C and the lower zone at 16 °C."
    assert _goal(WINE, said) == {"upper_zone": 11, "lower_zone": 16}


PROCESSOR = """
appliance: {id: proc_x, category: food_processor, name: "Kora P5 food processor", brand: K}
controls:
  - {id: speed_key, kind: button, label: "SPEED"}
  - {id: snd_key, kind: button, label: "STARTUP SOUND"}
variables:
  speed: {type: discrete, values: ["1", "2", "3"]}
  startup: {type: discrete, values: ["off", "on"], label: "STARTUP SOUND"}
actions:
  press_speed: {control: speed_key}
  press_snd: {control: snd_key}
features:
  speed:
    - {actions: [press_speed], variable: speed, effect: next}
  startup:
    - {actions: [press_snd], variable: startup, effect: toggle}
"""


def test_a_verb_and_its_particle_are_no_compound() -> None:
    """ "start up on speed 2" is a verb and its particle, not the STARTUP name spelt apart
    (goal_spelling); "the start up sound" (a word of the name after) still is."""
    assert _goal(PROCESSOR, "Start up on speed 2.") == {"speed": "2"}
    assert _goal(PROCESSOR, "Turn the start up sound off.") == {"startup": "off"}


_WARMER = """\
# Calda W3 plate warmer

## The keys

- START: starts heating; pressed again, stops it.
- SET: opens the settings menu and moves from one code to the next.
- ▲ and ▼: raise or lower the plate temperature by 5 °C. In the menu: the next or last value.

## Temperature

The plate temperature runs from 40 °C to 80 °C in steps of 5 °C. Factory setting: 60 °C.

## The settings menu

Stop heating before you open the settings.

| Code | Setting  | Values (in ▲ order) | Factory |
|------|----------|---------------------|---------|
| bP   | Key beep | ON, OFF             | ON      |
| Ao   | Auto off | OFF, 1, 2, 4        | 2       |

1. Press SET. The first code appears with its value, for example bP ON.
2. Press ▲ or ▼ until the value you want is shown.
3. Press SET. The value is kept and the next code appears.
"""


def test_a_menu_pair_keeps_the_quantity_it_sets_outside_the_menu() -> None:
    """The pair that steps a settings menu's values also sets the plate temperature on the home
    screen, said in words the home-screen rule does not know ("raise or lower the plate
    temperature"): the menu may not take the pair from the reader of that quantity (roles_menu,
    a Code-headed menu made by set17)."""
    model = read_manual(_WARMER, ["press_start", "press_set", "press_up", "press_down"]).model
    assert "settings_menu" in model.features
    temperature = next(s for n, s in model.variables.items() if "temperature" in n)
    assert temperature.ranges == [(40, 80, 5)]
