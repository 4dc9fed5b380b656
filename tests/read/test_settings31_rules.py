"""Rules of the settings31 session, each on a small manual of our own words: a one-letter key
named by "each press of M" (``labels``); a hold whose sentence, or the next, prints the two
values it flips with a two-way arrow (``held_flips``)."""

from __future__ import annotations

from apbot.read import read_manual

# a bike computer whose one-letter key S steps the readout shown
BIKE_COMPUTER = """
Kadro C-2 bike computer

KEYS

  | Key | Press               | Hold 2 s      |
  |-----|---------------------|---------------|
  | S   | next readout        | backlight     |

READOUT

A short press of S shows the next readout:

      SPD  →  AVG  →  DST  →  SPD …

  SPD    speed now
  AVG    average speed
  DST    distance of the trip
"""

BIKE_ACTIONS = ["press_s", "hold_s"]


def test_a_one_letter_key_said_as_each_press_of_it_takes_the_list_after() -> None:
    model = read_manual(BIKE_COMPUTER, BIKE_ACTIONS).model
    stepped = [
        s.variable
        for f in model.features.values()
        for s in f
        if s.actions == ["press_s"] and s.variable
    ]
    assert stepped
    values = getattr(model.variables[stepped[0]], "values", None)
    assert [str(v).lower() for v in values or []] == ["spd", "avg", "dst"]


# a camping inverter whose AC key's hold flips the output frequency, said in a numbered step
INVERTER = """
Ronda IV-300 camping inverter

KEYS

  ⓐ ⏻   Hold 2 s: inverter on / off.
  ⓑ AC  Press: socket on / off.

5 OUTPUT FREQUENCY 50 / 60 HZ

Choose the frequency your devices need:
1. Switch the socket off first.
2. Hold AC for 3 seconds. The screen changes: 50Hz ↔ 60Hz.
3. Press AC to switch the socket on again.
"""

INVERTER_ACTIONS = ["hold_power", "press_ac", "hold_ac"]


def test_a_hold_then_two_values_with_a_two_way_arrow_is_a_flip_named_by_its_section() -> None:
    model = read_manual(INVERTER, INVERTER_ACTIONS).model
    name = next(n for n in model.variables if "frequency" in n)  # (not "ac_hold")
    values = getattr(model.variables[name], "values", None)
    assert [str(v) for v in values or []] == ["50", "60"]  # the figures, said "sixty hertz"
    assert getattr(model.variables[name], "show", None) == {"50": "50Hz", "60": "60Hz"}
    flips = [s for f in model.features.values() for s in f if s.variable == name]
    assert flips and flips[0].actions == ["hold_ac"]


# a record player whose start key's hold plays backwards, said as an item led by the job's name
RECORD_PLAYER = """
Orvo RP-2 record player

  [ ⏻ ]   [ START/STOP ]   [ 33 ]   [ 45 ]

PLAYING

  • Press START/STOP to turn the platter; the PLAY lamp lights.
  • Press START/STOP again to stop it.
  • Backspin: hold START/STOP for 2 seconds. The BACK lamp lights and the platter turns
    the other way. Hold START/STOP for 2 seconds again for normal play.
"""

RECORD_ACTIONS = ["press_power", "press_start", "hold_start", "press_33", "press_45"]


def test_an_item_led_by_a_name_then_a_hold_and_a_lamp_is_a_setting_of_the_hold() -> None:
    model = read_manual(RECORD_PLAYER, RECORD_ACTIONS).model
    held = [s for f in model.features.values() for s in f if s.actions == ["hold_start"]]
    assert held and held[0].variable == "backspin" and held[0].effect == "toggle"
    assert getattr(model.variables["backspin"], "show", None) == {"off": "", "on": "BACK"}
