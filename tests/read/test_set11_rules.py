"""Rules of the set11 session, each on a small manual of our own words: clock figures of a
setting told in whole minutes are minutes (``values_labels.whole_minutes_said``), and the stops
an ellipsis leaves out of a printed row (``list_ellipsis.fill_ellipses``)."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.list_ellipsis import fill_ellipses
from apbot.read.values_labels import whole_minutes_said

# a foot spa whose BATH key steps a bath time shown as a clock figure
SPA = """
AquaRelax FS-2 foot spa

  Keys: ⏻  BATH  START

  BATH   Bath time.

BATH TIME

 A bath lasts 2 to 8 minutes. Each press of BATH adds one minute; after 8:00 it goes
 back to 2:00.

    2:00 → 3:00 → 4:00 ... → 7:00 → 8:00 → 2:00
"""


def test_a_clock_row_of_a_setting_told_in_minutes_is_minutes_and_seconds() -> None:
    model = read_manual(SPA, ["press_power", "press_bath", "press_start"]).model
    bath = model.variables["bath"]
    assert bath.format == "mm:ss"
    assert [tuple(r) for r in bath.ranges] == [("00:02:00", "00:08:00", 60)]


def test_whole_minutes_need_minute_words_and_no_hours() -> None:
    assert whole_minutes_said(["2:00", "8:00"], ["A bath lasts 2 to 8 minutes."])
    assert whole_minutes_said(["2:00", "3:00"], ["Each press adds one minute."])
    assert not whole_minutes_said(["2:00", "8:00"], ["Each press adds one hour."])
    assert not whole_minutes_said(["2:30", "8:00"], ["A bath lasts 2 to 8 minutes."])
    assert not whole_minutes_said(["2:00", "8:00"], ["Delay the start by 2 to 8 hours."])


def test_an_ellipsis_in_a_row_stands_for_the_stops_on_the_step_before_it() -> None:
    assert fill_ellipses([10, 20, 30, 90], "10 → 20 → 30 … 90", float) == [
        10, 20, 30, 40, 50, 60, 70, 80, 90,
    ]  # fmt: skip
    # no ellipsis, no stops made up: a jump stays a jump
    assert fill_ellipses([10, 20, 30, 90], "10 → 20 → 30 → 90", float) == [10, 20, 30, 90]
