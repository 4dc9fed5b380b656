"""Settings reached through a numbered menu (roles_menu), each rule on a small manual of our own."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.sim.simulator import Simulator

# a pond heater: a held MENU key opens items d1 … d3, told under headings of their own
HEATER = """# Pond heater PH-2

## Keys

| Key | Press | Hold |
|---|---|---|
| MENU | next item | 4 s: open the user menu |
| + | raise the value | - |
| - | lower the value | - |
| HEAT | heater on / off | - |

## The user menu (d1 - d3)

1. Hold MENU for 4 seconds. The display shows d1 and its value.
2. Change the value with + or -.
3. Press MENU to go to the next item. You must press + or - at least once first.
4. After d3, press MENU again to store and leave.

d1  Water temperature

Adjustable from 4 °C to 20 °C. Default 8 °C.
It changes in steps of 1 °C.

AQUAHEAT    OWNER GUIDE    PAGE

d2  Pump speed

Low, Medium or High.

d3  Night setback

The setback runs 0 h - 2 h - 4 h - 6 h - 8 h.
"""
HEATER_ACTIONS = ["hold_menu", "press_menu", "press_plus", "press_minus", "press_heat"]


def _menu_steps(model: object) -> list[tuple[tuple[str, ...], str | None]]:
    feats = model.features  # type: ignore[attr-defined]
    return [(tuple(s.actions), s.variable) for s in feats["settings_menu"]]


def test_a_held_key_opens_the_items_one_after_the_other() -> None:
    model = read_manual(HEATER, HEATER_ACTIONS).model
    steps = _menu_steps(model)
    pair = ("press_plus", "press_minus")
    assert [a for a, _v in steps] == [
        ("hold_menu",),
        pair,
        ("press_menu",),
        pair,
        ("press_menu",),
        pair,
        ("press_menu",),
    ]
    names = [v for _a, v in steps if v]
    assert len(names) == 3
    temp, speed, setback = (model.variables[n] for n in names)
    assert temp.label == "d1" and speed.label == "d2" and setback.label == "d3"
    assert temp.ranges == [(4, 20, 1)] and temp.initial == 8
    assert speed.values == ["low", "medium", "high"]
    assert setback.ranges == [(0, 8, 2)]


def test_the_menu_walks_to_a_later_item_on_the_simulator() -> None:
    model = read_manual(HEATER, HEATER_ACTIONS).model
    sim = Simulator(model)
    shown = [sim.step(a).text for a in ("hold_menu", "press_plus", "press_menu", "press_plus")]
    assert shown[1].startswith("d1 9") and shown[3].startswith("d2 ")


# a gate controller: the items are rows of a table; a list with "--" (off) among its values
GATE = """GATE CONTROLLER GC-3

PROG   Hold 3 seconds: programming. Press: next parameter.
UP     Programming: next value.
DOWN   Programming: previous value.
OPEN   Opens or closes the gate.

PROGRAMMING (C1 - C2)

| Code | Parameter | Values | Factory |
|---|---|---|---|
| C1 | pause before closing | -- (off) · 30 · 60 · 120 s | -- |
| C2 | motor force | 1 · 2 · 3 … 6 | 4 |
| C3 | courtesy light | 1.5 · 2.5 · 3.5 min | 2.5 |

Hold PROG for 3 seconds. The display shows C1 and the pause.
Press UP or DOWN, then PROG to go on to C2.
"""
GATE_ACTIONS = ["hold_prog", "press_prog", "press_up", "press_down", "press_open"]


def test_table_rows_give_the_items_and_their_values() -> None:
    model = read_manual(GATE, GATE_ACTIONS).model
    steps = _menu_steps(model)
    assert steps[0] == (("hold_prog",), None)
    pause, force, light = (model.variables[v] for _a, v in steps if v)
    assert pause.values[0] == "off" and len(pause.values) == 4
    assert pause.initial == "off"
    assert force.ranges == [(1, 6, 1)] and force.initial == 4
    # minutes printed as bare numbers ("C3 2.5") stay numbers, not a clock shown as 02:30
    assert light.type == "numeric" and light.unit == "min"
    assert light.ranges == [(1.5, 3.5, 1)] and light.initial == 2.5


# a programme chart with codes is no settings menu: MENU steps the programmes themselves
COOKER = """# Cooker

