"""Rules of how people phrase requests (goal16), checked on models written for these tests (loaded
unchecked: only the parts a rule reads are written): a wood router, a spice grinder, an egg
timer, a document camera, a coffee roaster, a reading lamp and a clock radio — none of them in
a suite. Each test would fail without its rule."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction


def _goal(model_text: str, said: str, manual: str = "") -> dict[str, object]:
    return dict(parse_instruction(loads_model(model_text, check=False), said, manual))


ROUTER = """
appliance: {id: router_x, category: wood_router, name: "Holzfix R8 router", brand: H}
controls:
  - {id: power_key, kind: button, label: "POWER"}
  - {id: speed_dial, kind: dial, label: "SPEED"}
  - {id: run_key, kind: button, label: "RUN"}
variables:
  power: {type: discrete, values: ["off", "on"]}
  speed: {type: numeric, ranges: [[8, 24, 1]], initial: 12}
  running: {type: discrete, values: ["off", "on"]}
actions:
  press_power: {control: power_key}
  faster: {control: speed_dial, skill: turn_cw}
  slower: {control: speed_dial, skill: turn_ccw}
  press_run: {control: run_key}
features:
  power:
    - {actions: [press_power], variable: power, effect: toggle}
  speed:
    - {actions: [faster, slower], variable: speed, effect: {faster: next, slower: prev}}
  start:
    - {actions: [press_run], variable: running, effect: toggle}
"""
ROUTER_MANUAL = """The two digits show the spindle speed in thousands of rpm: 16 is 16,000 rpm.
Turn SPEED to change it; each click is 1,000 rpm (8 to 24)."""


def test_thousands_on_a_display_that_counts_in_thousands() -> None:
    """ "eighteen thousand rpm" is the speed 18 where the manual says the display counts in
    thousands; said without its unit it still finds the speed (goal_thousands)."""
    said = "Run the router at eighteen thousand rpm."
    assert _goal(ROUTER, said, ROUTER_MANUAL) == {"speed": 18, "running": "on"}
    assert _goal(ROUTER, "Run it at 16k.", ROUTER_MANUAL) == {"speed": 16, "running": "on"}
    assert _goal(ROUTER, "Set it to 20,000 but don't start it.", ROUTER_MANUAL) == {
        "speed": 20,
        "running": "off",
    }


def test_the_appliance_running_at_a_value_is_a_start() -> None:
    """ "Router running at 14" asks for the router to run (goal_start)."""
    said = "Router running at fourteen thousand."
    assert _goal(ROUTER, said, ROUTER_MANUAL) == {"speed": 14, "running": "on"}


GRINDER = """
appliance: {id: grinder_x, category: spice_grinder, name: "Mahl S2 spice mill", brand: M}
controls:
  - {id: grind_dial, kind: dial, label: "GRIND"}
  - {id: cups_key, kind: button, label: "AMOUNT"}
  - {id: start_key, kind: button, label: "START"}
variables:
  grind: {type: numeric, ranges: [[1, 9, 1]], initial: 5}
  amount:
    type: discrete
    values: ["1", "2", "4", "6"]
    show: {"1": "1C", "2": "2C", "4": "4C", "6": "6C"}
  running: {type: discrete, values: ["off", "on"]}
actions:
  coarser: {control: grind_dial, skill: turn_cw}
  finer: {control: grind_dial, skill: turn_ccw}
  press_cups: {control: cups_key}
  press_start: {control: start_key}
features:
  grind:
    - {actions: [coarser, finer], variable: grind, effect: {coarser: next, finer: prev}}
  amount:
    - {actions: [press_cups], variable: amount, effect: next}
  start:
    - {actions: [press_start], variable: running, effect: toggle}
"""
GRINDER_MANUAL = """GRIND dial: nine clicks, 1 (finest) to 9 (coarsest).
AMOUNT: the cups of seeds in the hopper, 1C, 2C, 4C or 6C.

 Mark | Result
 -----+-----------------------
  1   | dust-fine (finest)
  9   | cracked (coarsest)
