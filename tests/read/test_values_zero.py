"""A setting whose zero means none (values_zero)."""

from apbot.read.values import Range
from apbot.read.values_zero import from_zero, zero_told


def test_zero_told_names_the_setting() -> None:
    texts = [
        "Timer: 1 - 12 hours.",
        "Press OFF TIMER. The display shows the hours set (0 means no timer).",
    ]
    assert zero_told(texts, {"timer"}, "h") == 1


def test_zero_of_another_setting_is_not_its() -> None:
    texts = ["d 2 h   delayed start of 2 hours (d 0 h = no delay)"]
    assert zero_told(texts, {"time"}, "s") is None  # the delay's zero, not the cooking time's
    assert zero_told(["TIMER 0 min = no timer"], {"timer"}, "°C") is None  # another unit


def test_from_zero() -> None:
    assert from_zero([Range(1, 12, "h", 1)], None) == [Range(0, 12, "h", 1)]
    assert from_zero([Range(2, 8, "h", 2)], None) == [Range(0, 8, "h", 2)]
    assert from_zero([Range(1, 4, "h", 0.5)], None) == [Range(0, 1, "h", 1), Range(1, 4, "h", 0.5)]
    assert from_zero([Range(1, 12, "h")], 1.0) == [Range(0, 12, "h", 1.0)]
