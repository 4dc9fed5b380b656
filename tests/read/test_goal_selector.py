"""An ON / AUTO / OFF selector standing for the power of a timer-switched appliance, and a
switch's word said in another setting's name — checked on a model and sentences written for
these tests (a garden-lighting timer no suite has)."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction

GARDEN = """
appliance: {id: garden_1, category: garden_light_timer, name: "Lumo GL-4 garden light", brand: L}
controls:
  - {id: mode_button, kind: button, label: "MODE"}
  - {id: clock_button, kind: button, label: "CLOCK"}
  - {id: dusk_button, kind: button, label: "DUSK"}
  - {id: up_button, kind: button, label: "+"}
  - {id: glow_button, kind: button, label: "GLOW"}
variables:
  mode:
    type: discrete
    values: ["on", auto, "off"]
    show: {"on": "ON", auto: "AUTO", "off": "OFF"}
  clock:
    type: time
    ranges: [["00:00:00", "23:59:00", 60]]
    initial: "12:00:00"
    format: "hh:mm"
    wrap: true
    label: "CLOCK"
  dusk:
    type: time
    ranges: [["00:00:00", "23:45:00", 900]]
    initial: "18:00:00"
    format: "hh:mm"
    wrap: true
    label: "DUSK ON"
  glow:
    type: discrete
    values: ["off", "on"]
    show: {"off": "", "on": "GLOW"}
  glow_time:
    type: discrete
    values: [1 min, 3 min, 5 min]
    label: "GLOW TIME"
  buzzer:
    type: discrete
    values: ["on", "off"]
    label: "BUZZER"
  battery_alert:
    type: numeric
    unit: "%"
    ranges: [[10, 30, 10]]
    initial: 20
    wrap: true
    label: "BATTERY ALERT"
actions:
  press_mode: {control: mode_button}
  press_clock: {control: clock_button}
  press_dusk: {control: dusk_button}
  press_up: {control: up_button}
  press_glow: {control: glow_button}
  hold_glow: {control: glow_button, skill: hold, seconds: 2}
  hold_mode: {control: mode_button, skill: hold, seconds: 2}
  hold_clock: {control: clock_button, skill: hold, seconds: 2}
features:
  mode:
    - {actions: [press_mode], variable: mode, effect: next}
  clock:
    - {actions: [press_clock]}
    - {actions: [press_up], variable: clock, effect: next}
  dusk:
    - {actions: [press_dusk]}
    - {actions: [press_up], variable: dusk, effect: next}
  glow:
    - {actions: [press_glow], variable: glow, effect: toggle}
  glow_time:
    - {actions: [hold_glow], variable: glow_time, effect: next}
  buzzer:
    - {actions: [hold_mode], variable: buzzer, effect: toggle}
  battery_alert:
    - {actions: [hold_clock], variable: battery_alert, effect: next}
display:
  idle: "{mode}"
"""


def _garden(instruction: str) -> dict[str, object]:
    return parse_instruction(loads_model(GARDEN), instruction)


def test_said_on_or_off_now_sets_the_selector() -> None:
    assert _garden("Switch it on right now and put the glow on.") == {"mode": "on", "glow": "on"}
    assert _garden("Keep the lights off for now, the glow on.")["mode"] == "off"
    assert _garden("Light off manually, please.")["mode"] == "off"


def test_a_state_said_with_a_negation_sets_nothing() -> None:
    """ "Don't switch it on": no state is asked of the selector (it once read ON)."""
    assert "mode" not in _garden("Don't switch it on, just put the glow on.")
    assert "mode" not in _garden("Please do not turn the lights on yet.")


def test_a_switching_time_sets_auto() -> None:
    assert _garden("Turn the lights on at 7 pm.") == {"dusk": "19:00:00", "mode": "auto"}
    assert _garden("Dusk on at half past eight in the evening.")["mode"] == "auto"


def test_on_before_an_article_is_a_preposition() -> None:
    # "on the timer" is its programmed times, "on the patio" a place: neither says it on now
    assert _garden("Keep the lights on the timer.") == {"mode": "auto"}
    assert _garden("Put the light on the patio table.").get("mode") != "on"


def test_a_switch_named_or_the_clock_is_no_selector() -> None:
    assert _garden("It's 10:20 now, set the clock, and switch on the glow.") == {
        "clock": "10:20:00",
        "glow": "on",
    }


def test_a_switch_word_in_another_settings_name_is_no_switch() -> None:
    """GLOW names the glow switch, but "the glow timer to 3 minutes" is GLOW TIME's name;
    "the battery alarm" is BATTERY ALERT's, so the BUZZER said off later stays off."""
    assert _garden("Set the glow timer to 3 minutes.") == {"glow_time": "3 min"}
    assert _garden("Battery alarm at 30 percent, and the buzzer off.") == {
        "battery_alert": 30,
        "buzzer": "off",
    }
    assert _garden("Glow on for 5 minutes.") == {"glow": "on", "glow_time": "5 min"}
    assert _garden("Switch on glow mode for 3 minutes.") == {
        "glow": "on",
        "glow_time": "3 min",
    }


def test_a_switch_said_on_after_its_compound_stays_the_switch() -> None:
    # "the glow light on for 5 minutes": GLOW's word before a noun, then its state said
    assert _garden("Switch the glow light on for 5 minutes.") == {
        "glow": "on",
        "glow_time": "5 min",
    }
    assert _garden("Put the glow timer on 5 minutes.") == {"glow_time": "5 min"}
