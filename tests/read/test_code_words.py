"""Letter codes the manual spells out as words, each on a small manual written in our own words:
a lamp legend listing the codes and then their words in the same order, and a line per code
("S - small cubes"). The value is the word the user says; the display keeps the code."""

from __future__ import annotations

from apbot.model.validate import check_model
from apbot.read import read_manual

# a legend line: the codes, then their words in brackets in the same order
LEGEND = """FROSTA CUBE-3 ICE MACHINE
Instructions

CONTROL PANEL

  SIZE      next cube size: S → M → L → S
  POWER     switches the machine on or off

Lamps
  S / M / L    cube size chosen (small, medium, large)
  RUN          making ice

Press SIZE until the lamp of the size you want lights, then press POWER.
"""
LEGEND_ACTIONS = ["press_size", "press_power"]

# a line per code, the code first and its meaning after it
DEFINITIONS = """LUMO TANK LIGHT T-40
User guide

KEYS
  TINT      which LEDs light: R+G → R → G → R+G
  ON/OFF    light on or off

Tint
  Press TINT until the lamp of the tint you want lights:
    R+G   red and green together (the factory setting)
    R     red LEDs only
    G     green LEDs only, for plants
"""
DEFINITIONS_ACTIONS = ["press_tint", "press_on_off"]


def test_codes_a_legend_spells_out_become_words_and_the_display_shows_the_codes() -> None:
    model = read_manual(LEGEND, LEGEND_ACTIONS).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    size = model.variables["size"]
    assert size.values == ["small", "medium", "large"]
    assert size.show == {"small": "S", "medium": "M", "large": "L"}


def test_a_line_per_code_names_each_code_by_the_words_it_abbreviates() -> None:
    model = read_manual(DEFINITIONS, DEFINITIONS_ACTIONS).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    tint = model.variables["tint"]
    assert tint.values == ["red and green", "red", "green"]
    assert tint.show == {"red and green": "R+G", "red": "R", "green": "G"}


def test_codes_whose_lines_do_not_abbreviate_words_stay_codes() -> None:
    text = LEGEND.replace("(small, medium, large)", "(see the table)")
    model = read_manual(text, LEGEND_ACTIONS).model
    assert model.variables["size"].values == ["s", "m", "l"]


def test_three_letter_codes_are_words_users_say_and_stay() -> None:
    text = (
        LEGEND.replace("S → M → L → S", "ECO → MAX → ECO")
        .replace(
            "S / M / L    cube size chosen (small, medium, large)",
            "ECO / MAX    (economy, maximum)",
        )
        .replace("SIZE ", "MODE ")
        .replace("size you want", "mode you want")
    )
    model = read_manual(text, ["press_mode", "press_power"]).model
    assert model.variables["mode"].values == ["eco", "max"]


# letter codes that are a fault's (under a troubleshooting heading) or the models' ("Models
# S / M / L") do not spell out a setting's codes
ICE = """FRIO I-2 ICE MAKER
Instructions

CONTROL PANEL

  Key          What it does
  -----------  ---------------------------------------------
  POWER        switches the ice maker on or off
  SIZE         cube size S, M or L

MODELS
Models S / M / L (standard, maxi, large tank).

TROUBLESHOOTING
  S  Sensor fault: call service.
  M  Motor blocked: remove the ice.
  L  Low water: fill the tank.
"""


def test_fault_codes_and_model_codes_are_no_setting_words() -> None:
    model = read_manual(ICE, ["press_power", "press_size"]).model
    assert model.variables["size"].values == ["s", "m", "l"]
    without_models = ICE.replace("Models S / M / L (standard, maxi, large tank).", "")
    model = read_manual(without_models, ["press_power", "press_size"]).model
    assert model.variables["size"].values == ["s", "m", "l"]


# a run of arrows glossing each code in brackets: the codes need not abbreviate the words
GLOSSED = """NOVA CL-2 bedside clock
Instructions

KEYS
  GLOW      display brightness
  SIDE      which side the text sits on

Press GLOW to change the brightness:
    g2 (bright) → g1 (dim) → g0 (dark) → g2 …

Press SIDE to move the text:
    SIDE L (left) → SIDE M (middle) → SIDE R (right) → SIDE L …
"""
GLOSSED_ACTIONS = ["press_glow", "press_side"]


def test_codes_glossed_in_brackets_along_their_arrows_become_the_glossed_words() -> None:
    model = read_manual(GLOSSED, GLOSSED_ACTIONS).model
    values = {tuple(v.values or []) for v in model.variables.values()}
    assert ("bright", "dim", "dark") in values
    assert ("left", "middle", "right") in values


# two keys stepping through the same codes, each glossed its own way: which is which is open
TWO_GLOSSES = """NOVA CL-3 bedside fan clock
Instructions

KEYS
  GLOW      display brightness
  FAN       fan speed

Press FAN to change the fan speed:
    F1 (gentle) → F2 (breeze) → F3 (storm) → F1 …

Press GLOW to change the brightness:
    F1 (dim) → F2 (soft) → F3 (full) → F1 …
"""


def test_the_same_codes_glossed_apart_on_two_lines_stay_codes() -> None:
    model = read_manual(TWO_GLOSSES, ["press_glow", "press_fan"]).model
    assert all("gentle" not in (v.values or []) for v in model.variables.values())
