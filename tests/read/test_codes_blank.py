"""Codes a key steps through with the display's blank among them ("-- → B1 → B2 → B3"): the
chart that names the codes names the blank too, so every value takes its name (``codes``)."""

from __future__ import annotations

from apbot.read import read_manual

STAMPER = """INKO S-4 LABEL STAMPER
Instructions

KEYS
  (1)  ⏻        On / off
  (2)  BORDER   Border around the label

BORDERS
  Press BORDER repeatedly to choose a border. The display shows the border number:

    | Disp. | Border          | Looks like |
    |-------|-----------------|------------|
    | --    | no border       | TEXT       |
    | B1    | thin line       | [TEXT]     |
    | B2    | wavy line       | ~TEXT~     |
    | B3    | hearts          | <3 TEXT    |

  After B3 the next press returns to no border (--).
"""


def test_the_blank_among_codes_is_named_by_the_chart() -> None:
    model = read_manual(STAMPER, ["press_power", "press_border"]).model
    border = model.variables["border"]
    assert border.values == ["no border", "thin line", "wavy line", "hearts"]  # type: ignore[union-attr]
    assert border.show["no border"] == "--"  # type: ignore[union-attr,index]


def test_two_blanks_are_no_codes_to_name() -> None:
    text = STAMPER.replace("| B3    | hearts ", "| ---   | hearts ").replace("B3", "---")
    model = read_manual(text, ["press_power", "press_border"]).model
    assert "no border" not in model.variables["border"].values  # type: ignore[union-attr]
