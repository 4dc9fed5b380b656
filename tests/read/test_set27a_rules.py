"""Rules of the set27a session, each on a small manual of our own words: keys that add signed
amounts to one count (``signed_keys``), a clock typed as minutes and seconds
(``typed_minutes``), a key printed "START/STOP <name>" (``printed_starts``), cycles whose values
share the setting's short name, carry bracketed meanings or are glossed in a dotted legend
(``cycle_words``), a dial's scale per mode from the modes' subsections (``mode_scales``), a key
that finishes a typed entry (``roles_confirm``, ``roles_own_dials``) and a hold said after a
semicolon in the legend's next sentence (``roles_common.held_switch``)."""

from __future__ import annotations

from typing import Any

from apbot.model.domain import all_values
from apbot.read import read_manual

# a darts / table-game counter: a row of signed keys per player, a typed round timer
COUNTER = """
TALLYPRO TP-4 game counter

1  KEYS

  ⏻              on / off
  RED  +1 +5 +10 −1    the red player's keys
  BLUE +1 +5 +10 −1    the blue player's keys
  SET TIME       the round time, then the number keys
  0 - 9          number keys
  OK             see section 3
  [START/STOP MATCH]   the big key
  PRESET         the table preset
  SRV            the serve mark

2  POINTS

  Every press adds the printed amount: +5 adds five, −1 takes one off. Points go from 0 to
  500 and stop there.

3  ROUND TIME

  1. Press SET TIME.
  2. Key in the minutes and the seconds, e.g. 2 3 0 for 2:30.
  3. Press OK to finish.

  The round time holds up to 59 minutes 59 seconds.

4  PRESET

  Each press of PRESET moves on:

      PRE A → PRE B → PRE C → PRE X → PRE A → ...

6  MATCH

  Press START/STOP MATCH to run the round; RUN appears. Press it again to halt.

5  SERVE MARK

  Press SRV to move the serve mark:

      (no mark) → ◄SRV (red) → SRV► (blue) → (no mark) → ...
"""

COUNTER_ACTIONS = [
    "press_power",
    "press_red_plus1",
    "press_red_plus5",
    "press_red_plus10",
    "press_red_minus1",
    "press_blue_plus1",
    "press_blue_plus5",
    "press_blue_plus10",
    "press_blue_minus1",
    "press_set_time",
    *[f"press_{d}" for d in range(10)],
    "press_ok",
    "press_match",
    "press_preset",
    "press_srv",
]


def _counter() -> Any:
    return read_manual(COUNTER, COUNTER_ACTIONS).model


def test_signed_keys_add_their_amounts_to_one_count_per_stem() -> None:
    model = _counter()
    red = [n for n in model.variables if n.startswith("red")]
    assert red == ["red_point"]
    var = model.variables[red[0]]
    assert var.type == "numeric"
    assert list(all_values(var))[-1] == 500
    effects = next(st.effect for f in model.features.values() for st in f if st.variable == red[0])
    assert effects["press_red_plus10"].add == 10
    assert effects["press_red_minus1"].add == -1


# numbered zones use the same key names: + and − for zone 1, + and − for zone 2
ZONES = """
TWINCOOK 2-zone fryer

  +1 / −1   raise or lower zone 1's temperature
  +2 / −2   raise or lower zone 2's temperature

The temperature runs from 80 to 200 °C in each zone.
"""


def test_numbered_zone_keys_stay_steppers() -> None:
    model = read_manual(ZONES, ["press_plus1", "press_minus1", "press_plus2", "press_minus2"]).model
    added = [
        st
        for f in model.features.values()
        for st in f
        if isinstance(st.effect, dict) and any(isinstance(e, dict) and "add" in e
                                               for e in st.effect.values())
    ]  # fmt: skip
    assert not added


def test_a_clock_keyed_as_minutes_and_seconds_up_to_its_top() -> None:
    model = _counter()
    timer = next(n for n, v in model.variables.items() if v.type == "time")
    var = model.variables[timer]
    assert var.format == "mm:ss"
    values = list(all_values(var))
    assert "00:02:30" in [str(v) for v in values] or 150 in values
    assert len(values) == 59 * 60 + 59 + 1


