"""Rules for manuals that arrive noisy (see benchmarks/manual_noise.py): tables drawn with
spaces by a converter that does not know Markdown, running text broken again."""

from __future__ import annotations

from apbot.read.text import parse_manual

TWO_COLUMNS = """\
## The keys

The keys sit under the display. Tap them lightly.

Key                           Use
⏻ ON (left corner)            Wakes the grill or sends it to sleep.
PANINI · STEAK · FISH         Cooking modes.
VEGETABLES · TOAST · BURGER   More cooking modes.
SEAR                          Adds a burst of heat.
GO                            Starts!
"""


def test_a_two_column_table_drawn_with_spaces_gives_one_row_per_line() -> None:
    units = parse_manual(TWO_COLUMNS).units
    rows = [u for u in units if u.header == ("Key", "Use")]
    assert [u.cells[0] for u in rows] == [
        "⏻ ON (left corner)",
        "PANINI · STEAK · FISH",
        "VEGETABLES · TOAST · BURGER",
        "SEAR",
        "GO",
    ]
    assert rows[1].cells[1] == "Cooking modes."


def test_a_wrapped_two_column_legend_stays_running_text() -> None:
    legend = """\
Key                 Meaning
DRIP                Drop icon. Starts the flow; touch a second time to
(drop)              stop it before the cup is full.
HEAT                Flame icon. Heats the water again.
"""
    units = parse_manual(legend).units
    assert not any(u.header for u in units)
    assert any("stop it before the cup is full" in u.text for u in units)


def test_capitalised_words_in_a_table_are_no_two_columns_of_prose() -> None:
    # three lines split at one gap, whose right parts are short capitalised phrases: a table
    # a converter drew, not prose set side by side (read down one column, then the other)
    text = """\
Part                        Job
⏻ POWER (right corner)      Turns it on and off.
LIGHT · DARK · EXTRA DARK   Browning levels.
BAGEL · PASTRY · CRUMPET    Bread kinds.
"""
    units = parse_manual(text).units
    light = next(u for u in units if "LIGHT" in u.text)
    assert "Browning levels." in light.text
