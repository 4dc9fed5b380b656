"""Narrowings of the 7 December rules (parse30, settings30) where they misfired on sentences and
manuals other than the ones they were written for. Models, manuals and sentences are written
for these tests; none is a suite appliance's."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read import read_manual
from apbot.read.goal import parse_instruction

METER = """
appliance: {id: meter_r, category: bench_meter, name: "Voltix C3 bench meter", brand: Voltix}
controls:
  - {id: dial, kind: knob, label: "FUNCTION"}
  - {id: hold_key, kind: button, label: "HOLD"}
  - {id: light_key, kind: button, label: "DISPLAY"}
  - {id: apo_key, kind: button, label: "APO"}
variables:
  function: {type: discrete, values: ["off", volts, ohms], wrap: false}
  hold: {type: discrete, values: ["off", "on"], show: {"off": "", "on": "H"}}
  auto_off: {type: discrete, values: ["on", "off"], show: {"on": "APO", "off": ""}}
actions:
  turn_right: {control: dial}
  press_hold: {control: hold_key}
  press_light: {control: light_key}
  press_apo: {control: apo_key}
features:
  function:
    - {actions: [turn_right], variable: function, effect: next}
  hold:
    - {actions: [press_hold], variable: hold, effect: toggle}
  auto_off:
    - {actions: [press_apo], variable: auto_off, effect: toggle}
display:
  idle: "{function}"
"""

COOKER = """
appliance: {id: cooker_r, category: rice_cooker, name: "Kome R1 rice cooker", brand: Kome}
controls:
  - {id: prog_key, kind: button, label: "PROGRAM"}
  - {id: cup_key, kind: button, label: "CUPS"}
variables:
  program: {type: discrete, values: ["A", "B", "C"], show: {A: "P-A", B: "P-B", C: "P-C"}}
  cups: {type: discrete, values: ["1/2", "1", "2", "3"], show: "{value} CUP"}
actions:
  press_prog: {control: prog_key}
  press_cups: {control: cup_key}
features:
  program:
    - {actions: [press_prog], variable: program, effect: next}
  cups:
    - {actions: [press_cups], variable: cups, effect: next}
display:
  idle: "{program} {cups}"
"""


def _goal(model_text: str, said: str) -> dict[str, object]:
    return dict(parse_instruction(loads_model(model_text, check=False), said, ""))


def test_holding_a_key_named_display_is_no_held_reading() -> None:
    """ "hold the display button": a key held down, not the reading frozen."""
    assert "hold" not in _goal(METER, "volts, then press and hold the display button")
    assert _goal(METER, "volts and hold the reading")["hold"] == "on"


def test_a_thing_left_out_does_not_stop_the_switching_off() -> None:
    """ "without the lid" leaves out a lid; the switching off itself is still asked for."""
    assert _goal(METER, "ohms without the lid and let it turn itself off")["auto_off"] == "on"
    assert _goal(METER, "ohms, without the meter turning itself off")["auto_off"] == "off"


def test_a_lettered_programme_shown_with_a_prefix_is_named_by_its_letter() -> None:
    """PROGRAM A shown "P-A": "program A" names it; the article "a" alone still does not."""
    assert _goal(COOKER, "program A, two cups")["program"] == "A"
    assert "program" not in _goal(COOKER, "a cup of rice, two cups")


RADIO = """
Tono R5 table radio

  Controls: ⏻   [BT] [FM]   VOLUME knob

LISTENING TO A PHONE

1. Press BT. The display shows BT and the radio waits for your phone.
2. Turn the VOLUME knob to a comfortable level (0 to 30).

LISTENING TO THE RADIO

1. Press FM.
2. Turn the VOLUME knob to a comfortable level.
"""
RADIO_ACTIONS = ["press_power", "press_bt", "press_fm", "turn_volume_cw", "turn_volume_ccw"]


def test_a_key_that_only_selects_is_not_lent_the_dial() -> None:
    """The only range the VOLUME knob has is the one after "Press BT": it is the knob's own,
    so BT takes no setting turned by the knob."""
    model = read_manual(RADIO, RADIO_ACTIONS).model
    bt = next(f for f in model.features.values() if f[0].actions == ["press_bt"])
    assert len(bt) == 1
    assert all(s.variable != "bt" or model.variables["bt"].type == "discrete" for s in bt)


# a stand mixer counting its speeds in levels; only the data table gives the motor's rpm
MIXER = """
Kneta K6 stand mixer

  Controls: ⏻   [SPEED ▲] [SPEED ▼]   [TIMER]

USING THE MIXER

Press SPEED ▲ or SPEED ▼ to choose one of the six speeds; the display shows the speed number.
Start at a low speed and raise it gradually.

TIMER sets the mixing time from 1 to 20 minutes.

TECHNICAL DATA

  | Item            | K6               |
  |-----------------|------------------|
  | Motor speed     | 60 – 250 rpm     |
  | Power           | 1000 W           |
"""


def test_a_speed_never_said_in_rpm_takes_no_rpm_range_from_the_data() -> None:
    """The SPEED keys are never said with rpm: the motor's 60–250 rpm is no range of theirs."""
    model = read_manual(
        MIXER, ["press_power", "press_speed_up", "press_speed_down", "press_timer"]
    ).model
    speed = model.variables["speed"]
    assert getattr(speed, "unit", "") != "rpm"
    assert all(r[1] < 60 for r in speed.ranges)  # type: ignore[union-attr]
