"""Settings the parser used to leave out of a goal though the model holds them: a superlative
of heat closed by the appliance's own limit ("the hottest it goes") or ending its clause ("the
music at the loudest;"), never an end of a time; "the second level" on a setting counted in
numbers; a setting a panel names by an adjective (BRIGHT) said by its noun ("full
brightness"). Small models written for these tests."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction

CURLER = """
appliance: {id: curler_1, category: hair_curler, name: "Wave C-2 curling wand", brand: W}
controls:
  - {id: curl_key, kind: button, label: "CURL"}
  - {id: up_key, kind: button, label: "+"}
  - {id: down_key, kind: button, label: "-"}
  - {id: ao_key, kind: button, label: "CURL AO"}
  - {id: beat_key, kind: button, label: "MUSIC"}
  - {id: vol_key, kind: button, label: "VOLUME"}
variables:
  curl: {type: discrete, values: [loose, tight], show: {loose: "LOOSE", tight: "TIGHT"}}
  temperature:
    type: numeric
    unit: "°C"
    ranges: [[120, 200, 10]]
    initial: 160
    wrap: false
    show: "{value}"
  curl_off:
    type: numeric
    unit: min
    label: "CURL AO"
    ranges: [[30, 90, 30]]
    initial: 60
    wrap: true
    show: "AO {value}"
  music:
    type: discrete
    values: [rain, waves, birds]
    show: {rain: "RN", waves: "WV", birds: "BD"}
  volume: {type: numeric, ranges: [[1, 6, 1]], initial: 3, wrap: true, show: "V{value}"}
actions:
  press_curl: {control: curl_key}
  press_up: {control: up_key}
  press_down: {control: down_key}
  press_ao: {control: ao_key}
  press_music: {control: beat_key}
  press_vol: {control: vol_key}
features:
  curl:
    - {actions: [press_curl], variable: curl, effect: next}
  temperature:
    - actions: [press_up, press_down]
      variable: temperature
      effect: {press_up: next, press_down: prev}
  curl_off:
    - {actions: [press_ao], variable: curl_off, effect: next}
  music:
    - {actions: [press_music], variable: music, effect: next}
  volume:
    - {actions: [press_vol], variable: volume, effect: next}
"""

LAMP = """
appliance: {id: lamp_1, category: desk_lamp, name: "Lumo D-4 desk lamp", brand: L}
controls:
  - {id: b_key, kind: button, label: "BRIGHT"}
  - {id: s_key, kind: button, label: "SPEED"}
variables:
  bright:
    type: discrete
    values: ["25", "50", "75", "100"]
    show: {"25": "B25", "50": "B50", "75": "B75", "100": "B100"}
  fan:
    {type: numeric, label: "SPEED", ranges: [[1, 5, 1]], initial: 1, wrap: true, show: "F{value}"}
actions:
  press_bright: {control: b_key}
  press_speed: {control: s_key}
features:
  bright:
    - {actions: [press_bright], variable: bright, effect: next}
  fan:
    - {actions: [press_speed], variable: fan, effect: next}
"""


def _curler(text: str) -> dict[str, object]:
    return parse_instruction(loads_model(CURLER), text)


def _lamp(text: str) -> dict[str, object]:
    return parse_instruction(loads_model(LAMP), text)


def test_the_hottest_it_goes_is_the_top_temperature() -> None:
    assert _curler("Loose curls at the hottest it goes.") == {"curl": "loose", "temperature": 200}
    assert _curler("the coolest it will go, please")["temperature"] == 120


def test_a_superlative_of_heat_is_no_end_of_a_time() -> None:
    assert _curler("Tight curl, hottest setting.") == {"curl": "tight", "temperature": 200}


def test_a_superlative_ending_its_clause_after_at_the() -> None:
    assert _curler("Birdsong at the loudest; that is all.") == {"music": "birds", "volume": 6}
    assert _curler("Rain at the loudest, please")["volume"] == 6


def test_the_second_level_is_level_two_of_a_numbered_setting() -> None:
    assert _lamp("Fan on the second level") == {"fan": 2}
    assert _lamp("the third level for the fan, half brightness")["fan"] == 3


def test_an_adjectives_noun_names_the_setting() -> None:
    assert _lamp("Full brightness.") == {"bright": "100"}


RECLINER = """
appliance: {id: recliner_1, category: recliner, name: "Sofa R-3 power recliner", brand: R}
controls:
  - {id: back_up, kind: button, label: "BACK ▲"}
  - {id: back_down, kind: button, label: "BACK ▼"}
  - {id: legs_up, kind: button, label: "LEGS ▲"}
  - {id: legs_down, kind: button, label: "LEGS ▼"}
  - {id: nap_key, kind: button, label: "NAP"}
  - {id: heat_key, kind: button, label: "HEAT"}
