"""Rows of clock times that trail off go on round the whole day."""

from apbot.read.clock_rows import open_day_row
from apbot.read.values import Range


def test_open_row_of_times_of_day_is_the_whole_day() -> None:
    said = "Each touch sets the wake time 15 minutes later (06:00 → 06:15 → 06:30 …)."
    assert open_day_row(["06:00", "06:15", "06:30"], said) == Range(0, 85500, "s", 900)


def test_row_with_a_last_time_or_durations_is_left_alone() -> None:
    closed = "The delay steps (01:00, 02:00, 03:00 … 12:00)."
    assert open_day_row(["01:00", "02:00", "03:00"], closed) is None
    duration = "Each press adds half an hour (0:30 → 1:00 → 1:30 …)."
    assert open_day_row(["0:30", "1:00", "1:30"], duration) is None
    uneven = "The times 07:00 → 07:30 → 08:30 …"
    assert open_day_row(["07:00", "07:30", "08:30"], uneven) is None
