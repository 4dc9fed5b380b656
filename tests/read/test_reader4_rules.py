"""Rules found on the nine dev categories' read beliefs (reader4 round): each on a small manual
or sentence of our own, in the wording a real manual of any appliance might use."""

from __future__ import annotations

from apbot.model.domain import all_values
from apbot.read import read_manual
from apbot.read.value_steps import find_step


def test_by_one_step_is_no_step_of_one_second() -> None:
    # "by one step" is a click of the dial, not "by one s(econd)"
    assert find_step("Every click moves the setting by one step.") is None
    assert find_step("Each turn changes the time by 1 s.") == (1.0, "s")
    assert find_step("Each press changes the time by 5 minutes.") == (5.0, "min")


DRYER = """# PEBBLE DB-2 Dish Dryer

## Controls

| Control | Use |
|---|---|
| **MODE** knob | Chooses DRY or HEAT. |
| **TIME** knob | Sets the drying time. |
| **START** | Starts the cycle. |

## Setting the time

Turn the TIME knob; each click changes the time by one step. You can dry for 10 – 40 min.
"""


def test_a_dial_of_one_step_per_click_keeps_minute_steps() -> None:
    model = read_manual(
        DRYER, ["turn_mode_cw", "turn_time_cw", "turn_time_ccw", "press_start"]
    ).model
    time = next(v for name, v in model.variables.items() if "time" in name)
    assert len(all_values(time)) <= 31  # minutes (or coarser), never 1,801 seconds


# A read belief of a water dispenser: the reader names each switch after its key, so the pour
# under way is a switch `dispense` toggled by DISPENSE, beside a GENTLE POUR switch.
URN = """
appliance: {id: urn_1, category: urn, name: "Kessel HW-5 hot water urn", brand: Kessel}
controls:
  - {id: gentle_button, kind: button, label: "GENTLE POUR"}
  - {id: size_button, kind: button, label: "SIZE"}
  - {id: dispense_button, kind: button, label: "DISPENSE"}
variables:
  gentle_pour: {type: discrete, values: ["off", "on"], label: "GENTLE POUR"}
  size: {type: discrete, values: [glass, jug], label: "SIZE"}
  dispense: {type: discrete, values: ["off", "on"], label: "DISPENSE"}
actions:
  press_gentle: {control: gentle_button}
  press_size: {control: size_button}
  press_dispense: {control: dispense_button}
features:
  gentle_pour:
    - {actions: [press_gentle], variable: gentle_pour, effect: toggle}
  size:
    - {actions: [press_size], variable: size, effect: next}
  dispense:
    - {actions: [press_dispense], variable: dispense, effect: toggle}
"""


def test_the_verb_of_a_key_named_pour_starts_it() -> None:
    from apbot.model.load import loads_model
    from apbot.read.goal import parse_instruction

    urn = loads_model(URN)
    assert parse_instruction(urn, "Pour me a jug of hot water.") == {
        "size": "jug",
        "dispense": "on",
    }
    # the operation's verb is not the GENTLE POUR switch, which its own words still name
    assert parse_instruction(urn, "Choose the glass and start pouring.") == {
        "size": "glass",
        "dispense": "on",
    }
    assert parse_instruction(urn, "Turn on the gentle pour.") == {"gentle_pour": "on"}


COOKER = """# TAVOLA MC-6 Multicooker

## Controls

The programme names are printed round the PROGRAM dial: RICE, SOUP, STEW, YOGURT, PORRIDGE.

| Control | Use |
|---|---|
| **PROGRAM** dial | Chooses the programme. |
| **COOK TIME** | Changes the cooking time. |
| **START** | Starts cooking. |

## Cooking time

With SOUP, STEW and PORRIDGE you can choose the cooking time yourself; the other programmes
time themselves. Press COOK TIME, then turn the PROGRAM dial to change the time, from 0:20 to
4:00.
"""


def test_menus_named_beside_a_time_key_are_not_its_values() -> None:
    # the dial's programmes the time applies to are no values of the time
    actions = ["turn_program_cw", "turn_program_ccw", "press_cook_time", "press_start"]
    model = read_manual(COOKER, actions).model
    assert "stew" in all_values(model.variables["program"])
    assert model.variables["cook_time"].type == "time"


PURIFIER = """BREEZA AP-7 Air Purifier

CONTROL PANEL
FAN        Changes the fan speed: LOW, MID, HIGH.
TIMER      Sets the off-timer, 1 to 8 hours, one hour per press. Press and hold for
           2 seconds to turn the beep on or off.
"""


def test_holding_a_key_to_switch_something_on_or_off_is_that_switch() -> None:
    from apbot.read.goal import parse_instruction

    actions = ["press_fan", "press_timer", "hold_timer"]
    model = read_manual(PURIFIER, actions).model
    beep = model.variables["beep"]
    assert all_values(beep) == ["off", "on"]
    assert beep.label == "BEEP"  # its own name, so "the timer" does not name it
    held = [s for steps in model.features.values() for s in steps if "hold_timer" in s.actions]
    assert [s.variable for s in held] == ["beep"]
    assert parse_instruction(model, "Turn off the beep.") == {"beep": "off"}


HEATER = """ORBIT FH-3 Fan Heater

CONTROL PANEL
HEAT       Changes the heat level: LOW, MEDIUM, HIGH. Holding HEAT switches the night
           mode (see below).
SWING      Turns the oscillation on and off.
"""


def test_holding_a_key_switches_what_its_legend_says() -> None:
    model = read_manual(HEATER, ["press_heat", "hold_heat", "press_swing"]).model
    held = [s for steps in model.features.values() for s in steps if "hold_heat" in s.actions]
    assert [s.variable for s in held] == ["night_mode"]
    assert all_values(model.variables["night_mode"]) == ["off", "on"]


GRILL = """
appliance: {id: grill_1, category: contact_grill, name: "Presso CG-2 contact grill", brand: Presso}
controls:
  - {id: heat_button, kind: button, label: "HEAT"}
  - {id: tone_button, kind: button, label: "TONE"}
variables:
  heat: {type: discrete, values: [low, medium, high], label: "HEAT"}
  tone: {type: discrete, values: ["off", "on"], label: "TONE", initial: "on"}
actions:
  press_heat: {control: heat_button}
  press_tone: {control: tone_button}
features:
  heat:
    - {actions: [press_heat], variable: heat, effect: next}
  tone:
    - {actions: [press_tone], variable: tone, effect: toggle}
"""

GRILL_MANUAL = """# Presso CG-2

| Key | Use |
|---|---|
| HEAT | Changes the plate heat. |
| TONE | Chime when the sandwich is ready |
"""


def test_a_legend_that_names_what_a_switch_is_names_it_when_said_without() -> None:
    from apbot.model.load import loads_model
    from apbot.read.goal import parse_instruction

    grill = loads_model(GRILL)
    said = "High heat, and without the ready chime please."
    assert parse_instruction(grill, said, GRILL_MANUAL) == {"heat": "high", "tone": "off"}
