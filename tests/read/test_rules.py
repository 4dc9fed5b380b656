"""Reading rules on small manuals written for the test: each says one thing one way."""

from __future__ import annotations

from apbot.model.validate import check_model
from apbot.read import read_manual

WASHER = """
# Panel

| Key | What it does |
|---|---|
| POWER | Switches the washer on and off. |
| MODE | Chooses the wash mode. |
| TEMP | Sets the temperature, adjusted with + and −. |
| START | Starts the wash. |

Each press of MODE moves to the next mode: ECO → FAST → NIGHT → back to ECO.

| Mode | Temperature |
|---|---|
| ECO | 30 – 60 °C |
| FAST | 40 – 90 °C |
| NIGHT | 20 – 40 °C |

Press TEMP, then + or − to change the temperature in 10 °C steps.
To lock the keys, press and hold + and − together for 3 seconds; LOCK appears.
"""
WASHER_ACTIONS = [
    "press_power", "press_mode", "press_temp", "press_plus", "press_minus", "press_start",
    "hold_plus_minus",
]  # fmt: skip


def test_a_mode_cycle_a_dependent_range_a_stepping_pair_and_a_lock():
    model = read_manual(WASHER, WASHER_ACTIONS).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    assert model.variables["mode"].values == ["eco", "fast", "night"]
    temp = model.variables["temp"]
    assert temp.depends_on == "mode"
    assert temp.cases["fast"].ranges == [(40, 90, 10)]
    steps = model.features["set_temp"]
    assert steps[0].actions == ["press_temp"] and set(steps[1].actions) == {
        "press_plus",
        "press_minus",
    }
    assert model.features["child_lock"][0].actions == ["hold_plus_minus"]
    assert model.variables["child_lock"].show == {"off": "", "on": "LOCK"}
    guards = {g.name: g for g in model.guards}
    assert guards["power off"].only == ["press_power"]


COOKER = """
## Program pads

| Program | Cooking time |
|---|---|
| RICE | automatic |
| SOUP | 0:30 – 3:00 |
| STEW | 0:30 – 8:00 |

Touch a program pad, then START. The RUN lamp lights and the display shows RUN.
"""


def test_pads_listed_in_a_programme_table_select_one_programme():
    model = read_manual(COOKER, ["press_rice", "press_soup", "press_stew", "press_start"]).model
    program = model.variables["program"]
    assert program.values == ["rice", "soup", "stew"]
    (step,) = model.features["soup"]
    assert step.actions == ["press_soup"] and step.variable == "program"
    assert step.effect is not None and getattr(step.effect, "to", None) == "soup"


def test_silence_is_a_recorded_guess_and_still_a_checked_model():
    reading = read_manual("Nothing about the keys here.", ["press_a", "press_b", "turn_c_cw"])
    assert not [p for p in check_model(reading.model) if p.severity == "error"]
    assert reading.report.guesses and all(n.line is None for n in reading.report.guesses)
