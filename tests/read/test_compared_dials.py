"""A dial whose two turns are named only by what they do (``turn_faster`` / ``turn_slower``):
one dial, whose quantity the pair names, instead of two settings of their own that no sentence
names. Manuals written in our own words."""

from __future__ import annotations

from apbot.model.validate import check_model
from apbot.read import read_manual
from apbot.read.actions import parse_actions
from apbot.read.goal import parse_instruction

LATHE = """TURNO MINI LATHE
Guide

CONTROLS
  POWER        on or off
  SPEED dial   positions 1 to 9; clockwise faster, anticlockwise slower

The display shows the speed position.
"""
LATHE_ACTIONS = ["press_power", "turn_faster", "turn_slower"]


def test_a_dial_named_by_its_two_ways_is_one_setting_the_user_can_name() -> None:
    reading = read_manual(LATHE, LATHE_ACTIONS)
    model = reading.model
    assert {n.subject for n in reading.report.guesses} >= {
        "actions.turn_faster",
        "actions.turn_slower",
    }  # the dial's name came from the actions: a guess, recorded
    assert not [p for p in check_model(model) if p.severity == "error"]
    assert "faster" not in model.variables and "slower" not in model.variables
    steps = [s for f in model.features.values() for s in f if s.variable == "speed"]
    assert steps and set(steps[0].actions) == {"turn_faster", "turn_slower"}
    goal = parse_instruction(model, "Switch on and set the speed to 5.", LATHE, outside=[])
    assert goal.get("speed") == 5


def test_one_comparative_turn_alone_stays_a_dial_of_its_own() -> None:
    infos = {i.name: i for i in parse_actions(["press_power", "turn_faster"])}
    assert infos["turn_faster"].controls == ("faster",)
    both = {i.name: i for i in parse_actions(["turn_coarser", "turn_finer"])}
    assert both["turn_coarser"].controls == both["turn_finer"].controls == ("fineness",)
    assert {both["turn_coarser"].skill, both["turn_finer"].skill} == {"turn_cw", "turn_ccw"}


# a mill whose positions grow coarser: "the finest" is where the FINER turn stops, position 1
MILL = """KORNO HAND MILL
Guide

CONTROLS
  POWER           on or off
  FINENESS dial   positions 1 (finest) to 8 (coarsest); clockwise coarser, anticlockwise finer
"""
MILL_ACTIONS = ["press_power", "turn_coarser", "turn_finer"]


def test_a_superlative_of_a_keys_own_word_is_the_end_that_key_turns_to() -> None:
    model = read_manual(MILL, MILL_ACTIONS).model
    finest = parse_instruction(model, "The finest setting, please.", MILL, outside=[])
    assert finest.get("fineness") == 1
    coarsest = parse_instruction(model, "Set the coarsest setting.", MILL, outside=[])
    assert coarsest.get("fineness") == 8
    second = parse_instruction(model, "Use the second finest setting.", MILL, outside=[])
    assert second.get("fineness") == 2
