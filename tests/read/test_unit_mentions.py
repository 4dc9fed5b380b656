"""A degree sign in another key's sentence is no mention of the TEMP key: a rule on a small
manual of our own words."""

from __future__ import annotations

from apbot.read import read_manual

# a grill whose dial sets what the last key pressed chose; the probe's range is told in °F
GRILL = """
EmberMate EG-5 pellet grill

THE PANEL
  TEMP    Choose the grill temperature for the dial.
  PROBE   Choose the probe target for the dial.

SETTING THE TEMPERATURE
 1. Press TEMP.
 2. Turn the dial. Each click changes it by 5 °F, from 150 °F to 450 °F.

SETTING THE PROBE TARGET
 1. Press PROBE. The display shows PROBE 150°F.
 2. Turn the dial.
 3. The target changes in 5 °F steps from 110 °F to 210 °F.
"""


def test_a_range_in_degrees_under_another_key_is_not_the_temperature_keys() -> None:
    names = ["press_temp", "press_probe", "turn_dial_cw", "turn_dial_ccw"]
    model = read_manual(GRILL, names).model
    probe = model.variables["probe"]
    assert probe.type == "numeric" and [list(r) for r in probe.ranges] == [[110, 210, 5]]
