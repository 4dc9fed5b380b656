"""Settings a read belief holds that the parser used to drop: the strength at an end ("at full
power", "the output at full") on an appliance that counts it in percent, and a three-letter
panel code (REV) named by the long word its manual prints beside it ("reverse"). Small models
and manual lines written for these tests."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction

LAMP = """
appliance: {id: lamp_1, category: stage_lamp, name: "read from the manual", brand: ""}
controls:
  - {id: fx_key, kind: button, label: "FX"}
  - {id: level_knob, kind: knob, label: "LEVEL"}
  - {id: kelvin_knob, kind: knob, label: "CCT"}
variables:
  fx: {type: discrete, label: FX, values: [flame, storm, strobe], initial: flame}
  level:
    {type: numeric, label: LEVEL, unit: "%", ranges: [[0, 100, 5]], initial: 50, wrap: false,
     show: "{value}%"}
  cct:
    {type: numeric, label: CCT, unit: K, ranges: [[3000, 6000, 100]], initial: 4500,
     wrap: false, show: "{value}K"}
actions:
  press_fx: {control: fx_key}
  turn_level_up: {control: level_knob}
  turn_level_down: {control: level_knob}
  turn_cct_up: {control: kelvin_knob}
  turn_cct_down: {control: kelvin_knob}
features:
  fx:
    - {actions: [press_fx], variable: fx, effect: next}
  level:
    - actions: [turn_level_up, turn_level_down]
      variable: level
      effect: {turn_level_up: next, turn_level_down: prev}
  cct:
    - actions: [turn_cct_up, turn_cct_down]
      variable: cct
      effect: {turn_cct_up: next, turn_cct_down: prev}
"""


def _lamp(text: str) -> dict[str, object]:
    return parse_instruction(loads_model(LAMP), text, "", outside=[])


def test_full_power_goes_to_the_one_setting_counted_in_percent() -> None:
    assert _lamp("The storm effect at full power.") == {"fx": "storm", "level": 100}
    assert _lamp("Strobe, with the output at full.") == {"fx": "strobe", "level": 100}


def test_a_percent_setting_takes_no_end_that_is_not_of_its_strength() -> None:
    assert _lamp("The storm effect at full speed.") == {"fx": "storm"}
    assert _lamp("Strobe, with the output at 40.") == {"fx": "strobe", "level": 40}


SHREDDER = """
appliance: {id: shredder_1, category: shredder, name: "read from the manual", brand: ""}
controls:
  - {id: feed_key, kind: button, label: "FEED"}
  - {id: size_key, kind: button, label: "CUT"}
variables:
  feed: {type: discrete, label: FEED, values: [aut, con, rev], initial: aut}
  cut: {type: discrete, label: CUT, values: [p-3, p-4], initial: p-3}
actions:
  press_feed: {control: feed_key}
  press_size: {control: size_key}
features:
  feed:
    - {actions: [press_feed], variable: feed, effect: next}
  cut:
    - {actions: [press_size], variable: cut, effect: next}
"""

LEGEND = """# Shredder
## Keys
  FEED    steps the feed: AUT, CON, REV
## Feed modes
  REV     reverse running, to free a jam
"""

LABEL_LEGEND = """# Shredder
## Keys
  FEED    changes between automatic, continuous and reverse feeding
"""


def _shred(text: str, manual: str) -> dict[str, object]:
    return parse_instruction(loads_model(SHREDDER), text, manual, outside=[])


def test_a_code_is_named_by_the_long_word_its_manual_line_prints() -> None:
    assert _shred("Put it in reverse.", LEGEND) == {"feed": "rev"}
    assert _shred("P-4 cut, in reverse.", LABEL_LEGEND) == {"feed": "rev", "cut": "p-4"}


def test_no_manual_line_no_long_word() -> None:
    assert _shred("P-4 cut, in reverse.", "# Shredder\n") == {"cut": "p-4"}
