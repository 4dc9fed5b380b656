"""Values and ranges the read model lacked (seventh round), each on a small manual of our own."""

from __future__ import annotations

from apbot.read import read_manual

# a panel drawn with key caps in square brackets, spaced like a table, and a chart of what
# each touch of one key shows on the display
STEAMER = """CONTROL PANEL

  [ STEAM      ] [ COOK TIME   ]        Display: the time of day, or the setting
  [ LEVEL      ] [ CLOCK       ]        being entered.
  [ 1 ] [ 2 ] [ 3 ]
  [ STOP       ]  [ START ]

STEAM
  1. Touch STEAM. Each touch moves on to the next steam amount, as the chart shows.
  2. Touch START.

Steam chart
   Touch STEAM      Display          Use
   1 time           STM 2 cups       vegetables
   2 times          STM 4 cups       fish
   3 times          STM off          no steam
"""

STEAMER_ACTIONS = [
    "press_steam",
    "press_cook_time",
    "press_level",
    "press_clock",
    "press_1",
    "press_2",
    "press_3",
    "press_stop",
    "press_start",
]


def test_key_caps_drawn_in_brackets_are_no_column_of_values() -> None:
    model = read_manual(STEAMER, STEAMER_ACTIONS).model
    values = [str(v) for v in model.variables["steam"].model_dump(mode="json").get("values", [])]
    assert not any("[" in v or "clock" in v or "level" in v for v in values), values


def test_a_display_column_loses_the_word_every_row_starts_with() -> None:
    model = read_manual(STEAMER, STEAMER_ACTIONS).model
    values = model.variables["steam"].model_dump(mode="json")["values"]
    assert values == ["2 cups", "4 cups", "off"], values

