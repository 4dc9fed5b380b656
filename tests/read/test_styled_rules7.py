"""Rules found on the styled manuals (seventh round), each on a small manual of our own."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.text import parse_manual

# a washer whose chart lists each programme's temperatures and marks the default with a
# symbol that only the legend above the chart explains
WASHER = """CONTROL PANEL

TEMP.      Press to change the wash temperature of the chosen programme.
PROGRAMME  Turn the knob to choose a programme.
START      Starts the wash.

PROGRAMME CHART

◆ = factory setting of the programme      ✓ = possible

  Programme        Temp.                          Pre-wash
  ----------------------------------------------------------------
  Cottons          Cold, 30 °C, 40 °C ◆, 60 °C     ✓
  Synthetics       Cold ◆, 30 °C, 40 °C            ✓
  Wool             Cold ◆, 30 °C                   –
  Towels           40 °C, 60 °C ◆                  ✓

Turn the knob to a programme, press TEMP. until the temperature you want shows, then press START.
"""


def test_a_chart_symbol_the_legend_calls_the_default_gives_each_programme_its_initial() -> None:
    actions = ["turn_programme_cw", "turn_programme_ccw", "press_temp", "press_start"]
    model = read_manual(WASHER, actions).model
    name = next(n for n in model.variables if "temp" in n)
    cases = model.variables[name].model_dump(mode="json")["cases"]
    assert cases["cottons"]["initial"] == "40 °c", cases
    assert cases["synthetics"]["initial"] == "cold", cases
    assert cases["towels"]["initial"] == "60 °c", cases


def test_symbols_no_legend_calls_a_default_still_become_spaces() -> None:
    text = "● Use a socket of the standard kind.\n\nCottons   Cold ✓, Warm\n"
    joined = " ".join(u.text for u in parse_manual(text).units)
    assert "●" not in joined and "✓" not in joined, joined


# a chart whose caption stands on its own line right above the header, with no full stop
CAPTIONED = """Choose the steam level with the STEAM key.

Steam chart (more on the back)
   Touches      Display      Use
   1            S1           shirts
   2            S2           linen
   3            OFF          no steam
"""


def test_a_caption_line_above_a_space_table_does_not_hide_its_header() -> None:
    units = parse_manual(CAPTIONED).units
    rows = [u for u in units if u.cells and u.header]
    assert rows and rows[0].header == ("Touches", "Display", "Use"), [
        (u.text, u.header) for u in units
    ]
    assert not any("Touches" in u.text and not u.cells for u in units)


# an oven's minute minder: typed on the number keys, its top written only as one clock figure
MINDER = """KEYS
MINDER      Sets the minute minder.
0-9         Number keys.
START       Starts the oven or the minder.

MINUTE MINDER
1. Touch MINDER. The display shows 00:00.
2. Type the minutes and seconds on the number keys. You can set up to 99:59.
3. Touch START.
"""


def test_a_top_written_as_one_clock_figure_bounds_a_typed_timer_in_minutes_and_seconds() -> None:
    actions = ["press_minder", *(f"press_{d}" for d in range(10)), "press_start"]
    model = read_manual(MINDER, actions).model
    name = next(n for n in model.variables if "minder" in n)
    var = model.variables[name].model_dump(mode="json")
    assert var["format"] == "mm:ss", var
    assert var["ranges"][-1][1] == "01:39:59", var


def test_a_range_the_sentence_goes_on_past_by_one_level_ends_at_that_level() -> None:
    from apbot.read.values import find_ranges

    said = "Key in a grill setting from 1 to 4, or hold the key for setting 5."
    assert [(r.low, r.high) for r in find_ranges(said)] == [(1, 5)]
    other = "Key in a grill setting from 1 to 4, or 8 for 8 minutes of toasting."
    assert [(r.low, r.high) for r in find_ranges(other)] == [(1, 4)]


# a grill whose chart marks, per food, which browning levels its SHADE key offers
GRILL = """KEYS
FOOD      Press to choose the food: TOAST, BAGEL, MUFFIN, CRUMPET.
SHADE     Press to change the browning: LIGHT, MEDIUM, DARK.
START     Starts toasting.

FOOD AND SHADE CHART

✪ used when the food is chosen (standard)      ✦ can be chosen      – not offered

  Food        LIGHT     MEDIUM     DARK
  --------------------------------------------
  TOAST       ✦         ✪          ✦
  BAGEL       –         ✪          ✦
  MUFFIN      ✪         ✦          –
  CRUMPET     –         –          –

Press FOOD, then SHADE until the browning you want shows, then START.
"""


def test_a_chart_of_marks_gives_each_row_the_marked_values_and_the_default_mark_its_initial() -> (
    None
):
    model = read_manual(GRILL, ["press_food", "press_shade", "press_start"]).model
    name = next(n for n in model.variables if "shade" in n)
    cases = model.variables[name].model_dump(mode="json")["cases"]
    assert cases and cases["toast"] == {"values": ["light", "medium", "dark"], "initial": "medium"}
    assert cases["bagel"] == {"values": ["medium", "dark"], "initial": "medium"}
    assert cases["muffin"]["values"] == ["light", "medium"], cases
    assert "crumpet" not in cases, cases


def test_a_programme_whose_chart_row_shows_a_dash_gets_no_case_filled_from_the_others() -> None:
    washer = WASHER.replace(
        "  Towels           40 °C, 60 °C ◆                  ✓\n",
        "  Towels           40 °C, 60 °C ◆                  ✓\n"
        "  Drain            –                               –\n"
        "  Refresh          –                               –\n",
    )
    actions = ["turn_programme_cw", "turn_programme_ccw", "press_temp", "press_start"]
    model = read_manual(washer, actions).model
    name = next(n for n in model.variables if "temp" in n)
    cases = model.variables[name].model_dump(mode="json")["cases"]
    assert cases["cottons"]["initial"] == "40 °c", cases
    assert "drain" not in cases and "refresh" not in cases, cases


def test_a_wait_in_a_step_numbered_without_a_full_stop_is_still_a_wait() -> None:
    from apbot.read.shapes import is_wait

    assert is_wait("2  Let it soak for 3–4 hours.")
    assert is_wait("4) Wait for 10 to 20 minutes.")
    assert not is_wait("Set 2 to 4 hours with the TIMER key.")
