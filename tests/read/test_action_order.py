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
    model = read_manual(DRYER, actions, "herbdry", "food_dryer").model
    return model.model_dump(mode="json")


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
    names = ["press_start", "hold_temp_and_fan", "press_fan", "press_temp", "press_3", "press_1"]
    infos = parse_actions(names)
    manual = parse_manual(DRYER, sorted({c for i in infos for c in i.controls}))
    tokens = sorted({c for i in infos for c in i.controls if i.digit is None})
    ranked = [i.name for i in in_manual_order(infos, manual, find_labels(manual, tokens))]
    assert ranked[:4] == ["press_temp", "press_fan", "hold_temp_and_fan", "press_start"]
    assert ranked[4:] == ["press_1", "press_3"]  # no key of their own named: after, by digit
