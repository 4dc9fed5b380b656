"""Reader rules a third review found misfiring, each on a small manual of its own."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.shown import shown_words
from apbot.sim.simulator import Simulator


def test_a_figure_callout_letter_after_an_icon_is_not_its_glyph() -> None:
    assert shown_words("The kettle icon (B) lights while water heats.") == ["KETTLE"]
    assert shown_words("A leaf symbol (C) appears in eco mode.") == ["LEAF"]


def test_a_printed_glyph_or_word_after_an_icon_still_shows() -> None:
    assert shown_words("The star symbol (*) lights.") == ["*"]
    assert shown_words("The fan icon (AIR) lights.") == ["AIR"]


KEY_LEGEND = """# Soup maker SM-1

## Buttons

| No. | Mode | What it does |
|-----|------|--------------|
| 1 | PROG | Steps through the soup programs. |
| 2 | KEEP WARM | Keeps the soup hot. |
| 3 | START | Begins blending and heating. |
| 4 | STOP | Ends the program. |

## Picking a program

Press PROG several times to pick a program; its lamp lights.

Press START to begin and STOP to end.
"""


def test_a_numbered_legend_of_the_panels_keys_is_not_a_programme_list() -> None:
    actions = ["press_prog", "press_keep_warm", "press_start", "press_stop"]
    model = read_manual(KEY_LEGEND, actions).model
    prog = model.variables.get("prog")
    values = {str(v).lower() for v in (prog.values or [])} if prog else set()
    assert not {"start", "stop", "keep warm"} & values


NUMBERED_PROGRAMMES = """# Soup maker SM-2

| No. | Program | Time |
|-----|---------|------|
| 1 | SMOOTH | 25 min |
| 2 | CHUNKY | 30 min |
| 3 | JUICE | 5 min |

Press PROG several times to pick a program.
"""


def test_a_numbered_chart_of_programme_names_is_still_the_programme_list() -> None:
    model = read_manual(NUMBERED_PROGRAMMES, ["press_prog", "press_start"]).model
    assert model.variables["prog"].values == ["smooth", "chunky", "juice"]


TWO_SETTINGS = """# Slow steamer ST-4

## Keys

- STEAM TIME: how long the food steams.
- DELAY: how long to wait before steaming.
- START: begins.

## Times

The delay may be set from 1 to 8 hours.

The steam time goes up by 2 min until 20 min; past 20 min it goes up by 10 min, up to 120 min.

Press DELAY several times to choose the wait.

Press STEAM TIME, then turn the dial to set the steaming time.
"""
ST_ACTIONS = ["press_steam_time", "press_delay", "press_start", "turn_dial_left", "turn_dial_right"]


def test_a_changing_step_told_of_another_setting_is_not_this_settings_range() -> None:
    model = read_manual(TWO_SETTINGS, ST_ACTIONS).model
    ranges = getattr(model.variables["delay"], "ranges", None) or []
    assert len(ranges) == 1 and ranges[0][1] in (8, "08:00:00")  # (before: the steam pieces)


SHADES = """KEYS

SHADE     Print shade. Each touch goes one shade deeper, and after the deepest back to the
          palest. The screen reads SHADE 1, SHADE 2 or SHADE 3.
GO        Starts printing.
"""


def test_levels_stripped_of_the_keys_name_still_display_with_it() -> None:
    model = read_manual(SHADES, ["press_shade", "press_go"]).model
    sim = Simulator(model)
    sim.reset()
    shown = [sim.step("press_shade").display for _ in range(3)]
    assert shown == ["SHADE 2", "SHADE 3", "SHADE 1"]  # as the manual says the screen reads
