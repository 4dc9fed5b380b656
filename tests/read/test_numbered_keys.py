"""Numbered key families the manual never explains (M1 / M2 / M3 on a desk, T1 / T2 on a timer):
read key by key they were settings of their own that no sentence could bind; the guess is one
choice setting named by the stem, each key going to its own, recorded as a guess. Manuals
written in our own words."""

from __future__ import annotations

from apbot.model.validate import check_model
from apbot.read import read_manual
from apbot.read.goal import parse_instruction

# memory keys printed on the panel, nothing said of what they choose
DESK = """LIFTO DUO STANDING DESK
Quick guide

PANEL
  UP / DOWN     raise or lower the desk (72 to 120 cm)
  M1 / M2 / M3  memory keys
  SET           store

Hold UP or DOWN to move the desk. The display shows the height in cm.
"""
DESK_ACTIONS = ["press_up", "press_down", "press_m1", "press_m2", "press_m3", "press_set"]

# zone keys read as switches, one per zone: several may be on at once, left as read
OVEN = """BRAVO TRIPLE WARMER
Guide

KEYS
  Z1 / Z2 / Z3 ... each zone on or off
  POWER .......... on or off
"""
OVEN_ACTIONS = ["press_z1", "press_z2", "press_z3", "press_power"]


def test_numbered_keys_read_one_by_one_become_one_choice_the_user_can_name() -> None:
    reading = read_manual(DESK, DESK_ACTIONS)
    model = reading.model
    assert not [p for p in check_model(model) if p.severity == "error"]
    memory = model.variables["m"]
    assert memory.values == ["m1", "m2", "m3"]
    assert memory.show == {"m1": "M1", "m2": "M2", "m3": "M3"}
    goes = {
        step.actions[0]: step.effect.to
        for steps in model.features.values()
        for step in steps
        if step.variable == "m"
    }
    assert goes == {"press_m1": "m1", "press_m2": "m2", "press_m3": "m3"}
    assert not {"m1", "m2", "m3"} & set(model.variables)  # no setting per key any more
    assert any(n.subject == "variables.m" for n in reading.report.guesses)
    goal = parse_instruction(model, "Go to memory two.", DESK, outside=[])
    assert goal.get("m") == "m2"


def test_numbered_keys_read_as_switches_of_their_own_stay_switches() -> None:
    reading = read_manual(OVEN, OVEN_ACTIONS)
    assert {"z1", "z2", "z3"} <= set(reading.model.variables)
    assert not any("numbered" in n.what for n in reading.report.guesses)


# function keys whose lines each give a setting of its own: read for themselves, left as read
PURIFIER = """AIRO TWIN PURIFIER
Guide

KEYS
  F1      fan speed: LOW → MID → HIGH → LOW
  F2      timer: 1H → 2H → 4H → 8H → 1H
  POWER   on or off
"""
PURIFIER_ACTIONS = ["press_f1", "press_f2", "press_power"]


def test_numbered_keys_each_read_with_values_of_its_own_are_left_as_read() -> None:
    model = read_manual(PURIFIER, PURIFIER_ACTIONS).model
    assert model.variables["f1"].values == ["low", "mid", "high"]
    assert "f" not in model.variables
