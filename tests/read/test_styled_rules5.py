"""Rules found on the styled and new-category development sets (fifth round), each on a
small manual of our own."""

from __future__ import annotations

import pytest

from apbot.model.load import loads_model
from apbot.model.schema import DiscreteVariable, NumericVariable
from apbot.read import read_manual
from apbot.read.goal import parse_instruction

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


# an aquarium pump whose flow key shows its speeds abbreviated (LO, MED, HI)
AQUARIUM = """
appliance: {id: aquarium_pump, category: aquarium_pump, name: "Aquarium pump"}
controls:
  - {id: power_button, kind: button, label: "POWER"}
  - {id: flow_button, kind: button, label: "FLOW"}
variables:
  power: {type: discrete, values: ["off", "on"], initial: "off"}
  flow:
    type: discrete
    values: [lo, med, hi]
    initial: hi
    label: "FLOW"
actions:
  press_power: {control: power_button}
  press_flow: {control: flow_button}
features:
  power:
    - {actions: [press_power], variable: power, effect: toggle}
  flow:
    - {actions: [press_flow], variable: flow, effect: next}
display:
  idle: "FLOW {flow}"
"""


def test_abbreviated_levels_are_a_scale_with_ends() -> None:
    model = loads_model(AQUARIUM)
    assert parse_instruction(model, "Turn the flow down to its lowest speed")["flow"] == "lo"
    assert parse_instruction(model, "Set the flow as high as it goes")["flow"] == "hi"


# a pond pump whose JET key the manual describes, in a legend or in a section title, as the
# thing a user talks about ("the bubbles")
POND = AQUARIUM.replace("flow", "jet").replace("FLOW", "JET")
POND_LEGEND = """KEYS

 1  POWER     Switches the pump on or off.
 2  JET       Sets the bubble strength: LO, MED, HI, then LO again.
"""
POND_TITLE = """3. BUBBLE STRENGTH (JET)

Each press of JET gives the next strength: LO, MED, HI.
"""


@pytest.mark.parametrize("manual", [POND_LEGEND, POND_TITLE])
def test_a_key_legend_or_title_names_what_the_key_sets(manual: str) -> None:
    model = loads_model(POND)
    goal = parse_instruction(model, "Bubble strength to the lowest, please", manual)
    assert goal.get("jet") == "lo", goal
    assert "jet" not in parse_instruction(model, "Bubble strength to the lowest, please")


# a griddle whose POWER key steps the output: fine steps low down, coarser ones above
GRIDDLE = """KEYS

ON/OFF    switches the griddle on or off.
POWER     touch, then + or - to change the output.
+  -      change the value shown.

Touch POWER, then + or - to choose the output. The output goes from 300 to 1200 W in 100 W
steps, above 1200 W in steps of 300 W up to 2400 W.
"""
GRIDDLE_ACTIONS = ["press_on_off", "press_power", "press_plus", "press_minus"]


def test_an_amount_whose_step_changes_part_way_has_two_pieces() -> None:
    model = read_manual(GRIDDLE, GRIDDLE_ACTIONS).model
    power = next(v for v in model.variables.values() if isinstance(v, NumericVariable))
    assert [tuple(r) for r in power.ranges or []] == [(300, 1200, 100), (1200, 2400, 300)]


# a soup maker whose BLEND MODE key (action press_blend) lists BLEND as its own first value
SOUP = """KEYS

  POWER         Switches the soup maker on or off.
  BLEND MODE    Each touch moves on to the next texture: BLEND → CHUNKY → SMOOTH → BLEND again.
"""


def test_a_key_named_one_word_longer_than_its_action_heads_the_legend_row() -> None:
    model = read_manual(SOUP, ["press_power", "press_blend"]).model
    var = next(v for v in model.variables.values() if v.label == "BLEND MODE")
    assert isinstance(var, DiscreteVariable)
    assert var.values == ["blend", "chunky", "smooth"]


# a grill whose list of display messages shows the timer as a clock time ("TIMER 0:15")
GRILL = """KEYS

TIMER   touch, then + or - to set the switch-off time.
+  -    change the value shown.

DISPLAY MESSAGES

  TIMER 0:15        timer being set, hours:minutes
  HOT               the plate is still hot

SETTING THE TIMER

Touch TIMER, then + or -. The timer goes from 0:00 to 2:00 in steps of 5 minutes.
"""


def test_a_clock_time_in_a_display_message_is_no_list_colon() -> None:
    model = read_manual(GRILL, ["press_timer", "press_plus", "press_minus"]).model
    timer = model.variables["timer"]
    assert [tuple(r) for r in getattr(timer, "ranges", None) or []] == [
        ("00:00:00", "02:00:00", 300)
    ], timer
