"""A code one step past the end of a numbered scale ("press + beyond 6 and the display shows
T"), on small manuals written in our own words: the setting becomes the numbers and the code in
panel order, so a user asking for the code's word gets a value the panel can show."""

from __future__ import annotations

from apbot.model.schema import ApplianceModel, DiscreteVariable
from apbot.model.validate import check_model
from apbot.read import read_manual
from apbot.read.goal import parse_instruction
from tests.helpers import model_from

GRILL = """ORVO TG-2 TABLE GRILL
User guide

KEYS
  POWER     switches the grill on or off
  HEAT      selects the heat setting
  + / -     change the selected setting

HEAT
Press HEAT, then + or - to choose a heat setting from 1 to 6. Press + beyond 6 and the display
shows T: turbo heat, for searing. After five minutes on T the grill returns to 6.
"""
GRILL_ACTIONS = ["press_power", "press_heat", "press_plus", "press_minus"]

AIRER = """DRYA C-40 CLOTHES AIRER DRYER
Instructions

Panel: POWER key, MODE key, UP key, DOWN key.

Setting the dryness
The target humidity can be set from 40 % to 70 % in steps of 10 % with UP and DOWN.
Keep pressing DOWN past the lowest value until CN appears: the airer then dries without stopping.
"""
AIRER_ACTIONS = ["press_power", "press_mode", "press_up", "press_down"]


def _scale(model: ApplianceModel, actions: set[str]) -> tuple[str, DiscreteVariable]:
    """The list of more than three values a step with one of ``actions`` sets."""
    for feature in model.features.values():
        for step in feature:
            var = model.variables.get(step.variable or "")
            if (
                set(step.actions) & actions
                and isinstance(var, DiscreteVariable)
                and len(var.values) > 3
            ):
                return step.variable or "", var
    raise AssertionError("no scale with codes")


def test_a_code_past_the_top_of_a_scale_follows_its_numbers() -> None:
    model = read_manual(GRILL, GRILL_ACTIONS).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    _name, heat = _scale(model, {"press_plus"})
    assert heat.values == ["1", "2", "3", "4", "5", "6", "T"]
    assert heat.wrap is False


def test_a_code_below_the_lowest_value_comes_before_the_numbers() -> None:
    model = read_manual(AIRER, AIRER_ACTIONS).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    _name, humidity = _scale(model, {"press_down"})
    assert humidity.values == ["CN", "40", "50", "60", "70"]


def test_the_scale_s_end_may_be_named_as_a_level() -> None:
    text = GRILL.replace(
        "Press + beyond 6 and the display\nshows T", "Pressing + Past level 6\ndisplays T"
    )
    model = read_manual(text, GRILL_ACTIONS).model
    _name, heat = _scale(model, {"press_plus"})
    assert heat.values == ["1", "2", "3", "4", "5", "6", "T"]


def test_a_sentence_with_no_code_changes_nothing() -> None:
    text = GRILL.replace("and the display\nshows T: turbo heat", "and nothing more\nhappens: the")
    model = read_manual(text, GRILL_ACTIONS).model
    assert not any(
        isinstance(v, DiscreteVariable) and "T" in v.values for v in model.variables.values()
    )


PLATES = """
controls: [{id: power}, {id: left}, {id: right}, {id: plus}]
variables:
  power: {type: discrete, values: ["off", "on"]}
  left: {type: discrete, values: ["0", "1", "2", "3", "4", "5", "6", "T"], wrap: false,
         label: LEFT}
  right: {type: discrete, values: ["0", "1", "2", "3", "4", "5", "6", "T"], wrap: false,
          label: RIGHT}
actions:
  press_power: {control: power}
  press_left: {control: left}
  press_right: {control: right}
  press_plus: {control: plus}
features:
  power: [{actions: [press_power], variable: power, effect: toggle}]
  set_left: [{actions: [press_left, press_plus], variable: left, effect: next}]
  set_right: [{actions: [press_right, press_plus], variable: right, effect: next}]
"""
PLATES_LEGEND = """DISPLAY
| Display | Meaning |
|---|---|
| 0 | plate off |
| 1 … 6 | heat setting |
| T | Turbo, the step after 6 |
"""


def test_a_superlative_before_a_value_word_is_part_of_its_name() -> None:
    """ "full turbo", "maximum turbo": the word after the superlative is the value asked for,
    of the plate named; the superlative asks no other plate for its top number."""
    model = model_from(PLATES)
    for said in ("Right plate on full turbo.", "Right plate on maximum turbo"):
        assert parse_instruction(model, said, PLATES_LEGEND, []) == {"right": "T"}
    highest = parse_instruction(model, "Right plate on the highest heat.", PLATES_LEGEND, [])
    assert highest == {"right": "6"}


def test_the_top_of_a_scale_with_a_code_past_it_is_the_code() -> None:
    """ "full heat" on a grill whose manual puts T one step beyond 6: T is the top of the panel's
    scale; with no such sentence the top stays the highest number (above)."""
    model = read_manual(GRILL, GRILL_ACTIONS).model
    name, _heat = _scale(model, {"press_plus"})
    assert parse_instruction(model, "Grill at full heat.", GRILL, []).get(name) == "T"
    assert parse_instruction(model, "Grill at the lowest heat.", GRILL, []).get(name) == "1"


SMOKER = """KETO S-9 SMOKER GRILL
User guide

KEYS
  POWER     switches the grill on or off
  HEAT      selects the heat setting
  SMOKE     selects the smoke level
  + / -     change the selected setting

HEAT
Press HEAT, then + or - to choose a heat setting from 1 to 6. Press + beyond 6 and the display
shows T: turbo heat.

SMOKE
Press SMOKE, then + or - to choose a smoke level from 1 to 9.
"""


def test_a_code_past_one_scale_s_top_leaves_a_longer_scale_on_the_same_keys_whole() -> None:
    actions = ["press_power", "press_heat", "press_smoke", "press_plus", "press_minus"]
    model = read_manual(SMOKER, actions).model
    smoke = [v for n, v in model.variables.items() if "smoke" in n]
    assert smoke, list(model.variables)
    assert all(not isinstance(v, DiscreteVariable) or "9" in v.values for v in smoke)
    assert all(not isinstance(v, DiscreteVariable) or "T" not in v.values for v in smoke)


def test_a_code_shown_when_the_press_past_the_end_is_refused_is_no_value() -> None:
    refused = (
        "Press + beyond 6 and the display\nshows ERR for a moment: the heat stays at 6.",
        "Pressing + past the highest setting only beeps and shows HI.",
    )
    for sentence in refused:
        text = GRILL.replace(
            "Press + beyond 6 and the display\nshows T: turbo heat, for searing.", sentence
        )
        assert sentence in text
        model = read_manual(text, GRILL_ACTIONS).model
        assert not any(
            isinstance(v, DiscreteVariable) and {"ERR", "HI"} & set(v.values)
            for v in model.variables.values()
        ), sentence
