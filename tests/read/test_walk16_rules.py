"""Walk rules of walk16: a walk told in running prose (`walk_steps.py`)."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.text import parse_manual
from apbot.read.walk_steps import prose_opener, walk_steps

# a towel-rail radiator (our own words): the clock walk told as prose, no numbered steps
RADIATOR = """TOWELWARM R5 towel rail

KEYS
  POWER     on / off.
  CLOCK     opens the clock.
  ▲         raises the flashing value.
  ▼         lowers the flashing value.

SETTING THE CLOCK
Press and hold CLOCK for 3 seconds. The hour flashes. Press ▲ or ▼ to set the hour.
Press CLOCK again and the minutes flash. Press ▲ or ▼ to set the minutes.
After 8 seconds without a key the clock is stored.
"""
RADIATOR_ACTIONS = ["press_power", "press_clock", "hold_clock", "press_up", "press_down"]

# a lift table (our own words): holding the stepping pair moves fast, it opens no walk
LIFT = """RAISO L1 lift table

MOVING THE TABLE

  Tap ▲ or ▼: the table moves 1 cm up or down and the display shows the new height.

  Hold ▲ or ▼ for 2 seconds: the table travels 5 cm in that direction and stops. Hold again
  for another 5 cm. From 50 cm a hold on ▲ gives 55 cm.

  The L1 travels between 40 cm (lowest) and 90 cm (highest).
"""
LIFT_ACTIONS = ["press_up", "press_down", "hold_up", "hold_down"]


def test_prose_sentences_that_work_a_key_begin_steps() -> None:
    units = parse_manual(RADIATOR).units
    at = next(i for i, u in enumerate(units) if u.text.startswith("Press and hold CLOCK"))
    steps = [t for _, t in walk_steps(units, at)]
    assert steps[0] == "Press and hold CLOCK for 3 seconds. The hour flashes."
    assert steps[2] == "Press CLOCK again and the minutes flash."
    assert steps[-1].endswith("the clock is stored.")
    assert len(steps) == 4


def test_a_clock_walk_told_in_prose_is_read() -> None:
    model = read_manual(RADIATOR, RADIATOR_ACTIONS).model
    walks = [s for s in model.features.values() if [x.actions for x in s][:1] == [["hold_clock"]]]
    assert len(walks) == 1
    timed = [s for s in walks[0] if s.variable]
    assert len(timed) == 2 and model.variables[timed[0].variable].type == "time"
    assert "press_clock" in walks[0][2].actions


def test_a_held_stepping_key_opens_no_prose_walk() -> None:
    model = read_manual(LIFT, LIFT_ACTIONS).model
    assert not any(
        [x.actions for x in s][:1] == [["hold_up"]] and len(s) > 2 for s in model.features.values()
    )


def test_a_held_stepping_key_is_no_prose_opener() -> None:
    units = parse_manual(LIFT).units
    hold = next(u for u in units if u.text.startswith("Hold ▲"))
    assert not prose_opener(hold, paired=True)
    assert prose_opener(hold, paired=False)
