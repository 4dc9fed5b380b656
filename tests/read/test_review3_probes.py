"""Reader rules a third review found misfiring, each on a small manual of its own."""

from __future__ import annotations

from apbot.read.shown import shown_words


def test_a_figure_callout_letter_after_an_icon_is_not_its_glyph() -> None:
    assert shown_words("The kettle icon (B) lights while water heats.") == ["KETTLE"]
    assert shown_words("A leaf symbol (C) appears in eco mode.") == ["LEAF"]


def test_a_printed_glyph_or_word_after_an_icon_still_shows() -> None:
    assert shown_words("The star symbol (*) lights.") == ["*"]
    assert shown_words("The fan icon (AIR) lights.") == ["AIR"]
