"""Panel names that cut the user's word short (``goal_vocab.cut_short``): a value whose stem is
shorter than the panel's word ("BUZZ", stem "buz", for buzzer), a switch cut at a syllable
("OSC" for oscillation, "REGEN" for regeneration), and a value that is the head noun of the
user's compound ("teapot" for POT, where the manual speaks of tea)."""

from __future__ import annotations

from apbot.read.goal import parse_instruction
from apbot.read.goal_vocab import cut_short
from tests.helpers import model_from

# a bedside water station: an alarm sound, a serving size, a swirling spray and a filter rinse
STATION = model_from(
    """
    controls: [{id: sound}, {id: size}, {id: osc}, {id: regen}]
    variables:
      sound: {type: discrete, values: ["off", buzz, radio], label: SOUND}
      size: {type: discrete, values: [cup, mug, pot], label: SIZE}
      osc: {type: discrete, values: ["off", "on"], label: OSC}
      regen: {type: discrete, values: ["off", "on"], label: REGEN}
    actions:
      press_sound: {control: sound}
      press_size: {control: size}
      press_osc: {control: osc}
      press_regen: {control: regen}
    features:
      set_sound:
        - {actions: [press_sound], variable: sound, effect: next}
      set_size:
        - {actions: [press_size], variable: size, effect: next}
      osc:
        - {actions: [press_osc], variable: osc, effect: toggle}
      regen:
        - {actions: [press_regen], variable: regen, effect: toggle}
    """
)
MANUAL = "Pour hot water for tea or coffee. SIZE picks CUP, MUG or POT. OSC swirls the spray."


def test_a_panel_word_is_the_start_of_the_users_word() -> None:
    assert parse_instruction(STATION, "Wake me with the buzzer.", MANUAL) == {"sound": "buzz"}
    assert parse_instruction(STATION, "Turn the oscillation on.", MANUAL) == {"osc": "on"}
    assert parse_instruction(STATION, "Run a regeneration.", MANUAL) == {"regen": "on"}


def test_a_value_heads_the_users_compound() -> None:
    assert parse_instruction(STATION, "Fill the teapot.", MANUAL) == {"size": "pot"}
    # "spot" and "depot" merely end in its letters: no word of the manual comes first
    assert "size" not in parse_instruction(STATION, "Fill it on the spot.", MANUAL)


def test_a_cut_ends_a_syllable() -> None:
    assert cut_short("temp", "temperature")
    assert cut_short("recirc", "recirculation")
    assert not cut_short("temp", "temptation")
    assert not cut_short("set", "settings")
    assert not cut_short("fan", "fantastically")


# a water softener whose REGEN key starts a regeneration and REGEN TIME sets when it runs
SOFTENER = model_from(
    """
    controls: [{id: regen}, {id: regen_time}]
    variables:
      regen: {type: discrete, values: ["off", "on"], label: REGEN}
      regen_time: {type: numeric, ranges: [[0, 23, 1]], unit: h, label: REGEN TIME}
    actions:
      press_regen: {control: regen}
      press_regen_time: {control: regen_time}
    features:
      regen:
        - {actions: [press_regen], variable: regen, effect: toggle}
      set_regen_time:
        - {actions: [press_regen_time], variable: regen_time, effect: next}
    """
)


def test_the_long_word_of_a_setting_given_is_not_the_switch() -> None:
    assert parse_instruction(SOFTENER, "Start a regeneration now.") == {"regen": "on"}
    assert "regen" not in parse_instruction(SOFTENER, "Move the regeneration time to 4 h.")


# a small oven whose HEAT key picks the elements; its manual speaks of the counter it stands on
OVEN = model_from(
    """
    controls: [{id: heat}]
    variables:
      heat: {type: discrete, values: [top, bottom, both], label: HEAT}
    actions:
      press_heat: {control: heat}
    features:
      set_heat:
        - {actions: [press_heat], variable: heat, effect: next}
    """
)
OVEN_MANUAL = "Stand the oven on a flat counter. HEAT picks TOP, BOTTOM or BOTH elements."


def test_a_compound_said_as_a_place_names_no_value() -> None:
    """ "on the countertop" says where the oven stands, not the TOP element."""
    assert "heat" not in parse_instruction(OVEN, "Leave it on the countertop.", OVEN_MANUAL)


# a stand mixer: a speed level, a cooling FAN, a PRE-whip, an ION air freshener, a bowl MODE
# (PRE stays: "prepare" still turns it on — the fix drawn for it was shaped by a held-out record
# and was not merged)
MIXER = model_from(
    """
    controls: [{id: level}, {id: fan}, {id: pre}, {id: ion}, {id: mode}]
    variables:
      level: {type: discrete, values: ["1", "2", "3"], label: LEVEL}
      fan: {type: discrete, values: ["off", "on"], label: FAN}
      pre: {type: discrete, values: ["off", "on"], label: PRE}
      ion: {type: discrete, values: ["off", "on"], label: ION}
      mode: {type: discrete, values: [normal, freeze, chill], label: MODE}
    actions:
      press_level: {control: level}
      press_fan: {control: fan}
      press_pre: {control: pre}
      press_ion: {control: ion}
      press_mode: {control: mode}
    features:
      set_level:
        - {actions: [press_level], variable: level, effect: next}
      fan:
        - {actions: [press_fan], variable: fan, effect: toggle}
      pre:
        - {actions: [press_pre], variable: pre, effect: toggle}
      ion:
        - {actions: [press_ion], variable: ion, effect: toggle}
      set_mode:
        - {actions: [press_mode], variable: mode, effect: next}
    """
)
MIXER_MANUAL = (
    "LEVEL sets the speed from 1 to 3. FAN cools the motor. PRE runs a short pre-whip. "
    "ION freshens the air. MODE picks NORMAL, FREEZE or CHILL for the bowl."
)


def test_an_adjective_after_a_three_letter_name_is_no_cut() -> None:
    assert not cut_short("fan", "fancy")
    assert not cut_short("ion", "ionic")
    assert cut_short("ion", "ionizer")
    assert parse_instruction(MIXER, "Nothing fancy, just level 2.", MIXER_MANUAL) == {"level": "2"}
    assert "ion" not in parse_instruction(MIXER, "Level 2 with the ionic air.", MIXER_MANUAL)
    assert parse_instruction(MIXER, "Turn on the ionizer.", MIXER_MANUAL) == {"ion": "on"}


def test_where_a_thing_was_names_no_value() -> None:
    said = "Level 2, the bowl was in the freezer."
    assert parse_instruction(MIXER, said, MIXER_MANUAL) == {"level": "2"}
    assert parse_instruction(MIXER, "Level 2 on freeze.", MIXER_MANUAL)["mode"] == "freeze"
