"""Two keys named for what they do (FASTER / SLOWER, HOTTER / COOLER), not for a direction:
their own legend rows say one raises and the other lowers the same quantity, so they are one
stepped pair on that quantity, as ▲ / ▼ keys are. Rows that name both keys, or that speak of a
different quantity for each key, pair nothing."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.roles_raiselower import directions

FAN = """\
# Tower fan TF-8

## The keys

| Key    | What it does                           |
|--------|----------------------------------------|
| ON     | Switches the fan on or off.            |
| BREEZE | Increases the fan speed by one level.  |
| CALM   | Decreases the fan speed by one level.  |
| SWING  | Oscillation on / off.                  |

The fan speed can be set from 1 to 8.
"""


def test_two_keys_that_raise_and_lower_the_same_quantity_are_one_stepped_pair() -> None:
    model = read_manual(FAN, ["press_on", "press_breeze", "press_calm", "press_swing"]).model
    data = model.model_dump(mode="json")
    steps = [s for f in data["features"].values() for s in f if "press_breeze" in s["actions"]]
    assert steps, data["features"]
    step = steps[0]
    assert set(step["actions"]) == {"press_breeze", "press_calm"}, step
    assert step["effect"] == {"press_breeze": "next", "press_calm": "prev"}, step
    var = data["variables"][step["variable"]]
    assert var["ranges"][0][:2] == [1, 8], var


HEATER = """\
# Bath heater

- HOTTER: raises the water temperature.
- COOLER: lowers the fan noise.
- BOTH: press HOTTER and COOLER to raise or lower the temperature.
"""


def test_keys_that_move_different_quantities_are_no_pair() -> None:
    data = read_manual(HEATER, ["press_hotter", "press_cooler"]).model.model_dump(mode="json")
    for steps in data["features"].values():
        for s in steps:
            assert set(s["actions"]) != {"press_hotter", "press_cooler"}, s


def test_the_quantity_is_the_noun_the_verb_acts_on_not_a_key_word() -> None:
    assert directions("Raise the temperature of the selected zone.") == {("up", "temperature")}
    assert directions("Lower the cooking time by 1 min") == {("down", "time")}
    assert directions("Makes the crust darker.") == set()  # darker: no direction of its own
    assert directions("Each touch makes the mist stronger.") == {("up", "mist")}
    assert directions("warmer key") == set()
    # a bare comparative names a level a key selects, not a step
    assert directions("Lower temperature for cooking all day.") == set()
    assert directions("Longer time, gentler heat.") == set()


KETTLE = """\
# Tea kettle TK-3

| Key              | Use                                    |
|------------------|----------------------------------------|
| BOIL             | Start or stop heating.                 |
| COOLER / WARMER  | Lower / raise the water temperature.   |

The water temperature can be set from 60 to 100 °C in steps of 5 °C.
"""


def test_one_row_naming_both_keys_and_both_verbs_in_order_pairs_them() -> None:
    actions = ["press_boil", "press_cooler", "press_warmer"]
    data = read_manual(KETTLE, actions).model.model_dump(mode="json")
    steps = [s for f in data["features"].values() for s in f if "press_warmer" in s["actions"]]
    assert steps and steps[0]["effect"] == {"press_warmer": "next", "press_cooler": "prev"}, steps
    var = data["variables"][steps[0]["variable"]]
    assert var["ranges"][0][:2] == [60, 100], var


DEEP_FRYER = """\
# Olio DF-3 deep fryer

## The keys

| Key    | What it does                            |
|--------|-----------------------------------------|
| POWER  | Switches the fryer on or off.           |
| UPLIFT | Raises the basket.                      |
| DIP    | Lowers the basket.                      |
| HEAT   | Selects 150, 170 or 190 °C.             |
"""


def test_keys_that_raise_and_lower_a_part_are_no_stepped_pair() -> None:
    actions = ["press_power", "press_uplift", "press_dip", "press_heat"]
    model = read_manual(DEEP_FRYER, actions).model
    paired = [
        s
        for f in model.features.values()
        for s in f
        if {"press_uplift", "press_dip"} <= set(s.actions)
    ]
    assert not paired, paired
    assert "basket" not in model.variables
