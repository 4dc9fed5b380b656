"""Positions a manual names outside its charts, and keys and codes that name their setting:
a legend line "2 FINE — …" or "stage 2 (FINE)" names a numbered position; a word every name
of a setting's codes shares ("… head") is the setting's kind; a key that steps a setting and
goes to one value when held names the setting; a code written with a leading zero is not the
same code as the number. Small models and manuals written for these tests."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction
from apbot.read.goal_manual import coded_names

GRINDER = """
appliance: {id: grinder_1, category: spice_grinder, name: "Mill M-3 grinder", brand: M}
controls:
  - {id: grade_key, kind: button, label: "GRADE"}
  - {id: cup_key, kind: button, label: "CUPS"}
variables:
  grade:
    type: discrete
    values: ["1", "2", "3"]
    label: "GRADE"
  cups:
    type: numeric
    ranges: [[1, 6, 1]]
actions:
  press_grade: {control: grade_key}
  press_cups: {control: cup_key}
features:
  grade:
    - {actions: [press_grade], variable: grade, effect: next}
  cups:
    - {actions: [press_cups], variable: cups, effect: next}
"""

GRINDER_MANUAL = """
Choosing the grade

   1 ROUGH — cracked seeds for rubs and crusts.
   2 MEDIUM — for most dishes.
   3 POWDER — as fine as flour; for sauces.

Tip: grade 2 (MEDIUM) suits pepper.
"""


def test_legend_lines_name_numbered_positions() -> None:
    model = loads_model(GRINDER)
    names = coded_names(model, GRINDER_MANUAL)
    assert ("grade", "3", "powder") in names
    assert parse_instruction(model, "grind it to a powder, 2 cups", GRINDER_MANUAL) == {
        "grade": "3",
        "cups": 2,
    }


def test_one_legend_line_names_nothing() -> None:
    manual = "   1 ROUGH — cracked seeds for rubs and crusts.\n"
    assert coded_names(loads_model(GRINDER), manual) == []


CUTTER = """
appliance: {id: cutter_1, category: paper_shredder, name: "Snip S-2 shredder", brand: S}
controls:
  - {id: a_key, kind: button, label: "C-2"}
  - {id: b_key, kind: button, label: "C-3"}
variables:
  blade:
    type: discrete
    values: [c2, c3]
    show: {c2: "C-2", c3: "C-3"}
actions:
  press_a: {control: a_key}
  press_b: {control: b_key}
features:
  blade:
    - actions: [press_a, press_b]
      variable: blade
      effect: {press_a: {to: c2}, press_b: {to: c3}}
"""

CUTTER_MANUAL = """
  ①    C-2            Strip-cut head (level C-2).
  ②    C-3            Confetti-cut head (level C-3).
"""


def test_a_word_every_code_name_shares_names_no_value() -> None:
    model = loads_model(CUTTER)
    assert parse_instruction(model, "confetti-cut please", CUTTER_MANUAL) == {"blade": "c3"}


JET = """
appliance: {id: jet_1, category: water_jet, name: "Spritz J-1", brand: S}
controls:
  - {id: force_key, kind: button, label: "FORCE"}
variables:
  force:
    type: numeric
    ranges: [[1, 8, 1]]
    wrap: true
actions:
  press_force: {control: force_key}
  hold_force: {control: force_key, skill: hold, seconds: 2}
features:
  force:
    - actions: [press_force, hold_force]
      variable: force
      effect: {press_force: next, hold_force: {to: 1}}
"""


def test_a_key_that_steps_a_setting_names_the_setting_not_its_held_value() -> None:
    assert parse_instruction(loads_model(JET), "force 6 please") == {"force": 6}


KILN = """
appliance: {id: kiln_9, category: pottery_kiln, name: "Fire K-9", brand: F}
controls:
  - {id: cone_key, kind: button, label: "CONE"}
variables:
  cone:
    type: discrete
    values: ["08", "06", "04", "4", "6", "8"]
actions:
  press_cone: {control: cone_key}
features:
  cone:
    - {actions: [press_cone], variable: cone, effect: next}
"""


def test_a_leading_zero_tells_two_codes_apart() -> None:
    model = loads_model(KILN)
    assert parse_instruction(model, "fire to cone 6") == {"cone": "6"}
    assert parse_instruction(model, "fire to cone 06") == {"cone": "06"}
