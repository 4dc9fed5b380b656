"""Negative numbers in an instruction: "minus 19", "at -18" (a freezer, a chiller)."""

from __future__ import annotations

from apbot.read.goal_text import Text
from apbot.read.numbers import find_mentions


def test_negative_numbers_are_read_with_their_sign() -> None:
    for said, value in (("at minus 19", -19), ("at -18", -18), (", -21 in", -21)):
        mentions = find_mentions(Text.of(said).tokens)
        assert [m.value for m in mentions] == [value], (said, mentions)
    for said, values in (("combi C-3", [3]), ("2-6 slices", [2, 6])):
        assert [m.value for m in find_mentions(Text.of(said).tokens)] == values, said


def test_a_sign_spaced_off_the_name_before_it_is_a_sign() -> None:
    """ "Freezer -20": the hyphen stands apart from the word and on the digits — a minus,
    where "XR-18" (glued on both sides) stays a code."""
    for said, values in (("freezer -20, fridge 3", [-20, 3]), ("chill box -4", [-4])):
        assert [m.value for m in find_mentions(Text.of(said).tokens)] == values, said
    assert [m.value for m in find_mentions(Text.of("the XR-18 chest").tokens)] == [18]
