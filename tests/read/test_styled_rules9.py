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


# a hob's timer: the steps of each span told in lettered items under a numbered step, and a
# worked example elsewhere that presses TIMER beside a temperature run
HOB = """KEYS
TIMER      Sets the cooking timer.
KNOB       Turn to change the value shown.
START      Starts cooking.

SETTING THE TIMER
1. Press TIMER. The display shows TIMER 0:00.
2. Turn the knob clockwise to set the time.
   a) From 0:00 to 1:00 each click is one minute.
   b) From 1:00 to 4:00 each click is fifteen minutes.
3. Press START.

EXAMPLE
Can I keep soup at 85 °C for two hours?
Yes: knob 2 clicks anticlockwise (95 → 90 → 85 °C), TIMER, knob 64 clicks clockwise.
"""

HOB_ACTIONS = ["press_timer", "turn_knob_cw", "turn_knob_ccw", "press_start"]


def test_spans_of_a_timer_each_with_what_a_click_adds_are_its_pieces() -> None:
    spec = read_manual(HOB, HOB_ACTIONS).model.variables["timer"].model_dump(mode="json")
    assert spec["type"] == "time", spec
    assert spec["ranges"] == [["00:00:00", "01:00:00", 60], ["01:00:00", "04:00:00", 900]], spec


# a cooker's delay, set with + and −, its steps told in the items under that step
COOKER = """BUTTONS
DELAY      Delays the end of cooking.
+ / –      Change the value shown.
START      Starts cooking.

DELAYED START
1. Press DELAY. 0:00 flashes.
2. Press + to lengthen the delay, – to shorten it.
   - from 0:00 to 2:00 each press changes the delay by 15 minutes;
   - from 2:00 to 12:00 each press changes it by one hour.
3. Press START.
"""


def test_steps_told_in_the_items_under_a_press_of_the_stepping_keys_are_the_settings() -> None:
    actions = ["press_delay", "press_plus", "press_minus", "press_start"]
    spec = read_manual(COOKER, actions).model.variables["delay"].model_dump(mode="json")
    assert spec["ranges"] == [["00:00:00", "02:00:00", 900], ["02:00:00", "12:00:00", 3600]], spec
