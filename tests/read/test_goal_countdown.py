"""A time to finish at is met only once the countdown runs: the goal parser starts it unless
the instruction says not to (a small cooker manual written in our own words)."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.goal import parse_instruction

POT = """# Multi cooker MC-2

## Keys
| Key | Function |
|---|---|
| MENU | Chooses the programme: STEW, SOUP or BEANS. |
| CLOCK | Sets the clock with HOUR and MIN. |
| FINISH | Recalls the time at which the food should be done, to set it with HOUR and MIN. |
| HOUR | Raises the hour. |
| MIN | Raises the minutes. |
| START | Starts cooking, or confirms the finish time. |
| CANCEL | Stops cooking or the finish timer. |

## Finish timer
Choose the time of day at which the food should be ready.
1. Choose the programme with MENU.
2. Press FINISH. The finish time flashes.
3. Set the time of day with HOUR and MIN.
4. Press START. The FINISH lamp lights and the cooker waits.
"""
ACTIONS = [
    "press_menu",
    "press_clock",
    "press_finish",
    "press_hour",
    "press_min",
    "press_start",
    "press_cancel",
]


def test_a_time_to_be_ready_at_starts_the_countdown_unless_told_not_to() -> None:
    model = read_manual(POT, ACTIONS).model
    goal = parse_instruction(model, "I want the beans done at 6:30 tonight.")
    assert goal == {"menu": "beans", "finish": "18:30:00", "running": "on"}
    goal = parse_instruction(model, "Soup ready for 7:15 please, but don't start it yet.")
    assert goal["running"] == "off"
