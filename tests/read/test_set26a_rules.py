"""Rules of the set26a session, each on a small manual of our own words: a chart of the values
a setting steps through (``chart_steps``), figures each counted by one noun and a run that goes
"then back to" its start (``value_runs_back``), a key that starts and stops the noun of its own
verb (``work_keys``), the word shown while other keys are locked (``roles_running``), signs kept
and read as a dial's positions (``text_chars``, ``value_runs_back.drawn_sign``, ``text_boxes``)
and a key's values per dial position from a table (``cases_positions``)."""

from __future__ import annotations

from typing import Any

from apbot.model.domain import all_values
from apbot.read import read_manual
from apbot.read.text import parse_manual
from apbot.read.value_lists import find_list

# a photo-lamp timer that steps a printed scale, with a run of counts and a start key
LAMP = """
GLOWBOX LT-2 print lamp timer

2  KEYS

  (1) ⏻       on / standby
  (2) (3)     ▲ ▼ a longer / shorter time
  (4) BANDS   number of bands
  (5) GAP     change between bands
  (6) BURN    start / stop a burn (the pedal does the same)

3  THE TIME SCALE

  The timer does not count in whole seconds. It moves along this scale:

  +------+------+------+------+
  | 2.0  | 2.8  | 4.0  | 5.6  |
  +------+------+------+------+
  | 8.0  | 11   | 16   | 23   |
  +------+------+------+------+

  The time is set with ▲ and ▼. The time stops at 2.0 s and at 23 s.

4  BANDS AND GAPS

  1. Press BANDS. The first press only shows the count, for example BANDS 4. Each further
     press adds one band: 4, 5, 6, then back to 2.
  2. Press GAP. Again the first press only shows it. Each further press picks the next
     change between bands:

        1/4 turn  >  1/2 turn  >  1 turn  >  back to 1/4

5  BURNING

  Press BURN to start; press it again to stop early. While a burn runs every other key is
  locked (the display shows WAIT); only BURN and ⏻ work.
"""

LAMP_ACTIONS = ["press_power", "press_up", "press_down", "press_bands", "press_gap", "press_burn"]


def _lamp() -> dict[str, Any]:
    return dict(read_manual(LAMP, LAMP_ACTIONS).model.model_dump()["variables"])


def _stepped(variables: dict[str, Any], action: str, model: Any) -> str:
    return next(s.variable for f in model.features.values() for s in f if action in s.actions)


def test_a_chart_of_numbers_gives_the_values_a_stepped_time_takes() -> None:
    model = read_manual(LAMP, LAMP_ACTIONS).model
    name = _stepped({}, "press_up", model)
    values = list(model.variables[name].values)
    assert values == ["2.0 s", "2.8 s", "4.0 s", "5.6 s", "8.0 s", "11 s", "16 s", "23 s"]
    assert model.variables[name].wrap is False


def test_a_run_that_goes_back_counts_from_where_it_goes_back_to() -> None:
    model = read_manual(LAMP, LAMP_ACTIONS).model
    bands = model.variables[_stepped({}, "press_bands", model)]
    assert [float(v) for v in all_values(bands)] == [2, 3, 4, 5, 6]


def test_figures_each_with_one_noun_are_the_figures() -> None:
    assert find_list("1/4 turn  >  1/2 turn  >  1 turn  >  back to 1/4") == (
        ["1/4", "1/2", "1"],
        "arrows",
    )
    model = read_manual(LAMP, LAMP_ACTIONS).model
    assert list(model.variables[_stepped({}, "press_gap", model)].values) == ["1/4", "1/2", "1"]


def test_a_key_starting_and_stopping_its_own_verbs_noun_runs_the_job() -> None:
    model = read_manual(LAMP, LAMP_ACTIONS).model
    running = _stepped({}, "press_burn", model)
    assert list(model.variables[running].values) == ["off", "on"]
    guard = next(g for g in model.guards if running in g.when)
    assert "press_burn" in guard.only
    # WAIT is what a refused key shows, not the lamp of a running burn
    assert "WAIT" not in str(model.variables[running].show or "")


