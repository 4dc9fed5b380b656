"""Formats of commercial manuals found on the styled set (ninth round), each on a small manual
of our own."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.text import parse_manual

# a steamer's chart: each column lists the choices of one setting, the default marked in
# brackets, and the column's head says so in brackets too
STEAMER = """KEYS
MENU      Chooses the menu: VEG, FISH, RICE, EGGS.
LEVEL     Steps through the steam levels of the chosen menu.
START     Starts steaming.

MENU CHART

  Menu      Steam levels [default]      Water
  -------   -------------------------   -----
  VEG       low, [medium], high         0.5 l
  FISH      [low], medium               0.4 l
  RICE      medium, [high]              0.8 l
  EGGS      [low], medium, high         0.3 l
"""


def test_a_column_whose_head_names_the_default_in_brackets_lists_each_menus_choices() -> None:
    actions = ["press_menu", "press_level", "press_start"]
    model = read_manual(STEAMER, actions).model
    spec = model.variables["level"].model_dump(mode="json")
    assert spec.get("depends_on") == "menu", spec
    assert spec["cases"]["fish"]["values"] == ["low", "medium"], spec["cases"]
    assert spec["cases"]["rice"]["initial"] == "high", spec["cases"]


def test_a_column_of_one_value_with_a_bracketed_default_still_is_no_value_list() -> None:
    text = STEAMER.replace("Steam levels [default]", "Top level (default)  ")
    for a, b in [
        ("low, [medium], high", "high (medium)      "),
        ("[low], medium", "medium (low) "),
        ("medium, [high]", "high (high)   "),
        ("[low], medium, high", "high (low)         "),
    ]:
        text = text.replace(a, b)
    model = read_manual(text, ["press_menu", "press_level", "press_start"]).model
    assert model.variables["level"].model_dump(mode="json").get("depends_on") is None


# a chart whose rows go on after the page's footer and a drawn line under it
PAGED = """ACME K2 kettle                                                  page 1
-----------------------------------------------------------------------

HOLD key

Hold times

  Display    Hold time         Presses
  -------    ---------------   -------
  0 min      no hold           none
  15 min     a quarter hour    1 press


ACME K2 kettle                                                  page 2
-----------------------------------------------------------------------

  30 min     half an hour      2 presses
  60 min     one hour          3 presses

Cleaning

Wipe the kettle with a damp cloth.

ACME K2 kettle                                                  page 3
-----------------------------------------------------------------------
"""


def test_a_chart_goes_on_after_the_footer_and_the_drawn_line_of_a_page_break() -> None:
    units = parse_manual(PAGED).units
    rows = [u for u in units if u.header and u.header[0] == "Display"]
    assert [u.cells[0] for u in rows] == ["0 min", "15 min", "30 min", "60 min"], [
        (u.text, u.header) for u in units
    ]
