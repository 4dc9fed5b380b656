"""Values a panel shows as three-letter codes ("SLO", "FST", "GRN", "MAN"), named by the words
they cut short (``goal_shortened.display_abbreviation``); and a read belief's placeholder name,
whose words ("read from the manual") are no words for the appliance (``belief_name.UNNAMED``)."""

from __future__ import annotations

from apbot.model.schema import ApplianceModel
from apbot.read.belief_name import UNNAMED
from apbot.read.goal import parse_instruction
from apbot.read.goal_shortened import display_abbreviation
from tests.helpers import model_from

# a drying cabinet whose display abbreviates: fan SLO / MED / FST, lamp WHT / GRN, AUTO / MAN
CABINET = """
    controls: [{id: fan}, {id: lamp}, {id: mode}, {id: level}, {id: time}]
    variables:
      fan: {type: discrete, values: [slo, med, fst], label: FAN}
      lamp: {type: discrete, values: [wht, grn, red], label: LAMP}
      mode: {type: discrete, values: [auto, man], label: MODE}
      level: {type: discrete, values: [min, mid, max], label: LEVEL}
      time: {type: numeric, ranges: [[1, 60, 1]], unit: min, label: TIME}
    actions:
      press_fan: {control: fan}
      press_lamp: {control: lamp}
      press_mode: {control: mode}
      press_level: {control: level}
      press_time: {control: time}
    features:
      fan:
        - {actions: [press_fan], variable: fan, effect: next}
      lamp:
        - {actions: [press_lamp], variable: lamp, effect: next}
      mode:
        - {actions: [press_mode], variable: mode, effect: next}
      level:
        - {actions: [press_level], variable: level, effect: next}
      time:
        - {actions: [press_time], variable: time, effect: next}
    """
SHORT = model_from(CABINET)
READ = model_from(f"\n    appliance: {{id: t, category: dryer, name: {UNNAMED}}}" + CABINET)


def test_a_code_is_the_word_it_cuts_short() -> None:
    assert parse_instruction(SHORT, "The fan on fast and the lamp in green.") == {
        "fan": "fst",
        "lamp": "grn",
    }
    assert parse_instruction(SHORT, "A slow fan with white light.") == {
        "fan": "slo",
        "lamp": "wht",
    }


def test_time_units_and_other_words_are_no_codes() -> None:
    assert display_abbreviation("min", "minute") is False
    assert display_abbreviation("mid", "midnight") is False
    assert display_abbreviation("fst", "first") is False
    assert display_abbreviation("man", "manually") is False
    assert parse_instruction(SHORT, "Run it for a minute.") == {"time": 1}


def test_manual_is_no_word_for_a_read_belief_appliance() -> None:
    assert parse_instruction(READ, "Manual mode, fan on slow.") == {"mode": "man", "fan": "slo"}


def test_only_a_value_written_as_three_letters_is_a_code() -> None:
    """FREE (stem "fre") is no code for "french"; PRE is no "press"."""
    words = model_from(
        """
        controls: [{id: flow}, {id: wash}]
        variables:
          flow: {type: discrete, values: [free, metered], label: FLOW}
          wash: {type: discrete, values: [pre, main], label: WASH}
        actions:
          press_flow: {control: flow}
          press_wash: {control: wash}
        features:
          flow:
            - {actions: [press_flow], variable: flow, effect: next}
          wash:
            - {actions: [press_wash], variable: wash, effect: next}
        """
    )
    assert "flow" not in parse_instruction(words, "A French press of coffee.")
    assert "wash" not in parse_instruction(words, "Press the wash key.")


def test_with_a_manual_a_code_is_cut_only_from_a_word_the_manual_uses() -> None:
    """Given the manual, a word that merely starts like a code ("mango", "autumn") or shares
    its consonants ("grain") names it no more; the words the manual explains it by still do."""
    manual = "FAN: SLO (slow) or FST (fast). LAMP: WHT (white) or GRN (green). MODE: AUTO or MAN."
    assert parse_instruction(SHORT, "A mango smoothie in autumn.", manual) == {}
    assert parse_instruction(SHORT, "Whole grain, feast for 5 minutes.", manual) == {"time": 5}
    assert parse_instruction(SHORT, "Fan on fast, lamp in green.", manual) == {
        "fan": "fst",
        "lamp": "grn",
    }


