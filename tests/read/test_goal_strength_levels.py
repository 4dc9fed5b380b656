"""A strength counted in numbered levels (an intensity 1-5, a pulse OFF/1/2/3): "the gentlest
level", "as strong as it goes" and "a medium pulse" pick its levels though the sentence names
no setting or the list opens with OFF. Checked on a small neck-massager model written for
these tests."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction

NECK = """
appliance: {id: neck_1, category: neck_massager, name: "Kneady NM-2 neck massager", brand: K}
controls:
  - {id: power_button, kind: button, label: "POWER"}
  - {id: force_button, kind: button, label: "FORCE"}
  - {id: warmth_button, kind: button, label: "WARMTH"}
  - {id: minutes_button, kind: button, label: "MINUTES"}
variables:
  power:
    type: discrete
    values: ["off", "on"]
  force:
    type: numeric
    ranges: [[1, 5, 1]]
  warmth:
    type: discrete
    values: ["off", low, high]
  minutes:
    type: time
    ranges: [["00:05:00", "00:30:00", 300]]
    format: "h:mm"
actions:
  press_power: {control: power_button}
  press_force: {control: force_button}
  press_warmth: {control: warmth_button}
  press_minutes: {control: minutes_button}
features:
  power:
    - {actions: [press_power], variable: power, effect: toggle}
  force:
    - {actions: [press_force], variable: force, effect: next}
  warmth:
    - {actions: [press_warmth], variable: warmth, effect: next}
  minutes:
    - {actions: [press_minutes], variable: minutes, effect: next}
"""

PULSE = NECK.replace(
    "type: numeric\n    ranges: [[1, 5, 1]]", 'type: discrete\n    values: ["off", "1", "2", "3"]'
)


def test_the_gentlest_level_is_the_lowest_numbered_level() -> None:
    goal = parse_instruction(loads_model(NECK), "Ten minutes at the gentlest level, please.")
    assert goal.get("force") == 1
    assert "warmth" not in goal


def test_as_strong_as_it_goes_is_the_top_level_not_high_warmth() -> None:
    goal = parse_instruction(loads_model(NECK), "Twenty minutes, as strong as it goes.")
    assert goal.get("force") == 5
    assert "warmth" not in goal


def test_levels_after_off_give_the_scale() -> None:
    model = loads_model(PULSE)
    assert parse_instruction(model, "A medium force for fifteen minutes.").get("force") == "2"
    assert parse_instruction(model, "The softest level, please.").get("force") == "1"
    assert parse_instruction(model, "The strongest force there is.").get("force") == "3"


def test_a_named_setting_keeps_its_superlative() -> None:
    """ "the lowest warmth": the setting is named, so its own scale is meant."""
    goal = parse_instruction(loads_model(NECK), "The lowest warmth for ten minutes.")
    assert goal.get("warmth") == "low"
    assert "force" not in goal