variables:
  back: {type: numeric, ranges: [[0, 50, 5]], show: "BACK {value}"}
  legs: {type: numeric, ranges: [[0, 30, 5]], show: "LEGS {value}"}
  heat: {type: discrete, values: ["off", "on"], show: {"off": "", "on": "HEAT"}}
  tilt: {type: numeric, ranges: [[1, 3, 1]], wrap: true, show: "T{value}"}
actions:
  press_back_up: {control: back_up}
  press_back_down: {control: back_down}
  press_legs_up: {control: legs_up}
  press_legs_down: {control: legs_down}
  press_nap: {control: nap_key}
  press_heat: {control: heat_key}
features:
  back:
    - actions: [press_back_up, press_back_down]
      variable: back
      effect: {press_back_up: next, press_back_down: prev}
  legs:
    - actions: [press_legs_up, press_legs_down]
      variable: legs
      effect: {press_legs_up: next, press_legs_down: prev}
  heat:
    - {actions: [press_heat], variable: heat, effect: toggle}
  tilt:
    - {actions: [press_nap], variable: tilt, effect: next}
"""

RECLINER_MANUAL = """
# Sofa R-3

## One-touch keys

| Key | Back | Legs | What for            |
|-----|------|------|---------------------|
| NAP | 35°  | 20°  | a short rest        |
| TV  | 15°  | kept | watching television |
"""


def _recliner(text: str) -> dict[str, object]:
    return parse_instruction(loads_model(RECLINER), text, RECLINER_MANUAL)


def test_a_charted_key_named_sets_the_settings_its_row_gives() -> None:
    assert _recliner("The nap position with the heat on") == {"back": 35, "legs": 20, "heat": "on"}


def test_a_setting_the_sentence_gives_keeps_its_value_and_kept_sets_nothing() -> None:
    assert _recliner("Nap position, but the legs at 10") == {"back": 35, "legs": 10}
    assert "back" not in _recliner("TV at 15")  # TV is no key of this panel


AMP = """
appliance: {id: amp_1, category: stereo_amplifier, name: "Tono A-1 amplifier", brand: T}
controls:
  - {id: src_key, kind: button, label: "SOURCE"}
  - {id: led_key, kind: button, label: "LED"}
  - {id: feed_key, kind: button, label: "FEED"}
variables:
  source:
    type: discrete
    values: [cd, phono, tuner, bt]
    show: {cd: "CD", phono: "PHONO", tuner: "TUNER", bt: "BT"}
  led:
    type: discrete
    values: [white, violet, amber]
    show: {white: "W", violet: "V", amber: "A"}
  feed: {type: discrete, values: [grid, solar], show: {grid: "GRID", solar: "SOLAR"}}
actions:
  press_source: {control: src_key}
  press_led: {control: led_key}
  press_feed: {control: feed_key}
features:
  source:
    - {actions: [press_source], variable: source, effect: next}
  led:
    - {actions: [press_led], variable: led, effect: next}
  feed:
    - {actions: [press_feed], variable: feed, effect: next}
"""


def _amp(text: str) -> dict[str, object]:
    return parse_instruction(loads_model(AMP), text)


def test_plain_words_name_values_printed_in_a_trades_word() -> None:
    assert _amp("Play the radio") == {"source": "tuner"}
    assert _amp("my vinyl, please")["source"] == "phono"
    assert _amp("Bluetooth with the purple glow") == {"source": "bt", "led": "violet"}
    assert _amp("run it on sun power")["feed"] == "solar"


STATION = """
appliance: {id: station_1, category: power_bank, name: "Volt P-5 station", brand: V}
controls:
  - {id: on_key, kind: button, label: "⏻"}
  - {id: lamp_key, kind: button, label: "LAMP"}
  - {id: usb_key, kind: button, label: "USB"}
variables:
  main_hold: {type: discrete, values: ["off", "on"], show: {"off": "", "on": "ON"}}
  lamp: {type: discrete, values: ["off", "on"], show: {"off": "", "on": "LAMP"}}
  usb: {type: discrete, values: ["off", "on"], show: {"off": "", "on": "USB"}}
actions:
  hold_on: {control: on_key, skill: hold, seconds: 2}
  press_lamp: {control: lamp_key}
  press_usb: {control: usb_key}
