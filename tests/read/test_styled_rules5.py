"""Rules found on the styled and new-category development sets (fifth round), each on a
small manual of our own."""

from __future__ import annotations

from apbot.model.schema import DiscreteVariable
from apbot.read import read_manual

# a fan heater: a dial picks the room and the fan's standard speed, a FAN key steps the fan;
# the chart says which speeds each position allows, one of them as "LOW only"
HEATER = """PANEL

ROOM dial   FAN key   POWER

Turn the ROOM dial to choose BATH, BEDROOM or HALL. Each position sets its standard fan speed.

Press FAN to go to the next fan speed: LOW -> MID -> HIGH -> LOW.

  Position   Heat        Standard fan   Fan speeds possible
  --------   ---------   ------------   -------------------
  BATH       500 W       LOW            LOW only
  BEDROOM    1000 W      LOW            LOW, MID
  HALL       2000 W      MID            LOW, MID, HIGH
  --------   ---------   ------------   -------------------
"""
HEATER_ACTIONS = ["turn_room_cw", "turn_room_ccw", "press_fan", "press_power"]


def test_a_cell_that_says_one_value_only_is_that_value() -> None:
    model = read_manual(HEATER, HEATER_ACTIONS).model
    fan = model.variables["fan"]
    assert isinstance(fan, DiscreteVariable)
    assert fan.cases is not None and fan.cases["bath"].values == ["low"], fan.cases
