"""unify18: one test of a coded chart's code column for the settings-menu reader and the walk
of coded fields. A chart whose code column is headed "Display" is the same chart as one headed
"Code", and the settings-menu reader (which wins on a chart both read) reads both alike."""

from __future__ import annotations

import pytest

from apbot.read.reader import read_manual

_WARMER = """ORA B2 bottle warmer

CONTROLS

  POWER turns the warmer on and off. SET leads through the user settings; + and - change
  the value shown.

USER SETTINGS

  Each setting is shown by a short code in front of its value, in this order:

  | {head} | Setting    | Values              |
  |------|------------|---------------------|
  | HT   | Heat       | LOW, MID, HIGH      |
  | KW   | Keep warm  | OFF, 10, 20, 30     |
  | BZ   | Buzzer     | ON, OFF             |

  1. Press SET. HT and its value appear.
  2. Press + or - until the value you want is shown.
  3. Press SET. The value is kept and the next code appears.
"""


@pytest.mark.parametrize("head", ["Code", "Display", "Codes"])
def test_a_code_column_headed_display_is_the_settings_menus_chart(head: str) -> None:
    actions = ["press_power", "press_set", "press_plus", "press_minus"]
    model = read_manual(_WARMER.replace("{head}", head), actions).model
    menu = model.features["settings_menu"]
    labels = [model.variables[s.variable].label for s in menu if s.variable]
    assert labels == ["HT", "KW", "BZ"]
    assert [str(v) for v in model.variables[menu[1].variable or ""].values] == [
        "low",
        "mid",
        "high",
    ]
