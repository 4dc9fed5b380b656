"""A count shown in marks is read whole: one wave is not two, three bars are not four.

A panel that shows a level as a run of marks (``~``, ``~~``, ``~~~``; ``▮▮▮▯``) beside its
main screen: the reader finds the setting's marks inside the longer text, and must take the
longest run there, never a shorter one inside it.
"""

from __future__ import annotations

from apbot.agent.reader import DisplayReader
from tests.helpers import model_from

IRON = """
controls: [{id: power}, {id: type}, {id: temp}]
variables:
  power: {type: discrete, values: ["off", "on"]}
  hair:
    {type: discrete, values: [fine, normal, thick], show: {fine: "~", normal: "~~", thick: "~~~"}}
  temperature: {type: numeric, unit: "°C", ranges: [[150, 200, 10]], initial: 180, wrap: true}
actions:
  press_power: {control: power}
  press_type: {control: type}
  press_temp: {control: temp}
features:
  power: [{actions: [press_power], variable: power, effect: toggle}]
  set_hair: [{actions: [press_type], variable: hair, effect: next}]
  set_temperature: [{actions: [press_temp], variable: temperature, effect: next}]
"""


def _hair(text: str) -> set[object]:
    reading = DisplayReader(model_from(IRON)).read(text)
    return {h.value("hair") for h in reading.hypotheses if "hair" in h.shown()}


def test_two_waves_beside_another_screen_read_as_two_not_one() -> None:
    assert _hair("180°C  ~~") == {"normal"}
    assert _hair("180°C  ~~~") == {"thick"}
    assert _hair("180°C  ~") == {"fine"}


def test_bars_of_a_level_are_read_whole() -> None:
    bars = IRON.replace(
        'fine: "~", normal: "~~", thick: "~~~"', 'fine: "▮▯▯", normal: "▮▮▯", thick: "▮▮▮"'
    )
    reading = DisplayReader(model_from(bars)).read("180°C  ▮▮▯")
    assert {h.value("hair") for h in reading.hypotheses if "hair" in h.shown()} == {"normal"}