def test_a_key_that_finishes_the_entry_closes_it_and_is_no_setting() -> None:
    model = _counter()
    assert not any("ok" in n for n in model.variables)
    closing = [
        f for f in model.features.values() if any(st.actions == ["press_ok"] for st in f[1:])
    ]
    assert closing


def test_start_stop_printed_before_the_keys_noun_runs() -> None:
    model = _counter()
    running = [
        st.variable for f in model.features.values() for st in f if st.actions == ["press_match"]
    ]
    assert running == ["running"] and model.variables["running"].show == {"off": "", "on": "RUN"}


def test_values_after_the_settings_short_name() -> None:
    model = _counter()
    pre = model.variables["preset"]
    assert pre.values == ["a", "b", "c", "x"]
    assert pre.show == {"a": "PRE A", "b": "PRE B", "c": "PRE C", "x": "PRE X"}


def test_bracketed_meanings_of_a_cycle_and_its_bare_state() -> None:
    model = _counter()
    srv = next(v for n, v in model.variables.items() if n.startswith("srv"))
    assert srv.values == ["none", "red", "blue"]
    assert srv.show == {"none": "", "red": "◄SRV", "blue": "SRV►"}


# a slide projector whose one dial means a different thing per mode
LAMP = """
BRIGHTA PL-3 studio lamp

2  PARTS

  ① MODE     chooses FIX, S or ECO
  ② LEVEL    dial. Turn it to change the brightness of the chosen mode.
  ③ TONE     steps the colour sign

  Display signs:
    ☀W ................ warm white light
    ☀C ................ cool daylight

  Each press of TONE: N → W → C → N.

4  MODES

  Each press of MODE: FIX → S → ECO → FIX.

  S (strobe light)
    The lamp flashes with every shutter release.

5  BRIGHTNESS

  Every mode keeps its own brightness. Factory values: FIX 0.0, S 1/1, ECO 1/32.

  5.1 FIX - steady light
      The brightness is set from -2.0 to +2.0 in steps of one third, written -1.7, -1.3
      and so on; +1.0 is one stop brighter.

  5.2 S and ECO - a share of full power
      The lamp shows a share of full power: 1/32, 1/16, 1/8, 1/4, 1/2 and 1/1.
      In ECO only 1/32, 1/16 and 1/8 can be chosen.

  5.3 Leaving
      Press any key.
"""

LAMP_ACTIONS = ["press_mode", "turn_level_cw", "turn_level_ccw", "press_tone"]


def test_a_dials_scale_per_mode_from_the_modes_subsections() -> None:
    model = read_manual(LAMP, LAMP_ACTIONS).model
    var = model.variables["brightness"]
    assert var.depends_on == "mode"
    assert var.remember
    assert var.cases["fix"].values[0] == "-2.0" and "+1.3" in var.cases["fix"].values
    assert var.cases["strobe"].values == ["1/32", "1/16", "1/8", "1/4", "1/2", "1/1"]
    assert var.cases["eco"].values == ["1/32", "1/16", "1/8"]
    # "Factory values: FIX 0.0, S 1/1, ECO 1/32": where each mode's scale starts
    assert [var.cases[m].initial for m in ("fix", "strobe", "eco")] == ["0.0", "1/1", "1/32"]


def test_a_one_letter_mode_named_by_its_headings_two_word_gloss() -> None:
    model = read_manual(LAMP, LAMP_ACTIONS).model
    assert model.variables["mode"].values == ["fix", "strobe", "eco"]
    assert model.variables["mode"].show["strobe"] == "S"


def test_signs_glossed_with_dotted_leaders_name_the_values() -> None:
    model = read_manual(LAMP, LAMP_ACTIONS).model
    tone = next(v for n, v in model.variables.items() if n.startswith("tone"))
    assert tone.values == ["n", "warm white light", "cool daylight"] or tone.values == [
        "n",
        "warm white",
        "cool daylight",
    ]


BEEP = """
KLIK SL-2 speedlight

  ⑥ OK button. Press briefly to go back to the main screen; press and hold for 3 seconds
    to switch the buzzer on or off.
  ⑦ ZOOM steps the head.
"""


def test_a_hold_after_a_semicolon_switches_the_named_setting() -> None:
    model = read_manual(BEEP, ["press_ok", "hold_ok", "press_zoom"]).model
    held = [st.variable for f in model.features.values() for st in f if st.actions == ["hold_ok"]]
    assert held == ["buzzer"]
