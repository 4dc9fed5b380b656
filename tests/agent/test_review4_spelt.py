"""The explorer renames a belief's values to the display's longer spelling only for words:
a dial read as 1, 2, 3 that shows 10, 20, 30 has other values, not the same ones spelt out."""

from __future__ import annotations

from apbot.agent.walk_learning import _spelt_out


def test_short_words_are_spelt_out_but_numbers_are_not_renamed() -> None:
    assert _spelt_out(["eco", "med"], ["economy", "medium"]) == {
        "eco": "economy",
        "med": "medium",
    }
    assert _spelt_out(["1", "2", "5"], ["10", "20", "50"]) == {}
    assert _spelt_out(["p1", "p2"], ["p10", "p20"]) == {}
