"""An on/off setting the display legend names only while it is off ("SILENT  sound switched
off"), on a small manual written in our own words: it starts on and shows the word while off."""

from __future__ import annotations

from apbot.model.validate import check_model
from apbot.read import read_manual

SCALE = """LIBRA KS-7 KITCHEN SCALE
Instructions

CONTROL PANEL

  No.  Key            Press briefly                     Press and hold (3 s)
  ---  -------------  --------------------------------  --------------------------
  1    ON/OFF         switches the scale on or off      --
  2    TARE           sets the weight to zero           sound off / on
  3    UNIT           grams or ounces                   --

DISPLAY
  0 g          the weight on the platform
  SILENT       sound switched off
  LO           battery low

Each touch of a key gives a short beep. To silence it, hold TARE for 3 seconds.
"""
SCALE_ACTIONS = ["press_on_off", "press_tare", "hold_tare", "press_unit"]


def test_a_toggle_the_legend_shows_only_while_off_starts_on() -> None:
    model = read_manual(SCALE, SCALE_ACTIONS).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    held = [f for f, steps in model.features.items() if steps[0].actions == ["hold_tare"]]
    assert held
    tone = model.variables[model.features[held[0]][0].variable]
    assert tone.values == ["on", "off"] and tone.initial == "on"
    assert tone.show == {"on": "", "off": "SILENT"}


def test_a_legend_line_saying_other_things_are_off_changes_nothing() -> None:
    text = SCALE.replace("SILENT       sound switched off", "CAL          calibrating. Keys off")
    model = read_manual(text, SCALE_ACTIONS).model
    held = [f for f, steps in model.features.items() if steps[0].actions == ["hold_tare"]]
    assert held
    tone = model.variables[model.features[held[0]][0].variable]
    assert tone.values == ["off", "on"]


# a held key read with no setting of its own: the legend's off word and a sentence holding the
# key name the same thing
STEAMER = """VAPO S-3 FOOD STEAMER
Instructions

  Key / element        What it does
  -------------------  ---------------------------------------------------------------
  ON/OFF               Switches the steamer on or off.
  MENU                 Each press selects the next menu in the order
                       FISH → RICE → VEG → EGGS → FISH. Hold MENU for 3 seconds to silence
                       the beeper.
  START                Starts the selected menu; press again to stop.

  Display symbols
  ---------------
  FISH        the selected menu
  QUIET       the beeper is silenced
"""
STEAMER_ACTIONS = ["press_on_off", "press_menu", "hold_menu", "press_start"]


def test_a_held_key_with_no_setting_of_its_own_switches_what_the_off_word_names() -> None:
    model = read_manual(STEAMER, STEAMER_ACTIONS).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    held = [f for f, steps in model.features.items() if steps[0].actions == ["hold_menu"]]
    assert held
    beeper = model.variables[model.features[held[0]][0].variable]
    assert beeper.values == ["on", "off"] and beeper.initial == "on"
    assert beeper.show == {"on": "", "off": "QUIET"}


# a legend word whose meaning is another thing and only mentions a setting going off: the
# setting is still an ordinary toggle that starts off
OVEN = """BRIO K-5 MINI OVEN
Instructions

CONTROL PANEL

  No.  Key            Press briefly
  ---  -------------  --------------------------------
  1    POWER          switches the oven on or off
  2    LAMP           oven lamp on or off
  3    FAN            convection fan on or off

DISPLAY
  180          the temperature
  ECO          energy saving, lamp off after 2 min

Press LAMP to switch the oven lamp on or off. The lamp is off when the oven is switched on.
"""


def test_a_legend_word_naming_something_else_leaves_the_toggle_alone() -> None:
    model = read_manual(OVEN, ["press_power", "press_lamp", "press_fan"]).model
    lamp = model.variables["lamp"]
    assert lamp.show != {"on": "", "off": "ECO"}
    assert lamp.initial != "on"


# a held key whose own setting copies another's list, in a sentence that only mentions the beep:
# the hold keeps its setting (the beep is switched by another key)
HEATER = """AERO H-2 HEATER FAN
Instructions

CONTROL PANEL

  Key          What it does
  -----------  ---------------------------------------------
  POWER        switches the heater on or off
  SPEED        fan speed: LOW, MED or HIGH
  NIGHT        hold 3 s: night speed LOW, MED or HIGH

Hold NIGHT for 3 seconds to choose the night speed; each beep confirms a change.

DISPLAY
  88           the room temperature
  SILENT       beep switched off
"""


def test_a_hold_that_only_mentions_the_muted_thing_keeps_its_setting() -> None:
    model = read_manual(HEATER, ["press_power", "press_speed", "hold_night"]).model
    (steps,) = [s for s in model.features.values() if s[0].actions == ["hold_night"]]
    assert model.variables[steps[0].variable].values == ["low", "med", "high"]


# a fault code in the troubleshooting list saying a thing will not start is no display word
# of that thing's off state: the toggle stays an ordinary one
COOKER = """CALDA S-1 SOUS VIDE
Instructions

CONTROL PANEL

  Key          What it does
  -----------  ---------------------------------------------
  POWER        switches the cooker on or off
  PUMP         circulation pump on or off
  START        starts heating

Press PUMP to switch the circulation pump on or off. The pump is off when you switch on.

TROUBLESHOOTING
  E2           pump will not start: clean the impeller
  E3           water too low
"""


def test_a_fault_code_is_no_off_word() -> None:
    model = read_manual(COOKER, ["press_power", "press_pump", "press_start"]).model
    pump = model.variables["pump"]
    assert pump.show != {"on": "", "off": "E2"}
    assert pump.initial != "on"
