"""Rules of the set25a session, each on a small manual of our own words: legend marks in square
brackets and two marks joined for a pair held together (``text._BULLET_RE``), a legend's hold
clause after a semicolon (``roles_holdcell.held_toggle``), numbered codes a chart names
(``code_numbers``), a hold that flips two printed values (``held_flips``), one key stepping both
ways by press and hold (``press_hold_pairs``), a walked field whose values are a printed list
(``walk_listed``), a press opening a setting its numbered steps give (``press_opened``), a
display legend's sign with the word shown while off (``symbol_lamps.sign_meaning``), a play key
printed ▶/❚❚ (``labels.SYMBOLS``, ``work_keys``) and a key tone that is no lock
(``roles_holdcell.lock_or_appliance``)."""

from __future__ import annotations

from typing import Any

from apbot.read import read_manual
from apbot.read.text import parse_manual

# a rowing monitor with three keys, one of them stepping a list both ways
ROWER = """
STROKA RM-3 rowing monitor

4  KEYS AND SCREEN

  (A) MODE   (B) SET   (C) LAMP

  [1]  Top row: KG or LB (weight unit), PAUSE (auto pause on), ☀ (lamp on)
  (A)  MODE - next screen; hold 2 s on the main screen: KG <-> LB; in the weight list:
       next weight (press) / previous weight (hold 2 s)
  (B)  SET - hold 3 seconds to open the weight list; press to close it
  (A)+(B) held together for 3 seconds - clock 24H <-> 12H
  (C)  LAMP - light on / off; hold 2 seconds for auto pause on / off

5  SETTINGS

5.1  Weight unit (KG or LB)
  Hold MODE for 2 seconds on the main screen. The lamp changes from KG to LB, or back.

5.2  Rower weight
  1. Hold SET for 3 seconds. The current weight flashes, for example W 80 kg.
  2. Press MODE to go to the next larger weight. Hold MODE for 2 seconds to go to the
     next smaller weight.
  3. Press SET to close the list.

  The list steps through these weights: 60, 70, 80, 90, 100, 120.

5.3  Clock format
  Hold MODE and SET together for 3 seconds. The display shows 24H or 12H, and the other one
  each time you hold the two keys.
"""
ROWER_ACTIONS = [
    "press_mode",
    "hold_mode",
    "hold_set",
    "press_set",
    "hold_mode_and_set",
    "press_lamp",
    "hold_lamp",
]

# a quiz buzzer timer with lettered keys in columns and a chart of numbered codes
QUIZ = """
BUZZA QT-2 quiz timer

3. KEYS AND DISPLAY

     ① answer time        ② ♫  key tone on (QUIET when off)        ③ ▶  game running

     [A] ⏻      power on / off
     [B] PRG    round type; hold 3 s: key tone on / off
     [C] SET    press: answer time; hold 2 s: warning
     [D] +  [E] −   raise / lower the flashing value
     [F] ▶/❚❚   start or pause the game

4. ROUND TYPES

   | Code   | Round           | What happens                          |
   |--------|-----------------|---------------------------------------|
   | P 1    | Open            | Anyone may buzz.                      |
   | P 2    | Relay           | Teams buzz in turn.                   |
   | P 3    | Knockout        | A wrong answer removes the team.      |

   Press PRG again to step to the next code: P 1 > P 2 > P 3 > P 1 ...

5. ANSWER TIME

   1. Press SET. The answer time flashes, e.g. 0:10 (hours:minutes).
   2. Press + or − to change it by one minute. Hold + or − for 2 seconds to change it by
      ten minutes. The range is 0:01 to 2:00; it stops at both ends.
"""
QUIZ_ACTIONS = [
    "press_power",
    "press_prg",
    "hold_prg",
    "press_set",
    "hold_set",
    "press_plus",
    "press_minus",
    "hold_plus",
    "hold_minus",
    "press_play",
]


def _by_values(model: Any, values: list[str]) -> str:
    """The variable of the read model whose values are these."""
    return next(n for n, v in model.variables.items() if list(v.values or []) == values)


def _feature_of(model: Any, action: str, var: str) -> list[Any]:
    """The features that name ``action`` in a step setting ``var``."""
    return [
        steps
        for steps in model.features.values()
        for step in steps
        if action in step.actions and step.variable == var
    ]


