"""The push-and-turn rule: a knob's push opens its amount only when the manual says so."""

from __future__ import annotations

from apbot.read import read_manual

ACTIONS = ["press_power", "turn_temp_cw", "turn_temp_ccw", "turn_time_cw", "turn_time_ccw"]

# a fryer whose TIME knob is turned to set the time and pushed to start or pause the cycle
FRYER = """AIR FRYER AF-9 GUIDE

CONTROLS

TEMP knob: Turn to set the temperature, 80 to 200 °C.

TIME knob: Turn to set the time, 1 to 30 minutes. Push to start or pause.

POWER button: Switches the fryer on or off.
"""


def test_a_push_that_starts_is_not_the_first_step_of_the_time() -> None:
    model = read_manual(FRYER, [*ACTIONS, "press_time"]).model
    steps = model.features["select_time"]
    assert [s.actions for s in steps] == [["turn_time_cw", "turn_time_ccw"]]
    assert model.features["push_time"][0].variable == "running"


def test_a_push_that_opens_the_time_still_comes_first() -> None:
    text = FRYER.replace("Push to start or pause.", "Push it: the time flashes; then turn it.")
    model = read_manual(text, [*ACTIONS, "press_time"]).model
    steps = model.features["set_time"]
    assert steps[0].actions == ["press_time"]
