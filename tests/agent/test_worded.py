"""A numeric setting whose panel names some positions in words ("air only" after the lowest
heat): the walk turns it into a list of choices, so the planner counts every press."""

from __future__ import annotations

from tests.helpers import model_from
from tests.helpers import run_checked as run

TRUTH = """
controls: [{id: heat, label: HEAT}]
variables:
  heat:
    type: discrete
    values: ["70", "60", "50", air only, "80"]
    initial: "60"
    wrap: true
    label: HEAT
actions:
  press_heat: {control: heat}
features:
  heat:
    - {actions: [press_heat], variable: heat, effect: next}
display:
  idle: "HEAT {heat}"
"""

BELIEF = """
controls: [{id: heat, label: HEAT}]
variables:
  heat: {type: numeric, ranges: [[50, 80, 10]], initial: 60, wrap: true, label: HEAT}
actions:
  press_heat: {control: heat}
features:
  heat:
    - {actions: [press_heat], variable: heat, effect: next}
"""


def test_words_among_a_numeric_settings_positions_become_choices() -> None:
    episode, reached = run(model_from(TRUTH), model_from(BELIEF), {"heat": "80"})
    assert reached
    assert any("air only" in note for note in episode.repairs)
