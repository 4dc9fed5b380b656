"""Sentences said to instruments (a bench meter, a darkroom timer, a rotor, a keyboard): the
parser rules of the 7 December parse30 session. Models, manual lines and sentences are written
for these tests; none is a suite appliance's."""

from __future__ import annotations

import pytest

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction
from apbot.read.goal_vocab import stem

METER = """
appliance: {id: meter_t, category: bench_meter, name: "Ohmix B2 bench meter", brand: Ohmix}
controls:
  - {id: dial, kind: knob, label: "FUNCTION"}
  - {id: sel_key, kind: button, label: "SEL"}
  - {id: range_key, kind: button, label: "RANGE"}
  - {id: hold_key, kind: button, label: "HOLD"}
  - {id: apo_key, kind: button, label: "APO"}
variables:
  function:
    type: discrete
    values: ["off", volts, ohms, microamps, amps]
    wrap: false
    show: {"off": "OFF", volts: "V", ohms: "Ω", microamps: "µA", amps: "A"}
  sub:
    type: discrete
    depends_on: function
    label: "SEL"
    cases: {ohms: [resistance, continuity, diode], microamps: [dc, ac], amps: [dc, ac]}
  range:
    type: discrete
    depends_on: function
    label: "RANGE"
    cases: {volts: [auto, 4V, 40V, 400V, 1000V], ohms: [auto, 400ohm, 4kohm]}
  hold: {type: discrete, values: ["off", "on"], show: {"off": "", "on": "H"}}
  auto_off: {type: discrete, values: ["on", "off"], show: {"on": "APO", "off": ""}}
actions:
  turn_right: {control: dial}
  press_sel: {control: sel_key}
  press_range: {control: range_key}
  press_hold: {control: hold_key}
  press_apo: {control: apo_key}
features:
  function:
    - {actions: [turn_right], variable: function, effect: next}
  sub:
    - {actions: [press_sel], variable: sub, effect: next}
  range:
    - {actions: [press_range], variable: range, effect: next}
  hold:
    - {actions: [press_hold], variable: hold, effect: toggle}
  auto_off:
    - {actions: [press_apo], variable: auto_off, effect: toggle}
display:
  idle: "{function} {sub} {range}"
"""

PRINTER = """
appliance: {id: printer_t, category: darkroom_timer, name: "Lumo D4 darkroom timer", brand: Lumo}
controls:
  - {id: up_key, kind: button, label: "▲"}
  - {id: step_key, kind: button, label: "STEP"}
variables:
  exposure:
    type: discrete
    values: ["2.0", "2.8", "4.0", "5.6", "8.0", "11", "16", "22", "32"]
    initial: "8.0"
    wrap: false
    show: "{value} s"
  step:
    type: discrete
    values: ["1/4", "1/2", "1"]
    show: {"1/4": "STEP 1/4", "1/2": "STEP 1/2", "1": "STEP 1"}
actions:
  press_up: {control: up_key}
  press_step: {control: step_key}
features:
  exposure:
    - {actions: [press_up], variable: exposure, effect: next}
  step:
    - {actions: [press_step], variable: step, effect: next}
display:
  idle: "{exposure} {step}"
"""

PRINTER_MANUAL = """
STEP  chooses how far apart the bands of a test sheet are: 1/4 stop, 1/2 stop or 1 stop.
"""

ROTOR = """
appliance: {id: rotor_t, category: lab_spinner, name: "Rotek S9 bench spinner", brand: Rotek}
controls:
  - {id: unit_key, kind: button, label: "rpm / x g"}
  - {id: up_key, kind: button, label: "SPEED ▲"}
variables:
  unit: {type: discrete, values: [rpm, rcf], show: {rpm: "rpm", rcf: "x g"}}
  speed:
    type: numeric
    depends_on: unit
    label: "SPEED"
    cases:
      rpm: {ranges: [[1000, 12000, 500]], initial: 6000}
      rcf: {ranges: [[200, 9000, 100]], initial: 3000}
actions:
  press_unit: {control: unit_key}
  press_up: {control: up_key}
features:
  unit:
    - {actions: [press_unit], variable: unit, effect: toggle}
  speed:
    - {actions: [press_up], variable: speed, effect: {add: 100}}
display:
  idle: "{speed} {unit}"
"""