| Key | Use |
|---|---|
| MENU | Touch: next programme (A1 → A2 → A3). Hold 3 s: key lock on / off. |
| + / - | Keep-warm time. |

## Menu chart

| Code | Menu | Time |
|---|---|---|
| A1 | STEW | 4 h |
| A2 | SOUP | 2 h |
| A3 | RICE | 1 h |
"""
COOKER_ACTIONS = ["press_menu", "hold_menu", "press_plus", "press_minus"]


def test_a_chart_of_programme_codes_is_no_settings_menu() -> None:
    model = read_manual(COOKER, COOKER_ACTIONS).model
    assert "settings_menu" not in model.features


# an item whose range depends on an earlier item, one table row per value of that item
SCALE = """# Brooder

Hold SET for 3 seconds: the setting menu opens and the display shows P1.
Press SET for the next item. ▲ / ▼ change the value.

P1  Unit

▲ or ▼ switch between C (Celsius) and F (Fahrenheit).

P2  Set temperature

| unit (P1) | range | one press | default |
|---|---|---|---|
| C | 20.0 - 40.0 | 0.5 | 32.0 |
| F | 68 - 104 | 1 | 90 |
"""
SCALE_ACTIONS = ["hold_set", "press_set", "press_up", "press_down"]


def test_an_item_ranged_per_value_of_an_earlier_item() -> None:
    model = read_manual(SCALE, SCALE_ACTIONS).model
    steps = _menu_steps(model)
    unit, temp = (v for _a, v in steps if v)
    assert model.variables[unit].values == ["celsius", "fahrenheit"]
    spec = model.variables[temp]
    assert spec.depends_on == unit
    assert set(spec.cases) == {"celsius", "fahrenheit"}


# items listed one a line with their choices in brackets, the menu opened by a press
FRIDGE = """Wine cabinet

Press MODE: the display shows U1 and its value. Press MODE again for the next setting;
+ and - change it.

User settings:

- U1: display unit (C/F)
- U2: door alarm (on/off)
"""
FRIDGE_ACTIONS = ["press_mode", "press_plus", "press_minus"]


def test_choices_in_brackets_after_the_item_name() -> None:
    model = read_manual(FRIDGE, FRIDGE_ACTIONS).model
    steps = _menu_steps(model)
    assert steps[0] == (("press_mode",), None)
    unit, alarm = (v for _a, v in steps if v)
    assert model.variables[unit].values == ["c", "f"]
    assert model.variables[alarm].values == ["on", "off"]


# a programme chart under a MENU key, its temperature set with a pair named TEMP: no menu
WASHER = """# Washer

| Key | Function |
|---|---|
| MENU | Press to choose the next programme. |
| TEMP + | Raises the wash temperature. |
| TEMP - | Lowers the wash temperature. |

Press MENU: the display shows P1. Each further press shows the next programme.

| Code | Programme | Temperatures |
|---|---|---|
| P1 | Cotton | 20 - 40 - 60 - 90 °C |
| P2 | Synthetics | 20 - 30 - 40 °C |
| P3 | Wool | 20 - 30 - 40 °C |
"""
WASHER_ACTIONS = ["press_menu", "press_temp_plus", "press_temp_minus"]


def test_a_pair_named_for_its_own_quantity_serves_no_menu() -> None:
    model = read_manual(WASHER, WASHER_ACTIONS).model
    assert "settings_menu" not in model.features
    assert any(s.variable == "temp" for s in model.features["set_temp"])


# a chart of foods under a pressed AUTO MENU key, each weighed with ▲ / ▼: a press that steps
# the chart ("the next food") is no menu of settings
AUTO = """# Microwave

| Key | Function |
|---|---|
| AUTO MENU | Chooses an automatic programme. |
| ▲ | More weight. |
| ▼ | Less weight. |

## Auto menu (A1 - A3)

Press AUTO MENU: the display shows A1. Press AUTO MENU again for the next food, then set the
weight with ▲ or ▼.

A1  Popcorn        1.75 · 3.0 · 3.5 oz
A2  Potato         1 · 2 · 3 · 4 pieces
A3  Pizza          1 · 2 · 3 slices
"""


def test_a_pressed_key_stepping_a_chart_of_foods_is_no_menu() -> None:
    model = read_manual(AUTO, ["press_auto_menu", "press_up", "press_down"]).model
    assert "settings_menu" not in model.features
