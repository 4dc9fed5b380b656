"""Reader rules from the newcats C5/D5 failures, each on a small manual in our own words."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.build_base import PLACEHOLDERS
from apbot.read.values import find_ranges

# a grill whose own section for the core-sensor key gives its range in °F, a unit sign that
# the TEMP key's label also matches
GRILL = """EMBERLINE G5 pellet grill

CONTROL PANEL
  POWER     Switch the panel on or off.
  TEMP      Select the grill temperature for adjustment.
  CORE      Select the core sensor target for adjustment.
  KNOB      Turn: change the selected setting. Press: confirm.

SETTING THE GRILL TEMPERATURE
1. Press TEMP. The display shows TEMP and the grill temperature.
2. Turn the KNOB. The temperature changes in 10 °F steps from 180 °F to 500 °F.
3. Press the knob to confirm.

SETTING THE CORE SENSOR TARGET
1. Push the sensor into the meat.
2. Press CORE. The display shows CORE and the target.
3. Turn the KNOB. The target changes in 5 °F steps from 110 °F to 210 °F.
4. Press the knob to confirm.
"""
GRILL_ACTIONS = [
    "press_power",
    "press_temp",
    "press_core",
    "turn_knob_cw",
    "turn_knob_ccw",
    "press_knob",
]


# a cooler whose second zone is set by repeating the numbered steps
COOLER = """FROSTA DZ-2 drinks cooler

The ZONE key changes between the LEFT and the RIGHT zone.

Setting the temperature
1. Touch ZONE until the lamp of the zone you want is lit.
2. Touch ▲ or ▼ to set the temperature, 4 °C to 16 °C.
3. Wait 5 seconds: the setting is stored.
4. To set the other zone, touch ZONE and repeat steps 2 to 3.
"""
COOLER_ACTIONS = ["press_zone", "press_up", "press_down"]


def test_a_reference_to_numbered_steps_is_no_range() -> None:
    assert find_ranges("To set the other zone, touch ZONE and repeat steps 2 to 4.") == []
    assert find_ranges("Repeat steps 3–5 for the right drawer.") == []
    assert find_ranges("Set it in steps 1 to 9 minutes.") != []  # a unit: an amount
    assert find_ranges("Choose the crust (steps 1–5 above).") == []
    # levels said as steps, no reference to the manual's numbered steps: a range
    assert [(r.low, r.high) for r in find_ranges("Set the heat in steps 1 to 9.")] == [(1, 9)]
    zone = read_manual(COOLER, COOLER_ACTIONS).model.variables["zone"]
    assert [2.0, 3.0] not in [list(r[:2]) for r in zone.ranges or []]


# a juicer whose display shows the pulp setting and the light level as bars of segments
JUICER = """PRESSA J3 slow juicer

KEYS
  PULP      next pulp setting: LOW → MEDIUM → HIGH → LOW
  LIGHT     light level: 25 → 50 → 75 → 100 % → 25

DISPLAY
  ▮▯▯   pulp LOW
  ▮▮▯   pulp MEDIUM
  ▮▮▮   pulp HIGH

LIGHT LEVEL
Press LIGHT. Each press raises the level by one step of 25 %:
  ▮▯▯▯ 25 %    ▮▮▯▯ 50 %    ▮▮▮▯ 75 %    ▮▮▮▮ 100 %
"""
JUICER_ACTIONS = ["press_pulp", "press_light"]


def test_a_setting_shown_as_bars_takes_the_bars() -> None:
    model = read_manual(JUICER, JUICER_ACTIONS).model
    assert model.variables["pulp"].show == {"low": "▮▯▯", "medium": "▮▮▯", "high": "▮▮▮"}


# a dehumidifier whose fan speed is shown as bars, and whose dryness of the same three values
# is shown in words
DRYER = """AIRDRY D4 dehumidifier

KEYS
  FAN       fan speed: LOW → MEDIUM → HIGH → LOW
  DRY       dryness: LOW → MEDIUM → HIGH → LOW (the display shows LOW, MEDIUM or HIGH)

FAN SPEED
The fan speed is shown as bars:
  ▮▯▯ LOW    ▮▮▯ MEDIUM    ▮▮▮ HIGH
"""


def test_bars_go_to_the_setting_named_with_them() -> None:
    model = read_manual(DRYER, ["press_fan", "press_dry"]).model
    assert model.variables["fan"].show == {"low": "▮▯▯", "medium": "▮▮▯", "high": "▮▮▮"}
    assert not model.variables["dry"].show


def test_a_few_stepped_levels_shown_as_bars_become_their_list() -> None:
    light = read_manual(JUICER, JUICER_ACTIONS).model.variables["light"]
    assert light.type == "discrete"
    assert light.values == ["25", "50", "75", "100"]
    assert light.show == {"25": "▮▯▯▯", "50": "▮▮▯▯", "75": "▮▮▮▯", "100": "▮▮▮▮"}


# a smoker whose dial, turned alone, sets nothing the manual names (placeholder choices)
SMOKER = """SMOKEHOUSE S2

CONTROL PANEL
  POWER        Switch the control panel on or off.
  TEMP         Select the cabinet temperature for adjustment.
  TIME         Select the cooking time for adjustment.
  SELECT dial  Turn: change the selected setting. Press: confirm the setting.
               Press and hold 2 seconds: start or stop smoking.

 What the dial changes depends on which of TEMP or TIME you pressed last. If none of
 them has been pressed, turning the dial does nothing.

SWITCHING ON
Press POWER. The display lights up and shows the set temperature.

SETTING THE TEMPERATURE
1. Press TEMP. The display shows TEMP and the temperature.
2. Turn the SELECT dial clockwise to raise the temperature or counterclockwise to lower it.
   Each click changes it by 5 °F.
3. The range is 100 °F to 275 °F.
4. Press the dial to confirm.

SETTING THE COOKING TIME
1. Press TIME. The display shows TIME and the time in hours and minutes.
2. Turn the SELECT dial. The time changes in 15-minute steps between 0:15 and 12:00.
3. Press the dial to confirm.
"""
SMOKER_ACTIONS = [
    "press_power",
    "press_temp",
    "press_time",
    "turn_dial_cw",
    "turn_dial_ccw",
    "press_dial",
    "hold_dial",
]


def test_placeholder_choices_are_not_the_idle_display() -> None:
    reading = read_manual(SMOKER, SMOKER_ACTIONS)
    placeholders = {n.subject.split(".")[1] for n in reading.report.notes if n.what == PLACEHOLDERS}
    assert "dial" in placeholders
    assert reading.model.display.idle == ""
    assert "{dial}" not in str(reading.model.variables["power"].show)
