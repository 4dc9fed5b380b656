"""A quantity with a unit, for a setting the reader left without one (``goal_unitless.py``); a
value named by a later word of its name (``goal_phrases._first_words``).

The cabinet below was read the way readers often read: its CELLAR setting has the right range
but no unit, and its CHILL setting is a list of bare numbers. The user says degrees.
"""

from __future__ import annotations

from apbot.read.goal import parse_instruction
from tests.helpers import model_from

# a two-zone drinks cabinet: CELLAR steps 5 … 18, CHILL cycles -2 … -5, both read unitless
CABINET = model_from(
    """
    controls: [{id: cellar}, {id: chill}, {id: light}]
    variables:
      cellar: {type: numeric, ranges: [[5, 18, 1]], label: CELLAR}
      chill: {type: discrete, values: ["-2", "-3", "-4", "-5"], label: CHILL}
      light: {type: discrete, values: ["off", "on"], label: LIGHT}
    actions:
      press_cellar: {control: cellar}
      press_chill: {control: chill}
      press_light: {control: light}
    features:
      set_cellar:
        - {actions: [press_cellar], variable: cellar, effect: next}
      set_chill:
        - {actions: [press_chill], variable: chill, effect: next}
      light:
        - {actions: [press_light], variable: light, effect: toggle}
    """
)

# the same cabinet with a setting that does say degrees: a temperature goes there
DIALLED = model_from(
    """
    controls: [{id: cellar}, {id: temp}]
    variables:
      cellar: {type: numeric, ranges: [[5, 18, 1]], label: CELLAR}
      temp: {type: numeric, ranges: [[5, 18, 1]], unit: "°C", label: TEMP}
    actions:
      press_cellar: {control: cellar}
      press_temp: {control: temp}
    features:
      set_cellar:
        - {actions: [press_cellar], variable: cellar, effect: next}
      set_temp:
        - {actions: [press_temp], variable: temp, effect: next}
    """
)


def test_degrees_go_to_the_unitless_setting_named_beside_them() -> None:
    goal = parse_instruction(CABINET, "Cellar at 12 degrees and the chill zone at -4 °C, please.")
    assert goal == {"cellar": 12, "chill": "-4"}
    assert parse_instruction(CABINET, "Put 7 °C in the cellar.") == {"cellar": 7}


def test_an_unnamed_or_impossible_quantity_is_not_given_to_it() -> None:
    for said in ("Make it 12 degrees.", "Cellar lamp on, it is 12 degrees outside."):
        try:
            goal = parse_instruction(CABINET, said)
        except ValueError:
            continue  # refused with a message is right too: no setting is named with it
        assert "cellar" not in goal, (said, goal)


def test_a_setting_of_the_quantitys_kind_is_meant_instead() -> None:
    assert parse_instruction(DIALLED, "Set 9 degrees.") == {"temp": 9}


# a foot massager whose automatic programmes share their first word
MASSAGER = model_from(
    """
    controls: [{id: mode}]
    variables:
      programme: {type: discrete, values: [auto calm, auto revive, auto warm up, kneading],
                  label: PROGRAMME}
    actions:
      press_mode: {control: mode}
    features:
      set_programme:
        - {actions: [press_mode], variable: programme, effect: next}
    """
)


def test_a_later_word_of_a_value_names_it_beside_the_settings_word() -> None:
    """Users name AUTO REVIVE "the revive programme"; the shared AUTO names none of them, and
    a distinctive word without the setting's own word beside it names nothing."""
    assert parse_instruction(MASSAGER, "The revive programme, please.") == {
        "programme": "auto revive"
    }
    assert parse_instruction(MASSAGER, "The calm programme.") == {"programme": "auto calm"}
    for said in ("Keep me calm and start it.", "The auto programme."):
        try:
            goal = parse_instruction(MASSAGER, said)
        except ValueError:
            continue
        assert "programme" not in goal, (said, goal)
