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
