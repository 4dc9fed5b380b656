"""Which time an add-time key (+30 SEC) adds to when the panel also has a clock
(apbot.read.added_time): the one its sentences name, never the clock first because the manual
happens to name the CLOCK key first. A manual written for this test."""

from __future__ import annotations

from apbot.read import read_manual

MANUAL = """Nova M2 Microwave

Control panel
  CLOCK      sets the time of day
  COOK TIME  enter a cooking time with the number pads
  +30 SEC    adds 30 seconds to the cooking time and starts
  START      starts cooking

Setting the clock
  1. Press CLOCK. 2. Enter the time of day with the number pads, e.g. 7, 3, 0 for 7:30.
  3. Press CLOCK again.

Cooking by time
  1. Press COOK TIME. 2. Enter the cooking time, e.g. 2, 3, 0 for 2 minutes 30 seconds.
  3. Press START.

Quick start
  Touch +30 SEC: the oven cooks at full power for 30 seconds; each touch adds 30 seconds
  to the cooking time.
"""

ACTIONS = ["press_clock", "press_cook_time", "press_add_30_sec", "press_start"] + [
    f"press_{d}" for d in range(10)
]


def test_an_add_time_key_adds_to_the_time_its_sentences_name_not_the_clock() -> None:
    for actions in (ACTIONS, ACTIONS[::-1]):
        model = read_manual(MANUAL, actions).model
        assert "clock" in model.variables
        steps = model.features["add_30_sec"]
        assert [s.variable for s in steps] == ["cook_time"]
