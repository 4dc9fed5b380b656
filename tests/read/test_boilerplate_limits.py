"""Where the boilerplate rules stop: a warning box inside an operating chapter, a safety
chapter that tells how to lock the keys, a chapter heading the parser ran into a paragraph,
a key sentence that mentions keeping the appliance, a programme named before "only:", one
small mark named on a knob, a cross in a chart's on/off column."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.cases_cells import _toggle_cell
from apbot.read.evidence_checks import between_marks
from apbot.read.text import parse_manual
from apbot.read.text_sections import boilerplate_heading

GRILL = """\
USING THE GRILL

Plug the grill in and open the lid.

WARNING
The plates are hot for a long time after use.
Turn the HEAT dial to choose 120 to 220 °C.
The CLOCK dial runs 2 to 45 minutes.

CARE
Let it cool and wipe the plates.
"""


def test_a_warning_line_inside_an_operating_chapter_hides_none_of_its_settings() -> None:
    texts = [u.text for u in parse_manual(GRILL).units]
    assert any("120 to 220" in t for t in texts), texts
    model = read_manual(GRILL, ["turn_heat", "turn_clock"]).model
    heat = model.variables["heat"].model_dump(mode="json")
    assert heat["ranges"][0][:2] == [120, 220], heat


LOCK_UNDER_SAFETY = """\
# Juicer JC-2

## Keys

- RUN: starts and stops the motor.
- GUARD: the key lock.

## Safety

Keep children away: hold GUARD for 4 seconds and the lock lamp comes on; hold it again
for 4 seconds to free the keys.
"""


def test_a_safety_chapter_that_tells_how_to_lock_the_keys_is_read() -> None:
    texts = [u.text for u in parse_manual(LOCK_UNDER_SAFETY).units]
    assert any("hold GUARD for 4 seconds" in t for t in texts), texts


RUN_ON = """\
2 SAFETY RULES
- Never pour water over the base
3 CONTROL KEYS
The FAN key moves through LOW, MID and HIGH. The lowest setting is quiet.
"""


def test_a_safety_chapter_ends_at_a_numbered_heading_the_parser_ran_on_into() -> None:
    # the heading is run into the paragraph above it: the sentence holding it is kept
    texts = [u.text for u in parse_manual(RUN_ON).units]
    assert any("LOW, MID and HIGH" in t for t in texts), texts


def test_a_key_worked_on_other_models_keeps_no_safety_chapter() -> None:
    text = """\
## Safety

Unplug the fryer before cleaning. On model QF-20 press RESET after a power cut.

## Frying

Press HEAT to choose 160 to 200 °C.
"""
    texts = [u.text for u in parse_manual(text).units]
    assert not any("power cut" in t for t in texts), texts
    assert any("160 to 200" in t for t in texts), texts


def test_headings_of_settings_are_no_boilerplate_chapters() -> None:
    for heading in ("Demonstration mode", "Safety mode", "Intended use and first use", "CAUTION"):
        assert not boilerplate_heading(heading), heading
    for heading in ("Safety first", "Software notice", "Packaging contents"):
        # a chapter's heading words alone, whatever product range wrote them
        assert boilerplate_heading(heading) == (heading == "Safety first"), heading


WARMER = """\
# Soup kettle SK-1

## Keys
- HOT: press HOT to keep the appliance hot for 2 to 8 hours; each press adds 2 hours.
"""


def test_a_key_sentence_about_keeping_the_appliance_warm_keeps_its_range() -> None:
    model = read_manual(WARMER, ["press_hot"]).model
    spec = model.variables["hot"].model_dump(mode="json")
    assert spec["ranges"][0][:2] in (["02:00:00", "08:00:00"], [2, 8], [7200, 28800]), spec


RINSE = """\
# Rinser RS-2

## Spin

Press SPIN to change the spin speed.
Wool 30 only: choose 300, 500 or 700 rpm.
"""


def test_a_programme_name_before_only_is_no_sister_model() -> None:
    model = read_manual(RINSE, ["press_power", "press_spin"]).model
    assert "spin" in model.variables, model.variables
    assert "300" in str(model.variables["spin"].model_dump(mode="json")), model.variables


def test_one_small_mark_named_is_no_stop_between_the_numbers() -> None:
    assert not between_marks("Turn the DIAL back until it rests at the small mark next to 0.")
    assert not between_marks("The settings are printed as short lines on the dial.")
    assert between_marks("The dial also clicks at each small mark between two numbers.")
    assert between_marks("Between two numbers it stops at a small mark.")


def test_a_cross_in_an_on_off_column_is_not_offered() -> None:
    assert _toggle_cell("x") is not True
    assert _toggle_cell("✗") is not True
    assert _toggle_cell("✓") is True
    assert _toggle_cell("yes") is True
