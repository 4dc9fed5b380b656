"""Rules a fresh-eyes review found firing on ordinary text, each pinned on a small manual of
our own: a key legend after a page break is no chart row, a switch named later in a sentence is
no hold's toggle, punctuation is no default mark, ..."""

from __future__ import annotations

from apbot.model.schema import DiscreteVariable
from apbot.read import read_manual
from apbot.read.goal import parse_instruction
from apbot.read.values import find_ranges


def _values(model, name: str) -> list[str]:  # type: ignore[no-untyped-def]
    var = model.variables[name]
    assert isinstance(var, DiscreteVariable), var
    return [str(v).lower() for v in var.values]


# a dryer's chart ends at a page break; the next page opens with its key legend, laid out
# in two columns of its own
LEGEND_AFTER_BREAK = """TUMBLE DRYER TD-4 GUIDE

DRYING CHART

   Cycle            Heat              Minutes
   Towels           High              90
   Shirts           Medium            50
   Delicates        Low               30

                                                   Page 1

HEAT             Picks another heat level.
DELAY            Puts off the start by an hour.
START            Begins drying.

                                                   Page 2

CARE

Empty the lint screen after each load.

                                                   Page 3
"""


def test_a_key_legend_after_a_page_break_is_not_read_as_chart_rows() -> None:
    actions = ["turn_cycle_cw", "press_heat", "press_delay", "press_start"]
    model = read_manual(LEGEND_AFTER_BREAK, actions).model
    name = next(n for n in model.variables if "cycle" in n)
    assert _values(model, name) == ["towels", "shirts", "delicates"]


# a soup maker whose long press cancels, and whose next sentence-half switches the mains by hand
SOUP = """
KEYS

BLEND     Chooses smooth or chunky.
START     Begins cooking.

Press and hold START for 2 seconds to stop the programme, then switch the MAINS off at the wall.
"""


def test_a_switch_named_after_then_is_not_what_the_hold_toggles() -> None:
    model = read_manual(SOUP, ["press_blend", "press_start", "hold_start"]).model
    held = [f for fs in model.features.values() for f in fs if f.actions == ["hold_start"]]
    assert held and all(f.effect != "toggle" for f in held), held


# a desk fan whose legend says what holding a key switches off, the "off" right before the stop
FAN = """
KEYS

SPEED     Steps through low, medium and high.
GLOW      Lights the panel. Holding GLOW turns the panel light off.
"""


def test_the_off_after_a_held_key_s_noun_is_not_part_of_the_toggle_s_name() -> None:
    model = read_manual(FAN, ["press_speed", "press_glow", "hold_glow"]).model
    held = [f for fs in model.features.values() for f in fs if f.actions == ["hold_glow"]]
    assert held and held[0].variable == "panel_light", held


# a washer's chart whose lists end in a full stop: no item is marked as the default
STOPS = """
KEYS

PROGRAM knob   Chooses the programme.
SPIN           Spin strength. Each touch lights the next one.
START          Starts washing.

PROGRAMME CHART

   Program          Spin                     Load
   Denim            Gentle, Normal, Fast.    jeans, jackets
   Mixed            Gentle, Normal.          shirts
   Silk             Gentle.                  scarves
"""


def test_a_full_stop_after_a_chart_list_is_no_default_mark() -> None:
    model = read_manual(STOPS, ["turn_program_cw", "press_spin", "press_start"]).model
    cases = model.variables["spin"].model_dump()["cases"]
    assert cases["denim"]["values"] == ["gentle", "normal", "fast"]
    assert all(c.get("initial") in (None, "gentle") for c in cases.values()), cases


# a bread maker whose programme legend has a row headed by the key's name and one more word,
# the key named again in the row's instructions (not as one of a list of values)
RISE = """
# Bread maker

## Using it

Press KNEAD to mix the dough. Press START to begin.

## Programmes

KNEAD RISE     Lets the dough prove: cover the pan, wait an hour and press KNEAD.
QUIET MODE     The beeper stays silent.
"""


def test_a_longer_row_head_naming_the_key_in_its_instructions_is_not_the_key() -> None:
    model = read_manual(RISE, ["press_knead", "press_start"]).model
    labels = {c.id: c.label for c in model.controls}
    assert labels["knead_control"] == "KNEAD", labels


# a pressure cooker with a heat key, and a sewing machine whose stitch length is a setting
COOKER = """
## Keys

DISH        Chooses the dish: STEW → BEANS → STEAM.
HEAT        Chooses the heat: LOW → MEDIUM → HIGH.
START       Starts cooking.
"""

SEWER = """
## Keys

STITCH      Chooses the stitch: STRAIGHT → ZIGZAG → BLIND.
LENGTH      Switches the long stitch on or off.
START       Starts sewing.
"""


def test_slowly_is_a_pace_not_a_low_heat() -> None:
    model = read_manual(COOKER, ["press_dish", "press_heat", "press_start"]).model
    goal = parse_instruction(model, "Steam the vegetables slowly and start")
    assert goal.get("dish") == "steam" and "heat" not in goal, goal
    assert parse_instruction(model, "Steam the vegetables on low heat").get("heat") == "low"


def test_long_without_a_number_sets_no_length() -> None:
    model = read_manual(SEWER, ["press_stitch", "press_length", "press_start"]).model
    goal = parse_instruction(model, "Sew a long zigzag seam")
    assert goal.get("stitch") == "zigzag" and "length" not in goal, goal


def test_a_clock_range_labelled_minutes_and_seconds_is_not_also_hours() -> None:
    found = find_ranges("Grill timer      0:05 - 30:00 (min:s)")
    assert [(r.low, r.high, r.unit) for r in found] == [(5, 1800, "s")]


# a dryer's chart whose head is at the foot of one page and whose rows carry an options
# column the head never named ("Wrinkle ●")
DRYER_CHART = """
The dryer starts on Mixed when switched on.

Aster Dryer Guide                                                      Page 4 of 12
==========================================================================================

SECTION 5   CYCLE CHART

   Cycle          Heat                     Dryness

Aster Dryer Guide                                                      Page 5 of 12
==========================================================================================

   Mixed          Low, Medium ▣, High      Damp, Normal ▣, Very Dry     Wrinkle ●
   Towels         Medium, High ▣           Normal, Very Dry ▣           Wrinkle ●
   Delicates      Low ▣                    Damp ▣, Normal               -

Turn the CYCLE knob to choose a cycle.

Aster Dryer Guide                                                      Page 6 of 12
==========================================================================================
"""


def test_chart_rows_with_an_unnamed_options_column_go_on_over_a_page_break() -> None:
    model = read_manual(DRYER_CHART, ["turn_cycle_cw", "turn_cycle_ccw"]).model
    values = [v.values for v in model.variables.values() if v.type == "discrete"]
    assert ["mixed", "towels", "delicates"] in values