"""


def test_ends_named_by_the_manuals_superlatives() -> None:
    """1 is the finest grind, the lowest number: the manual's "(finest)" / "(coarsest)" say
    which end a superlative is, and an ordinal counts in from it (goal_marked_ends)."""
    assert _goal(GRINDER, "The coarsest grind, please.", GRINDER_MANUAL) == {"grind": 9}
    assert _goal(GRINDER, "Use the finest setting.", GRINDER_MANUAL) == {"grind": 1}
    assert _goal(GRINDER, "The second finest setting.", GRINDER_MANUAL) == {"grind": 2}
    assert _goal(GRINDER, "The third coarsest setting.", GRINDER_MANUAL) == {"grind": 7}


def test_a_bare_number_waits_until_the_others_are_placed() -> None:
    """ "six cups … at setting four": once the cups took the amount, the four has one home
    left (goal_assign)."""
    said = "Six cups of pepper at setting four."
    assert _goal(GRINDER, said, GRINDER_MANUAL) == {"amount": "6", "grind": 4}


def test_mill_opening_an_order_starts_it() -> None:
    """ "Mill two cups" opens with the doing, as "Grind …" does (goal_text)."""
    said = "Mill two cups of cumin at setting three."
    assert _goal(GRINDER, said, GRINDER_MANUAL) == {"amount": "2", "grind": 3, "running": "on"}


EGG_TIMER = """
appliance: {id: timer_x, category: kitchen_timer, name: "Tikk E3 kitchen timer", brand: T}
controls:
  - {id: ch_key, kind: button, label: "CH"}
  - {id: sound_key, kind: button, label: "SOUND"}
variables:
  channel: {type: discrete, values: [c1, c2], show: {c1: "C1", c2: "C2"}}
  sound: {type: discrete, values: [loud, soft, mute], show: {loud: "L", soft: "S", mute: "M"}}
actions:
  press_ch: {control: ch_key}
  press_sound: {control: sound_key}
features:
  channel:
    - {actions: [press_ch], variable: channel, effect: next}
  sound:
    - {actions: [press_sound], variable: sound, effect: next}
"""
EGG_MANUAL = "Press CH to choose the countdown C1 or C2. Each countdown rings on its own."


def test_an_ordinal_before_the_noun_a_code_letter_abbreviates() -> None:
    """C1 / C2 are the countdowns: "the second countdown" is C2 (goal_ordinals)."""
    assert _goal(EGG_TIMER, "Pick the second countdown.", EGG_MANUAL) == {"channel": "c2"}


def test_a_quiet_sound_and_a_sound_switched_off() -> None:
    """A sound's levels LOUD / SOFT / MUTE: "quiet" is SOFT, "the beeping off" MUTE — a
    volume by the sound's own name (goal_vocab, goal_mute)."""
    assert _goal(EGG_TIMER, "Use the quiet alarm.", EGG_MANUAL) == {"sound": "soft"}
    assert _goal(EGG_TIMER, "Turn the beeping off.", EGG_MANUAL) == {"sound": "mute"}


CAMERA = """
appliance: {id: cam_x, category: document_camera, name: "Vizo D4 document camera", brand: V}
controls:
  - {id: ak_key, kind: button, label: "AUTO TILT"}
  - {id: up_dial, kind: dial, label: "V-TILT"}
  - {id: side_dial, kind: dial, label: "H-TILT"}
  - {id: vol_dial, kind: dial, label: "VOL"}
  - {id: look_key, kind: button, label: "LOOK"}
variables:
  auto_tilt: {type: discrete, values: ["off", "on"]}
  v_tilt: {type: numeric, ranges: [[-10, 10, 1]], initial: 0}
  h_tilt: {type: numeric, ranges: [[-10, 10, 1]], initial: 0}
  volume: {type: numeric, ranges: [[0, 15, 1]], initial: 5}
  look: {type: discrete, values: [natural, bright, text]}
actions:
  press_ak: {control: ak_key}
  v_down: {control: up_dial, skill: turn_ccw}
  v_up: {control: up_dial, skill: turn_cw}
  h_down: {control: side_dial, skill: turn_ccw}
  h_up: {control: side_dial, skill: turn_cw}
  louder: {control: vol_dial, skill: turn_cw}
  quieter: {control: vol_dial, skill: turn_ccw}
  press_look: {control: look_key}
features:
  auto_tilt:
    - {actions: [press_ak], variable: auto_tilt, effect: toggle}
  v_tilt:
    - {actions: [v_down, v_up], variable: v_tilt, effect: {v_down: prev, v_up: next}}
  h_tilt:
    - {actions: [h_down, h_up], variable: h_tilt, effect: {h_down: prev, h_up: next}}
  volume:
    - {actions: [louder, quieter], variable: volume, effect: {louder: next, quieter: prev}}
  look:
    - {actions: [press_look], variable: look, effect: next}
"""


def test_letting_it_do_a_thing_by_itself_turns_its_auto_switch_on() -> None:
    """ "let the camera correct the vertical tilt by itself" is AUTO TILT on, the vertical
    tilt left to it (goal_left_to_it)."""
    said = "Let the camera correct the vertical tilt by itself, and the horizontal tilt at 4."
    assert _goal(CAMERA, said) == {"auto_tilt": "on", "h_tilt": 4}


