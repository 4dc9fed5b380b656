"""Where drop24's goal-parser rules misfired on other models and other sentences: a start verb
that is the first word of a setting's name ("Stitch length 3" starts no seam), a POWER or ⏻ key
that switches a part of its own (a vacuum's BOOST is no power), a charted one-touch key the
sentence denies ("not the nap position"), and a bare number after the key verb HOLD said as a
verb ("hold at 70 for 30 minutes": 70 is held, not the HOLD's length). Small models written for
these tests."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction
from tests.read.test_goal_dropped_settings import RECLINER, RECLINER_MANUAL

SEWER = """
appliance: {id: sewer_1, category: sewing_machine, name: "Hem S-2 sewing machine", brand: H}
controls:
  - {id: go_key, kind: button, label: "START/STOP"}
  - {id: kind_key, kind: button, label: "STITCH"}
  - {id: len_key, kind: button, label: "LENGTH"}
  - {id: wid_key, kind: button, label: "WIDTH"}
variables:
  running: {type: discrete, values: ["off", "on"], show: {"off": "", "on": "RUN"}}
  stitch:
    type: discrete
    values: [straight, zigzag, blind]
    show: {straight: "ST", zigzag: "ZZ", blind: "BL"}
  length:
    type: numeric
    label: "STITCH LENGTH"
    ranges: [[1, 5, 0.5]]
    initial: 2.5
    wrap: true
    show: "L{value}"
  width:
    type: numeric
    label: "STITCH WIDTH"
    ranges: [[0, 7, 1]]
    initial: 3
    wrap: true
    show: "W{value}"
actions:
  press_go: {control: go_key}
  press_kind: {control: kind_key}
  press_length: {control: len_key}
  press_width: {control: wid_key}
features:
  start:
    - {actions: [press_go], variable: running, effect: toggle}
  stitch:
    - {actions: [press_kind], variable: stitch, effect: next}
  length:
    - {actions: [press_length], variable: length, effect: next}
  width:
    - {actions: [press_width], variable: width, effect: next}
"""


def test_a_start_verb_that_begins_a_settings_name_starts_nothing() -> None:
    """STITCH LENGTH said by its name sets a length; "Stitch design 9" still orders a seam."""
    sewer = loads_model(SEWER)
    assert parse_instruction(sewer, "Stitch length 3, zigzag.") == {"stitch": "zigzag", "length": 3}
    assert parse_instruction(sewer, "Stitch width 4 please") == {"width": 4}
    assert "running" not in parse_instruction(sewer, "Stitch: blind, width 2")
    assert parse_instruction(sewer, "Stitch a zigzag seam at width 5")["running"] == "on"
    assert parse_instruction(sewer, "Stitch zigzag at width 5")["running"] == "on"


STICK = """
appliance: {id: stick_1, category: stick_vacuum, name: "Dust V-2 stick vacuum", brand: D}
controls:
  - {id: pow_key, kind: button, label: "POWER"}
  - {id: led_key, kind: button, label: "LED"}
  - {id: head_key, kind: button, label: "HEAD"}
variables:
  boost: {type: discrete, values: ["off", "on"], show: {"off": "", "on": "MAX"}}
  led: {type: discrete, values: ["off", "on"], show: {"off": "", "on": "LED"}}
  head: {type: discrete, values: [carpet, hard], show: {carpet: "CP", hard: "HF"}}
actions:
  press_power: {control: pow_key}
  press_led: {control: led_key}
  press_head: {control: head_key}
features:
  boost:
    - {actions: [press_power], variable: boost, effect: toggle}
  led:
    - {actions: [press_led], variable: led, effect: toggle}
  head:
    - {actions: [press_head], variable: head, effect: next}
"""


def test_a_power_key_that_switches_a_part_of_its_own_is_no_power() -> None:
    stick = loads_model(STICK)
    goal = parse_instruction(stick, "Turn it on, carpet head with the LED on")
    assert goal == {"head": "carpet", "led": "on"}


def _recliner(text: str) -> dict[str, object]:
    return parse_instruction(loads_model(RECLINER), text, RECLINER_MANUAL)


def test_a_charted_key_the_sentence_denies_sets_nothing() -> None:
    assert _recliner("Not the nap position, just the heat on") == {"heat": "on"}
    assert _recliner("No nap today: back at 10") == {"back": 10}
    assert _recliner("The nap position, please")["legs"] == 20


BATH = """
appliance: {id: bath_1, category: sous_vide, name: "Bain S-3 sous-vide bath", brand: B}
controls:
  - {id: up_key, kind: button, label: "TEMP +"}
  - {id: down_key, kind: button, label: "TEMP -"}
  - {id: hold_key, kind: button, label: "HOLD"}
variables:
  temperature:
    {type: numeric, unit: "°C", ranges: [[40, 95, 1]], initial: 60, wrap: false, show: "{value}"}
  hold: {type: numeric, unit: min, ranges: [[0, 120, 10]], initial: 0, wrap: true, show: "H{value}"}
actions:
  press_up: {control: up_key}
  press_down: {control: down_key}
  press_hold: {control: hold_key}
features:
  temperature:
    - actions: [press_up, press_down]
      variable: temperature
      effect: {press_up: next, press_down: prev}
  hold:
    - {actions: [press_hold], variable: hold, effect: next}
"""


def test_a_number_held_at_is_no_length_of_the_hold() -> None:
    bath = loads_model(BATH)
    assert parse_instruction(bath, "hold at 70 for 30 minutes") == {"temperature": 70, "hold": 30}
    assert parse_instruction(bath, "Set the hold at 20") == {"hold": 20}