KEYBOARD = """
appliance: {id: keys_t, category: party_speaker, name: "Singo P2 party speaker", brand: Singo}
controls:
  - {id: flat_key, kind: button, label: "♭"}
  - {id: sharp_key, kind: button, label: "♯"}
variables:
  key:
    type: discrete
    values: ["-3", "-2", "-1", "0", "+1", "+2", "+3"]
    initial: "0"
    wrap: false
    show: {"-3": "♭3", "-2": "♭2", "-1": "♭1", "0": "0", "+1": "♯1", "+2": "♯2", "+3": "♯3"}
actions:
  press_flat: {control: flat_key}
  press_sharp: {control: sharp_key}
features:
  key:
    - actions: [press_sharp, press_flat]
      variable: key
      effect: {press_sharp: next, press_flat: prev}
display:
  idle: "{key}"
"""


def _goal(model_text: str, said: str, manual: str = "") -> dict[str, object]:
    return dict(parse_instruction(loads_model(model_text, check=False), said, manual))


def test_numbers_are_not_stemmed() -> None:
    """1000 is no 100 with a doubled letter: "the 1000 V range" and "the 100 V range" differ."""
    assert stem("1000") == "1000"
    assert _goal(METER, "volts on the 1000 V range")["range"] == "1000V"


@pytest.mark.parametrize(
    ("said", "wanted"),
    [
        # a display code left a bare article ("µA" as "a") names nothing
        ("check a battery on the 40 V range", {"function": "volts", "range": "40V"}),
        # a sub-function's named choice tells the one dial position that has it
        ("test the kettle lead for continuity", {"function": "ohms", "sub": "continuity"}),
        # hyphenated hundreds before a unit
        ("the four-hundred-volt range", {"function": "volts", "range": "400V"}),
        # HOLD named by freezing what the display shows
        ("ohms, and freeze the display", {"function": "ohms", "hold": "on"}),
        (
            "measure amps in AC and hold the reading",
            {"function": "amps", "sub": "ac", "hold": "on"},
        ),
        # the automatic switch-off prevented without "stop … itself off"
        (
            "diode test, without it turning itself off",
            {"function": "ohms", "sub": "diode", "auto_off": "off"},
        ),
        (
            "volts, and keep it from powering down on its own",
            {"function": "volts", "auto_off": "off"},
        ),
    ],
)
def test_meter_sentences(said: str, wanted: dict[str, object]) -> None:
    assert _goal(METER, said) == wanted


def test_hold_as_a_verb_names_no_hold_switch() -> None:
    assert "hold" not in _goal(METER, "hold the dial and turn it to ohms")


@pytest.mark.parametrize(
    ("said", "wanted"),
    [
        ("an eleven-second exposure", {"exposure": "11"}),  # "{value} s": seconds
        ("the longest time it has", {"exposure": "32"}),  # the one open duration's end
        ("bands half a stop apart", {"step": "1/2"}),  # the manual counts stops in fractions
        ("quarter-of-a-stop steps", {"step": "1/4"}),
        ("a whole stop between the bands", {"step": "1"}),
    ],
)
def test_darkroom_sentences(said: str, wanted: dict[str, object]) -> None:
    assert _goal(PRINTER, said, PRINTER_MANUAL) == wanted


def test_a_fraction_of_a_change_is_no_step() -> None:
    assert "step" not in _goal(PRINTER, "half a stop longer than 8 seconds", PRINTER_MANUAL)


def test_half_an_hour_is_no_step() -> None:
    assert "step" not in _goal(PRINTER, "half a stop apart", "")  # no manual: stops unknown


@pytest.mark.parametrize(
    ("said", "wanted"),
    [
        ("spin at 4000 rpm", {"speed": 4000}),
        ("spin at five hundred g", {"unit": "rcf", "speed": 500}),
        ("two thousand times g", {"unit": "rcf", "speed": 2000}),
        ("seven and a half thousand revolutions a minute", {"speed": 7500}),
    ],
)
def test_rotor_sentences(said: str, wanted: dict[str, object]) -> None:
    assert _goal(ROTOR, said) == wanted


@pytest.mark.parametrize(
    ("said", "wanted"),
    [
        ("key up one", {"key": "+1"}),
        ("take the key down three semitones", {"key": "-3"}),
        ("the key as high as it goes", {"key": "+3"}),
        ("set the key to +2", {"key": "+2"}),
        ("key to 2", {"key": "+2"}),
        ("key to -2", {"key": "-2"}),
        ("key flat 2", {"key": "-2"}),
    ],
)
def test_keyboard_key(said: str, wanted: dict[str, object]) -> None:
    assert _goal(KEYBOARD, said) == wanted
