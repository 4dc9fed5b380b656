"""Settings a read belief holds that the parser used to drop: a key label cut short (MIC) that
the manual's legend writes out ("microphone volume dial") is named by the whole word, and one
end said of several settings joined by "and" ("the bass and the treble all the way up") goes to
each of them. Small models and manual lines written for these tests."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction

SPEAKER = """
appliance: {id: speaker_1, category: party_speaker, name: "read from the manual", brand: ""}
controls:
  - {id: mic_knob, kind: knob, label: "MIC"}
  - {id: bass_knob, kind: knob, label: "BASS"}
  - {id: treb_knob, kind: knob, label: "TREBLE"}
variables:
  mic: {type: numeric, label: MIC, ranges: [[0, 10, 1]], initial: 5, wrap: false, show: "{value}"}
  bass: {type: numeric, label: BASS, ranges: [[0, 8, 1]], initial: 4, wrap: false, show: "{value}"}
  treble:
    {type: numeric, label: TREBLE, ranges: [[0, 8, 1]], initial: 4, wrap: false, show: "{value}"}
actions:
  turn_mic_up: {control: mic_knob}
  turn_mic_down: {control: mic_knob}
  turn_bass_up: {control: bass_knob}
  turn_bass_down: {control: bass_knob}
  turn_treble_up: {control: treb_knob}
  turn_treble_down: {control: treb_knob}
features:
  mic:
    - actions: [turn_mic_up, turn_mic_down]
      variable: mic
      effect: {turn_mic_up: next, turn_mic_down: prev}
  bass:
    - actions: [turn_bass_up, turn_bass_down]
      variable: bass
      effect: {turn_bass_up: next, turn_bass_down: prev}
  treble:
    - actions: [turn_treble_up, turn_treble_down]
      variable: treble
      effect: {turn_treble_up: next, turn_treble_down: prev}
"""

LEGEND = """# Party speaker
## The dials
  (1) MIC       level of the microphone input
  (2) BASS      low tones
  (3) TREBLE    high tones
"""


def _parse(text: str, manual: str = LEGEND) -> dict[str, object]:
    return parse_instruction(loads_model(SPEAKER), text, manual, outside=[])


def test_a_cut_short_label_is_named_by_the_word_its_legend_writes_out() -> None:
    assert _parse("The microphone turned right down.") == {"mic": 0}
    assert _parse("Bass at 3 and the microphone right up.") == {"bass": 3, "mic": 10}


def test_without_the_legend_the_whole_word_names_nothing() -> None:
    assert _parse("The microphone turned right down.", manual="# Party speaker\n") == {}


def test_one_end_said_of_settings_joined_by_and_goes_to_each() -> None:
    assert _parse("Turn the bass and the treble all the way up.") == {"bass": 8, "treble": 8}
    assert _parse("Bass and microphone right down, please.") == {"bass": 0, "mic": 0}


def test_an_end_said_of_one_setting_stays_its_own() -> None:
    assert _parse("Treble at 2 and the bass all the way up.") == {"treble": 2, "bass": 8}


BRUSH = """
appliance: {id: brush_1, category: face_brush, name: "Glow F-2 cleansing brush", brand: G}
controls:
  - {id: p_key, kind: button, label: "⏻"}
  - {id: m_key, kind: button, label: "MODE"}
  - {id: beep_key, kind: button, label: "BEEP"}
variables:
  power: {type: discrete, values: ["off", "on"], show: {"off": "", "on": "ON"}}
  mode: {type: discrete, values: [daily, deep, gentle], show: {daily: DLY, deep: DP, gentle: GNT}}
  beep: {type: discrete, values: ["off", "on"], show: {"off": "", "on": "BP"}}
actions:
  press_power: {control: p_key}
  press_mode: {control: m_key}
  press_beep: {control: beep_key}
features:
  power:
    - {actions: [press_power], variable: power, effect: toggle}
  mode:
    - {actions: [press_mode], variable: mode, effect: next}
  beep:
    - {actions: [press_beep], variable: beep, effect: toggle}
"""


def _brush(text: str) -> dict[str, object]:
    return parse_instruction(loads_model(BRUSH), text, "", outside=[])


def test_the_power_said_to_stay_off_is_off() -> None:
    assert _brush("Gentle mode for tomorrow, but leave it off.") == {
        "mode": "gentle",
        "power": "off",
    }
    assert _brush("Deep mode and keep the brush switched off afterwards.")["power"] == "off"
    assert _brush("Without switching it on, pick the daily mode.")["power"] == "off"
    assert _brush("Without switching the gadget on, pick the daily mode.")["power"] == "off"


def test_a_switch_left_off_is_that_switch_not_the_power() -> None:
    assert "power" not in _brush("Deep mode, and leave the beep off.")
