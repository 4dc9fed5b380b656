"""A SLEEP timer switches the appliance off at its end: "switch off after 30 minutes" sets it,
not another setting counted in minutes (goal_view's turns). A model written for this test: a
bedside speaker with a SLEEP list and a snooze length."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction

SPEAKER = """
appliance: {id: speaker_9, category: bedside_speaker, name: "Nocta BS-9 speaker", brand: N}
controls:
  - {id: sleep_button, kind: button, label: "SLEEP"}
  - {id: snooze_button, kind: button, label: "SNOOZE"}
variables:
  sleep_timer:
    type: discrete
    values: ["off", "60 min", "30 min", "15 min"]
  snooze_minutes:
    type: numeric
    unit: min
    ranges: [[5, 30, 5]]
    initial: 10
    wrap: true
    label: "SNZ"
actions:
  press_sleep: {control: sleep_button}
  press_snooze: {control: snooze_button}
features:
  sleep_timer:
    - {actions: [press_sleep], variable: sleep_timer, effect: next}
  snooze_minutes:
    - {actions: [press_snooze], variable: snooze_minutes, effect: next}
display:
  idle: "{sleep_timer}"
"""


def test_switching_off_after_a_while_is_the_sleep_timer() -> None:
    goal = parse_instruction(loads_model(SPEAKER), "Have it switch off after 30 minutes.")
    assert goal == {"sleep_timer": "30 min"}
