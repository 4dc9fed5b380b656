"""Uneven scales printed under the sentence that introduces them (values_scales), each run of
equal gaps one piece of the setting, in short manuals written in our own words."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.text import parse_manual
from apbot.read.values import Range
from apbot.read.values_scales import scale_pieces, uneven_pieces


def test_runs_of_equal_gaps_are_pieces() -> None:
    assert uneven_pieces([100, 120, 140, 150, 160], "°C") == [
        Range(100, 140, "°C", 20),
        Range(140, 160, "°C", 10),
    ]
    assert uneven_pieces([1, 2, 3, 4], "") == []  # even: one range, read elsewhere


def _scale(text: str) -> list[Range]:
    units = parse_manual(text).units
    at = next(i for i, u in enumerate(units) if u.text.rstrip().endswith(":"))
    return scale_pieces(units, at)


def test_a_scale_drawn_with_a_line_takes_the_unit_in_brackets() -> None:
    said = (
        "The heat goes in unequal steps.\n\n"
        "Heat settings (°C):\n\n"
        "   90 ── 110 ── 130 ── 140 ── 150\n"
    )
    assert _scale(said) == [Range(90, 130, "°C", 20), Range(130, 150, "°C", 10)]


def test_a_one_row_table_led_by_its_unit() -> None:
    said = (
        "Choose the soaking time. The times you can choose are:\n\n"
        "   +---------+---+---+---+----+----+\n"
        "   | minutes | 3 | 6 | 9 | 12 | 20 | 28 |\n"
        "   +---------+---+---+---+----+----+\n"
    )
    assert _scale(said) == [Range(3, 12, "min", 3), Range(12, 28, "min", 8)]


def test_codes_that_do_not_climb_are_no_scale() -> None:
    said = "The firing codes are:\n\n   022 → 018 → 010 → 06 → 05\n"
    assert _scale(said) == []


GRIDDLE = """BAKO GR-2 griddle

KEYS
   ⏻          on / off
   HEAT −     lowers the plate heat by one step
   HEAT +     raises the plate heat by one step
   START      starts and stops the timer

Plate heat

   The plate heat is set with HEAT − and HEAT +. The steps are not even.

      Plate heats (°C):

         150 ── 170 ── 190 ── 200 ── 210 ── 220

   At the ends the keys do nothing more.
"""


def test_the_griddle_heat_is_read_in_its_pieces() -> None:
    model = read_manual(GRIDDLE, ["press_power", "press_heat_minus", "press_heat_plus"]).model
    heat = next(v for n, v in model.variables.items() if "heat" in n)
    assert [tuple(r) for r in heat.ranges] == [(150, 190, 20), (190, 220, 10)]


FRYER = """# KOKO AF-5 air fryer

## Keys

| Key | What it does |
|---|---|
| ⏻ | On and off. |
| TIME + | Adds a minute to the cooking time. |
| TIME − | Takes a minute off the cooking time. |

## Cooking time

Set the cooking time with TIME + and TIME −. Suggested times for common foods (minutes):

    8 ── 12 ── 15 ── 18 ── 25

The cooking time can be set from 1 to 60 minutes in steps of 1 minute.
"""


def test_a_range_stated_after_a_guides_stops_and_reaching_past_them_holds() -> None:
    model = read_manual(FRYER, ["press_power", "press_time_plus", "press_time_minus"]).model
    time = next(v for n, v in model.variables.items() if "time" in n)
    assert [tuple(r) for r in time.ranges] == [("00:01:00", "01:00:00", 60)]


XL = """# KOKO AF-6 air fryer

## Keys

| Key | What it does |
|---|---|
| ⏻ | On and off. |
| TEMP + | Raises the temperature. |
| TEMP − | Lowers the temperature. |

## Temperature

Press TEMP + or TEMP − to set the temperature from 80 to 200 °C in 10 °C steps.

On the larger model the temperatures are (°C):

    80 ── 100 ── 120 ── 140 ── 180 ── 200 ── 230
"""


def test_a_scale_reaching_past_the_range_stated_before_it_is_not_this_settings() -> None:
    model = read_manual(XL, ["press_power", "press_temp_plus", "press_temp_minus"]).model
    temp = next(v for n, v in model.variables.items() if "temp" in n)
    assert [tuple(r) for r in temp.ranges] == [(80, 200, 10)]


def test_a_row_of_numbers_in_no_unit_is_no_scale() -> None:
    assert _scale("The heater is sold in these sizes:\n\n   1200 ── 1500 ── 1800 ── 2000\n") == []
    assert _scale("This manual covers the years:\n\n   2019 ── 2020 ── 2021 ── 2023\n") == []