def test_square_bracket_marks_in_columns_start_legend_items() -> None:
    units = [u.text for u in parse_manual(QUIZ, ["prg", "set"]).units]
    assert "PRG    round type; hold 3 s: key tone on / off" in units
    assert any(u.startswith("SET    press: answer time") for u in units)


def test_two_joined_marks_start_their_own_item() -> None:
    units = [u.text for u in parse_manual(ROWER, ["mode", "set"]).units]
    assert any(u.startswith("held together for 3 seconds - clock 24H") for u in units)
    assert not any("press to close it" in u and "held together" in u for u in units)


def test_a_hold_clause_after_a_semicolon_toggles_its_noun() -> None:
    model = read_manual(QUIZ, QUIZ_ACTIONS).model
    tone = [n for n in model.variables if n.startswith("key_tone")]
    assert tone and _feature_of(model, "hold_prg", tone[0])
    # "hold 2 seconds for auto pause on / off": the hold's own toggle, named
    rower = read_manual(ROWER, ROWER_ACTIONS).model
    assert "auto_pause" in rower.variables and _feature_of(rower, "hold_lamp", "auto_pause")


def test_numbered_codes_take_the_charts_names() -> None:
    model = read_manual(QUIZ, QUIZ_ACTIONS).model
    var = _by_values(model, ["open", "relay", "knockout"])
    assert model.variables[var].show == {"open": "P 1", "relay": "P 2", "knockout": "P 3"}
    assert _feature_of(model, "press_prg", var)


def test_a_hold_that_flips_two_printed_values() -> None:
    model = read_manual(ROWER, ROWER_ACTIONS).model
    unit = _by_values(model, ["kg", "lb"])
    assert unit == "weight_unit" and _feature_of(model, "hold_mode", unit)
    assert not _feature_of(model, "press_mode", unit)


def test_a_two_key_hold_that_flips_values_is_no_lock() -> None:
    model = read_manual(ROWER, ROWER_ACTIONS).model
    assert "child_lock" not in model.variables
    clock = _by_values(model, ["24h", "12h"])
    assert clock == "clock_format" and _feature_of(model, "hold_mode_and_set", clock)


def test_press_and_hold_of_one_key_step_a_printed_list() -> None:
    model = read_manual(ROWER, ROWER_ACTIONS).model
    weight = _by_values(model, ["60", "70", "80", "90", "100", "120"])
    assert weight == "rower_weight"
    steps = next(s for s in model.features.values() if s[-1].variable == weight)
    assert steps[0].actions == ["hold_set"]
    assert steps[-1].effect == {"press_mode": "next", "hold_mode": "prev"}


def test_a_press_opens_the_setting_its_steps_give() -> None:
    model = read_manual(QUIZ, QUIZ_ACTIONS).model
    spec = model.variables["answer_time"]
    assert spec.type == "time"
    assert [list(map(str, r)) for r in spec.ranges] == [["00:01:00", "02:00:00", "60"]]
    steps = next(s for s in model.features.values() if s[-1].variable == "answer_time")
    assert steps[0].actions == ["press_set"]
    assert steps[-1].effect["hold_plus"].add == 600  # "hold … to change it by ten minutes"


def test_a_display_legends_sign_and_its_word_when_off() -> None:
    model = read_manual(QUIZ, QUIZ_ACTIONS).model
    tone = next(n for n in model.variables if n.startswith("key_tone"))
    assert model.variables[tone].show == {"off": "QUIET", "on": "♫"}
    rower = read_manual(ROWER, ROWER_ACTIONS).model
    assert rower.variables["lamp"].show == {"off": "", "on": "☀"}
    # a key's "power on / off" names no sign of the display
    assert model.variables["power"].show != {"off": "", "on": "⏻"}


def test_a_play_key_printed_as_its_sign_starts_and_pauses_the_game() -> None:
    model = read_manual(QUIZ, QUIZ_ACTIONS).model
    assert _feature_of(model, "press_play", "running")
    # "♫ key tone on (QUIET when off)" on the line that says running: QUIET is no running word
    assert (model.variables["running"].show or {}).get("on") != "QUIET"


def test_a_key_tone_is_no_lock() -> None:
    model = read_manual(QUIZ, QUIZ_ACTIONS).model
    assert "child_lock" not in model.variables and "key_tone" in model.variables
