"""A number the speaker takes back at once ("speed 8 - no, make it seven") is not meant: only the
correction is (goal_spelling)."""

from __future__ import annotations

from apbot.read.goal_spelling import _corrected


def test_a_number_taken_back_goes() -> None:
    assert _corrected("Mix at speed 8 - no, make it seven - for 5 minutes") == (
        "Mix at speed seven - for 5 minutes"
    )
    assert _corrected("Heat to 60... sorry, 65 degrees") == "Heat to 65 degrees"


def test_a_no_that_corrects_nothing_stays() -> None:
    assert _corrected("level 3 - no problem") == "level 3 - no problem"
    assert _corrected("two cups, no sugar") == "two cups, no sugar"
