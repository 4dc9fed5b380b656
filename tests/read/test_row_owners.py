"""A table row's amounts belong to the setting the row or the column names (evidence_whose.py:
``led_by_another``, ``own_columns``), each on a small manual of our own words."""

from __future__ import annotations

from apbot.read import read_manual

# a drying cupboard: a specification row about the delay follows the row naming the keys, and a
# programme table keeps one column per timed key
CUPBOARD = """
Siccus DC-4 drying cupboard

SPECIFICATIONS

  Item                    DC-4
  ----------------------  ---------------------------------
  Programmes              AUTO, WARM+AIR, WARM, AIR
  Delayed start           0 - 12 h
  Keys                    ⏻ PROG WARM AIR − + DELAY START

PROGRAMME TABLE

  Programme   What it does                 Warming time        Airing time
  ----------  ---------------------------  ------------------  -----------------
  AUTO        warm, then air               fixed               fixed
  WARM+AIR    warm, then air               10 - 30 min         20 - 90 min
  WARM        warming only                 10 - 30 min         none
  AIR         airing only                  none                20 - 90 min

  To change the warming time, touch WARM, then − or +.
  To change the airing time, touch AIR, then − or +.

  Delayed start: touch DELAY; each touch adds one hour, up to 12 hours.
"""
ACTIONS = [
    "press_power", "press_prog", "press_warm", "press_air", "press_minus", "press_plus",
    "press_delay", "press_start",
]  # fmt: skip


def _ranges(name: str) -> list[list[str]]:
    model = read_manual(CUPBOARD, ACTIONS).model
    var = model.variables[name]
    return [[str(x) for x in r[:2]] for r in (getattr(var, "ranges", None) or [])]


def test_a_specification_row_named_for_another_key_is_not_this_key_s() -> None:
    assert _ranges("air") and _ranges("air")[0] != ["0", "12"]  # not the delay's 0 - 12 h


def test_a_row_s_amount_is_taken_from_the_column_named_for_the_key() -> None:
    assert _ranges("air") == [["00:20:00", "01:30:00"]]  # the airing column, not warming's