# a bench meter: signs on the dial, per-position tables
METER = """
OHMEX BM-2 bench meter

2  THE PANEL

   Buttons
   [1] MODE     picks the second function of the dial position.
                Hold for 2 seconds: beeper on / off.
   [2] SPAN     steps through the fixed spans; hold 2 seconds to return to AUTO.
   [3] FREEZE   freezes / releases the reading.

   Display
   (g)          what MODE has chosen: °C or °F on TEMP; DC or AC on the current positions

3  THE DIAL

   The dial positions, clockwise from OFF:

     OFF > V⎓ > Ω·)))▶| > ⊣⊢ > TEMP > mA

   ┌──────┬──────────┬──────────────┐
   │ Pos. │ Display  │ Measures     │
   ├──────┼──────────┼──────────────┤
   │ 1    │ V⎓       │ DC voltage   │
   │ 2    │ Ω        │ resistance   │
   │ 3    │ nF       │ capacitance  │
   │ 4    │ TEMP     │ temperature  │
   │ 5    │ mA       │ current      │
   └──────┴──────────┴──────────────┘

4  THE MODE BUTTON

   ┌──────────┬──────────────────────────────┐
   │ Position │ MODE steps                   │
   ├──────────┼──────────────────────────────┤
   │ Ω        │ Ω ohms  >  ▶| diode          │
   │ TEMP     │ °C  >  °F                    │
   │ mA       │ DC  >  AC                    │
   └──────────┴──────────────────────────────┘

5  SPANS

   In AUTO the meter picks the span. Each press of SPAN fixes the next higher span; after the
   highest, the next press returns to AUTO.

   Fixed spans per position (lowest first):

   ┌──────┬──────────────────────────┐
   │ V⎓   │ 2 V    20 V    200 V     │
   │ Ω    │ 200 Ω   2 kΩ   20 kΩ     │
   │ mA   │ 20 mA   200 mA           │
   │ TEMP │ automatic only           │
   └──────┴──────────────────────────┘
"""

METER_ACTIONS = [
    "turn_dial_cw",
    "turn_dial_ccw",
    "press_mode",
    "hold_mode",
    "press_span",
    "hold_span",
    "press_freeze",
]


def test_the_dc_sign_and_a_sign_drawn_with_a_bar_are_kept() -> None:
    units = parse_manual(METER, ["dial", "mode", "span", "freeze"]).units
    assert any("V⎓" in u.text for u in units)
    row = next(u for u in units if u.cells and u.cells[0] == "Ω" and "diode" in u.text)
    assert len(row.cells) == 2  # ("▶|" split no column off)


def test_a_dial_of_printed_signs_keeps_every_position() -> None:
    model = read_manual(METER, METER_ACTIONS).model
    dial = model.variables[_stepped({}, "turn_dial_cw", model)]
    assert list(dial.values) == ["off", "v⎓", "ω·)))▶|", "⊣⊢", "temp", "ma"]
    assert dict(dial.show or {})["⊣⊢"] == "nF"  # (the numbered table's Display column)


def test_a_keys_values_per_dial_position_make_it_depend_on_the_dial() -> None:
    model = read_manual(METER, METER_ACTIONS).model
    dial = _stepped({}, "turn_dial_cw", model)
    mode = model.variables[_stepped({}, "press_mode", model)]
    assert mode.depends_on == dial
    assert list(mode.cases["temp"].values) == ["°c", "°f"]
    assert list(mode.cases["ω·)))▶|"].values) == ["ohms", "diode"]
    span_name = _stepped({}, "press_span", model)
    span = model.variables[span_name]
    assert span.depends_on == dial
    assert list(span.cases["v⎓"].values) == ["auto", "2 V", "20 V", "200 V"]
    assert "temp" not in span.cases  # ("automatic only": no fixed span there)
    held = next(s for f in model.features.values() for s in f if "hold_span" in s.actions)
    assert held.variable == span_name  # (the hold returns the span to AUTO)
