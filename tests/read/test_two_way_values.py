"""Keys that flip between two named values (not on and off): each rule on a small manual of our
own words."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.value_lists import find_list
from apbot.read.values import ON_OFF_RE

# a dough proofer whose keys flip between two words each; holding one switches a fan
PROOFER = """
RiseRight DP-2 dough proofer

CONTROLS

  1  POWER     On / off.
  2  DOUGH     Touch: LEAN <-> RICH.  Touch and hold 3 seconds: fan on / off.
  3  HUMIDITY  Touch: LOW <-> HIGH.

  The DOUGH and HUMIDITY choices are kept when the proofer is switched off and on again.
"""

# a hand warmer: the touch switches heating, holding the same key changes the unit
WARMER = """
CosyHands HW-1 hand warmer

  No.  Key      Touch                 Touch and hold 3 seconds
  ---  -------  --------------------  ------------------------
  1    POWER    switch on / off       --
  2    HEAT     heating on / off      change °C / °F
  3    UP       one degree higher     --
"""


def test_a_two_way_arrow_names_the_two_values() -> None:
    assert find_list("Touch: LEAN <-> RICH.  Touch and hold 3 seconds: fan on / off.") == (
        ["LEAN", "RICH"], "arrows"
    )  # fmt: skip
    assert find_list("Press it: °C ↔ °F") == (["°C", "°F"], "arrows")
    assert find_list("Keep warm at 40 °C ↔ 90 °C.") == (["40 °C", "90 °C"], "arrows")


def test_switched_off_and_on_again_is_the_power_not_a_toggle() -> None:
    assert not ON_OFF_RE.search("kept when the proofer is switched off and on again")
    assert ON_OFF_RE.search("Press it to switch the light on or off.")


def test_keys_flipping_two_words_are_two_valued_settings() -> None:
    model = read_manual(PROOFER, ["press_power", "press_dough", "hold_dough", "press_humidity"])
    variables = model.model.variables
    assert variables["dough"].values == ["lean", "rich"]  # the hold's fan on / off is its own
    assert variables["humidity"].values == ["low", "high"]


def test_the_hold_column_names_the_values_the_hold_flips() -> None:
    model = read_manual(WARMER, ["press_power", "press_heat", "hold_heat", "press_up"]).model
    held = [v for v in model.variables.values() if v.values and "°f" in v.values]
    assert held and held[0].values == ["°c", "°f"]
    assert model.variables["heat"].values == ["off", "on"]
