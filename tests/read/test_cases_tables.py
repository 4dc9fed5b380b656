"""A table the manual calls advice gives no settings per programme: a manual of our own words
read with and without the note that says so."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.cases_tables import _tables, advice_table
from apbot.read.text import parse_manual

DRYER = """
FruitAir FD-4 food dryer

KEYS
  MODE      Each press selects the next mode: FRUIT → HERBS → JERKY → FRUIT.
  TEMP      Each press raises the temperature by 5 °C, from 35 °C to 70 °C.

DRYING GUIDE

  Mode        Temperature   Food
  ----------  -----------   ----------------
  FRUIT       55 °C         apples, bananas
  HERBS       40 °C         basil, mint
  JERKY       70 °C         beef strips

{note}
"""
NOTE = "  These values are suggestions only; the dryer does not set them for you.\n"
ACTIONS = ["press_mode", "press_temp"]


def test_a_table_the_manual_calls_advice_is_no_table_of_programmes() -> None:
    plain = read_manual(DRYER.format(note=""), ACTIONS).model
    advised = read_manual(DRYER.format(note=NOTE), ACTIONS).model
    assert plain.variables["temp"].depends_on == "mode"  # (the table read as per mode)
    assert advised.variables["temp"].depends_on is None
    assert [list(r) for r in advised.variables["temp"].ranges] == [[35, 70, 5]]  # type: ignore[union-attr]


def test_only_a_note_about_the_whole_table_makes_it_advice() -> None:
    column_note = "  The suggested temperatures are only suggestions.\n"
    for note, advice in ((NOTE, True), (column_note, False)):
        units = parse_manual(DRYER.format(note=note), ["mode", "temp"]).units
        ((_, rows),) = _tables(units)
        assert advice_table(units, rows) is advice


def test_a_chart_called_recommended_but_not_left_to_the_user_stays_per_programme() -> None:
    # "recommendations only; adjust them": each mode still sets them, the user may change them
    note = "  These settings are recommendations only; adjust them to the amount of food.\n"
    model = read_manual(DRYER.format(note=note), ACTIONS).model
    assert model.variables["temp"].depends_on == "mode"


def test_an_order_to_the_reader_after_the_advice_note_leaves_the_chart_per_programme() -> None:
    # "Do not select …", "Do not set the dryer …": the reader is told, the dryer still sets them
    for note in (
        "  These values are recommendations only. Do not select JERKY for fish.\n",
        "  These settings are only guidance.\n  Do not set the dryer on a soft surface.\n",
    ):
        model = read_manual(DRYER.format(note=note), ACTIONS).model
        assert model.variables["temp"].depends_on == "mode", note