features:
  main_hold:
    - {actions: [hold_on], variable: main_hold, effect: toggle}
  lamp:
    - {actions: [press_lamp], variable: lamp, effect: toggle}
  usb:
    - {actions: [press_usb], variable: usb, effect: toggle}
"""


def test_the_switch_of_the_power_symbol_is_the_power() -> None:
    goal = parse_instruction(loads_model(STATION), "Turn the station on with the USB ports on")
    assert goal == {"main_hold": "on", "usb": "on"}


DECK = """
appliance: {id: deck_1, category: record_deck, name: "Platter D-2 record deck", brand: P}
controls:
  - {id: start_key, kind: button, label: "START/STOP"}
  - {id: speed_key, kind: button, label: "SPEED"}
variables:
  running: {type: discrete, values: ["off", "on"], show: {"off": "", "on": "RUN"}}
  speed: {type: discrete, values: ["33", "45"], show: {"33": "33", "45": "45"}}
actions:
  press_start: {control: start_key}
  press_speed: {control: speed_key}
features:
  start:
    - {actions: [press_start], variable: running, effect: toggle}
  speed:
    - {actions: [press_speed], variable: speed, effect: toggle}
"""


def test_an_order_to_play_or_stitch_starts_the_work() -> None:
    deck = loads_model(DECK)
    assert parse_instruction(deck, "Play a single at 45") == {"speed": "45", "running": "on"}
    assert parse_instruction(deck, "Put it on 33 but don't play it yet")["running"] == "off"


KILN = """
appliance: {id: kiln_1, category: glass_kiln, name: "Fuse K-3 glass kiln", brand: F}
controls:
  - {id: hold_key, kind: button, label: "HOLD"}
  - {id: weeks_key, kind: button, label: "CURE"}
  - {id: lamp_key, kind: button, label: "LAMP HOURS"}
variables:
  hold:
    type: numeric
    unit: min
    ranges: [[0, 60, 10]]
    initial: 10
    wrap: true
    show: "H{value}"
  cure:
    type: discrete
    values: [1 d, 3 d, 7 d, 14 d, 28 d]
    show: {1 d: "1d", 3 d: "3d", 7 d: "7d", 14 d: "14d", 28 d: "28d"}
  lamp_hours: {type: numeric, ranges: [[8, 18, 1]], initial: 12, wrap: true, show: "L{value}"}
actions:
  press_hold: {control: hold_key}
  press_cure: {control: weeks_key}
  press_lamp: {control: lamp_key}
features:
  hold:
    - {actions: [press_hold], variable: hold, effect: next}
  cure:
    - {actions: [press_cure], variable: cure, effect: next}
  lamp_hours:
    - {actions: [press_lamp], variable: lamp_hours, effect: next}
"""


def _kiln(text: str) -> dict[str, object]:
    return parse_instruction(loads_model(KILN), text)


def test_a_setting_named_by_a_key_verb_is_named_by_it() -> None:
    assert _kiln("Fire it with no hold") == {"hold": 0}
    assert _kiln("a 20 minute hold")["hold"] == 20


def test_weeks_on_a_list_of_days() -> None:
    assert _kiln("Let it cure for two weeks") == {"cure": "14 d"}
    assert _kiln("cure for four weeks")["cure"] == "28 d"


def test_weeks_read_as_days_go_to_the_list_of_days_only() -> None:
    outside: list[str] = []
    goal = parse_instruction(
        loads_model(KILN), "I'm away for a week, so cure it for 3 days", "", outside
    )
    assert goal == {"cure": "3 d"} and outside == []


MIXER = """
appliance: {id: granita_1, category: granita_machine, name: "Gelo G-2 granita machine", brand: G}
controls:
  - {id: t_key, kind: button, label: "THICK"}
  - {id: v_key, kind: button, label: "VOL"}
variables:
  thick: {type: numeric, ranges: [[1, 5, 1]], initial: 3, wrap: true, show: "T{value}"}
  vol: {type: numeric, ranges: [[1, 8, 1]], initial: 4, wrap: true, show: "V{value}"}
actions:
  press_thick: {control: t_key}
  press_vol: {control: v_key}
features:
  thick:
    - {actions: [press_thick], variable: thick, effect: next}
  vol:
    - {actions: [press_vol], variable: vol, effect: next}
"""


def test_a_vol_is_the_volume_and_the_texture_is_the_thickness() -> None:
    mixer = loads_model(MIXER)
    assert parse_instruction(mixer, "the loudest volume") == {"vol": 8}
    assert parse_instruction(mixer, "the softest texture") == {"thick": 1}
