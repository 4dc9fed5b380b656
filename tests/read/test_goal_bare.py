"""A list of bare numbers that says its unit once, or is named for time (``goal_bare.py``).

The boot dryer below was read the way readers often read a row of lamps: TIME is a list of bare
numbers (the legend says minutes elsewhere), and LENGTH prints its unit once, after the last.
"""

from __future__ import annotations

from apbot.read.goal import parse_instruction
from tests.helpers import model_from

DRYER = model_from(
    """
    controls: [{id: time}, {id: strap}, {id: heat}]
    variables:
      time: {type: discrete, values: ["30", "60", "90", "120", "∞"], label: TIME}
      strap: {type: discrete, values: [auto, "20", "40", "60 mm"], label: STRAP}
      heat: {type: discrete, values: ["1", "2", "3"], label: HEAT}
    actions:
      press_time: {control: time}
      press_strap: {control: strap}
      press_heat: {control: heat}
    features:
      set_time:
        - {actions: [press_time], variable: time, effect: next}
      set_strap:
        - {actions: [press_strap], variable: strap, effect: next}
      set_heat:
        - {actions: [press_heat], variable: heat, effect: next}
    """
)


def test_a_duration_names_the_minutes_of_a_time_list() -> None:
    assert parse_instruction(DRYER, "Dry them for two hours.") == {"time": "120"}
    assert parse_instruction(DRYER, "Half an hour on heat 2.") == {"time": "30", "heat": "2"}


def test_a_quantity_in_the_unit_the_list_prints_once() -> None:
    assert parse_instruction(DRYER, "A 40 mm strap.") == {"strap": "40"}
    assert parse_instruction(DRYER, "A 4 cm strap.") == {"strap": "40"}


def test_no_unit_said_for_a_list_not_named_for_it() -> None:
    try:
        goal = parse_instruction(DRYER, "Heat for 2 minutes.")
    except ValueError:
        return  # refused with a message is right too
    assert "heat" not in goal
