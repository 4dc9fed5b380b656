"""A chart's cells belong to their columns: a range in another setting's column, or inside a
row's name, is not the range of the setting a cell names; and a symbol named in a legend keeps
a chart drawn with spaces in its columns. Short manuals in our own words."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.chart_cells import own_cells, row_names, without_names
from apbot.read.text import Unit, parse_manual

HEAD = ("Menu", "Cooking time", "Delay")


def test_a_row_gives_a_setting_only_its_own_column() -> None:
    row = Unit(
        9,
        "STEAM | 0:10 – 0:50 | not possible (TIMER --)",
        ("STEAM", "0:10 – 0:50", "not possible (TIMER --)"),
        HEAD,
    )
    assert own_cells(row, {"delay"}).text == "not possible (TIMER --)"
    assert own_cells(row, {"cook", "time"}).text == "0:10 – 0:50"


def test_a_range_in_a_rows_name_is_part_of_the_name() -> None:
    head = ("Programme", "Load", "Wash")
    row = Unit(
        9,
        "Mix 30-50 | 6 kg | automatic (TEMP --)",
        ("Mix 30-50", "6 kg", "automatic (TEMP --)"),
        head,
    )
    assert "30-50" not in own_cells(row, {"temp"}).text
    assert row_names([row]) == ["Mix 30-50"]
    assert "30" not in without_names("Mix 30-50 has no temperature of its own.", ["Mix 30-50"])


# a cooker whose delay column says "not possible" on a row that also prints a cooking time
COOKER = """# Multi cooker MC-2

## Keys
| Key | Function |
|---|---|
| MENU | Chooses the menu: RICE, STEAM or SOUP. |
| DELAY | Sets after how long the cooking ends, 0:30 to 12:00, in 30-minute steps. |
| START | Starts cooking. |

## Menu chart
| Menu | Cooking time | Delay |
|---|---|---|
| RICE | automatic | up to 12:00 |
| STEAM | 0:10 – 0:50 | not possible (DELAY --) |
| SOUP | 0:30 – 2:00 | up to 12:00 |
"""


def test_the_delay_is_not_read_from_the_cooking_time_column() -> None:
    model = read_manual(COOKER, ["press_menu", "press_delay", "press_start"]).model
    delay = model.variables["delay"]
    assert str(delay.ranges[0][1]) in ("12:00:00", "43200"), delay.ranges


def test_a_named_snowflake_keeps_a_spaced_chart_in_its_columns() -> None:
    text = """# Washer

TEMP cold = ❄

 Programme    Temperatures        Spin speeds
 ----------   -----------------   -----------------
 Cottons      ❄ 20 [40] 60        400 800 [1200]
 Mixed        ❄ [30] 40           400 [800] 1000
                                  1400
 Wool         ❄ [20]              [400] 600
"""
    rows = [u.cells for u in parse_manual(text).units if u.cells and u.header]
    assert ("Mixed", "COLD [30] 40", "400 [800] 1000 1400") in rows, rows


def test_a_spaced_list_of_values_marks_its_default_in_brackets() -> None:
    from apbot.read.cases_cells import _case

    spec = {"type": "discrete", "values": ["cold", "20", "40", "60"]}
    assert _case(spec, "COLD 20 [40] 60") == {"values": ["cold", "20", "40", "60"], "initial": "40"}
