"""Equally fitting settings told apart by meaning, not by the order the belief lists them in
(goal_ties, goal_assign, goal_cases): models and manuals written for these tests."""

from __future__ import annotations

from typing import Any

import yaml

from apbot.model.load import loads_model
from apbot.model.schema import ApplianceModel
from apbot.read.goal import parse_instruction

STAMPER = """
appliance: {id: stamp_1, category: tag_maker, name: "Tagger T1", brand: T}
controls:
  - {id: look_button, kind: button, label: "LOOK"}
  - {id: feed_button, kind: button, label: "FEED"}
variables:
  look:
    type: discrete
    values: [plain, heavy, slanted]
    label: LOOK
  feed:
    type: discrete
    values: [plain, heavy, slanted]
    label: FEED
actions:
  press_look: {control: look_button}
  press_feed: {control: feed_button}
features:
  set_look:
    - {actions: [press_look], variable: look, effect: next}
  set_feed:
    - {actions: [press_feed], variable: feed, effect: next}
display:
  idle: "{look}"
"""

STAMPER_MANUAL = """Tagger T1

FEED     Feeds the tape out; press again to stop.

Letter look (LOOK)
  Press LOOK repeatedly to go round the looks:
      PLAIN -> HEAVY -> SLANTED -> PLAIN
"""


def _reordered(text: str, first: str) -> ApplianceModel:
    """The model with the variable ``first`` listed first."""
    data: dict[str, Any] = yaml.safe_load(text)
    variables = data["variables"]
    data["variables"] = {first: variables[first]} | {
        k: v for k, v in variables.items() if k != first
    }
    return loads_model(yaml.safe_dump(data, sort_keys=False))


def test_a_value_two_settings_offer_goes_to_the_one_the_manual_lists_it_under() -> None:
    for first in ("look", "feed"):
        model = _reordered(STAMPER, first)
        assert parse_instruction(model, "Slanted letters please", STAMPER_MANUAL, []) == {
            "look": "slanted"
        }


PROBE_OVEN = """
appliance: {id: smoke_1, category: smoker, name: "Ember S1", brand: E}
controls:
  - {id: heat_button, kind: button, label: "HEAT"}
  - {id: menu_button, kind: button, label: "MENU"}
  - {id: up_button, kind: button, label: "+"}
  - {id: down_button, kind: button, label: "-"}
variables:
  chamber:
    type: numeric
    unit: "°C"
    ranges: [[50, 150, 5]]
    initial: 100
    label: HEAT
  core:
    type: numeric
    unit: "°C"
    ranges: [[50, 150, 5]]
    initial: 70
    label: MENU
  weight:
    type: numeric
    unit: g
    ranges: [[50, 150, 5]]
    initial: 100
    label: MENU
actions:
  press_heat: {control: heat_button}
  press_menu: {control: menu_button}
  press_up: {control: up_button}
  press_down: {control: down_button}
features:
  set_chamber:
    - actions: [press_heat, press_up, press_down]
      variable: chamber
      effect: {press_heat: next, press_up: next, press_down: prev}
  menu:
    - {actions: [press_menu]}
    - actions: [press_up, press_down]
      variable: core
      effect: {press_up: next, press_down: prev}
    - actions: [press_up, press_down]
      variable: weight
      effect: {press_up: next, press_down: prev}
display:
  idle: "{chamber}"
"""


def test_a_number_two_settings_take_goes_by_its_unit_in_either_order() -> None:
    for first in ("chamber", "core", "weight"):
        model = _reordered(PROBE_OVEN, first)
        assert parse_instruction(model, "Smoke 120 g of fish") == {"weight": 120}


def test_a_number_no_word_tells_apart_goes_to_the_setting_with_its_own_key() -> None:
    for first in ("chamber", "core", "weight"):
        model = _reordered(PROBE_OVEN, first)
        assert parse_instruction(model, "Keep it at 90 degrees") == {"chamber": 90}


GRILL_OVEN = """
appliance: {id: grill_1, category: combi_oven, name: "Tessa G1", brand: T}
controls:
  - {id: hot_air_button, kind: button, label: "HOT AIR"}
  - {id: grill_button, kind: button, label: "GRILL"}
  - {id: up_button, kind: button, label: "+"}
  - {id: down_button, kind: button, label: "-"}
variables:
  mode:
    type: discrete
    values: [hot air, grill]
  air_temp:
    type: numeric
    unit: "°C"
    ranges: [[100, 220, 10]]
    initial: 160
  grill_level:
    type: numeric
    ranges: [[1, 3, 1]]
    initial: 2
actions:
  press_hot_air: {control: hot_air_button}
  press_grill: {control: grill_button}
  press_up: {control: up_button}
  press_down: {control: down_button}
features:
  hot_air:
    - {actions: [press_hot_air], variable: mode, effect: {to: hot air}}
    - actions: [press_up, press_down]
      variable: air_temp
      effect: {press_up: next, press_down: prev}
  grill:
    - {actions: [press_grill], variable: mode, effect: {to: grill}}
    - actions: [press_up, press_down]
      variable: grill_level
      effect: {press_up: next, press_down: prev}
display:
  idle: "{mode}"
"""


def test_a_read_belief_that_states_no_start_is_asked_for_the_implied_mode() -> None:
    oven = loads_model(GRILL_OVEN)
    said = "Bake it at 180 degrees"
    # the author's model: the first value is where the panel starts; nothing to add
    assert parse_instruction(oven, said) == {"air_temp": 180}
    # a read belief only guesses its start from the manual's first key: the mode is asked for
    assert parse_instruction(oven, said, "", []) == {"air_temp": 180, "mode": "hot air"}
    stated = loads_model(
        GRILL_OVEN.replace(
            "values: [hot air, grill]", "values: [hot air, grill]\n    initial: hot air"
        )
    )
    assert parse_instruction(stated, said, "", []) == {"air_temp": 180}
