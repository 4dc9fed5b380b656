"""A hold lasts as long as the manual says for its key (a legend column or a sentence), not a
guessed 3 s: a shorter hold is ignored by the appliance."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.hold_seconds import hold_seconds

_LEGEND = """# Aquarium heater AH-2

## Buttons

  Button   Short press                 Press and hold
  -------  --------------------------  --------------------------
  (1) TEMP raise the water temperature  -
  (2) LIGHT light on / off              4 s: buttons locked / free
  (3) FEED feeding pause on / off       -

## Locking the buttons

Keep pressing LIGHT for 4 seconds: the LOCK symbol lights and the buttons no longer react.
Keep pressing LIGHT for 4 seconds again to free them.

## Feeding pause

Press FEED: the pump stops for 10 minutes. Press FEED again to end the pause early.
"""


def test_legend_and_sentence_give_the_hold_time() -> None:
    reading = read_manual(_LEGEND, ["press_temp", "press_light", "hold_light", "press_feed"])
    assert reading.model.actions["hold_light"].seconds == 4


def test_sentence_forms() -> None:
    lines = ["To clear the timer, press and hold the TIMER button for about 6 seconds."]
    assert hold_seconds(lines, "TIMER") == 6
    assert hold_seconds(["Step 3   CLOCK, keep touching 2 s   the hours flash"], "CLOCK") == 2
    assert hold_seconds(["Hold TIMER 3 s to clear it."], "TIMER") == 3
    # another key's time is not this key's
    assert hold_seconds(["Hold MODE for 5 seconds; press TIMER to set."], "TIMER") is None


def test_legend_row_with_a_letter_mark() -> None:
    row = "  B     SIZE      next cube size                 3 sec: key lock on / off"
    assert hold_seconds([row], "SIZE") == 3
    assert hold_seconds([row], "LOCK") is None
