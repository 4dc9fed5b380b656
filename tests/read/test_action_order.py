"""The reading does not depend on the order of the action names: a small manual of our own, read
with its actions as listed, reversed and shuffled, gives the same model; the actions are read in
the order the manual introduces their keys."""

from __future__ import annotations

import random

from apbot.read import read_manual
from apbot.read.action_rank import in_manual_order
from apbot.read.actions import parse_actions
from apbot.read.labels import find_labels
from apbot.read.text import parse_manual

DRYER = """HERBDRY HD-3 FOOD DRYER
Operating instructions

CONTROL PANEL
   POWER     switches the dryer on and off.
   APPLE, BASIL, JERKY   programme keys: press one to choose its drying programme.
   TEMP      each press raises the drying temperature by 5 °C (35 °C to 70 °C).
   FAN       switches the quiet fan on or off. The FAN lamp is lit while the quiet fan is on.
   Keys 0-9  type the drying time in hours (1 to 24).
   START     starts drying.

Press and hold TEMP and FAN together for 3 seconds to lock the keys; the LOCK lamp lights.
While the dryer is running only START and POWER work.
"""
ACTIONS = [
    "press_power",
    "press_apple",
    "press_basil",
    "press_jerky",
    "press_temp",
    "press_fan",
    *(f"press_{d}" for d in range(10)),
    "press_start",
    "hold_temp_and_fan",
]


def _dump(actions: list[str]) -> dict[str, object]:
    """The read model, its listing of actions and controls (the caller's order) put aside."""
    model = read_manual(DRYER, actions, "herbdry", "food_dryer").model
    assert list(model.actions) == actions  # listed as given
    data = model.model_dump(mode="json")
    data["actions"] = dict(sorted(data["actions"].items()))
    data["controls"] = sorted(data["controls"], key=lambda c: c["id"])
    return data


def test_reversed_actions_read_the_same_model() -> None:
    assert _dump(ACTIONS) == _dump(ACTIONS[::-1])


def test_shuffled_actions_read_the_same_model() -> None:
    shuffled = list(ACTIONS)
    random.Random(3).shuffle(shuffled)
    assert _dump(ACTIONS) == _dump(shuffled)


def test_the_pads_values_come_in_the_manuals_order() -> None:
    """Program keys give their values in the order the manual lists the keys, not the actions'."""
    reversed_dump = _dump(ACTIONS[::-1])
    variables = reversed_dump["variables"]
    assert isinstance(variables, dict)
    lists = [v.get("values") for v in variables.values() if isinstance(v, dict)]
    food = next(values for values in lists if values and "apple" in values)
    assert food.index("apple") < food.index("basil") < food.index("jerky")


def test_actions_are_ranked_by_their_keys_first_mention() -> None:
    names = ["press_start", "hold_temp_and_fan", "press_fan", "press_temp", "press_0", "press_1"]
    infos = parse_actions(names)
    manual = parse_manual(DRYER, sorted({c for i in infos for c in i.controls}))
    tokens = sorted({c for i in infos for c in i.controls if i.digit is None})
    ranked = [i.name for i in in_manual_order(infos, manual, find_labels(manual, tokens))]
    assert ranked[:4] == ["press_temp", "press_fan", "hold_temp_and_fan", "press_start"]
    assert ranked[4:] == ["press_1", "press_0"]  # no label: after, in a keypad's order


SPINNER = """ZIPPA S-2 salad spinner

PARTS
  (A) Display (B) BOOST button: a short burst at top speed (C) Crank knob: turn to choose a
  speed; push (click) to start or stop
"""


def _start_key(actions: list[str]) -> list[str]:
    model = read_manual(SPINNER, actions).model
    return [
        step.actions[0]
        for steps in model.features.values()
        for step in steps
        if step.variable == "running"
    ]


def test_a_legends_push_clause_is_the_nearest_keys_whatever_the_order() -> None:
    """BOOST is named first on the line, but the push clause follows the crank's name: the
    crank's push starts, in either order of the actions."""
    actions = ["press_boost", "turn_crank_cw", "turn_crank_ccw", "press_crank"]
    assert _start_key(actions) == ["press_crank"]
    assert _start_key(actions[::-1]) == ["press_crank"]
