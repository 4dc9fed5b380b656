"""A key both touched and held: the list said for one way of working it is not the other's
(roles_heldvalues.py), each on a small manual of our own words."""

from __future__ import annotations

from apbot.read import read_manual

# a garden fountain: GLOW touched switches the lamp, held steps its colour
FOUNTAIN = """
AquaGlow F-2 garden fountain

  Ref  Key        Touch                      Touch and hold
  ---  ---------  -------------------------  ------------------------
  1    PUMP       Pump on / off              -
  2    GLOW       Lamp on / off              2 s: next lamp colour

DISPLAY

  Message   Meaning
  -------   ----------------------------------------------
  PUMP      Pump running
  GLOW      Lamp on; the colour shows as AMB, TEA, ROS or WHT

Lamp
  - Touch GLOW to switch the lamp on or off.
  - Hold GLOW for 2 seconds to change the colour. Each hold selects the next colour in this
    order, and after WHT it starts again at amber:

      Display   Colour
      -------   ---------------
      AMB       amber
      TEA       teal
      ROS       rose
      WHT       white
"""
FOUNTAIN_ACTIONS = ["press_pump", "press_glow", "hold_glow"]

# a sauna heater whose key table keeps the held job in a column of its own
SAUNA = """
Kivi S-6 sauna heater

  Key        Touch                                  Touch and hold
  ---------  -------------------------------------  ---------------------------------
  ON         Heater on / off                        -
  STYLE      Next bathing style DRY → SOFT → MIST    3 s: ventilation programming
"""
SAUNA_ACTIONS = ["press_on", "press_style", "hold_style"]


def test_a_list_said_for_holding_the_key_is_not_the_touch_s() -> None:
    model = read_manual(FOUNTAIN, FOUNTAIN_ACTIONS).model
    touched = model.features["glow"][0] if "glow" in model.features else None
    assert touched is not None and touched.effect == "toggle"  # the touch: lamp on / off
    assert set(model.variables["glow"].values) == {"off", "on"}
    held = [f.variable for fs in model.features.values() for f in fs if "hold_glow" in f.actions]
    assert "amber" in (model.variables[held[0]].values or [])  # the hold: the colours


def test_a_row_s_touch_list_is_not_the_hold_s() -> None:
    model = read_manual(SAUNA, SAUNA_ACTIONS).model
    held = [f.variable for fs in model.features.values() for f in fs if "hold_style" in f.actions]
    touched = [
        f.variable for fs in model.features.values() for f in fs if "press_style" in f.actions
    ]
    assert "dry" in model.variables[touched[0]].values
    assert not held or "dry" not in (model.variables[held[0]].values or [])
