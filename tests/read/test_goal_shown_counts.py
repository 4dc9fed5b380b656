"""Rules of the goal parser checked on small models written for these tests: an interval the
display shows as counts with a unit letter ("W 3d", "d2") takes "every 3 days", "every other
day", "once a week" (and nothing not said "every"); the unit a display prints after a value
("SIZE {value}pt") names that setting ("8 pt writing")."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction

GARDEN = """
appliance: {id: garden_1, category: grow_box, name: "Verda G-1 grow box", brand: V}
controls:
  - {id: water_key, kind: touch, label: "WATER"}
  - {id: again_key, kind: touch, label: "AGAIN"}
  - {id: pause_key, kind: touch, label: "PAUSE"}
variables:
  watering:
    type: discrete
    values: ["off", "1", "2", "3", "7"]
    show: {"off": "W OFF", "1": "W 1d", "2": "W 2d", "3": "W 3d", "7": "W 7d"}
  again:
    type: discrete
    values: ["off", "1", "2"]
    show: {"off": "", "1": "d1", "2": "d2"}
  pause:
    type: discrete
    values: ["off", 24 h, 48 h]
    show: {"off": "", 24 h: "P 24H", 48 h: "P 48H"}
actions:
  press_water: {control: water_key}
  press_again: {control: again_key}
  press_pause: {control: pause_key}
features:
  watering:
    - {actions: [press_water], variable: watering, effect: next}
  again:
    - {actions: [press_again], variable: again, effect: next}
  pause:
    - {actions: [press_pause], variable: pause, effect: next}
display:
  idle: "{watering}"
"""


def _goal(model: str, text: str) -> dict[str, object]:
    return parse_instruction(loads_model(model), text)


def test_an_interval_shown_with_a_unit_letter_takes_every_so_many_days() -> None:
    assert _goal(GARDEN, "water every 3 days") == {"watering": "3"}
    assert _goal(GARDEN, "water once a week") == {"watering": "7"}
    assert _goal(GARDEN, "again every other day") == {"again": "2"}
    # a span not said "every" is no interval: a pause of two days
    assert _goal(GARDEN, "pause the watering for two days") == {"pause": "48 h"}


PRINTER = """
appliance: {id: printer_1, category: label_printer, name: "Tag P-1 printer", brand: T}
controls:
  - {id: size_key, kind: button, label: "SIZE"}
  - {id: copies_key, kind: button, label: "COPIES"}
variables:
  font_size:
    type: discrete
    values: ["6", "8", "10", "12"]
    show: "SIZE {value}pt"
  copies: {type: numeric, ranges: [[1, 20, 1]], initial: 1, wrap: true}
actions:
  press_size: {control: size_key}
  press_copies: {control: copies_key}
features:
  font_size:
    - {actions: [press_size], variable: font_size, effect: next}
  copies:
    - {actions: [press_copies], variable: copies, effect: next}
"""


def test_the_unit_a_display_prints_after_the_value_names_its_setting() -> None:
    assert _goal(PRINTER, "small 8 pt writing, three copies") == {"font_size": "8", "copies": 3}