def test_the_sound_is_the_one_volume() -> None:
    """No setting is named for sound: "the sound" is the volume (goal_view)."""
    assert _goal(CAMERA, "Turn the sound down to 2.") == {"volume": 2}


def test_fully_says_how_far_and_names_no_value() -> None:
    """ "fully" is no FULL (a synonym of BRIGHT): "the tilt fully to the left, minus ten"."""
    said = "Put the horizontal tilt fully to the left, minus ten."
    assert _goal(CAMERA, said) == {"h_tilt": -10}


LAMP = """
appliance: {id: lamp_x, category: reading_lamp, name: "Lumo R3 reading lamp", brand: L}
controls:
  - {id: light_key, kind: button, label: "LIGHT"}
  - {id: timer_key, kind: button, label: "TIMER"}
variables:
  light: {type: discrete, values: ["off", "on"]}
  timer: {type: discrete, values: ["off", "15", "30", "60"]}
actions:
  press_light: {control: light_key}
  press_timer: {control: timer_key}
features:
  light:
    - {actions: [press_light], variable: light, effect: toggle}
  timer:
    - {actions: [press_timer], variable: timer, effect: next}
"""


def test_not_letting_a_thing_go_out_keeps_it_on() -> None:
    """ "don't let the light go out" denies its going out: the light stays on (goal_let)."""
    assert _goal(LAMP, "Don't let the light go out.") == {"light": "on"}
    assert _goal(LAMP, "Never let the light switch off.") == {"light": "on"}
    assert _goal(LAMP, "Don't switch the light on.") == {"light": "off"}


RADIO = """
appliance: {id: radio_x, category: clock_radio, name: "Tempo C2 clock radio", brand: T}
controls:
  - {id: mute_key, kind: button, label: "MUTE"}
  - {id: chime_key, kind: button, label: "STARTUP TONE"}
  - {id: dim_key, kind: button, label: "AUTO DIM"}
variables:
  mute: {type: discrete, values: ["off", "on"]}
  startup_tone: {type: discrete, values: ["off", "on"], label: "STARTUP TONE"}
  auto_dim: {type: discrete, values: ["off", "on"]}
actions:
  press_mute: {control: mute_key}
  press_chime: {control: chime_key}
  press_dim: {control: dim_key}
features:
  mute:
    - {actions: [press_mute], variable: mute, effect: toggle}
  startup_tone:
    - {actions: [press_chime], variable: startup_tone, effect: toggle}
  auto_dim:
    - {actions: [press_dim], variable: auto_dim, effect: toggle}
"""


def test_a_sound_word_after_anothers_name_is_no_mute() -> None:
    """ "the startup sound off" is STARTUP TONE off; "sound" (MUTE's group) said after
    another switch's own word is that switch's name, not the mute (goal_switches)."""
    assert _goal(RADIO, "Turn the startup sound off.") == {"startup_tone": "off"}


def test_never_letting_it_go_into_a_mode_turns_that_mode_off() -> None:
    """ "never let it go into the dim mode", "don't let it dim automatically": AUTO DIM off
    (goal_let; a refused letting hands no choice over, goal_left_to_it)."""
    assert _goal(RADIO, "Never let it go into the dim mode.") == {"auto_dim": "off"}
    assert _goal(RADIO, "Don't let it dim automatically.") == {"auto_dim": "off"}


NOISE = """
appliance: {id: noise_x, category: sound_machine, name: "Hush N2 sound machine", brand: H}
controls:
  - {id: vol_dial, kind: dial, label: "VOL"}
  - {id: sound_key, kind: button, label: "SOUND"}
variables:
  volume: {type: numeric, ranges: [[1, 12, 1]], initial: 5}
  track: {type: discrete, values: [rain, surf, fan]}
actions:
  louder: {control: vol_dial, skill: turn_cw}
  softer: {control: vol_dial, skill: turn_ccw}
  press_sound: {control: sound_key}
features:
  volume:
    - {actions: [louder, softer], variable: volume, effect: {louder: next, softer: prev}}
  track:
    - {actions: [press_sound], variable: track, effect: next}
"""


def test_as_quiet_as_it_goes_is_the_volumes_bottom() -> None:
    """ "as quiet as it goes", "the loudest it goes" measure loudness: the ends of the one
    VOLUME (goal_scale_kinds)."""
    assert _goal(NOISE, "Surf, as quiet as it goes.") == {"track": "surf", "volume": 1}
    assert _goal(NOISE, "Rain on its loudest setting.") == {"track": "rain", "volume": 12}


