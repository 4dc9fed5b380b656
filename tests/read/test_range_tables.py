"""Rules about how far a setting goes when a manual tells it in a small table or an example,
each on a short manual written in our own words the way a converted commercial manual reads."""

from __future__ import annotations

from apbot.read import read_manual

# a fan heater whose off-timer table (range, step) was flattened into one line
HEATER = """# Fan heater FH-9

## Keys
| Key | Function |
|---|---|
| ON/OFF | Switches the heater on and off. |
| TIMER | Sets the switch-off timer. |

## Switch-off timer
Press TIMER repeatedly to choose after how long the heater switches itself off.
Timer settings:   Range         Step   0.5 – 4 h   30 min   4 – 16 h   2 h
"""


def test_a_flattened_range_and_step_table_in_hours_gives_each_piece_its_step() -> None:
    model = read_manual(HEATER, ["press_on_off", "press_timer"]).model
    timer = model.variables["timer"]
    tops = [str(r[1]) for r in timer.ranges]
    steps = [str(r[2]) for r in timer.ranges]
    assert tops in (["4", "16"], ["04:00:00", "16:00:00"]), timer.ranges
    assert steps in (["0.5", "2"], ["1800", "7200"]), timer.ranges
