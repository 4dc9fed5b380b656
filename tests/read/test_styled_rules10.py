"""Rules found on the round-9 styled manuals (session 10), each on a small manual of our own."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.roles_raised import quantity_noun
from apbot.read.values import Range, find_ranges

# a fan heater whose temperature setting is listed one by one, the unit after every item, and
# whose worked example moves the setting between two of them
HEATER = """CONTROL PANEL

 1  POWER  — switches the heater on or off.
 2  TEMP   — picks the temperature setting for changing with the arrow pads.
 3  TIMER  — picks the off-timer for changing with the arrow pads.
 4  ▲      — raises the picked value.
 5  ▼      — lowers the picked value.

USING THE HEATER

1. Touch TEMP. The display shows the present setting.
2. Touch ▲ or ▼ to change the setting. The settings are 15 °C, 20 °C, 25 °C and 30 °C.
3. Touch TIMER, then ▲ or ▼, to set the off-timer from 1 to 8 hours.

   Example: from 20 °C to 25 °C, touch TEMP, then ▲ once.
"""

ACTIONS = ["press_power", "press_temp", "press_timer", "press_up", "press_down"]


def _ranges(name: str) -> list[list[float]]:
    model = read_manual(HEATER, ACTIONS).model
    return [list(r) for r in model.variables[name].model_dump(mode="json")["ranges"]]


def test_the_last_two_items_of_a_list_of_amounts_are_no_range() -> None:
    said = "The levels are 10 %, 20 %, 30 % and 40 % of full power."
    assert find_ranges(said) == [Range(10, 40, "%", 10)]  # the whole list, not "30 and 40 %"
    assert find_ranges("between 30 °C and 40 °C") != []  # a range said with "and" stays one


def test_a_worked_example_states_no_limits() -> None:
    assert find_ranges("Example: from 20 °C to 25 °C, touch TEMP, then ▲ once.") == []
    assert find_ranges("For example, 35 - 40 - 45 °C on three touches.") == []


def test_a_listed_setting_is_read_whole_not_from_its_example() -> None:
    assert _ranges("temp") == [[15, 30, 5]]


def test_a_short_list_may_be_a_sample_and_is_no_range() -> None:
    assert find_ranges("Only 60, 80 and 100 °C are offered below 100 °C.") == []


def test_a_pair_that_raises_the_chosen_value_names_no_quantity_of_its_own() -> None:
    # "− lowers the chosen value": the value another key chose, like "the selected value"
    assert quantity_noun("chosen value") == ""
    assert quantity_noun("selected value") == ""
    assert quantity_noun("goal value") == "goal_value"