FLOSSER = """
appliance: {id: floss_x, category: water_flosser, name: "Jetta W5 water flosser", brand: J}
controls:
  - {id: mode_key, kind: button, label: "MODE"}
  - {id: level_key, kind: button, label: "LEVEL"}
  - {id: start_key, kind: button, label: "START"}
variables:
  mode: {type: discrete, values: [clean, massage, soft]}
  level: {type: numeric, ranges: [[1, 10, 1]], initial: 5}
  running: {type: discrete, values: ["off", "on"]}
actions:
  press_mode: {control: mode_key}
  press_level: {control: level_key}
  press_start: {control: start_key}
features:
  mode:
    - {actions: [press_mode], variable: mode, effect: next}
  level:
    - {actions: [press_level], variable: level, effect: next}
  start:
    - {actions: [press_start], variable: running, effect: toggle}
"""


def test_a_verb_before_a_kind_word_is_a_name() -> None:
    """ "Clean mode at level 8" names the CLEAN mode; "Clean my teeth" still starts (goal_start)."""
    assert _goal(FLOSSER, "Clean mode at level 8.") == {"mode": "clean", "level": 8}
    assert _goal(FLOSSER, "Clean my teeth at level 8.")["running"] == "on"


def test_getting_it_ready_is_no_start() -> None:
    """ "Get it ready at level 6" prepares it; "get it going" starts it (goal_start)."""
    assert _goal(FLOSSER, "Get it ready at level 6 in massage mode.") == {
        "level": 6,
        "mode": "massage",
    }
    assert _goal(FLOSSER, "Get it going at level 6.")["running"] == "on"


INFLATOR = """
appliance: {id: pump_x, category: tyre_inflator, name: "Aero P3 inflator", brand: A}
controls:
  - {id: up_key, kind: button, label: "+"}
  - {id: down_key, kind: button, label: "-"}
  - {id: go_key, kind: button, label: "GO"}
variables:
  target: {type: numeric, unit: psi, ranges: [[5, 60, 1]], initial: 30}
  running: {type: discrete, values: ["off", "on"]}
actions:
  press_up: {control: up_key}
  press_down: {control: down_key}
  press_go: {control: go_key}
features:
  target:
    - actions: [press_up, press_down]
      variable: target
      effect: {press_up: next, press_down: prev}
  start:
    - {actions: [press_go], variable: running, effect: toggle}
"""


def test_pump_and_inflate_open_an_order() -> None:
    """ "Pump the tyres to 36 psi", "Inflate the ball …" ask for the work (goal_text)."""
    assert _goal(INFLATOR, "Pump the tyres to 36 psi.") == {"target": 36, "running": "on"}
    assert _goal(INFLATOR, "Inflate the ball to 9 psi.") == {"target": 9, "running": "on"}


SCENES = """
appliance: {id: light_x, category: ceiling_light, name: "Lumo C5 ceiling light", brand: L}
controls:
  - {id: down_key, kind: touch, label: "DIM -"}
  - {id: up_key, kind: touch, label: "DIM +"}
  - {id: film_key, kind: touch, label: "FILM"}
variables:
  brightness: {type: numeric, unit: "%", ranges: [[10, 100, 10]], initial: 100}
  colour: {type: discrete, values: ["2700", "4000", "6500"], initial: "4000"}
actions:
  press_down: {control: down_key}
  press_up: {control: up_key}
  press_film: {control: film_key}
features:
  brightness:
    - actions: [press_down, press_up]
      variable: brightness
      effect: {press_down: prev, press_up: next}
  film:
    - {actions: [press_film], variable: brightness, effect: {to: 20}, set: {colour: "2700"}}
"""


def test_a_scene_keys_own_quantity_yields_to_the_one_said() -> None:
    """ "Film scene, but at forty percent": the scene's colour, at the brightness said — the
    key's 20 % only when nothing else is said of the brightness (goal_presets)."""
    said = "Film scene, but a bit brighter: forty percent."
    assert _goal(SCENES, said) == {"brightness": 40, "colour": "2700"}
    assert _goal(SCENES, "The film scene, please.") == {"brightness": 20, "colour": "2700"}


def test_a_marked_end_said_of_another_setting_is_that_ones() -> None:
    """The manual marks the grind's 9 (coarsest), yet "the coarsest amount" would be no grind:
    the word after the superlative names another setting (goal_marked_ends)."""
    assert "grind" not in _goal(GRINDER, "The coarsest amount.", GRINDER_MANUAL)