def one_key_setting(name: str, values: str, label: str) -> ApplianceModel:
    """A panel of one key stepping one coded setting through ``values`` (a YAML list's items)."""
    return model_from(f"""
        controls: [{{id: {name}}}]
        variables:
          {name}: {{type: discrete, values: [{values}], label: {label}}}
        actions:
          press_{name}: {{control: {name}}}
        features:
          {name}:
            - {{actions: [press_{name}], variable: {name}, effect: next}}
        """)


# a sealer whose pressure is NORMAL or GENTLE, with the same fan codes
SEALER = model_from("""
    controls: [{id: fan}, {id: pressure}]
    variables:
      fan: {type: discrete, values: [slo, med, fst], label: FAN}
      pressure: {type: discrete, values: [normal, gentle], label: PRESSURE}
    actions:
      press_fan: {control: fan}
      press_pressure: {control: pressure}
    features:
      fan:
        - {actions: [press_fan], variable: fan, effect: next}
      pressure:
        - {actions: [press_pressure], variable: pressure, effect: next}
    """)


def test_an_adverb_names_the_value_of_its_adjective() -> None:
    # "gently" drops GENTLE's final e; "slowly" is slow, which SLO cuts short
    assert parse_instruction(SEALER, "Seal the crackers gently.") == {"pressure": "gentle"}
    assert parse_instruction(SEALER, "Dry the herbs slowly.") == {"fan": "slo"}
    # an adverb of another adjective names nothing
    assert "fan" not in parse_instruction(SEALER, "Seal it gently, it stops automatically.")


def test_an_adverb_opening_a_sentence_or_not_in_the_manual_names_no_code() -> None:
    """ "Finally," comments on the sentence; "manually" names MAN only in a manual that says
    "manual" (as a code is cut only from a word the manual uses)."""
    stages = one_key_setting("stage", "pre, fin", "STAGE")
    assert "stage" not in parse_instruction(stages, "Finally, rinse the cups.")
    manual = "FAN: SLO (slow) or FST (fast). LAMP: WHT (white) or GRN (green). MODE: AUTO or MAN."
    said = parse_instruction(SHORT, "Dry the herbs slowly, I will stop it manually.", manual)
    assert said == {"fan": "slo"}


def test_a_time_adverb_or_the_users_own_act_names_no_code() -> None:
    """ "shortly" says when, not how: no SHT even where the manual reads SHT as "short"; and
    "manually" of the user stopping it names no MAN even where the manual says "manual"."""
    cycles = one_key_setting("cycle", "sht, lng", "CYCLE")
    manual = "CYCLE: SHT (short) or LNG (long)."
    assert "cycle" not in parse_instruction(
        cycles, "Wash the jars, it should be done shortly.", manual
    )
    manual = "FAN: SLO (slow) or FST (fast). MODE: AUTO (automatic) or MAN (manual)."
    for said in (
        "Dry the herbs slowly, I will stop it manually.",
        "Dry the herbs slowly and stop it manually.",
        "Dry the herbs slowly; I'll stop it manually.",
    ):
        assert parse_instruction(SHORT, said, manual) == {"fan": "slo"}
    # a wish is no act of the user's: "I want it …slowly" still names SLO
    said = parse_instruction(SHORT, "I want the herbs dried slowly.", manual)
    assert said == {"fan": "slo"}


def test_an_interval_named_by_a_time_adverb_is_still_named() -> None:
    """ "daily" and "weekly" say how often, and an interval setting's values are named so:
    only "shortly" and "lately" say when rather than which."""
    interval = one_key_setting("every", "daily, weekly", "EVERY")
    manual = "EVERY: DAILY or WEEKLY watering."
    assert parse_instruction(interval, "Water the beds weekly.", manual) == {"every": "weekly"}
    assert parse_instruction(interval, "I'd like it daily.", manual) == {"every": "daily"}
