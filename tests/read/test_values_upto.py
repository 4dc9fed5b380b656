"""An amount said only as "up to" starts where the manual says it does (values_upto, values)."""

from apbot.read.reader import read_manual
from apbot.read.values import Range, find_ranges
from apbot.read.values_upto import stated_low


def test_from_in_the_same_clause() -> None:
    assert find_ranges("Set the glow from 20 % up to 90 %.") == [Range(20, 90, "%")]
    assert find_ranges("Mist lasts from 5 min up to 2 h.") == [Range(5, 120, "min")]
    assert find_ranges("Mist lasts up to 2 h.") == [Range(0, 2, "h")]  # no low end said
    assert find_ranges("From the menu: up to 60 %.") == [Range(0, 60, "%")]  # another clause


def test_clock_from_and_seconds_steps() -> None:
    text = "Press + in 15-second steps, from 1:30 (shown 01:30) up to 9:00 (shown 09:00)."
    assert find_ranges(text) == [Range(90, 540, "s")]  # seconds steps: m:ss, not h:mm
    assert find_ranges("The delay goes up to 9:00.") == [Range(0, 9 * 3600, "s")]


def test_stated_low_from_the_setting_named_elsewhere() -> None:
    top = Range(0, 60, "°C", 1)
    said = "Hold + to go beyond, up to 60 °C."
    assert stated_low(top, said, (Range(25, 45, "°C"), 3)) == Range(25, 60, "°C", 1)
    assert stated_low(top, said, (Range(25, 70, "°C"), 3)) == top  # past the top: not its
    assert stated_low(top, said, (Range(25, 45, "%"), 3)) == top  # another unit
    assert stated_low(top, "Range 0 - 60 °C.", (Range(25, 45, "°C"), 3)) == top  # a real 0
    timer = Range(0, 12, "h", 1)  # a timer counts from nothing
    assert stated_low(timer, "up to 12 h", (Range(1, 4, "h"), 3)) == timer


MANUAL = """
# Foot bath FB-2

## Keys

Touch ▲ for warmer water or ▼ for cooler. Each touch changes the temperature by 1 °C,
up to 48 °C.

Keep your feet out of the water while it heats.

Empty the bath after each use.

## Technical data

| Item | Value |
|---|---|
| Water temperature | 30 – 44 °C |
| Power | 450 W |
"""


def test_up_to_takes_the_low_end_named_elsewhere() -> None:
    model = read_manual(MANUAL, ["press_up", "press_down"]).model
    ranges = [
        tuple(r)
        for v in model.variables.values()
        if getattr(v, "unit", None) == "°C"
        for r in v.ranges or []
    ]
    assert ranges and all(r[0] == 30 for r in ranges), ranges
