"""Reader rules a third review found misfiring, each on a small manual of its own."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.shown import shown_words


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
